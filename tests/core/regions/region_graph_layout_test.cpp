// SPDX-License-Identifier: GPL-3.0-or-later
// The region graph's drawing without a widget: merging, packing, filters, 10,000 regions.
#include <algorithm>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "core/regions/region_graph_layout.h"

namespace region_graph_layout_test {

using core::kNone;
using core::RegionGraphLayout;

/** A graph from regions (layer, pixels, centre row) and undirected links (a, b, count). */
struct Link {
    std::uint32_t a, b, links;
};
core::RegionGraph makeGraph(const std::vector<core::Region>& regions,
                            const std::vector<Link>& links) {
    core::RegionGraph graph;
    graph.regions = regions;
    for (std::size_t i = 0; i < graph.regions.size(); ++i)
        graph.regions[i].id = std::uint32_t(i);
    std::vector<std::vector<core::RegionLink>> lists(regions.size());
    for (const Link& l : links) {
        lists[l.a].push_back({l.b, l.links});
        lists[l.b].push_back({l.a, l.links});
    }
    graph.neighborOffsets.push_back(0);
    for (auto& list : lists) {
        std::sort(list.begin(), list.end(),
                  [](const core::RegionLink& x, const core::RegionLink& y) {
                      return x.region < y.region;
                  });
        graph.neighbors.insert(graph.neighbors.end(), list.begin(), list.end());
        graph.neighborOffsets.push_back(std::uint32_t(graph.neighbors.size()));
    }
    return graph;
}

core::Region region(std::uint32_t layer, std::uint32_t pixels, int row) {
    core::Region r;
    r.layer = layer;
    r.pixels = pixels;
    r.minY = row - 2;
    r.maxY = row + 2;
    r.maxX = 10;
    return r;
}

/** No two nodes of one column overlap, and every node lies inside the reported extent. */
void expectPacked(const RegionGraphLayout& layout) {
    for (std::size_t i = 0; i < layout.nodes.size(); ++i) {
        const RegionGraphLayout::Node& a = layout.nodes[i];
        EXPECT_GE(a.y - a.radius, layout.top - 1e-9);
        EXPECT_LE(a.y + a.below(), layout.bottom + 1e-9);
        for (std::size_t j = i + 1; j < layout.nodes.size(); ++j) {
            const RegionGraphLayout::Node& b = layout.nodes[j];
            if (a.layer != b.layer)
                continue;
            const bool apart =
                a.y + a.below() + RegionGraphLayout::kNodeGap <= b.y - b.radius + 1e-9 ||
                b.y + b.below() + RegionGraphLayout::kNodeGap <= a.y - a.radius + 1e-9;
            EXPECT_TRUE(apart) << "nodes " << i << " and " << j << " overlap";
        }
    }
}

TEST(RegionGraphLayout, ColumnsFollowTheViewAndEdgesSumTheLinks) {
    // Layer 1: a region at the top and one at the bottom of a 100-pixel view; layer 2: one in
    // the middle linked to both.
    const core::RegionGraph graph = makeGraph(
        {region(1, 400, 10), region(1, 100, 90), region(2, 50, 50)}, {{0, 2, 30}, {1, 2, 5}});
    const RegionGraphLayout layout = core::layoutRegionGraph(graph, 100);
    ASSERT_EQ(layout.nodes.size(), 3u);
    EXPECT_EQ(layout.layerCount, 2u);
    EXPECT_EQ(layout.mergedRegions, 0u);
    EXPECT_EQ(layout.hiddenRegions, 0u);
    // By layer, top to bottom.
    EXPECT_EQ(layout.nodes[0].region, 0u);
    EXPECT_EQ(layout.nodes[1].region, 1u);
    EXPECT_EQ(layout.nodes[2].region, 2u);
    EXPECT_LT(layout.nodes[0].y, layout.nodes[1].y);
    // Sized by pixels: the largest gets the largest radius.
    EXPECT_DOUBLE_EQ(layout.nodes[0].radius, RegionGraphLayout::kMaxRadius);
    EXPECT_LT(layout.nodes[2].radius, layout.nodes[1].radius);
    EXPECT_EQ(layout.nodes[2].neighbors, 2u);
    ASSERT_EQ(layout.edges.size(), 2u);
    EXPECT_EQ(layout.edges[0].a, 0);
    EXPECT_EQ(layout.edges[0].b, 2);
    EXPECT_EQ(layout.edges[0].links, 30u);
    EXPECT_EQ(layout.edges[1].links, 5u);
    // Pulled towards its more strongly linked neighbour, the top one.
    EXPECT_LT(layout.nodes[2].y, 0.5 * (layout.nodes[0].y + layout.nodes[1].y));
    expectPacked(layout);
}

TEST(RegionGraphLayout, SmallRegionsOfALayerShareOneNodeAtTheBottom) {
    std::vector<core::Region> regions;
    std::vector<Link> links;
    for (int i = 0; i < 40; ++i)
        regions.push_back(region(1, std::uint32_t(1000 - i), 5 * i));
    core::RegionGraphLayoutOptions options;
    options.maxNodesPerLayer = 10;
    const RegionGraphLayout layout =
        core::layoutRegionGraph(makeGraph(regions, links), 200, options);
    ASSERT_EQ(layout.nodes.size(), 10u);
    EXPECT_EQ(layout.mergedRegions, 31u);
    const RegionGraphLayout::Node& merged = layout.nodes.back();
    EXPECT_TRUE(merged.merged());
    EXPECT_EQ(merged.members, 31u);
    for (const RegionGraphLayout::Node& node : layout.nodes) {
        if (!node.merged()) {
            EXPECT_LT(node.region, 9u); // the nine largest
            EXPECT_LT(node.y, merged.y);
        }
    }
    expectPacked(layout);
}

TEST(RegionGraphLayout, FiltersBySizeAndByNeighbourhood) {
    const core::RegionGraph graph =
        makeGraph({region(1, 500, 10), region(1, 8, 30), region(2, 300, 50), region(2, 40, 70),
                   region(3, 20, 60)},
                  {{0, 2, 10}, {1, 2, 3}, {2, 4, 6}, {3, 4, 2}});
    core::RegionGraphLayoutOptions options;
    options.minPixels = 30;
    RegionGraphLayout layout = core::layoutRegionGraph(graph, 100, options);
    std::set<std::uint32_t> shown;
    for (const auto& node : layout.nodes)
        shown.insert(node.region);
    EXPECT_EQ(shown, (std::set<std::uint32_t>{0, 2, 3}));
    EXPECT_EQ(layout.hiddenRegions, 2u);
    EXPECT_EQ(layout.layerCount, 2u);
    ASSERT_EQ(layout.edges.size(), 1u); // only 0-2 joins shown regions
    EXPECT_EQ(layout.edges[0].links, 10u);

    options = {};
    options.focus = 4;
    layout = core::layoutRegionGraph(graph, 100, options);
    shown.clear();
    for (const auto& node : layout.nodes)
        shown.insert(node.region);
    EXPECT_EQ(shown, (std::set<std::uint32_t>{2, 3, 4}));
    EXPECT_EQ(layout.hiddenRegions, 2u);
    EXPECT_EQ(layout.edges.size(), 2u);

    // Both at once; an unknown focus shows everything.
    options.minPixels = 30;
    layout = core::layoutRegionGraph(graph, 100, options);
    EXPECT_EQ(layout.nodes.size(), 2u);
    options.focus = 99;
    options.minPixels = 0;
    EXPECT_EQ(core::layoutRegionGraph(graph, 100, options).nodes.size(), 5u);
}

TEST(RegionGraphLayout, TenThousandRegionsOnSeventeenLayers) {
    std::mt19937 random(7);
    std::vector<core::Region> regions;
    std::vector<Link> links;
    for (int i = 0; i < 10000; ++i) {
        const auto layer = std::uint32_t(1 + i % 17);
        regions.push_back(region(layer, std::uint32_t(1 + random() % 5000), int(random() % 720)));
        if (i >= 17)
            links.push_back(
                {std::uint32_t(i), std::uint32_t(i - 17 + 1), 1 + std::uint32_t(random() % 50)});
    }
    const core::RegionGraph graph = makeGraph(regions, links);
    const RegionGraphLayout layout = core::layoutRegionGraph(graph, 720);
    EXPECT_EQ(layout.layerCount, 17u);
    EXPECT_EQ(layout.nodes.size(), 17u * 24u);
    EXPECT_EQ(layout.mergedRegions, 10000u - 17u * 23u);
    expectPacked(layout);
    // Deterministic.
    const RegionGraphLayout again = core::layoutRegionGraph(graph, 720);
    ASSERT_EQ(again.nodes.size(), layout.nodes.size());
    for (std::size_t i = 0; i < layout.nodes.size(); ++i) {
        EXPECT_EQ(again.nodes[i].region, layout.nodes[i].region);
        EXPECT_EQ(again.nodes[i].y, layout.nodes[i].y);
    }
    // Hiding the regions under 2,500 pixels leaves about half of them.
    core::RegionGraphLayoutOptions options;
    options.minPixels = 2500;
    const RegionGraphLayout big = core::layoutRegionGraph(graph, 720, options);
    EXPECT_GT(big.hiddenRegions, 4000u);
    EXPECT_LT(big.hiddenRegions, 6000u);
    for (const auto& node : big.nodes) {
        if (!node.merged()) {
            EXPECT_GE(graph.regions[node.region].pixels, 2500u);
        }
    }
}

TEST(RegionGraphLayout, EmptyAndBrokenGraphs) {
    const RegionGraphLayout empty = core::layoutRegionGraph({}, 100);
    EXPECT_TRUE(empty.nodes.empty());
    EXPECT_EQ(empty.layerCount, 0u);
    core::RegionGraph broken = makeGraph({region(1, 10, 5), region(0, 10, 5)}, {});
    broken.neighborOffsets.clear(); // no adjacency: nodes without edges
    const RegionGraphLayout layout = core::layoutRegionGraph(broken, 0);
    EXPECT_EQ(layout.nodes.size(), 1u); // the layer-0 region is no node
    EXPECT_TRUE(layout.edges.empty());
}

} // namespace region_graph_layout_test
