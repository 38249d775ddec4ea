// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QLabel>

namespace ui {

/**
 * A one-line label that, when narrower than its text, shows the text cut at a letter with "…"
 * instead of cut anywhere, and puts the whole text at the head of its tooltip. Its minimum width
 * is a few letters, so a long text never holds a window wide. text() is always the whole text.
 */
class ElidedLabel : public QLabel {
    Q_OBJECT
    Q_PROPERTY(QString shownText READ shownText)
    Q_PROPERTY(QString shownToolTip READ shownToolTip)

public:
    explicit ElidedLabel(QWidget* parent = nullptr);

    /** The text as drawn now: whole, or elided to the width. */
    QString shownText() const;
    /** The tooltip as shown now: toolTip(), after the whole text when that is elided. */
    QString shownToolTip() const;

    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    bool event(QEvent* event) override;
};

} // namespace ui
