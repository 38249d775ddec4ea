// SPDX-License-Identifier: GPL-3.0-or-later
// A straight line (Document::lineTo, the GUI's Shift+click) on layers of a real capture
// (headless EGL, llvmpipe on CI): from a stroke that ended on a surface hidden behind another,
// the line runs on along that hidden surface, behind the occluder, as any layer-aware stroke.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "tests/core/test_scenes.h"
#include "tests/render/gl_test.h"

#include "core/document/document.h"
#include "core/paint/targets/paint_target.h"
#include "render/gl_depth_capturer.h"

namespace stroke_line_gltest {

using core_test::addQuad;
using core_test::pixelView;

constexpr int kWidth = 96, kHeight = 64;

class StrokeLineGlTest : public render_test::GlTest {
protected:
    void SetUp() override {
        ASSERT_TRUE(s_context);
        const core::Status status = m_capturer.initialize();
        ASSERT_TRUE(status) << status.error();
    }
    void TearDown() override { m_capturer.depthCapture().release(); }

    /**
     * A back quad (depth 8, u 0..0.5) whose middle a front quad (depth 4, u 0.5..1) covers:
     * under x 36..92, y 16..48 the back quad is depth layer 2.
     */
    std::unique_ptr<core::Document> open() {
        core::Mesh mesh;
        addQuad(mesh, {{4.0f, 8.0f}, {64.0f, 56.0f}, 8.0f, {0.0f, 0.0f}, {0.5f, 1.0f}, 4});
        addQuad(mesh, {{36.0f, 16.0f}, {92.0f, 48.0f}, 4.0f, {0.5f, 0.0f}, {1.0f, 1.0f}, 4});
        auto doc = std::make_unique<core::Document>();
        doc->setMesh(std::move(mesh), "two quads");
        core::PaintTargetOptions options;
        options.resolution = 128;
        EXPECT_TRUE(doc->setPaintTarget(options).ok());
        m_capturer.setMesh(doc->mesh());
        const core::Status status = doc->buildDepthLayers(m_capturer, pixelView(kWidth, kHeight));
        EXPECT_TRUE(status) << status.error();
        doc->brush().radius = 3.0f;
        doc->brush().hardness = 1.0f;
        doc->setLayerAware(true);
        doc->setAutoPopUp(false); // the back quad stays behind: what is drawn does not change
        return doc;
    }

    /** The texels of the front quad's half of the page (clear of the seam padding). */
    static std::vector<std::uint8_t> frontHalf(const core::Document& doc) {
        const core::Image& page =
            dynamic_cast<const core::TextureTarget&>(*doc.currentPaintTarget()).page(0);
        std::vector<std::uint8_t> out;
        for (int y = 0; y < page.height; ++y)
            for (int x = page.width / 2 + 4; x < page.width; ++x)
                for (int c = 0; c < 4; ++c)
                    out.push_back(
                        page.rgba[4 * (std::size_t(y) * std::size_t(page.width) + std::size_t(x)) +
                                  std::size_t(c)]);
        return out;
    }

    render::GlDepthCapturer m_capturer;
};

std::size_t pixelOf(glm::vec2 p) {
    return std::size_t(p.y) * std::size_t(kWidth) + std::size_t(p.x);
}

TEST_F(StrokeLineGlTest, ALineFromAHiddenSurfaceRunsBehindTheOccluderOnIt) {
    std::unique_ptr<core::Document> doc = open();
    ASSERT_NE(doc->depthLayers(), nullptr);
    const core::DepthStack& stack = doc->depthLayers()->stack;
    ASSERT_EQ(stack.layerCount(pixelOf({58.0f, 42.0f})), 2u) << "both quads there";
    const std::vector<std::uint8_t> front = frontHalf(*doc);

    // A stroke from the back quad's open part in under the front quad.
    core::PaintChanges changes;
    ASSERT_TRUE(doc->beginStroke({{14.0f, 30.0f}, 1.0f}, changes).ok());
    doc->moveStroke({{30.0f, 30.0f}, 1.0f}, changes);
    doc->moveStroke({{50.0f, 30.0f}, 1.0f}, changes);
    doc->endStroke(changes);
    ASSERT_EQ(frontHalf(*doc), front);
    ASSERT_TRUE(doc->lineStart());

    // The line from there: its dabs are on layer 2 (the back quad) all the way to the click.
    ASSERT_TRUE(doc->lineTo({{58.0f, 42.0f}, 1.0f}, changes).ok());
    EXPECT_FALSE(changes.texels.empty());
    EXPECT_EQ(doc->strokeTracker().paintableLayer(pixelOf({58.0f, 42.0f})), 2u);
    EXPECT_EQ(frontHalf(*doc), front) << "the front quad took no paint";
    EXPECT_EQ(doc->visibleFragment(pixelOf({58.0f, 42.0f})),
              stack.fragment(pixelOf({58.0f, 42.0f}), 1))
        << "and still covers it";

    // Started on the front quad instead (what a plain click there would do), it paints that.
    core::PaintChanges undone;
    ASSERT_TRUE(doc->undo(undone));
    ASSERT_TRUE(doc->line({{50.0f, 30.0f}, 1.0f}, {{58.0f, 42.0f}, 1.0f}, changes).ok());
    EXPECT_EQ(doc->strokeTracker().paintableLayer(pixelOf({58.0f, 42.0f})), 1u);
    EXPECT_NE(frontHalf(*doc), front);
}

} // namespace stroke_line_gltest
