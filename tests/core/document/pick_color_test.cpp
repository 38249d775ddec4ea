// SPDX-License-Identifier: GPL-3.0-or-later
// The eyedropper in the controller: Document::pickColor returns the paint target's unlit colour
// of the visible fragment (texture texel or vertex colour), honouring hidden regions, and the
// pressure curve that maps pen pressure.
#include <cmath>
#include <cstdint>
#include <optional>

#include <gtest/gtest.h>

#include "core/base/color.h"
#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/paint/brush/dab.h"
#include "core/paint/targets/paint_target.h"
#include "tests/core/test_scenes.h"

namespace pick_color_test {

using core_test::addQuad;
using core_test::pixelView;

constexpr int kWidth = 80, kHeight = 60;
const glm::vec4 kFront(0.6f, 0.1f, 0.05f, 1.0f);
const glm::vec4 kBack(0.05f, 0.2f, 0.7f, 1.0f);

/** A back quad over most of the view and a front quad across its middle, on one texture page. */
core::Mesh twoQuads() {
    core::Mesh mesh;
    mesh.materials = {{"front", kFront, -1}, {"back", kBack, -1}};
    addQuad(mesh, {{30.25f, 5.25f}, {49.75f, 54.75f}, 4.0f, {0.0f, 0.0f}, {0.5f, 1.0f}, 1, 0});
    addQuad(mesh, {{5, 10}, {75, 50}, 8.0f, {0.5f, 0.0f}, {1.0f, 1.0f}, 1, 1});
    return mesh;
}

std::size_t pixelAt(int x, int y) {
    return std::size_t(y) * kWidth + std::size_t(x);
}

/** The colour after a round trip through an sRGB byte, as a texture page stores it. */
glm::vec4 quantized(const glm::vec4& c) {
    return {core::srgbToLinear(core::linearToSrgb(c.r)),
            core::srgbToLinear(core::linearToSrgb(c.g)),
            core::srgbToLinear(core::linearToSrgb(c.b)), 1.0f};
}

void expectColor(const std::optional<glm::vec4>& got, const glm::vec4& want, float tolerance,
                 const char* what) {
    ASSERT_TRUE(got.has_value()) << what;
    for (int c = 0; c < 4; ++c)
        EXPECT_NEAR((*got)[c], want[c], tolerance) << what << ", channel " << c;
}

class PickColorTest : public ::testing::Test {
protected:
    void build(core::Mesh mesh, const core::PaintTargetOptions& options = {}) {
        m_doc.setMesh(std::move(mesh), "quads");
        ASSERT_TRUE(m_doc.setPaintTarget(options).ok());
        core::CpuDepthCapturer capturer;
        capturer.setMesh(m_doc.mesh());
        const core::Status status = m_doc.buildDepthLayers(capturer, pixelView(kWidth, kHeight));
        ASSERT_TRUE(status.ok()) << status.error();
    }

    void stroke(glm::vec2 from, glm::vec2 to) {
        core::PaintChanges changes;
        ASSERT_TRUE(m_doc.beginStroke({from, 1.0f}, changes).ok());
        m_doc.moveStroke({to, 1.0f}, changes);
        m_doc.endStroke();
    }

    core::Document m_doc;
};

TEST_F(PickColorTest, PicksTheTextureColourOfTheVisibleSurface) {
    build(twoQuads());
    ASSERT_EQ(m_doc.paintTarget()->kind(), core::PaintTargetKind::Texture);
    expectColor(m_doc.pickColor(pixelAt(40, 30)), quantized(kFront), 1e-6f, "front quad");
    expectColor(m_doc.pickColor(pixelAt(10, 30)), quantized(kBack), 1e-6f, "back quad");
    EXPECT_FALSE(m_doc.pickColor(pixelAt(2, 2)).has_value()) << "background";
    EXPECT_FALSE(m_doc.pickColor(std::size_t(kWidth) * kHeight).has_value()) << "outside";

    // Hiding the front quad's region shows, and picks, the back quad behind it.
    const core::DepthLayers& layers = *m_doc.depthLayers();
    const std::uint32_t front = m_doc.visibleFragment(pixelAt(40, 30));
    ASSERT_NE(front, core::kNone);
    core::RegionOrder order = m_doc.regionOrder();
    order.hide(layers.segmentation.region[front]);
    m_doc.setRegionOrder(order);
    expectColor(m_doc.pickColor(pixelAt(40, 30)), quantized(kBack), 1e-6f, "behind hidden");
}

TEST_F(PickColorTest, PicksAPoppedUpSurface) {
    build(twoQuads());
    const std::size_t pixel = pixelAt(40, 30);
    const core::DepthStack& stack = m_doc.depthLayers()->stack;
    ASSERT_EQ(stack.layerCount(pixel), 2u);
    // Pop up the back quad's region where the front quad covers it: the pick follows.
    const std::uint32_t back = stack.fragment(pixel, 2);
    ASSERT_TRUE(m_doc.popUpRegion(m_doc.depthLayers()->segmentation.region[back]));
    ASSERT_EQ(m_doc.visibleFragment(pixel), back);
    expectColor(m_doc.pickColor(pixel), quantized(kBack), 1e-6f, "popped up");
}

TEST_F(PickColorTest, PicksWhatWasJustPainted) {
    build(twoQuads());
    m_doc.brush().color = {0.9f, 0.7f, 0.02f, 1.0f};
    m_doc.brush().radius = 4.0f;
    m_doc.brush().hardness = 1.0f;
    stroke({36.5f, 30.5f}, {44.5f, 30.5f});
    expectColor(m_doc.pickColor(pixelAt(40, 30)), quantized(m_doc.brush().color), 1e-6f,
                "stroke centre");
    // Away from the stroke the surface keeps its colour.
    expectColor(m_doc.pickColor(pixelAt(40, 10)), quantized(kFront), 1e-6f, "unpainted");
    // The eraser end brings the original back.
    m_doc.brush().eraser = true;
    stroke({36.5f, 30.5f}, {44.5f, 30.5f});
    expectColor(m_doc.pickColor(pixelAt(40, 30)), quantized(kFront), 1e-6f, "erased");
}

TEST_F(PickColorTest, PicksInterpolatedVertexColours) {
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::VertexColors;
    build(twoQuads(), options);
    ASSERT_EQ(m_doc.paintTarget()->kind(), core::PaintTargetKind::VertexColors);
    expectColor(m_doc.pickColor(pixelAt(40, 30)), kFront, 1e-6f, "front quad");
    // A stroke that covers every corner of the front quad paints it all.
    m_doc.brush().color = {0.1f, 0.8f, 0.3f, 1.0f};
    m_doc.brush().radius = 40.0f;
    m_doc.brush().hardness = 1.0f;
    m_doc.setLayerAware(false);
    stroke({40.5f, 29.5f}, {40.5f, 30.5f});
    expectColor(m_doc.pickColor(pixelAt(33, 8)), m_doc.brush().color, 1e-5f, "painted");
}

TEST_F(PickColorTest, FollowsTheUvsIntoTheTexture) {
    // A 2 × 2 texture on one quad: each quarter of the quad shows, and picks, one texel.
    core::Mesh mesh;
    core::Image image;
    image.width = image.height = 2;
    image.rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255};
    mesh.textures.push_back(image);
    mesh.materials = {{"textured", glm::vec4(1.0f), 0}};
    addQuad(mesh, {{10, 10}, {70, 50}, 5.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 1, 0});
    build(std::move(mesh));
    expectColor(m_doc.pickColor(pixelAt(20, 20)), {1, 0, 0, 1}, 1e-6f, "top left");
    expectColor(m_doc.pickColor(pixelAt(60, 20)), {0, 1, 0, 1}, 1e-6f, "top right");
    expectColor(m_doc.pickColor(pixelAt(20, 45)), {0, 0, 1, 1}, 1e-6f, "bottom left");
    expectColor(m_doc.pickColor(pixelAt(60, 45)), {1, 1, 0, 1}, 1e-6f, "bottom right");
}

TEST_F(PickColorTest, NeedsLayers) {
    m_doc.setMesh(twoQuads(), "quads");
    EXPECT_FALSE(m_doc.pickColor(pixelAt(40, 30)).has_value());
}

TEST(PressureCurveTest, MapsPressureByGamma) {
    core::PressureCurve linear;
    EXPECT_FLOAT_EQ(linear.apply(0.3f), 0.3f);
    core::PressureCurve firm{2.0f};
    EXPECT_FLOAT_EQ(firm.apply(0.5f), 0.25f);
    EXPECT_FLOAT_EQ(firm.apply(1.0f), 1.0f); // a mouse is unaffected
    core::PressureCurve soft{0.5f};
    EXPECT_NEAR(soft.apply(0.25f), 0.5f, 1e-6f);
    EXPECT_FLOAT_EQ(soft.apply(0.0f), 0.0f);
    // Out of range: pressure and gamma are clamped, NaN is a full press.
    EXPECT_FLOAT_EQ(firm.apply(1.7f), 1.0f);
    EXPECT_FLOAT_EQ(firm.apply(-0.2f), 0.0f);
    EXPECT_FLOAT_EQ(firm.apply(std::nanf("")), 1.0f);
    core::PressureCurve extreme{100.0f};
    EXPECT_FLOAT_EQ(extreme.apply(0.5f), std::pow(0.5f, core::PressureCurve::kMaxGamma));
}

} // namespace pick_color_test
