// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/base/helper_threads.h"

#include <algorithm>
#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace core {

namespace {

/**
 * How long a thread checks for what it waits for before it sleeps: the parts of a dab come
 * within this of each other, and waking a sleeping thread takes tens of microseconds.
 */
constexpr auto kSpin = std::chrono::microseconds(200);

/** Waits until value differs from old: spinning for kSpin, then asleep. */
template <typename T> T waitWhile(const std::atomic<T>& value, T old) {
    const auto until = std::chrono::steady_clock::now() + kSpin;
    for (unsigned i = 1;; ++i) {
        const T now = value.load(std::memory_order_acquire);
        if (now != old)
            return now;
#if defined(__x86_64__) || defined(__i386__)
        _mm_pause();
#endif
        if (i % 64 == 0 && std::chrono::steady_clock::now() >= until)
            break;
    }
    for (T now; (now = value.load(std::memory_order_acquire)) == old;)
        value.wait(old, std::memory_order_acquire);
    return value.load(std::memory_order_acquire);
}

} // namespace

HelperThreads& HelperThreads::shared() {
    static HelperThreads helpers(std::max(std::thread::hardware_concurrency(), 1u) - 1u);
    return helpers;
}

HelperThreads::HelperThreads(unsigned helpers) {
    try {
        for (unsigned h = 0; h < helpers; ++h)
            m_helpers.emplace_back([this, h] { loop(h); });
    } catch (const std::system_error&) {
        // Fewer helpers than asked for: run() gives the calling thread the rest.
    }
    m_errors.resize(m_helpers.size() + 1);
}

HelperThreads::~HelperThreads() {
    m_stop.store(true);
    m_generation.fetch_add(1);
    m_generation.notify_all();
    m_helpers.clear(); // joins
}

void HelperThreads::loop(std::size_t helper) {
    std::uint32_t seen = 0;
    for (;;) {
        seen = waitWhile(m_generation, seen);
        if (m_stop.load())
            return;
        // Every helper answers every job, with a part or without: the next job cannot start
        // (and change the job's fields) before all have read this one's.
        if (const int part = int(helper) + 1; part < m_parts) {
            try {
                (*m_fn)(part);
            } catch (...) {
                m_errors[std::size_t(part)] = std::current_exception();
            }
        }
        if (m_pending.fetch_sub(1, std::memory_order_acq_rel) == 1)
            m_pending.notify_one();
    }
}

void HelperThreads::run(int parts, const std::function<void(int)>& fn) {
    if (parts <= 0)
        return;
    std::unique_lock lock(m_use, std::try_to_lock);
    const int onHelpers = lock.owns_lock() ? std::min(parts, width()) : 1;
    if (onHelpers > 1) {
        std::fill(m_errors.begin(), m_errors.end(), nullptr);
        m_fn = &fn;
        m_parts = onHelpers;
        m_pending.store(int(m_helpers.size()), std::memory_order_relaxed);
        m_generation.fetch_add(1, std::memory_order_release);
        m_generation.notify_all();
    }
    std::exception_ptr first;
    try {
        fn(0);
    } catch (...) {
        first = std::current_exception();
    }
    if (onHelpers > 1) {
        for (int left; (left = m_pending.load(std::memory_order_acquire)) != 0;)
            waitWhile(m_pending, left);
        for (int part = 1; part < onHelpers && !first; ++part)
            first = m_errors[std::size_t(part)];
    }
    for (int part = onHelpers; part < parts; ++part) {
        try {
            fn(part);
        } catch (...) {
            if (!first)
                first = std::current_exception();
        }
    }
    if (first)
        std::rethrow_exception(first);
}

} // namespace core
