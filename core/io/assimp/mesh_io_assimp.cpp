// SPDX-License-Identifier: GPL-3.0-or-later
// Loader for everything Assimp reads (OBJ, PLY, STL, OFF, ...): the order of work and Assimp's
// messages in the user's words. The checks before Assimp are in assimp_prechecks, the confined
// file access in assimp_file_access, the scene checks and flattening in assimp_flatten.
//
// Before Assimp: OFF and PLY header counts must fit the file (Assimp allocates and loops over
// them first: the corpus's 309-byte OutOfMemory.off cost 16 GB and 20 s), and an OBJ face
// statement without vertices is refused (Assimp drops it silently).
//
// Assimp reads with no post-processing first; checkRawScene() then checks every face index, bone
// weight and morph mesh that the post-processing steps read. That replaces
// aiProcess_ValidateDataStructure, which checks the same but rejects whole files for harmless
// defects (an empty solid in an STL, an empty mesh) and animation data never used here. The
// steps: Triangulate (polygons to triangles; points and lines stay and are skipped with a
// warning) and JoinIdenticalVertices (OBJ/STL importers emit one vertex per face corner; joining
// restores shared vertices, so vertex counts are those of distinct position/normal/UV/color
// tuples per mesh, compared with Assimp's small epsilon). Not used: PreTransformVertices and
// SortByPType (both reorder triangles; node transforms are applied here, nodes depth-first,
// meshes in node order), FindDegenerates (drops triangles and shifts the ids), GenNormals
// (normals are computed area-weighted in loadMesh).
//
// Files: Assimp opens files only inside the model's folder (FolderIOSystem); a reference outside
// it (mtllib ../x.mtl) is not read and becomes a warning. Texture paths are resolved the same
// way, falling back to the bare file name in the model's folder (OBJ files written on Windows
// often carry absolute paths).
//
// Conventions: UVs are flipped to glTF's (origin at the top-left, v down) so that they index
// Image rows top first. Vertex colors are treated as sRGB-encoded display values (as PLY/OBJ
// tools do) and converted to linear. With a diffuse texture, a legacy diffuse color does not
#include <algorithm>
#include <cctype>
#include <cstring>
#include <exception>
#include <filesystem>
#include <string>

#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "core/base/text.h"
#include "core/io/assimp/assimp_file_access.h"
#include "core/io/assimp/assimp_flatten.h"
#include "core/io/assimp/assimp_prechecks.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/mesh_io.h"

namespace core::detail {

Result<Mesh> loadAssimp(const std::filesystem::path& file, const ProgressFn& progress,
                        const LoadLimits& limits);

namespace {

namespace fs = std::filesystem;

/** Maps Assimp's progress to [0, 0.5] and relays cancellation. */
class Progress : public Assimp::ProgressHandler {
public:
    explicit Progress(const ProgressFn& fn) : m_fn(fn) {}
    bool Update(float percentage) override {
        const double f = percentage >= 0.0f ? std::clamp(double(percentage), 0.0, 1.0) : 0.0;
        if (!reportProgress(m_fn, 0.05 + 0.45 * f))
            m_cancelled = true;
        return !m_cancelled;
    }
    bool cancelled() const { return m_cancelled; }

private:
    const ProgressFn& m_fn;
    bool m_cancelled = false;
};

std::string oneLine(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r')
            c = ' ';
    while (!s.empty() && s.back() == ' ')
        s.pop_back();
    return s;
}

/** The format a file's extension (lower case, with the dot) stands for, with its article. */
std::string formatName(const std::string& ext) {
    if (ext == ".obj")
        return "a Wavefront OBJ";
    if (ext == ".ply")
        return "a Stanford PLY";
    if (ext == ".stl")
        return "an STL";
    if (ext == ".off")
        return "an OFF";
    std::string name = ext.empty() ? ext : ext.substr(1);
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return "a " + name;
}

/**
 * What Assimp said about a file it could not read, in the user's words: its common messages
 * mapped, anything else kept as detail without the file's path or bytes that cannot be shown.
 */
std::string readError(const fs::path& file, const std::string& ext, std::string assimp) {
    const std::string format = formatName(ext);
    const auto says = [&](const char* text) { return assimp.find(text) != std::string::npos; };
    if (assimp.empty())
        return "could not be read as " + format + " model";
    if (says("No suitable reader found"))
        return "is not in a 3D model format LayerPaint can read";
    if (says("too small") || says("Unexpected end of file") || says("unexpected end"))
        return "is too short to be " + format + " model; it may be cut off or another kind of file";
    if (says("magic number") || says("Magic number") || says("storage representation") ||
        says("not a valid") || says("no data loaded"))
        return "is not " + format + " model; it may be damaged or another kind of file";
    // Otherwise Assimp's own words as the detail, without the path (the message names it).
    for (const std::string& path : {file.string(), file.filename().string()})
        for (std::size_t p; !path.empty() && (p = assimp.find(path)) != std::string::npos;)
            assimp.replace(p, path.size(), "the file");
    for (char& c : assimp)
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F)
            c = '?';
    return "could not be read as " + format + " model (" + assimp + ")";
}

Result<Mesh> load(const fs::path& file, const ProgressFn& progress, const LoadLimits& limits) {
    const fs::path folder = file.parent_path();
    Assimp::Importer importer;
    // The importer owns and deletes both.
    auto* io = new assimp::FolderIOSystem(folder, limits.maxFileBytes);
    importer.SetIOHandler(io);
    auto* handler = new Progress(progress);
    importer.SetProgressHandler(handler);
    // Keep loaders from building skeleton-only placeholder meshes.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);

    const std::string ext = lowerExtension(file);
    if (ext == ".obj")
        if (Status checked = assimp::checkObjFaces(file); !checked)
            return checked.takeError();
    std::error_code ec;
    const std::uintmax_t fileSize = fs::file_size(file, ec);
    if (ec)
        return Error{"cannot be read (" + ec.message() + ")", ErrorKind::Io};
    if (Status checked = assimp::checkDeclaredCounts(file, fileSize, limits); !checked)
        return checked.takeError();
    if (ext == ".off")
        if (Status checked = assimp::checkOffFaces(file); !checked)
            return checked.takeError();

    const aiScene* raw = importer.ReadFile(file.string(), 0);
    if (handler->cancelled())
        return cancelledError();
    if (raw == nullptr)
        return Error{readError(file, ext, oneLine(importer.GetErrorString()))};
    // The importer owns the scene and post-processing changes it anyway.
    if (Status checked = assimp::checkRawScene(*const_cast<aiScene*>(raw), limits); !checked)
        return checked.takeError();
    const aiScene* scene =
        importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
    if (handler->cancelled())
        return cancelledError();
    if (scene == nullptr)
        return Error{readError(file, ext, oneLine(importer.GetErrorString()))};
    Result<Mesh> flattened = assimp::flattenAssimp(*scene, folder, limits);
    if (!flattened)
        return flattened.takeError();
    Mesh mesh = std::move(flattened).value();
    if (!io->rejected().empty())
        mesh.warnings.push_back("a reference to a file outside the model's folder was ignored: " +
                                io->rejected());
    if (!reportProgress(progress, 0.9))
        return cancelledError();
    return mesh;
}

} // namespace

Result<Mesh> loadAssimp(const std::filesystem::path& file, const ProgressFn& progress,
                        const LoadLimits& limits) {
    return catchLoadErrors([&] { return load(file, progress, limits); });
}

} // namespace core::detail
