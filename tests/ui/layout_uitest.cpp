// SPDX-License-Identifier: GPL-3.0-or-later
// The window at its minimum size, in English, German and Chinese: no label is cut off (each is at
// least as large as its size hint asks, or as tall as its wrapped text needs), and the tool bar
// shows every tool (none pushed into its » overflow menu). Real widgets under Xvfb.
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QLabel>
#include <QLocale>
#include <QSignalSpy>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <QTranslator>

#include <memory>
#include <string>

#include "tests/ui/ui_test_util.h"
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

std::string languageName(const ::testing::TestParamInfo<std::string>& language) {
    return language.param == "zh_CN" ? std::string("zh") : language.param;
}

INSTANTIATE_TEST_SUITE_P(Languages, LayoutTest, ::testing::Values("en", "de", "zh_CN"),
                         languageName);

} // namespace layout_uitest
