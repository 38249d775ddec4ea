// SPDX-License-Identifier: GPL-3.0-or-later
// Document::raiseTextureSize(): a material's texture page made larger with what it holds, as one
// undoable step and as the script operation raise-texture-size; refused with a clear message
// where it cannot be done (no texture, not larger); paint layers go along, resampled.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>

#include "core/document/document.h"
#include "core/document/script.h"
#include "core/document/session_log.h"
#include "core/paint/targets/layout_target.h"
#include "tests/core/script_host.h"
#include "tests/core/test_scenes.h"

namespace texture_size_test {

/** The texel (x, y) of image. */
std::array<std::uint8_t, 4> texel(const core::Image& image, int x, int y) {
    const std::size_t i = (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4;
    return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2], image.rgba[i + 3]};
}

/** A quad over the whole UV square with a 64 × 32 texture: left half red, right half blue. */
core::Mesh texturedQuad() {
    core::Mesh mesh;
    mesh.positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.triangleMaterial = {0, 0};
    mesh.computeNormals();
    core::Image image;
    image.width = 64;
    image.height = 32;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x)
            image.rgba.insert(image.rgba.end(), {std::uint8_t(x < 32 ? 255 : 0), 0,
                                                 std::uint8_t(x < 32 ? 0 : 255), 255});
    mesh.textures.push_back(image);
    mesh.materials = {{"painted", glm::vec4(1.0f), 0}};
    return mesh;
}

core::PaintTargetOptions texture() {
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::Texture;
    return options;
}

TEST(TextureSize, RaisingResamplesThePageAsOneUndoableStep) {
    core::Document doc;
    doc.setMesh(texturedQuad(), "quad");
    ASSERT_TRUE(doc.setPaintTarget(texture()).ok());
    ASSERT_EQ(doc.paintTarget()->page(0).width, 64);

    const core::Status raised = doc.raiseTextureSize(0, 256);
    ASSERT_TRUE(raised.ok()) << raised.error();
    const core::Image& page = doc.paintTarget()->page(0);
    ASSERT_EQ(page.width, 256);
    ASSERT_EQ(page.height, 128); // in proportion
    EXPECT_EQ(texel(page, 10, 10), (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
    EXPECT_EQ(texel(page, 250, 120), (std::array<std::uint8_t, 4>{0, 0, 255, 255}));
    // Across the edge the halves blend as the texels' centres say.
    EXPECT_EQ(texel(page, 127, 0)[0], 159); // 255 · (1 - 0.375)
    EXPECT_EQ(core::texturePageSizes(doc.paintedMesh(), texture())[0], (core::PageSize{256, 128}));

    core::PaintChanges changes;
    ASSERT_TRUE(doc.undo(changes));
    EXPECT_EQ(doc.paintTarget()->page(0).width, 64);
    ASSERT_TRUE(doc.redo(changes));
    EXPECT_EQ(doc.paintTarget()->page(0).width, 256);
}

TEST(TextureSize, RefusedWithAReason) {
    core::Document doc;
    doc.setMesh(texturedQuad(), "quad");
    core::PaintTargetOptions colours;
    colours.kind = core::PaintTargetKind::VertexColors;
    ASSERT_TRUE(doc.setPaintTarget(colours).ok());
    EXPECT_EQ(doc.raiseTextureSize(0, 128).error(), "the paint target is not a texture");

    ASSERT_TRUE(doc.setPaintTarget(texture()).ok());
    EXPECT_EQ(doc.raiseTextureSize(1, 128).error(), "there is no material 1 (the model has 1)");
    EXPECT_EQ(doc.raiseTextureSize(0, 64).error(),
              "the texture is 64 × 32 already: give a larger width");
    EXPECT_EQ(doc.raiseTextureSize(0, 16384).error(),
              "a texture can be at most 8192 texels on a side");
}

TEST(TextureSize, PaintLayersAreResampledWithThePage) {
    core::Document doc;
    doc.setMesh(texturedQuad(), "quad");
    ASSERT_TRUE(doc.setPaintTarget(texture()).ok());
    core::PaintChanges changes;
    ASSERT_TRUE(doc.addPaintLayer(core::PaintLayerSettings{"green"}, changes).ok());
    {
        // Texels x 8..23, y 8..23 of the layer painted green, fully covered.
        core::PaintLayerStack& stack = (*doc.paintLayerTarget())->paintLayerStack();
        core::TiledPlane& plane = *stack.channelPlane(0, core::PaintChannel::BaseColor);
        for (int y = 8; y < 24; ++y)
            for (int x = 8; x < 24; ++x) {
                std::uint8_t* t = plane.writableTexel(0, x, y);
                t[0] = 0, t[1] = 200, t[2] = 0, t[3] = 255;
            }
        stack.updateAll();
    }
    const core::Status raised = doc.raiseTextureSize(0, 256);
    ASSERT_TRUE(raised.ok()) << raised.error();
    const core::PaintLayerStack& stack = (*doc.paintLayerTarget())->paintLayerStack();
    ASSERT_EQ(stack.size(), 1u);
    EXPECT_EQ(stack.layer(0).settings.name, "green");
    const core::TiledPlane& plane = *stack.layer(0).channels[0];
    ASSERT_EQ(plane.pages()[0], (core::PageSize{256, 128}));
    // Inside: the paint; outside: unpainted; at the edge the coverage falls off but the colour
    // stays the paint's (not darkened towards the unpainted texels' zeros).
    EXPECT_EQ(plane.texel(0, 64, 64)[1], 200);
    EXPECT_EQ(plane.texel(0, 64, 64)[3], 255);
    EXPECT_EQ(plane.texel(0, 10, 10)[3], 0);
    const std::uint8_t* edge = plane.texel(0, 32, 64);
    EXPECT_GT(edge[3], 0);
    EXPECT_LT(edge[3], 255);
    EXPECT_EQ(edge[1], 200);
    // The composite: the paint over the base, the base (red) elsewhere; the base is the
    // resampled base, not the old composite.
    const core::Image& page = doc.paintTarget()->page(0);
    EXPECT_EQ(texel(page, 64, 64), (std::array<std::uint8_t, 4>{0, 200, 0, 255}));
    EXPECT_EQ(texel(page, 10, 10), (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
    const std::vector<std::uint8_t>& base = stack.baseColor(0);
    const std::size_t at = (64 * 256 + 64) * 4;
    EXPECT_EQ(base[at], 255);
    EXPECT_EQ(base[at + 1], 0);

    ASSERT_TRUE(doc.undo(changes));
    const core::PaintLayerStack& before = (*doc.paintLayerTarget())->paintLayerStack();
    EXPECT_EQ(before.layer(0).channels[0]->pages()[0], (core::PageSize{64, 32}));
    EXPECT_EQ(doc.paintTarget()->page(0).width, 64);
}

TEST(TextureSize, TheScriptOperationRaisesAndIsLogged) {
    core::Document doc;
    doc.setMesh(texturedQuad(), "quad");
    ASSERT_TRUE(doc.setPaintTarget(texture()).ok());
    core_test::CpuScriptHost host;
    core::ScriptRunner runner(doc, host, core_test::pixelView(80, 60));
    const core::Status status =
        runner.run(nlohmann::json{{"op", "raise-texture-size"}, {"material", 0}, {"width", 128}});
    ASSERT_TRUE(status.ok()) << status.error();
    EXPECT_EQ(doc.paintTarget()->page(0).width, 128);
    EXPECT_FALSE(
        runner.run(nlohmann::json{{"op", "raise-texture-size"}, {"material", 0}, {"width", "big"}})
            .ok());
    const std::string log = doc.session().script().operations.dump();
    EXPECT_NE(log.find(R"({"material":0,"op":"raise-texture-size","width":128})"),
              std::string::npos)
        << log;
}

} // namespace texture_size_test
