// SPDX-License-Identifier: GPL-3.0-or-later
// glTF's doubleSided with back faces culled: the back faces of a double-sided material's open
// surfaces are captured and painted, those of closed ones (which face their inside) and of
// single-sided materials are not.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "core/depth/cpu_capture.h"
#include "core/document/document.h"
#include "core/model/builtin_models.h"
#include "core/model/mesh_topology.h"
#include "tests/core/script_host.h"
#include "tests/core/test_scenes.h"

namespace double_sided_test {

using core_test::pixelView;

constexpr int kWidth = 96, kHeight = 64;

/** q turned to face away from the pixelView (its back faces the viewer). */
void addBackFacingQuad(core::Mesh& mesh, const core_test::Quad& q) {
    const std::size_t first = mesh.indices.size();
    core_test::addQuad(mesh, q);
    for (std::size_t i = first; i < mesh.indices.size(); i += 3)
        std::swap(mesh.indices[i + 1], mesh.indices[i + 2]);
}

/**
 * Two quads facing away from the view, left of material 0 (double-sided) and right of material 1
 * (single-sided), and with a tube, a closed tube of material 0 behind them.
 */
core::Mesh leaves(bool withTube = true) {
    core::Mesh mesh;
    addBackFacingQuad(mesh, {{4.0f, 8.0f}, {44.0f, 56.0f}, 4.0f, {0.0f, 0.0f}, {0.5f, 1.0f}, 2, 0});
    addBackFacingQuad(mesh,
                      {{52.0f, 8.0f}, {92.0f, 56.0f}, 4.0f, {0.5f, 0.0f}, {1.0f, 1.0f}, 2, 1});
    mesh.materials.resize(2);
    mesh.materials[0].doubleSided = true;
    const std::size_t quadTriangles = mesh.triangleCount();
    if (!withTube)
        return mesh;
    core::Mesh tube = core::makeTrefoil(40, 12);
    const auto base = std::uint32_t(mesh.positions.size());
    for (glm::vec3 p : tube.positions)
        mesh.positions.push_back(glm::vec3(48.0f, 32.0f, -40.0f) + p * 10.0f);
    mesh.normals.insert(mesh.normals.end(), tube.normals.begin(), tube.normals.end());
    mesh.uvs.resize(mesh.positions.size(), glm::vec2(0.25f));
    for (std::uint32_t i : tube.indices)
        mesh.indices.push_back(base + i);
    mesh.triangleMaterial.resize(mesh.triangleCount(), 0);
    EXPECT_EQ(mesh.triangleCount() - quadTriangles, tube.triangleCount());
    return mesh;
}

std::vector<std::uint32_t> trianglesOfQuad(int quad) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t t = 0; t < 8; ++t) // 2 × 2 cells of 2 triangles
        out.push_back(std::uint32_t(quad) * 8 + t);
    return out;
}

TEST(DoubleSided, OnlyOpenSurfacesOfDoubleSidedMaterialsShowTheirBackFaces) {
    core::Mesh mesh = leaves();
    EXPECT_EQ(core::buildMeshTopology(mesh).shownBackFaces, trianglesOfQuad(0));
    mesh.materials[0].doubleSided = false;
    EXPECT_TRUE(core::buildMeshTopology(mesh).shownBackFaces.empty());
}

TEST(DoubleSided, TheCaptureKeepsTheShownBackFacesOnly) {
    const core::Mesh mesh = leaves();
    const core::MeshTopology topology = core::buildMeshTopology(mesh);
    const core::View view = pixelView(kWidth, kHeight);
    core::CpuCaptureOptions options;
    const core::DepthStack culled = core::captureDepthLayersCpu(mesh, view, options);
    options.shownBackFaces = topology.shownBackFaces;
    const core::DepthStack shown = core::captureDepthLayersCpu(mesh, view, options);
    // The quads' nearest fragment at a pixel (the tube's triangles are 16 on).
    const auto at = [&](const core::DepthStack& stack, int x, int y) {
        const std::size_t pixel = std::size_t(y) * kWidth + std::size_t(x);
        for (std::uint32_t k = 1; k <= stack.layerCount(pixel); ++k)
            if (stack.triangle[stack.fragment(pixel, k)] < 16)
                return stack.triangle[stack.fragment(pixel, k)];
        return core::kNone;
    };
    EXPECT_EQ(at(culled, 20, 20), core::kNone);
    EXPECT_LT(at(shown, 20, 20), 8u);          // the double-sided quad's back
    EXPECT_EQ(at(shown, 80, 20), core::kNone); // the single-sided one stays culled
    // Behind them, the tube shows the same front faces either way.
    std::size_t tubeFragments = 0;
    for (std::size_t p = 0; p < culled.pixelCount(); ++p)
        for (std::uint32_t k = 1; k <= culled.layerCount(p); ++k)
            tubeFragments += culled.triangle[culled.fragment(p, k)] >= 16 ? 1 : 0;
    std::size_t tubeShown = 0;
    for (std::size_t p = 0; p < shown.pixelCount(); ++p)
        for (std::uint32_t k = 1; k <= shown.layerCount(p); ++k)
            tubeShown += shown.triangle[shown.fragment(p, k)] >= 16 ? 1 : 0;
    EXPECT_GT(tubeFragments, 50u);
    EXPECT_EQ(tubeShown, tubeFragments);
}

TEST(DoubleSided, AStrokePaintsTheBackOfADoubleSidedLeafOnly) {
    core::Document doc;
    doc.setMesh(leaves(false), "leaves");
    core::PaintTargetOptions options;
    options.resolution = 64;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    core_test::CpuScriptHost host;
    ASSERT_TRUE(host.buildDepthLayers(doc, pixelView(kWidth, kHeight)).ok());
    doc.brush().radius = 4.0f;
    const auto page = [&doc] {
        return dynamic_cast<const core::TextureTarget&>(*doc.currentPaintTarget()).page(0).rgba;
    };
    const std::vector<std::uint8_t> before = page();
    core::PaintChanges changes;
    for (const glm::vec2 at : {glm::vec2(80.0f, 30.0f), glm::vec2(20.0f, 30.0f)}) {
        const std::vector<std::uint8_t> was = page();
        ASSERT_TRUE(doc.beginStroke({at, 1.0f}, changes).ok());
        doc.endStroke(changes);
        if (at.x > 48.0f)
            EXPECT_EQ(page(), was) << "the single-sided leaf's back was painted";
        else
            EXPECT_NE(page(), was) << "the double-sided leaf's back was not painted";
    }
    EXPECT_NE(page(), before);
}

} // namespace double_sided_test
