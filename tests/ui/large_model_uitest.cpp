// SPDX-License-Identifier: GPL-3.0-or-later
// What keeps a large model's window answering, through real Qt event delivery, on the built-in
// trefoil with low thresholds: a new model's GL buffers are filled in the background (the view
// says so meanwhile, a press given then paints once they are there), and a frame too large to
// draw at once is drawn a slice per event while the stand-in shows. Each gives the picture made
// at once, pixel for pixel.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QMetaObject>
#include <QSignalSpy>
#include <QTest>

#include <optional>
#include <vector>

#include "core/document/document.h"
#include "render/software_gl.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace large_model_uitest {

using namespace ui_test;

constexpr std::size_t kStandInTriangles = 20000;

class LargeModelTest : public WindowTest {
protected:
    LargeModelTest() : WindowTest({1000, 700}) {}

    /** Opens the trefoil with a low stand-in threshold and waits for its stand-in. */
    void openWithStandIn() {
        viewport()->setStandInTriangles(kStandInTriangles);
        openTrefoil();
        if (HasFatalFailure())
            return;
        ASSERT_TRUE(QTest::qWaitFor([&] { return viewport()->hasStandIn(); }, kBuildTimeoutMs));
    }

    std::size_t fullTriangles() const { return document().mesh().triangleCount(); }

    /**
     * Opens the trefoil again with every model's buffers filled in the background, up to its
     * first frame: the buffers are being filled (no event was handled since).
     */
    void reopenFilledInTheBackground() {
        viewport()->setBackgroundFillTriangles(1);
        QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
        m_window->openFile(QStringLiteral("builtin:trefoil"));
        ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
        grab();
        ASSERT_TRUE(viewport()->isPreparingMesh());
    }
};

TEST_F(LargeModelTest, ANewModelsBuffersAreFilledInTheBackgroundWhileTheViewSaysSo) {
    viewport()->setBackgroundFillTriangles(0); // at once: the picture to compare with
    openTrefoil();
    if (HasFatalFailure())
        return;
    const QImage atOnce = grab();

    reopenFilledInTheBackground();
    if (HasFatalFailure())
        return;
    // Meanwhile: no mesh drawn, no depth layers, the notice.
    const QImage meanwhile = grab();
    EXPECT_EQ(viewport()->lastFrameTriangles(), 0u);
    EXPECT_FALSE(viewport()->isShowingDepthLayers());
    EXPECT_EQ(document().depthLayers(), nullptr);
    EXPECT_GT(differingFraction(meanwhile, atOnce), 0.1);
    QSignalSpy built(builder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !viewport()->isPreparingMesh(); }, kBuildTimeoutMs));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return viewport()->isShowingDepthLayers(); }, kBuildTimeoutMs));
    EXPECT_TRUE(grab() == atOnce);
}

TEST_F(LargeModelTest, APressGivenWhileTheBuffersAreFilledPaintsOnceTheyAreThere) {
    openTrefoil();
    if (HasFatalFailure())
        return;
    const std::optional<QPoint> p = solidPixel();
    ASSERT_TRUE(p.has_value());
    reopenFilledInTheBackground();
    if (HasFatalFailure())
        return;
    const std::vector<std::uint8_t> before = pageBytes();
    ASSERT_FALSE(before.empty());
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, *p);
    EXPECT_FALSE(viewport()->isPreparingMesh()); // the capture waited for them
    QTest::mouseMove(viewport(), *p + QPoint(10, 0));
    QTest::mouseMove(viewport(), *p + QPoint(20, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, *p + QPoint(20, 0));
    EXPECT_NE(pageBytes(), before);
}

// A frame of a model too large to draw at once (a low slice size here) is drawn a slice per
// event: the stand-in shows meanwhile, what was given meanwhile is handled between the slices,
// and the whole frame is the picture drawn at once, pixel for pixel.
TEST_F(LargeModelTest, ALargeSettledFrameIsDrawnInSlicesWhileTheStandInShows) {
    openWithStandIn();
    if (HasFatalFailure())
        return;
    viewport()->makeCurrent();
    const bool software = render::isSoftwareRenderer();
    viewport()->doneCurrent();
    if (!software)
        GTEST_SKIP() << "frames are drawn in slices on a software renderer only";
    const std::size_t full = fullTriangles();
    builder()->setSettleDelay(600000); // the full mesh, not the depth layers, once released
    viewport()->setFrameSliceTriangles(full / 5);
    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value());
    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, *start);
    QTest::mouseMove(viewport(), *start + QPoint(20, 6));
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, *start + QPoint(20, 6));
    ASSERT_FALSE(viewport()->isShowingDepthLayers());

    // The first slice: the stand-in shows.
    const QImage standIn = grab();
    EXPECT_FALSE(viewport()->isFrameWhole());
    EXPECT_GT(viewport()->lastFrameTriangles(), 0u);
    EXPECT_LE(viewport()->lastFrameTriangles(), kStandInTriangles);
    // Something given now is handled before the frame is whole.
    std::optional<bool> wholeWhenHandled;
    QMetaObject::invokeMethod(
        viewport(), [&] { wholeWhenHandled = viewport()->isFrameWhole(); }, Qt::QueuedConnection);
    ASSERT_TRUE(QTest::qWaitFor([&] { return viewport()->isFrameWhole(); }, kBuildTimeoutMs));
    ASSERT_TRUE(wholeWhenHandled.has_value());
    EXPECT_FALSE(*wholeWhenHandled);
    const QImage sliced = grab();
    EXPECT_TRUE(viewport()->isFrameWhole());
    EXPECT_EQ(viewport()->lastFrameTriangles(), full);

    viewport()->setFrameSliceTriangles(0);
    viewport()->update();
    const QImage atOnce = grab();
    EXPECT_EQ(viewport()->lastFrameTriangles(), full);
    EXPECT_TRUE(sliced == atOnce);
    EXPECT_GT(differingFraction(standIn, sliced), 0.0);
}

} // namespace large_model_uitest
