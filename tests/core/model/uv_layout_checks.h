// SPDX-License-Identifier: GPL-3.0-or-later
// What every automatic UV layout must be, checked on its output mesh: the input's triangles,
// charts in one piece, nothing flipped or covered twice, the padding kept.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numeric>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/model/uv_layout.h"
#include "core/paint/targets/uv_raster.h"

namespace uvcheck {

inline double area3d(const core::Mesh& m, std::size_t t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
    return 0.5 * double(glm::length(glm::cross(b - a, c - a)));
}

/** Signed area in texels of triangle t's UVs (positive: counter-clockwise in u, v). */
inline double areaUv(const core::UvLayout& l, std::size_t t) {
    const core::Mesh& m = l.mesh;
    const glm::dvec2 a = glm::dvec2(m.uvs[m.indices[3 * t]]) * double(l.resolution);
    const glm::dvec2 b = glm::dvec2(m.uvs[m.indices[3 * t + 1]]) * double(l.resolution);
    const glm::dvec2 c = glm::dvec2(m.uvs[m.indices[3 * t + 2]]) * double(l.resolution);
    return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

/** The same triangles, in the same order, with the same corners, materials and normals. */
inline void expectSameTriangles(const core::Mesh& in, const core::UvLayout& l) {
    const core::Mesh& out = l.mesh;
    ASSERT_EQ(out.triangleCount(), in.triangleCount());
    ASSERT_EQ(out.triangleMaterial, in.triangleMaterial);
    ASSERT_EQ(out.uvs.size(), out.positions.size());
    ASSERT_EQ(l.sourceVertex.size(), out.positions.size());
    EXPECT_TRUE(out.validate().ok()) << out.validate().error();
    for (std::size_t i = 0; i < in.indices.size(); ++i) {
        const std::uint32_t v = out.indices[i];
        ASSERT_EQ(l.sourceVertex[v], in.indices[i]) << "corner " << i;
        ASSERT_EQ(out.positions[v], in.positions[in.indices[i]]);
        ASSERT_EQ(out.normals[v], in.normals[in.indices[i]]);
    }
}

/**
 * Union-find over triangles of one chart joined by an edge: the same two positions with the same
 * UVs (vertices are copies where the input split them, e.g. at hard edges), or along part of one
 * (a T-junction: two points of one triangle's side lie on the other's side, in 3D and in UV).
 * Returns the pieces.
 */
inline std::uint32_t piecesOfCharts(const core::UvLayout& l,
                                    std::vector<std::uint32_t>& piecesPerChart) {
    const core::Mesh& m = l.mesh;
    std::vector<std::uint32_t> parent(m.triangleCount());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&](std::uint32_t x) {
        while (parent[x] != x)
            x = parent[x] = parent[parent[x]];
        return x;
    };
    using Corner = std::array<float, 5>;
    // Positions quantized: seam copies computed along different paths differ in the last bits.
    const auto corner = [&](std::uint32_t v) {
        const glm::vec3 p = m.positions[v];
        return Corner{std::round(p.x * 1e4f), std::round(p.y * 1e4f), std::round(p.z * 1e4f),
                      m.uvs[v].x, m.uvs[v].y};
    };
    std::map<std::pair<Corner, Corner>, std::pair<std::uint32_t, int>> edges; // first, count
    for (std::uint32_t t = 0; t < m.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            Corner a = corner(m.indices[3 * t + std::size_t(k)]),
                   b = corner(m.indices[3 * t + std::size_t((k + 1) % 3)]);
            if (b < a)
                std::swap(a, b);
            const auto [it, added] = edges.try_emplace({a, b}, t, 0);
            ++it->second.second;
            if (!added && l.triangleChart[it->second.first] == l.triangleChart[t])
                parent[find(it->second.first)] = find(t);
        }

    // T-junctions: sides met once, per chart, swept along x.
    struct Side {
        glm::dvec3 p[2];
        glm::dvec2 uv[2];
        std::uint32_t triangle, chart;
    };
    std::vector<Side> sides;
    for (std::uint32_t t = 0; t < m.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v0 = m.indices[3 * t + std::size_t(k)];
            const std::uint32_t v1 = m.indices[3 * t + std::size_t((k + 1) % 3)];
            Corner a = corner(v0), b = corner(v1);
            if (b < a)
                std::swap(a, b);
            if (edges.at({a, b}).second == 1)
                sides.push_back({{glm::dvec3(m.positions[v0]), glm::dvec3(m.positions[v1])},
                                 {glm::dvec2(m.uvs[v0]), glm::dvec2(m.uvs[v1])},
                                 t,
                                 l.triangleChart[t]});
        }
    const double tol = 1e-4 * double(m.bounds().longestSide());
    const double uvTol = 1e-2 / double(l.resolution);
    const auto lowX = [](const Side& s) { return std::min(s.p[0].x, s.p[1].x); };
    std::sort(sides.begin(), sides.end(), [&](const Side& a, const Side& b) {
        return a.chart != b.chart ? a.chart < b.chart : lowX(a) < lowX(b);
    });
    // Point p (uv q) on side s, in 3D and in UV.
    const auto onSide = [&](const glm::dvec3& p, const glm::dvec2& q, const Side& s) {
        const glm::dvec3 d = s.p[1] - s.p[0];
        const double len2 = glm::dot(d, d);
        if (!(len2 > 0.0))
            return false;
        const double f = std::clamp(glm::dot(p - s.p[0], d) / len2, 0.0, 1.0);
        return glm::length(s.p[0] + d * f - p) <= tol &&
               glm::length(s.uv[0] + (s.uv[1] - s.uv[0]) * f - q) <= uvTol;
    };
    for (std::size_t i = 0; i < sides.size(); ++i)
        for (std::size_t j = i + 1;
             j < sides.size() && sides[j].chart == sides[i].chart &&
             lowX(sides[j]) <= std::max(sides[i].p[0].x, sides[i].p[1].x) + tol;
             ++j) {
            const Side &a = sides[i], &b = sides[j];
            std::vector<glm::dvec3> shared;
            for (int k = 0; k < 2; ++k) {
                if (onSide(b.p[k], b.uv[k], a))
                    shared.push_back(b.p[k]);
                if (onSide(a.p[k], a.uv[k], b))
                    shared.push_back(a.p[k]);
            }
            bool apart = false;
            for (const glm::dvec3& x : shared)
                apart = apart || glm::length(x - shared[0]) > tol;
            if (apart)
                parent[find(a.triangle)] = find(b.triangle);
        }

    piecesPerChart.assign(l.chartCount, 0u);
    std::uint32_t roots = 0;
    for (std::uint32_t t = 0; t < m.triangleCount(); ++t)
        if (find(t) == t) {
            ++piecesPerChart[l.triangleChart[t]];
            ++roots;
        }
    return roots;
}

/**
 * Checks what every layout must be: charts in one piece, no triangle with area flipped, no texel
 * covered twice, and at least the padding in texels between texels of different charts.
 */
inline void expectValidLayout(const core::Mesh& in, const core::UvLayout& l) {
    expectSameTriangles(in, l);
    const core::Mesh& m = l.mesh;
    ASSERT_EQ(l.triangleChart.size(), m.triangleCount());
    ASSERT_EQ(l.chartPage.size(), l.chartCount);
    for (const glm::vec2& uv : m.uvs) {
        ASSERT_GE(uv.x, 0.0f);
        ASSERT_LE(uv.x, 1.0f);
        ASSERT_GE(uv.y, 0.0f);
        ASSERT_LE(uv.y, 1.0f);
    }

    std::vector<std::uint32_t> pieces;
    piecesOfCharts(l, pieces);
    for (std::uint32_t c = 0; c < l.chartCount; ++c)
        EXPECT_EQ(pieces[c], 1u) << "chart " << c << " is not one connected piece";

    double total = 0.0;
    for (std::size_t t = 0; t < m.triangleCount(); ++t)
        total += area3d(m, t);
    std::size_t flipped = 0;
    for (std::size_t t = 0; t < m.triangleCount(); ++t)
        if (area3d(m, t) > 1e-9 * total && !(areaUv(l, t) > 0.0))
            ++flipped;
    EXPECT_EQ(flipped, 0u);

    // Which chart covers each texel centre, with the painting's fill rule.
    const int size = l.resolution;
    const std::size_t texels = std::size_t(size) * std::size_t(size);
    constexpr std::uint32_t kEmpty = 0xffffffffu;
    std::vector<std::uint32_t> owner(texels * l.pageCount, kEmpty);
    std::size_t twice = 0;
    for (std::size_t t = 0; t < m.triangleCount(); ++t) {
        glm::vec2 uv[3];
        for (int k = 0; k < 3; ++k)
            uv[k] = m.uvs[m.indices[3 * t + std::size_t(k)]];
        core::uv::UvTriangle r;
        if (!core::uv::setUpUv(uv, size, size, r))
            continue;
        const std::uint32_t chart = l.triangleChart[t];
        std::uint32_t* page = owner.data() + texels * l.chartPage[chart];
        core::uv::scanUv(r, std::max(r.minX, 0), std::min(r.maxX, size - 1), std::max(r.minY, 0),
                         std::min(r.maxY, size - 1), [&](int x, int y, auto, auto, auto) {
                             std::uint32_t& o =
                                 page[std::size_t(y) * std::size_t(size) + std::size_t(x)];
                             twice += o != kEmpty;
                             o = chart;
                         });
    }
    EXPECT_EQ(twice, 0u) << "texels covered by more than one triangle";

    // Two small charts (covering at most smallChartTexels texels each) keep smallChartPadding
    // texels between them, any other two the padding.
    std::vector<std::size_t> covered(l.chartCount, 0u);
    for (const std::uint32_t c : owner)
        if (c != kEmpty)
            ++covered[c];
    const auto small = [&](std::uint32_t c) {
        return covered[c] <= std::size_t(l.smallChartTexels);
    };
    EXPECT_LE(l.smallChartPadding, l.padding);
    std::size_t tooClose = 0;
    const int p = l.padding;
    for (std::uint32_t page = 0; page < l.pageCount; ++page)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const std::uint32_t c =
                    owner[texels * page + std::size_t(y) * std::size_t(size) + std::size_t(x)];
                if (c == kEmpty)
                    continue;
                for (int dy = -p; dy <= p; ++dy)
                    for (int dx = -p; dx <= p; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= size || ny >= size)
                            continue;
                        const std::uint32_t o =
                            owner[texels * page + std::size_t(ny) * std::size_t(size) +
                                  std::size_t(nx)];
                        if (o == kEmpty || o == c)
                            continue;
                        const int gap = small(c) && small(o) ? l.smallChartPadding : p;
                        tooClose += std::max(std::abs(dx), std::abs(dy)) <= gap;
                    }
            }
    EXPECT_EQ(tooClose, 0u) << "texels of different charts closer than the padding";
}

} // namespace uvcheck
