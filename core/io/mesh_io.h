// SPDX-License-Identifier: GPL-3.0-or-later
// core/io/: every file read or written: gltf/, assimp/ (model loading), image/ (codecs),
// project/ (project files), importer/ (the sandboxed importer process), and here the entry
// points, exports and atomic writes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/model/mesh.h"

namespace core {

/** Size caps that keep a hostile file from exhausting memory, and how strict loading is. */
struct LoadLimits {
    std::uint64_t maxFileBytes = 2ull << 30; // 2 GiB
    std::uint64_t maxVertices = 50'000'000;
    std::uint64_t maxTriangles = 50'000'000;
    std::uint64_t maxImagePixels = 16384ull * 16384ull;
    /**
     * A glTF base colour texture that cannot be read fails the load instead of being dropped
     * with a warning (a project's textures hold the painting).
     */
    bool requireTextures = false;
    /**
     * Processor seconds a file may take in the importer process, and its wall-clock deadline;
     * longer is an error. 0: processor time estimated from what the load reads (the file and
     * the companion files it names: 2 s, plus 0.5 s per MiB and 5 s per image), with a deadline
     * of three times that plus 10 s (detail::importSeconds()). What the importer may send back
     * is capped from the sizes above.
     */
    double maxSeconds = 0.0;
    /**
     * Bytes a project's paint layers may take once read (their planes' tiles, twice: as read and
     * as restored, plus their decoded images); more is refused before anything is decoded. 0:
     * half the machine's memory.
     */
    std::uint64_t maxPaintLayerBytes = 0;
};

/**
 * Loads a mesh: "builtin:NAME" (see builtin_models.h), glTF 2.0 (.gltf/.glb) through tinygltf,
 * or any format Assimp reads (OBJ, PLY, STL, OFF, ...). The default scene is flattened with node
 * transforms; points and lines are skipped with a warning.
 *
 * Files are parsed in a short-lived importer process (layerpaint-import: found through the
 * environment variable LAYERPAINT_IMPORTER, beside the running program, or in
 * ../libexec/layerpaint/ from it) with resource limits and read access to the model's folder
 * only; what it sends back is checked again here. Built-in models are made in this process.
 *
 * Returns the mesh, or an Error whose message names the file and the problem; an importer that
 * crashes, hangs or exceeds a limit gives "FILE: the importer stopped: …". Never throws.
 * A cancelled load (progress returned false) ends the importer and returns "…: cancelled".
 */
Result<Mesh> loadMesh(const std::string& path, const ProgressFn& progress = {},
                      const LoadLimits& limits = {});

/**
 * Keeps one importer process started ahead of the next loadMesh()/loadImageFile(), so that a
 * load does not wait for the program and its libraries to load (a few hundred milliseconds).
 * For programs that load files again and again (the GUI); each file still gets its own process.
 * keepImporterReady(false) ends the waiting one and stops doing so.
 */
void keepImporterReady(bool keep = true);

/**
 * Decodes an image file (PNG, JPEG, ...) to RGBA8 through OpenImageIO in the importer process, as
 * loadMesh() does a model. Returns the image or an Error "FILE: problem". Never throws.
 */
Result<Image> loadImageFile(const std::string& path, const LoadLimits& limits = {});

/** An image in a buffer view of a binary glTF, and the size it must have (0 × 0: any). */
struct GlbImageRequest {
    int view = 0;
    int width = 0;
    int height = 0;
};

/**
 * Decodes the images stored in the buffer views of the binary glTF file path that requests name
 * (a project's paint-layer images), in the importer process like loadImageFile(): the images in
 * the requests' order, or an Error "FILE: problem". An image whose header gives another size
 * than its request's is refused before it is decoded. Never throws.
 */
Result<std::vector<Image>> loadGlbImages(const std::string& path,
                                         const std::vector<GlbImageRequest>& requests,
                                         const LoadLimits& limits = {});

/**
 * Decodes an image file held in memory (PNG, JPEG, ...) to RGBA8 through OpenImageIO, in this
 * process (the loaders call it inside the importer).
 */
Result<Image> decodeImage(const std::uint8_t* data, std::size_t size, const std::string& name,
                          const LoadLimits& limits = {});

/**
 * An image file's bytes to keep beside its decoded texture: PNG and JPEG files (by their
 * signature), which glTF holds as they are; empty for other formats.
 */
EncodedImage encodedImageOf(const std::uint8_t* data, std::size_t size);

} // namespace core
