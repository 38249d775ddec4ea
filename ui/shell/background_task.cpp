// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/background_task.h"

#include <exception>
#include <memory>
#include <new>

namespace ui {

struct BackgroundTask::State {
    QFuture<void> future;
    bool ran = false; // the job started (a job cancelled before it started never does)
    QString error;    // written by the job, read once it finished
};

BackgroundTask::BackgroundTask(QObject* parent) : QObject(parent) {
    m_pool.setMaxThreadCount(1);
}

BackgroundTask::~BackgroundTask() {
    // The job's report goes to a watcher that dies with this object; it only has to end first.
    m_pool.waitForDone();
}

bool BackgroundTask::start(Job job) {
    if (m_state)
        return false;
    auto state = std::make_shared<State>();
    m_state = state;
    state->future = runInBackground(
        m_pool, this,
        [raw = state.get(), job = std::move(job)](const core::ProgressFn& progress) {
            raw->ran = true;
            try {
                raw->error = job(progress);
            } catch (const std::bad_alloc&) {
                raw->error = tr("Not enough memory.");
            } catch (const std::exception& e) {
                raw->error = QString::fromStdString(e.what());
            }
        },
        [this, state] { finish(state); });
    return true;
}

void BackgroundTask::cancel() {
    if (m_state)
        m_state->future.cancel();
}

double BackgroundTask::progress() const {
    return m_state ? jobProgress(m_state->future) : 0.0;
}

void BackgroundTask::wait() {
    if (!m_state)
        return;
    const std::shared_ptr<State> state = m_state;
    state->future.waitForFinished();
    finish(state); // the watcher's report then finds the job gone and does nothing
}

void BackgroundTask::finish(const std::shared_ptr<State>& state) {
    if (state != m_state)
        return; // already reported (wait())
    m_state.reset();
    if (!state->ran)
        state->error = QStringLiteral("cancelled"); // as core says of a job stopped at once
    // A job that completed although asked to stop (too late to cancel) succeeded.
    emit finished(state->error, !state->error.isEmpty() && state->future.isCanceled());
}

} // namespace ui
