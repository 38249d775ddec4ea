// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/index.h"
#include "core/regions/region_graph.h"

namespace core {

/** What a region graph drawing shows (RegionGraphLayout). */
struct RegionGraphLayoutOptions {
    /** Regions of one layer drawn as nodes of their own; the rest of the layer share one. */
    int maxNodesPerLayer = 24;
    /** Regions with fewer pixels are left out (0 shows all). */
    std::uint32_t minPixels = 0;
    /** When a region: only it and its neighbours are shown (kNone shows all). */
    std::uint32_t focus = kNone;
    /** The height the view's picture maps onto, in layout units. */
    double height = 320.0;
};

/**
 * A drawing of a region graph (the paper's Figure 3, right) in layout units: one column per depth
 * layer, a node per region sized by its pixels, an edge per pair of connected nodes with the
 * summed pixel links. Within a column nodes follow the regions' height in the view (spread over
 * the height used), nudged towards their neighbours by a few barycentric sweeps so most edges
 * run level, and packed so they never overlap. The largest regions of a layer get their own
 * node, the rest of the layer share one merged node at the bottom of its column. Columns are
 * placed by whoever draws it (x is not part of the layout). Deterministic.
 */
struct RegionGraphLayout {
    static constexpr double kMinRadius = 4.0;
    static constexpr double kMaxRadius = 18.0;
    static constexpr double kMergedMinRadius = 7.0;
    static constexpr double kNodeGap = 3.0;
    /** Room under a merged node for its "+N" label. */
    static constexpr double kMergedLabelSpace = 14.0;

    struct Node {
        std::uint32_t region = kNone; // kNone: merged small regions of the layer
        std::uint32_t layer = 1;
        std::uint32_t members = 1;   // regions in the node
        double pixels = 0.0;         // of its regions together
        std::uint32_t neighbors = 0; // the region's neighbours in the whole graph (0 if merged)
        double y = 0.0;              // centre
        double radius = kMinRadius;

        bool merged() const { return region == kNone; }
        /** Room the node needs below its centre. */
        double below() const { return radius + (merged() ? kMergedLabelSpace : 0.0); }
    };
    struct Edge {
        int a = 0, b = 0; // node indices, a < b
        std::uint64_t links = 0;
    };

    std::vector<Node> nodes;        // by layer, then as placed top to bottom
    std::vector<Edge> edges;        // sorted by (a, b)
    std::uint32_t layerCount = 0;   // deepest layer with a node
    double top = 0.0, bottom = 0.0; // of the nodes (bottom includes the merged labels)
    std::size_t mergedRegions = 0;  // regions drawn in merged nodes
    std::size_t hiddenRegions = 0;  // regions the filter left out
};

/** Lays out graph (of a view imageHeight pixels high) as options say. */
RegionGraphLayout layoutRegionGraph(const RegionGraph& graph, int imageHeight,
                                    const RegionGraphLayoutOptions& options = {});

} // namespace core
