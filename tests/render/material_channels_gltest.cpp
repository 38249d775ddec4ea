// SPDX-License-Identifier: GPL-3.0-or-later
// draw_layers with metallic-roughness (headless EGL, llvmpipe on CI): roughness and metallic
// painted into a paint layer reach the compositor tile by tile, the Roughness and Metallic
// channels show the painted values as grey, and the lit Material tells metal from non-metal.
#include <algorithm>
#include <array>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/render/gl_test.h"

#include "core/document/document.h"
#include "core/io/image/image_write.h"
#include "core/model/camera.h"
#include "core/paint/targets/paint_target.h"
#include "render/depth_compositor.h"
#include "render/gl_depth_capturer.h"
#include "render/offscreen_target.h"

namespace material_channels_gltest {

constexpr int kWidth = 200;
constexpr int kHeight = 120;

/** A square facing the camera (pixels 60-140 × 20-100), uv mapped to a grey 256² texture. */
core::Mesh texturedSquare() {
    core::Mesh mesh;
    mesh.positions = {
        {-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 0.0f}, {-1.0f, 1.0f, 0.0f}};
    mesh.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
    mesh.uvs = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.triangleMaterial = {0, 0};
    core::Image texture{256, 256, {}};
    texture.rgba.assign(256 * 256 * 4, 160);
    mesh.textures = {texture};
    mesh.materials = {core::Material{"grey", glm::vec4(1.0f), 0}};
    return mesh;
}

class MaterialChannelsGlTest : public render_test::GlCaptureTest {
protected:
    void SetUp() override {
        ASSERT_NO_FATAL_FAILURE(GlCaptureTest::SetUp());
        const core::Status status = m_compositor.initialize();
        ASSERT_TRUE(status) << status.error();
    }
    void TearDown() override {
        m_compositor.release();
        GlCaptureTest::TearDown();
    }

    core::Image draw(render::MaterialChannel channel, const std::string& name) {
        render::CompositeOptions options;
        options.channel = channel;
        core::Image image = render_test::drawComposite(m_compositor, kWidth, kHeight, options);
        if (const char* dir = std::getenv("LAYERPAINT_TEST_IMAGES"); dir && *dir) {
            EXPECT_TRUE(core::writeImage(std::string(dir) + "/" + name + ".png", image.width,
                                         image.height, 4, core::PixelType::UInt8,
                                         image.rgba.data()));
        }
        return image;
    }

    /** A short horizontal stroke around pixel (x, y); what each call painted goes to changes. */
    void stroke(core::Document& doc, float x, float y, core::PaintChanges& changes) {
        core::PaintChanges step;
        ASSERT_TRUE(doc.beginStroke({{x - 4.0f, y}, 1.0f}, step));
        changes.texels.insert(changes.texels.end(), step.texels.begin(), step.texels.end());
        doc.moveStroke({{x + 4.0f, y}, 1.0f}, step);
        changes.texels.insert(changes.texels.end(), step.texels.begin(), step.texels.end());
        doc.endStroke();
    }

    render::DepthCompositor m_compositor;
};

std::array<int, 3> rgb(const core::Image& image, int x, int y) {
    const std::size_t i = (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4;
    return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]};
}

TEST_F(MaterialChannelsGlTest, PaintedRoughnessAndMetallicShowInTheirChannelsAndTheMaterial) {
    core::Document doc;
    doc.setMesh(texturedSquare(), "square");
    core::Camera camera;
    camera.frame(doc.mesh().bounds());
    doc.camera() = camera;
    m_capturer.setMesh(doc.mesh());
    ASSERT_TRUE(doc.buildDepthLayers(m_capturer, camera.view(kWidth, kHeight)));

    core::PaintChanges changes;
    auto layer = doc.addPaintLayer({.name = "material"}, changes);
    ASSERT_TRUE(layer) << layer.error();
    const auto* target = dynamic_cast<const core::TextureTarget*>(doc.paintTarget());
    ASSERT_NE(target, nullptr);

    // Shown before painting, as the viewport does; painting then updates touched texels only.
    ASSERT_TRUE(m_compositor.setMesh(doc.paintedMesh()));
    m_compositor.textures().setMetallicRoughness(0, target->metallicRoughnessPage(0));
    ASSERT_TRUE(m_compositor.setDepthLayers(*doc.depthLayers()));
    const core::Image before = draw(render::MaterialChannel::Material, "material_before");

    core::Brush& brush = doc.brush();
    brush.radius = 8.0f;
    brush.hardness = 1.0f;
    brush.paintBaseColor = false;
    brush.paintRoughness = true;
    brush.paintMetallic = true;
    brush.roughness = 0.2f; // byte 51
    brush.metallic = 1.0f;
    changes.clear();
    stroke(doc, 78.0f, 60.0f, changes);
    brush.metallic = 0.0f;
    stroke(doc, 122.0f, 60.0f, changes);
    ASSERT_FALSE(changes.texels.empty());
    for (const core::TexelRect& r : changes.texels) {
        EXPECT_LT(std::size_t(r.width) * std::size_t(r.height), std::size_t(256 * 256));
        m_compositor.textures().updateTexels(r.page, r.x, r.y, r.width, r.height,
                                             target->page(r.page));
        m_compositor.textures().updateMetallicRoughness(r.page, r.x, r.y, r.width, r.height,
                                                        target->metallicRoughnessPage(r.page));
    }

    const core::Image roughness = draw(render::MaterialChannel::Roughness, "channel_roughness");
    const core::Image metallic = draw(render::MaterialChannel::Metallic, "channel_metallic");
    const core::Image material = draw(render::MaterialChannel::Material, "material_after");
    const core::Image base = draw(render::MaterialChannel::BaseColor, "channel_base");
    for (int x : {78, 122}) {
        const auto r = rgb(roughness, x, 60);
        EXPECT_NEAR(r[0], 51, 2) << "x " << x;
        EXPECT_EQ(r[0], r[1]);
        EXPECT_EQ(r[1], r[2]);
        // Base colour was not painted: the grey texture, unlit.
        EXPECT_NEAR(rgb(base, x, 60)[0], 160, 3) << "x " << x;
    }
    EXPECT_NEAR(rgb(metallic, 78, 60)[0], 255, 2);
    EXPECT_NEAR(rgb(metallic, 122, 60)[0], 0, 2);
    // Unpainted: the base's roughness 1 and metal 0; background stays background.
    EXPECT_NEAR(rgb(roughness, 100, 30)[0], 255, 2);
    EXPECT_NEAR(rgb(metallic, 100, 30)[0], 0, 2);
    EXPECT_EQ(rgb(roughness, 2, 2), rgb(before, 2, 2));

    // The lit material: metal (tinted reflections, no diffuse) against smooth plastic, and both
    // against the rough surface around them, which looks as before painting.
    int metalVsPlastic = 0;
    for (int c = 0; c < 3; ++c)
        metalVsPlastic += std::abs(rgb(material, 78, 60)[c] - rgb(material, 122, 60)[c]);
    EXPECT_GT(metalVsPlastic, 30);
    EXPECT_NE(rgb(material, 78, 60), rgb(before, 78, 60));
    EXPECT_EQ(rgb(material, 100, 30), rgb(before, 100, 30));
}

} // namespace material_channels_gltest
