// SPDX-License-Identifier: GPL-3.0-or-later
// core/io/importer/: the sandboxed importer process that parses model files, and the
// protocol its output follows.
//
// What the importer process (layerpaint-import) writes on its standard output and loadMesh()
// reads back: frames of a 16-byte header (magic, tag, payload length) and a payload of plain
// native-endian arrays, so nothing is parsed twice. The reader trusts nothing: every length is
// checked against the counts announced and the LoadLimits before memory is allocated.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/base/progress.h"
#include "core/io/mesh_io.h"
#include "core/model/mesh.h"
#include "core/model/source_scene.h"

namespace core::importer {

inline constexpr std::uint32_t kMagic = 0x3149504Cu; // "LPI1" in little-endian byte order

enum class Tag : std::uint32_t {
    Progress = 1,           // double, a fraction in [0, 1]
    Warning = 2,            // UTF-8 text
    Error = 3,              // UTF-8 text: "FILE: problem"
    MeshBegin = 4,          // MeshHeader
    Positions = 5,          // float[3 * vertices]
    Normals = 6,            // float[3 * vertices]
    Uvs = 7,                // float[2 * vertices]
    Colors = 8,             // float[4 * vertices]
    Indices = 9,            // uint32[indices]
    TriangleMaterials = 10, // uint32[indices / 3]
    Material = 11,          // MaterialHeader, then the name's bytes
    Texture = 12,           // ImageHeader, then RGBA8 rows
    MeshEnd = 13,           // empty: the mesh is complete
    Image = 14,             // ImageHeader, then RGBA8 rows (an image file's pixels)
    TextureSource = 15,     // TextureSourceHeader, the MIME type, then the file's bytes
    SourceScene = 16,       // SourceSceneHeader, the JSON text, notKept, primitives, used
                            // vertices (uint32), the bin
    TextureOrigins = 17,    // int32[textures]: each texture's glTF image (-1: none)
    Tangents = 18,          // float[4 * vertices]
    Objects = 19,           // per named object: uint32 first triangle, uint32 name length, name
};

struct FrameHeader {
    std::uint32_t magic;
    std::uint32_t tag;
    std::uint64_t length;
};

/** Element counts; normals, uvs, colors and tangents are 0 or the vertex count. */
struct MeshHeader {
    std::uint64_t vertices;
    std::uint64_t indices;
    std::uint64_t normals;
    std::uint64_t uvs;
    std::uint64_t colors;
    std::uint64_t tangents;
    std::uint64_t triangleMaterials;
    std::uint64_t materials;
    std::uint64_t textures;
};

/** A MaterialMap: its texture (-1: none) and uvTransform, column-major. */
struct MapHeader {
    std::int32_t texture;
    float uvTransform[9];
};

struct MaterialHeader {
    float baseColorFactor[4];
    std::int32_t baseColorTexture;
    float metallicFactor;
    float roughnessFactor;
    float normalScale;
    float occlusionStrength;
    float emissiveFactor[3];
    float emissiveStrength;
    float alphaCutoff;
    MapHeader maps[4]; // metallicRoughness, normal, occlusion, emissive
    std::uint8_t alphaMode;
    std::uint8_t doubleSided;
    std::uint8_t reserved[2];
    std::uint32_t nameLength;
};

/** The kept file of a texture sent before (Mesh::textureSources); at most one per texture. */
struct TextureSourceHeader {
    std::uint32_t texture;
    std::uint32_t mimeTypeLength;
};

/** Mesh::source (SourceScene): the lengths of what follows the header. */
struct SourceSceneHeader {
    std::uint64_t jsonLength;
    std::uint64_t binLength;
    std::uint64_t primitives;   // SourcePrimitive records
    std::uint64_t usedVertices; // uint32 indices
    std::uint64_t uvHash;
    std::uint64_t colorHash;
    std::uint32_t notKeptLength;
    std::uint32_t reserved;
};

struct ImageHeader {
    std::uint32_t width;
    std::uint32_t height;
};

/** Writes frames to a file descriptor; after a failed write every later call fails too. */
class FrameWriter {
public:
    explicit FrameWriter(int fd) : m_fd(fd) {}

    /**
     * Promises that the bytes of every later frame stay unchanged until this process ends (the
     * importer writes its answer, then exits without freeing anything). Large payloads then go
     * to a pipe by reference (vmsplice) instead of being copied into it: the reader's read() is
     * the only copy. Elsewhere (not a pipe) they are written as before.
     */
    void lendUntilExit() { m_lend = true; }
    /** Whether large payloads still go by reference (false once the descriptor refused it). */
    bool lending() const { return m_lend; }

    bool progress(double fraction);
    bool text(Tag tag, const std::string& text);
    bool mesh(const Mesh& mesh);
    bool image(const Image& image);

private:
    bool objects(const std::vector<MeshObject>& objects);
    bool sourceScene(const SourceScene& scene);
    bool frame(Tag tag, const void* a, std::size_t aSize, const void* b = nullptr,
               std::size_t bSize = 0);
    bool writeAll(const void* data, std::size_t size);

    int m_fd;
    bool m_ok = true;
    bool m_lend = false;
    /**
     * Payloads made for a frame rather than pointing into the mesh: kept as long as the writer,
     * since a lent payload's pages must not change (freeing writes into them) before the reader
     * has read them.
     */
    std::vector<std::vector<std::uint8_t>> m_held;
};

/** Where frames come from: fills exactly size bytes, or returns false (ended or stopped). */
class FrameSource {
public:
    virtual ~FrameSource() = default;
    virtual bool read(void* data, std::size_t size) = 0;
};

/** What a run of the importer sent. At most one of mesh, image, error is set. */
struct Received {
    std::optional<Mesh> mesh;         // complete (MeshEnd seen), not yet validated
    std::optional<Image> image;       // sizes checked
    std::optional<std::string> error; // the importer's own message, made one line
    std::vector<std::string> warnings;
    std::string malformed;  // not empty: the output broke the format (what was wrong)
    bool cancelled = false; // a progress report returned false
    // None of the above: the source ended before a complete answer.
};

/** The most bytes one load may send under limits; more is refused. */
std::uint64_t maxOutputBytes(const LoadLimits& limits);

/**
 * Reads frames until an answer (mesh, image or error), a violation of the format, a cancel or
 * the end of the source. Progress frames go to progress.
 */
Received readFrames(FrameSource& source, const LoadLimits& limits, const ProgressFn& progress);

/** Text from the importer as one line of at most 2000 bytes without control characters. */
std::string cleanText(std::string text);

} // namespace core::importer
