// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include <QObject>
#include <QString>
#include <QTimer>

#include "core/document/script.h"

namespace core {
class Document;
}

class QAction;
class QProgressDialog;

namespace ui {

class DepthLayersBuilder;
class Notifier;
class Viewport;

/**
 * File ▸ Run Script… (replays a script on the open document, as one undo step or step by step,
 * an operation per event-loop turn with a cancellable progress dialog) and Edit ▸ Copy Session
 * as Script (what the user did since opening, as a script, on the clipboard). Scripts run through
 * the core's ScriptRunner: the same code the headless tool runs.
 */
class ScriptActions : public QObject {
    Q_OBJECT

public:
    /** Scripts run on document in viewport's view, their depth layers built by builder. */
    ScriptActions(core::Document& document, Viewport& viewport, DepthLayersBuilder& builder,
                  Notifier& notifier);
    ~ScriptActions() override;

    QAction* runAction() const { return m_run; }
    QAction* copySessionAction() const { return m_copy; }

    /** Runs script on the open document (oneStep: as one undo step); finished() follows. */
    void run(const core::Script& script, bool oneStep);
    bool isRunning() const { return m_job != nullptr; }
    /** The session so far as script JSON text (what Copy Session as Script puts on the clipboard).
     */
    QString sessionText() const;

signals:
    /** A script changed the document wholesale: every widget shows its state again. */
    void documentStateChanged();
    /** The script ended: error is empty on success (and says so when it was cancelled). */
    void finished(const QString& error);

private:
    struct Job;
    void showRunDialog();
    void step();
    void finish(const QString& error);

    core::Document& m_document;
    Viewport& m_viewport;
    DepthLayersBuilder& m_builder;
    Notifier& m_notifier;
    QAction* m_run;
    QAction* m_copy;
    std::unique_ptr<Job> m_job;
    QTimer m_timer;
    QProgressDialog* m_progress = nullptr;
};

} // namespace ui
