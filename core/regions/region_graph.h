// SPDX-License-Identifier: GPL-3.0-or-later
// core/regions/: regions and their order: the segmentation of the depth layers, the region
// graph and its layout, the region order (pop-up, hiding).
//
// The region graph: the regions of one view's segmentation and their cross-layer links (the
// paper's region-level connectivity). Made by segmentDepthLayers() (segmentation.h), laid out for
// the Region Graph panel by region_graph_layout.h, reordered by region_order.h.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace core {

/** One region: a 4-connected component of same-layer links on one depth layer. */
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

} // namespace core
