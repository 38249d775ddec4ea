// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>

namespace core {

/** Reports progress in [0, 1] from a long operation; returning false asks it to cancel. */
using ProgressFn = std::function<bool(double fraction)>;

/** Calls fn if set; true means go on. */
inline bool reportProgress(const ProgressFn& fn, double fraction) {
    return !fn || fn(fraction);
}

} // namespace core
