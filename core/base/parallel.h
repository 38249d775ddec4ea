// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cstddef>
#include <exception>
#include <new>
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
 * [0, count); part 0 runs on the calling thread, the others on their own thread. Returns when
 * every part is done. A part whose thread cannot be started runs on the calling thread, so the
 * work is always done. If a part throws (e.g. std::bad_alloc), every other part still finishes
 * and the first exception, in part order, is rethrown on the calling thread. Callers that need
 * results independent of the thread count must make each part's output depend only on its items
 * (or stitch parts in part order).
 */
template <typename Fn> void parallelRanges(int count, unsigned threads, Fn&& fn) {
    const int parts = partCount(count, threads);
    if (parts == 1) {
        fn(0, 0, std::max(count, 0));
        return;
    }
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(parts));
    const auto run = [&fn, &errors, count, parts](int part) noexcept {
        try {
            fn(part, splitBegin(count, parts, part), splitBegin(count, parts, part + 1));
        } catch (...) {
            errors[std::size_t(part)] = std::current_exception();
        }
    };
    {
        std::vector<std::jthread> workers; // joined when the scope ends, whatever happens
        std::vector<int> inlineParts;
        try {
            workers.reserve(std::size_t(parts - 1));
        } catch (const std::bad_alloc&) {
        }
        for (int part = 1; part < parts; ++part) {
            try {
                workers.emplace_back(run, part);
            } catch (...) { // no thread (std::system_error) or no memory for one
                inlineParts.push_back(part);
            }
        }
        run(0);
        for (int part : inlineParts)
            run(part);
    }
    for (const std::exception_ptr& error : errors)
        if (error)
            std::rethrow_exception(error);
}

} // namespace core
