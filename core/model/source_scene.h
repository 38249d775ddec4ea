// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

namespace core {

/**
 * A run of a flattened mesh's triangles and vertices and the glTF primitive they came from. The
 * run's vertices are the primitive's, in order: all of them, or (kPartial) only those its
 * triangles use, listed in SourceScene::usedVertices.
 */
struct SourcePrimitive {
    static constexpr std::uint32_t kDraco = 1;   // decoded from KHR_draco_mesh_compression
    static constexpr std::uint32_t kPartial = 2; // not every vertex of the primitive is used

    std::uint32_t mesh = 0;      // index into the scene's meshes
    std::uint32_t primitive = 0; // index into that mesh's primitives
    std::uint32_t firstTriangle = 0;
    std::uint32_t triangleCount = 0;
    std::uint32_t firstVertex = 0;
    std::uint32_t vertexCount = 0;
    std::uint32_t sourceVertices = 0; // the primitive's vertex count
    std::uint32_t flags = 0;
};

/**
 * The glTF scene a Mesh was flattened from, kept so that saving writes the scene back with only
 * what was painted changed (core/io/gltf/gltf_write_back.h): the file's JSON with every buffer
 * merged into one (buffer 0, bin) and every image stored in a buffer view, and where each run of
 * the mesh's triangles came from. A scene that cannot be written back says why in notKept (its
 * JSON and bin are then empty).
 */
struct SourceScene {
    nlohmann::json json;
    std::vector<std::uint8_t> bin;
    std::vector<SourcePrimitive> primitives; // in triangle order, covering every triangle
    /** For each kPartial primitive in turn, the indices of its vertexCount used vertices. */
    std::vector<std::uint32_t> usedVertices;
    std::uint64_t uvHash = 0;    // hashValues() of the mesh's uvs as flattened
    std::uint64_t colorHash = 0; // and of its vertex colours
    std::string notKept;
};

/** A hash of the bytes of values (FNV-1a over 64-bit words), to tell whether they changed. */
std::uint64_t hashValues(const void* data, std::size_t bytes);
inline std::uint64_t hashValues(const std::vector<glm::vec2>& v) {
    return hashValues(v.data(), v.size() * sizeof(glm::vec2));
}
inline std::uint64_t hashValues(const std::vector<glm::vec4>& v) {
    return hashValues(v.data(), v.size() * sizeof(glm::vec4));
}

} // namespace core
