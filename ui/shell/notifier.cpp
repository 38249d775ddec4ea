// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/notifier.h"

#include <QMainWindow>
#include <QMessageBox>
#include <QStatusBar>

namespace ui {

Notifier::Notifier(QMainWindow& window) : QObject(&window), m_window(window) {}

QWidget* Notifier::dialogParent() const {
    return &m_window;
}

void Notifier::showStatus(const QString& text, int timeoutMs) {
    m_window.statusBar()->showMessage(text, timeoutMs);
}

void Notifier::clearStatus() {
    m_window.statusBar()->clearMessage();
}

void Notifier::showError(const QString& title, const QString& text, const QString& details) {
    if (!m_dialogs)
        return;
    // Window-modal and opened, not exec()'d: no nested event loop.
    auto* box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, &m_window);
    box->setInformativeText(details);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::WindowModal);
    box->open();
}

} // namespace ui
