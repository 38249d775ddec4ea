// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec4.hpp>

#include "core/base/progress.h"
#include "core/model/mesh.h"

namespace core {

/**
 * Connectivity of a Mesh after welding vertices by position, so seam and hard-edge duplicates
 * (same place, different normal or UV) join. Used by the Surface connection test (which
 * triangles share an edge, which belong to different parts, and the triangles' planes, which a
 * view only transforms) and by the quality measurements.
 */
struct MeshTopology {
    /** Per vertex: its welded vertex id, numbered in order of first occurrence. */
    std::vector<std::uint32_t> weldedVertex;
    std::uint32_t weldedVertexCount = 0;
    /** Per triangle: its three corners as welded vertex ids. */
    std::vector<std::array<std::uint32_t, 3>> corners;
    /**
     * Per triangle and edge e (corners e and e + 1 mod 3): the triangle across it, or kNone on a
     * boundary, degenerate or non-manifold (more than two triangles) edge.
     */
    std::vector<std::array<std::uint32_t, 3>> edgeNeighbors;
    /** Per triangle: its connected component (triangles joined through welded vertices). */
    std::vector<std::uint32_t> component;
    /** Components are numbered 0 .. componentCount - 1 in order of their first triangle. */
    std::uint32_t componentCount = 0;
    /** Per triangle: its plane in the mesh's own space (trianglePlane()). */
    std::vector<glm::vec4> planes;
    /**
     * Ascending: the triangles whose back faces are shown and captured although back faces are
     * culled, as glTF's doubleSided asks: those of double-sided materials in components that are
     * open (an edge without a triangle across). A closed component's back faces face its inside,
     * hidden from any view outside it, so capturing them would only add depth layers.
     */
    std::vector<std::uint32_t> shownBackFaces;

    std::size_t triangleCount() const { return corners.size(); }
    /** Whether triangle t is one of shownBackFaces. */
    bool showsBackFace(std::uint32_t t) const;
    /** How many welded corners triangles a and b have in common (0 to 3). */
    int sharedCorners(std::uint32_t a, std::uint32_t b) const;
};

/**
 * Triangle t's plane in the mesh's own space: unit normal by winding (xyz) and offset (w) with
 * dot(normal, p) + w = 0, the offset taken at the centroid (the least rounding error over the
 * triangle), computed in double. Zero if degenerate or an index is out of range.
 */
glm::vec4 trianglePlane(const Mesh& mesh, std::size_t t);

/**
 * Welds the mesh's vertices closer than weldTolerance × its bounding box's longest side (and
 * always those in one quantization cell of that size) and derives triangle corners, edge
 * neighbours, components and planes. Indices out of range are treated as their own isolated vertex
 * (run Mesh::validate() first); an empty mesh gives an empty topology.
 */
MeshTopology buildMeshTopology(const Mesh& mesh, float weldTolerance = 1e-5f);
/**
 * buildMeshTopology() reporting its progress between its steps: nullopt as soon as progress
 * returns false (cancelled).
 */
std::optional<MeshTopology> buildMeshTopology(const Mesh& mesh, const ProgressFn& progress,
                                              float weldTolerance = 1e-5f);

} // namespace core
