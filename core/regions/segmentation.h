// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/depth/connectivity.h"
#include "core/depth/depth_stack.h"

namespace core {

/** One region: a 4-connected component of same-layer links on one layer. */
struct Region {
    std::uint32_t id = 0;
    std::uint32_t layer = 0;                    // 1-based
    std::uint32_t pixels = 0;                   // fragments (one per pixel)
    int minX = 0, minY = 0, maxX = 0, maxY = 0; // inclusive bounding box in pixels
};

/** A region graph edge seen from one end. */
struct RegionLink {
    std::uint32_t region = 0;
    /** Cross-layer pixel links between the two regions, counting both directions. */
    std::uint32_t links = 0;

    friend bool operator==(const RegionLink&, const RegionLink&) = default;
};

/**
 * Region-level connectivity: nodes are regions (indexed by id), edges join regions with
 * cross-layer pixel links. Undirected: an edge's count is the number of links from r to s plus
 * the number from s to r, and it is listed under both ends, sorted by neighbour id.
 */
struct RegionGraph {
    std::vector<Region> regions;
    std::vector<std::uint32_t> neighborOffsets; // regions.size() + 1
    std::vector<RegionLink> neighbors;

    std::span<const RegionLink> neighborsOf(std::uint32_t region) const {
        return {neighbors.data() + neighborOffsets[region],
                neighbors.data() + neighborOffsets[region + 1]};
    }
};

/** Region ids of every fragment plus the region graph of one view. */
struct Segmentation {
    /** Per fragment of the LayerStack: its region id. */
    std::vector<std::uint32_t> region;
    RegionGraph graph;
};

/**
 * Segments a LayerStack by its connectivity (docs/architecture.md §3 step 2). Two fragments at
 * neighbouring pixels on the same layer are in one region when either links to the other.
 * Region ids are ordered by layer, then by the row-major scan position of the region's first
 * pixel, so they do not depend on the thread count (0 = hardware concurrency). Links that point
 * outside the neighbour's fragment list are ignored. Returns an empty Segmentation when the
 * connectivity does not match the stack.
 */
/** Where segmentLayers() spends its time (milliseconds). */
struct SegmentationTimings {
    double labelsMs = 0.0; // union-find, region ids and per-band link lists
    double graphMs = 0.0;  // region nodes and edges assembled from them
};

Segmentation segmentLayers(const LayerStack& stack, const Connectivity& connectivity,
                           unsigned threads = 0, SegmentationTimings* timings = nullptr);

} // namespace core
