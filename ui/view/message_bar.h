// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>

#include <QFrame>
#include <QList>
#include <QStringList>

class QLabel;
class QToolButton;

namespace ui {

/**
 * A note about the open document shown over the top of a widget (the viewport): load warnings,
 * why a model paints into vertex colours, that work was recovered. It keeps every line whole
 * (wrapped), stays until the close button or the next document replaces it, and never resizes
 * the widget under it. Its children are named messageBarText and messageBarClose.
 */
class MessageBar : public QFrame {
    Q_OBJECT

public:
    enum class Level { Information, Warning };

    /** Over parent's top edge; follows its size. Hidden until showMessage(). */
    explicit MessageBar(QWidget& parent);

    /**
     * Shows title and the lines under it (plain text), replacing what was shown (and its
     * buttons).
     */
    void showMessage(Level level, const QString& title, const QStringList& lines = {});
    /**
     * A button after the text of the message shown (named messageBarButton); clicking it calls
     * onClick and dismisses the bar. Gone with the message.
     */
    QToolButton* addButton(const QString& text, std::function<void()> onClick);
    /** Hides the bar (as its close button does). */
    void dismiss();
    QString text() const;
    Level level() const { return m_level; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void place();

    QWidget& m_host;
    QLabel* m_icon = nullptr;
    QLabel* m_text = nullptr;
    QToolButton* m_close = nullptr;
    QList<QToolButton*> m_buttons;
    Level m_level = Level::Information;
};

} // namespace ui
