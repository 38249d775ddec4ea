// SPDX-License-Identifier: GPL-3.0-or-later
#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/helper_threads.h"

namespace helper_threads_test {

TEST(HelperThreads, EveryPartRunsOnceAndTheHelpersTakeTheirShare) {
    core::HelperThreads helpers(3);
    ASSERT_EQ(helpers.width(), 4);
    for (int parts : {1, 2, 4, 7}) {
        for (int round = 0; round < 50; ++round) { // the same helpers, job after job
            std::vector<std::atomic<int>> runs(static_cast<std::size_t>(parts));
            std::mutex lock;
            std::set<std::thread::id> threads;
            helpers.run(parts, [&](int part) {
                ++runs[std::size_t(part)];
                const std::lock_guard guard(lock);
                threads.insert(std::this_thread::get_id());
            });
            for (int part = 0; part < parts; ++part)
                ASSERT_EQ(runs[std::size_t(part)].load(), 1) << parts << " parts";
            // Part 0 on the calling thread, up to three more parts on the three helpers.
            EXPECT_EQ(threads.size(), std::size_t(std::min(parts, 4))) << parts << " parts";
            EXPECT_TRUE(threads.count(std::this_thread::get_id()));
        }
    }
}

TEST(HelperThreads, TheFirstExceptionInPartOrderReachesTheCallerAfterEveryPartRan) {
    core::HelperThreads helpers(1);
    std::atomic<int> finished = 0;
    EXPECT_THROW(helpers.run(4,
                             [&](int part) {
                                 ++finished;
                                 if (part == 1)
                                     throw std::logic_error("part 1");
                                 if (part == 3)
                                     throw std::runtime_error("part 3");
                             }),
                 std::logic_error);
    EXPECT_EQ(finished.load(), 4);
    // The helpers still work after a part threw.
    std::atomic<int> after = 0;
    helpers.run(2, [&](int) { ++after; });
    EXPECT_EQ(after.load(), 2);
}

TEST(HelperThreads, TwoCallersAtOnceBothFinishTheirWork) {
    core::HelperThreads helpers(1);
    std::atomic<int> first = 0, second = 0;
    std::thread other([&] {
        for (int i = 0; i < 200; ++i)
            helpers.run(2, [&](int) { ++second; });
    });
    for (int i = 0; i < 200; ++i)
        helpers.run(2, [&](int) { ++first; });
    other.join();
    EXPECT_EQ(first.load(), 400);
    EXPECT_EQ(second.load(), 400);
}

TEST(HelperThreads, WithoutHelpersTheCallerRunsEveryPart) {
    core::HelperThreads helpers(0);
    EXPECT_EQ(helpers.width(), 1);
    std::vector<int> order;
    helpers.run(3, [&](int part) { order.push_back(part); });
    EXPECT_EQ(order, (std::vector<int>{0, 1, 2}));
}

} // namespace helper_threads_test
