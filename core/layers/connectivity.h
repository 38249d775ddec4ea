// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/layers/layer_stack.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"

namespace core {

/** How two fragments at neighbouring pixels are judged to lie on one continuous surface. */
enum class ConnectionTest : std::uint8_t {
    /** The paper's test: |depth difference| < threshold. Breaks surfaces steeper than a pixel. */
    Plain,
    /** Predicts both depths from the fragments' triangle planes (see computeConnectivity()). */
    Surface,
};

struct ConnectivityOptions {
    ConnectionTest test = ConnectionTest::Surface;
    /** Depth tolerance in unit-cube units (the paper's default is 0.001). */
    float threshold = 0.001f;
    /** Model (view) units to unit-cube units: 1 / mesh.bounds().longestSide(); see unitScale(). */
    float unitScale = 1.0f;
    /**
     * Surface: triangles sharing a corner whose normals differ by at most this angle connect
     * whenever the crease through it passes between the two pixel centres, at any slope.
     */
    float creaseAngleDegrees = 100.0f;
    /**
     * Surface: other triangles of one mesh component whose normals differ by at most this angle
     * connect where the two samples lie on a common arc (a curved surface sampled coarsely,
     * near silhouettes or with triangles smaller than pixels); see computeConnectivity().
     */
    float smoothAngleDegrees = 60.0f;
    /**
     * Surface: fragments of different mesh components (see MeshTopology) connect only when the
     * predicted depths agree within threshold × contactFactor, i.e. where the parts touch.
     */
    float contactFactor = 0.1f;
    /** Worker threads; 0 = std::thread::hardware_concurrency(). Results do not depend on it. */
    unsigned threads = 0;
    /**
     * Surface: two neighbouring pixels with 16 fragment pairs or more have all their plane
     * depths computed at once and most pairs decided four at a time, only the rest one by one.
     * Results do not depend on it (false: every pair one by one, as tests compare).
     */
    bool batchDeepPixels = true;
};

/** The mesh's unit-cube scale, 1 / bounds().longestSide(); 1 for an empty or flat-point mesh. */
float unitScale(const Mesh& mesh);

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
                                    const View& view, const LayerStack* stack = nullptr);

/** Link directions, in the order links are stored: right, left, up (y - 1), down (y + 1). */
enum Direction : int { kRight = 0, kLeft = 1, kUp = 2, kDown = 3 };

/** Layers deeper than this cannot be stored in a link byte: they are left unconnected. */
inline constexpr std::uint32_t kMaxLinkedLayers = 255;

/** Pixel-level connectivity (docs/architecture.md §3 step 2) of a LayerStack. */
struct Connectivity {
    int width = 0;
    int height = 0;
    /**
     * 4 bytes per fragment in Direction order: the 1-based layer of the neighbour pixel's
     * fragment it connects to, 0 for none (the CLI's conn_L.png RGBA).
     */
    std::vector<std::uint8_t> links;
    /**
     * True when some pixel has more than kMaxLinkedLayers fragments: those deeper fragments have
     * no links and no fragment links to them.
     */
    bool truncated = false;

    std::uint8_t link(std::size_t fragment, int direction) const {
        return links[4 * fragment + std::size_t(direction)];
    }
};

/**
 * Links every fragment of stack to at most one fragment of each 4-neighbour pixel.
 *
 * Among the neighbour's fragments that pass the test, the best is chosen: the same triangle
 * first, then the smallest depth error, then the same layer, then the shallowest layer. The
 * test and its error are symmetric, but the choice is made per side, so link(p→q) = b does not
 * always imply link(q→p) = a (it does whenever a is b's best candidate too, as on any single
 * surface); segmentLayers() joins a pair linked in either direction.
 *
 * Surface test for fragments a, b of triangles A, B at pixel centres P, Q (M their midpoint),
 * all errors in unit-cube units:
 * - A = B: connected, error 0 (exact at any slope);
 * - A, B in different mesh components: connected iff the depths of planes A and B on the ray
 *   through M differ by less than threshold × contactFactor (the parts touch);
 * - A, B share a welded corner (MeshTopology), their normals are within creaseAngleDegrees
 *   and, along the rays from P to Q, the two planes' depths cross (their line of intersection,
 *   through the shared corner, lies between the pixel centres): connected, error 0 (creases
 *   and hard edges stay joined at any slope; a fold's edge lies beside both samples, so a fold
 *   does not join);
 * - the planes' depths on the ray through M differ by less than threshold: connected;
 * - the planes cross between P and Q, the normals are within smoothAngleDegrees and each
 *   sample is within 1.5 × chord × sin(normal angle / 2) + threshold of the other's plane (the
 *   samples lie on one arc of a smooth surface): connected (curved meshes near silhouettes);
 * - A, B share a corner, their normals are within 30° and each sample is within
 *   2.5 × chord × sin(normal angle / 2) + threshold of the other's plane: connected (the
 *   facets of a coarse curved mesh; a fold that flat would be off by 4× or more);
 * - a ray within ~0.6° of a plane (grazing), a degenerate or unknown triangle: plain test,
 *   and for a grazing plane of the same part also the arc condition without the crossing.
 * The tests never join surfaces further apart than threshold except along their own mesh
 * part's continuation; what they cannot tell apart is two parts closer than
 * threshold × contactFactor, or one part's sheets closer than threshold (both look touching).
 * Without geometry (nullptr) the Surface test falls back to the Plain test.
 */
Connectivity computeConnectivity(const LayerStack& stack, const ConnectivityOptions& options,
                                 const SurfaceGeometry* geometry = nullptr);

/** How well connectivity follows the mesh (for the README and regression tests). */
struct ConnectivityQuality {
    /** Neighbouring-pixel fragment pairs on the same triangle (any layers). */
    std::uint64_t sameTrianglePairs = 0;
    /** ... of which not linked in both directions (target 0). */
    std::uint64_t sameTriangleDisconnected = 0;
    /** Neighbouring-pixel fragment pairs on different triangles sharing a welded corner. */
    std::uint64_t adjacentTrianglePairs = 0;
    /** ... of which linked in neither direction (lower is better; silhouettes break some). */
    std::uint64_t adjacentTriangleDisconnected = 0;
    /** Fragment pairs linked in at least one direction. */
    std::uint64_t connectedPairs = 0;
    /** ... of which on triangles of different mesh components (target 0 but true contact). */
    std::uint64_t crossComponentConnected = 0;

    double sameTriangleDisconnectedShare() const {
        return sameTrianglePairs ? double(sameTriangleDisconnected) / double(sameTrianglePairs)
                                 : 0.0;
    }
    double adjacentTriangleDisconnectedShare() const {
        return adjacentTrianglePairs
                   ? double(adjacentTriangleDisconnected) / double(adjacentTrianglePairs)
                   : 0.0;
    }
    double crossComponentShare() const {
        return connectedPairs ? double(crossComponentConnected) / double(connectedPairs) : 0.0;
    }
};

/**
 * Counts the pairs of ConnectivityQuality over every pair of fragments at 4-neighbouring
 * pixels. Fragments whose triangle id is outside topology are skipped; mismatched sizes give
 * all zeros.
 */
ConnectivityQuality measureConnectivity(const LayerStack& stack, const Connectivity& connectivity,
                                        const MeshTopology& topology);

} // namespace core
