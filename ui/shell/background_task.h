// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <memory>
#include <thread>

#include <QObject>
#include <QString>

#include "core/base/progress.h"

namespace ui {

/**
 * Runs one job at a time on a worker thread (saving, exporting) and reports back on the GUI
 * thread, so long encodes never block the event loop. The job gets a ProgressFn that publishes
 * its progress (poll progress()) and returns false once cancel() was called. The job must only
 * touch data it owns (a snapshot), never the document.
 */
class BackgroundTask : public QObject {
    Q_OBJECT

public:
    /** The job: returns an error message for the user, or an empty string on success. */
    using Job = std::function<QString(const core::ProgressFn& progress)>;

    explicit BackgroundTask(QObject* parent = nullptr);
    /** Waits for a running job (it finishes; its result is dropped). */
    ~BackgroundTask() override;

    /** Starts job; false (and nothing started) while another one runs. */
    bool start(Job job);
    bool isRunning() const { return m_state != nullptr; }
    /** Asks the running job to stop at its next progress report. */
    void cancel();
    /** Progress of the running job in [0, 1]; safe to poll from the GUI thread. */
    double progress() const;
    /** Blocks until the running job has finished and finished() was emitted. */
    void wait();

signals:
    /** error is empty on success; cancelled when cancel() stopped the job (error says so). */
    void finished(const QString& error, bool cancelled);

private:
    struct State;
    void finish(const std::shared_ptr<State>& state);

    std::shared_ptr<State> m_state; // the running job, or null
};

} // namespace ui
