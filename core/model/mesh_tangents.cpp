// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/mesh_tangents.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace core {

namespace {

/** v normalized; zero if it is (almost) zero or not finite. */
glm::vec3 unit(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > 1e-20f && std::isfinite(length) ? v / length : glm::vec3(0.0f);
}

/** v without its component along unit n, normalized; zero if nothing is left. */
glm::vec3 inPlane(const glm::vec3& v, const glm::vec3& n) {
    return unit(v - n * glm::dot(n, v));
}

/** Any unit vector perpendicular to unit n. */
glm::vec3 anyPerpendicular(const glm::vec3& n) {
    const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 t = inPlane(axis, n);
    return t == glm::vec3(0.0f) ? glm::vec3(1, 0, 0) : t;
}

/** The angle of the triangle at corner p between edges to q and r. */
float cornerAngle(const glm::vec3& p, const glm::vec3& q, const glm::vec3& r) {
    const glm::vec3 a = q - p, b = r - p;
    const float la = glm::length(a), lb = glm::length(b);
    if (!(la > 0.0f && lb > 0.0f))
        return 0.0f;
    return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f));
}

/** Sums of a vertex's weighted tangent and bitangent (direction of decreasing v). */
struct Sums {
    glm::vec3 tangent{0.0f};
    glm::vec3 bitangent{0.0f};
};

/** Adds triangle t's tangent frame to its three corners. */
void addTriangle(const Mesh& mesh, std::size_t t, std::vector<Sums>& sums) {
    const std::uint32_t v[3] = {mesh.indices[3 * t], mesh.indices[3 * t + 1],
                                mesh.indices[3 * t + 2]};
    const glm::vec3 p0 = mesh.positions[v[0]], p1 = mesh.positions[v[1]], p2 = mesh.positions[v[2]];
    const glm::vec2 w0 = mesh.uvs[v[0]], w1 = mesh.uvs[v[1]], w2 = mesh.uvs[v[2]];
    const glm::vec3 e1 = p1 - p0, e2 = p2 - p0;
    const glm::vec2 d1 = w1 - w0, d2 = w2 - w0;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 0.0f) || !std::isfinite(det))
        return; // no area in uv space: no direction to follow
    const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
    const glm::vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
    const glm::vec3 corners[3] = {p0, p1, p2};
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 n = unit(mesh.normals[v[i]]);
        const float angle = cornerAngle(corners[i], corners[(i + 1) % 3], corners[(i + 2) % 3]);
        sums[v[i]].tangent += angle * inPlane(dPdu, n);
        sums[v[i]].bitangent -= angle * inPlane(dPdv, n);
    }
}

} // namespace

std::vector<glm::vec4> computeTangents(const Mesh& mesh) {
    const std::size_t vertices = mesh.vertexCount();
    if (mesh.uvs.size() != vertices || mesh.normals.size() != vertices)
        return {};
    std::vector<Sums> sums(vertices);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        if (v[0] < vertices && v[1] < vertices && v[2] < vertices)
            addTriangle(mesh, t, sums);
    }
    std::vector<glm::vec4> tangents(vertices);
    for (std::size_t i = 0; i < vertices; ++i) {
        const glm::vec3 n = unit(mesh.normals[i]);
        glm::vec3 t = inPlane(sums[i].tangent, n);
        if (t == glm::vec3(0.0f))
            t = anyPerpendicular(n);
        const float sign = glm::dot(glm::cross(n, t), sums[i].bitangent) < 0.0f ? -1.0f : 1.0f;
        tangents[i] = glm::vec4(t, sign);
    }
    return tangents;
}

std::vector<glm::vec4> vertexTangents(const Mesh& mesh) {
    const std::size_t vertices = mesh.vertexCount();
    if (mesh.uvs.size() != vertices)
        return {};
    const bool allGiven = mesh.tangents.size() == vertices &&
                          std::none_of(mesh.tangents.begin(), mesh.tangents.end(),
                                       [](const glm::vec4& t) { return t.w == 0.0f; });
    if (allGiven)
        return mesh.tangents;
    std::vector<glm::vec4> tangents = computeTangents(mesh);
    if (mesh.tangents.size() == vertices)
        for (std::size_t i = 0; i < vertices; ++i)
            if (mesh.tangents[i].w != 0.0f)
                tangents[i] = mesh.tangents[i];
    return tangents;
}

} // namespace core
