// SPDX-License-Identifier: GPL-3.0-or-later
// Brush tips in the GUI through real Qt event delivery: clicking a tip in the Brush panel's
// chooser sets the document's brush, and a drag paints with it (a textured tip paints other
// bytes than the round one on the same path). Needs a display with OpenGL 4.5 (xvfb-run).
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QListWidget>
#include <QScrollArea>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "core/document/document.h"
#include "core/paint/targets/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace brush_tips_uitest {

using namespace ui_test;

class BrushTipsTest : public WindowTest {
protected:
    BrushTipsTest() : WindowTest({1260, 720}) {}

    /** Whether the 11 × 11 pixels around p all show the model. */
    bool solid(int px, int py) const {
        return showsModelAround(document().depthLayers()->stack, {px, py}, 5);
    }

    /** Horizontal runs across the model at least 70 px long, rows 50 px apart or more. */
    std::vector<std::pair<QPoint, QPoint>> runs() const {
        const core::DepthStack& stack = document().depthLayers()->stack;
        std::vector<std::pair<QPoint, QPoint>> out;
        for (int y = 20; y < stack.height - 20; y += 5) {
            if (!out.empty() && y - out.back().first.y() < 50)
                continue;
            int start = -1;
            for (int x = 0; x <= stack.width; ++x) {
                const bool inside = x < stack.width && solid(x, y);
                if (inside && start < 0)
                    start = x;
                if (!inside && start >= 0) {
                    if (x - start >= 70) {
                        out.push_back({{start + 4, y}, {std::min(x - 5, start + 160), y}});
                        break;
                    }
                    start = -1;
                }
            }
        }
        return out;
    }

    /** Clicks the tip named name (its data) in the Brush panel's chooser. */
    void chooseTip(const QString& name) {
        auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("brushDock"));
        ASSERT_NE(dock, nullptr);
        dock->show();
        dock->raise();
        auto* list = m_window->findChild<QListWidget*>(QStringLiteral("brushTipList"));
        ASSERT_NE(list, nullptr);
        if (auto* scroll = qobject_cast<QScrollArea*>(dock->widget()))
            scroll->ensureWidgetVisible(list);
        QApplication::processEvents();
        QListWidgetItem* item = nullptr;
        for (int i = 0; i < list->count(); ++i)
            if (list->item(i)->data(Qt::UserRole).toString() == name)
                item = list->item(i);
        ASSERT_NE(item, nullptr) << name.toStdString();
        list->scrollToItem(item);
        QApplication::processEvents();
        const QRect r = list->visualItemRect(item);
        ASSERT_TRUE(list->viewport()->rect().contains(r.center())) << name.toStdString();
        QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier, r.center());
        ASSERT_EQ(document().brush().tip, name.toStdString());
    }
};

TEST_F(BrushTipsTest, AChosenTipPaintsTheStroke) {
    openTrefoil();
    const auto paths = runs();
    ASSERT_GE(paths.size(), 3u) << "no three runs across the knot";
    const std::vector<std::uint8_t> original = pageBytes();
    ASSERT_FALSE(original.empty());

    // The same path with the star and with the round tip paints different texels.
    chooseTip(QStringLiteral("star"));
    drag(paths[0].first, paths[0].second);
    const std::vector<std::uint8_t> star = pageBytes();
    EXPECT_NE(star, original);
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    ASSERT_EQ(pageBytes(), original);
    chooseTip(QStringLiteral("round"));
    drag(paths[0].first, paths[0].second);
    const std::vector<std::uint8_t> round = pageBytes();
    EXPECT_NE(round, original);
    EXPECT_NE(round, star);
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);

    // Three tips, three strokes with the dabs apart: each adds paint (the picture is kept for a
    // look).
    auto* spacing = m_window->findChild<QSpinBox*>(QStringLiteral("brushPanelSpacing"));
    ASSERT_NE(spacing, nullptr);
    QTest::mouseDClick(spacing, Qt::LeftButton);
    QTest::keyClick(spacing, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(spacing, QStringLiteral("90"));
    QTest::keyClick(spacing, Qt::Key_Return);
    ASSERT_FLOAT_EQ(document().brush().spacing, 0.9f);
    std::vector<std::uint8_t> before = pageBytes();
    const QString tips[] = {QStringLiteral("star"), QStringLiteral("bristle"),
                            QStringLiteral("spatter")};
    for (int i = 0; i < 3; ++i) {
        chooseTip(tips[i]);
        drag(paths[std::size_t(i)].first, paths[std::size_t(i)].second);
        const std::vector<std::uint8_t> after = pageBytes();
        EXPECT_NE(after, before) << tips[i].toStdString();
        before = after;
    }
    const QString shot = QDir::temp().filePath(QStringLiteral("layerpaint_brush_tips.png"));
    if (viewport()->grabFramebuffer().save(shot))
        std::printf("[ picture ] %s\n", qPrintable(shot));
}

TEST_F(BrushTipsTest, AChosenTipComesWithTheSpacingAndJitterThatMakeItLookLikeItself) {
    openTrefoil();
    auto* spacing = m_window->findChild<QSpinBox*>(QStringLiteral("brushPanelSpacing"));
    auto* scatter = m_window->findChild<QSpinBox*>(QStringLiteral("brushTipJitterScatter"));
    ASSERT_TRUE(spacing && scatter);
    for (const QString& tip : {QStringLiteral("spatter"), QStringLiteral("chalk"),
                               QStringLiteral("bristle"), QStringLiteral("round")}) {
        chooseTip(tip);
        const core::TipCharacter expected = core::tipCharacter(tip.toStdString());
        const core::Brush& brush = document().brush();
        EXPECT_FLOAT_EQ(brush.spacing, expected.spacing) << tip.toStdString();
        EXPECT_EQ(brush.angleMode, expected.angleMode) << tip.toStdString();
        EXPECT_EQ(brush.jitter, expected.jitter) << tip.toStdString();
        // The panels show what the brush has.
        EXPECT_EQ(spacing->value(), int(std::lround(expected.spacing * 100.0f)));
        EXPECT_EQ(scatter->value(), int(std::lround(expected.jitter.scatter * 100.0f)));
    }
    EXPECT_FLOAT_EQ(core::tipCharacter("spatter").spacing, 0.5f); // apart, as spatter looks
    EXPECT_GT(core::tipCharacter("spatter").jitter.scatter, 0.0f);

    // The artist's own spacing then stays while other settings change.
    QTest::mouseDClick(spacing, Qt::LeftButton);
    QTest::keyClick(spacing, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(spacing, QStringLiteral("40"));
    QTest::keyClick(spacing, Qt::Key_Return);
    QTest::mouseDClick(scatter, Qt::LeftButton);
    QTest::keyClick(scatter, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(scatter, QStringLiteral("20"));
    QTest::keyClick(scatter, Qt::Key_Return);
    EXPECT_FLOAT_EQ(document().brush().spacing, 0.4f);
    EXPECT_FLOAT_EQ(document().brush().jitter.scatter, 0.2f);
}

} // namespace brush_tips_uitest
