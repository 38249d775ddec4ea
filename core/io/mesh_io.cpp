// SPDX-License-Identifier: GPL-3.0-or-later
// loadMeshInProcess: checks the file, dispatches to the glTF or Assimp loader, then (unless the
// application will) repairs what can be repaired (normals, stray UV/color values) and validates
// the result.
#include "core/io/mesh_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>
#include <string_view>
#include <system_error>

#include <glm/geometric.hpp>

#include "core/base/text.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/model/builtin_models.h"
#include "core/model/uv_coverage.h"

namespace core {

// The format loaders (mesh_io_gltf.cpp, mesh_io_assimp.cpp). `file` is canonical; errors carry
// only the problem, loadMeshInProcess() prefixes the path. Both leave normals to finishMesh()
// below.
namespace detail {
Result<Mesh> loadGltf(const std::filesystem::path& file, const ProgressFn& progress,
                      const LoadLimits& limits);
Result<Mesh> loadAssimp(const std::filesystem::path& file, const ProgressFn& progress,
                        const LoadLimits& limits);
} // namespace detail

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/**
 * UVs that cover no area are dropped (a texture is then painted over an automatic layout); UVs
 * that mostly overlap are kept (mirrored islands are often meant), with a warning. Both name the
 * file: a project's warnings list several.
 */
void checkUvCoverage(Mesh& mesh, const std::string& path) {
    if (!mesh.hasUvs())
        return;
    const UvCoverage coverage = measureUvCoverage(mesh);
    const std::string name = std::filesystem::path(path).filename().string();
    if (coversNoArea(coverage)) {
        mesh.uvs.clear();
        mesh.tangents.clear();
        mesh.warnings.push_back("the texture coordinates (UVs) of " + name +
                                " cover no area (every triangle is a point or a line in UV "
                                "space), so they were dropped: a texture is painted over an "
                                "automatic UV layout");
    } else if (mostlyOverlaps(coverage)) {
        const long percent = std::lround(100.0 * coverage.overlap);
        mesh.warnings.push_back(std::to_string(percent) + "% of the UV area of " + name +
                                " is covered by two or more triangles: a stroke paints every "
                                "overlapping place at once (a texture with automatic UVs "
                                "paints them apart)");
    }
}

/**
 * A file's object name as kept: control characters as spaces, cut after 256 bytes (a UTF-8
 * sequence begun before kept whole).
 */
std::string objectName(std::string_view name) {
    constexpr std::size_t kMaxBytes = 256;
    std::string out;
    for (std::size_t i = 0; i < name.size(); ++i) {
        const auto c = static_cast<unsigned char>(name[i]);
        if (i >= kMaxBytes && (c & 0xC0) != 0x80)
            break;
        out += c < 0x20 || c == 0x7F ? ' ' : char(c);
    }
    return out;
}

/**
 * Mesh::objects as kept: objects without triangles dropped, neighbours of one name joined, none
 * at all where none is named.
 */
void tidyObjects(Mesh& mesh) {
    std::vector<MeshObject> kept;
    const auto triangles = std::uint32_t(mesh.triangleCount());
    for (std::size_t o = 0; o < mesh.objects.size(); ++o) {
        MeshObject& object = mesh.objects[o];
        const std::uint32_t end =
            o + 1 < mesh.objects.size() ? mesh.objects[o + 1].firstTriangle : triangles;
        if (end <= object.firstTriangle || (!kept.empty() && kept.back().name == object.name))
            continue;
        kept.push_back(std::move(object));
    }
    if (!kept.empty() && kept.front().firstTriangle != 0) // triangles before the first object
        kept.insert(kept.begin(), MeshObject{"", 0});
    const bool named = std::any_of(kept.begin(), kept.end(),
                                   [](const MeshObject& object) { return !object.name.empty(); });
    mesh.objects = named ? std::move(kept) : std::vector<MeshObject>{};
}

} // namespace

namespace detail {

Error fileError(const std::string& path, std::string problem, ErrorKind kind) {
    for (char& c : problem)
        if (c == '\n' || c == '\r' || c == '\t')
            c = ' ';
    while (!problem.empty() && (problem.back() == ' ' || problem.back() == '.'))
        problem.pop_back();
    return Error{path + ": " + (problem.empty() ? std::string("cannot be loaded") : problem), kind};
}

Error fileError(const std::string& path, const Error& error) {
    return fileError(path, error.message,
                     error.kind == ErrorKind::Failed ? ErrorKind::BadInput : error.kind);
}

Result<UsedVertices> numberUsedVertices(const std::vector<std::uint32_t>& tris,
                                        std::size_t vertexCount, const Mesh& mesh,
                                        const LoadLimits& limits) {
    UsedVertices used;
    used.remap.assign(vertexCount, std::numeric_limits<std::uint32_t>::max());
    for (std::uint32_t v : tris)
        used.remap[v] = 0;
    for (std::uint32_t& r : used.remap)
        if (r == 0)
            r = static_cast<std::uint32_t>(used.count++);
    if (mesh.positions.size() + used.count > limits.maxVertices)
        return Error{"too many vertices (more than " + std::to_string(limits.maxVertices) + ")",
                     ErrorKind::BadInput};
    if (mesh.triangleCount() + tris.size() / 3 > limits.maxTriangles)
        return Error{"too many triangles (more than " + std::to_string(limits.maxTriangles) + ")",
                     ErrorKind::BadInput};
    return used;
}

void Flattener::finish(Mesh& out) {
    Mesh& mesh = m_mesh;
    if (!m_anyUv)
        mesh.uvs = {};
    if (!m_anyTangent || !m_anyUv)
        mesh.tangents = {};
    if (!m_anyColor)
        mesh.colors = {};
    const auto withNormal =
        static_cast<std::size_t>(std::count(m_hasNormal.begin(), m_hasNormal.end(), 1));
    if (withNormal == 0) {
        mesh.normals.clear(); // loadMesh computes them all
    } else if (withNormal != m_hasNormal.size()) {
        Mesh computed;
        computed.positions = mesh.positions;
        computed.indices = mesh.indices;
        computed.computeNormals();
        for (std::size_t i = 0; i < m_hasNormal.size(); ++i)
            if (!m_hasNormal[i])
                mesh.normals[i] = computed.normals[i];
    }
    tidyObjects(mesh);
    out = std::move(mesh);
}

void Flattener::beginObject(const std::string& name) {
    m_mesh.objects.push_back({objectName(name), std::uint32_t(m_mesh.triangleCount())});
}

int Flattener::addTexture(Image image, const std::uint8_t* file, std::size_t fileSize) {
    Mesh& mesh = m_mesh;
    mesh.textureSources.resize(mesh.textures.size());
    mesh.textures.push_back(std::move(image));
    mesh.textureSources.push_back(file ? encodedImageOf(file, fileSize) : EncodedImage{});
    return static_cast<int>(mesh.textures.size() - 1);
}

bool toFloat(const glm::dvec3& p, glm::vec3& out) {
    constexpr double kMax = std::numeric_limits<float>::max();
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(p[k]) || std::abs(p[k]) > kMax)
            return false;
    out = glm::vec3(p);
    return true;
}

glm::vec3 unitNormal(const glm::dvec3& n) {
    const double len = glm::length(n);
    return std::isfinite(len) && len > 0.0 ? glm::vec3(n / len) : glm::vec3(0.0f);
}

Status finishMesh(Mesh& mesh, const LoadLimits& limits, const std::string& path) {
    if (mesh.positions.size() > limits.maxVertices)
        return Error{"too many vertices (" + std::to_string(mesh.positions.size()) + ")",
                     ErrorKind::BadInput};
    if (mesh.triangleCount() > limits.maxTriangles)
        return Error{"too many triangles (" + std::to_string(mesh.triangleCount()) + ")",
                     ErrorKind::BadInput};
    if (mesh.positions.empty() || mesh.indices.empty())
        return Error{"the file contains no triangles", ErrorKind::BadInput};
    for (const glm::vec3& p : mesh.positions)
        if (!finite(p))
            return Error{"a vertex position is not a finite number", ErrorKind::BadInput};
    for (std::uint32_t i : mesh.indices)
        if (i >= mesh.positions.size())
            return Error{"a vertex index is out of range", ErrorKind::BadInput};
    // Nothing to see or paint if every triangle is degenerate (e.g. all corners one vertex).
    bool anyArea = false;
    for (std::size_t t = 0; t + 2 < mesh.indices.size() && !anyArea; t += 3) {
        const glm::vec3& a = mesh.positions[mesh.indices[t]];
        const glm::vec3 n = glm::cross(mesh.positions[mesh.indices[t + 1]] - a,
                                       mesh.positions[mesh.indices[t + 2]] - a);
        anyArea = n.x != 0.0f || n.y != 0.0f || n.z != 0.0f;
    }
    if (!anyArea)
        return Error{"the file contains only degenerate triangles (no area)", ErrorKind::BadInput};

    if (mesh.materials.empty())
        mesh.materials.push_back(Material{"default", glm::vec4(1.0f), -1});
    if (mesh.triangleMaterial.empty())
        mesh.triangleMaterial.assign(mesh.triangleCount(), 0);

    // Normals: keep the file's where usable, compute the rest from the triangles.
    if (mesh.normals.size() != mesh.positions.size()) {
        mesh.computeNormals();
    } else {
        std::size_t bad = 0;
        for (glm::vec3& n : mesh.normals) {
            const float len = finite(n) ? glm::length(n) : 0.0f;
            if (std::isfinite(len) && len > 1e-12f) {
                // Unit normals stay as they are: a second pass (the application checking what
                // the importer process sent) changes nothing.
                if (std::abs(len - 1.0f) > 1e-6f)
                    n /= len;
            } else {
                n = glm::vec3(std::numeric_limits<float>::quiet_NaN());
                ++bad;
            }
        }
        if (bad > 0) {
            Mesh computed;
            computed.positions = mesh.positions;
            computed.indices = mesh.indices;
            computed.computeNormals();
            for (std::size_t i = 0; i < mesh.normals.size(); ++i)
                if (!finite(mesh.normals[i]))
                    mesh.normals[i] = computed.normals[i];
            mesh.warnings.push_back(bad == 1
                                        ? std::string("1 invalid normal was recomputed from "
                                                      "the triangles")
                                        : std::to_string(bad) + " invalid normals were "
                                                                "recomputed from the triangles");
        }
    }

    std::size_t badUvs = 0;
    for (glm::vec2& uv : mesh.uvs)
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
            uv = glm::vec2(0.0f);
            ++badUvs;
        }
    if (badUvs > 0)
        mesh.warnings.push_back(std::to_string(badUvs) +
                                " texture coordinates were not finite numbers and were set to 0");
    checkUvCoverage(mesh, path);
    for (glm::vec4& c : mesh.colors)
        for (int k = 0; k < 4; ++k)
            c[k] = std::isfinite(c[k]) ? std::clamp(c[k], 0.0f, 1.0f) : 1.0f;
    return mesh.validate();
}

Result<std::filesystem::path> checkModelFile(const std::string& path, const LoadLimits& limits) {
    if (path.empty())
        return Error{"(no file name): no file was given"};

    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path given(path);
    const fs::file_status st = fs::status(given, ec);
    if (ec && ec != std::errc::no_such_file_or_directory)
        return fileError(path, "cannot be read (" + ec.message() + ")", ErrorKind::Io);
    if (!fs::exists(st))
        return fileError(path, "does not exist", ErrorKind::Io);
    if (fs::is_directory(st))
        return fileError(path, "is a directory, not a file");
    if (!fs::is_regular_file(st))
        return fileError(path, "is not a regular file");
    const std::uintmax_t size = fs::file_size(given, ec);
    if (ec)
        return fileError(path, "cannot be read (" + ec.message() + ")", ErrorKind::Io);
    if (size == 0)
        return fileError(path, "is empty");
    if (size > limits.maxFileBytes)
        return fileError(path, "is too large (" + std::to_string(size) + " bytes; the limit is " +
                                   std::to_string(limits.maxFileBytes) + ")");
    // Canonical: external files are resolved inside the real folder of the model.
    fs::path file = fs::canonical(given, ec);
    if (ec)
        return fileError(path, "cannot be read (" + ec.message() + ")", ErrorKind::Io);
    return file;
}

} // namespace detail

namespace {

using detail::fileError;

Result<Mesh> load(const std::string& path, const ProgressFn& progress, const LoadLimits& limits,
                  bool finish) {
    if (path.rfind(kBuiltinPrefix, 0) == 0) {
        Result<Mesh> builtin = makeBuiltinModel(path.substr(std::string(kBuiltinPrefix).size()));
        if (!builtin && builtin.error().rfind(path, 0) != 0)
            return fileError(path, builtin.takeError());
        return builtin;
    }
    Result<std::filesystem::path> checked = detail::checkModelFile(path, limits);
    if (!checked)
        return checked.takeError();
    const std::filesystem::path& file = *checked;
    const std::filesystem::path given(path);

    if (!reportProgress(progress, 0.0))
        return fileError(path, "cancelled", ErrorKind::Cancelled);
    const std::string ext = lowerExtension(given);
    Result<Mesh> result = (ext == ".gltf" || ext == ".glb")
                              ? detail::loadGltf(file, progress, limits)
                              : detail::loadAssimp(file, progress, limits);
    if (!result)
        return fileError(path, result.takeError());
    Mesh mesh = std::move(result).value();
    if (finish)
        if (const Status finished = detail::finishMesh(mesh, limits, path); !finished)
            return fileError(path, finished.takeError());
    if (!reportProgress(progress, 1.0))
        return fileError(path, "cancelled", ErrorKind::Cancelled);
    return mesh;
}

} // namespace

Result<Mesh> loadMeshInProcess(const std::string& path, const ProgressFn& progress,
                               const LoadLimits& limits, MeshChecks checks) {
    try {
        return load(path, progress, limits, checks == MeshChecks::Finish);
    } catch (const std::bad_alloc&) {
        return fileError(
            path, "too large for this machine's memory (an allocation failed while loading it)",
            ErrorKind::Failed);
    } catch (const std::exception& e) {
        return fileError(path, e.what(), ErrorKind::Failed);
    } catch (...) {
        return fileError(path, "cannot be loaded (unexpected error)", ErrorKind::Failed);
    }
}

} // namespace core
