// SPDX-License-Identifier: GPL-3.0-or-later
// The projection context both paint targets share (used inside core/paint only): the texel
// blend, the current view's projected vertices and triangle setups, the dab's window onto the
// paintable map, and the tiles a stroke touched with their coverage and stroke-start bytes.
// PaintTarget::Context is defined here; its methods are in paint_context.cpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/base/color.h"
#include "core/depth/connectivity.h"
#include "core/depth/depth_layers.h"
#include "core/paint/targets/paint_target.h"

namespace core {

// ---------------------------------------------------------------------------------------------
// sRGB

inline std::uint8_t encodeUnorm(float x) {
    if (!(x > 0.0f))
        return 0;
    if (x >= 1.0f)
        return 255;
    return std::uint8_t(x * 255.0f + 0.5f);
}

/**
 * Sets the texel at dst to lerp(before, target, cover) on the stored values (sRGB-encoded colour,
 * alpha linear), the arithmetic a Normal paint layer's composite makes (PaintLayerStack): colour
 * mixes in one space whether painted on the base or on a paint layer. Coverage 1 gives the
 * target bytes exactly.
 */
inline void blendTexel(std::uint8_t* dst, const std::uint8_t* before,
                       const std::uint8_t* targetBytes, float cover) {
    if (cover >= 1.0f) {
        std::memcpy(dst, targetBytes, 4);
        return;
    }
    for (int k = 0; k < 4; ++k) {
        const float from = layer_bytes::fromByte(before[k]);
        dst[k] = layer_bytes::toByte(from + cover * (layer_bytes::fromByte(targetBytes[k]) - from));
    }
}

// ---------------------------------------------------------------------------------------------
// Projection

/** Clip w at or below which a vertex is at or behind the eye. */
constexpr float kMinW = 1e-6f;

/** A vertex in the current view: view-space position and window position × clip w. */
struct ProjectedVertex {
    glm::vec3 view{0.0f};
    float sx = 0.0f, sy = 0.0f, w = 0.0f; // window x = sx / w, y = sy / w
};

/** A triangle taking part in the current dab. */
struct TriangleSetup {
    std::uint32_t triangle = 0;
    std::array<std::uint32_t, 3> vertex{};
    glm::vec2 screen[3];
    glm::vec4 plane{0.0f}; // view space: unit normal, offset (zero when degenerate)
};

/**
 * What a dab needs of a triangle in the current view, kept while the view stays: its setup,
 * whether it is usable (in front of the eye) and front-facing, and its screen bounding box
 * floored and widened by a pixel (overlapsMap()).
 */
struct ViewTriangle {
    TriangleSetup setup;
    float x0 = 0.0f, x1 = 0.0f, y0 = 0.0f, y1 = 0.0f;
    bool usable = false;
    bool front = false;
};

/** What the context knows of one triangle in the current dab. */
struct TriangleMark {
    std::uint32_t dab = 0;       // the last dab that looked at it
    std::uint32_t local = kNone; // in that dab: its index into setups, or kNone (rejected)
};

/** A triangle's entry in the view cache: valid when serial is the view's. */
struct TriangleView {
    std::uint32_t serial = 0;
    std::uint32_t index = 0;
};

/**
 * What the context keeps of one view (see Context): the projections of the vertices and the
 * setups of the triangles dabs looked at in it. A symmetric stroke paints through a view per
 * copy, dab after dab; the views not in use wait in Context::keptViews.
 */
struct ViewState {
    bool have = false;
    View view;
    std::uint32_t serial = 0;
    float halfWidth = 0.5f, halfHeight = 0.5f;
    PixelRays rays;
    float footprintScale = 0.0f, footprintOffset = 0.0f;
    std::vector<ProjectedVertex> vertices;
    std::vector<std::uint32_t> vertexView;  // per vertex: the serial it was projected for
    std::vector<TriangleView> triangleView; // per triangle
    // Triangles set up in this view. A dab on a dense mesh looks at tens of thousands of
    // triangles, mostly the same as the dab before.
    // In chunks of kViewChunk, so that growing never moves (copies) what is there.
    static constexpr std::size_t kViewChunkBits = 12, kViewChunk = std::size_t(1) << kViewChunkBits;
    std::vector<std::unique_ptr<ViewTriangle[]>> viewChunks;
    std::size_t viewTriangleCount = 0;

    bool shows(const View& v) const {
        return have && v.width == view.width && v.height == view.height && v.view == view.view &&
               v.proj == view.proj;
    }
    std::size_t bytes() const {
        return vertices.capacity() * sizeof(ProjectedVertex) +
               vertexView.capacity() * sizeof(std::uint32_t) +
               triangleView.capacity() * sizeof(TriangleView) +
               viewChunks.size() * kViewChunk * sizeof(ViewTriangle);
    }
};

/** A texel a texture dab reaches (its page's texel coordinates) and the falloff weight there. */
struct DabTexel {
    std::uint16_t x = 0, y = 0; // pages are at most 65535 texels wide and high
    float weight = 0.0f;
    // The stroke's slot of the texel's tile; -1 until between the passes where the tile had
    // none yet.
    std::int32_t slot = -1;
};

/**
 * What the first pass of a texture dab (TextureTarget::paint()) found of one triangle: whether it
 * was scanned, its texels the dab reaches (a range of its chunk's DabTexel list), the least
 * stroke coverage among its other texels, and whether all its texels were looked at.
 */
struct DabTriangle {
    std::uint32_t begin = 0, end = 0;
    std::uint32_t page = 0;
    float least = 0.0f;
    bool scanned = false;
    bool whole = false;
    bool newTiles = false; // some of its texels are in tiles without a slot
    // The slot of all its texels if they share one (found in the first pass), else -1.
    std::int32_t slot = -1;
};

struct StrokeTile {
    TileKey key;
    std::vector<float> alpha;         // stroke coverage per element
    std::vector<std::uint8_t> before; // the tile at stroke start
    std::uint32_t dab = 0;            // the last dab that touched it
    // What that dab wrote: texels [x0, x1) × [y0, y1) of the tile (texture targets).
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    // And per row y of the tile, its texels [rowX0[y], rowX1[y]) (none: rowX0[y] >= rowX1[y]).
    std::array<std::uint8_t, kTextureTile> rowX0{}, rowX1{};
    // On a paint layer, that dab's tiles of the layer's channels it writes (nullptr: not one).
    std::array<std::uint8_t*, 3> paintLayerTiles{};
    std::vector<float> groupAlpha; // alpha when the current dab group first touched it
    std::uint32_t group = 0;       // that group
};

struct PaintTarget::Context {
    std::shared_ptr<const Mesh> mesh;
    std::shared_ptr<const MeshTopology> topology;
    PaintTargetOptions options;

    // The view the cached projections belong to, and up to maxKeptViews() others.
    ViewState current;
    std::vector<ViewState> keptViews;
    // Names for the current view's parts, as the dab code reads them.
    std::vector<ProjectedVertex>& vertices = current.vertices;
    const PixelRays& rays = current.rays;
    /** How many views besides the current one are kept (a memory budget). */
    std::size_t maxKeptViews() const;

    // The dab being painted.
    std::uint32_t dab = 0;
    bool cullBackFaces = true;
    std::vector<TriangleMark> marks; // per triangle
    std::vector<TriangleSetup> setups;
    // Per triangle, in the stroke: a coverage all its texels have reached (texture targets),
    // and the triangles the stroke raised it for (set back at the next stroke's start, not all).
    std::vector<float> triangleCover;
    std::vector<std::uint32_t> coveredTriangles;
    /** Sets triangleCover[t] (never lowered within a stroke) to cover. */
    void setTriangleCover(std::uint32_t t, float cover) {
        if (triangleCover[t] == 0.0f && cover != 0.0f)
            coveredTriangles.push_back(t);
        triangleCover[t] = cover;
    }
    /** All of triangleCover 0 again, for a new stroke. */
    void clearTriangleCover() {
        const std::size_t n = mesh->triangleCount();
        if (triangleCover.size() != n || coveredTriangles.size() > n / 8) {
            triangleCover.assign(n, 0.0f);
        } else {
            for (const std::uint32_t t : coveredTriangles)
                triangleCover[t] = 0.0f;
        }
        coveredTriangles.clear();
    }
    // Per pixel of the map's bounding box: the setup of its fragment's triangle, or kNone.
    std::vector<std::uint32_t> window;
    // Map pixels in window rows [0, y) × columns [0, x), at y * (windowW + 1) + x.
    std::vector<std::uint32_t> windowSums;
    int windowX = 0, windowY = 0, windowW = 0, windowH = 0;
    glm::vec2 center{0.0f};
    float radius = 0.0f;
    TipSampler tip; // the dab's weight per screen offset
    float dabOpacity = 0.0f;
    float flowOpacity = 0.0f;
    float toleranceScale = 0.0f, toleranceOffset = 0.0f; // per unit of depth, constant

    // The stroke.
    bool inStroke = false;
    std::uint32_t group = 0, groupSerial = 0; // the dab group in progress (0 none) and the last
    Brush brush;
    std::uint64_t strokePlane = 0; // TileKey::plane of the tiles the stroke paints
    glm::vec4 colorLinear{0.0f};
    std::array<std::uint8_t, 4> colorBytes{};
    std::size_t elementsPerTile = 0, bytesPerTile = 0;
    std::vector<std::vector<std::int32_t>> tileSlot; // per page and tile: stroke slot or -1
    std::vector<StrokeTile> slots;                   // a pool reused from stroke to stroke
    std::size_t slotsUsed = 0;
    std::vector<std::uint32_t> touched; // slots the current dab touched
    std::vector<TileKey> keys;          // scratch
    std::vector<TexelSpan> rows;        // scratch: the rows of a tile a dab wrote
    std::vector<std::uint8_t> scratch;
    // Scratch of a texture dab: per setup what its first pass found, per chunk of setups the
    // texels the dab reaches.
    std::vector<DabTriangle> dabTriangles;
    std::vector<std::vector<DabTexel>> dabTexels;
    // The second pass's scratch: per slot its texels and the part that writes them; per part
    // the least coverage it saw of each triangle and the tiles it touched first (with the
    // position of the texel, (triangle << 32) | texel, to list them in the one loop's order).
    std::vector<std::uint32_t> slotTexels;
    std::vector<std::vector<std::uint32_t>> partSlotTexels; // the first pass's counts per part
    std::vector<std::uint8_t> slotPart;
    std::vector<std::vector<float>> partLeast;
    std::vector<std::vector<std::pair<std::uint64_t, std::uint32_t>>> partTouched;
    PaintChanges changes;
    /** A texture dab's passes over this context (TextureTarget::paint()). */
    struct TextureDab;

    void updateView(const View& v);
    /** Sizes the current view's per-vertex and per-triangle arrays (kept when they fit). */
    void prepareView();
    const ProjectedVertex& vertex(std::uint32_t v);
    bool setUpTriangle(std::uint32_t t, TriangleSetup& s);
    /** Triangle t in the current view, set up on first use in the view. */
    const ViewTriangle& viewTriangle(std::uint32_t t);
    /** A new dab number (the per-triangle and per-tile marks compare with it). */
    void nextDab() {
        if (++dab == 0) {
            for (TriangleMark& m : marks)
                m.dab = 0;
            for (StrokeTile& s : slots)
                s.dab = 0;
            dab = 1;
        }
    }
    /**
     * Starts dab d in layers' view: its constants, the window onto its map and the triangles
     * that may reach the map (setups). False when it paints nothing.
     */
    bool beginDab(const DepthLayers& layers, const Dab& d);
    /** beginDab()'s first step: the dab's constants; false when it paints nothing. */
    bool setUpDab(const DepthLayers& layers, const Dab& d);
    /** The map's bounding box as the window, all kNone; false when the map has no pixel. */
    bool placeWindow(const DepthStack& st, const Dab& d);
    /** The triangles of the map's fragments, each set up once, and the window's pixels. */
    void mapFragmentTriangles(const DepthStack& st, const Dab& d);
    /** The window's prefix sums of map pixels, for overlapsMap(). */
    void sumWindow();
    /**
     * The neighbours across edges of the triangles set up whose projection reaches a map pixel,
     * and theirs in turn: triangles too small to cover a pixel centre have no fragment, yet
     * their surface points (their texels) project into the map.
     */
    void addNeighbourTriangles();
    /**
     * Starts a paintElements() call: a new dab number, nothing touched yet. Returns the coverage
     * the elements get, the stroke's opacity (0 when there is nothing to paint).
     */
    float beginElements() {
        changes.clear();
        touched.clear();
        if (!inStroke)
            return 0.0f;
        nextDab();
        return std::isfinite(brush.opacity) ? std::clamp(brush.opacity, 0.0f, 1.0f) : 0.0f;
    }
    bool overlapsMap(const ViewTriangle& t) const;
    /**
     * The setup of the map's fragment at window position (px, py), or kNone. Truncating the
     * non-negative offset from the window's integer corner is the floor: the pixel (x, y)
     * covering [x, x + 1) × [y, y + 1).
     */
    std::uint32_t mapAt(float px, float py) const {
        const float fx = px - float(windowX), fy = py - float(windowY);
        if (!(fx >= 0.0f && fx < float(windowW) && fy >= 0.0f && fy < float(windowH)))
            return kNone;
        return window[std::size_t(fy) * std::size_t(windowW) + std::size_t(fx)];
    }
    /**
     * Whether view-space point p of the triangle of setup own, seen in a pixel whose map
     * fragment lies on the triangle of setup mapped, is that fragment's surface.
     */
    bool onMapSurface(std::uint32_t own, const glm::vec3& p, std::uint32_t mapped) const {
        // A planar triangle meets a pixel's ray once: the same triangle is the same point.
        if (own == mapped)
            return true;
        // Another triangle (a neighbour, or another surface): compare with its plane, which is
        // exact across the pixel at any slope where the depth at the pixel centre is not.
        const glm::vec4& plane = setups[mapped].plane;
        const float depth = -p.z;
        return plane != glm::vec4(0.0f) && std::fabs(glm::dot(glm::vec3(plane), p) + plane.w) <=
                                               depth * toleranceScale + toleranceOffset;
    }
    /** The setup of the map's fragment at pixel (x, y), or kNone (also outside the window). */
    std::uint32_t mapAtPixel(int x, int y) const {
        const int wx = x - windowX, wy = y - windowY;
        if (wx < 0 || wy < 0 || wx >= windowW || wy >= windowH)
            return kNone;
        return window[std::size_t(wy) * std::size_t(windowW) + std::size_t(wx)];
    }
    /**
     * Whether view-space point p of the triangle of setup own, seen at window position (px, py)
     * in a pixel whose centre saw no fragment of the map on its surface, is still on the map's
     * surface where the pixel is only partly covered by it: a neighbouring pixel of the 2 × 2
     * block of pixel centres around the position has the map on its surface, and the pixel's
     * centre saw nothing in front of the point and nothing on its surface, unless the centre
     * lies outside the dab's disc (the map ends there for the radius alone). Such points are
     * painted as if their pixel were in the map, so the paint ends at the surface's outline and
     * at the dab's circle, not at the saw-tooth of whole pixels around them.
     */
    bool coveredAtEdge(const DepthStack& stack, std::uint32_t own, const glm::vec3& p, float px,
                       float py) const {
        const float fx = std::floor(px), fy = std::floor(py);
        const int x = int(fx), y = int(fy);
        const int nx = px - fx < 0.5f ? x - 1 : x + 1;
        const int ny = py - fy < 0.5f ? y - 1 : y + 1;
        const int neighbours[3][2] = {{nx, y}, {x, ny}, {nx, ny}};
        bool beside = false;
        for (const auto& q : neighbours) {
            const std::uint32_t mapped = mapAtPixel(q[0], q[1]);
            if (mapped != kNone && onMapSurface(own, p, mapped)) {
                beside = true;
                break;
            }
        }
        if (!beside)
            return false;
        if (x < 0 || y < 0 || x >= stack.width || y >= stack.height)
            return true;
        const std::size_t pixel = std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
        const glm::vec2 centreOffset = glm::vec2(fx + 0.5f, fy + 0.5f) - center;
        const bool outsideDisc = glm::dot(centreOffset, centreOffset) >= radius * radius;
        const float depth = -p.z;
        const float tolerance = depth * toleranceScale + toleranceOffset;
        for (std::uint32_t f = stack.offsets[pixel]; f < stack.offsets[pixel + 1]; ++f) {
            const std::uint32_t t = stack.triangle[f];
            const bool onSurface =
                t < marks.size() && marks[t].dab == dab && marks[t].local != kNone
                    ? onMapSurface(own, p, marks[t].local)
                    : std::fabs(stack.depth[f] - depth) <= tolerance;
            // The centre saw this surface, yet it is not in the map: hidden, too far along the
            // surface, or another layer chosen there; or only outside the disc.
            if (onSurface ? !outsideDisc : stack.depth[f] < depth)
                return false;
        }
        return true;
    }
    bool windowPreimage(const TriangleSetup& s, const glm::dvec2 texel[3], double& minX,
                        double& maxX, double& minY, double& maxY) const;
    std::int32_t slotFor(TileStore& store, std::uint32_t page, std::uint32_t tile);
    void touch(std::int32_t slot) {
        if (claim(slots[std::size_t(slot)]))
            touched.push_back(std::uint32_t(slot));
    }
    /** Readies a tile for what this dab writes to it; true the first time in this dab. */
    bool claim(StrokeTile& s) const {
        if (s.dab == dab)
            return false;
        s.dab = dab;
        s.x0 = s.y0 = std::numeric_limits<int>::max();
        s.x1 = s.y1 = std::numeric_limits<int>::min();
        s.rowX0.fill(std::uint8_t(kTextureTile));
        s.rowX1.fill(0);
        return true;
    }
    /** Adds texel (x, y) of a tile touch() was called for (tile coordinates) to what it wrote. */
    static void wrote(StrokeTile& s, int x, int y) {
        s.x0 = std::min(s.x0, x);
        s.y0 = std::min(s.y0, y);
        s.x1 = std::max(s.x1, x + 1);
        s.y1 = std::max(s.y1, y + 1);
        s.rowX0[std::size_t(y)] = std::min(s.rowX0[std::size_t(y)], std::uint8_t(x));
        s.rowX1[std::size_t(y)] = std::max(s.rowX1[std::size_t(y)], std::uint8_t(x + 1));
    }
    /**
     * The coverage a dab builds on in slot's tile: the stroke's so far, or within a dab group
     * (PaintTarget::beginDabGroup()) what it was before the group touched the tile.
     */
    const float* coverBase(std::int32_t slot) {
        StrokeTile& s = slots[std::size_t(slot)];
        if (group == 0)
            return s.alpha.data();
        if (s.group != group) {
            s.group = group;
            s.groupAlpha.assign(s.alpha.begin(), s.alpha.end());
        }
        return s.groupAlpha.data();
    }
    /** New coverage of an element after this dab at falloff weight, or old if unchanged. */
    float coverAfter(float old, float weight) const {
        return std::max(old, std::min(dabOpacity, old + flowOpacity * weight));
    }
};

/** Weights for colorAt: negative ones dropped, normalised; false if none are usable. */
inline bool normalizedWeights(const Mesh& mesh, std::uint32_t triangle, glm::vec3 w,
                              glm::vec3& out) {
    if (triangle >= mesh.triangleCount() || !std::isfinite(w.x) || !std::isfinite(w.y) ||
        !std::isfinite(w.z))
        return false;
    w = glm::max(w, glm::vec3(0.0f));
    const float sum = w.x + w.y + w.z;
    if (!(sum > 0.0f) || !std::isfinite(sum))
        return false;
    out = w / sum;
    return true;
}

/**
 * The roughness and metallic page `page` (width × height) of a texture target starts with
 * (texture_target_material.cpp): per texel, its material's metallic-roughness map (under the
 * map's placement, G roughness, B metallic, linear) times the material's factors, or the factors
 * alone; texels outside every chart take the page's first material's. materialPage: each
 * material's page.
 */
Image startingMetallicRoughness(const Mesh& mesh, const std::vector<std::uint32_t>& materialPage,
                                std::uint32_t page, int width, int height);

} // namespace core
