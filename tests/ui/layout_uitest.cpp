// SPDX-License-Identifier: GPL-3.0-or-later
// The window at its minimum size, in English, German and Chinese: no label is cut off (each is at
// least as large as its size hint asks, or as tall as its wrapped text needs), and the tool bar
// shows every tool (none pushed into its » overflow menu). The first start's dock layout at
// 1280 × 800 and 1920 × 1080 gives the paint layers room. Real widgets under Xvfb.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <QTranslator>
#include <QTreeWidget>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "tests/ui/ui_test_util.h"
#include "ui/panels/color_panel.h"
#include "ui/panels/paint_layers_panel.h"
#include "ui/shell/elided_label.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"

namespace layout_uitest {

using namespace ui_test;

/** The application's translation for language ("en": none), installed while it lives. */
class Language {
public:
    explicit Language(const std::string& language) {
        if (language == "en")
            return;
        m_translator = std::make_unique<QTranslator>();
        const QString file = QStringLiteral(LAYERPAINT_QM_DIR "/layerpaint_") +
                             QString::fromStdString(language) + QStringLiteral(".qm");
        m_loaded = m_translator->load(file);
        if (m_loaded)
            QCoreApplication::installTranslator(m_translator.get());
    }
    ~Language() {
        if (m_loaded)
            QCoreApplication::removeTranslator(m_translator.get());
    }
    Language(const Language&) = delete;
    Language& operator=(const Language&) = delete;
    bool ok() const { return !m_translator || m_loaded; }

private:
    std::unique_ptr<QTranslator> m_translator;
    bool m_loaded = false;
};

/** Whether w and all its parents are shown (a tab behind another is not). */
bool shown(const QWidget* w) {
    return w->isVisible() && !w->visibleRegion().isEmpty();
}

/** Why label is cut off at its size, or empty. */
std::string clipped(const QLabel& label) {
    if (label.text().isEmpty() || qobject_cast<const ui::ElidedLabel*>(&label) ||
        !label.pixmap().isNull())
        return {};
    const QSize hint = label.sizeHint();
    if (label.wordWrap()) {
        const int needed = label.heightForWidth(label.width());
        if (needed > label.height() + 1)
            return "its wrapped text needs " + std::to_string(needed) + " px of height, it has " +
                   std::to_string(label.height());
        return {};
    }
    if (hint.width() > label.width() + 1)
        return "its text needs " + std::to_string(hint.width()) + " px, it has " +
               std::to_string(label.width());
    if (label.fontMetrics().height() > label.height() + 1)
        return "a line needs " + std::to_string(label.fontMetrics().height()) +
               " px of height, it has " + std::to_string(label.height());
    return {};
}

/** Why button's text is cut off, or empty. */
std::string clipped(const QAbstractButton& button) {
    if (button.text().isEmpty() || qobject_cast<const QToolButton*>(&button))
        return {};
    const QSize hint = button.sizeHint();
    if (hint.width() > button.width() + 1)
        return "its text needs " + std::to_string(hint.width()) + " px, it has " +
               std::to_string(button.width());
    return {};
}

/** Why box's current text is cut off, or empty (the text, its frame and arrow must fit). */
std::string clipped(const QComboBox& box) {
    if (box.currentText().isEmpty() || box.isEditable())
        return {};
    QStyleOptionComboBox option;
    option.initFrom(&box);
    option.currentText = box.currentText();
    const QSize text(box.fontMetrics().horizontalAdvance(box.currentText()),
                     box.fontMetrics().height());
    const int needed =
        box.style()->sizeFromContents(QStyle::CT_ComboBox, &option, text, &box).width();
    if (needed > box.width() + 1)
        return "“" + box.currentText().toStdString() + "” needs " + std::to_string(needed) +
               " px, it has " + std::to_string(box.width());
    return {};
}

class LayoutTest : public ::testing::TestWithParam<std::string> {};

TEST_P(LayoutTest, AtTheMinimumSizeNoLabelIsCutOffAndEveryToolIsShown) {
    const Language language(GetParam());
    ASSERT_TRUE(language.ok()) << "no translation for " << GetParam();
    auto window = std::make_unique<ui::MainWindow>();
    window->setErrorDialogsEnabled(false);
    window->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
    QSignalSpy loaded(window.get(), &ui::MainWindow::modelLoaded);
    window->openFile(QStringLiteral("builtin:trefoil"));
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    const QSize minimum = window->minimumSizeHint().expandedTo(window->minimumSize());
    window->resize(minimum);
    QTest::qWait(200); // the layouts settle
    std::printf("[ layout  ] %s: minimum window %d x %d\n", GetParam().c_str(), window->width(),
                window->height());

    for (const QLabel* label : window->findChildren<QLabel*>()) {
        if (!shown(label))
            continue;
        const std::string why = clipped(*label);
        EXPECT_TRUE(why.empty()) << "label “" << label->text().toStdString() << "” ("
                                 << label->objectName().toStdString() << ") is cut off: " << why;
    }
    for (const QAbstractButton* button : window->findChildren<QAbstractButton*>()) {
        if (!shown(button))
            continue;
        const std::string why = clipped(*button);
        EXPECT_TRUE(why.empty()) << "button “" << button->text().toStdString()
                                 << "” is cut off: " << why;
    }
    for (const QComboBox* box : window->findChildren<QComboBox*>()) {
        if (!shown(box))
            continue;
        const std::string why = clipped(*box);
        EXPECT_TRUE(why.empty()) << "drop-down " << box->objectName().toStdString()
                                 << " is cut off: " << why;
    }
    // Every tool of the tool bars is on it, not in the overflow menu.
    for (const QToolBar* bar : window->findChildren<QToolBar*>()) {
        if (!shown(bar))
            continue;
        for (QAction* action : bar->actions()) {
            if (action->isSeparator() || !action->isVisible())
                continue;
            const QWidget* widget = bar->widgetForAction(action);
            EXPECT_TRUE(widget && shown(widget))
                << "“" << action->text().toStdString() << "” of the tool bar "
                << bar->objectName().toStdString() << " is in its overflow menu";
        }
    }
}

/** The rows of list its viewport shows whole. */
int rowsShown(const QTreeWidget& list) {
    const int row = list.visualItemRect(list.topLevelItem(0)).height();
    return row > 0 ? list.viewport()->height() / row : 0;
}

struct DefaultLayout {
    int listRows = 0;
    int pickerHeight = 0;
};

/**
 * A first start at size with the trefoil, four paint layers and a fill layer added through the
 * panel's own button: the Paint Layers panel in front with every control in sight (nothing to
 * scroll to), the settings panels no higher than they need; what it measured.
 */
DefaultLayout checkDefaultLayout(QSize size) {
    QSettings().clear(); // no layout of an earlier session
    auto window = std::make_unique<ui::MainWindow>();
    window->setErrorDialogsEnabled(false);
    window->resize(size);
    window->show();
    EXPECT_TRUE(QTest::qWaitForWindowExposed(window.get()));
    QSignalSpy loaded(window.get(), &ui::MainWindow::modelLoaded);
    window->openFile(QStringLiteral("builtin:trefoil"));
    EXPECT_TRUE(loaded.wait(kLoadTimeoutMs));
    auto* panel = window->paintLayersPanel();
    auto* newLayer = panel->findChild<QAction*>(QStringLiteral("actionNewPaintLayer"));
    auto* newFill = panel->findChild<QAction*>(QStringLiteral("actionNewFillLayer"));
    if (!newLayer || !newFill) {
        ADD_FAILURE() << "no New Paint Layer or New Fill Layer action";
        return {};
    }
    for (QAction* action : {newLayer, newLayer, newLayer, newLayer, newFill}) {
        QToolButton* button = nullptr;
        for (QToolButton* b : panel->findChildren<QToolButton*>())
            if (b->defaultAction() == action)
                button = b;
        if (!button || !shown(button)) {
            ADD_FAILURE() << "the button of “" << action->iconText().toStdString()
                          << "” is not in sight";
            return {};
        }
        QTest::mouseClick(button, Qt::LeftButton);
    }
    QTest::qWait(200); // the layouts settle
    const std::string at = std::to_string(size.width()) + " x " + std::to_string(size.height());

    EXPECT_TRUE(shown(panel)) << at << ": the Paint Layers panel is not in front";
    const auto* scroll = qobject_cast<const QScrollArea*>(
        window->findChild<QDockWidget*>(QStringLiteral("paintLayersDock"))->widget());
    EXPECT_TRUE(scroll && scroll->verticalScrollBar()->maximum() == 0)
        << at << ": the Paint Layers panel scrolls (its fill values or buttons are out of sight)";
    for (const char* name : {"paintLayerOpacity", "paintLayerBlend", "paintLayerFillColor"}) {
        const QWidget* w = panel->findChild<QWidget*>(QString::fromLatin1(name));
        EXPECT_TRUE(w && shown(w)) << at << ": " << name << " is not in sight";
    }
    const auto* list = panel->findChild<QTreeWidget*>(QStringLiteral("paintLayersList"));
    DefaultLayout measured;
    if (list && list->topLevelItemCount() == 6)
        measured.listRows = rowsShown(*list);
    else
        ADD_FAILURE() << at << ": the list does not hold the five paint layers and the base";
    // Segmentation at the top is as high as its controls need, give or take.
    const QDockWidget* segmentation =
        window->findChild<QDockWidget*>(QStringLiteral("segmentationDock"));
    EXPECT_TRUE(shown(segmentation)) << at;
    EXPECT_LE(segmentation->height(), segmentation->sizeHint().height() + 24)
        << at << ": Segmentation has empty room";
    measured.pickerHeight = window->findChild<QWidget*>(QStringLiteral("hsvPicker"))->height();
    std::printf("[ layout  ] %s: %d rows of paint layers shown, colour square %d px high\n",
                at.c_str(), measured.listRows, measured.pickerHeight);
    return measured;
}

TEST(DefaultDockLayout, GivesThePaintLayersRoomAt1280x800And1920x1080) {
    const DefaultLayout small = checkDefaultLayout({1280, 800});
    const DefaultLayout large = checkDefaultLayout({1920, 1080});
    QSettings().clear();
    // Every row in sight at 1280 × 800; a taller window's height goes to the list, not to the
    // colour square.
    EXPECT_GE(small.listRows, 6);
    EXPECT_GT(large.listRows, small.listRows);
    EXPECT_LE(large.pickerHeight, ui::HsvPicker::kMaximumHeight);
}

std::string languageName(const ::testing::TestParamInfo<std::string>& language) {
    return language.param == "zh_CN" ? std::string("zh") : language.param;
}

INSTANTIATE_TEST_SUITE_P(Languages, LayoutTest, ::testing::Values("en", "de", "zh_CN"),
                         languageName);

} // namespace layout_uitest
