// SPDX-License-Identifier: GPL-3.0-or-later
// Threads kept for short parallel work that runs many times a second (the parts of a dab), so
// that such work does not pay for starting and joining a thread each time as parallelRanges()
// does.
#pragma once

#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace core {

class HelperThreads {
public:
    /** The process's helpers: one fewer than the hardware threads (none on one core). */
    static HelperThreads& shared();

    explicit HelperThreads(unsigned helpers);
    ~HelperThreads();
    HelperThreads(const HelperThreads&) = delete;
    HelperThreads& operator=(const HelperThreads&) = delete;

    /** How many parts run() can run at once: the helpers and the calling thread. */
    int width() const { return int(m_helpers.size()) + 1; }

    /**
     * Calls fn(part) for every part in [0, parts) and returns when all are done: part 0 on the
     * calling thread, the others on helpers. Parts beyond the helpers, and every part while
     * another thread is running work on them, run on the calling thread after part 0. If parts
     * throw, every part still runs and the first exception in part order is rethrown.
     */
    void run(int parts, const std::function<void(int)>& fn);

private:
    void loop(std::size_t helper);

    std::mutex m_use; // one caller at a time
    std::vector<std::jthread> m_helpers;
    // The job: generation counts the jobs; a helper h runs part h + 1 if it is below parts.
    std::atomic<std::uint32_t> m_generation{0};
    std::atomic<int> m_pending{0}; // helpers that have not answered the job
    std::atomic<bool> m_stop{false};
    const std::function<void(int)>* m_fn = nullptr;
    int m_parts = 0;
    std::vector<std::exception_ptr> m_errors;
};

} // namespace core
