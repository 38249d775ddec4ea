// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QUndoCommand>

namespace core {
class Document;
}

namespace ui {

class Viewport;

/**
 * A paint stroke or fill on the QUndoStack: a thin wrapper around the document's undo record (the
 * core keeps the tiles in Document::history()). The paint is already there when it is pushed, so
 * the first redo(), which QUndoStack::push() calls, does nothing. While suspended is true
 * (the stack being rebuilt to match the core's history) undo() and redo() touch nothing.
 */
class StrokeCommand : public QUndoCommand {
public:
    StrokeCommand(core::Document& document, Viewport& viewport, const bool& suspended,
                  const QString& text);

    void undo() override;
    void redo() override;

private:
    core::Document& m_document;
    Viewport& m_viewport;
    const bool& m_suspended;
    bool m_pushed = false;
};

} // namespace ui
