// SPDX-License-Identifier: GPL-3.0-or-later
// Hand-made scenes for the core tests: camera-facing quads in a view whose world x, y are
// window pixels, so expected maps can be checked by hand; grids in 3D seen from the front.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/model/camera.h"
#include "core/model/mesh.h"

namespace core_test {

/** An orthographic view whose world x, y are window pixels (y down), looking down -Z. */
inline core::View pixelView(int width, int height) {
    core::View view;
    view.width = width;
    view.height = height;
    view.view = glm::mat4(1.0f);
    view.proj = glm::ortho(0.0f, float(width), float(height), 0.0f, 0.1f, 100.0f);
    return view;
}

/**
 * A camera-facing quad grid of cells × cells squares from window p0 to p1 at a view depth, uv0 at
 * p0 to uv1 at p1, its triangles of the given material.
 */
struct Quad {
    glm::vec2 p0, p1;
    float depth = 5.0f;
    glm::vec2 uv0{0.0f}, uv1{1.0f};
    int cells = 1;
    std::uint32_t material = 0;

    glm::vec2 pixelOfUv(glm::vec2 uv) const { return p0 + (uv - uv0) / (uv1 - uv0) * (p1 - p0); }
    bool hasUv(glm::vec2 uv) const {
        return uv.x >= std::min(uv0.x, uv1.x) && uv.x <= std::max(uv0.x, uv1.x) &&
               uv.y >= std::min(uv0.y, uv1.y) && uv.y <= std::max(uv0.y, uv1.y);
    }
    bool hasPixel(glm::vec2 p) const {
        return p.x >= p0.x && p.x <= p1.x && p.y >= p0.y && p.y <= p1.y;
    }
};

/**
 * Adds q with its own vertices (neighbouring quads weld along shared edges), and a grey material
 * if the mesh has none.
 */
inline void addQuad(core::Mesh& mesh, const Quad& q, bool uvs = true) {
    const auto base = std::uint32_t(mesh.positions.size());
    const int n = q.cells;
    for (int r = 0; r <= n; ++r) {
        for (int c = 0; c <= n; ++c) {
            const glm::vec2 f(float(c) / float(n), float(r) / float(n));
            const glm::vec2 p = q.p0 + f * (q.p1 - q.p0);
            mesh.positions.push_back({p.x, p.y, -q.depth});
            mesh.normals.push_back({0.0f, 0.0f, 1.0f});
            if (uvs)
                mesh.uvs.push_back(q.uv0 + f * (q.uv1 - q.uv0));
        }
    }
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
            const std::uint32_t a = base + std::uint32_t(r * (n + 1) + c), b = a + 1;
            const std::uint32_t d = a + std::uint32_t(n + 1), e = d + 1;
            // Clockwise in window coordinates (y down) is counter-clockwise in NDC: front.
            mesh.indices.insert(mesh.indices.end(), {a, d, e, a, e, b});
            mesh.triangleMaterial.insert(mesh.triangleMaterial.end(), {q.material, q.material});
        }
    }
    if (mesh.materials.empty())
        mesh.materials.push_back({"paint", glm::vec4(0.5f, 0.5f, 0.5f, 1.0f), -1});
}

/**
 * For a 96 × 64 pixelView: a back quad (depth 8, u 0..0.5 of the texture) partly covered by a
 * front quad (depth 4, u 0.5..1): the covered part of the back quad is depth layer 2 at x 36..64,
 * y 16..48.
 */
inline core::Mesh overlappingQuads() {
    core::Mesh mesh;
    addQuad(mesh, {{4.0f, 8.0f}, {64.0f, 56.0f}, 8.0f, {0.0f, 0.0f}, {0.5f, 1.0f}, 4});
    addQuad(mesh, {{36.0f, 16.0f}, {92.0f, 48.0f}, 4.0f, {0.5f, 0.0f}, {1.0f, 1.0f}, 4});
    return mesh;
}

/** The texels of the front quad's half of an overlappingQuads() page (clear of the seam padding).
 */
inline std::vector<std::uint8_t> frontHalfTexels(const core::Image& page) {
    std::vector<std::uint8_t> out;
    for (int y = 0; y < page.height; ++y)
        for (int x = page.width / 2 + 4; x < page.width; ++x)
            for (int c = 0; c < 4; ++c)
                out.push_back(
                    page.rgba[4 * (std::size_t(y) * std::size_t(page.width) + std::size_t(x)) +
                              std::size_t(c)]);
    return out;
}

/** Appends an n × n grid quad spanning corners o, o + u, o + v (counter-clockwise from u × v). */
inline void addGrid(core::Mesh& mesh, glm::vec3 o, glm::vec3 u, glm::vec3 v, int n) {
    const auto base = std::uint32_t(mesh.positions.size());
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            mesh.positions.push_back(o + u * (float(i) / float(n)) + v * (float(j) / float(n)));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::uint32_t a = base + std::uint32_t(j * (n + 1) + i), b = a + 1,
                                d = a + std::uint32_t(n + 1), e = d + 1;
            mesh.indices.insert(mesh.indices.end(), {a, b, e, a, e, d});
        }
}

/** Gives grids made by addGrid one default material and their normals. */
inline void finishGrids(core::Mesh& mesh) {
    mesh.materials = {core::Material{}};
    mesh.triangleMaterial.assign(mesh.triangleCount(), 0);
    mesh.computeNormals();
}

/** A view from +Z at distance 2 looking at the origin, 45° vertical field of view. */
inline core::View frontView(int width, int height, bool orthographic = false) {
    core::Camera camera;
    camera.sceneRadius = 1.0f;
    camera.distance = 2.0f;
    camera.orthographic = orthographic;
    return camera.view(width, height);
}

} // namespace core_test
