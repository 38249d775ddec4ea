// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/model/mesh.h"

namespace core {

/**
 * A simplified copy of a mesh's triangles for drawing while the camera moves. Its triangles use
 * a subset of the source mesh's vertices (indices address the source's vertex arrays), so every
 * vertex attribute, the paint on UVs or vertex colours included, is the source's.
 */
struct StandIn {
    std::vector<std::uint32_t> indices;          // three per triangle, into the source's vertices
    std::vector<std::uint32_t> triangleMaterial; // one per triangle, index into the materials

    std::size_t triangleCount() const { return indices.size() / 3; }
    bool empty() const { return indices.empty(); }
};

/**
 * Simplifies mesh to at most targetTriangles triangles (meshoptimizer's edge-collapse
 * simplifier, which keeps attribute seams; where that cannot get down far enough, the grid
 * clustering one). Each material is simplified on its own, with a share of the target by its
 * triangle count; a material whose share is under one triangle is left out. Deterministic. An
 * empty stand-in when the mesh has no more than targetTriangles triangles. progress returning
 * false cancels (a cancelled error).
 */
Result<StandIn> simplifyForDisplay(const Mesh& mesh, std::size_t targetTriangles,
                                   const ProgressFn& progress = {});

/**
 * The stand-in made from source, for drawn: a mesh with the same triangles in the same order
 * whose vertices may be split further (a paint target's automatic UV layout). Each stand-in
 * vertex becomes the drawn vertex at one corner where the source used it, and each triangle
 * takes the drawn material of its source material. Empty when the triangle counts differ.
 */
StandIn standInFor(const StandIn& standIn, const Mesh& source, const Mesh& drawn);

} // namespace core
