// SPDX-License-Identifier: GPL-3.0-or-later
// What the Surface connectivity test knows of a view: its pixel rays and the planes of the
// triangles it shows (see computeConnectivity() in connectivity.h).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/depth/depth_stack.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"

namespace core {

/**
 * The rays of a view's pixels in view space (eye at the origin, looking down -Z): the point at
 * positive view depth z seen at window position (px, py) (pixel centres at +0.5, y down) is
 * origin(px, py) + z * direction(px, py), with direction.z = -1 and origin.z = 0. Both are
 * affine in (px, py) for perspective and orthographic projections.
 */
struct PixelRays {
    glm::vec3 origin0{0.0f}, originDx{0.0f}, originDy{0.0f};
    glm::vec3 direction0{0.0f, 0.0f, -1.0f}, directionDx{0.0f}, directionDy{0.0f};

    glm::vec3 origin(float px, float py) const { return origin0 + px * originDx + py * originDy; }
    glm::vec3 direction(float px, float py) const {
        return direction0 + px * directionDx + py * directionDy;
    }
    /** The rays of a view; a singular projection gives the default (orthographic, unit) rays. */
    static PixelRays fromView(const View& view);
};

/** What the Surface test knows about one triangle, in the view's view space. */
struct SurfaceTriangle {
    /** Unit normal (xyz, by winding) and offset (w): dot(normal, p) + w = 0. Zero if degenerate. */
    glm::vec4 plane{0.0f};
    /** Welded vertex ids (MeshTopology::corners); kNone when unknown. */
    std::array<std::uint32_t, 3> corners{kNone, kNone, kNone};
    /** Mesh component (MeshTopology::component); kNone when unknown. */
    std::uint32_t component = kNone;
};

/**
 * Per-view input of the Surface test: pixel rays and per-triangle planes. Without entries, the
 * triangles are by triangle id; with entries (made from a stack), only the triangles in view are
 * kept, and a triangle id's entry is its index among them (kNone: not in view): entry[id] when
 * the view shows a good share of the mesh, else through entryTable, so that a build costs
 * nothing per triangle of a large mesh the view shows little of.
 */
struct SurfaceGeometry {
    PixelRays rays;
    std::vector<SurfaceTriangle> triangles;
    std::vector<std::uint32_t> entry;
    /** A triangle id and its entry; a free slot has id kNone. */
    struct EntrySlot {
        std::uint32_t id = kNone;
        std::uint32_t entry = kNone;
    };
    /** Open-addressed by id (linear probing), a power of two of slots. */
    std::vector<EntrySlot> entryTable;
    /**
     * With entries: each fragment's triangle entry (kNone when unknown), for the stack the
     * geometry was made from. The triangles are numbered in the order the fragments first show
     * them, so a pass over the pixels reads them nearly in order.
     */
    std::vector<std::uint32_t> fragmentEntry;

    /** Whether only the triangles in view are kept (and entries find them). */
    bool hasEntries() const { return !entry.empty() || !entryTable.empty(); }
    /** Triangle id's index in triangles: kNone when out of range or not in view. */
    std::uint32_t entryOf(std::uint32_t id) const;
    /** Triangle id's triangle, or nullptr when unknown (out of range or not in view). */
    const SurfaceTriangle* find(std::uint32_t id) const { return atEntry(entryOf(id)); }
    /** The triangle of an entry (as entry and fragmentEntry hold), or nullptr for kNone. */
    const SurfaceTriangle* atEntry(std::uint32_t index) const {
        return index != kNone ? &triangles[index] : nullptr;
    }
};

/**
 * Planes of mesh's triangles in view's view space, with topology's corners/components, indexed by
 * triangle id. With stack, only the triangles with a fragment in it are computed and kept (the
 * only ones the Surface test reads; SurfaceGeometry's entries and fragmentEntry find them): a mesh
 * of millions of triangles costs at most a word per triangle, not a plane.
 */
SurfaceGeometry makeSurfaceGeometry(const Mesh& mesh, const MeshTopology& topology,
                                    const View& view, const DepthStack* stack = nullptr);

} // namespace core
