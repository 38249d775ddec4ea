// SPDX-License-Identifier: GPL-3.0-or-later
// ui/commands/: the Qt side of the document's history (Edit ▸ Undo/Redo).
#pragma once

#include <cstdint>

#include <QObject>
#include <QString>

#include "core/document/history.h"
#include "core/paint/targets/paint_target.h"

class QUndoStack;

namespace core {
class Document;
}

namespace ui {

/**
 * The GUI's view of the document's one history (core::History): a QUndoStack that mirrors it
 * step for step, for Edit ▸ Undo/Redo with the step's name and for the saved-state mark. The
 * history itself, and what undo does, are the core's: the stack holds no data. It listens to the
 * history, so the stack follows every change whoever made it. The document must outlive it.
 */
class HistoryBridge : public QObject {
    Q_OBJECT

public:
    explicit HistoryBridge(core::Document& document, QObject* parent = nullptr);
    ~HistoryBridge() override;

    QUndoStack* stack() const { return m_stack; }
    /** The document as it is now is saved (after a save or a load). */
    void markSaved();
    /** Whether the document is at its saved state (undo/redo may come back to it). */
    bool isClean() const;
    /** The name of a step of kind, as Edit ▸ Undo shows it ("Paint Stroke"). */
    static QString stepText(core::StepKind kind);

signals:
    /** Undo or redo through the stack changed the document; changes is the paint it touched. */
    void applied(const core::PaintChanges& changes);
    /** The history changed (a step added, undone, redone or dropped). */
    void changed();
    void cleanChanged(bool clean);

private:
    friend class HistoryCommand;
    void undoStep();
    void redoStep();
    /** Brings the stack in line with the history (it told us it changed). */
    void sync();

    core::Document& m_document;
    QUndoStack* m_stack;
    bool m_suspended = false; // rebuilding the stack: its commands touch nothing
    bool m_applying = false;  // the stack's undo/redo runs: it syncs once its index moved
    std::uint64_t m_listener = 0;
    std::uint64_t m_revision = 0;
    bool m_clean = true;
};

} // namespace ui
