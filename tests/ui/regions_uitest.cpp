// SPDX-License-Identifier: GPL-3.0-or-later
// The region operations in the GUI through real Qt event delivery: Ctrl+Shift+click and the pop-up
// tool cycle the regions at a pixel, paint-to-hide on the segmentation map with its panel,
// undo of order changes, reset, and layer-aware rotation about a popped-up surface point.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <memory>

#include <glm/geometric.hpp>

#include "core/document/document.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/panels/hidden_regions_panel.h"
#include "ui/shell/main_window.h"
#include "ui/tools/region_tools.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace regions_uitest {

using namespace ui_test;

class RegionsTest : public WindowTest {
protected:
    RegionsTest() : WindowTest({1100, 720}) {}

    void SetUp() override {
        WindowTest::SetUp();
        if (HasFatalFailure())
            return;
        WindowTest::openTrefoil();
        if (HasFatalFailure())
            return;
        ASSERT_TRUE(viewport()->isShowingDepthLayers());
        // Device pixels are logical ones here, so the layers' pixels are the widget's.
        ASSERT_EQ(viewport()->devicePixelRatioF(), 1.0);
    }

    const core::DepthStack& stack() const { return document().depthLayers()->stack; }

    /** Layer (1-based) of the visible fragment at p, 0 for background. */
    std::uint32_t visibleLayer(QPoint p) const {
        const std::size_t pixel = std::size_t(p.y()) * std::size_t(stack().width) + p.x();
        const std::uint32_t f = document().visibleFragment(pixel);
        return f == core::kNone ? 0 : f - stack().offsets[pixel] + 1;
    }
    /** A pixel near the middle with at least layers fragments, and the same around it. */
    QPoint deepPixel(std::uint32_t layers) const {
        const core::DepthStack& s = stack();
        QPoint best(-1, -1);
        double bestDistance = 1e30;
        for (int y = 3; y < s.height - 3; ++y)
            for (int x = 3; x < s.width - 3; ++x) {
                bool deep = true;
                for (int dy = -2; dy <= 2 && deep; ++dy)
                    for (int dx = -2; dx <= 2 && deep; ++dx)
                        deep = s.layerCount(std::size_t(y + dy) * s.width + (x + dx)) >= layers;
                const double d = std::hypot(x - s.width / 2.0, y - s.height / 2.0);
                if (deep && d < bestDistance) {
                    bestDistance = d;
                    best = {x, y};
                }
            }
        return best;
    }
};

TEST_F(RegionsTest, CtrlShiftClickCyclesThroughTheRegionsAtAPixelAndUndoRestores) {
    const QPoint p = deepPixel(2);
    ASSERT_GE(p.x(), 0) << "no pixel with two layers";
    const std::uint32_t layers = stack().layerCount(std::size_t(p.y()) * stack().width + p.x());
    const QImage before = viewport()->grabFramebuffer();
    ASSERT_EQ(visibleLayer(p), 1u);

    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ControlModifier | Qt::ShiftModifier, p);
    EXPECT_EQ(visibleLayer(p), 2u);
    EXPECT_EQ(undoStack()->count(), 1);
    EXPECT_GT(differingFraction(before, viewport()->grabFramebuffer()), 0.001);
    EXPECT_EQ(document().history().undoKind(), core::StepKind::PopUp); // no paint

    // The pop-up tool (P) goes on cycling: deeper, then back to the top.
    QTest::keyClick(m_window.get(), Qt::Key_P);
    ASSERT_EQ(m_window->tool(), ui::Tool::PopUp);
    for (std::uint32_t k = 3; k <= layers; ++k) {
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, p);
        EXPECT_EQ(visibleLayer(p), k);
    }
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, p);
    EXPECT_EQ(visibleLayer(p), 1u);
    EXPECT_EQ(undoStack()->count(), int(layers));

    // Undo walks the order back; one more undo than clicks past the first leaves layer 2.
    for (std::uint32_t k = 0; k + 1 < layers; ++k)
        QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(visibleLayer(p), 2u);
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(visibleLayer(p), 1u);
    QTest::keyClick(m_window.get(), Qt::Key_B); // the pop-up tool highlights the hovered region
    // The same picture but for the brush outline now at the cursor (a ring of ~200 pixels).
    EXPECT_LE(differingFraction(before, viewport()->grabFramebuffer()), 0.003);
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(visibleLayer(p), 2u);

    // Reset (R) shows the initial order and is undoable too.
    QTest::keyClick(m_window.get(), Qt::Key_R);
    EXPECT_EQ(visibleLayer(p), 1u);
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(visibleLayer(p), 2u);
}

TEST_F(RegionsTest, PaintToHideRevealsWhatLiesBehindAndThePanelUnhides) {
    const QPoint p = deepPixel(2);
    ASSERT_GE(p.x(), 0);
    QTest::keyClick(m_window.get(), Qt::Key_H);
    ASSERT_EQ(m_window->tool(), ui::Tool::Hide);
    EXPECT_EQ(viewport()->display(), render::DepthLayerDisplay::Segmentation);

    const std::size_t pixel = std::size_t(p.y()) * std::size_t(stack().width) + p.x();
    const std::uint32_t front =
        document().depthLayers()->segmentation.region[stack().offsets[pixel]];
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, p);
    QTest::mouseMove(viewport(), p + QPoint(2, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, p + QPoint(2, 0));
    EXPECT_TRUE(document().regionOrder().isHidden(front));
    EXPECT_GE(visibleLayer(p), 2u);
    auto* panel = m_window->findChild<ui::HiddenRegionsPanel*>();
    ASSERT_NE(panel, nullptr);
    const std::vector<std::uint32_t> listed = panel->regions();
    EXPECT_NE(std::find(listed.begin(), listed.end(), front), listed.end());
    EXPECT_EQ(listed.size(), document().regionOrder().hiddenRegions().size());
    EXPECT_EQ(undoStack()->count(), 1);

    // A stroke of the brush on the revealed surface never paints the hidden region.
    QTest::keyClick(m_window.get(), Qt::Key_B);
    EXPECT_NE(viewport()->display(), render::DepthLayerDisplay::Segmentation);
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, p);
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, p);
    const core::StrokeTracker& tracker = document().strokeTracker();
    ASSERT_FALSE(tracker.paintablePixels().empty());
    for (const std::uint32_t q : tracker.paintablePixels()) {
        const std::uint32_t f = stack().fragment(q, tracker.paintableLayer(q));
        ASSERT_NE(f, core::kNone);
        EXPECT_FALSE(
            document().regionOrder().isHidden(document().depthLayers()->segmentation.region[f]));
    }

    // Unhide All in the panel, then undo brings the hiding back.
    auto* unhideAll = panel->findChild<QPushButton*>(QStringLiteral("unhideAllButton"));
    ASSERT_NE(unhideAll, nullptr);
    QTest::mouseClick(unhideAll, Qt::LeftButton);
    EXPECT_TRUE(document().regionOrder().hiddenRegions().empty());
    EXPECT_TRUE(panel->regions().empty());
    EXPECT_EQ(visibleLayer(p), 1u);
    undoStack()->undo();
    EXPECT_TRUE(document().regionOrder().isHidden(front));
}

TEST_F(RegionsTest, OrbitTurnsAboutThePoppedUpSurfacePointUnderTheCursor) {
    const QPoint p = deepPixel(2);
    ASSERT_GE(p.x(), 0);
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ControlModifier | Qt::ShiftModifier, p);
    ASSERT_EQ(visibleLayer(p), 2u);
    const std::size_t pixel = std::size_t(p.y()) * std::size_t(stack().width) + p.x();
    const float depth = stack().depth[stack().offsets[pixel] + 1];
    const core::View before = viewport()->view();

    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, p);
    for (int i = 1; i <= 10; ++i)
        QTest::mouseMove(viewport(), p + QPoint(6 * i, 3 * i));
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, p + QPoint(60, 30));
    const auto pivot = viewport()->orbitPivot();
    ASSERT_TRUE(pivot.has_value());
    // The pivot is the layer-2 fragment's point, not the front surface's.
    const glm::vec3 expected = before.unproject({p.x() + 0.5f, p.y() + 0.5f}, depth);
    EXPECT_LT(glm::distance(*pivot, expected), 1e-3f * (1.0f + glm::length(expected)));
    // It stayed under the press position while the view turned.
    const glm::vec3 now = viewport()->view().project(*pivot);
    EXPECT_NEAR(now.x, p.x() + 0.5f, 1.0f);
    EXPECT_NEAR(now.y, p.y() + 0.5f, 1.0f);
    EXPECT_NE(viewport()->view().view, before.view);
}

} // namespace regions_uitest
