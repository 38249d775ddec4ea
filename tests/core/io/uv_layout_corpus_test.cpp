// SPDX-License-Identifier: GPL-3.0-or-later
// The automatic UV layout on a real file without texture coordinates, loaded as the app does.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/io/mesh_io.h"
#include "core/model/uv_layout.h"
#include "tests/core/model/uv_layout_checks.h"

namespace uv_layout_corpus_test {

namespace fs = std::filesystem;

TEST(UvLayoutCorpus, EngineWithoutUvsGetsAValidLayout) {
    const fs::path path = fs::path(LAYERPAINT_ASSIMP_MODELS) /
                          "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    if (!fs::exists(path))
        GTEST_SKIP() << path << " is not installed";
    const core::Result<core::Mesh> mesh = core::loadMesh(path.string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    ASSERT_FALSE(mesh->hasUvs());

    core::UvLayoutOptions options;
    options.resolution = 2048;
    auto layout = core::makeUvLayout(*mesh, options);
    ASSERT_TRUE(layout.ok()) << layout.error();

    // Triangle order, corners and materials are the file's; charts in one piece (across the
    // T-junctions between its CAD faces too), nothing covered twice, the padding kept.
    uvcheck::expectValidLayout(*mesh, *layout);

    const core::UvLayoutMetrics m = core::measureUvLayout(*layout);
    EXPECT_EQ(layout->pageCount, 1u);
    EXPECT_EQ(m.flippedTriangles, 0u);
    // A few slivers of a thousandth of a texel round to no area in float UVs; nothing else.
    EXPECT_LT(m.collapsedTriangles, m.triangles / 1000);
    EXPECT_EQ(m.overlappingTexels, 0u);
    EXPECT_LE(m.stretchP95, 1.5);
    EXPECT_GT(m.charts, 100u);
    // At least 60 % of the page's texels are covered (the layout is the same on every run and
    // thread count).
    EXPECT_GE(m.packingEfficiency, 0.60);

    // Its thousands of charts of a few texels share their padding, so they fit a small page too.
    options.resolution = 512;
    options.threads = 2;
    auto small = core::makeUvLayout(*mesh, options);
    ASSERT_TRUE(small.ok()) << small.error();
    const core::UvLayoutMetrics s = core::measureUvLayout(*small);
    EXPECT_EQ(small->pageCount, 1u);
    EXPECT_EQ(s.flippedTriangles, 0u);
    EXPECT_EQ(s.overlappingTexels, 0u);

    // The same layout on one thread (charts across T-junctions, flattened in parallel).
    options.threads = 1;
    auto oneThread = core::makeUvLayout(*mesh, options);
    ASSERT_TRUE(oneThread.ok()) << oneThread.error();
    EXPECT_EQ(oneThread->triangleChart, small->triangleChart);
    EXPECT_EQ(oneThread->mesh.uvs, small->mesh.uvs);
    EXPECT_EQ(oneThread->mesh.indices, small->mesh.indices);
}

} // namespace uv_layout_corpus_test
