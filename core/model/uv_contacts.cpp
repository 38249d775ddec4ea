// SPDX-License-Identifier: GPL-3.0-or-later
// Contacts of the automatic UV layout's surface: open sides of triangles that lie along open
// sides of others. CAD exports join faces at T-junctions (a corner of one face on a side of the
// next) where no edge is shared; charts grow across them as across shared edges.
#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/model/uv_layout_internal.h"

namespace core::uvl {

namespace {

/**
 * True when side b lies along side a (its ends within tol of a's line, overlapping a by more than
 * tol) with the two triangles on either side of that line.
 */
bool alongEachOther(const Surface& s, std::uint32_t a, std::uint32_t b, double tol) {
    const std::uint32_t a0 = s.cornerOfSide(a, 0), a1 = s.cornerOfSide(a, 1);
    const std::uint32_t b0 = s.cornerOfSide(b, 0), b1 = s.cornerOfSide(b, 1);
    const glm::dvec3 p = s.position[a0];
    const glm::dvec3 d = s.position[a1] - p;
    const double length = glm::length(d);
    if (!(length > tol))
        return false;
    const glm::dvec3 dir = d / length;
    double along[2];
    const std::uint32_t ends[2] = {b0, b1};
    for (int k = 0; k < 2; ++k) {
        const glm::dvec3 q = s.position[ends[k]] - p;
        along[k] = glm::dot(q, dir);
        if (glm::length(q - dir * along[k]) > tol)
            return false;
    }
    const double overlap = std::min(length, std::max(along[0], along[1])) -
                           std::max(0.0, std::min(along[0], along[1]));
    if (!(overlap > tol))
        return false;
    // The two triangles lie on either side of the line, not on top of each other.
    const glm::dvec3 across = glm::cross(s.normal[a / 3], dir);
    const double sideA = glm::dot(s.position[s.cornerOfSide(a, 2)] - p, across);
    const double sideB = glm::dot(s.position[s.cornerOfSide(b, 2)] - p, across);
    return (sideA > 0.0) != (sideB > 0.0) && sideA != 0.0 && sideB != 0.0;
}

} // namespace

void findContacts(Surface& s, double tolerance) {
    const MeshTopology& topo = *s.topology;
    const std::size_t n = topo.triangleCount();
    s.contactBegin.assign(3 * n + 1, 0u);
    s.contacts.clear();
    std::vector<std::uint32_t> open;
    for (std::uint32_t t = 0; t < n; ++t)
        if (!s.degenerate(t))
            for (std::uint32_t e = 0; e < 3; ++e)
                if (topo.edgeNeighbors[t][e] == kNone)
                    open.push_back(3 * t + e);
    if (open.size() < 2)
        return;

    // A grid of cells about as long as the median open side; each side goes into the cells of
    // points along it half a cell apart, so sides along one line meet in some cell.
    glm::dvec3 lo(1e300), hi(-1e300);
    std::vector<double> lengths(open.size());
    for (std::size_t i = 0; i < open.size(); ++i) {
        const glm::dvec3 a = s.position[s.cornerOfSide(open[i], 0)];
        const glm::dvec3 b = s.position[s.cornerOfSide(open[i], 1)];
        lo = glm::min(lo, glm::min(a, b));
        hi = glm::max(hi, glm::max(a, b));
        lengths[i] = glm::length(b - a);
    }
    std::vector<double> sorted = lengths;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2),
                     sorted.end());
    const glm::dvec3 extent = hi - lo;
    constexpr int kCellBits = 20;
    const double cell = std::max({sorted[sorted.size() / 2], tolerance,
                                  std::max({extent.x, extent.y, extent.z}) / (1 << kCellBits)});
    if (!(cell > 0.0) || !std::isfinite(cell))
        return;
    const auto key = [&](const glm::dvec3& p) {
        std::uint64_t k = 0;
        for (int a = 0; a < 3; ++a) {
            const double c = std::floor((p[a] - lo[a]) / cell);
            k = (k << 21) | std::uint64_t(std::clamp(c, 0.0, double((1 << 21) - 1)));
        }
        return k;
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> cells;
    cells.reserve(open.size() * 3);
    for (std::uint32_t i = 0; i < open.size(); ++i) {
        const glm::dvec3 a = s.position[s.cornerOfSide(open[i], 0)];
        const glm::dvec3 b = s.position[s.cornerOfSide(open[i], 1)];
        const int steps = int(std::min(std::ceil(2.0 * lengths[i] / cell), 65536.0));
        for (int k = 0; k <= steps; ++k) {
            const std::pair<std::uint64_t, std::uint32_t> entry{
                key(a + (b - a) * (steps > 0 ? double(k) / steps : 0.0)), i};
            if (cells.empty() || cells.back() != entry)
                cells.push_back(entry);
        }
    }
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs = pairsSharingACell(cells);

    std::vector<std::pair<std::uint32_t, std::uint32_t>> found; // both ways, as sides
    for (const auto& [i, j] : pairs) {
        const std::uint32_t a = open[i], b = open[j];
        // The shorter side's ends against the longer side's line: a long side's far end can
        // stray from a short side's line by more than the tolerance.
        const bool aLonger = lengths[i] >= lengths[j];
        if (a / 3 != b / 3 && alongEachOther(s, aLonger ? a : b, aLonger ? b : a, tolerance)) {
            found.emplace_back(a, b);
            found.emplace_back(b, a);
        }
    }
    std::sort(found.begin(), found.end());
    s.contacts.reserve(found.size());
    for (const auto& [side, other] : found) {
        ++s.contactBegin[side + 1];
        s.contacts.push_back(other);
    }
    for (std::size_t i = 1; i < s.contactBegin.size(); ++i)
        s.contactBegin[i] += s.contactBegin[i - 1];
}

} // namespace core::uvl
