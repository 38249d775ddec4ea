// SPDX-License-Identifier: GPL-3.0-or-later
// How a mesh's texture coordinates cover UV space: whether they cover any area at all (UVs that
// put every triangle on a point or a line paint nothing), and how much of what they cover is
// covered more than once (a stroke paints every overlapping place at once).
#pragma once

#include <cstddef>

#include "core/model/mesh.h"

namespace core {

struct UvCoverage {
    /** The triangles' summed area in UV space (the unit square is 1; overlaps count twice). */
    double area = 0.0;
    /** Triangles without area in UV space (a point or a line). */
    std::size_t degenerate = 0;
    std::size_t triangles = 0;
    /**
     * Of the cells of a kUvCoverageGrid² grid over the (repeating) unit square whose centre a
     * triangle covers, the fraction covered by two triangles or more; 0 without such cells. One
     * grid per base colour texture (and one for materials without): triangles of materials that
     * paint different textures never overlap.
     */
    double overlap = 0.0;
};

inline constexpr int kUvCoverageGrid = 256;

/**
 * UvCoverage of mesh's UVs (all zero for a mesh without UVs). Visits at most a few dozen cells
 * per grid cell in all; beyond that the overlap is measured on the triangles visited so far.
 */
UvCoverage measureUvCoverage(const Mesh& mesh);

/**
 * Whether UVs cover no area: every triangle degenerate in UV space, or all of them together less
 * than one texel of the largest texture painted (16384²). True for a mesh without UVs.
 */
bool coversNoArea(const UvCoverage& coverage);

/** Whether UVs mostly overlap: more than half the area they cover is covered twice or more. */
inline bool mostlyOverlaps(const UvCoverage& coverage) {
    return coverage.overlap > 0.5;
}

} // namespace core
