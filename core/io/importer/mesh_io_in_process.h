// SPDX-License-Identifier: GPL-3.0-or-later
// The loaders that parse files in the calling process. Only the importer process
// (layerpaint-import) and the fuzz targets call these: everything else loads through loadMesh(),
// loadImageFile() and loadProject(), which run them in that helper process.
#pragma once

#include <exception>
#include <filesystem>
#include <new>
#include <set>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/io/importer/import_budget.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/model/mesh.h"

namespace core {

/** Whether a mesh loaded in this process goes through detail::finishMesh() here. */
enum class MeshChecks {
    Finish, // yes: the mesh is ready to use
    Later,  // no: the importer process leaves them to the application, which makes them anyway
};

/**
 * loadMesh() in this process: the same contract, the same messages. With MeshChecks::Later the
 * mesh is the format loader's, not yet checked nor repaired (normals may be missing).
 */
Result<Mesh> loadMeshInProcess(const std::string& path, const ProgressFn& progress = {},
                               const LoadLimits& limits = {},
                               MeshChecks checks = MeshChecks::Finish);

/** loadImageFile() in this process. */
Result<Image> loadImageFileInProcess(const std::string& path, const LoadLimits& limits = {});

/** loadGlbImages() in this process. */
Result<std::vector<Image>> loadGlbImagesInProcess(const std::string& path,
                                                  const std::vector<GlbImageRequest>& requests,
                                                  const LoadLimits& limits = {});

/** loadProject() with the mesh read by loadMeshInProcess(). */
Result<Project> loadProjectInProcess(const std::string& path, const ProgressFn& progress = {},
                                     const LoadLimits& limits = {});

namespace detail {
/**
 * The importer's processor time for path: limits.maxSeconds, or an estimate from what the load
 * reads (importProcessorSeconds(estimateImportInput(path, kind)), import_budget.h).
 */
double importSeconds(const std::string& path, const LoadLimits& limits,
                     ImportKind kind = ImportKind::Model);

/**
 * "<path>: <problem>" on one line (line breaks become spaces, no final full stop), of the given
 * kind (a problem with the file unless said otherwise).
 */
Error fileError(const std::string& path, std::string problem, ErrorKind kind = ErrorKind::BadInput);

/**
 * error (from a format loader, which names no file) with path in front; its kind, or BadInput
 * where the loader gave none (the loaders' errors are about the file).
 */
Error fileError(const std::string& path, const Error& error);

/**
 * load() (a format loader's work), with an exception it throws turned into the Error it stands
 * for, naming no file.
 */
template <typename Load> Result<Mesh> catchLoadErrors(Load&& load) {
    try {
        return load();
    } catch (const std::bad_alloc&) {
        return Error{"too large for this machine's memory (an allocation failed while loading it)"};
    } catch (const std::exception& e) {
        return Error{std::string("cannot be loaded (") + e.what() + ")"};
    } catch (...) {
        return Error{"cannot be loaded (unexpected error)"};
    }
}

/** The vertices a run of triangle corners uses, numbered in their original order. */
struct UsedVertices {
    std::vector<std::uint32_t> remap; // per vertex: its new index, or UINT32_MAX where unused
    std::uint64_t count = 0;
};

/**
 * The vertices (of vertexCount) that the triangle corners tris use, numbered in their original
 * order, so primitives sharing one big vertex array do not multiply it; an Error (BadInput) when
 * adding them and their triangles to mesh would pass limits.
 */
Result<UsedVertices> numberUsedVertices(const std::vector<std::uint32_t>& tris,
                                        std::size_t vertexCount, const Mesh& mesh,
                                        const LoadLimits& limits);

/**
 * What the glTF and the Assimp flattener share: the mesh being built, the first error, warnings
 * said once, and which vertices came with UVs, colours and normals.
 */
class Flattener {
public:
    const Error& error() const { return m_error; }

protected:
    /** Keeps the first error; returns false for `return fail(...)`. */
    bool fail(std::string msg, ErrorKind kind = ErrorKind::BadInput) {
        if (m_error.message.empty())
            m_error = Error{std::move(msg), kind};
        return false;
    }
    void warnOnce(const std::string& msg) {
        if (m_warned.insert(msg).second)
            m_mesh.warnings.push_back(msg);
    }
    /**
     * The last step, the mesh moved into out: UVs, tangents and colours are dropped where no
     * primitive had them; for normals, m_hasNormal[v] says whether vertex v came with one: none
     * did, so all are left for loadMesh to compute (normals cleared); some did, so the others get
     * normals computed from the triangles.
     */
    void finish(Mesh& out);
    /**
     * Appends a decoded texture and, when file (its encoded bytes, or null) is PNG or JPEG, keeps
     * those bytes beside it (Mesh::textureSources); returns the texture's index.
     */
    int addTexture(Image image, const std::uint8_t* file = nullptr, std::size_t fileSize = 0);
    /**
     * The triangles added from now on are the object name's (Mesh::objects; finish() drops
     * objects without triangles, joins neighbours of one name and keeps none if none is named).
     */
    void beginObject(const std::string& name);

    Mesh m_mesh;
    Error m_error;
    std::set<std::string> m_warned;
    std::vector<char> m_hasNormal;
    bool m_anyUv = false, m_anyTangent = false, m_anyColor = false;
};

/** p as floats, or false if it does not fit (a double beyond float range is not castable). */
bool toFloat(const glm::dvec3& p, glm::vec3& out);

/** n normalized in double precision; zero (recomputed later) when it has no direction. */
glm::vec3 unitNormal(const glm::dvec3& n);

/**
 * The checks made before a model file is parsed: it exists, is a regular file, not empty and
 * within limits.maxFileBytes. Returns its canonical path, or the Error.
 */
Result<std::filesystem::path> checkModelFile(const std::string& path, const LoadLimits& limits);

/**
 * The checks and repairs every loaded mesh goes through (counts against the limits, finite
 * values, normals, materials, UVs that cover no area dropped, Mesh::validate()) of the file
 * path (named in warnings); the first problem as an Error (no path).
 */
Status finishMesh(Mesh& mesh, const LoadLimits& limits, const std::string& path);
} // namespace detail

} // namespace core
