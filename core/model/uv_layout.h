// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <vector>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/model/mesh.h"

namespace core {

struct UvLayoutOptions {
    /** Width and height of a texture page in texels (64 .. 16384). */
    int resolution = 2048;
    /** At least this many empty texels between two charts (half of it at a page's border). */
    int padding = 4;
    /**
     * Texels per model unit. 0: the largest density that packs every chart into one page;
     * otherwise the charts go on as many pages as they need at this density.
     */
    double texelsPerUnit = 0.0;
    /** A chart grows while its triangles' normals stay within this angle of its mean normal. */
    float maxNormalDeviationDegrees = 50.0f;
    /** Edges where the surface bends more than this always cut charts apart. */
    float sharpEdgeDegrees = 40.0f;
    /**
     * A flattened chart is split again when more than 5 % of its area is stretched more than
     * this (max(r, 1/r) of its triangles' UV to 3D area ratios, relative to the chart).
     */
    float maxChartStretch = 1.4f;
    /**
     * Charts filling at most this many texels keep only half the padding (rounded up to whole
     * texels on each side) between each other, and the full padding to larger charts and a
     * page's border. 0: every chart keeps the full padding.
     */
    int smallChartTexels = 64;
    /** Worker threads (0: one per core). The layout is the same for any count. */
    unsigned threads = 0;
};

/**
 * A mesh with generated texture coordinates. The triangles keep their order, material and
 * winding; vertices are re-indexed (in order of first use by the triangles) because a vertex on a
 * seam between charts needs one copy per chart. Unused vertices of the input are dropped.
 */
struct UvLayout {
    /** The input with uvs (per page: 0..1 across the page, v = 0 is the image's top row). */
    Mesh mesh;
    /** Per new vertex: the vertex of the input it copies. */
    std::vector<std::uint32_t> sourceVertex;
    /** Per triangle: its chart; charts are numbered in order of their first triangle. */
    std::vector<std::uint32_t> triangleChart;
    /** Per chart: the texture page it lies on (always 0 when packed into one page). */
    std::vector<std::uint32_t> chartPage;
    std::uint32_t chartCount = 0;
    std::uint32_t pageCount = 0;
    int resolution = 0;
    int padding = 0;
    /**
     * Two charts that each cover (texel centres inside their triangles) at most
     * smallChartTexels texels keep at least smallChartPadding texels between them; any other two
     * at least padding.
     */
    int smallChartTexels = 0;
    int smallChartPadding = 0;
    /** The density the charts were packed at: texels per model unit. */
    double texelsPerUnit = 0.0;
};

/**
 * Gives a mesh an automatic UV layout: charts grown by normal deviation up to sharp edges, each
 * flattened by least-squares conformal maps and split again where it folds over or stretches,
 * scaled by its 3D area, and packed by shape into texture pages with padding. Existing uvs are
 * replaced. Deterministic: the same mesh and options give the same bytes for any thread count.
 * progress runs on the calling thread; its false cancels (ErrorKind::Cancelled). An Error for an
 * invalid mesh or options, or charts that cannot fit (ErrorKind::BadInput); never throws except
 * std::bad_alloc.
 */
Result<UvLayout> makeUvLayout(const Mesh& mesh, const UvLayoutOptions& options = {},
                              const ProgressFn& progress = {});

/** Quality figures of a layout; ratios are of areas or lengths as described. */
struct UvLayoutMetrics {
    std::uint32_t charts = 0;
    std::uint32_t pages = 0;
    std::uint64_t triangles = 0;
    std::uint64_t vertices = 0; // of the laid-out mesh (seams add copies)
    /**
     * Area stretch per triangle: r = (its share of the UV area) / (its share of the 3D area),
     * taken symmetric as max(r, 1/r); 1 is none. The 95th percentile by 3D area and by count,
     * and the maximum. Triangles without 3D area are left out.
     */
    double stretchP95 = 0.0;
    double stretchP95Triangles = 0.0;
    double stretchMax = 0.0;
    /** Texels per model unit of each triangle, 95th over 5th percentile by 3D area (1 = even). */
    double texelDensitySpread = 0.0;
    /** Covered texels (texel centres inside a triangle) over all texels of the pages. */
    double packingEfficiency = 0.0;
    /** Texels covered by more than one triangle (0 when nothing overlaps). */
    std::uint64_t overlappingTexels = 0;
    /** Triangles with 3D area whose UV triangle has a negative signed area. */
    std::uint64_t flippedTriangles = 0;
    /**
     * Triangles with 3D area whose UV triangle has none (slivers far below a texel, rounded to
     * a line by the float UVs); they cover no texel.
     */
    std::uint64_t collapsedTriangles = 0;
    /** Total 3D length of the edges between two charts, in model units and in unit-cube units. */
    double seamLength = 0.0;
    double seamLengthUnitCube = 0.0;
};

/**
 * Measures layout (as made by makeUvLayout) at its resolution. Threads as in the options; the
 * figures do not depend on them.
 */
UvLayoutMetrics measureUvLayout(const UvLayout& layout, unsigned threads = 0);

} // namespace core
