// SPDX-License-Identifier: GPL-3.0-or-later
// Hand-made scenes for the core tests: camera-facing quads in a view whose world x, y are
// window pixels, so expected maps can be checked by hand.
#pragma once

#include <algorithm>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec2.hpp>

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

/** A camera-facing quad grid from window p0 to p1 at a view depth, uv0 at p0 to uv1 at p1. */
struct Quad {
    glm::vec2 p0, p1;
    float depth = 5.0f;
    glm::vec2 uv0{0.0f}, uv1{1.0f};
    int cells = 1;

    glm::vec2 pixelOfUv(glm::vec2 uv) const { return p0 + (uv - uv0) / (uv1 - uv0) * (p1 - p0); }
    bool hasUv(glm::vec2 uv) const {
        return uv.x >= std::min(uv0.x, uv1.x) && uv.x <= std::max(uv0.x, uv1.x) &&
               uv.y >= std::min(uv0.y, uv1.y) && uv.y <= std::max(uv0.y, uv1.y);
    }
};

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
            mesh.triangleMaterial.insert(mesh.triangleMaterial.end(), {0u, 0u});
        }
    }
    if (mesh.materials.empty())
        mesh.materials.push_back({"paint", glm::vec4(0.5f, 0.5f, 0.5f, 1.0f), -1});
}

} // namespace core_test
