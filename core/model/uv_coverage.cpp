// SPDX-License-Identifier: GPL-3.0-or-later
// measureUvCoverage(): the UV triangles' area, and their overlap counted on a grid of cell
// centres per texture page (each triangle moved to the unit square its lowest corner is in, the
// grid repeating as a texture does), a shared edge's centres counted for one of its two
// triangles only. Materials painting different textures do not overlap.
#include "core/model/uv_coverage.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include <glm/vec2.hpp>

namespace core {

namespace {

constexpr int kGrid = kUvCoverageGrid;
/** Cell visits in all, as a multiple of the grid's cells. */
constexpr std::uint64_t kMaxVisitsPerCell = 256;

struct UvTriangle {
    glm::dvec2 p[3]; // in grid cells, counter-clockwise
};

/** Whether q is inside the edge p0 → p1 of a counter-clockwise triangle; on it for one side. */
bool inside(const glm::dvec2& p0, const glm::dvec2& p1, const glm::dvec2& q) {
    const glm::dvec2 d = p1 - p0;
    const double e = d.x * (q.y - p0.y) - d.y * (q.x - p0.x);
    return e > 0.0 || (e == 0.0 && (d.y > 0.0 || (d.y == 0.0 && d.x < 0.0)));
}

/** Adds the cells whose centre the triangle covers to counts (saturating at 2). */
std::uint64_t countCells(const UvTriangle& tri, std::vector<std::uint8_t>& counts) {
    const auto [minX, maxX] = std::minmax({tri.p[0].x, tri.p[1].x, tri.p[2].x});
    const auto [minY, maxY] = std::minmax({tri.p[0].y, tri.p[1].y, tri.p[2].y});
    // Cells whose centre (i + 0.5, j + 0.5) is within the bounding box, one repeat at most.
    const double x0 = std::ceil(minX - 0.5), y0 = std::ceil(minY - 0.5);
    const double x1 = std::min(std::floor(maxX - 0.5), x0 + kGrid - 1);
    const double y1 = std::min(std::floor(maxY - 0.5), y0 + kGrid - 1);
    std::uint64_t visits = 0;
    for (double y = y0; y <= y1; ++y)
        for (double x = x0; x <= x1; ++x, ++visits) {
            const glm::dvec2 q(x + 0.5, y + 0.5);
            if (!inside(tri.p[0], tri.p[1], q) || !inside(tri.p[1], tri.p[2], q) ||
                !inside(tri.p[2], tri.p[0], q))
                continue;
            const auto cx = static_cast<std::size_t>(int(x) % kGrid);
            const auto cy = static_cast<std::size_t>(int(y) % kGrid);
            std::uint8_t& c = counts[cy * kGrid + cx];
            c = std::uint8_t(std::min(2, c + 1));
        }
    return visits;
}

/**
 * The grid a triangle's material paints into: one per base colour texture (materials sharing a
 * texture share a page), one for the materials without; past kMaxGrids textures the last one.
 */
std::vector<std::uint8_t>& gridOf(const Mesh& mesh, std::size_t triangle,
                                  std::map<int, std::vector<std::uint8_t>>& grids) {
    constexpr std::size_t kMaxGrids = 64;
    const std::size_t m =
        triangle < mesh.triangleMaterial.size() ? mesh.triangleMaterial[triangle] : SIZE_MAX;
    int texture = m < mesh.materials.size() ? mesh.materials[m].baseColorTexture : -1;
    if (!grids.contains(texture) && grids.size() >= kMaxGrids)
        texture = grids.rbegin()->first;
    std::vector<std::uint8_t>& counts = grids[texture];
    counts.resize(std::size_t(kGrid) * kGrid, 0);
    return counts;
}

} // namespace

UvCoverage measureUvCoverage(const Mesh& mesh) {
    UvCoverage coverage;
    if (!mesh.hasUvs())
        return coverage;
    std::map<int, std::vector<std::uint8_t>> grids;
    std::uint64_t visits = 0;
    const std::uint64_t maxVisits = kMaxVisitsPerCell * std::uint64_t(kGrid) * kGrid;
    coverage.triangles = mesh.triangleCount();
    for (std::size_t t = 0; t < coverage.triangles; ++t) {
        glm::dvec2 uv[3];
        for (int k = 0; k < 3; ++k)
            uv[k] = glm::dvec2(mesh.uvs[mesh.indices[3 * t + std::size_t(k)]]);
        const double cross =
            (uv[1].x - uv[0].x) * (uv[2].y - uv[0].y) - (uv[1].y - uv[0].y) * (uv[2].x - uv[0].x);
        if (!(std::abs(cross) > 0.0) || !std::isfinite(cross)) {
            ++coverage.degenerate;
            continue;
        }
        coverage.area += 0.5 * std::abs(cross);
        if (visits >= maxVisits)
            continue;
        if (cross < 0.0)
            std::swap(uv[1], uv[2]);
        const glm::dvec2 shift(std::floor(std::min({uv[0].x, uv[1].x, uv[2].x})),
                               std::floor(std::min({uv[0].y, uv[1].y, uv[2].y})));
        UvTriangle tri;
        for (int k = 0; k < 3; ++k)
            tri.p[k] = (uv[k] - shift) * double(kGrid);
        visits += countCells(tri, gridOf(mesh, t, grids));
    }
    std::size_t covered = 0, twice = 0;
    for (const auto& [texture, counts] : grids) {
        covered +=
            std::size_t(std::count_if(counts.begin(), counts.end(), [](auto c) { return c > 0; }));
        twice += std::size_t(std::count(counts.begin(), counts.end(), std::uint8_t(2)));
    }
    coverage.overlap = covered > 0 ? double(twice) / double(covered) : 0.0;
    return coverage;
}

bool coversNoArea(const UvCoverage& coverage) {
    constexpr double kLargestTexel = 1.0 / (16384.0 * 16384.0);
    return coverage.degenerate == coverage.triangles || coverage.area < kLargestTexel;
}

} // namespace core
