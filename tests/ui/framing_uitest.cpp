// SPDX-License-Identifier: GPL-3.0-or-later
// Framing and window sizes through real Qt events: Frame All on load and on F/Home for wide and
// tall views, a new model in the default view, the smallest window and back.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>
#include <QWheelEvent>

#include <memory>
#include <vector>

#include <glm/geometric.hpp>

#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/view/viewport.h"

namespace framing_uitest {

using namespace ui_test;

QString enginePath() {
    return QStringLiteral(LAYERPAINT_ASSIMP_MODELS
                          "/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
}

class FramingTest : public WindowTest {
protected:
    FramingTest() : WindowTest({1000, 700}) {}

    bool openAndWait(const QString& source) {
        QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
        QSignalSpy failed(m_window.get(), &ui::MainWindow::loadFailed);
        m_window->openFromCommandLine({source});
        const bool done =
            QTest::qWaitFor([&] { return !loaded.isEmpty() || !failed.isEmpty(); }, kLoadTimeoutMs);
        return done && loaded.size() == 1 && failed.isEmpty();
    }

    /** Resizes the window as a window manager does and waits until the layout has settled. */
    void resizeWindow(QSize size) {
        m_window->resize(size);
        QTest::qWait(50);
        QApplication::processEvents();
    }

    /**
     * How far inside the view (device pixels) the nearest projected corner of the model's
     * bounding box lies; negative when one is outside.
     */
    float cornerClearance() const {
        const core::Bounds box = viewport()->mesh()->bounds();
        const core::View view = viewport()->view();
        float clearance = 1e30f;
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                                   (i & 4) ? box.max.z : box.min.z);
            const glm::vec3 p = view.project(corner);
            clearance =
                std::min({clearance, p.x, p.y, float(view.width) - p.x, float(view.height) - p.y});
            if (!(p.z > 0.0f))
                clearance = -1.0f;
        }
        return clearance;
    }

    /** Pixels of the picture's outermost two rows and columns that are not background. */
    int modelPixelsOnTheBorder() {
        // The brush outline is no part of the model: the pointer leaves the view first.
        QEvent leave(QEvent::Leave);
        QApplication::sendEvent(viewport(), &leave);
        EXPECT_FALSE(viewport()->brushOutlineVisible());
        const QImage image = viewport()->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        const QRgb background = image.pixel(0, 0);
        int count = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const bool border =
                    x < 2 || y < 2 || x >= image.width() - 2 || y >= image.height() - 2;
                if (border && channelDifference(image.pixel(x, y), background) > 8)
                    ++count;
            }
        return count;
    }

    void middleDrag(Qt::KeyboardModifiers modifiers, QPoint delta) {
        const QPoint start = viewport()->rect().center();
        QTest::mousePress(viewport(), Qt::MiddleButton, modifiers, start);
        for (int i = 1; i <= 10; ++i)
            QTest::mouseMove(viewport(), start + delta * i / 10);
        QTest::mouseRelease(viewport(), Qt::MiddleButton, modifiers, start + delta);
    }
};

TEST_F(FramingTest, FrameAllFitsTheEngineInWideAndTallViews) {
    if (!QFileInfo::exists(enginePath()))
        GTEST_SKIP() << "assimp test models not installed: " << enginePath().toStdString();
    // Wide: the window is much wider than high, even with the panels beside the view.
    resizeWindow({1500, 560});
    ASSERT_GT(viewport()->width(), viewport()->height() * 3 / 2);
    ASSERT_TRUE(openAndWait(enginePath()));
    EXPECT_GT(cornerClearance(), 0.0f) << "on load, wide";
    EXPECT_EQ(modelPixelsOnTheBorder(), 0) << "on load, wide";

    // Tall: the view is narrower than high. The model opened in the wide view is cut now...
    resizeWindow({760, 1000});
    ASSERT_LT(viewport()->width(), viewport()->height());
    // ...and F frames it for the view's shape.
    QTest::keyClick(m_window.get(), Qt::Key_F);
    EXPECT_GT(cornerClearance(), 0.0f) << "after F, tall";
    EXPECT_EQ(modelPixelsOnTheBorder(), 0) << "after F, tall";

    // Moved away and zoomed in, then Home: framed again, also orthographic.
    middleDrag(Qt::ShiftModifier, QPoint(80, 40));
    middleDrag(Qt::NoModifier, QPoint(70, 30));
    QTest::keyClick(m_window.get(), Qt::Key_O);
    ASSERT_TRUE(viewport()->isOrthographic());
    QTest::keyClick(m_window.get(), Qt::Key_Home);
    EXPECT_GT(cornerClearance(), 0.0f) << "after Home, tall, orthographic";
    EXPECT_EQ(modelPixelsOnTheBorder(), 0) << "after Home, tall, orthographic";

    // A model opened in the tall view is framed for it at once.
    QTest::keyClick(m_window.get(), Qt::Key_O);
    ASSERT_TRUE(openAndWait(QStringLiteral("builtin:hexring")));
    ASSERT_TRUE(openAndWait(enginePath()));
    EXPECT_GT(cornerClearance(), 0.0f) << "on load, tall";
    EXPECT_EQ(modelPixelsOnTheBorder(), 0) << "on load, tall";
}

TEST_F(FramingTest, AnotherModelOpensInTheDefaultView) {
    ASSERT_TRUE(openAndWait(QStringLiteral("builtin:trefoil")));
    const core::Camera initial = viewport()->camera();
    EXPECT_FALSE(initial.orthographic);
    auto* ortho = m_window->findChild<QAction*>(QStringLiteral("actionOrthographic"));
    ASSERT_NE(ortho, nullptr);

    // Turned, moved, zoomed and orthographic...
    middleDrag(Qt::NoModifier, QPoint(90, 40));
    middleDrag(Qt::ShiftModifier, QPoint(50, 20));
    QWheelEvent wheel(QPointF(viewport()->rect().center()),
                      viewport()->mapToGlobal(QPointF(viewport()->rect().center())), QPoint(),
                      QPoint(0, 360), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &wheel);
    QTest::keyClick(m_window.get(), Qt::Key_O);
    ASSERT_TRUE(viewport()->isOrthographic());
    ASSERT_NE(viewport()->camera().yawDegrees, initial.yawDegrees);

    // ...then another model: framed in the default view, in perspective.
    ASSERT_TRUE(openAndWait(QStringLiteral("builtin:hexring")));
    const core::Camera& camera = viewport()->camera();
    EXPECT_FALSE(camera.orthographic);
    EXPECT_FALSE(viewport()->isOrthographic());
    EXPECT_FALSE(ortho->isChecked());
    EXPECT_EQ(camera.yawDegrees, initial.yawDegrees);
    EXPECT_EQ(camera.pitchDegrees, initial.pitchDegrees);
    const core::Bounds bounds = viewport()->mesh()->bounds();
    EXPECT_LT(glm::length(camera.target - bounds.center()), 1e-5f * bounds.longestSide());
    EXPECT_GT(cornerClearance(), 0.0f);
    // As F frames it.
    const float distance = camera.distance;
    QTest::keyClick(m_window.get(), Qt::Key_F);
    EXPECT_FLOAT_EQ(viewport()->camera().distance, distance);

    // The same for the first model opened again.
    QTest::keyClick(m_window.get(), Qt::Key_O);
    middleDrag(Qt::NoModifier, QPoint(-60, 30));
    ASSERT_TRUE(openAndWait(QStringLiteral("builtin:trefoil")));
    EXPECT_FALSE(viewport()->camera().orthographic);
    EXPECT_FALSE(ortho->isChecked());
    EXPECT_EQ(viewport()->camera().yawDegrees, initial.yawDegrees);
    EXPECT_EQ(viewport()->camera().pitchDegrees, initial.pitchDegrees);
    EXPECT_FLOAT_EQ(viewport()->camera().distance, initial.distance);
}

TEST_F(FramingTest, SmallestWindowKeepsAUsableViewAndWholeStatusTexts) {
    resizeWindow({1280, 800});
    const auto docks = m_window->findChildren<QDockWidget*>();
    const auto dockWidths = [&] {
        std::vector<int> widths;
        for (const QDockWidget* dock : docks)
            widths.push_back(dock->isVisible() && !dock->isFloating() ? dock->width() : -1);
        return widths;
    };
    const std::vector<int> widths = dockWidths();
    const int viewWidth = viewport()->width();

    // As small as the window goes...
    resizeWindow({200, 150});
    const QSize smallest = m_window->size();
    EXPECT_GE(viewport()->width(), 320)
        << "window " << smallest.width() << "x" << smallest.height();
    EXPECT_GE(viewport()->height(), 200);
    // ...then a model, whose facts fill the status bar once its layers are built.
    ASSERT_TRUE(openAndWait(QStringLiteral("builtin:trefoil")));
    auto* layerInfo = m_window->statusBar()->findChild<QLabel*>(QStringLiteral("layerInfo"));
    ASSERT_NE(layerInfo, nullptr);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return layerInfo->text().contains(QStringLiteral("Regions")); }, kBuildTimeoutMs));
    QApplication::processEvents();
    EXPECT_EQ(m_window->size(), smallest);
    // Every status text is shown whole or elided, never cut off mid-letter.
    int labels = 0;
    for (const QLabel* label : m_window->statusBar()->findChildren<QLabel*>()) {
        if (!label->isVisible() || label->text().isEmpty())
            continue;
        ++labels;
        const QString shown = label->property("shownText").isValid()
                                  ? label->property("shownText").toString()
                                  : label->text();
        EXPECT_LE(label->fontMetrics().horizontalAdvance(shown), label->contentsRect().width())
            << label->objectName().toStdString() << ": " << shown.toStdString();
        EXPECT_LE(label->mapTo(m_window->statusBar(), QPoint(label->width(), 0)).x(),
                  m_window->statusBar()->width())
            << label->objectName().toStdString();
        if (shown != label->text()) {
            EXPECT_TRUE(shown.endsWith(QChar(0x2026))) << shown.toStdString();
            EXPECT_TRUE(label->property("shownToolTip").toString().startsWith(label->text()));
        }
    }
    EXPECT_GE(labels, 3);

    // Back to the first size: the panels and the view as they were.
    resizeWindow({1280, 800});
    (void)QTest::qWaitFor([&] { return dockWidths() == widths; }, 2000);
    const std::vector<int> restored = dockWidths();
    for (qsizetype i = 0; i < docks.size(); ++i)
        EXPECT_NEAR(restored[std::size_t(i)], widths[std::size_t(i)], 2)
            << docks[i]->objectName().toStdString();
    EXPECT_NEAR(viewport()->width(), viewWidth, 2);
    // With room, the texts are whole again (once the status bar has laid them out).
    (void)QTest::qWaitFor(
        [&] { return layerInfo->property("shownText").toString() == layerInfo->text(); }, 2000);
    EXPECT_EQ(layerInfo->property("shownText").toString(), layerInfo->text());
}

} // namespace framing_uitest
