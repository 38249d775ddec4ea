// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <vector>

#include "core/depth/depth_stack.h"
#include "core/depth/surface_geometry.h"
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
     * Surface: two neighbouring pixels with 16 fragment pairs or more (8 in eight lanes) have
     * all their plane depths computed at once and most pairs decided in groups of lanes (see
     * wideLanes), only the rest one by one. Results do not depend on it (false: every pair one by
     * one, as tests compare).
     */
    bool batchDeepPixels = true;
    /**
     * Groups of eight lanes (AVX2) where the processor has AVX2, else of four. Results do not
     * depend on it (false: four lanes everywhere, as tests compare).
     */
    bool wideLanes = true;
};

/** The mesh's unit-cube scale, 1 / bounds().longestSide(); 1 for an empty or flat-point mesh. */
float unitScale(const Mesh& mesh);

/** Link directions, in the order links are stored: right, left, up (y - 1), down (y + 1). */
enum Direction : int { kRight = 0, kLeft = 1, kUp = 2, kDown = 3 };

/** Depth layers deeper than this cannot be stored in a link byte: they are left unconnected. */
inline constexpr std::uint32_t kMaxLinkedLayers = 255;

/** Pixel-level connectivity (docs/architecture.md §3 step 2) of a DepthStack. */
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
 * surface); segmentDepthLayers() joins a pair linked in either direction.
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
Connectivity computeConnectivity(const DepthStack& stack, const ConnectivityOptions& options,
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
ConnectivityQuality measureConnectivity(const DepthStack& stack, const Connectivity& connectivity,
                                        const MeshTopology& topology);

} // namespace core
