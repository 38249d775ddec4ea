// SPDX-License-Identifier: GPL-3.0-or-later
// Painting in the GUI through real Qt event delivery: a left drag paints through the document
// and the picture follows without a recapture, Ctrl+Z / Ctrl+Shift+Z restore and redo the
// texture exactly, L toggles layer-aware painting, the undo stack follows the core's budget.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QColor>
#include <QComboBox>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>
#include <QWindow>
#include <qpa/qwindowsysteminterface.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <thread>
#include <vector>

#include "core/document/document.h"
#include "core/paint/targets/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace painting_uitest {

using namespace ui_test;

class PaintingTest : public WindowTest {
protected:
    PaintingTest() : WindowTest({1260, 720}) {}

    void openTrefoil() {
        WindowTest::openTrefoil();
        if (HasFatalFailure())
            return;
        ASSERT_TRUE(viewport()->isShowingDepthLayers());
    }

    const core::TextureTarget* texture() {
        return dynamic_cast<const core::TextureTarget*>(document().paintTarget());
    }

    /** Whether pixel (device = logical here) and its 9 × 9 neighbourhood all show the model. */
    bool solid(QPoint p) const { return showsModelAround(document().depthLayers()->stack, p, 4); }

    /** A horizontal run across the model near the middle of the view, at least minLength long. */
    std::pair<QPoint, QPoint> pathAcrossTheKnot(int minLength = 80) const {
        const core::DepthStack& stack = document().depthLayers()->stack;
        for (int k = 0; k < stack.height / 2; k += 7) {
            for (int y : {stack.height / 2 - k, stack.height / 2 + k}) {
                int runStart = -1;
                for (int x = 0; x <= stack.width; ++x) {
                    const bool inside = x < stack.width && solid({x, y});
                    if (inside && runStart < 0)
                        runStart = x;
                    if (!inside && runStart >= 0) {
                        if (x - runStart >= minLength)
                            return {{runStart + 5, y}, {x - 6, y}};
                        runStart = -1;
                    }
                }
            }
        }
        return {};
    }

    /** A left drag from a to b in 4-pixel steps; each step repainted like a frame. */
    void drag(QPoint a, QPoint b) {
        QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, a);
        const int steps = std::max(1, int(std::hypot(b.x() - a.x(), b.y() - a.y()) / 4));
        for (int i = 1; i <= steps; ++i) {
            QTest::mouseMove(viewport(), a + (b - a) * i / steps);
            viewport()->repaint();
        }
        QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, b);
        // The pointer leaves, taking the brush outline along: pictures compare the model only.
        QEvent leave(QEvent::Leave);
        QApplication::sendEvent(viewport(), &leave);
    }

    bool clickGivenWhileALoadKeepsTheWindowBusyPaints(QPoint p, int busyMs);
};

TEST_F(PaintingTest, DragPaintsAndUndoRedoRestoreTheTextureExactly) {
    openTrefoil();
    const int captures = builder()->captureCount();
    const auto [a, b] = pathAcrossTheKnot();
    ASSERT_GT(b.x() - a.x(), 60) << "no run across the knot";
    ASSERT_NE(texture(), nullptr);
    const std::vector<std::uint8_t> original = pageBytes();
    QApplication::processEvents();
    const QImage before = grab();

    drag(a, b);

    // The texture changed, and the picture along the path without a recapture.
    const std::vector<std::uint8_t> painted = pageBytes();
    EXPECT_NE(painted, original);
    EXPECT_EQ(builder()->captureCount(), captures);
    EXPECT_TRUE(viewport()->isShowingDepthLayers());
    const QImage after = grab();
    int changed = 0, samples = 0;
    for (int x = a.x(); x <= b.x(); x += 3, ++samples)
        changed += channelDifference(before.pixel(x, a.y()), after.pixel(x, a.y())) > 24;
    EXPECT_GT(changed, samples * 8 / 10) << changed << " of " << samples;
    // Away from the stroke nothing changed.
    EXPECT_LT(differingFraction(before.copy(0, 0, before.width(), a.y() - 60),
                                after.copy(0, 0, after.width(), a.y() - 60)),
              0.001);

    ASSERT_EQ(undoStack()->count(), 1);
    EXPECT_TRUE(m_window->findChild<QAction*>(QStringLiteral("actionUndo"))->isEnabled());
    EXPECT_FALSE(m_window->findChild<QAction*>(QStringLiteral("actionRedo"))->isEnabled());

    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(pageBytes(), original);
    EXPECT_EQ(undoStack()->index(), 0);
    QApplication::processEvents();
    EXPECT_LT(differingFraction(before, grab()), 0.001);

    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(pageBytes(), painted);
    QApplication::processEvents();
    EXPECT_LT(differingFraction(after, grab()), 0.001);

    // Ctrl+Y redoes too.
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(pageBytes(), original);
    QTest::keyClick(m_window.get(), Qt::Key_Y, Qt::ControlModifier);
    EXPECT_EQ(pageBytes(), painted);
}

TEST_F(PaintingTest, TheFirstStrokeAndItsUndoDoNotSendTheMeshAgain) {
    openTrefoil();
    const auto [a, b] = pathAcrossTheKnot();
    ASSERT_GT(b.x() - a.x(), 60) << "no run across the knot";
    // The paint target was made with the model, in the background: the first frame sends the
    // mesh with its pages, once, and the first stroke paints into it without sending it again.
    ASSERT_TRUE(document().hasPaintTarget());
    grab();
    const int uploads = viewport()->meshUploads();
    ASSERT_EQ(uploads, 1);
    drag(a, b);
    grab();
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    grab();
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    grab();
    drag(a, b);
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    grab();
    EXPECT_EQ(viewport()->meshUploads(), uploads) << "an undo or redo sent the mesh again";
}

TEST_F(PaintingTest, PaintsVertexColoursOnRequest) {
    openTrefoil();
    auto* combo = m_window->findChild<QComboBox*>(QStringLiteral("paintTarget"));
    ASSERT_NE(combo, nullptr);
    const int item = combo->count() - 1; // vertex colours
    combo->setCurrentIndex(item);
    emit combo->activated(item);
    const auto* target = dynamic_cast<const core::VertexColorTarget*>(document().paintTarget());
    ASSERT_NE(target, nullptr);
    const std::vector<glm::vec4> original = target->colors();
    const auto [a, b] = pathAcrossTheKnot();
    ASSERT_GT(b.x() - a.x(), 60);
    QApplication::processEvents();
    const QImage before = grab();
    drag(a, b);
    EXPECT_NE(target->colors(), original);
    const QImage after = grab();
    int changed = 0, samples = 0;
    for (int x = a.x(); x <= b.x(); x += 3, ++samples)
        changed += channelDifference(before.pixel(x, a.y()), after.pixel(x, a.y())) > 24;
    EXPECT_GT(changed, samples * 7 / 10) << changed << " of " << samples;
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(target->colors(), original);
    QApplication::processEvents();
    EXPECT_LT(differingFraction(before, grab()), 0.001);
}

TEST_F(PaintingTest, LTogglesLayerAwarePainting) {
    openTrefoil();
    auto* action = m_window->findChild<QAction*>(QStringLiteral("actionLayerAware"));
    ASSERT_NE(action, nullptr);
    EXPECT_TRUE(action->isChecked());
    EXPECT_TRUE(document().layerAware());
    QTest::keyClick(m_window.get(), Qt::Key_L);
    EXPECT_FALSE(document().layerAware());
    EXPECT_FALSE(action->isChecked());
    QTest::keyClick(m_window.get(), Qt::Key_L);
    EXPECT_TRUE(document().layerAware());
}

TEST_F(PaintingTest, PressOnTheBackgroundPaintsNothing) {
    openTrefoil();
    const std::vector<std::uint8_t> original = pageBytes();
    const QPoint corner(3, 3);
    ASSERT_EQ(
        document().depthLayers()->stack.offsets[3 * document().depthLayers()->stack.width + 4],
        document().depthLayers()->stack.offsets[3 * document().depthLayers()->stack.width + 3]);
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, corner);
    EXPECT_EQ(pageBytes(), original);
    EXPECT_EQ(undoStack()->count(), 0);
}

TEST_F(PaintingTest, PaintingRightAfterAnOrbitUsesFreshLayers) {
    openTrefoil();
    const auto [a, b] = pathAcrossTheKnot();
    ASSERT_GT(b.x() - a.x(), 60);
    const QPoint target = (a + b) / 2;
    const std::vector<std::uint8_t> original = pageBytes();
    builder()->setSettleDelay(60000); // the timer must not build them first
    const int captures = builder()->captureCount();

    const QPoint start = viewport()->rect().center();
    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, start);
    QTest::mouseMove(viewport(), start + QPoint(3, 0));
    QTest::mouseMove(viewport(), start + QPoint(6, 0));
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, start + QPoint(6, 0));
    EXPECT_EQ(document().depthLayers(), nullptr);

    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, target);
    const core::DepthLayers* layers = document().depthLayers();
    ASSERT_NE(layers, nullptr);
    EXPECT_EQ(builder()->captureCount(), captures + 1);
    const core::View view = viewport()->view();
    EXPECT_EQ(layers->view.view, view.view);
    EXPECT_EQ(layers->view.proj, view.proj);
    QTest::mouseMove(viewport(), target + QPoint(10, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, target + QPoint(10, 0));
    EXPECT_NE(pageBytes(), original);
    EXPECT_EQ(undoStack()->count(), 1);
    EXPECT_TRUE(viewport()->isShowingDepthLayers());
}

TEST_F(PaintingTest, UndoStackFollowsTheBudget) {
    openTrefoil();
    const auto [a, b] = pathAcrossTheKnot();
    ASSERT_GT(b.x() - a.x(), 60);
    drag(a, {a.x() + 30, a.y()});
    const std::size_t first = document().history().bytes();
    ASSERT_GT(first, 0u);
    document().history().setBudget(first * 3 / 2);
    drag({b.x() - 30, b.y()}, b); // a step of about the same size: the first must go
    EXPECT_EQ(document().history().undoCount(), 1u);
    EXPECT_EQ(undoStack()->count(), 1);
    EXPECT_EQ(undoStack()->index(), 1);
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_FALSE(undoStack()->canUndo());
    EXPECT_FALSE(m_window->findChild<QAction*>(QStringLiteral("actionUndo"))->isEnabled());
    EXPECT_TRUE(undoStack()->canRedo());
}

TEST_F(PaintingTest, BrushMapsShowAroundTheStroke) {
    openTrefoil();
    const auto [a, b] = pathAcrossTheKnot();
    ASSERT_GT(b.x() - a.x(), 60);
    auto* action = m_window->findChild<QAction*>(QStringLiteral("actionShowBrushMaps"));
    ASSERT_NE(action, nullptr);
    action->trigger();
    ASSERT_TRUE(viewport()->brushMapsVisible());
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, a);
    QTest::mouseMove(viewport(), a + QPoint(20, 0));
    const QImage image = grab();
    int blue = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            blue += c.blue() > c.red() + 60 && c.blue() > c.green() + 60;
        }
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, a + QPoint(20, 0));
    EXPECT_GT(blue, 500);
}

/**
 * Opens the trefoil again; when it arrives the GUI thread stays busy for busyMs, and meanwhile a
 * click at p is given from another thread, as the window system's reader queues it. Whether
 * that click painted.
 */
bool PaintingTest::clickGivenWhileALoadKeepsTheWindowBusyPaints(QPoint p, int busyMs) {
    ui::MainWindow& window = *m_window;
    QWindow* handle = window.windowHandle();
    const QPointF local = viewport()->mapTo(&window, QPointF(p));
    const QPointF global = viewport()->mapToGlobal(QPointF(p));
    const QMetaObject::Connection busy =
        QObject::connect(&window, &ui::MainWindow::modelLoaded, &window, [&] {
            std::thread reader([&] {
                using Input = QWindowSystemInterface;
                Input::handleMouseEvent<Input::AsynchronousDelivery>(handle, local, global,
                                                                     Qt::LeftButton, Qt::LeftButton,
                                                                     QEvent::MouseButtonPress);
                Input::handleMouseEvent<Input::AsynchronousDelivery>(handle, local, global,
                                                                     Qt::NoButton, Qt::LeftButton,
                                                                     QEvent::MouseButtonRelease);
            });
            reader.join();
            QThread::msleep(std::uint64_t(busyMs));
        });
    QSignalSpy built(builder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    window.openFile(QStringLiteral("builtin:trefoil"));
    const bool done = QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs);
    QObject::disconnect(busy);
    QTest::qWait(100);
    EXPECT_TRUE(done) << "the depth layers were not built";
    return window.isWindowModified() || undoStack()->count() > 0;
}

TEST_F(PaintingTest, AClickGivenWhileALoadKeepsTheWindowBusyNeverPaints) {
    openTrefoil();
    const std::optional<QPoint> p = solidPixel();
    ASSERT_TRUE(p.has_value());
    {
        const BusyInputMs fence(250.0);
        ASSERT_NE(fence.app(), nullptr);
        const std::size_t dropped = fence.app()->droppedInputEvents();
        EXPECT_FALSE(clickGivenWhileALoadKeepsTheWindowBusyPaints(*p, 400));
        EXPECT_GE(fence.app()->droppedInputEvents(), dropped + 2) << "the press and its release";
    }
    ASSERT_FALSE(HasFailure());
    // The same click, without the fence, is a stroke: the test can fail.
    const BusyInputMs fence(1e9);
    EXPECT_TRUE(clickGivenWhileALoadKeepsTheWindowBusyPaints(*p, 400));
}

} // namespace painting_uitest
