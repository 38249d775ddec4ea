// SPDX-License-Identifier: GPL-3.0-or-later
// The stroke tools in the GUI through real Qt event delivery: a stabilized drag paints a smoother
// path than its jittered input and draws its string while it pulls, and a Shift+click draws a
// straight line on from the end of the last stroke as one undo step.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QGroupBox>
#include <QMenu>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "core/document/document.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace stroke_tools_uitest {

using namespace ui_test;

class StrokeToolsTest : public WindowTest {
protected:
    StrokeToolsTest() : WindowTest({1260, 720}) {}

    void SetUp() override {
        WindowTest::SetUp();
        if (HasFatalFailure())
            return;
        openTrefoil();
        if (HasFatalFailure())
            return;
        core::Brush brush = document().brush();
        brush.radius = 4.0f;
        brush.hardness = 1.0f;
        brush.color = {1.0f, 0.0f, 0.0f, 1.0f};
        m_window->setBrush(brush);
    }

    /** Whether pixel p and its (2 margin + 1)² neighbourhood all show the model. */
    bool solid(QPoint p, int margin) const {
        return showsModelAround(document().depthLayers()->stack, p, margin);
    }
    /** A horizontal run over the model, at least minLength long, clear by margin on all sides. */
    std::pair<QPoint, QPoint> runAcrossTheKnot(int minLength, int margin) const {
        const core::DepthStack& stack = document().depthLayers()->stack;
        for (int k = 0; k < stack.height / 2; k += 5) {
            for (int y : {stack.height / 2 - k, stack.height / 2 + k}) {
                int start = -1;
                for (int x = 0; x <= stack.width; ++x) {
                    const bool inside = x < stack.width && solid({x, y}, margin);
                    if (inside && start < 0)
                        start = x;
                    if (!inside && start >= 0) {
                        if (x - start >= minLength)
                            return {{start + 2, y}, {x - 3, y}};
                        start = -1;
                    }
                }
            }
        }
        return {};
    }
    /** The jittered hand: from a to b in 3-pixel steps, every other sample 5 px up, then down. */
    std::vector<QPoint> zigzag(QPoint a, QPoint b) const {
        std::vector<QPoint> points;
        for (int x = a.x(); x <= b.x(); x += 3)
            points.emplace_back(x, a.y() + (points.size() % 2 == 0 ? 5 : -5));
        points.front() = a;
        return points;
    }
    /** Presses at the first point, moves through the rest (calling during after each move). */
    template <typename During> void drag(const std::vector<QPoint>& points, During during) {
        QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, points.front());
        for (std::size_t i = 1; i < points.size(); ++i) {
            QTest::mouseMove(viewport(), points[i]);
            during(i);
        }
        QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, points.back());
        // The pointer leaves, taking the brush outline along: pictures compare the model only.
        QEvent leave(QEvent::Leave);
        QApplication::sendEvent(viewport(), &leave);
    }
    /** The mean height of the painted band over columns x0..x1 (pixels that changed). */
    static double bandHeight(const QImage& before, const QImage& after, int x0, int x1, int y,
                             int reach) {
        double total = 0.0;
        int columns = 0;
        for (int x = x0; x <= x1; ++x) {
            int top = -1, bottom = -1;
            for (int yy = y - reach; yy <= y + reach; ++yy) {
                if (channelDifference(before.pixel(x, yy), after.pixel(x, yy)) > 40) {
                    if (top < 0)
                        top = yy;
                    bottom = yy;
                }
            }
            if (top >= 0) {
                total += bottom - top + 1;
                ++columns;
            }
        }
        return columns ? total / columns : 0.0;
    }
};

TEST_F(StrokeToolsTest, AStabilizedDragPaintsASmootherPathAndDrawsItsString) {
    const auto [a, b] = runAcrossTheKnot(110, 12);
    ASSERT_GT(b.x() - a.x(), 100) << "no run across the knot";
    const std::vector<QPoint> input = zigzag(a, b);
    QApplication::processEvents();
    const QImage before = grab();

    // The raw hand first: its zigzag is painted.
    drag(input, [](std::size_t) {});
    QApplication::processEvents();
    const double raw = bandHeight(before, grab(), a.x() + 30, b.x() - 30, a.y(), 14);
    ASSERT_EQ(m_window->undoStack()->count(), 1);
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    QApplication::processEvents();
    EXPECT_LT(differingFraction(before, grab()), 0.001) << "undone";

    // Paint ▸ Stroke Stabilizer and the Brush panel's string length.
    auto* action = m_window->findChild<QAction*>(QStringLiteral("actionStabilizer"));
    ASSERT_NE(action, nullptr);
    action->trigger();
    EXPECT_TRUE(document().brush().stabilizer);
    auto* box = m_window->findChild<QGroupBox*>(QStringLiteral("brushPanelStabilizer"));
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->isChecked()) << "the panel follows the menu";
    auto* length = box->findChild<QSpinBox*>(QStringLiteral("brushPanelStabilizerLength"));
    ASSERT_NE(length, nullptr);
    length->setValue(20);
    EXPECT_EQ(document().brush().stabilizerLength, 20.0f);

    // The same hand, stabilized; half-way the string is on screen.
    QImage midway;
    glm::vec2 tip(0.0f), pointer(0.0f);
    drag(input, [&](std::size_t i) {
        if (i == input.size() / 2) {
            ASSERT_TRUE(document().stabilizer().stabilizing());
            tip = document().stabilizer().tip();
            pointer = document().stabilizer().pointer();
            midway = grab();
        }
    });
    QApplication::processEvents();
    const QImage after = grab();
    const double stabilized = bandHeight(before, after, a.x() + 30, b.x() - 30, a.y(), 14);
    std::printf("[ stabilizer ] painted band: raw %.1f px, stabilized %.1f px high\n", raw,
                stabilized);
    EXPECT_GT(raw, 15.0) << "the zigzag (10 px) and the dab (8 px) were painted";
    EXPECT_LT(stabilized, raw - 6.0);
    EXPECT_EQ(m_window->undoStack()->count(), 1);

    // The string: light on dark along the line from the tip to the pointer, gone after release.
    ASSERT_FALSE(midway.isNull());
    EXPECT_NEAR(glm::distance(tip, pointer), 20.0f, 0.5f);
    const glm::vec2 middle = 0.5f * (tip + pointer);
    const QPoint m(int(std::lround(middle.x)), int(std::lround(middle.y)));
    const QRgb string = midway.pixel(m);
    EXPECT_GT(qGray(string), 200) << "the string's light core";
    EXPECT_GT(channelDifference(string, after.pixel(m)), 40) << "gone after release";
    const QString shot =
        QDir::current().absoluteFilePath(QStringLiteral("stroke_tools_uitest.png"));
    EXPECT_TRUE(midway.save(shot));
}

TEST_F(StrokeToolsTest, ShiftClickDrawsALineOnFromTheLastStroke) {
    const auto [a, b] = runAcrossTheKnot(110, 8);
    ASSERT_GT(b.x() - a.x(), 100) << "no run across the knot";
    const QPoint m((a.x() + b.x()) / 2, a.y());
    QApplication::processEvents();
    const QImage before = grab();
    drag({a, a + (m - a) / 2, m}, [](std::size_t) {});
    QApplication::processEvents();
    const QImage stroke = grab();
    const QPoint between((m.x() + b.x()) / 2, a.y());
    EXPECT_LT(channelDifference(before.pixel(between), stroke.pixel(between)), 24)
        << "the stroke ended at the middle";

    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ShiftModifier, b);
    QEvent leave(QEvent::Leave);
    QApplication::sendEvent(viewport(), &leave);
    QApplication::processEvents();
    const QImage line = grab();
    for (const QPoint p : {between, QPoint((m.x() + between.x()) / 2, a.y()), b - QPoint(4, 0)})
        EXPECT_GT(channelDifference(stroke.pixel(p), line.pixel(p)), 40)
            << "the line painted " << p.x() << ", " << p.y();
    EXPECT_EQ(m_window->undoStack()->count(), 2) << "the line is one step";
    ASSERT_TRUE(document().lineStart());
    EXPECT_LT(glm::distance(*document().lineStart(), glm::vec2(b.x(), b.y())), 2.0f);
    EXPECT_EQ(document().history().undoKind(), core::StepKind::Stroke)
        << "Shift+click paints now; it no longer pops a region up";

    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    QApplication::processEvents();
    EXPECT_LT(differingFraction(stroke, grab()), 0.001) << "undo takes the line only";
}

TEST_F(StrokeToolsTest, TheBrushBarsSymmetryButtonSetsTheMirrorsWithoutThePanel) {
    auto* button = m_window->findChild<QToolButton*>(QStringLiteral("symmetryButton"));
    ASSERT_NE(button, nullptr);
    ASSERT_TRUE(button->isVisible()) << "on the brush bar of the default layout";
    EXPECT_FALSE(document().brush().symmetry.active());
    auto* mirrorX = m_window->findChild<QCheckBox*>(QStringLiteral("brushPanelSymmetryMirrorX"));
    ASSERT_NE(mirrorX, nullptr);
    EXPECT_FALSE(mirrorX->isChecked());

    // A click opens the menu; a click on Mirror X in it turns the mirror on.
    bool clicked = false;
    QTimer::singleShot(300, [&] {
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        if (menu == nullptr)
            return;
        auto* action = menu->findChild<QAction*>(QStringLiteral("actionMirrorX"));
        if (action == nullptr) {
            menu->close();
            return;
        }
        QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(action).center());
        clicked = true;
    });
    QTest::mouseClick(button, Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(clicked, 5000);
    QApplication::processEvents();
    EXPECT_TRUE(document().brush().symmetry.mirrorX);
    EXPECT_FALSE(document().brush().symmetry.mirrorY);
    EXPECT_TRUE(mirrorX->isChecked()) << "the Brush panel follows";
    EXPECT_TRUE(button->text().contains(QLatin1Char('X'))) << button->text().toStdString();
    EXPECT_EQ(QSettings().value(QStringLiteral("brush/symmetry/mirror")).toString(),
              QStringLiteral("x"))
        << "remembered for the next session";

    // The panel's radial copies show on the button; Paint ▸ Symmetry ▸ Symmetry Off ends both.
    auto* radial = m_window->findChild<QSpinBox*>(QStringLiteral("brushPanelSymmetryRadial"));
    ASSERT_NE(radial, nullptr);
    radial->setValue(3);
    EXPECT_EQ(document().brush().symmetry.radial, 3);
    EXPECT_TRUE(button->text().contains(QLatin1Char('3'))) << button->text().toStdString();
    auto* off = m_window->findChild<QAction*>(QStringLiteral("actionSymmetryOff"));
    ASSERT_NE(off, nullptr);
    off->trigger();
    EXPECT_FALSE(document().brush().symmetry.active());
    EXPECT_FALSE(mirrorX->isChecked());
    EXPECT_EQ(radial->value(), 1);
    auto* menuMirrorX = m_window->findChild<QAction*>(QStringLiteral("actionMirrorX"));
    ASSERT_NE(menuMirrorX, nullptr);
    EXPECT_FALSE(menuMirrorX->isChecked());
}

TEST_F(StrokeToolsTest, ASymmetricStabilizedDragPaintsTheMirroredSide) {
    // The default view looks at the bounding-box centre along the model's axes, so mirror X
    // mirrors the picture: a copy's dab at column x lands at column w - 1 - x. The trefoil is
    // chiral, though: where its mirror image passes behind a crossing, the copy paints a side
    // this view does not show. So the mirror image is checked where the knot shows there at the
    // stroke's depth, on the run (over the knot on both sides) that has the most such columns.
    const core::DepthStack& stack = document().depthLayers()->stack;
    const int w = stack.width;
    const auto frontDepth = [&](int x, int y) {
        return stack.depth[stack.offsets[std::size_t(y) * std::size_t(w) + std::size_t(x)]];
    };
    const auto mirrorShown = [&](int x, int y) {
        for (int dy = -6; dy <= 6; dy += 3) {
            const float d = frontDepth(x, y + dy), m = frontDepth(w - 1 - x, y + dy);
            if (std::abs(d - m) > 0.02f * d)
                return false;
        }
        return true;
    };
    // The stabilized tip trails the pointer by its string: only the stroke's first half counts.
    const auto checkedColumns = [&](QPoint from, QPoint to) {
        std::vector<int> columns;
        for (int x = from.x() + 4; x <= (from.x() + to.x()) / 2; ++x)
            if (mirrorShown(x, from.y()))
                columns.push_back(x);
        return columns;
    };
    QPoint a, b;
    std::vector<int> shown;
    for (int k = 0; k < 200; k += 4) {
        for (int y : {viewport()->height() / 2 - k, viewport()->height() / 2 + k}) {
            int start = -1;
            for (int x = 10; x < w / 2 - 30; ++x) {
                const bool both = solid({x, y}, 8) && solid({w - 1 - x, y}, 8);
                if (both && start < 0)
                    start = x;
                if ((!both || x == w / 2 - 31) && start >= 0) {
                    if (x - start >= 50) {
                        const QPoint from(start + 2, y), to(x - 3, y);
                        std::vector<int> columns = checkedColumns(from, to);
                        if (columns.size() > shown.size()) {
                            a = from;
                            b = to;
                            shown = std::move(columns);
                        }
                    }
                    start = -1;
                }
            }
        }
    }
    ASSERT_GE(shown.size(), 12u) << "no run whose mirror image shows the knot at its depth";
    QApplication::processEvents();
    const QImage before = grab();

    // Mirror X in the Brush panel: its views are built in the background, not on this thread.
    auto* mirrorX = m_window->findChild<QCheckBox*>(QStringLiteral("brushPanelSymmetryMirrorX"));
    ASSERT_NE(mirrorX, nullptr);
    QSignalSpy finished(m_window->depthLayersBuilder(), &ui::DepthLayersBuilder::symmetryFinished);
    mirrorX->setChecked(true);
    ASSERT_TRUE(document().brush().symmetry.mirrorX);
    EXPECT_TRUE(m_window->depthLayersBuilder()->isBuildingSymmetry());
    EXPECT_FALSE(document().symmetryReady()) << "nothing captured on the GUI thread";
    ASSERT_TRUE(finished.wait(60000));
    EXPECT_TRUE(document().symmetryReady());
    EXPECT_EQ(document().symmetryLayers().size(), 1u);
    // Paint ▸ Stroke Stabilizer on.
    auto* action = m_window->findChild<QAction*>(QStringLiteral("actionStabilizer"));
    ASSERT_NE(action, nullptr);
    action->trigger();
    ASSERT_TRUE(document().brush().stabilizer);

    std::vector<QPoint> input;
    for (int x = a.x(); x <= b.x(); x += 3)
        input.emplace_back(x, a.y());
    bool stringActive = false;
    drag(input, [&](std::size_t i) {
        if (i == input.size() / 2)
            stringActive = document().stabilizer().stabilizing();
    });
    QApplication::processEvents();
    EXPECT_TRUE(stringActive) << "the stroke went through the stabilizer";
    EXPECT_EQ(m_window->undoStack()->count(), 1) << "the stroke and its copy are one step";
    const QImage after = grab();

    // Each column of the stroke and of its mirror image changed near the stroke's row.
    const auto painted = [&](int x) {
        for (int dx = -3; dx <= 3; ++dx)
            for (int dy = -6; dy <= 6; ++dy)
                if (channelDifference(before.pixel(x + dx, a.y() + dy),
                                      after.pixel(x + dx, a.y() + dy)) > 40)
                    return true;
        return false;
    };
    int strokeColumns = 0, mirroredColumns = 0;
    for (int x : shown) {
        strokeColumns += painted(x) ? 1 : 0;
        mirroredColumns += painted(w - 1 - x) ? 1 : 0;
    }
    const double stroke = double(strokeColumns) / double(shown.size());
    const double mirrored = double(mirroredColumns) / double(shown.size());
    std::printf("[ symmetry ] painted columns of %zu: stroke %.2f, mirror image %.2f\n",
                shown.size(), stroke, mirrored);
    EXPECT_GT(stroke, 0.9);
    EXPECT_GT(mirrored, 0.8);
    const QString shot = QDir::current().absoluteFilePath(QStringLiteral("symmetry_uitest.png"));
    EXPECT_TRUE(after.save(shot));
}

} // namespace stroke_tools_uitest
