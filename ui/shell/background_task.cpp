// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/background_task.h"

#include <QMetaObject>

#include <atomic>
#include <exception>
#include <new>

namespace ui {

struct BackgroundTask::State {
    std::atomic<bool> cancel{false};
    std::atomic<double> progress{0.0};
    QString error;
    std::thread thread;
};

BackgroundTask::BackgroundTask(QObject* parent) : QObject(parent) {}

BackgroundTask::~BackgroundTask() {
    // The worker posts its result to this object: joining here, before ~QObject drops pending
    // events, means none runs against a destroyed task.
    if (m_state && m_state->thread.joinable())
        m_state->thread.join();
}

bool BackgroundTask::start(Job job) {
    if (m_state)
        return false;
    auto state = std::make_shared<State>();
    m_state = state;
    state->thread = std::thread([this, state, job = std::move(job)] {
        const core::ProgressFn progress = [raw = state.get()](double fraction) {
            raw->progress.store(fraction, std::memory_order_relaxed);
            return !raw->cancel.load(std::memory_order_relaxed);
        };
        try {
            state->error = job(progress);
        } catch (const std::bad_alloc&) {
            state->error = tr("Not enough memory.");
        } catch (const std::exception& e) {
            state->error = QString::fromStdString(e.what());
        }
        QMetaObject::invokeMethod(
            this, [this, state] { finish(state); }, Qt::QueuedConnection);
    });
    return true;
}

void BackgroundTask::cancel() {
    if (m_state)
        m_state->cancel = true;
}

double BackgroundTask::progress() const {
    return m_state ? m_state->progress.load(std::memory_order_relaxed) : 0.0;
}

void BackgroundTask::wait() {
    if (!m_state)
        return;
    const std::shared_ptr<State> state = m_state;
    state->thread.join();
    finish(state); // the queued call then finds the job gone and does nothing
}

void BackgroundTask::finish(const std::shared_ptr<State>& state) {
    if (state != m_state)
        return; // already reported (wait())
    if (state->thread.joinable())
        state->thread.join(); // posting was its last step: returns at once
    m_state.reset();
    // A job that completed although asked to stop (too late to cancel) succeeded.
    emit finished(state->error, !state->error.isEmpty() && state->cancel.load());
}

} // namespace ui
