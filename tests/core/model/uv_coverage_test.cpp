// SPDX-License-Identifier: GPL-3.0-or-later
// measureUvCoverage() on small meshes whose UV area and overlap are known: UVs that cover no
// area (a point, a line, less than a texel), UVs apart, stacked, mirrored, repeating, and a grid
// whose shared diagonals pass through the coverage grid's cell centres.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include <glm/vec2.hpp>

#include "core/model/uv_coverage.h"

namespace uv_coverage_test {

using Quad = std::array<glm::vec2, 4>; // corners counter-clockwise from the lowest

/** A row of quads in space (two triangles each), with the given UVs at their corners. */
core::Mesh meshOfQuads(const std::vector<Quad>& quads) {
    core::Mesh mesh;
    for (std::size_t q = 0; q < quads.size(); ++q) {
        const auto base = std::uint32_t(mesh.positions.size());
        const float x = float(q);
        mesh.positions.insert(mesh.positions.end(),
                              {{x, 0, 0}, {x + 1, 0, 0}, {x + 1, 1, 0}, {x, 1, 0}});
        mesh.uvs.insert(mesh.uvs.end(), quads[q].begin(), quads[q].end());
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0, 0, 1));
    mesh.triangleMaterial.assign(mesh.triangleCount(), 0);
    mesh.materials.push_back(core::Material{});
    return mesh;
}

Quad square(float u0, float v0, float u1, float v1) {
    return {glm::vec2(u0, v0), glm::vec2(u1, v0), glm::vec2(u1, v1), glm::vec2(u0, v1)};
}

TEST(UvCoverage, AMeshWithoutUvsCoversNoArea) {
    core::Mesh mesh = meshOfQuads({square(0, 0, 1, 1)});
    mesh.uvs.clear();
    const core::UvCoverage c = core::measureUvCoverage(mesh);
    EXPECT_EQ(c.area, 0.0);
    EXPECT_TRUE(core::coversNoArea(c));
}

TEST(UvCoverage, OneUvForEveryVertexCoversNoArea) {
    const glm::vec2 p(0.0f, 1.0f); // as WusonOBJ.obj: one "vt" for all corners
    const core::UvCoverage c = core::measureUvCoverage(meshOfQuads({{p, p, p, p}, {p, p, p, p}}));
    EXPECT_EQ(c.triangles, 4u);
    EXPECT_EQ(c.degenerate, 4u);
    EXPECT_EQ(c.area, 0.0);
    EXPECT_TRUE(core::coversNoArea(c));
    EXPECT_FALSE(core::mostlyOverlaps(c));
}

TEST(UvCoverage, UvsOnALineOrWithinATexelCoverNoArea) {
    const Quad line = {glm::vec2(0, 0), glm::vec2(0.5f, 0.5f), glm::vec2(1, 1),
                       glm::vec2(0.25f, 0.25f)};
    EXPECT_TRUE(core::coversNoArea(core::measureUvCoverage(meshOfQuads({line}))));
    // Less than one texel of a 16384² texture: not degenerate, but no area to paint.
    const core::UvCoverage tiny =
        core::measureUvCoverage(meshOfQuads({square(0, 0, 1e-5f, 1e-5f)}));
    EXPECT_EQ(tiny.degenerate, 0u);
    EXPECT_TRUE(core::coversNoArea(tiny));
    // One texel of a 4096² texture is enough.
    EXPECT_FALSE(core::coversNoArea(
        core::measureUvCoverage(meshOfQuads({square(0, 0, 1 / 4096.0f, 1 / 4096.0f)}))));
}

TEST(UvCoverage, QuadsSideBySideDoNotOverlap) {
    const core::UvCoverage c =
        core::measureUvCoverage(meshOfQuads({square(0, 0, 0.5f, 1), square(0.5f, 0, 1, 1)}));
    EXPECT_NEAR(c.area, 1.0, 1e-6);
    EXPECT_EQ(c.overlap, 0.0);
    EXPECT_FALSE(core::coversNoArea(c));
}

TEST(UvCoverage, AGridWhoseDiagonalsCrossCellCentresDoesNotOverlap) {
    // 64 × 64 quads of 4 × 4 cells: every diagonal passes through cell centres, which only one
    // of its two triangles counts.
    std::vector<Quad> quads;
    const float step = 1.0f / 64.0f;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i)
            quads.push_back(
                square(float(i) * step, float(j) * step, float(i + 1) * step, float(j + 1) * step));
    const core::UvCoverage c = core::measureUvCoverage(meshOfQuads(quads));
    EXPECT_NEAR(c.area, 1.0, 1e-4);
    EXPECT_EQ(c.overlap, 0.0);
}

TEST(UvCoverage, MirroredHalvesOverlapEverywhere) {
    // The right half's UVs are the left half's, mirrored: one island painted twice.
    const Quad left = square(0.1f, 0.1f, 0.6f, 0.9f);
    const Quad mirrored = {left[1], left[0], left[3], left[2]};
    const core::UvCoverage c = core::measureUvCoverage(meshOfQuads({left, mirrored}));
    EXPECT_DOUBLE_EQ(c.overlap, 1.0);
    EXPECT_TRUE(core::mostlyOverlaps(c));
    EXPECT_FALSE(core::coversNoArea(c));
}

TEST(UvCoverage, OneStackedQuadOfThreePlacesIsAThird) {
    const core::UvCoverage c =
        core::measureUvCoverage(meshOfQuads({square(0, 0, 0.5f, 0.5f), square(0, 0, 0.5f, 0.5f),
                                             square(0.5f, 0, 1, 0.5f), square(0, 0.5f, 0.5f, 1)}));
    EXPECT_NEAR(c.overlap, 1.0 / 3.0, 1e-9);
    EXPECT_FALSE(core::mostlyOverlaps(c));
}

TEST(UvCoverage, UvsOutsideTheUnitSquareRepeat) {
    // A texture repeats: [3, 4] × [-2, -1] paints the same texels as [0, 1]².
    const core::UvCoverage apart = core::measureUvCoverage(meshOfQuads({square(3, -2, 4, -1)}));
    EXPECT_EQ(apart.overlap, 0.0);
    EXPECT_NEAR(apart.area, 1.0, 1e-6);
    const core::UvCoverage stacked =
        core::measureUvCoverage(meshOfQuads({square(3, -2, 4, -1), square(0, 0, 1, 1)}));
    EXPECT_DOUBLE_EQ(stacked.overlap, 1.0);
}

} // namespace uv_coverage_test
