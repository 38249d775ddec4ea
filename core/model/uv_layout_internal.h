// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to core: the steps of makeUvLayout (uv_layout.cpp) in their own files: growing and
// splitting charts (uv_charts.cpp), flattening one chart (uv_flatten.cpp) and packing the charts
// into pages (uv_pack.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/base/index.h"
#include "core/base/result.h"
#include "core/model/mesh_topology.h"
#include "core/model/uv_layout.h"

namespace core::uvl {

/** The welded surface the layout works on, in double precision. */
struct Surface {
    const MeshTopology* topology = nullptr;
    std::vector<glm::dvec3> position; // per welded vertex (its first copy's position)
    std::vector<glm::dvec3> normal;   // per triangle, unit length (zero when degenerate)
    std::vector<double> area;         // per triangle
    /** Triangles with less area than this have no reliable normal and are laid out alone. */
    double degenerateArea = 0.0;

    bool degenerate(std::uint32_t t) const { return !(area[t] > degenerateArea); }

    /**
     * Contacts: open sides (no single neighbour across them) lying along open sides of other
     * triangles over some length, the two triangles on either side of the line: a T-junction
     * where one face's corner sits on another's side, or two triangles that continue each other
     * across an edge of more than two triangles (a fin standing on a plate).
     * The contacts of side 3 t + e (corners e and e + 1 of triangle t) are the sides
     * contacts[contactBegin[3 t + e] .. contactBegin[3 t + e + 1]), each as 3 u + f.
     */
    std::vector<std::uint32_t> contactBegin;
    std::vector<std::uint32_t> contacts;

    /** The contacts of side 3 t + e. */
    std::span<const std::uint32_t> contactsOf(std::uint32_t side) const {
        return {contacts.data() + contactBegin[side], contacts.data() + contactBegin[side + 1]};
    }

    std::uint32_t cornerOfSide(std::uint32_t side, int k) const {
        return topology->corners[side / 3][(side % 3 + std::uint32_t(k)) % 3];
    }
};

/**
 * The pairs (i, j), i < j, of items that share a cell, each once and in ascending order, from
 * (cell, item) entries (sorted here); items are in ascending order within a cell once sorted.
 */
template <typename Cell>
std::vector<std::pair<std::uint32_t, std::uint32_t>>
pairsSharingACell(std::vector<std::pair<Cell, std::uint32_t>>& entries) {
    std::sort(entries.begin(), entries.end());
    entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t begin = 0; begin < entries.size();) {
        std::size_t end = begin + 1;
        while (end < entries.size() && entries[end].first == entries[begin].first)
            ++end;
        for (std::size_t i = begin; i < end; ++i)
            for (std::size_t j = i + 1; j < end; ++j)
                pairs.emplace_back(entries[i].second, entries[j].second);
        begin = end;
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

/**
 * Finds the surface's contacts (see Surface::contacts): sides within tolerance (model units) of
 * one line, overlapping by more than it. Needs position, normal and area.
 */
void findContacts(Surface& surface, double tolerance);

/** Charts as lists of triangles (ascending), grown from seeds in triangle order. */
std::vector<std::vector<std::uint32_t>> growCharts(const Surface& surface,
                                                   const UvLayoutOptions& options);

/**
 * Splits a chart of at least two triangles into two parts (connected across edges and contacts)
 * grown at once from two far-apart triangles (ascending lists).
 */
std::array<std::vector<std::uint32_t>, 2> splitChart(const Surface& surface,
                                                     const std::vector<std::uint32_t>& triangles);

/** A chart and its flattening. */
struct Chart {
    std::vector<std::uint32_t> triangles;            // ascending
    std::vector<std::uint32_t> vertices;             // welded ids of its local vertices
    std::vector<std::array<std::uint32_t, 3>> local; // per triangle: local vertex indices
    std::vector<glm::dvec2> uv; // per local vertex, in model units (UV area = 3D area)
    double area = 0.0;          // 3D area
};

enum class FlattenOutcome { Good, Flipped, Overlapping, Stretched, Crooked };

/**
 * Flattens chart (triangles set) with least-squares conformal maps, or by projection when it is
 * planar, scales it so its UV area is its 3D area and turns it so its smallest box is
 * axis-aligned. Good, or why it has to be split; overlaps are looked for at half a texel of the
 * expected density (texels per model unit), and a chart of many texels at that density that
 * fills too little of its box is Crooked.
 */
FlattenOutcome flattenChart(const Surface& surface, Chart& chart, double maxStretch,
                            double density);

/** Where packCharts() put a chart. */
struct Placement {
    std::uint32_t page = 0;
    int rotation = 0;          // quarter turns
    int x = 0, y = 0;          // texel offset of the chart's (rotated) mask on its page
    glm::dvec2 origin{0.0};    // subtracted from uv × density before the rotation
    int width = 0, height = 0; // the unrotated mask's size
};

struct Packing {
    std::vector<Placement> placements; // per chart
    std::uint32_t pageCount = 0;
};

/**
 * Packs charts at density texels per model unit into pages of options.resolution, at most
 * maxPages of them; nothing (an empty optional placement list) when they do not fit. Cancels
 * when cancel becomes true.
 */
Result<Packing> packCharts(const std::vector<Chart>& charts, double density,
                           const UvLayoutOptions& options, std::uint32_t maxPages,
                           const std::atomic<bool>& cancel);

/**
 * How far small charts are grown (the other charts: half the padding, rounded up); two small
 * charts keep twice this between them, at most the padding.
 */
int smallChartRadius(int padding);

/** The texel position of a chart's uv after placement (rotation and offset applied). */
glm::dvec2 placeUv(const Placement& placement, const glm::dvec2& uv, double density);

} // namespace core::uvl
