// SPDX-License-Identifier: GPL-3.0-or-later
// The stand-in through real Qt event delivery: with a low threshold the built-in trefoil gets a
// simplified stand-in in the background; an orbit drag and the wheel draw it, the settled view
// draws the full mesh, and painting after the orbit works on the full mesh's depth layers.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QApplication>
#include <QSignalSpy>
#include <QTest>
#include <QWheelEvent>

#include <set>
#include <vector>

#include "core/document/document.h"
#include "core/paint/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/view/layer_builder.h"
#include "ui/view/viewport.h"

namespace {

using namespace ui_test;

constexpr std::size_t kStandInTriangles = 20000;

class StandInTest : public WindowTest {
protected:
    StandInTest() : WindowTest({1000, 700}) {}

    /** Opens the trefoil with a low stand-in threshold and waits for its stand-in. */
    void openWithStandIn() {
        viewport()->setStandInTriangles(kStandInTriangles);
        openTrefoil();
        if (HasFatalFailure())
            return;
        ASSERT_TRUE(QTest::qWaitFor([&] { return viewport()->hasStandIn(); }, kBuildTimeoutMs));
    }

    std::size_t fullTriangles() const { return document().mesh().triangleCount(); }

    /** Distinct triangles with a fragment in the document's depth layers. */
    std::size_t capturedTriangles() const {
        const core::LayerStack& stack = document().layers()->stack;
        const std::set<std::uint32_t> triangles(stack.triangle.begin(), stack.triangle.end());
        return triangles.size();
    }
};

TEST_F(StandInTest, OrbitDrawsTheStandInAndTheSettledViewTheFullMesh) {
    openWithStandIn();
    if (HasFatalFailure())
        return;
    const std::size_t full = fullTriangles();
    ASSERT_GT(full, kStandInTriangles * 3 / 2);
    // The layers show: no triangles drawn by the mesh renderer.
    grab();
    EXPECT_EQ(viewport()->lastFrameTriangles(), 0u);

    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value());
    const float yaw = document().camera().yawDegrees;
    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, *start);
    QImage during;
    for (int i = 1; i <= 5; ++i) {
        QTest::mouseMove(viewport(), *start + QPoint(8 * i, 2 * i));
        during = grab();
        const std::size_t drawn = viewport()->lastFrameTriangles();
        EXPECT_GT(drawn, 0u);
        EXPECT_LE(drawn, kStandInTriangles);
    }
    EXPECT_NE(document().camera().yawDegrees, yaw);
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, *start + QPoint(40, 10));
    // Settled, before the new layers are there: the full mesh, from the same camera.
    const QImage settled = grab();
    ASSERT_FALSE(viewport()->isShowingLayers());
    EXPECT_EQ(viewport()->lastFrameTriangles(), full);
    // The stand-in looked like the model: a few pixels along the outline differ, not the shape
    // or its colours.
    const double differing = differingFraction(during, settled);
    EXPECT_GT(differing, 0.0);
    EXPECT_LT(differing, 0.05);
}

TEST_F(StandInTest, WheelDrawsTheStandInUntilItRests) {
    openWithStandIn();
    if (HasFatalFailure())
        return;
    const QPointF middle = QPointF(viewport()->rect().center());
    QWheelEvent wheel(middle, viewport()->mapToGlobal(middle), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &wheel);
    ASSERT_TRUE(viewport()->isCameraMoving());
    grab();
    EXPECT_LE(viewport()->lastFrameTriangles(), kStandInTriangles);
    EXPECT_GT(viewport()->lastFrameTriangles(), 0u);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !viewport()->isCameraMoving(); }, kBuildTimeoutMs));
    grab();
    // The full mesh, or already the layers of the settled view.
    if (!viewport()->isShowingLayers()) {
        EXPECT_EQ(viewport()->lastFrameTriangles(), fullTriangles());
    }
}

TEST_F(StandInTest, PaintingAfterAnOrbitUsesTheFullMesh) {
    openWithStandIn();
    if (HasFatalFailure())
        return;
    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value());
    QSignalSpy built(builder(), &ui::LayerBuilder::layersBuilt);
    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, *start);
    for (int i = 1; i <= 4; ++i) {
        QTest::mouseMove(viewport(), *start + QPoint(6 * i, 0));
        grab();
        EXPECT_LE(viewport()->lastFrameTriangles(), kStandInTriangles);
    }
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, *start + QPoint(24, 0));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
    ASSERT_NE(document().layers(), nullptr);
    // Captured from the full mesh: far more triangles than the stand-in has.
    EXPECT_GT(capturedTriangles(), kStandInTriangles);

    const auto* target = dynamic_cast<const core::TextureTarget*>(document().paintTarget());
    ASSERT_NE(target, nullptr);
    const std::vector<std::uint8_t> before = target->page(0).rgba;
    const std::optional<QPoint> p = solidPixel();
    ASSERT_TRUE(p.has_value());
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, *p);
    for (int i = 1; i <= 5; ++i)
        QTest::mouseMove(viewport(), *p + QPoint(4 * i, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, *p + QPoint(20, 0));
    target = dynamic_cast<const core::TextureTarget*>(document().paintTarget());
    ASSERT_NE(target, nullptr);
    EXPECT_NE(target->page(0).rgba, before);
}

} // namespace
