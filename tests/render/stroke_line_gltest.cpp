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

using core_test::pixelView;

constexpr int kWidth = 96, kHeight = 64;

class StrokeLineGlTest : public render_test::GlCaptureTest {
protected:
    /** core_test::overlappingQuads() in a document, a 128² texture target, layers built. */
    std::unique_ptr<core::Document> open() {
        auto doc = std::make_unique<core::Document>();
        doc->setMesh(core_test::overlappingQuads(), "two quads");
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
        return core_test::frontHalfTexels(
            dynamic_cast<const core::TextureTarget&>(*doc.currentPaintTarget()).page(0));
    }
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
