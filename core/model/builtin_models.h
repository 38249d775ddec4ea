// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>
#include <vector>

#include "core/base/result.h"
#include "core/model/mesh.h"

namespace core {

struct BuiltinModel {
    std::string name;        // used as "builtin:NAME"
    std::string description; // English; the GUI translates its own labels
};

/** The procedural models: trefoil (the default), hexring, row, knot. */
const std::vector<BuiltinModel>& builtinModels();

/**
 * Builds "NAME" (without the "builtin:" prefix), "knot?triangles=N" with its size; an Error
 * (naming the model) for an unknown name or parameter, or N not a number or out of range.
 */
Result<Mesh> makeBuiltinModel(const std::string& name);

/**
 * The trefoil-knot tube, UV-mapped as three strips (one per lobe) so texels are near square.
 * The defaults (3 × 399 segments along, 119 around) give the paper's 144,000 vertices.
 */
Mesh makeTrefoil(int segmentsPerStrip = 399, int radialSegments = 119);
/** The trefoil tube's centre line at t in [0, 2π) (model units); the tube's radius is 0.45. */
glm::vec3 trefoilCurve(float t);
/** The segment along the tube (0 .. 3 × segmentsPerStrip − 1) that triangle t of makeTrefoil is in.
 */
int trefoilSegmentOfTriangle(std::size_t triangle, int radialSegments = 119);

inline constexpr std::size_t kKnotMinTriangles = 1000;
inline constexpr std::size_t kKnotMaxTriangles = 50'000'000;
inline constexpr std::size_t kKnotDefaultTriangles = 1'000'000;
/**
 * A (2, 5) torus-knot tube UV-mapped as the trefoil (five strips), its segments chosen so it has
 * close to `triangles` triangles (at least kKnotMinTriangles).
 */
Mesh makeKnot(std::size_t triangles);

/** A thick hexagonal ring: outer and inner walls and two caps ("Donuthexa"). */
Mesh makeHexRing(int subdivisions = 48);
/** Four identical bodies in a row along -Z, one behind the other, each on its own UV tile. */
Mesh makeRow(int subdivisions = 64);

inline constexpr const char* kBuiltinPrefix = "builtin:";
inline constexpr const char* kDefaultModel = "builtin:trefoil";

} // namespace core
