// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <vector>

#include "core/depth/connectivity.h"
#include "core/depth/depth_stack.h"
#include "core/regions/region_graph.h"

namespace core {

/** Region ids of every fragment plus the region graph of one view. */
struct Segmentation {
    /** Per fragment of the DepthStack: its region id. */
    std::vector<std::uint32_t> region;
    RegionGraph graph;
};

/** Where segmentDepthLayers() spends its time (milliseconds). */
struct SegmentationTimings {
    double labelsMs = 0.0; // union-find, region ids and per-band link lists
    double graphMs = 0.0;  // region nodes and edges assembled from them
};

/**
 * Segments a DepthStack by its connectivity (docs/architecture.md §3 step 2). Two fragments at
 * neighbouring pixels on the same layer are in one region when either links to the other.
 * Region ids are ordered by layer, then by the row-major scan position of the region's first
 * pixel, so they do not depend on the thread count (0 = hardware concurrency). Links that point
 * outside the neighbour's fragment list are ignored. Returns an empty Segmentation when the
 * connectivity does not match the stack.
 */
Segmentation segmentDepthLayers(const DepthStack& stack, const Connectivity& connectivity,
                                unsigned threads = 0, SegmentationTimings* timings = nullptr);

} // namespace core
