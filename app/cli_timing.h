// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The timings layerpaint-cli reports: milliseconds since a start, medians and percentiles.

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

namespace cli {

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/** The median of values (0 if there are none). */
inline double median(std::vector<double> values) {
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/** The p-quantile of values, 0 <= p < 1, as the value at index p·n (0 if there are none). */
inline double percentile(std::vector<double> values, double p) {
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    return values[std::min(values.size() - 1, std::size_t(p * double(values.size())))];
}

} // namespace cli
