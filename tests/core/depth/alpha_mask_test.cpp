// SPDX-License-Identifier: GPL-3.0-or-later
// glTF's alphaMode MASK in the depth layers: where the base colour's alpha is below the cutoff
// there is no surface, so the surface behind is the visible one (and the one painted).
#include <gtest/gtest.h>

#include <cstdint>

#include "core/depth/alpha_mask.h"
#include "core/document/document.h"
#include "tests/core/script_host.h"
#include "tests/core/test_scenes.h"

namespace alpha_mask_test {

using core_test::pixelView;

constexpr int kWidth = 96, kHeight = 64;

/**
 * A quad of material 0 in front (depth 4) whose texture is transparent (alpha 0) on its left
 * half, opaque on its right, over a quad of material 1 behind (depth 8) covering the view.
 */
core::Mesh leafOverWall(core::AlphaMode mode) {
    core::Mesh mesh;
    core_test::addQuad(mesh,
                       {{16.0f, 8.0f}, {80.0f, 56.0f}, 4.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 2, 0});
    core_test::addQuad(mesh,
                       {{0.0f, 0.0f}, {96.0f, 64.0f}, 8.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 12, 1});
    core::Image texture;
    texture.width = 16;
    texture.height = 16;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            texture.rgba.insert(texture.rgba.end(), {200, 200, 200, std::uint8_t(x < 8 ? 0 : 255)});
    mesh.textures = {texture};
    mesh.materials.resize(2);
    mesh.materials[0].baseColorTexture = 0;
    mesh.materials[0].alphaMode = mode;
    mesh.materials[0].alphaCutoff = 0.5f;
    return mesh;
}

/** The triangle of the visible surface at pixel (x, y) of layers, or kNone. */
std::uint32_t visibleAt(const core::DepthStack& stack, int x, int y) {
    const std::size_t pixel = std::size_t(y) * kWidth + std::size_t(x);
    return stack.layerCount(pixel) > 0 ? stack.triangle[stack.fragment(pixel, 1)] : core::kNone;
}

TEST(AlphaMask, TheCaptureHasNoSurfaceWhereTheAlphaIsBelowTheCutoff) {
    for (const core::AlphaMode mode : {core::AlphaMode::Opaque, core::AlphaMode::Mask}) {
        core::Document doc;
        doc.setMesh(leafOverWall(mode), "leaf");
        core_test::CpuScriptHost host;
        ASSERT_TRUE(host.buildDepthLayers(doc, pixelView(kWidth, kHeight)).ok());
        const core::DepthStack& stack = doc.depthLayers()->stack;
        const bool masked = mode == core::AlphaMode::Mask;
        // Left half of the leaf: the wall (triangles 8 on) shows through a masked leaf.
        EXPECT_EQ(visibleAt(stack, 24, 32) >= 8, masked);
        EXPECT_EQ(stack.layerCount(32 * kWidth + 24), masked ? 1u : 2u);
        // Right half: the leaf either way; beside it only the wall.
        EXPECT_LT(visibleAt(stack, 72, 32), 8u);
        EXPECT_GE(visibleAt(stack, 4, 4), 8u);
    }
}

TEST(AlphaMask, AlphaIsFactorTimesTextureTimesVertexColour) {
    core::Mesh mesh = leafOverWall(core::AlphaMode::Mask);
    mesh.materials[0].baseColorFactor.a = 0.5f;
    mesh.colors.assign(mesh.vertexCount(), glm::vec4(1.0f, 1.0f, 1.0f, 0.5f));
    // Triangle 0 lies where u < 0.5 (transparent); triangle 3 where u > 0.5 (opaque).
    EXPECT_FLOAT_EQ(core::surfaceAlpha(mesh, 0, glm::vec3(1.0f / 3.0f)), 0.0f);
    const float opaque = core::surfaceAlpha(mesh, 3, glm::vec3(0.1f, 0.1f, 0.8f));
    EXPECT_NEAR(opaque, 0.25f, 0.01f); // 0.5 × 1 × 0.5
}

TEST(AlphaMask, AStrokeThroughTheTransparentPartPaintsTheWall) {
    core::Document doc;
    core::Mesh mesh = leafOverWall(core::AlphaMode::Mask);
    mesh.materials[1].baseColorTexture = -1;
    doc.setMesh(std::move(mesh), "leaf");
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::VertexColors;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    core_test::CpuScriptHost host;
    ASSERT_TRUE(host.buildDepthLayers(doc, pixelView(kWidth, kHeight)).ok());
    doc.brush().radius = 3.0f;
    doc.brush().color = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    const std::vector<glm::vec4> before = doc.paintedMesh().colors;
    core::PaintChanges changes;
    ASSERT_TRUE(doc.beginStroke({glm::vec2(24.0f, 32.0f), 1.0f}, changes).ok());
    doc.endStroke(changes);
    const std::vector<glm::vec4> after = doc.paintedMesh().colors;
    ASSERT_EQ(after.size(), before.size());
    bool wallPainted = false;
    for (std::size_t v = 0; v < after.size(); ++v) {
        if (v < 9) // the leaf's 3 × 3 vertices
            EXPECT_EQ(after[v], before[v]) << "leaf vertex " << v << " was painted";
        else
            wallPainted = wallPainted || after[v] != before[v];
    }
    EXPECT_TRUE(wallPainted);
}

} // namespace alpha_mask_test
