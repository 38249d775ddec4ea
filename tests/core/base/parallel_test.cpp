// SPDX-License-Identifier: GPL-3.0-or-later
#include <atomic>
#include <new>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/parallel.h"

namespace parallel_test {

TEST(ParallelRanges, EveryItemIsVisitedOnceInContiguousParts) {
    for (unsigned threads : {1u, 2u, 3u, 8u}) {
        std::vector<int> seen(1000, 0);
        core::parallelRanges(int(seen.size()), threads, [&](int, int begin, int end) {
            for (int i = begin; i < end; ++i)
                ++seen[std::size_t(i)];
        });
        for (int count : seen)
            ASSERT_EQ(count, 1) << threads << " threads";
    }
}

TEST(ParallelRanges, AThrowingPartReachesTheCallerAfterTheOthersFinished) {
    std::atomic<int> finished = 0;
    const auto work = [&](int part, int, int) {
        if (part == 2)
            throw std::bad_alloc();
        if (part == 3)
            throw std::runtime_error("later part");
        ++finished;
    };
    EXPECT_THROW(core::parallelRanges(100, 4, work), std::bad_alloc); // the first in part order
    EXPECT_EQ(finished.load(), 2);
    // The calling thread's own part throwing is reported the same way.
    EXPECT_THROW(core::parallelRanges(100, 4,
                                      [](int part, int, int) {
                                          if (part == 0)
                                              throw std::runtime_error("part 0");
                                      }),
                 std::runtime_error);
}

} // namespace parallel_test
