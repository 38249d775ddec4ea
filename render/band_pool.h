// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace render {

/**
 * Worker threads kept for the capture's lifetime. run() shares bands between them and the
 * calling thread and returns as soon as every band is done, without waiting for a worker the OS
 * has not scheduled yet: on a busy 2-core machine a thread started per capture often began
 * milliseconds late, after the calling thread had done all the work alone.
 */
class BandPool {
public:
    explicit BandPool(int workers);
    ~BandPool();
    BandPool(const BandPool&) = delete;
    BandPool& operator=(const BandPool&) = delete;

    /** Calls work(b) once for every b in [0, count); false if a call threw (out of memory). */
    bool run(int count, const std::function<void(int)>& work);

private:
    void drain();
    void workerLoop();

    std::mutex m_mutex;
    std::condition_variable m_wake, m_done;
    const std::function<void(int)>* m_work = nullptr;
    int m_count = 0, m_next = 0, m_finished = 0;
    bool m_failed = false, m_stop = false;
    std::uint64_t m_generation = 0;
    std::vector<std::thread> m_threads;
};

} // namespace render
