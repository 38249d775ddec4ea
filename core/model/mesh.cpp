// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

namespace core {

float Bounds::longestSide() const {
    const glm::vec3 s = size();
    return std::max({s.x, s.y, s.z});
}

Bounds Mesh::bounds() const {
    if (positions.empty())
        return {};
    Bounds b{glm::vec3(std::numeric_limits<float>::max()),
             glm::vec3(std::numeric_limits<float>::lowest())};
    for (const glm::vec3& p : positions) {
        b.min = glm::min(b.min, p);
        b.max = glm::max(b.max, p);
    }
    return b;
}

void Mesh::computeNormals() {
    normals.assign(positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        // The cross product's length is twice the area: this weights by area.
        const glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for (glm::vec3& n : normals) {
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    }
}

static bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

Status Mesh::validate() const {
    const std::size_t n = positions.size();
    if (n == 0 || indices.empty())
        return Error{"the mesh has no triangles", ErrorKind::BadInput};
    if (indices.size() % 3 != 0)
        return Error{"the index count is not a multiple of 3", ErrorKind::BadInput};
    if (normals.size() != n)
        return Error{"normal count differs from vertex count", ErrorKind::BadInput};
    if (!uvs.empty() && uvs.size() != n)
        return Error{"texture coordinate count differs from vertex count", ErrorKind::BadInput};
    if (!colors.empty() && colors.size() != n)
        return Error{"vertex color count differs from vertex count", ErrorKind::BadInput};
    if (!tangents.empty() && tangents.size() != n)
        return Error{"tangent count differs from vertex count", ErrorKind::BadInput};
    if (triangleMaterial.size() != triangleCount())
        return Error{"per-triangle material count differs from triangle count",
                     ErrorKind::BadInput};
    if (materials.empty())
        return Error{"the mesh has no material", ErrorKind::BadInput};
    for (std::uint32_t i : indices)
        if (i >= n)
            return Error{"a vertex index is out of range", ErrorKind::BadInput};
    for (std::uint32_t m : triangleMaterial)
        if (m >= materials.size())
            return Error{"a material index is out of range", ErrorKind::BadInput};
    for (const Material& m : materials)
        for (int t : {m.baseColorTexture, m.metallicRoughness.texture, m.normal.texture,
                      m.occlusion.texture, m.emissive.texture})
            if (t >= static_cast<int>(textures.size()))
                return Error{"a texture index is out of range", ErrorKind::BadInput};
    if (!textureSources.empty() && textureSources.size() != textures.size())
        return Error{"the kept texture files differ in count from the textures",
                     ErrorKind::BadInput};
    if (!textureOrigins.empty() && textureOrigins.size() != textures.size())
        return Error{"the textures' origins differ in count from the textures",
                     ErrorKind::BadInput};
    if (!sourceVertices.empty() && sourceVertices.size() != vertexCount())
        return Error{"the vertices' origins differ in count from the vertices",
                     ErrorKind::BadInput};
    for (std::size_t o = 0; o < objects.size(); ++o)
        if (objects[o].firstTriangle >= triangleCount() ||
            (o == 0 ? objects[o].firstTriangle != 0
                    : objects[o].firstTriangle <= objects[o - 1].firstTriangle))
            return Error{"the named objects do not divide the triangles in order",
                         ErrorKind::BadInput};
    for (const glm::vec3& p : positions)
        if (!finite(p))
            return Error{"a vertex position is not a finite number", ErrorKind::BadInput};
    for (const Image& img : textures)
        if (img.rgba.size() != static_cast<std::size_t>(img.width) * img.height * 4)
            return Error{"a texture's pixel data does not match its size", ErrorKind::BadInput};
    return {};
}

} // namespace core
