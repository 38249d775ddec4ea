// SPDX-License-Identifier: GPL-3.0-or-later
// The one way the GUI runs work in the background (ui/shell/background_task.h): progress reaches
// the GUI thread, cancel reaches the job, and a job that finished although asked to stop counts
// as done. Real threads and Qt event delivery; no timing is asserted.
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTest>

#include <atomic>
#include <thread>

#include "ui/shell/background_task.h"

namespace background_task_uitest {

constexpr int kWaitMs = 60000;

TEST(BackgroundTaskTest, ProgressArrivesAndCancelStopsTheJob) {
    ui::BackgroundTask task;
    QSignalSpy finished(&task, &ui::BackgroundTask::finished);
    std::atomic<bool> reported{false};
    ASSERT_TRUE(task.start([&reported](const core::ProgressFn& progress) {
        // Reports half-way until told to stop, as a long save does (bounded, so a lost cancel
        // fails the test instead of hanging it).
        for (long i = 0; i < 200'000'000; ++i) {
            if (!progress(0.5))
                return QStringLiteral("stopped");
            reported = true;
        }
        return QString();
    }));
    EXPECT_TRUE(task.isRunning());
    EXPECT_FALSE(task.start([](const core::ProgressFn&) { return QString(); }));
    ASSERT_TRUE(QTest::qWaitFor([&] { return reported && task.progress() == 0.5; }, kWaitMs));
    task.cancel();
    ASSERT_TRUE(finished.wait(kWaitMs) || !finished.isEmpty());
    ASSERT_EQ(finished.size(), 1);
    EXPECT_EQ(finished.first().at(0).toString(), QStringLiteral("stopped"));
    EXPECT_TRUE(finished.first().at(1).toBool());
    EXPECT_FALSE(task.isRunning());
}

TEST(BackgroundTaskTest, AJobThatFinishesDespiteCancelSucceeds) {
    ui::BackgroundTask task;
    QSignalSpy finished(&task, &ui::BackgroundTask::finished);
    std::atomic<bool> started{false}, cancelled{false}, seen{false};
    ASSERT_TRUE(task.start([&](const core::ProgressFn& progress) {
        started = true;
        while (!cancelled)
            std::this_thread::yield();
        seen = !progress(1.0); // the cancel arrived, but the work is already done
        return QString();
    }));
    // Cancelled once running: a job cancelled before it starts never runs.
    ASSERT_TRUE(QTest::qWaitFor([&] { return bool(started); }, kWaitMs));
    task.cancel();
    cancelled = true;
    task.wait(); // reports at once
    ASSERT_EQ(finished.size(), 1);
    EXPECT_TRUE(seen);
    EXPECT_EQ(finished.first().at(0).toString(), QString());
    EXPECT_FALSE(finished.first().at(1).toBool());
    // The watcher's later report finds the job settled and says nothing more.
    QTest::qWait(50);
    EXPECT_EQ(finished.size(), 1);
}

} // namespace background_task_uitest
