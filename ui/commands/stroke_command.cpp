// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/commands/stroke_command.h"

#include "core/document/document.h"
#include "ui/view/viewport.h"

namespace ui {

StrokeCommand::StrokeCommand(core::Document& document, Viewport& viewport, const bool& suspended,
                             const QString& text)
    : QUndoCommand(text), m_document(document), m_viewport(viewport), m_suspended(suspended) {}

void StrokeCommand::undo() {
    if (m_suspended)
        return;
    core::PaintChanges changes;
    if (m_document.undo(changes))
        m_viewport.applyPaintChanges(changes);
}

void StrokeCommand::redo() {
    if (!m_pushed) {
        m_pushed = true; // push(): the stroke is on the target already
        return;
    }
    if (m_suspended)
        return;
    core::PaintChanges changes;
    if (m_document.redo(changes))
        m_viewport.applyPaintChanges(changes);
}

} // namespace ui
