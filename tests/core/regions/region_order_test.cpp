// SPDX-License-Identifier: GPL-3.0-or-later
// The region order of docs/architecture.md §3 step 3: the paper's pop-up example, two-level pop-up,
// cycling at a pixel, pruning and paint-to-hide.
#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/paint/tracking/stroke_tracker.h"
#include "core/regions/region_order.h"

namespace region_order_test {

using core::kNone;
using core::RegionOrder;
using Ids = std::vector<std::uint32_t>;

/** A region graph with the given layers (region id = index) and undirected edges. */
core::RegionGraph makeGraph(const Ids& layers,
                            const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges) {
    core::RegionGraph g;
    for (std::uint32_t r = 0; r < layers.size(); ++r) {
        core::Region region;
        region.id = r;
        region.layer = layers[r];
        g.regions.push_back(region);
    }
    std::vector<std::vector<core::RegionLink>> adj(layers.size());
    for (auto [a, b] : edges) {
        adj[a].push_back({b, 1});
        adj[b].push_back({a, 1});
    }
    g.neighborOffsets.push_back(0);
    for (auto& list : adj) {
        std::sort(list.begin(), list.end(),
                  [](const auto& x, const auto& y) { return x.region < y.region; });
        g.neighbors.insert(g.neighbors.end(), list.begin(), list.end());
        g.neighborOffsets.push_back(std::uint32_t(g.neighbors.size()));
    }
    return g;
}

/** The paper's Figure 5 view: s1..s3 on layer 1, s4..s6 on 2, s7..s9 on 3; s4 touches s1, s9. */
constexpr std::uint32_t s(int n) {
    return std::uint32_t(n - 1);
}
core::RegionGraph paperGraph() {
    return makeGraph({1, 1, 1, 2, 2, 2, 3, 3, 3}, {{s(4), s(1)}, {s(4), s(9)}});
}

/** Regions sorted by rank (hidden ones left out) must give order() without the hidden ones. */
void expectRanksMatchOrder(const RegionOrder& order) {
    const Ids rank = order.ranks();
    ASSERT_EQ(rank.size(), order.regionCount());
    Ids byRank(order.regionCount(), kNone);
    std::uint32_t visible = 0;
    for (std::uint32_t r = 0; r < rank.size(); ++r) {
        EXPECT_EQ(rank[r] == kNone, order.isHidden(r)) << r;
        if (rank[r] != kNone) {
            ASSERT_LT(rank[r], rank.size());
            byRank[rank[r]] = r;
            ++visible;
        }
    }
    byRank.resize(visible);
    Ids expected;
    for (std::uint32_t r : order.order())
        if (!order.isHidden(r))
            expected.push_back(r);
    EXPECT_EQ(byRank, expected);
}

TEST(RegionOrderTest, InitialOrderIsByLayerThenId) {
    // Ids not sorted by layer on purpose.
    const RegionOrder order(makeGraph({2, 1, 3, 1}, {}));
    EXPECT_EQ(order.order(), (Ids{1, 3, 0, 2}));
    EXPECT_EQ(order.ranks(), (Ids{2, 0, 3, 1}));
    expectRanksMatchOrder(order);
    EXPECT_TRUE(RegionOrder().order().empty());
}

TEST(RegionOrderTest, PaperExample) {
    RegionOrder order(paperGraph());
    EXPECT_EQ(order.order(), (Ids{s(1), s(2), s(3), s(4), s(5), s(6), s(7), s(8), s(9)}));
    order.popUpWithNeighbours(s(4));
    EXPECT_EQ(order.order(), (Ids{s(4), s(1), s(9), s(2), s(3), s(5), s(6), s(7), s(8)}));
    EXPECT_EQ(order.pruned(false), (Ids{s(4), s(1), s(9), s(2), s(3)}));
    EXPECT_EQ(order.pruned(true), (Ids{s(4), s(1), s(9), s(2), s(3)}));
    expectRanksMatchOrder(order);
}

TEST(RegionOrderTest, AutomaticPopUpMovesOnlyTheRegion) {
    RegionOrder order(paperGraph());
    order.popUp(s(4));
    EXPECT_EQ(order.order(), (Ids{s(4), s(1), s(2), s(3), s(5), s(6), s(7), s(8), s(9)}));
    order.popUp(s(8));
    EXPECT_EQ(order.order(), (Ids{s(8), s(4), s(1), s(2), s(3), s(5), s(6), s(7), s(9)}));
    order.popUp(99); // unknown: ignored
    EXPECT_EQ(order.order().size(), 9u);
    expectRanksMatchOrder(order);
}

TEST(RegionOrderTest, TwoLevelPopUpSortsTheGroupByLayer) {
    // 0, 1: layer 1; 2, 3: layer 2; 4, 5: layer 3; 6: layer 4.
    // Level 1 of 2: {0, 4}; level 2: {3} (via 0), {6} (via 4); level 3 (not popped): 1, 5.
    RegionOrder order(
        makeGraph({1, 1, 2, 2, 3, 3, 4}, {{2, 0}, {2, 4}, {0, 3}, {4, 6}, {6, 1}, {3, 5}}));
    order.popUpWithNeighbours(2);
    EXPECT_EQ(order.order(), (Ids{2, 0, 3, 4, 6, 1, 5}));
    // Popping from within the group reorders around the new region.
    order.popUpWithNeighbours(6);
    // Level 1 of 6: {1, 4}; level 2: {2} (via 4); 0, 3, 5 keep their relative order.
    EXPECT_EQ(order.order(), (Ids{6, 1, 2, 4, 0, 3, 5}));
    expectRanksMatchOrder(order);
}

TEST(RegionOrderTest, CycleThroughPixelRegionsAndBackToTop) {
    // A pixel with regions 0 (layer 1), 2 (layer 2), 4 (layer 3) front to back.
    RegionOrder order(makeGraph({1, 1, 2, 2, 3, 3}, {{0, 2}, {2, 4}, {1, 3}, {3, 5}}));
    const Ids pixel{0, 2, 4};
    EXPECT_EQ(order.visibleAt(pixel), 0u);
    const Ids expected{2, 4, 0, 2, 4, 0};
    for (std::uint32_t want : expected) {
        EXPECT_EQ(order.cycleAt(pixel), want);
        EXPECT_EQ(order.order().front(), want);
        EXPECT_EQ(order.visibleAt(pixel), want);
    }
    // Without neighbours as well.
    order.reset();
    for (std::uint32_t want : expected) {
        EXPECT_EQ(order.cycleAt(pixel, false), want);
        EXPECT_EQ(order.visibleAt(pixel), want);
    }
    // Hidden regions are skipped; nothing to pop when all are hidden.
    order.reset();
    order.hide(2);
    EXPECT_EQ(order.cycleAt(pixel), 4u);
    EXPECT_EQ(order.cycleAt(pixel), 0u);
    order.hide(0);
    order.hide(4);
    EXPECT_EQ(order.visibleAt(pixel), kNone);
    EXPECT_EQ(order.cycleAt(pixel), kNone);
    EXPECT_EQ(order.cycleAt(Ids{}), kNone);
}

TEST(RegionOrderTest, PruningAgainstDeeperLayersOnlyWithoutTransparency) {
    // 0, 1: layer 1; 2: layer 2; 3: layer 3.
    RegionOrder order(makeGraph({1, 1, 2, 3}, {}));
    EXPECT_EQ(order.pruned(false), (Ids{0, 1}));
    order.popUp(3);
    order.popUp(2);
    EXPECT_EQ(order.order(), (Ids{2, 3, 0, 1}));
    // Layer 2 is complete before region 3 (layer 3): covered, unless layer 2 is transparent.
    EXPECT_EQ(order.pruned(false), (Ids{2, 0, 1}));
    EXPECT_EQ(order.pruned(true), (Ids{2, 3, 0, 1}));
}

TEST(RegionOrderTest, HidingSkipsRanksAndPruning) {
    RegionOrder order(paperGraph());
    order.popUpWithNeighbours(s(4));
    order.hide(s(2));
    order.hide(s(2)); // twice is fine
    EXPECT_EQ(order.hiddenRegions(), (Ids{s(2)}));
    EXPECT_EQ(order.ranks()[s(2)], kNone);
    EXPECT_EQ(order.ranks()[s(3)], 3u);
    expectRanksMatchOrder(order);
    // Layer 1 no longer blocks (paint-to-hide); the complete layer 2 still covers layer 3.
    EXPECT_EQ(order.pruned(false), (Ids{s(4), s(1), s(9), s(3), s(5), s(6)}));
    EXPECT_EQ(order.pruned(true), (Ids{s(4), s(1), s(9), s(3), s(5), s(6), s(7), s(8)}));
    // A hidden layer-2 region stops layer 2 from blocking as well.
    order.hide(s(5));
    EXPECT_EQ(order.pruned(false), (Ids{s(4), s(1), s(9), s(3), s(6), s(7), s(8)}));
    order.unhide(s(5));
    EXPECT_EQ(order.hiddenRegions(), (Ids{s(2)}));
    order.hide(s(9));
    EXPECT_EQ(order.pruned(true), (Ids{s(4), s(1), s(3), s(5), s(6), s(7), s(8)}));
    // Hidden regions keep their place in the order.
    EXPECT_EQ(order.order(), (Ids{s(4), s(1), s(9), s(2), s(3), s(5), s(6), s(7), s(8)}));
    order.unhideAll();
    EXPECT_TRUE(order.hiddenRegions().empty());
    EXPECT_EQ(order.pruned(false), (Ids{s(4), s(1), s(9), s(2), s(3)}));
    expectRanksMatchOrder(order);
}

TEST(RegionOrderTest, ResetRestoresTheInitialOrderButKeepsHiding) {
    RegionOrder order(paperGraph());
    const Ids initial = order.order();
    order.popUpWithNeighbours(s(4));
    order.popUp(s(7));
    order.hide(s(6));
    order.reset();
    EXPECT_EQ(order.order(), initial);
    EXPECT_EQ(order.hiddenRegions(), (Ids{s(6)}));
    expectRanksMatchOrder(order);
}

TEST(RegionOrderTest, RanksDriveVisibleFragmentLookup) {
    // Two pixels: pixel 0 has regions 0 (layer 1) and 2 (layer 2); pixel 1 has region 1 only.
    core::DepthStack stack;
    stack.width = 2;
    stack.height = 1;
    stack.offsets = {0, 2, 3};
    stack.depth = {1.0f, 2.0f, 1.0f};
    stack.triangle = {0, 1, 2};
    const Ids fragmentRegion{0, 2, 1};
    RegionOrder order(makeGraph({1, 1, 2}, {{0, 2}}));
    EXPECT_EQ(core::regionsAtPixel(stack, fragmentRegion, 0), (Ids{0, 2}));
    EXPECT_EQ(core::regionsAtPixel(stack, fragmentRegion, 1), (Ids{1}));
    EXPECT_TRUE(core::regionsAtPixel(stack, fragmentRegion, 2).empty());

    const auto visible = [&](std::size_t pixel) {
        const Ids rank = order.ranks();
        return core::visibleFragmentByRank(stack, fragmentRegion, rank, pixel);
    };
    EXPECT_EQ(visible(0), 0u);
    EXPECT_EQ(order.cycleAt(core::regionsAtPixel(stack, fragmentRegion, 0)), 2u);
    EXPECT_EQ(visible(0), 1u);
    order.hide(2);
    EXPECT_EQ(visible(0), 0u);
    order.hide(1);
    EXPECT_EQ(visible(1), kNone);
}

} // namespace region_order_test
