// SPDX-License-Identifier: GPL-3.0-or-later
// The Document's region order in use: intentional and automatic pop-up, paint-to-hide, the
// pivot of layer-aware rotation, on a hand-made scene whose layers are known.
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/document/document.h"
#include "tests/core/test_scenes.h"

namespace document_order_test {

using core::kNone;
using core_test::pixelView;

constexpr int kWidth = 96, kHeight = 64;

/**
 * A back quad over the whole left two thirds (depth 8) and a front quad (depth 4) over its
 * right half and beyond: where both are, the back quad is layer 2. Neither touches the other,
 * so the regions are: front (layer 1), back's uncovered part (layer 1), back's covered part
 * (layer 2).
 */
struct Scene {
    core::Document doc;
    core::CpuDepthCapturer capturer;
    core::View view = pixelView(kWidth, kHeight);

    Scene() {
        doc.setMesh(core_test::overlappingQuads(), "two quads");
        capturer.setMesh(doc.mesh());
        core::DepthLayerOptions options;
        doc.setDepthLayerOptions(options);
        const core::Status built = doc.buildDepthLayers(capturer, view);
        EXPECT_TRUE(built.ok()) << built.error();
    }
    const core::DepthLayers& depthLayers() const { return *doc.depthLayers(); }
    static std::size_t pixel(int x, int y) { return std::size_t(y) * kWidth + std::size_t(x); }
    std::uint32_t visibleLayer(int x, int y) const {
        const std::uint32_t f = doc.visibleFragment(pixel(x, y));
        return f == kNone ? 0 : f - depthLayers().stack.offsets[pixel(x, y)] + 1;
    }
    std::uint32_t regionAt(int x, int y, std::uint32_t layer) const {
        const std::uint32_t f = depthLayers().stack.fragment(pixel(x, y), layer);
        return f == kNone ? kNone : depthLayers().segmentation.region[f];
    }
};

TEST(DocumentOrder, StartsWithLayerOneVisibleEverywhere) {
    Scene s;
    ASSERT_NE(s.doc.depthLayers(), nullptr);
    EXPECT_EQ(s.depthLayers().segmentation.graph.regions.size(), 3u);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const bool any = s.depthLayers().stack.layerCount(Scene::pixel(x, y)) > 0;
            EXPECT_EQ(s.visibleLayer(x, y), any ? 1u : 0u) << x << "," << y;
        }
    EXPECT_EQ(s.visibleLayer(0, 0), 0u); // background
}

TEST(DocumentOrder, ClicksCycleThroughThePixelsRegionsAndBack) {
    Scene s;
    const std::uint64_t serial = s.doc.regionOrderSerial();
    const glm::vec2 overlap(50.5f, 30.5f);
    EXPECT_EQ(s.doc.popUpAt(overlap), s.regionAt(50, 30, 2));
    EXPECT_GT(s.doc.regionOrderSerial(), serial);
    EXPECT_EQ(s.visibleLayer(50, 30), 2u);
    // The whole covered part of the back quad shows, the front quad elsewhere is still in front.
    EXPECT_EQ(s.visibleLayer(40, 20), 2u);
    EXPECT_EQ(s.visibleLayer(80, 30), 1u);
    EXPECT_EQ(s.doc.popUpAt(overlap), s.regionAt(50, 30, 1));
    EXPECT_EQ(s.visibleLayer(50, 30), 1u);
    // Background and outside the view: nothing.
    EXPECT_EQ(s.doc.popUpAt({1.5f, 1.5f}), kNone);
    EXPECT_EQ(s.doc.popUpAt({-3.0f, 10.0f}), kNone);
    EXPECT_EQ(s.doc.popUpAt({500.0f, 10.0f}), kNone);
}

TEST(DocumentOrder, HidingRevealsWhatLiesBehindAndTakesNoPaint) {
    Scene s;
    const std::vector<std::uint32_t> before = s.doc.regionRanks();
    // A short drag over the front quad, away from the back one.
    EXPECT_EQ(s.doc.hideAlong({70.0f, 30.0f}, {80.0f, 30.0f}, 3.0f, before), 1u);
    EXPECT_TRUE(s.doc.regionOrder().isHidden(s.regionAt(70, 30, 1)));
    EXPECT_EQ(s.visibleLayer(80, 30), 0u); // nothing behind it there
    EXPECT_EQ(s.visibleLayer(50, 30), 2u); // the back quad shows through
    // The same drag with the old ranks hides nothing more: a stroke does not drill through.
    EXPECT_EQ(s.doc.hideAlong({70.0f, 30.0f}, {80.0f, 30.0f}, 3.0f, before), 0u);

    // A stroke on the revealed back quad never paints the hidden front quad's fragments.
    core::PaintChanges changes;
    s.doc.brush().radius = 12.0f;
    ASSERT_TRUE(s.doc.beginStroke({{50.0f, 30.0f}, 1.0f}, changes).ok());
    s.doc.moveStroke({{62.0f, 30.0f}, 1.0f}, changes);
    const core::StrokeTracker& tracker = s.doc.strokeTracker();
    std::size_t painted = 0;
    for (const std::uint32_t pixel : tracker.paintablePixels()) {
        const std::uint32_t layer = tracker.paintableLayer(pixel);
        const std::uint32_t f = s.depthLayers().stack.fragment(pixel, layer);
        ASSERT_NE(f, kNone);
        EXPECT_FALSE(s.doc.regionOrder().isHidden(s.depthLayers().segmentation.region[f]));
        ++painted;
    }
    EXPECT_GT(painted, 100u);
    s.doc.endStroke();

    core::RegionOrder order = s.doc.regionOrder();
    order.unhideAll();
    s.doc.setRegionOrder(order);
    EXPECT_EQ(s.visibleLayer(50, 30), 1u);
}

TEST(DocumentOrder, AStrokeGoingUnderAnotherSurfacePopsItsRegionUp) {
    for (const bool automatic : {true, false}) {
        Scene s;
        s.doc.setAutoPopUp(automatic);
        s.doc.brush().radius = 4.0f;
        core::PaintChanges changes;
        // From the back quad's uncovered part to under the front quad.
        ASSERT_TRUE(s.doc.beginStroke({{20.0f, 30.0f}, 1.0f}, changes).ok());
        s.doc.moveStroke({{50.0f, 30.0f}, 1.0f}, changes);
        s.doc.endStroke();
        EXPECT_EQ(s.visibleLayer(50, 30), automatic ? 2u : 1u) << automatic;
        EXPECT_EQ(s.visibleLayer(80, 30), 1u);
    }
}

TEST(DocumentOrder, ANewBuildStartsFromTheInitialOrder) {
    Scene s;
    s.doc.popUpAt({50.5f, 30.5f});
    ASSERT_EQ(s.visibleLayer(50, 30), 2u);
    ASSERT_TRUE(s.doc.buildDepthLayers(s.capturer, s.view).ok());
    EXPECT_EQ(s.visibleLayer(50, 30), 1u);
    // An order of other layers is refused.
    s.doc.setRegionOrder(core::RegionOrder{});
    EXPECT_EQ(s.doc.regionOrder().regionCount(), 3u);
}

TEST(DocumentOrder, ThePivotIsThePointOfTheVisibleFragment) {
    Scene s;
    const auto front = s.doc.surfacePoint({50.5f, 30.5f});
    ASSERT_TRUE(front.has_value());
    EXPECT_NEAR(front->z, -4.0f, 1e-3f);
    EXPECT_NEAR(front->x, 50.5f, 1e-3f);
    EXPECT_NEAR(front->y, 30.5f, 1e-3f);
    s.doc.popUpAt({50.5f, 30.5f});
    const auto back = s.doc.surfacePoint({50.5f, 30.5f});
    ASSERT_TRUE(back.has_value());
    EXPECT_NEAR(back->z, -8.0f, 1e-3f);
    EXPECT_FALSE(s.doc.surfacePoint({1.5f, 1.5f}).has_value());
}

} // namespace document_order_test
