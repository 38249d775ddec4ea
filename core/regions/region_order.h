// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "core/depth/depth_stack.h"
#include "core/regions/segmentation.h"

namespace core {

/** What changes of a RegionOrder (the order and the hidden flags), for undo. */
struct RegionOrderState {
    std::vector<std::uint32_t> order;
    std::vector<std::uint8_t> hidden;

    std::size_t bytes() const { return order.size() * sizeof(std::uint32_t) + hidden.size(); }
    friend bool operator==(const RegionOrderState&, const RegionOrderState&) = default;
};

/**
 * The front-to-back region list of one view (docs/architecture.md §3 step 3; the paper's "Region
 * popup and sorting", "Back-to-front region rendering" and "Interactive Paint-to-Hide"). Initially
 * sorted by layer, then id. Hiding is separate from the order: a hidden region keeps its place in
 * order() (and moves with pop-ups) but gets no rank and is never drawn. Region ids outside the
 * graph are ignored by every operation. O(regions) per operation; deterministic.
 */
class RegionOrder {
public:
    RegionOrder() = default;
    /** Copies the region layers and the region graph's edges. */
    explicit RegionOrder(const RegionGraph& graph);

    std::size_t regionCount() const { return m_layer.size(); }
    /** Every region id, front to back, hidden ones included. */
    const std::vector<std::uint32_t>& order() const { return m_order; }
    /**
     * rank[r] = region r's place front to back among the non-hidden regions (0, 1, ...), kNone
     * when hidden: the format of visibleFragmentByRank and DepthCompositor::setRegionRanks.
     */
    std::vector<std::uint32_t> ranks() const;

    /** Automatic pop-up: moves region to the front. */
    void popUp(std::uint32_t region);
    /**
     * Intentional pop-up: region goes to the front, followed by the regions connected to it and
     * the regions connected to those (two-level recursion), all of them together sorted by layer,
     * then id (the paper sorts the additional regions by layer ID; the second level is not
     * placed after the first, so nearer layers of the group stay on top). The rest keep their
     * relative order. Hidden regions move with the group but stay hidden.
     */
    void popUpWithNeighbours(std::uint32_t region);
    /**
     * Intentional pop-up at a pixel whose regions front to back (one per layer, see
     * regionsAtPixel) are pixelRegions: pops up (with neighbours when withNeighbours) the first
     * non-hidden region below the currently visible one (the one first in the order), or, below
     * the deepest or when none is visible, the first non-hidden one from the top (layer 1),
     * so repeated calls cycle through the pixel's regions. Returns the region popped up, kNone
     * if every region there is hidden or unknown.
     */
    std::uint32_t cycleAt(std::span<const std::uint32_t> pixelRegions, bool withNeighbours = true);
    /** Of pixelRegions, the non-hidden one first in the order (the visible one), or kNone. */
    std::uint32_t visibleAt(std::span<const std::uint32_t> pixelRegions) const;

    /**
     * The regions to draw, front to back (draw them reversed): the non-hidden regions of order()
     * less those that cannot show. A region on layer i is dropped when, for some layer j < i,
     * every region of layer j comes before it; with transparency only j = 1 counts (only layer 1
     * is opaque). A layer with a hidden region never blocks (paint-to-hide: what lies below it
     * can show), so hiding a layer-1 region turns the layer-1 pruning off. The list ends once
     * layer 1 is complete and unhidden, as everything after it is covered.
     */
    std::vector<std::uint32_t> pruned(bool transparency) const;
    /**
     * ranks() restricted to pruned(transparency): the regions that cannot show get kNone too.
     * The visible fragment of every pixel is the same with either; drawing is cheaper with these.
     */
    std::vector<std::uint32_t> prunedRanks(bool transparency) const;

    /** Paint-to-hide. */
    void hide(std::uint32_t region);
    void unhide(std::uint32_t region);
    void unhideAll();
    bool isHidden(std::uint32_t region) const {
        return region < m_hidden.size() && m_hidden[region] != 0;
    }
    /** The hidden region ids, ascending. */
    std::vector<std::uint32_t> hiddenRegions() const;

    /** Back to the initial order (layer, then id); hidden regions stay hidden. */
    void reset();

    RegionOrderState state() const { return {m_order, m_hidden}; }
    /** Restores a state() of this order; false (nothing changed) if it has other regions. */
    bool setState(const RegionOrderState& state);

    /** Layer (1-based) of region, 0 if unknown. */
    std::uint32_t layerOf(std::uint32_t region) const {
        return region < m_layer.size() ? m_layer[region] : 0;
    }

private:
    void moveToFront(std::span<const std::uint32_t> group);

    std::vector<std::uint32_t> m_layer;           // per region id
    std::vector<std::uint32_t> m_neighborOffsets; // regionCount() + 1
    std::vector<std::uint32_t> m_neighbors;       // neighbour region ids
    std::vector<std::uint32_t> m_order;           // front to back
    std::vector<std::uint8_t> m_hidden;           // per region id
};

/**
 * The regions of pixel's fragments front to back (layer 1 first), kNone for a fragment without
 * a valid region; fragmentRegion is Segmentation::region.
 */
std::vector<std::uint32_t> regionsAtPixel(const DepthStack& stack,
                                          std::span<const std::uint32_t> fragmentRegion,
                                          std::size_t pixel);

/**
 * Paint-to-hide's footprint: the regions of the fragments visible (visibleFragmentByRank with
 * ranks) at pixels whose centre lies within radius of the segment from a to b, plus the pixel
 * under a itself; ascending, each once. Window pixels, y down.
 */
std::vector<std::uint32_t> visibleRegionsAlong(const DepthStack& stack,
                                               std::span<const std::uint32_t> fragmentRegion,
                                               std::span<const std::uint32_t> ranks, glm::vec2 a,
                                               glm::vec2 b, float radius);

} // namespace core
