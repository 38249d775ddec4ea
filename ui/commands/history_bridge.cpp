// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/commands/history_bridge.h"

#include <QScopedValueRollback>
#include <QUndoCommand>
#include <QUndoStack>

#include "core/document/document.h"

namespace ui {

/** One step of the history on the stack: undo() and redo() ask the document to do it. */
class HistoryCommand : public QUndoCommand {
public:
    HistoryCommand(HistoryBridge& bridge, const QString& text)
        : QUndoCommand(text), m_bridge(bridge) {}
    void undo() override {
        if (!m_bridge.m_suspended)
            m_bridge.undoStep();
    }
    void redo() override {
        if (!m_pushed) {
            m_pushed = true; // push(): the step is done already
            return;
        }
        if (!m_bridge.m_suspended)
            m_bridge.redoStep();
    }

private:
    HistoryBridge& m_bridge;
    bool m_pushed = false;
};

HistoryBridge::HistoryBridge(core::Document& document, QObject* parent)
    : QObject(parent), m_document(document), m_stack(new QUndoStack(this)) {
    m_revision = m_document.history().revision();
    m_listener = m_document.history().subscribe([this] {
        if (!m_suspended && !m_applying)
            sync();
    });
    // After the stack's own undo()/redo() (its index is up to date then): report the change.
    connect(m_stack, &QUndoStack::indexChanged, this, [this] {
        if (!m_suspended)
            sync();
    });
}

HistoryBridge::~HistoryBridge() {
    m_document.history().unsubscribe(m_listener);
}

QString HistoryBridge::stepText(core::StepKind kind) {
    switch (kind) {
    case core::StepKind::Stroke:
        return tr("Paint Stroke");
    case core::StepKind::Fill:
        return tr("Fill");
    case core::StepKind::PopUp:
        return tr("Pop Up Region");
    case core::StepKind::Hide:
        return tr("Hide Regions");
    case core::StepKind::Unhide:
        return tr("Unhide Regions");
    case core::StepKind::ResetOrder:
        return tr("Reset Region Order");
    case core::StepKind::PaintTarget:
        return tr("Change Paint Target");
    case core::StepKind::Script:
        return tr("Run Script");
    case core::StepKind::PaintLayers:
        return tr("Change Paint Layers");
    }
    return {};
}

void HistoryBridge::undoStep() {
    const QScopedValueRollback guard(m_applying, true);
    core::PaintChanges changes;
    if (m_document.undo(changes))
        emit applied(changes);
}

void HistoryBridge::redoStep() {
    const QScopedValueRollback guard(m_applying, true);
    core::PaintChanges changes;
    if (m_document.redo(changes))
        emit applied(changes);
}

bool HistoryBridge::isClean() const {
    return m_document.history().atSavedState();
}

void HistoryBridge::markSaved() {
    m_document.history().markSaved();
}

void HistoryBridge::sync() {
    const core::History& history = m_document.history();
    bool same =
        m_stack->count() == int(history.size()) && m_stack->index() == int(history.undoCount());
    for (int i = 0; same && i < m_stack->count(); ++i)
        same = m_stack->text(i) == stepText(history.kindAt(std::size_t(i)));
    const std::optional<std::size_t> saved = history.savedIndex();
    same = same && (saved ? m_stack->cleanIndex() == int(*saved) : m_stack->cleanIndex() < 0);
    if (!same) {
        const QScopedValueRollback guard(m_suspended, true);
        m_stack->clear();
        for (std::size_t i = 0; i < history.size(); ++i)
            m_stack->push(new HistoryCommand(*this, stepText(history.kindAt(i))));
        if (saved) {
            m_stack->setIndex(int(*saved));
            m_stack->setClean();
        } else {
            m_stack->resetClean();
        }
        m_stack->setIndex(int(history.undoCount()));
    }
    if (history.revision() != m_revision) {
        m_revision = history.revision();
        emit changed();
    }
    if (isClean() != m_clean) {
        m_clean = isClean();
        emit cleanChanged(m_clean);
    }
}

} // namespace ui
