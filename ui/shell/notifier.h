// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>

class QMainWindow;
class QWidget;

namespace ui {

/**
 * What a controller tells the user, without knowing the window: a line in the status bar, a
 * warning box, and the widget its own dialogs open over. Tests turn the dialogs off
 * (setDialogsEnabled(false)): errors then reach them through the controllers' signals only.
 */
class Notifier : public QObject {
    Q_OBJECT

public:
    explicit Notifier(QMainWindow& window);

    /** The widget dialogs open over (window-modal). */
    QWidget* dialogParent() const;
    /** Shows text in the status bar for timeoutMs (0: until replaced). */
    void showStatus(const QString& text, int timeoutMs = 0);
    void clearStatus();
    /** A warning box (window-modal, not blocking) unless dialogs are off. */
    void showError(const QString& title, const QString& text, const QString& details);
    /** Whether modal questions and warning boxes are shown (off in tests). */
    bool dialogsEnabled() const { return m_dialogs; }
    void setDialogsEnabled(bool enabled) { m_dialogs = enabled; }

private:
    QMainWindow& m_window;
    bool m_dialogs = true;
};

} // namespace ui
