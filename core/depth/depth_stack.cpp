// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/depth/depth_stack.h"

#include <algorithm>

namespace core {

std::pair<int, int> DepthStack::rowSpan(int y) const {
    // Offsets never fall: a row's first pixel with fragments is the first whose end is past the
    // row's start, and its pixels from the one starting at the row's end on are empty.
    const std::uint32_t* row = offsets.data() + std::size_t(y) * std::size_t(width);
    const std::uint32_t* rowEnd = row + width;
    const std::uint32_t* firstEnd = std::upper_bound(row + 1, rowEnd + 1, *row);
    if (firstEnd > rowEnd)
        return {0, 0};
    return {int(firstEnd - row) - 1, int(std::lower_bound(row, rowEnd, *rowEnd) - row)};
}

std::uint32_t DepthStack::maxLayers() const {
    std::uint32_t deepest = 0;
    const std::size_t pixels = offsets.empty() ? 0 : std::min(pixelCount(), offsets.size() - 1);
    for (std::size_t p = 0; p < pixels; ++p)
        deepest = std::max(deepest, layerCount(p));
    return deepest;
}

std::vector<std::uint32_t> DepthStack::fragmentsPerLayer() const {
    std::vector<std::uint32_t> counts(maxLayers(), 0);
    const std::size_t pixels = offsets.empty() ? 0 : std::min(pixelCount(), offsets.size() - 1);
    // Layer k is present at a pixel iff the pixel has at least k fragments, so counting the
    // pixels that end at each depth and summing from the back gives the per-layer counts.
    for (std::size_t p = 0; p < pixels; ++p)
        if (const std::uint32_t n = layerCount(p))
            ++counts[n - 1];
    for (std::size_t k = counts.size(); k-- > 1;)
        counts[k - 1] += counts[k];
    return counts;
}

} // namespace core
