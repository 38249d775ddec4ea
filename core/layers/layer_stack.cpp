// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/layers/layer_stack.h"

#include <algorithm>

namespace core {

std::uint32_t LayerStack::maxLayers() const {
    std::uint32_t deepest = 0;
    const std::size_t pixels = offsets.empty() ? 0 : std::min(pixelCount(), offsets.size() - 1);
    for (std::size_t p = 0; p < pixels; ++p)
        deepest = std::max(deepest, layerCount(p));
    return deepest;
}

std::vector<std::uint32_t> LayerStack::fragmentsPerLayer() const {
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
