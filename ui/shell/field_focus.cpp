// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/field_focus.h"

#include <QAbstractSpinBox>
#include <QCoreApplication>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QLocale>
#include <QScopedValueRollback>
#include <QSpinBox>

namespace ui {

namespace {

bool isEnter(int key) {
    return key == Qt::Key_Return || key == Qt::Key_Enter;
}

/** Whether a number field could take ch as typed text. */
bool partOfNumber(QChar ch) {
    const QLocale locale;
    return ch.isDigit() || ch == QLatin1Char('+') || ch == QLatin1Char('-') ||
           ch == QLatin1Char('.') || ch == QLatin1Char(',') || ch == QLatin1Char(' ') ||
           locale.decimalPoint().contains(ch) || locale.groupSeparator().contains(ch) ||
           locale.negativeSign().contains(ch) || locale.positiveSign().contains(ch);
}

} // namespace

FieldFocus::FieldFocus(QWidget& window, QWidget& home, QObject* parent)
    : QObject(parent), m_window(window), m_home(&home) {}

QWidget* FieldFocus::fieldOf(QObject* receiver) const {
    auto* widget = qobject_cast<QWidget*>(receiver);
    if (!widget)
        return nullptr;
    // A spin box's text is its inner line edit.
    if (auto* spin = qobject_cast<QAbstractSpinBox*>(widget->parentWidget()))
        widget = spin;
    if (!qobject_cast<QLineEdit*>(widget) && !qobject_cast<QAbstractSpinBox*>(widget))
        return nullptr;
    // Ours: in this window, in a tool bar or panel (floating or not), never in a dialog.
    for (QWidget* w = widget; w; w = w->parentWidget()) {
        if (w == &m_window)
            return widget;
        if (qobject_cast<QDialog*>(w))
            return nullptr;
    }
    return nullptr;
}

void FieldFocus::revert(QWidget* field) {
    if (auto* spin = qobject_cast<QSpinBox*>(field)) {
        spin->setValue(spin->value()); // shows the value in use again, typed text dropped
    } else if (auto* number = qobject_cast<QDoubleSpinBox*>(field)) {
        number->setValue(number->value());
    } else if (auto* edit = qobject_cast<QLineEdit*>(field)) {
        if (field == m_editing)
            edit->setText(m_savedText);
    }
}

bool FieldFocus::eventFilter(QObject* watched, QEvent* event) {
    const QEvent::Type type = event->type();
    if (m_forwarding ||
        (type != QEvent::KeyPress && type != QEvent::ShortcutOverride && type != QEvent::FocusIn))
        return false;
    QWidget* field = fieldOf(watched);
    if (!field)
        return false;
    if (type == QEvent::FocusIn) {
        if (auto* edit = qobject_cast<QLineEdit*>(field)) {
            m_editing = field;
            m_savedText = edit->text();
        }
        return false;
    }
    auto* key = static_cast<QKeyEvent*>(event);
    const Qt::KeyboardModifiers modifiers =
        key->modifiers() & ~(Qt::KeypadModifier | Qt::ShiftModifier);
    if (type == QEvent::ShortcutOverride) {
        // Letters and brackets in a number field: shortcuts, not (rejected) text.
        if (!qobject_cast<QAbstractSpinBox*>(field) || modifiers != Qt::NoModifier ||
            key->text().size() != 1)
            return false;
        const QChar ch = key->text().front();
        if (!ch.isPrint() || partOfNumber(ch))
            return false;
        return true; // not accepted: the shortcut map gets the key
    }
    // KeyPress
    const bool enter = isEnter(key->key());
    if ((!enter && key->key() != Qt::Key_Escape) || modifiers != Qt::NoModifier)
        return false;
    if (enter) {
        // The field takes its value first (spin boxes apply it on Enter).
        const QScopedValueRollback guard(m_forwarding, true);
        QCoreApplication::sendEvent(watched, event);
    } else {
        revert(field);
    }
    event->accept(); // nobody else sees it
    m_editing = nullptr;
    if (m_home && m_home->isVisible())
        m_home->setFocus(Qt::ShortcutFocusReason);
    return true;
}

} // namespace ui
