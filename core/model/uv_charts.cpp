// SPDX-License-Identifier: GPL-3.0-or-later
// Charts for the automatic UV layout: grown over the welded surface by normal deviation, across
// shared edges and contacts (T-junctions, and edges of more than two triangles where two
// continue each other) but never across sharp edges, and kept discs while they grow.
#include <algorithm>
#include <cmath>
#include <queue>
#include <utility>

#include <glm/geometric.hpp>

#include "core/model/uv_layout_internal.h"

namespace core::uvl {

namespace {

struct Candidate {
    double cost;
    std::uint32_t triangle;
    // A strict order, so the growth does not depend on the heap's implementation.
    bool operator>(const Candidate& o) const {
        return cost > o.cost || (cost == o.cost && triangle > o.triangle);
    }
};

} // namespace

std::vector<std::vector<std::uint32_t>> growCharts(const Surface& surface,
                                                   const UvLayoutOptions& options) {
    const MeshTopology& topo = *surface.topology;
    const std::uint32_t n = std::uint32_t(topo.triangleCount());
    const double cosCone = std::cos(double(options.maxNormalDeviationDegrees) * M_PI / 180.0);
    const double cosSharp = std::cos(double(options.sharpEdgeDegrees) * M_PI / 180.0);

    std::vector<std::uint32_t> chartOf(n, kNone);
    // vertexStamp[v] == chart + 1 while chart grows: v is one of its vertices.
    std::vector<std::uint32_t> vertexStamp(topo.weldedVertexCount, 0u);
    std::vector<std::vector<std::uint32_t>> charts;
    std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> heap;

    const auto smooth = [&](std::uint32_t t, std::uint32_t u) {
        return !surface.degenerate(u) && glm::dot(surface.normal[t], surface.normal[u]) >= cosSharp;
    };
    const auto joinsSmoothly = [&](std::uint32_t t, int edge) {
        const std::uint32_t u = topo.edgeNeighbors[t][std::size_t(edge)];
        return u != kNone && smooth(t, u);
    };

    for (std::uint32_t seed = 0; seed < n; ++seed) {
        if (chartOf[seed] != kNone)
            continue;
        const std::uint32_t chart = std::uint32_t(charts.size());
        charts.emplace_back();
        std::vector<std::uint32_t>& members = charts.back();
        const auto add = [&](std::uint32_t t) {
            chartOf[t] = chart;
            members.push_back(t);
            for (std::uint32_t v : topo.corners[t])
                vertexStamp[v] = chart + 1;
        };
        heap = {}; // what the last chart left behind is not next to this one
        add(seed);
        if (surface.degenerate(seed))
            continue; // alone: it has no normal to grow by
        glm::dvec3 normalSum = surface.normal[seed] * surface.area[seed];
        const auto pushNeighbours = [&](std::uint32_t t) {
            const glm::dvec3 mean = glm::normalize(normalSum);
            const auto push = [&](std::uint32_t u) {
                if (chartOf[u] == kNone)
                    heap.push({1.0 - glm::dot(surface.normal[u], mean), u});
            };
            for (int e = 0; e < 3; ++e) {
                if (joinsSmoothly(t, e))
                    push(topo.edgeNeighbors[t][std::size_t(e)]);
                // Across contacts (T-junctions) as across shared edges.
                for (const std::uint32_t other : surface.contactsOf(3 * t + std::uint32_t(e)))
                    if (smooth(t, other / 3))
                        push(other / 3);
            }
        };
        pushNeighbours(seed);
        while (!heap.empty()) {
            const std::uint32_t t = heap.top().triangle;
            heap.pop();
            if (chartOf[t] != kNone)
                continue;
            if (glm::dot(surface.normal[t], glm::normalize(normalSum)) < cosCone)
                continue; // may come back when another neighbour joins
            // Disc test: a triangle joining along one edge must bring a new vertex, else the
            // chart would close around a hole or touch itself at a vertex.
            int shared = 0;
            int sharedEdge = -1;
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t u = topo.edgeNeighbors[t][std::size_t(e)];
                if (u != kNone && chartOf[u] == chart && joinsSmoothly(t, e)) {
                    ++shared;
                    sharedEdge = e;
                }
            }
            if (shared == 1) {
                const int corner = (sharedEdge + 2) % 3;
                const std::uint32_t opposite = topo.corners[t][std::size_t(corner)];
                // Unless a side through that vertex lies along the chart (a contact): then the
                // triangle fills the corner between the two.
                const auto alongChart = [&](int e) {
                    for (const std::uint32_t other : surface.contactsOf(3 * t + std::uint32_t(e)))
                        if (chartOf[other / 3] == chart && smooth(t, other / 3))
                            return true;
                    return false;
                };
                if (vertexStamp[opposite] == chart + 1 && !alongChart(corner) &&
                    !alongChart((corner + 2) % 3))
                    continue;
            }
            add(t);
            normalSum += surface.normal[t] * surface.area[t];
            pushNeighbours(t);
        }
        std::sort(members.begin(), members.end());
    }
    return charts;
}

std::array<std::vector<std::uint32_t>, 2> splitChart(const Surface& surface,
                                                     const std::vector<std::uint32_t>& triangles) {
    const MeshTopology& topo = *surface.topology;
    const std::size_t m = triangles.size();
    // Local adjacency inside the chart.
    const auto localIndex = [&](std::uint32_t t) -> std::uint32_t {
        const auto it = std::lower_bound(triangles.begin(), triangles.end(), t);
        return it != triangles.end() && *it == t ? std::uint32_t(it - triangles.begin()) : kNone;
    };
    // Neighbours across edges and contacts, in one list per triangle.
    std::vector<std::uint32_t> adjacentBegin(m + 1, 0u), adjacent;
    for (std::size_t i = 0; i < m; ++i) {
        const std::uint32_t t = triangles[i];
        const auto add = [&](std::uint32_t u) {
            if (const std::uint32_t j = localIndex(u); j != kNone)
                adjacent.push_back(j);
        };
        for (int e = 0; e < 3; ++e) {
            if (const std::uint32_t u = topo.edgeNeighbors[t][std::size_t(e)]; u != kNone)
                add(u);
            for (const std::uint32_t other : surface.contactsOf(3 * t + std::uint32_t(e)))
                add(other / 3);
        }
        adjacentBegin[i + 1] = std::uint32_t(adjacent.size());
    }
    std::vector<std::uint32_t> label(m, kNone);
    std::vector<std::uint32_t> queue;
    queue.reserve(m);
    // Breadth-first from the given sources; returns the last triangle reached.
    const auto sweep = [&](std::initializer_list<std::uint32_t> sources) {
        std::fill(label.begin(), label.end(), kNone);
        queue.clear();
        std::uint32_t k = 0;
        for (std::uint32_t s : sources) {
            if (label[s] == kNone) {
                label[s] = k;
                queue.push_back(s);
            }
            ++k;
        }
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const std::uint32_t i = queue[head];
            for (std::uint32_t x = adjacentBegin[i]; x < adjacentBegin[i + 1]; ++x)
                if (const std::uint32_t j = adjacent[x]; label[j] == kNone) {
                    label[j] = label[i];
                    queue.push_back(j);
                }
        }
        return queue.back();
    };
    const std::uint32_t a = sweep({0u});
    const std::uint32_t b = sweep({a});
    sweep({a, b});
    std::array<std::vector<std::uint32_t>, 2> parts;
    for (std::size_t i = 0; i < m; ++i) {
        // Triangles the sweep did not reach (not connected) go with the first part's seed
        // only if they touch it; otherwise they are a part of their own in a later split.
        const std::uint32_t l = label[i] == kNone ? 1u : label[i];
        parts[l].push_back(triangles[i]);
    }
    if (parts[1].empty()) { // a == b: nothing to split by distance, halve the list
        parts[1].assign(parts[0].begin() + std::ptrdiff_t(m / 2), parts[0].end());
        parts[0].resize(m / 2);
    }
    return parts;
}

} // namespace core::uvl
