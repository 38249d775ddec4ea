// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "core/model/builtin_models.h"
#include "core/model/uv_layout.h"
#include "core/paint/targets/uv_raster.h"
#include "tests/core/model/uv_layout_checks.h"

namespace uv_layout_test {

using core::Mesh;
using core::UvLayout;
using core::UvLayoutOptions;
using uvcheck::areaUv;
using uvcheck::expectValidLayout;

Mesh withoutUvs(Mesh mesh) {
    mesh.uvs.clear();
    return mesh;
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
        Mesh mesh = withoutUvs(model);
        mesh.objects = {{"first", 0}, {"second", std::uint32_t(mesh.triangleCount() / 2)}};
        auto layout = core::makeUvLayout(mesh, smallPages());
        ASSERT_TRUE(layout.ok()) << layout.error();
        expectValidLayout(mesh, *layout);
        // The triangles keep their order, so the named objects stay as they were.
        ASSERT_EQ(layout->mesh.objects.size(), 2u);
        EXPECT_EQ(layout->mesh.objects[1].name, "second");
        EXPECT_EQ(layout->mesh.objects[1].firstTriangle, mesh.objects[1].firstTriangle);
        EXPECT_TRUE(layout->mesh.validate().ok());
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

/**
 * A strip of two faces that share no edge (a CAD export's T-junction): a 2 × 1 face of two
 * triangles, and on its top side a face of two 1 × 1 squares whose middle corner sits on that
 * side. The upper face is turned up about the line y = 1 by `bendDegrees`.
 */
Mesh tJunctionStrip(float bendDegrees) {
    Mesh mesh;
    mesh.materials.resize(1);
    const float a = glm::radians(bendDegrees);
    const auto up = [&](float x, float y) { // y ≥ 1: turned about y = 1
        return glm::vec3(x, 1.0f + (y - 1.0f) * std::cos(a), (y - 1.0f) * std::sin(a));
    };
    const glm::vec3 p[] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}, // the lower face
                           up(0, 1),  up(1, 1),  up(2, 1),  up(0, 2),  up(1, 2), up(2, 2)};
    for (const glm::vec3& q : p) {
        mesh.positions.push_back(q);
        mesh.normals.emplace_back(0.0f, 0.0f, 1.0f);
    }
    // Corners 4 and 6 coincide with 3 and 2 but are their own vertices, as in such files.
    mesh.indices = {0, 1, 2, 0, 2, 3, 4, 5, 8, 4, 8, 7, 5, 6, 9, 5, 9, 8};
    mesh.triangleMaterial.assign(6, 0u);
    return mesh;
}

TEST(UvLayout, ChartsGrowAcrossTJunctions) {
    for (const float bend : {0.0f, 25.0f}) {
        SCOPED_TRACE(bend);
        const Mesh mesh = tJunctionStrip(bend);
        ASSERT_TRUE(mesh.validate().ok());
        auto layout = core::makeUvLayout(mesh, smallPages());
        ASSERT_TRUE(layout.ok()) << layout.error();
        EXPECT_EQ(layout->chartCount, 1u); // one chart across the T-junction
        expectValidLayout(mesh, *layout);  // in one piece: the T-junction is closed in UV
        // The middle corner (vertex 5) lies on the lower face's top side in UV as in 3D.
        const Mesh& out = layout->mesh;
        const auto uvOf = [&](std::uint32_t v) {
            for (std::size_t i = 0; i < out.indices.size(); ++i)
                if (layout->sourceVertex[out.indices[i]] == v)
                    return glm::dvec2(out.uvs[out.indices[i]]) * double(layout->resolution);
            return glm::dvec2(-1.0);
        };
        const glm::dvec2 left = uvOf(3), right = uvOf(2), middle = uvOf(5);
        EXPECT_NEAR(glm::length(middle - (left + right) * 0.5), 0.0, 1e-3);
        const core::UvLayoutMetrics m = core::measureUvLayout(*layout);
        EXPECT_LT(m.stretchP95, bend == 0.0f ? 1.001 : 1.2);
    }
    // Bent past the sharp-edge angle, the faces are charts of their own.
    auto sharp = core::makeUvLayout(tJunctionStrip(60.0f), smallPages());
    ASSERT_TRUE(sharp.ok()) << sharp.error();
    EXPECT_EQ(sharp->chartCount, 2u);
    expectValidLayout(tJunctionStrip(60.0f), *sharp);
}

TEST(UvLayout, AFinOnAPlateLetsThePlateContinueAcrossItsFoot) {
    // A plate of two squares whose middle edge also carries an upright fin: that edge has three
    // triangles, so it has no single neighbour; the plate's halves still continue each other.
    Mesh mesh;
    mesh.materials.resize(1);
    const glm::vec3 p[] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0},
                           {1, 1, 0}, {2, 1, 0}, {1, 0, 1}, {1, 1, 1}};
    for (const glm::vec3& q : p) {
        mesh.positions.push_back(q);
        mesh.normals.emplace_back(0.0f, 0.0f, 1.0f);
    }
    mesh.indices = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4, 1, 6, 7, 1, 7, 4};
    mesh.triangleMaterial.assign(6, 0u);
    auto layout = core::makeUvLayout(mesh, smallPages());
    ASSERT_TRUE(layout.ok()) << layout.error();
    EXPECT_EQ(layout->chartCount, 2u); // the plate, the fin
    EXPECT_EQ(layout->triangleChart[0], layout->triangleChart[2]);
    EXPECT_NE(layout->triangleChart[0], layout->triangleChart[4]);
    expectValidLayout(mesh, *layout);
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

} // namespace uv_layout_test
