// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/base/index.h"

namespace core {

/**
 * Every captured fragment of one view as per-pixel lists sorted front to back (docs/architecture.md
 * §3 step 2), stored compactly: the fragments of pixel p = y * width + x are indices [offsets[p],
 * offsets[p + 1]) of the per-fragment arrays, layer 1 first. Layer k of a pixel is its k-th
 * fragment, so a fragment on layer j implies fragments on layers 1..j-1. Pixel y = 0 is the top
 * row.
 */
struct DepthStack {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> offsets;  // width * height + 1
    std::vector<float> depth;            // positive view-space depth, in view (model) units
    std::vector<std::uint32_t> triangle; // triangle id (index into Mesh triangles)
    // Nothing else is stored per fragment: the surface point, uv and normal follow from the
    // triangle and the pixel's ray, which keeps capture at 8 bytes a fragment.

    std::size_t pixelCount() const { return std::size_t(width) * std::size_t(height); }
    std::size_t fragmentCount() const { return depth.size(); }
    std::uint32_t layerCount(std::size_t pixel) const {
        return offsets[pixel + 1] - offsets[pixel];
    }
    /** Index of the fragment on 1-based layer at pixel, or kNone. */
    std::uint32_t fragment(std::size_t pixel, std::uint32_t layer) const {
        return layer >= 1 && layer <= layerCount(pixel) ? offsets[pixel] + layer - 1 : kNone;
    }
    /**
     * The columns [first, last] of row y between its first and last pixel with fragments, as
     * {first, last + 1}; {0, 0} for a row without any. Loops over a row's fragments can start and
     * stop there instead of visiting every empty pixel around the model.
     */
    std::pair<int, int> rowSpan(int y) const;
    /** The deepest layer anywhere in the view. */
    std::uint32_t maxLayers() const;
    /** Fragments on each layer: result[k - 1] for layer k. */
    std::vector<std::uint32_t> fragmentsPerLayer() const;
};

} // namespace core
