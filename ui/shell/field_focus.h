// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QPointer>
#include <QString>

class QWidget;

namespace ui {

/**
 * Keeps the painters' single-key shortcuts working around the text fields of a window's tool
 * bars and panels (dialogs are left alone):
 * - Enter in a field applies it and gives the keyboard back to home (the viewport); Escape puts
 *   back what the field showed before the typing and does the same.
 * - In a number field, keys that cannot be part of a number (letters, [ and ]) go to the
 *   shortcuts: a field that was only clicked or scrolled is not being typed into.
 * Install it on the application (it sees the events of floating panels too).
 */
class FieldFocus : public QObject {
    Q_OBJECT

public:
    FieldFocus(QWidget& window, QWidget& home, QObject* parent = nullptr);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /** The field (a line edit or a spin box) that receiver belongs to, if it is one of ours. */
    QWidget* fieldOf(QObject* receiver) const;
    void revert(QWidget* field);

    QWidget& m_window;
    QPointer<QWidget> m_home;
    QPointer<QWidget> m_editing; // the field whose text was saved at focus-in
    QString m_savedText;
    bool m_forwarding = false;
};

} // namespace ui
