// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include <QFuture>
#include <QFutureWatcher>
#include <QObject>
#include <QPromise>
#include <QString>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>

#include "core/base/progress.h"

namespace ui {

/** Steps of a background job's progress value: a fraction in [0, 1] is 0..kJobProgressSteps. */
inline constexpr int kJobProgressSteps = 10000;

/**
 * The one way the GUI runs work off its thread (loading, building layers, saving, exporting):
 * QtConcurrent::run on pool with a QPromise, and a QFutureWatcher that calls done() on context's
 * thread once work has returned, also when the future was cancelled (work never runs when it was
 * cancelled before it started). work gets a core::ProgressFn that publishes a fraction as the
 * future's progress value (which only grows: a lower one is ignored) and returns false once
 * QFuture::cancel() was called. work must catch its own exceptions and keep its result in
 * state it shares with done(); it must not touch the document. done() never comes once context
 * was destroyed, so whoever owns pool waits for its jobs first (a waited-for job still reports
 * later: done() must ignore a job it has settled).
 */
template <typename Work, typename Done>
QFuture<void> runInBackground(QThreadPool& pool, QObject* context, Work work, Done done) {
    QFuture<void> future =
        QtConcurrent::run(&pool, [work = std::move(work)](QPromise<void>& promise) mutable {
            promise.setProgressRange(0, kJobProgressSteps);
            const core::ProgressFn progress = [&promise](double fraction) {
                promise.setProgressValue(
                    int(std::lround(std::clamp(fraction, 0.0, 1.0) * kJobProgressSteps)));
                return !promise.isCanceled();
            };
            work(progress);
        });
    auto* watcher = new QFutureWatcher<void>(context);
    QObject::connect(watcher, &QFutureWatcherBase::finished, context,
                     [watcher, done = std::move(done)]() mutable {
                         watcher->deleteLater();
                         done();
                     });
    watcher->setFuture(future);
    return future;
}

/** A background job's progress in [0, 1]; safe to poll from the GUI thread. */
inline double jobProgress(const QFuture<void>& future) {
    return double(future.progressValue()) / double(kJobProgressSteps);
}

/**
 * Runs one job at a time in the background (saving, exporting) with runInBackground() and reports
 * back on the GUI thread, so long encodes never block the event loop. The job's ProgressFn
 * publishes its progress (poll progress()) and returns false once cancel() was called. The job
 * must only touch data it owns (a snapshot), never the document.
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

    QThreadPool m_pool;             // one thread: one job at a time
    std::shared_ptr<State> m_state; // the running job, or null
};

} // namespace ui
