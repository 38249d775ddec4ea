// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/band_pool.h"

#include <exception>

namespace render {

BandPool::BandPool(int workers) {
    for (int i = 0; i < workers; ++i)
        m_threads.emplace_back([this] { workerLoop(); });
}

BandPool::~BandPool() {
    {
        const std::lock_guard lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    for (std::thread& thread : m_threads)
        thread.join();
}

bool BandPool::run(int count, const std::function<void(int)>& work) {
    {
        const std::lock_guard lock(m_mutex);
        m_work = &work;
        m_count = count;
        m_next = m_finished = 0;
        m_failed = false;
        ++m_generation;
    }
    m_wake.notify_all();
    drain();
    std::unique_lock lock(m_mutex);
    m_done.wait(lock, [&] { return m_finished == m_count; });
    m_work = nullptr;
    m_count = m_next = 0; // a worker waking late finds nothing to do
    return !m_failed;
}

void BandPool::drain() {
    std::unique_lock lock(m_mutex);
    while (m_next < m_count) {
        const int band = m_next++;
        const std::function<void(int)>* work = m_work;
        lock.unlock();
        bool failed = false;
        try {
            (*work)(band);
        } catch (const std::exception&) {
            failed = true;
        }
        lock.lock();
        m_failed = m_failed || failed;
        if (++m_finished == m_count)
            m_done.notify_all();
    }
}

void BandPool::workerLoop() {
    std::uint64_t seen = 0;
    for (;;) {
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [&] { return m_stop || m_generation != seen; });
            if (m_stop)
                return;
            seen = m_generation;
        }
        drain();
    }
}

} // namespace render
