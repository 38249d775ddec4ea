// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <numeric>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/model/builtin_models.h"
#include "core/model/uv_layout.h"
#include "core/paint/uv_raster.h"

namespace {

using core::Mesh;
using core::UvLayout;
using core::UvLayoutOptions;

Mesh withoutUvs(Mesh mesh) {
    mesh.uvs.clear();
    return mesh;
}

double area3d(const Mesh& m, std::size_t t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
    return 0.5 * double(glm::length(glm::cross(b - a, c - a)));
}

/** Signed area in texels of triangle t's UVs (positive: counter-clockwise in u, v). */
double areaUv(const UvLayout& l, std::size_t t) {
    const Mesh& m = l.mesh;
    const glm::dvec2 a = glm::dvec2(m.uvs[m.indices[3 * t]]) * double(l.resolution);
    const glm::dvec2 b = glm::dvec2(m.uvs[m.indices[3 * t + 1]]) * double(l.resolution);
    const glm::dvec2 c = glm::dvec2(m.uvs[m.indices[3 * t + 2]]) * double(l.resolution);
    return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

/** The same triangles, in the same order, with the same corners, materials and normals. */
void expectSameTriangles(const Mesh& in, const UvLayout& l) {
    const Mesh& out = l.mesh;
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
 * UVs (vertices are copies where the input split them, e.g. at hard edges). Returns the pieces.
 */
std::uint32_t piecesOfCharts(const UvLayout& l, std::vector<std::uint32_t>& piecesPerChart) {
    const Mesh& m = l.mesh;
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
    std::map<std::pair<Corner, Corner>, std::uint32_t> edges;
    for (std::uint32_t t = 0; t < m.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            Corner a = corner(m.indices[3 * t + std::size_t(k)]),
                   b = corner(m.indices[3 * t + std::size_t((k + 1) % 3)]);
            if (b < a)
                std::swap(a, b);
            const auto [it, added] = edges.try_emplace({a, b}, t);
            if (!added && l.triangleChart[it->second] == l.triangleChart[t])
                parent[find(it->second)] = find(t);
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
void expectValidLayout(const Mesh& in, const UvLayout& l) {
    expectSameTriangles(in, l);
    const Mesh& m = l.mesh;
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

UvLayoutOptions smallPages() {
    UvLayoutOptions o;
    o.resolution = 512;
    o.padding = 4;
    return o;
}

TEST(UvLayout, TrefoilWithoutUvsIsValidAndLowInStretch) {
    const Mesh mesh = withoutUvs(core::makeTrefoil(60, 24));
    auto layout = core::makeUvLayout(mesh, smallPages());
    ASSERT_TRUE(layout.ok()) << layout.error();
    expectValidLayout(mesh, *layout);
    EXPECT_GT(layout->chartCount, 1u); // a closed tube cannot be one disc
    const core::UvLayoutMetrics m = core::measureUvLayout(*layout);
    EXPECT_EQ(m.flippedTriangles, 0u);
    EXPECT_EQ(m.overlappingTexels, 0u);
    EXPECT_LE(m.stretchP95, 1.5);
    EXPECT_GT(m.packingEfficiency, 0.2);
    EXPECT_GT(m.seamLength, 0.0);
}

TEST(UvLayout, HexRingAndRowAreValid) {
    for (const Mesh& model : {core::makeHexRing(12), core::makeRow(12)}) {
        const Mesh mesh = withoutUvs(model);
        auto layout = core::makeUvLayout(mesh, smallPages());
        ASSERT_TRUE(layout.ok()) << layout.error();
        expectValidLayout(mesh, *layout);
        const core::UvLayoutMetrics m = core::measureUvLayout(*layout);
        EXPECT_LE(m.stretchP95, 1.5);
        EXPECT_LT(m.texelDensitySpread, 2.0);
    }
}

TEST(UvLayout, FlatFacesAreFlattenedWithoutStretch) {
    // The hex ring is made of planar faces: each is projected, so areas keep their ratios.
    const Mesh mesh = withoutUvs(core::makeHexRing(8));
    auto layout = core::makeUvLayout(mesh, smallPages());
    ASSERT_TRUE(layout.ok()) << layout.error();
    const core::UvLayoutMetrics m = core::measureUvLayout(*layout);
    EXPECT_LT(m.stretchMax, 1.01);
    EXPECT_LT(m.texelDensitySpread, 1.01);
}

TEST(UvLayout, SameLayoutForOneAndTwoThreads) {
    const Mesh mesh = withoutUvs(core::makeTrefoil(40, 16));
    UvLayoutOptions one = smallPages(), two = smallPages();
    one.threads = 1;
    two.threads = 2;
    auto a = core::makeUvLayout(mesh, one);
    auto b = core::makeUvLayout(mesh, two);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->mesh.uvs, b->mesh.uvs);
    EXPECT_EQ(a->mesh.indices, b->mesh.indices);
    EXPECT_EQ(a->triangleChart, b->triangleChart);
    EXPECT_EQ(a->texelsPerUnit, b->texelsPerUnit);
}

TEST(UvLayout, FixedDensitySpreadsOverPages) {
    const Mesh mesh = withoutUvs(core::makeRow(8));
    UvLayoutOptions o;
    o.resolution = 128;
    o.padding = 2;
    auto fitted = core::makeUvLayout(mesh, o);
    ASSERT_TRUE(fitted.ok()) << fitted.error();
    EXPECT_EQ(fitted->pageCount, 1u);
    o.texelsPerUnit = fitted->texelsPerUnit * 3.0; // nine times the area: several pages
    auto paged = core::makeUvLayout(mesh, o);
    ASSERT_TRUE(paged.ok()) << paged.error();
    EXPECT_GT(paged->pageCount, 1u);
    EXPECT_EQ(paged->texelsPerUnit, o.texelsPerUnit);
    expectValidLayout(mesh, *paged);
}

TEST(UvLayout, ProgressRisesAndCancelStops) {
    const Mesh mesh = withoutUvs(core::makeHexRing(8));
    std::vector<double> seen;
    auto layout = core::makeUvLayout(mesh, smallPages(), [&](double f) {
        seen.push_back(f);
        return true;
    });
    ASSERT_TRUE(layout.ok());
    ASSERT_GE(seen.size(), 3u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_EQ(seen.back(), 1.0);

    int calls = 0;
    auto cancelled = core::makeUvLayout(mesh, smallPages(), [&](double) { return ++calls < 3; });
    ASSERT_FALSE(cancelled.ok());
    EXPECT_TRUE(cancelled.cancelled());
}

TEST(UvLayout, BadInputIsAnError) {
    Mesh empty;
    empty.materials.resize(1);
    auto none = core::makeUvLayout(empty);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.errorKind(), core::ErrorKind::BadInput);

    Mesh broken = withoutUvs(core::makeHexRing(4));
    broken.indices[0] = std::uint32_t(broken.positions.size()); // out of range
    auto bad = core::makeUvLayout(broken);
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.errorKind(), core::ErrorKind::BadInput);

    UvLayoutOptions o;
    o.resolution = 16;
    auto tiny = core::makeUvLayout(withoutUvs(core::makeHexRing(4)), o);
    ASSERT_FALSE(tiny.ok());
    EXPECT_NE(tiny.error().find("resolution"), std::string::npos);
}

TEST(UvLayout, SmallChartsShareTheirPadding) {
    // 150 separate unit squares: on a 64² page each is a few texels, so with the full padding of
    // 4 each takes at least 5 × 5 texels and they do not fit; small charts keep half of it
    // between each other and fit.
    Mesh mesh;
    mesh.materials.resize(1);
    for (int i = 0; i < 150; ++i) {
        const float x = float(i % 15) * 2.0f, y = float(i / 15) * 2.0f;
        const auto base = std::uint32_t(mesh.positions.size());
        for (const glm::vec2 c :
             {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
            mesh.positions.emplace_back(x + c.x, y + c.y, 0.0f);
            mesh.normals.emplace_back(0.0f, 0.0f, 1.0f);
        }
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
        mesh.triangleMaterial.insert(mesh.triangleMaterial.end(), {0u, 0u});
    }
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().error();
    UvLayoutOptions o;
    o.resolution = 64;
    o.padding = 4;
    auto shared = core::makeUvLayout(mesh, o);
    ASSERT_TRUE(shared.ok()) << shared.error();
    EXPECT_EQ(shared->chartCount, 150u);
    EXPECT_EQ(shared->smallChartPadding, 2);
    expectValidLayout(mesh, *shared);

    o.smallChartTexels = 0;
    auto full = core::makeUvLayout(mesh, o);
    ASSERT_FALSE(full.ok());
    EXPECT_EQ(full.errorKind(), core::ErrorKind::BadInput);
    EXPECT_NE(full.error().find("do not fit"), std::string::npos) << full.error();
}

TEST(UvLayout, DegenerateTrianglesKeepTheirPlaceAndCoverNothing) {
    Mesh mesh = withoutUvs(core::makeHexRing(4));
    // A triangle with all corners on one point, in the middle of the list.
    const std::uint32_t v = mesh.indices[0];
    const std::size_t middle = 3 * (mesh.triangleCount() / 2);
    mesh.indices.insert(mesh.indices.begin() + std::ptrdiff_t(middle), {v, v, v});
    mesh.triangleMaterial.insert(mesh.triangleMaterial.begin() + std::ptrdiff_t(middle / 3), 0u);
    auto layout = core::makeUvLayout(mesh, smallPages());
    ASSERT_TRUE(layout.ok()) << layout.error();
    expectValidLayout(mesh, *layout);
    EXPECT_EQ(areaUv(*layout, middle / 3), 0.0);
}

} // namespace
