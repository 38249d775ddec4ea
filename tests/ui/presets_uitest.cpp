// SPDX-License-Identifier: GPL-3.0-or-later
// Brush presets, the quick guide and the tool hint through real Qt event delivery: presets
// survive a new start and a file round trip, a clicked preset paints; Help ▸ Quick Guide opens
// with pictures the app drew, a first start opens it once; B/E/I/P change the status-bar hint.
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QLabel>
#include <QListWidget>
#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cstdio>

#include "core/paint/targets/paint_target.h"
#include "tests/ui/window_test.h"
#include "ui/panels/brush_presets_panel.h"
#include "ui/shell/quick_guide.h"
#include "ui/shell/quick_guide_pictures.h"

namespace presets_uitest {

using namespace ui_test;

class PresetsTest : public WindowTest {
protected:
    PresetsTest() : WindowTest(QSize(1260, 760)) {}

    ui::BrushPresetsPanel* panel() const { return m_window->brushPresetsPanel(); }
    int rowOf(const std::string& name) const {
        const auto& presets = panel()->presets();
        for (std::size_t i = 0; i < presets.size(); ++i)
            if (presets[i].name == name)
                return int(i);
        return -1;
    }
    /** Clicks the preset at row in the panel, as a user does. */
    void clickPreset(int row) {
        auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("brushPresetsDock"));
        ASSERT_NE(dock, nullptr);
        dock->show();
        dock->raise();
        QApplication::processEvents();
        QListWidget* list = panel()->list();
        ASSERT_GE(row, 0);
        QListWidgetItem* item = list->item(row);
        list->scrollToItem(item);
        QApplication::processEvents();
        const QRect r = list->visualItemRect(item);
        ASSERT_TRUE(list->viewport()->rect().contains(r.center()));
        QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier, r.center());
    }
    /** The brush as a preset sets it: the preset's, in the colour the artist had. */
    static core::Brush withColor(core::Brush brush, const glm::vec4& color) {
        brush.color = color;
        return brush;
    }
};

TEST_F(PresetsTest, PresetsRoundTripThroughTheSettings) {
    ASSERT_GE(panel()->presets().size(), 8u); // the starter set
    ASSERT_EQ(panel()->list()->count(), int(panel()->presets().size()));
    core::Brush brush = document().brush();
    brush.radius = 13.0f;
    brush.tip = "star";
    brush.angleMode = core::TipAngleMode::Stroke;
    brush.jitter.scatter = 0.5f;
    brush.seed = 42;
    brush.stabilizer = true;
    brush.stabilizerLength = 77.0f;
    brush.paintMetallic = true;
    brush.metallic = 0.25f;
    m_window->setBrush(brush);
    ASSERT_TRUE(panel()->addFromCurrent(QStringLiteral("My Star")));
    ASSERT_TRUE(panel()->renamePreset(rowOf("Chalk"), QStringLiteral("Dusty Chalk")));
    ASSERT_TRUE(panel()->deletePreset(rowOf("Spatter")));
    const std::vector<core::BrushPreset> saved = panel()->presets();

    showWindow(); // a new start
    EXPECT_EQ(panel()->presets(), saved);
    EXPECT_EQ(rowOf("Spatter"), -1);
    EXPECT_GE(rowOf("Dusty Chalk"), 0);
    const glm::vec4 color = document().brush().color;
    clickPreset(rowOf("My Star"));
    EXPECT_EQ(document().brush(), withColor(brush, color));
    clickPreset(rowOf("Metal Paint"));
    EXPECT_TRUE(document().brush().paintMetallic);
    EXPECT_FLOAT_EQ(document().brush().metallic, 1.0f);
    EXPECT_FLOAT_EQ(document().brush().roughness, 0.3f);
    EXPECT_EQ(document().brush().color, color);
}

TEST_F(PresetsTest, PresetsRoundTripThroughAFileAndABadFileIsNamed) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const int liner = rowOf("Stabilized Liner");
    ASSERT_GE(liner, 0);
    const QString path = dir.filePath(QStringLiteral("liner.lpbrush"));
    ASSERT_TRUE(panel()->exportFile(liner, path));
    const std::size_t before = panel()->presets().size();
    ASSERT_TRUE(panel()->importFile(path));
    ASSERT_EQ(panel()->presets().size(), before + 1);
    EXPECT_EQ(panel()->presets().back(), panel()->presets()[std::size_t(liner)]);

    QSignalSpy errors(panel(), &ui::BrushPresetsPanel::errorOccurred);
    const QString broken = dir.filePath(QStringLiteral("broken.lpbrush"));
    {
        QFile file(broken);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "layerpaint-brush", "name": "X", "brush": {"radius": "big"}})");
    }
    const std::vector<core::BrushPreset> kept = panel()->presets();
    const core::Brush brushBefore = document().brush();
    EXPECT_FALSE(panel()->importFile(broken));
    EXPECT_FALSE(panel()->importFile(dir.filePath(QStringLiteral("missing.lpbrush"))));
    ASSERT_EQ(errors.size(), 2);
    const QString first = errors[0][0].toString();
    EXPECT_TRUE(first.startsWith(QStringLiteral("broken.lpbrush: "))) << first.toStdString();
    EXPECT_TRUE(first.contains(QStringLiteral("radius"))) << first.toStdString();
    EXPECT_FALSE(first.contains(QLatin1Char('\n')));
    EXPECT_TRUE(errors[1][0].toString().startsWith(QStringLiteral("missing.lpbrush: ")));
    EXPECT_EQ(panel()->presets(), kept);
    EXPECT_EQ(document().brush(), brushBefore);
}

TEST_F(PresetsTest, AClickedPresetPaintsTheStroke) {
    openTrefoil();
    const QPoint a(viewport()->width() / 2 - 60, viewport()->height() / 2);
    const QPoint b(viewport()->width() / 2 + 60, viewport()->height() / 2 + 10);
    // Paint where the model is: the centre row of the knot.
    const core::DepthStack& stack = document().depthLayers()->stack;
    ASSERT_GT(
        stack.layerCount(std::size_t(a.y()) * std::size_t(stack.width) + std::size_t(a.x())) +
            stack.layerCount(std::size_t(b.y()) * std::size_t(stack.width) + std::size_t(b.x())),
        0u);

    clickPreset(rowOf("Hard Ink"));
    EXPECT_EQ(document().brush().tip, "round-hard");
    EXPECT_FLOAT_EQ(document().brush().radius, 6.0f);
    drag(a, b);
    const std::vector<std::uint8_t> ink = pageBytes();
    ASSERT_FALSE(ink.empty());
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    const std::vector<std::uint8_t> original = pageBytes();
    EXPECT_NE(ink, original);

    clickPreset(rowOf("Soft Round"));
    EXPECT_EQ(document().brush().tip, "round-soft");
    drag(a, b);
    const std::vector<std::uint8_t> soft = pageBytes();
    EXPECT_NE(soft, original);
    EXPECT_NE(soft, ink); // the same path, another brush
    const QString shot = QDir::temp().filePath(QStringLiteral("layerpaint_presets.png"));
    if (m_window->grab().save(shot))
        std::printf("[ picture ] %s\n", qPrintable(shot));
}

TEST_F(PresetsTest, APresetKeepsTheArtistsSymmetry) {
    // Mirror X on in the Brush panel, as a user ticks it.
    auto* mirrorX = m_window->findChild<QCheckBox*>(QStringLiteral("brushPanelSymmetryMirrorX"));
    ASSERT_NE(mirrorX, nullptr);
    auto* group = m_window->findChild<QGroupBox*>(QStringLiteral("brushPanelSymmetry"));
    ASSERT_NE(group, nullptr);
    if (group->isCheckable() && !group->isChecked())
        group->setChecked(true);
    mirrorX->setChecked(true);
    ASSERT_TRUE(document().brush().symmetry.mirrorX);

    clickPreset(rowOf("Hard Ink"));
    EXPECT_EQ(document().brush().tip, "round-hard") << "the preset was taken";
    EXPECT_TRUE(document().brush().symmetry.mirrorX) << "and the symmetry kept";
    EXPECT_TRUE(mirrorX->isChecked()) << "the panel shows it still on";
}

TEST_F(PresetsTest, QuickGuideOpensFromTheHelpMenuWithPictures) {
    ASSERT_EQ(m_window->quickGuide(), nullptr);
    QTest::keyClick(m_window.get(), Qt::Key_F1); // Help ▸ Quick Guide
    ui::QuickGuideDialog* guide = m_window->quickGuide();
    ASSERT_NE(guide, nullptr);
    EXPECT_TRUE(guide->isVisible());
    EXPECT_FALSE(guide->isModal());
    if (guide->pictures().empty()) {
        QSignalSpy ready(guide, &ui::QuickGuideDialog::picturesReady);
        ASSERT_TRUE(ready.wait(kLoadTimeoutMs));
    }
    ASSERT_EQ(guide->pictures().size(), 4u);
    for (const QImage& picture : guide->pictures()) {
        ASSERT_FALSE(picture.isNull());
        // A model on a background with the pointer's marks: many colours, not a blank.
        QSet<QRgb> colors;
        for (int y = 0; y < picture.height(); y += 2)
            for (int x = 0; x < picture.width(); x += 2)
                colors.insert(picture.pixel(x, y));
        EXPECT_GT(colors.size(), 50);
    }
    // The stroke picture holds the stroke's red.
    const QImage& stroke = guide->pictures()[0];
    int red = 0;
    for (int y = 0; y < stroke.height(); ++y)
        for (int x = 0; x < stroke.width(); ++x) {
            const QRgb p = stroke.pixel(x, y);
            red += qRed(p) > qGreen(p) + 60 && qRed(p) > qBlue(p) + 60 ? 1 : 0;
        }
    EXPECT_GT(red, 50);
    // The pop-up and paint-to-hide pictures show what came into view, tinted amber.
    for (const ui::GuidePicture which : {ui::GuidePicture::PopUp, ui::GuidePicture::PaintToHide}) {
        const QImage& picture = guide->pictures()[std::size_t(which)];
        int amber = 0;
        for (int y = 0; y < picture.height(); ++y)
            for (int x = 0; x < picture.width(); ++x) {
                const QRgb p = picture.pixel(x, y);
                amber += qRed(p) > qGreen(p) + 40 && qGreen(p) > qBlue(p) + 40 ? 1 : 0;
            }
        EXPECT_GT(amber, 200) << "picture " << int(which) << " shows nothing brought into view";
        picture.save(
            QDir::temp().filePath(QStringLiteral("layerpaint_guide_%1.png").arg(int(which))));
    }
    const QString shot = QDir::temp().filePath(QStringLiteral("layerpaint_quick_guide.png"));
    if (guide->grab().save(shot))
        std::printf("[ picture ] %s\n", qPrintable(shot));
    guide->close();
    QApplication::processEvents();
}

TEST_F(PresetsTest, AFirstStartShowsTheGuideOnce) {
    m_window->showQuickGuideAtStart();
    ASSERT_NE(m_window->quickGuide(), nullptr);
    EXPECT_FALSE(m_window->quickGuide()->showAtStartBox()->isChecked());
    m_window->quickGuide()->close();
    QApplication::processEvents();

    showWindow(); // the second start: not again
    m_window->showQuickGuideAtStart();
    EXPECT_EQ(m_window->quickGuide(), nullptr);

    // Asked to show at start, it does.
    m_window->showQuickGuide();
    QTest::mouseClick(m_window->quickGuide()->showAtStartBox(), Qt::LeftButton);
    m_window->quickGuide()->close();
    showWindow();
    m_window->showQuickGuideAtStart();
    ASSERT_NE(m_window->quickGuide(), nullptr);
    EXPECT_TRUE(m_window->quickGuide()->showAtStartBox()->isChecked());
}

TEST_F(PresetsTest, TheStatusBarHintFollowsTheTool) {
    auto* hint = m_window->findChild<QLabel*>(QStringLiteral("toolHint"));
    ASSERT_NE(hint, nullptr);
    QSet<QString> seen;
    const QString brush = hint->text();
    EXPECT_TRUE(brush.contains(QStringLiteral("Shift+click")));
    seen.insert(brush);
    for (Qt::Key key : {Qt::Key_E, Qt::Key_I, Qt::Key_P, Qt::Key_B}) {
        const QString before = hint->text();
        QTest::keyClick(m_window.get(), key);
        EXPECT_NE(hint->text(), before) << int(key);
        EXPECT_FALSE(hint->text().contains(QLatin1Char('\n')));
        seen.insert(hint->text());
    }
    EXPECT_EQ(seen.size(), 4);
    EXPECT_TRUE(hint->text() == brush);
    QTest::keyClick(m_window.get(), Qt::Key_P);
    EXPECT_TRUE(hint->text().contains(QStringLiteral("Ctrl+Shift+click")));
}

} // namespace presets_uitest
