// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/regions/region_graph_layout.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

namespace core {

namespace {

constexpr int kBarycentricSweeps = 4;

using Node = RegionGraphLayout::Node;

/** Per node while laying out: where the view puts it, and that nudged towards neighbours. */
struct Placement {
    double home = 0.0;
    double key = 0.0;
    std::vector<std::pair<int, double>> adjacent; // node, weight
};

/** Places one column's nodes in key order, as near their keys as the sizes allow. */
void packColumn(std::vector<Node>& nodes, const std::vector<Placement>& place,
                std::vector<int>& column, double height) {
    std::sort(column.begin(), column.end(), [&](int a, int b) {
        return place[a].key != place[b].key ? place[a].key < place[b].key : a < b;
    });
    double previousBottom = -1e300;
    for (int index : column) {
        Node& node = nodes[index];
        node.y =
            std::max(place[index].key, previousBottom + RegionGraphLayout::kNodeGap + node.radius);
        previousBottom = node.y + node.below();
    }
    // Pushed past the bottom: pull back up as far as the top allows.
    double nextTop = height;
    for (auto it = column.rbegin(); it != column.rend(); ++it) {
        Node& node = nodes[*it];
        node.y = std::min(node.y, nextTop - RegionGraphLayout::kNodeGap - node.below());
        nextTop = node.y - node.radius;
    }
    // A column taller than the height starts at the top instead.
    if (!column.empty() && nodes[column.front()].y - nodes[column.front()].radius < 0.0) {
        double top = 0.0;
        for (int index : column) {
            Node& node = nodes[index];
            node.y = std::max(node.y, top + node.radius);
            top = node.y + node.below() + RegionGraphLayout::kNodeGap;
        }
    }
}

/** The scratch of one layoutRegionGraph() call, which its passes fill in turn. */
struct LayoutPass {
    const RegionGraph& graph;
    const RegionGraphLayoutOptions& options;
    RegionGraphLayout& layout;
    double height = 0.0;
    double pictureHeight = 1.0;
    std::size_t regionCount = 0;
    bool graphValid = false;
    std::vector<std::uint8_t> shown;       // per region: whether the filter keeps it
    std::uint32_t layerCount = 0;          // deepest layer with a shown region
    std::vector<Placement> place;          // per node
    std::vector<int> nodeOf;               // per region: its node, -1 if none
    std::vector<std::vector<int>> columns; // per layer: its nodes
};

/** The filter: big enough, and the focus or one of its neighbours. */
void filterRegions(LayoutPass& s) {
    const RegionGraph& graph = s.graph;
    const RegionGraphLayoutOptions& options = s.options;
    s.shown.assign(s.regionCount, 1);
    if (options.focus != kNone && options.focus < s.regionCount && s.graphValid) {
        std::fill(s.shown.begin(), s.shown.end(), 0);
        s.shown[options.focus] = 1;
        for (const RegionLink& link : graph.neighborsOf(options.focus))
            if (link.region < s.regionCount)
                s.shown[link.region] = 1;
    }
    for (const Region& region : graph.regions)
        if (region.id < s.regionCount && region.pixels < options.minPixels)
            s.shown[region.id] = 0;
}

/** The shown regions' ids, per layer; the others are counted as hidden. */
std::vector<std::vector<std::uint32_t>> shownByLayer(LayoutPass& s) {
    s.layerCount = 0;
    for (const Region& region : s.graph.regions)
        if (region.id < s.regionCount && s.shown[region.id] && region.layer >= 1)
            s.layerCount = std::max(s.layerCount, region.layer);
    std::vector<std::vector<std::uint32_t>> byLayer(s.layerCount);
    for (const Region& region : s.graph.regions) {
        if (region.id >= s.regionCount || region.layer < 1 || !s.shown[region.id]) {
            ++s.layout.hiddenRegions;
            continue;
        }
        byLayer[region.layer - 1].push_back(region.id);
    }
    return byLayer;
}

/** Appends a node to layer l's column; its index. */
int addNode(LayoutPass& s, std::uint32_t l, const Node& node) {
    s.layout.nodes.push_back(node);
    s.place.emplace_back();
    const int index = int(s.layout.nodes.size() - 1);
    s.columns[l].push_back(index);
    return index;
}

/**
 * Layer l's nodes: the largest of its regions (ids) each get one, the rest share one. Each node
 * sums its regions' pixels and their pixel-weighted heights in the view.
 */
void addLayerNodes(LayoutPass& s, std::uint32_t l, std::vector<std::uint32_t>& ids) {
    const RegionGraph& graph = s.graph;
    std::vector<Node>& nodes = s.layout.nodes;
    const std::size_t perLayer = std::size_t(std::max(1, s.options.maxNodesPerLayer));
    const auto larger = [&](std::uint32_t a, std::uint32_t b) {
        return graph.regions[a].pixels != graph.regions[b].pixels
                   ? graph.regions[a].pixels > graph.regions[b].pixels
                   : a < b;
    };
    const std::size_t own = ids.size() <= perLayer ? ids.size() : perLayer - 1;
    // Only the largest need an order: a tiny threshold can make 100,000 regions.
    std::partial_sort(ids.begin(), ids.begin() + std::ptrdiff_t(own), ids.end(), larger);
    int shared = -1; // the layer's node for its small regions
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const Region& region = graph.regions[ids[i]];
        int index;
        if (i < own) {
            Node node;
            node.region = region.id;
            node.layer = l + 1;
            node.neighbors = s.graphValid ? std::uint32_t(graph.neighborsOf(region.id).size()) : 0u;
            index = addNode(s, l, node);
        } else {
            if (shared < 0) {
                Node node;
                node.layer = l + 1;
                node.members = 0;
                shared = addNode(s, l, node);
            }
            index = shared;
            ++nodes[std::size_t(index)].members;
            ++s.layout.mergedRegions;
        }
        s.nodeOf[region.id] = index;
        // Pixel-weighted sums, divided below.
        const double centre = 0.5 * (region.minY + region.maxY + 1) / s.pictureHeight;
        s.place[std::size_t(index)].home += centre * s.height * region.pixels;
        nodes[std::size_t(index)].pixels += region.pixels;
    }
}

/**
 * Each node's home height and radius. The heights the regions actually use are spread over the
 * height, keeping their order; a layer's merged small regions always sit at the bottom of its
 * column.
 */
void placeHomes(LayoutPass& s) {
    std::vector<Node>& nodes = s.layout.nodes;
    const double height = s.height;
    double maxPixels = 1.0;
    double lowest = height, highest = 0.0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        Placement& p = s.place[i];
        p.home = nodes[i].pixels > 0.0 ? p.home / nodes[i].pixels : height / 2.0;
        if (!nodes[i].merged()) {
            lowest = std::min(lowest, p.home);
            highest = std::max(highest, p.home);
        }
        maxPixels = std::max(maxPixels, nodes[i].pixels);
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        Placement& p = s.place[i];
        if (nodes[i].merged())
            p.home = 2.0 * height;
        else if (highest - lowest > 1.0)
            p.home = height * (0.1 + 0.8 * (p.home - lowest) / (highest - lowest));
        else
            p.home = height / 2.0;
        p.key = p.home;
        Node& node = nodes[i];
        node.radius = RegionGraphLayout::kMinRadius +
                      (RegionGraphLayout::kMaxRadius - RegionGraphLayout::kMinRadius) *
                          std::sqrt(node.pixels / maxPixels);
        if (node.merged())
            node.radius = std::max(node.radius, RegionGraphLayout::kMergedMinRadius);
    }
}

/** Edges by (a, b). */
void sortEdges(std::vector<RegionGraphLayout::Edge>& edges) {
    using Edge = RegionGraphLayout::Edge;
    std::sort(edges.begin(), edges.end(),
              [](const Edge& x, const Edge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
}

/** Edges between nodes, links summed over merged regions, and each node's weighted neighbours. */
void connectNodes(LayoutPass& s) {
    const RegionGraph& graph = s.graph;
    RegionGraphLayout& layout = s.layout;
    if (s.graphValid) {
        std::unordered_map<std::uint64_t, std::uint64_t> edgeLinks;
        for (const Region& region : graph.regions) {
            if (region.id >= s.regionCount || s.nodeOf[region.id] < 0)
                continue;
            for (const RegionLink& link : graph.neighborsOf(region.id)) {
                if (link.region <= region.id || link.region >= s.regionCount)
                    continue;
                const int a = s.nodeOf[region.id];
                const int b = s.nodeOf[link.region];
                if (b < 0 || a == b)
                    continue;
                const auto key =
                    (std::uint64_t(std::min(a, b)) << 32) | std::uint64_t(std::max(a, b));
                edgeLinks[key] += link.links;
            }
        }
        layout.edges.reserve(edgeLinks.size());
        for (const auto& [key, links] : edgeLinks)
            layout.edges.push_back({int(key >> 32), int(key & 0xffffffffu), links});
    }
    sortEdges(layout.edges);
    for (const RegionGraphLayout::Edge& edge : layout.edges) {
        const double weight = 1.0 + std::log10(double(std::max<std::uint64_t>(edge.links, 1)));
        s.place[std::size_t(edge.a)].adjacent.emplace_back(edge.b, weight);
        s.place[std::size_t(edge.b)].adjacent.emplace_back(edge.a, weight);
    }
}

/** Columns by layer; in a column by height in the view, pulled towards the neighbours. */
void arrangeColumns(LayoutPass& s) {
    std::vector<Node>& nodes = s.layout.nodes;
    std::vector<std::vector<int>>& columns = s.columns;
    for (std::vector<int>& column : columns)
        packColumn(nodes, s.place, column, s.height);
    for (int sweep = 0; sweep < kBarycentricSweeps; ++sweep) {
        for (std::size_t i = 0; i < columns.size(); ++i) {
            std::vector<int>& column = columns[sweep % 2 == 0 ? i : columns.size() - 1 - i];
            for (int index : column) {
                Placement& p = s.place[std::size_t(index)];
                if (nodes[std::size_t(index)].merged())
                    continue;
                double sum = 0.0, weights = 0.0;
                for (const auto& [other, weight] : p.adjacent) {
                    sum += nodes[std::size_t(other)].y * weight;
                    weights += weight;
                }
                p.key = weights > 0.0 ? 0.5 * p.home + 0.5 * sum / weights : p.home;
            }
            packColumn(nodes, s.place, column, s.height);
        }
    }
}

/** Nodes in drawing order: by layer, top to bottom; edges renumbered to match. */
void sortForDrawing(LayoutPass& s) {
    std::vector<Node>& nodes = s.layout.nodes;
    std::vector<int> order;
    order.reserve(nodes.size());
    for (const std::vector<int>& column : s.columns) {
        std::vector<int> sorted = column;
        std::sort(sorted.begin(), sorted.end(),
                  [&](int a, int b) { return nodes[std::size_t(a)].y < nodes[std::size_t(b)].y; });
        order.insert(order.end(), sorted.begin(), sorted.end());
    }
    std::vector<int> newIndex(nodes.size());
    std::vector<Node> ordered;
    ordered.reserve(nodes.size());
    for (const int index : order) {
        newIndex[std::size_t(index)] = int(ordered.size());
        ordered.push_back(nodes[std::size_t(index)]);
    }
    nodes = std::move(ordered);
    for (RegionGraphLayout::Edge& edge : s.layout.edges) {
        const int a = newIndex[std::size_t(edge.a)], b = newIndex[std::size_t(edge.b)];
        edge.a = std::min(a, b);
        edge.b = std::max(a, b);
    }
    sortEdges(s.layout.edges);
}

/** The layout's top and bottom: those of its nodes, if any. */
void measureExtent(RegionGraphLayout& layout) {
    if (layout.nodes.empty())
        return;
    layout.top = 1e300;
    layout.bottom = -1e300;
    for (const Node& node : layout.nodes) {
        layout.top = std::min(layout.top, node.y - node.radius);
        layout.bottom = std::max(layout.bottom, node.y + node.below());
    }
}

} // namespace

RegionGraphLayout layoutRegionGraph(const RegionGraph& graph, int imageHeight,
                                    const RegionGraphLayoutOptions& options) {
    RegionGraphLayout layout;
    LayoutPass s{graph, options, layout};
    s.height = options.height > 0.0 ? options.height : 320.0;
    s.pictureHeight = std::max(1, imageHeight);
    layout.bottom = s.height;
    s.regionCount = graph.regions.size();
    s.graphValid = graph.neighborOffsets.size() == s.regionCount + 1;

    filterRegions(s);
    // Nodes: per layer the largest regions, then one node for the rest.
    std::vector<std::vector<std::uint32_t>> byLayer = shownByLayer(s);
    s.nodeOf.assign(s.regionCount, -1);
    s.columns.resize(s.layerCount);
    for (std::uint32_t l = 0; l < s.layerCount; ++l)
        addLayerNodes(s, l, byLayer[l]);
    placeHomes(s);
    connectNodes(s);
    arrangeColumns(s);
    sortForDrawing(s);
    layout.layerCount = s.layerCount;
    measureExtent(layout);
    return layout;
}

} // namespace core
