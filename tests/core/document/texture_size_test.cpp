// SPDX-License-Identifier: GPL-3.0-or-later
// Document::raiseTextureSize(): a material's texture page made larger with what it holds, as one
// undoable step and as the script operation raise-texture-size; refused with a clear message
// where it cannot be done (paint layers, no texture, not larger).
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

    core::PaintChanges changes;
    ASSERT_TRUE(doc.addPaintLayer(core::PaintLayerSettings{}, changes).ok());
    const core::Status refused = doc.raiseTextureSize(0, 128);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().find("paint layers"), std::string::npos) << refused.error();
    EXPECT_EQ(doc.paintTarget()->page(0).width, 64) << "nothing changed";
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
