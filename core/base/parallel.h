// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cstddef>
#include <system_error>
#include <thread>
#include <vector>

namespace core {

/** The number of workers for a request: 0 means std::thread::hardware_concurrency(), never 0. */
inline unsigned resolveThreadCount(unsigned requested) {
    if (requested == 0)
        requested = std::thread::hardware_concurrency();
    return std::max(requested, 1u);
}

/** Start of part `part` when [0, count) is split into `parts` contiguous, nearly equal ranges. */
inline int splitBegin(int count, int parts, int part) {
    return int(static_cast<long long>(count) * part / parts);
}

/** How many parts parallelRanges() uses for count items and a thread request. */
inline int partCount(int count, unsigned threads) {
    return std::max(1, std::min(count, int(std::min(resolveThreadCount(threads), 1024u))));
}

/**
 * Calls fn(part, begin, end) for each of partCount(count, threads) contiguous parts of
 * [0, count); part 0 runs on the calling thread, the others on their own std::thread. Returns
 * when every part is done. A part whose thread cannot be started runs on the calling thread, so
 * the work is always done. Callers that need results independent of the thread count must make
 * each part's output depend only on its items (or stitch parts in part order).
 */
template <typename Fn> void parallelRanges(int count, unsigned threads, Fn&& fn) {
    const int parts = partCount(count, threads);
    if (parts == 1) {
        fn(0, 0, std::max(count, 0));
        return;
    }
    std::vector<std::thread> workers;
    std::vector<int> inlineParts;
    workers.reserve(std::size_t(parts - 1));
    for (int part = 1; part < parts; ++part) {
        const int begin = splitBegin(count, parts, part), end = splitBegin(count, parts, part + 1);
        try {
            workers.emplace_back([&fn, part, begin, end] { fn(part, begin, end); });
        } catch (const std::system_error&) {
            inlineParts.push_back(part);
        }
    }
    fn(0, 0, splitBegin(count, parts, 1));
    for (int part : inlineParts)
        fn(part, splitBegin(count, parts, part), splitBegin(count, parts, part + 1));
    for (std::thread& worker : workers)
        worker.join();
}

} // namespace core
