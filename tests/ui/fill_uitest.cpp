// SPDX-License-Identifier: GPL-3.0-or-later
// The Fill tool through real Qt event delivery: G chooses it and shows its panel, a click fills
// by the panel's mode (checked on the paint target and in the picture), each fill is one
// "Fill" step on the undo stack and Ctrl+Z restores the texture exactly.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

#include "core/document/document.h"
#include "core/paint/targets/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/panels/fill_panel.h"
#include "ui/shell/main_window.h"
#include "ui/tools/tool.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace fill_uitest {

using namespace ui_test;

class FillTest : public WindowTest {
protected:
    FillTest() : WindowTest({1100, 720}) {}

    const core::TextureTarget& texture() {
        return dynamic_cast<const core::TextureTarget&>(*document().paintTarget());
    }

    /** Covered texels of page 0 with exactly these bytes. */
    int coveredTexels(const std::array<std::uint8_t, 4>& bytes) {
        const core::TextureTarget& target = texture();
        const std::vector<std::uint8_t>& rgba = target.page(0).rgba;
        int count = 0;
        for (std::size_t i = 0; i < rgba.size() / 4; ++i)
            if (target.coverage(0)[i] == 1 && std::equal(bytes.begin(), bytes.end(), &rgba[i * 4]))
                ++count;
        return count;
    }
    int coveredTexels() {
        const std::vector<std::uint8_t>& coverage = texture().coverage(0);
        return int(std::count(coverage.begin(), coverage.end(), std::uint8_t(1)));
    }

    /** Whether pixel (x, y) and its 9 × 9 neighbourhood all show the model. */
    bool solid(int px, int py) const {
        return showsModelAround(document().depthLayers()->stack, {px, py}, 4);
    }

    /** A solid pixel near from (rings of growing size around it), or a null point. */
    QPoint solidPixel(QPoint from) const {
        const int width = document().depthLayers()->stack.width;
        for (int r = 0; r < width; r += 3)
            for (int dy = -r; dy <= r; dy += 3)
                for (int dx = -r; dx <= r; dx += 3)
                    if (std::max(std::abs(dx), std::abs(dy)) >= r - 2 &&
                        solid(from.x() + dx, from.y() + dy))
                        return {from.x() + dx, from.y() + dy};
        return {};
    }

    void chooseMode(core::FillMode mode) {
        auto* combo = m_window->findChild<QComboBox*>(QStringLiteral("fillMode"));
        ASSERT_NE(combo, nullptr);
        combo->setCurrentIndex(combo->findData(int(mode)));
        ASSERT_EQ(m_window->fillPanel()->mode(), mode);
    }

    /** A left click at p. */
    void click(QPoint p) {
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, p);
        QEvent leave(QEvent::Leave); // the brush outline goes: pictures show the model only
        QApplication::sendEvent(viewport(), &leave);
        QApplication::processEvents();
    }
};

bool greenish(QRgb c) {
    return qGreen(c) > 2 * qRed(c) + 10 && qGreen(c) > 2 * qBlue(c) + 10;
}

TEST_F(FillTest, GChoosesFillAndEachModeFillsWhatItShould) {
    openTrefoil();
    QTest::keyClick(m_window.get(), Qt::Key_G);
    ASSERT_EQ(m_window->tool(), ui::Tool::Fill);
    auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("fillDock"));
    ASSERT_NE(dock, nullptr);
    QApplication::processEvents();
    EXPECT_FALSE(dock->visibleRegion().isEmpty()); // its tab in front

    document().brush().color = {0.0f, 1.0f, 0.0f, 1.0f};
    document().brush().opacity = 1.0f;
    const std::array<std::uint8_t, 4> green{0, 255, 0, 255}, blue{0, 0, 255, 255};
    const core::DepthStack& stack = document().depthLayers()->stack;
    const QPoint p = solidPixel({stack.width / 2, stack.height / 2});
    ASSERT_FALSE(p.isNull());
    const std::vector<std::uint8_t> original = texture().page(0).rgba;
    const int covered = coveredTexels();
    const QImage before = viewport()->grabFramebuffer();
    ASSERT_FALSE(greenish(before.pixel(p)));

    // Surface: the trefoil is one connected tube, all of it fills, seen or not.
    chooseMode(core::FillMode::Surface);
    click(p);
    EXPECT_EQ(coveredTexels(green), covered);
    ASSERT_EQ(undoStack()->count(), 1);
    EXPECT_EQ(undoStack()->text(0), QStringLiteral("Fill"));
    EXPECT_TRUE(greenish(viewport()->grabFramebuffer().pixel(p)));
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_TRUE(texture().page(0).rgba == original);
    QApplication::processEvents();
    EXPECT_LT(differingFraction(before, viewport()->grabFramebuffer()), 0.001);

    // Region: the strand segment clicked, not the whole knot; shown at once.
    chooseMode(core::FillMode::Region);
    click(p);
    const int region = coveredTexels(green);
    EXPECT_GT(region, covered / 100);
    EXPECT_LT(region, covered * 3 / 4);
    const QImage afterRegion = viewport()->grabFramebuffer();
    EXPECT_TRUE(greenish(afterRegion.pixel(p)));
    EXPECT_EQ(undoStack()->count(), 1); // the undone surface fill was replaced

    // Similar colour, tolerance 0, on a part the region fill left alone: the rest of the
    // knot's base colour turns blue around the green patch, which stays as it is.
    QPoint q;
    for (int y = 0; y < stack.height && q.isNull(); y += 5)
        for (int x = 0; x < stack.width && q.isNull(); x += 5) {
            if (solid(x, y) && !greenish(afterRegion.pixel(x, y)) &&
                (QPoint(x, y) - p).manhattanLength() > 40)
                q = {x, y};
        }
    ASSERT_FALSE(q.isNull());
    chooseMode(core::FillMode::Color);
    auto* slider = m_window->findChild<QSlider*>(QStringLiteral("fillTolerance"));
    ASSERT_NE(slider, nullptr);
    EXPECT_TRUE(slider->isEnabled());
    slider->setValue(0);
    EXPECT_EQ(m_window->fillPanel()->tolerance(), 0.0f);
    document().brush().color = {0.0f, 0.0f, 1.0f, 1.0f};
    click(q);
    EXPECT_EQ(coveredTexels(green), region);
    const int blues = coveredTexels(blue);
    EXPECT_GT(blues, (covered - region) * 9 / 10);
    EXPECT_EQ(undoStack()->count(), 2);
    EXPECT_EQ(undoStack()->text(1), QStringLiteral("Fill"));

    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_TRUE(texture().page(0).rgba == original);
}

TEST_F(FillTest, OptionsAreRememberedAndAClickOnTheBackgroundFillsNothing) {
    {
        ui::FillPanel panel;
        panel.setMode(core::FillMode::Color);
        panel.setTolerance(0.37f);
    }
    {
        const ui::FillPanel panel;
        EXPECT_EQ(panel.mode(), core::FillMode::Color);
        EXPECT_FLOAT_EQ(panel.tolerance(), 0.37f);
    }
    openTrefoil();
    m_window->setTool(ui::Tool::Fill);
    click({3, 3}); // a corner of the view: background
    EXPECT_EQ(undoStack()->count(), 0);
    EXPECT_FALSE(document().history().canUndo());
}

} // namespace fill_uitest
