// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/paint_target.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include "core/base/color.h"
#include "core/layers/connectivity.h"
#include "core/layers/layers.h"
#include "core/paint/uv_raster.h"

namespace core {

using uv::scanUv;
using uv::setUpUv;
using uv::UvTriangle;
using uv::wrapIndex;

// ---------------------------------------------------------------------------------------------
// sRGB

namespace {

inline std::uint8_t encodeUnorm(float x) {
    if (!(x > 0.0f))
        return 0;
    if (x >= 1.0f)
        return 255;
    return std::uint8_t(x * 255.0f + 0.5f);
}

/**
 * Sets the texel at dst to lerp(before, target, cover) in linear colour (alpha linear as
 * stored). The target is given as bytes (sRGB colour, unorm alpha) and, when targetLinear is not
 * nullptr, as the exact linear values the bytes round; coverage 1 gives the target bytes exactly.
 */
inline void blendTexel(const SrgbTables& srgb, std::uint8_t* dst, const std::uint8_t* before,
                       const std::uint8_t* targetBytes, const float* targetLinear, float cover) {
    if (cover >= 1.0f) {
        std::memcpy(dst, targetBytes, 4);
        return;
    }
    for (int k = 0; k < 3; ++k) {
        const float from = srgb.decode[before[k]];
        const float to = targetLinear ? targetLinear[k] : srgb.decode[targetBytes[k]];
        dst[k] = srgb.encode(from + (to - from) * cover);
    }
    const float from = float(before[3]) / 255.0f;
    const float to = targetLinear ? targetLinear[3] : float(targetBytes[3]) / 255.0f;
    dst[3] = encodeUnorm(from + (to - from) * cover);
}

} // namespace

// ---------------------------------------------------------------------------------------------
// UV-space rasterization: core/uv_raster.h

namespace {

constexpr float kMinW = 1e-6f;

/** Tiles of kTextureTile texels → merged rectangles along tile rows (keys sorted). */
void texelRectsFromTiles(std::vector<TileKey>& keys, const std::vector<TextureTarget::Page>& pages,
                         std::vector<TexelRect>& out) {
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < keys.size();) {
        const TextureTarget::Page& page = pages[keys[i].page];
        const std::uint32_t row = keys[i].tile / std::uint32_t(page.tilesX);
        std::size_t j = i + 1;
        while (j < keys.size() && keys[j].page == keys[i].page &&
               keys[j].tile == keys[j - 1].tile + 1 &&
               keys[j].tile / std::uint32_t(page.tilesX) == row)
            ++j;
        const int tx0 = int(keys[i].tile % std::uint32_t(page.tilesX));
        const int tx1 = int(keys[j - 1].tile % std::uint32_t(page.tilesX));
        TexelRect rect;
        rect.page = keys[i].page;
        rect.x = tx0 * kTextureTile;
        rect.y = int(row) * kTextureTile;
        rect.width = std::min((tx1 + 1) * kTextureTile, page.image.width) - rect.x;
        rect.height = std::min(rect.y + kTextureTile, page.image.height) - rect.y;
        out.push_back(rect);
        i = j;
    }
}

void vertexRangesFromBlocks(std::vector<TileKey>& keys, std::uint32_t vertexCount,
                            std::vector<VertexRange>& out) {
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < keys.size();) {
        std::size_t j = i + 1;
        while (j < keys.size() && keys[j].tile == keys[j - 1].tile + 1)
            ++j;
        out.push_back({keys[i].tile * kVertexBlock,
                       std::min((keys[j - 1].tile + 1) * kVertexBlock, vertexCount)});
        i = j;
    }
}

} // namespace

// ---------------------------------------------------------------------------------------------
// Shared dab machinery

namespace {

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

struct StrokeTile {
    TileKey key;
    std::vector<float> alpha;         // stroke coverage per element
    std::vector<std::uint8_t> before; // the tile at stroke start
    std::uint32_t dab = 0;            // the last dab that touched it
};

} // namespace

struct PaintTarget::Context {
    std::shared_ptr<const Mesh> mesh;
    std::shared_ptr<const MeshTopology> topology;
    PaintTargetOptions options;

    // The view the cached projections belong to.
    bool haveView = false;
    View view;
    std::uint32_t viewSerial = 0;
    float halfWidth = 0.5f, halfHeight = 0.5f;
    PixelRays rays;
    float footprintScale = 0.0f, footprintOffset = 0.0f;
    std::vector<ProjectedVertex> vertices;
    std::vector<std::uint32_t> vertexView;

    // The dab being painted.
    std::uint32_t dab = 0;
    bool cullBackFaces = true;
    std::vector<std::uint32_t> triangleDab;   // per triangle: the last dab that looked at it
    std::vector<std::uint32_t> triangleLocal; // index into setups, or kNone (rejected)
    std::vector<TriangleSetup> setups;
    // Per pixel of the map's bounding box: the setup of its fragment's triangle, or kNone.
    std::vector<std::uint32_t> window;
    int windowX = 0, windowY = 0, windowW = 0, windowH = 0;
    glm::vec2 center{0.0f};
    float radius = 0.0f;
    float dabOpacity = 0.0f;
    float flowOpacity = 0.0f;
    float toleranceScale = 0.0f, toleranceOffset = 0.0f; // per unit of depth, constant

    // The stroke.
    bool inStroke = false;
    Brush brush;
    glm::vec4 colorLinear{0.0f};
    std::array<std::uint8_t, 4> colorBytes{};
    std::size_t elementsPerTile = 0, bytesPerTile = 0;
    std::vector<std::vector<std::int32_t>> tileSlot; // per page and tile: stroke slot or -1
    std::vector<StrokeTile> slots;                   // a pool reused from stroke to stroke
    std::size_t slotsUsed = 0;
    std::vector<std::uint32_t> touched; // slots the current dab touched
    std::vector<TileKey> keys;          // scratch
    std::vector<std::uint8_t> scratch;
    PaintChanges changes;

    void updateView(const View& v);
    const ProjectedVertex& vertex(std::uint32_t v);
    bool setUpTriangle(std::uint32_t t, TriangleSetup& s);
    /** A new dab number (the per-triangle and per-tile marks compare with it). */
    void nextDab() {
        if (++dab == 0) {
            std::fill(triangleDab.begin(), triangleDab.end(), 0u);
            for (StrokeTile& s : slots)
                s.dab = 0;
            dab = 1;
        }
    }
    bool beginDab(const Layers& layers, const Dab& d);
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
    bool overlapsMap(const TriangleSetup& s) const;
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
    bool coveredAtEdge(const LayerStack& stack, std::uint32_t own, const glm::vec3& p, float px,
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
                t < triangleDab.size() && triangleDab[t] == dab && triangleLocal[t] != kNone
                    ? onMapSurface(own, p, triangleLocal[t])
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
        StrokeTile& s = slots[std::size_t(slot)];
        if (s.dab != dab) {
            s.dab = dab;
            touched.push_back(std::uint32_t(slot));
        }
    }
    /** New coverage of an element after this dab at falloff weight, or old if unchanged. */
    float coverAfter(float old, float weight) const {
        return std::max(old, std::min(dabOpacity, old + flowOpacity * weight));
    }
};

void PaintTarget::Context::updateView(const View& v) {
    if (haveView && v.width == view.width && v.height == view.height && v.view == view.view &&
        v.proj == view.proj)
        return;
    haveView = true;
    view = v;
    if (++viewSerial == 0) {
        std::fill(vertexView.begin(), vertexView.end(), 0u);
        viewSerial = 1;
    }
    halfWidth = 0.5f * float(v.width);
    halfHeight = 0.5f * float(v.height);
    rays = PixelRays::fromView(v);
    footprintScale = std::max(glm::length(rays.directionDx), glm::length(rays.directionDy));
    footprintOffset = std::max(glm::length(rays.originDx), glm::length(rays.originDy));
}

const ProjectedVertex& PaintTarget::Context::vertex(std::uint32_t v) {
    ProjectedVertex& p = vertices[v];
    if (vertexView[v] != viewSerial) {
        vertexView[v] = viewSerial;
        const glm::vec4 eye = view.view * glm::vec4(mesh->positions[v], 1.0f);
        const glm::vec4 clip = view.proj * eye;
        p.view = glm::vec3(eye);
        p.w = clip.w;
        p.sx = (clip.x + clip.w) * halfWidth;
        p.sy = (clip.w - clip.y) * halfHeight;
    }
    return p;
}

bool PaintTarget::Context::setUpTriangle(std::uint32_t t, TriangleSetup& s) {
    s.triangle = t;
    for (int c = 0; c < 3; ++c) {
        const std::uint32_t index = mesh->indices[3 * std::size_t(t) + std::size_t(c)];
        const ProjectedVertex& p = vertex(index);
        if (!(p.w > kMinW))
            return false; // at or behind the eye: not paintable in this view
        s.vertex[std::size_t(c)] = index;
        s.screen[c] = {p.sx / p.w, p.sy / p.w};
    }
    const glm::vec3 a = vertices[s.vertex[0]].view, b = vertices[s.vertex[1]].view,
                    c = vertices[s.vertex[2]].view;
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    s.plane = length > 0.0f && std::isfinite(length)
                  ? glm::vec4(n / length, -glm::dot(n / length, a))
                  : glm::vec4(0.0f);
    return true;
}

bool PaintTarget::Context::overlapsMap(const TriangleSetup& s) const {
    // Its surface points project inside its screen bounding box: look for a map pixel there, or
    // one pixel beside it (points in a pixel next to the map can be painted: coveredAtEdge()).
    const float minX = std::min({s.screen[0].x, s.screen[1].x, s.screen[2].x});
    const float maxX = std::max({s.screen[0].x, s.screen[1].x, s.screen[2].x});
    const float minY = std::min({s.screen[0].y, s.screen[1].y, s.screen[2].y});
    const float maxY = std::max({s.screen[0].y, s.screen[1].y, s.screen[2].y});
    const float x0 = std::max(std::floor(minX) - 1.0f, float(windowX));
    const float x1 = std::min(std::floor(maxX) + 1.0f, float(windowX + windowW - 1));
    const float y0 = std::max(std::floor(minY) - 1.0f, float(windowY));
    const float y1 = std::min(std::floor(maxY) + 1.0f, float(windowY + windowH - 1));
    if (!(x0 <= x1 && y0 <= y1))
        return false;
    for (int y = int(y0); y <= int(y1); ++y) {
        const std::uint32_t* row = window.data() + std::size_t(y - windowY) * std::size_t(windowW);
        for (int x = int(x0); x <= int(x1); ++x)
            if (row[x - windowX] != kNone)
                return true;
    }
    return false;
}

bool PaintTarget::Context::beginDab(const Layers& layers, const Dab& d) {
    const LayerStack& st = layers.stack;
    cullBackFaces = layers.options.cullBackFaces;
    updateView(layers.view);
    nextDab();
    center = d.center;
    radius = d.radius;
    dabOpacity = std::clamp(d.opacity, 0.0f, 1.0f);
    flowOpacity = std::clamp(brush.flow, 0.0f, 1.0f) * dabOpacity;
    toleranceScale = options.relativeTolerance + options.pixelTolerance * footprintScale;
    toleranceOffset = options.pixelTolerance * footprintOffset;
    touched.clear();
    setups.clear();
    if (!(radius > 0.0f) || !(dabOpacity > 0.0f) || !(flowOpacity > 0.0f))
        return false;

    // The map's bounding box, then the map itself as a small screen window.
    const std::size_t pixels = st.pixelCount();
    const std::size_t fragments = st.fragmentCount();
    const std::size_t triangles = mesh->triangleCount();
    int minX = std::numeric_limits<int>::max(), minY = minX, maxX = -1, maxY = -1;
    const auto valid = [&](const MapPixel& m) {
        return m.pixel < pixels && m.fragment < fragments && st.triangle[m.fragment] < triangles;
    };
    for (const MapPixel& m : d.paintable) {
        if (!valid(m))
            continue;
        const int x = int(m.pixel % std::uint32_t(st.width)),
                  y = int(m.pixel / std::uint32_t(st.width));
        minX = std::min(minX, x);
        maxX = std::max(maxX, x);
        minY = std::min(minY, y);
        maxY = std::max(maxY, y);
    }
    if (maxX < 0)
        return false;
    windowX = minX;
    windowY = minY;
    windowW = maxX - minX + 1;
    windowH = maxY - minY + 1;
    const std::size_t area = std::size_t(windowW) * std::size_t(windowH);
    if (window.size() < area)
        window.resize(area);
    std::fill(window.begin(), window.begin() + std::ptrdiff_t(area), kNone);

    // The triangles of the map's fragments, each once.
    for (const MapPixel& m : d.paintable) {
        if (!valid(m))
            continue;
        const int x = int(m.pixel % std::uint32_t(st.width)),
                  y = int(m.pixel / std::uint32_t(st.width));
        const std::uint32_t t = st.triangle[m.fragment];
        if (triangleDab[t] != dab) {
            triangleDab[t] = dab;
            TriangleSetup s;
            if (setUpTriangle(t, s)) {
                triangleLocal[t] = std::uint32_t(setups.size());
                setups.push_back(s);
            } else {
                triangleLocal[t] = kNone;
            }
        }
        window[std::size_t(y - windowY) * std::size_t(windowW) + std::size_t(x - windowX)] =
            triangleLocal[t];
    }

    // Their neighbours across edges whose projection reaches a map pixel, and theirs in turn:
    // triangles too small to cover a pixel centre have no fragment, yet their surface points
    // (their texels) project into the map.
    if (topology && topology->edgeNeighbors.size() == triangles) {
        for (std::size_t i = 0; i < setups.size(); ++i) {
            const std::array<std::uint32_t, 3> next = topology->edgeNeighbors[setups[i].triangle];
            for (const std::uint32_t n : next) {
                if (n >= triangles || triangleDab[n] == dab)
                    continue;
                triangleDab[n] = dab;
                triangleLocal[n] = kNone;
                TriangleSetup s;
                if (!setUpTriangle(n, s))
                    continue;
                if (cullBackFaces) {
                    // Front faces are clockwise in window coordinates (counter-clockwise in NDC).
                    const glm::vec2 e1 = s.screen[1] - s.screen[0], e2 = s.screen[2] - s.screen[0];
                    if (!(e1.x * e2.y - e1.y * e2.x < 0.0f))
                        continue;
                }
                if (!overlapsMap(s))
                    continue;
                triangleLocal[n] = std::uint32_t(setups.size());
                setups.push_back(s);
            }
        }
    }
    return !setups.empty();
}

bool PaintTarget::Context::windowPreimage(const TriangleSetup& s, const glm::dvec2 texel[3],
                                          double& minX, double& maxX, double& minY,
                                          double& maxY) const {
    // The texels that can land in the window are those whose point lies inside the window's
    // preimage on the triangle's plane: a convex quadrilateral when all four corner rays hit
    // the plane in front of the eye (no horizon inside the window).
    if (s.plane == glm::vec4(0.0f))
        return false;
    const glm::dvec3 n(s.plane), v0(vertices[s.vertex[0]].view), v1(vertices[s.vertex[1]].view),
        v2(vertices[s.vertex[2]].view);
    const double w = s.plane.w;
    const glm::dvec3 e1 = v1 - v0, e2 = v2 - v0;
    const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
    const double denom = d00 * d11 - d01 * d01;
    if (!(denom > 0.0))
        return false;
    const double xs[2] = {double(windowX) - 1.0, double(windowX + windowW) + 1.0};
    const double ys[2] = {double(windowY) - 1.0, double(windowY + windowH) + 1.0};
    minX = minY = std::numeric_limits<double>::infinity();
    maxX = maxY = -std::numeric_limits<double>::infinity();
    for (const double px : xs) {
        for (const double py : ys) {
            const glm::dvec3 o(rays.origin(float(px), float(py)));
            const glm::dvec3 d(rays.direction(float(px), float(py)));
            const double nd = glm::dot(n, d);
            if (!(std::fabs(nd) > 1e-12))
                return false;
            const double z = -(glm::dot(n, o) + w) / nd;
            if (!(z > 0.0))
                return false;
            const glm::dvec3 q = o + z * d - v0;
            const double d20 = glm::dot(q, e1), d21 = glm::dot(q, e2);
            const double b1 = (d11 * d20 - d01 * d21) / denom;
            const double b2 = (d00 * d21 - d01 * d20) / denom;
            const glm::dvec2 t = texel[0] + b1 * (texel[1] - texel[0]) + b2 * (texel[2] - texel[0]);
            minX = std::min(minX, t.x);
            maxX = std::max(maxX, t.x);
            minY = std::min(minY, t.y);
            maxY = std::max(maxY, t.y);
        }
    }
    return std::isfinite(minX) && std::isfinite(maxX) && std::isfinite(minY) && std::isfinite(maxY);
}

std::int32_t PaintTarget::Context::slotFor(TileStore& store, std::uint32_t page,
                                           std::uint32_t tile) {
    std::int32_t& slot = tileSlot[page][tile];
    if (slot >= 0)
        return slot;
    if (slotsUsed == slots.size()) {
        slots.emplace_back();
        slots.back().alpha.resize(elementsPerTile);
        slots.back().before.resize(bytesPerTile);
    }
    StrokeTile& s = slots[slotsUsed];
    s.key = {page, tile};
    s.dab = 0;
    std::fill(s.alpha.begin(), s.alpha.end(), 0.0f);
    const std::size_t size = store.tileBytes(s.key);
    store.readTile(s.key, std::span<std::uint8_t>(s.before.data(), size));
    slot = std::int32_t(slotsUsed++);
    return slot;
}

// ---------------------------------------------------------------------------------------------
// PaintTarget

PaintTarget::PaintTarget(std::shared_ptr<const Mesh> mesh,
                         std::shared_ptr<const MeshTopology> topology,
                         const PaintTargetOptions& options)
    : m_context(std::make_unique<Context>()) {
    Context& c = *m_context;
    c.mesh = std::move(mesh);
    c.topology = std::move(topology);
    c.options = options;
    c.vertices.resize(c.mesh->vertexCount());
    c.vertexView.assign(c.mesh->vertexCount(), 0u);
    c.triangleDab.assign(c.mesh->triangleCount(), 0u);
    c.triangleLocal.assign(c.mesh->triangleCount(), kNone);
    m_drawMaterials = c.mesh->materials;
    for (Material& m : m_drawMaterials)
        m.baseColorFactor = glm::vec4(1.0f);
}

PaintTarget::~PaintTarget() = default;

const Mesh& PaintTarget::mesh() const {
    return *m_context->mesh;
}

void PaintTarget::setUpStrokeTiles(const std::vector<std::uint32_t>& tilesPerPage,
                                   std::size_t elementsPerTile, std::size_t bytesPerTile) {
    Context& c = *m_context;
    c.tileSlot.clear();
    for (const std::uint32_t tiles : tilesPerPage)
        c.tileSlot.emplace_back(tiles, -1);
    c.elementsPerTile = elementsPerTile;
    c.bytesPerTile = bytesPerTile;
    c.slots.clear();
    c.slotsUsed = 0;
    c.scratch.resize(bytesPerTile);
}

void PaintTarget::beginStroke(const Brush& brush) {
    Context& c = *m_context;
    if (c.inStroke)
        endStroke();
    c.inStroke = true;
    c.brush = brush;
    const SrgbTables& t = SrgbTables::get();
    for (int k = 0; k < 4; ++k) {
        c.colorLinear[k] =
            std::clamp(std::isfinite(brush.color[k]) ? brush.color[k] : 0.0f, 0.0f, 1.0f);
        c.colorBytes[std::size_t(k)] =
            k < 3 ? t.encode(c.colorLinear[k]) : encodeUnorm(c.colorLinear[k]);
    }
}

bool PaintTarget::inStroke() const {
    return m_context->inStroke;
}

TileUndoRecord PaintTarget::endStroke() {
    Context& c = *m_context;
    TileUndoRecord record;
    if (!c.inStroke)
        return record;
    c.inStroke = false;
    std::size_t changed = 0;
    for (std::size_t i = 0; i < c.slotsUsed; ++i) {
        StrokeTile& s = c.slots[i];
        const std::size_t size = tileBytes(s.key);
        readTile(s.key, std::span<std::uint8_t>(c.scratch.data(), size));
        // A tile the stroke only looked at (coverage stayed 0) or painted back is not kept.
        if (std::memcmp(c.scratch.data(), s.before.data(), size) != 0) {
            std::swap(c.slots[changed], s);
            ++changed;
        }
    }
    std::size_t total = 0;
    for (std::size_t i = 0; i < changed; ++i)
        total += tileBytes(c.slots[i].key);
    record.reserve(changed, total);
    for (std::size_t i = 0; i < changed; ++i) {
        const StrokeTile& s = c.slots[i];
        record.addTile(s.key, std::span<const std::uint8_t>(s.before.data(), tileBytes(s.key)));
    }
    for (std::size_t i = 0; i < c.slotsUsed; ++i)
        c.tileSlot[c.slots[i].key.page][c.slots[i].key.tile] = -1;
    c.slotsUsed = 0;
    // Keep the pool for the next stroke, but not what one huge stroke needed.
    constexpr std::size_t kKeptSlots = 512;
    if (c.slots.size() > kKeptSlots)
        c.slots.resize(kKeptSlots);
    return record;
}

// ---------------------------------------------------------------------------------------------
// TextureTarget

namespace {

/** Seam padding of one page: which uncovered texels copy which covered one (docs/architecture.md
 * §3). */
void buildPadding(TextureTarget::Page& page, int padding) {
    const int width = page.image.width, height = page.image.height;
    std::vector<std::uint8_t>& coverage = page.coverage;
    std::vector<TextureTarget::PadPair> frontier, next, pairs;
    const auto at = [&](int x, int y) {
        return std::uint32_t(wrapIndex(y, height)) * std::uint32_t(width) +
               std::uint32_t(wrapIndex(x, width));
    };
    static constexpr int kOrthogonal[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    static constexpr int kDiagonal[4][2] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
    if (padding > 0) {
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const std::uint32_t t = std::uint32_t(y) * std::uint32_t(width) + std::uint32_t(x);
                if (coverage[t] != 1)
                    continue;
                bool border = false;
                for (const auto& d : kOrthogonal)
                    border = border || coverage[at(x + d[0], y + d[1])] == 0;
                for (const auto& d : kDiagonal)
                    border = border || coverage[at(x + d[0], y + d[1])] == 0;
                if (border)
                    frontier.push_back({t, t});
            }
        }
    }
    // Ring by ring, orthogonal neighbours before diagonal ones, so each padded texel copies a
    // near covered texel; the scan order makes the choice deterministic.
    for (int ring = 0; ring < padding && !frontier.empty(); ++ring) {
        next.clear();
        for (const auto* directions : {kOrthogonal, kDiagonal}) {
            for (const TextureTarget::PadPair& f : frontier) {
                const int x = int(f.padded % std::uint32_t(width));
                const int y = int(f.padded / std::uint32_t(width));
                for (int k = 0; k < 4; ++k) {
                    const std::uint32_t n = at(x + directions[k][0], y + directions[k][1]);
                    if (coverage[n] != 0)
                        continue;
                    coverage[n] = 2;
                    pairs.push_back({n, f.source});
                    next.push_back({n, f.source});
                }
            }
        }
        frontier.swap(next);
    }
    // Group by the source texel's tile: a dab pads from the tiles it painted.
    const auto tileOf = [&](std::uint32_t texel) {
        const std::uint32_t x = texel % std::uint32_t(width), y = texel / std::uint32_t(width);
        return (y / kTextureTile) * std::uint32_t(page.tilesX) + x / kTextureTile;
    };
    const std::size_t tiles = std::size_t(page.tilesX) * std::size_t(page.tilesY);
    page.padOffsets.assign(tiles + 1, 0u);
    for (const TextureTarget::PadPair& p : pairs)
        ++page.padOffsets[tileOf(p.source) + 1];
    for (std::size_t i = 0; i < tiles; ++i)
        page.padOffsets[i + 1] += page.padOffsets[i];
    page.padPairs.resize(pairs.size());
    std::vector<std::uint32_t> cursor(page.padOffsets.begin(), page.padOffsets.end() - 1);
    for (const TextureTarget::PadPair& p : pairs)
        page.padPairs[cursor[tileOf(p.source)]++] = p;
}

bool isWhite(const glm::vec4& v) {
    return v == glm::vec4(1.0f);
}

} // namespace

TextureTarget::TextureTarget(std::shared_ptr<const Mesh> mesh,
                             std::shared_ptr<const MeshTopology> topology,
                             const PaintTargetOptions& options)
    : PaintTarget(std::move(mesh), std::move(topology), options) {}

TextureTarget::~TextureTarget() = default;

Result<std::unique_ptr<TextureTarget>>
TextureTarget::create(std::shared_ptr<const Mesh> mesh,
                      std::shared_ptr<const MeshTopology> topology,
                      const PaintTargetOptions& options) {
    if (!mesh)
        return Error{"no mesh to paint"};
    if (const Status valid = mesh->validate(); !valid)
        return Error{"cannot paint the mesh: " + valid.error(), ErrorKind::BadInput};
    if (!mesh->hasUvs())
        return Error{"the mesh has no texture coordinates to paint a texture with"};
    if (!topology || topology->triangleCount() != mesh->triangleCount())
        topology = std::make_shared<const MeshTopology>(buildMeshTopology(*mesh));
    std::unique_ptr<TextureTarget> target(new TextureTarget(mesh, topology, options));
    target->m_padding = std::clamp(options.padding, 0, kTextureTile);
    const SrgbTables& srgb = SrgbTables::get();

    // Vertex colours other than white have to be baked in; white ones change nothing.
    const bool bakeColors =
        mesh->hasColors() && std::any_of(mesh->colors.begin(), mesh->colors.end(),
                                         [](const glm::vec4& c) { return !isWhite(c); });

    // Pages: one per (texture, factor) of textured materials, one shared new page for the rest.
    std::vector<Page>& pages = target->m_pages;
    target->m_materialPage.assign(mesh->materials.size(), 0u);
    std::uint32_t newPage = kNone;
    const int resolution = std::clamp(options.resolution, 512, 8192);
    for (std::size_t m = 0; m < mesh->materials.size(); ++m) {
        const Material& material = mesh->materials[m];
        const int texture = material.baseColorTexture;
        // Texel indices are 32-bit: a texture beyond 16384² is baked into a new page instead.
        const bool textured = options.reuseTextures && texture >= 0 &&
                              !mesh->textures[std::size_t(texture)].empty() &&
                              std::int64_t(mesh->textures[std::size_t(texture)].width) *
                                      mesh->textures[std::size_t(texture)].height <=
                                  std::int64_t(16384) * 16384;
        std::uint32_t index = kNone;
        if (textured) {
            for (std::size_t p = 0; p < pages.size(); ++p)
                if (pages[p].source == texture && pages[p].factor == material.baseColorFactor)
                    index = std::uint32_t(p);
        } else {
            index = newPage;
        }
        if (index == kNone) {
            index = std::uint32_t(pages.size());
            Page page;
            page.factor = material.baseColorFactor;
            if (textured) {
                page.source = texture;
                page.image = mesh->textures[std::size_t(texture)];
                if (!isWhite(page.factor)) {
                    for (std::size_t i = 0; i < page.image.rgba.size(); i += 4) {
                        std::uint8_t* px = &page.image.rgba[i];
                        for (int k = 0; k < 3; ++k)
                            px[k] = srgb.encode(srgb.decode[px[k]] * page.factor[k]);
                        px[3] = encodeUnorm(float(px[3]) / 255.0f * page.factor[3]);
                    }
                }
            } else {
                newPage = index;
                page.image.width = page.image.height = resolution;
                page.image.rgba.resize(std::size_t(resolution) * std::size_t(resolution) * 4);
                const std::uint8_t fill[4] = {
                    srgb.encode(page.factor.r), srgb.encode(page.factor.g),
                    srgb.encode(page.factor.b), encodeUnorm(page.factor.a)};
                for (std::size_t i = 0; i < page.image.rgba.size(); i += 4)
                    std::memcpy(&page.image.rgba[i], fill, 4);
            }
            page.tilesX = (page.image.width + kTextureTile - 1) / kTextureTile;
            page.tilesY = (page.image.height + kTextureTile - 1) / kTextureTile;
            page.coverage.assign(std::size_t(page.image.width) * std::size_t(page.image.height),
                                 0u);
            pages.push_back(std::move(page));
        }
        target->m_materialPage[m] = index;
        target->m_drawMaterials[m].baseColorTexture = int(index);
    }

    // Coverage of every page, baking factor × vertex colours (× texture) into the texels of new
    // and baked pages; a page that is its texture byte for byte only records coverage.
    for (std::size_t t = 0; t < mesh->triangleCount(); ++t) {
        const Material& material = mesh->materials[mesh->triangleMaterial[t]];
        Page& page = pages[target->m_materialPage[mesh->triangleMaterial[t]]];
        const int width = page.image.width, height = page.image.height;
        glm::vec2 uv[3];
        glm::vec4 colors[3];
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = mesh->indices[3 * t + std::size_t(c)];
            uv[c] = mesh->uvs[v];
            colors[c] = bakeColors ? mesh->colors[v] : glm::vec4(1.0f);
        }
        UvTriangle r;
        if (!setUpUv(uv, width, height, r))
            continue;
        // Triangles spread over many repeats of the texture would take forever to visit.
        if (double(r.maxX - r.minX + 1) * double(r.maxY - r.minY + 1) >
            4.0 * double(width) * double(height))
            continue;
        // A textured page bakes from the mesh's texture, not from the page, so a texel that
        // overlapping charts visit twice is not multiplied twice.
        const bool bake = bakeColors || page.source < 0;
        const std::uint8_t* source =
            page.source >= 0 ? mesh->textures[std::size_t(page.source)].rgba.data() : nullptr;
        const glm::vec4 factor = page.source < 0 ? material.baseColorFactor : page.factor;
        const double invArea = 1.0 / double(r.area);
        scanUv(r, r.minX, r.maxX, r.minY, r.maxY,
               [&](int x, int y, std::int64_t e0, std::int64_t e1, std::int64_t e2) {
                   const std::size_t texel =
                       std::size_t(wrapIndex(y, height)) * std::size_t(width) +
                       std::size_t(wrapIndex(x, width));
                   page.coverage[texel] = 1;
                   if (!bake)
                       return;
                   const float l0 = float(double(e0) * invArea), l1 = float(double(e1) * invArea),
                               l2 = float(double(e2) * invArea);
                   const glm::vec4 color =
                       factor * (l0 * colors[r.corner[0]] + l1 * colors[r.corner[1]] +
                                 l2 * colors[r.corner[2]]);
                   std::uint8_t* px = &page.image.rgba[texel * 4];
                   if (source) {
                       const std::uint8_t* in = source + texel * 4;
                       for (int k = 0; k < 3; ++k)
                           px[k] = srgb.encode(srgb.decode[in[k]] * color[k]);
                       px[3] = encodeUnorm(float(in[3]) / 255.0f * color[3]);
                   } else {
                       for (int k = 0; k < 3; ++k)
                           px[k] = srgb.encode(color[k]);
                       px[3] = encodeUnorm(color[3]);
                   }
               });
    }
    for (Page& page : pages) {
        buildPadding(page, target->m_padding);
        // A page made here gets its padding texels from the charts, so filtering at chart
        // borders shows the surface's colour; a texture kept byte for byte stays as it was.
        const bool baked = page.source < 0 || bakeColors; // baked texel by texel
        if (baked)
            for (const PadPair& p : page.padPairs)
                std::memcpy(&page.image.rgba[std::size_t(p.padded) * 4],
                            &page.image.rgba[std::size_t(p.source) * 4], 4);
        page.original = page.image;
    }

    std::vector<std::uint32_t> tilesPerPage;
    for (const Page& page : pages)
        tilesPerPage.push_back(std::uint32_t(page.tilesX * page.tilesY));
    target->setUpStrokeTiles(tilesPerPage, std::size_t(kTextureTile) * kTextureTile,
                             std::size_t(kTextureTile) * kTextureTile * 4);
    return Result<std::unique_ptr<TextureTarget>>(std::move(target));
}

std::uint32_t TextureTarget::trianglePage(std::size_t t) const {
    return m_materialPage[mesh().triangleMaterial[t]];
}

namespace {
/** Weights for colorAt: negative ones dropped, normalised; false if none are usable. */
bool normalizedWeights(const Mesh& mesh, std::uint32_t triangle, glm::vec3 w, glm::vec3& out) {
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
} // namespace

std::optional<glm::vec4> TextureTarget::colorAt(std::uint32_t triangle,
                                                const glm::vec3& weights) const {
    const Mesh& m = mesh();
    glm::vec3 w;
    if (!normalizedWeights(m, triangle, weights, w))
        return std::nullopt;
    glm::vec2 uv(0.0f);
    for (int c = 0; c < 3; ++c)
        uv += w[c] * m.uvs[m.indices[3 * std::size_t(triangle) + std::size_t(c)]];
    const Image& image = m_pages[trianglePage(triangle)].image;
    if (image.empty())
        return std::nullopt;
    // The texel whose square holds the point (UVs repeat, as when painting).
    const double u = double(uv.x) - std::floor(double(uv.x));
    const double v = double(uv.y) - std::floor(double(uv.y));
    const int x = std::clamp(int(u * image.width), 0, image.width - 1);
    const int y = std::clamp(int(v * image.height), 0, image.height - 1);
    const std::uint8_t* texel =
        &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
    return glm::vec4(srgbToLinear(texel[0]), srgbToLinear(texel[1]), srgbToLinear(texel[2]),
                     float(texel[3]) / 255.0f);
}

std::size_t TextureTarget::bytes() const {
    std::size_t total = sizeof(*this);
    for (const Page& p : m_pages)
        total += p.image.rgba.capacity() + p.original.rgba.capacity() + p.coverage.capacity() +
                 p.padOffsets.capacity() * sizeof(std::uint32_t) +
                 p.padPairs.capacity() * sizeof(PadPair);
    const Context& c = *m_context;
    total += c.vertices.capacity() * sizeof(ProjectedVertex) +
             c.vertexView.capacity() * sizeof(std::uint32_t) +
             (c.triangleDab.capacity() + c.triangleLocal.capacity()) * sizeof(std::uint32_t) +
             c.window.capacity() * sizeof(std::uint32_t) +
             c.slots.size() * (c.elementsPerTile * sizeof(float) + c.bytesPerTile);
    return total;
}

std::size_t TextureTarget::tileBytes(TileKey key) const {
    if (key.page >= m_pages.size())
        return 0;
    const Page& p = m_pages[key.page];
    if (key.tile >= std::uint32_t(p.tilesX * p.tilesY))
        return 0;
    const int tx = int(key.tile % std::uint32_t(p.tilesX)),
              ty = int(key.tile / std::uint32_t(p.tilesX));
    const int w = std::min(kTextureTile, p.image.width - tx * kTextureTile);
    const int h = std::min(kTextureTile, p.image.height - ty * kTextureTile);
    return std::size_t(w) * std::size_t(h) * 4;
}

bool TextureTarget::readTile(TileKey key, std::span<std::uint8_t> out) const {
    const std::size_t size = tileBytes(key);
    if (size == 0 || out.size() != size)
        return false;
    const Page& p = m_pages[key.page];
    const int tx = int(key.tile % std::uint32_t(p.tilesX)),
              ty = int(key.tile / std::uint32_t(p.tilesX));
    const int w = std::min(kTextureTile, p.image.width - tx * kTextureTile);
    const std::size_t rowBytes = std::size_t(w) * 4;
    const std::size_t rows = size / rowBytes;
    for (std::size_t r = 0; r < rows; ++r) {
        const std::size_t y = std::size_t(ty * kTextureTile) + r;
        std::memcpy(
            out.data() + r * rowBytes,
            &p.image.rgba[(y * std::size_t(p.image.width) + std::size_t(tx * kTextureTile)) * 4],
            rowBytes);
    }
    return true;
}

bool TextureTarget::writeTile(TileKey key, std::span<const std::uint8_t> bytes) {
    const std::size_t size = tileBytes(key);
    if (size == 0 || bytes.size() != size)
        return false;
    Page& p = m_pages[key.page];
    const int tx = int(key.tile % std::uint32_t(p.tilesX)),
              ty = int(key.tile / std::uint32_t(p.tilesX));
    const int w = std::min(kTextureTile, p.image.width - tx * kTextureTile);
    const std::size_t rowBytes = std::size_t(w) * 4;
    const std::size_t rows = size / rowBytes;
    for (std::size_t r = 0; r < rows; ++r) {
        const std::size_t y = std::size_t(ty * kTextureTile) + r;
        std::memcpy(
            &p.image.rgba[(y * std::size_t(p.image.width) + std::size_t(tx * kTextureTile)) * 4],
            bytes.data() + r * rowBytes, rowBytes);
    }
    return true;
}

PaintChanges TextureTarget::changes(const TileUndoRecord& record) const {
    PaintChanges result;
    std::vector<TileKey> keys;
    for (std::size_t i = 0; i < record.tileCount(); ++i)
        if (tileBytes(record.tile(i)) > 0)
            keys.push_back(record.tile(i));
    texelRectsFromTiles(keys, m_pages, result.texels);
    return result;
}

void TextureTarget::padTouched() {
    Context& c = *m_context;
    const SrgbTables& srgb = SrgbTables::get();
    const bool eraser = c.brush.eraser;
    // Seam padding: uncovered texels next to charts take the coverage of the texel they copy,
    // blended over their own stroke-start value, so the eraser restores them exactly too.
    const std::size_t paintedTiles = c.touched.size(); // padding adds to the list
    for (std::size_t i = 0; i < paintedTiles; ++i) {
        const TileKey key = c.slots[c.touched[i]].key;
        Page& page = m_pages[key.page];
        const int width = page.image.width;
        const std::uint32_t begin = page.padOffsets[key.tile], end = page.padOffsets[key.tile + 1];
        if (begin == end)
            continue;
        const std::size_t sourceSlot = c.touched[i];
        const int sourceTileX = int(key.tile % std::uint32_t(page.tilesX)) * kTextureTile;
        const int sourceTileY = int(key.tile / std::uint32_t(page.tilesX)) * kTextureTile;
        const int sourceWidth = std::min(kTextureTile, width - sourceTileX);
        for (std::uint32_t j = begin; j < end; ++j) {
            const PadPair pair = page.padPairs[j];
            const int sx = int(pair.source % std::uint32_t(width)) - sourceTileX;
            const int sy = int(pair.source / std::uint32_t(width)) - sourceTileY;
            const float sourceCover =
                c.slots[sourceSlot]
                    .alpha[std::size_t(sy) * std::size_t(sourceWidth) + std::size_t(sx)];
            if (!(sourceCover > 0.0f))
                continue;
            const int px = int(pair.padded % std::uint32_t(width));
            const int py = int(pair.padded / std::uint32_t(width));
            const std::uint32_t tile =
                std::uint32_t(py / kTextureTile) * std::uint32_t(page.tilesX) +
                std::uint32_t(px / kTextureTile);
            const std::int32_t slot = c.slotFor(*this, key.page, tile);
            StrokeTile& st = c.slots[std::size_t(slot)];
            const int tileWidth =
                std::min(kTextureTile, width - (px / kTextureTile) * kTextureTile);
            const std::size_t local = std::size_t(py % kTextureTile) * std::size_t(tileWidth) +
                                      std::size_t(px % kTextureTile);
            if (!(sourceCover > st.alpha[local]))
                continue;
            st.alpha[local] = sourceCover;
            c.touch(slot);
            const std::size_t at = std::size_t(pair.padded) * 4;
            blendTexel(srgb, &page.image.rgba[at], &st.before[local * 4],
                       eraser ? &page.original.rgba[at] : c.colorBytes.data(),
                       eraser ? nullptr : &c.colorLinear[0], sourceCover);
        }
    }
}

const PaintChanges& TextureTarget::paintElements(std::span<const PaintElement> elements) {
    Context& c = *m_context;
    const float cover = c.beginElements();
    if (!(cover > 0.0f))
        return c.changes;
    const SrgbTables& srgb = SrgbTables::get();
    const bool eraser = c.brush.eraser;
    for (const PaintElement& e : elements) {
        if (e.page >= m_pages.size())
            continue;
        Page& page = m_pages[e.page];
        const int width = page.image.width;
        if (std::size_t(e.index) >= std::size_t(width) * std::size_t(page.image.height))
            continue;
        const int x = int(e.index % std::uint32_t(width)), y = int(e.index / std::uint32_t(width));
        const std::uint32_t tile = std::uint32_t(y / kTextureTile) * std::uint32_t(page.tilesX) +
                                   std::uint32_t(x / kTextureTile);
        const std::int32_t slot = c.slotFor(*this, e.page, tile);
        StrokeTile& st = c.slots[std::size_t(slot)];
        const int tileWidth = std::min(kTextureTile, width - (x / kTextureTile) * kTextureTile);
        const std::size_t local =
            std::size_t(y % kTextureTile) * std::size_t(tileWidth) + std::size_t(x % kTextureTile);
        if (!(cover > st.alpha[local]))
            continue;
        st.alpha[local] = cover;
        c.touch(slot);
        const std::size_t at = std::size_t(e.index) * 4;
        blendTexel(srgb, &page.image.rgba[at], &st.before[local * 4],
                   eraser ? &page.original.rgba[at] : c.colorBytes.data(),
                   eraser ? nullptr : &c.colorLinear[0], cover);
    }
    padTouched();
    c.keys.clear();
    for (const std::uint32_t slot : c.touched)
        c.keys.push_back(c.slots[slot].key);
    texelRectsFromTiles(c.keys, m_pages, c.changes.texels);
    return c.changes;
}

const PaintChanges& TextureTarget::paint(const Layers& layers, const Dab& dab) {
    Context& c = *m_context;
    c.changes.clear();
    if (!c.inStroke || !c.beginDab(layers, dab))
        return c.changes;
    const Mesh& m = *c.mesh;
    const SrgbTables& srgb = SrgbTables::get();
    const Brush& brush = c.brush;
    const bool eraser = brush.eraser;

    // Sets texel (page, x, y) to lerp(stroke start, target, coverage): the brush colour, or the
    // original for the eraser.
    const Page* blendPage = nullptr; // the page blend() writes to
    const auto blend = [&](std::uint8_t* pixels, std::size_t texel, const std::uint8_t* before,
                           float cover) {
        blendTexel(srgb, pixels + texel * 4, before,
                   eraser ? &blendPage->original.rgba[texel * 4] : c.colorBytes.data(),
                   eraser ? nullptr : &c.colorLinear[0], cover);
    };

    // The dab's constants as locals, which the compiler can keep in registers across the
    // texel loop (members would be reloaded after every texel store).
    const std::uint32_t* window = c.window.data();
    const float windowX = float(c.windowX), windowY = float(c.windowY);
    const float windowW = float(c.windowW), windowH = float(c.windowH);
    const std::size_t windowStride = std::size_t(c.windowW);
    const TriangleSetup* setups = c.setups.data();
    const glm::vec2 center = c.center;
    const float radius = c.radius, dabOpacity = c.dabOpacity, flowOpacity = c.flowOpacity;
    const float toleranceScale = c.toleranceScale, toleranceOffset = c.toleranceOffset;
    const LayerStack& stack = layers.stack;

    for (std::size_t si = 0; si < c.setups.size(); ++si) {
        const TriangleSetup s = c.setups[si];
        const auto own = std::uint32_t(si);
        const std::uint32_t pageIndex = m_materialPage[m.triangleMaterial[s.triangle]];
        Page& page = m_pages[pageIndex];
        blendPage = &page;
        const int width = page.image.width, height = page.image.height;
        const auto tilesX = std::uint32_t(page.tilesX);
        glm::vec2 uv[3];
        for (int k = 0; k < 3; ++k)
            uv[k] = m.uvs[s.vertex[std::size_t(k)]];
        UvTriangle r;
        if (!setUpUv(uv, width, height, r))
            continue;
        int x0 = r.minX, x1 = r.maxX, y0 = r.minY, y1 = r.maxY;
        // A triangle larger than the dab: visit only the texels that can land in the map.
        const float sMinX = std::min({s.screen[0].x, s.screen[1].x, s.screen[2].x});
        const float sMaxX = std::max({s.screen[0].x, s.screen[1].x, s.screen[2].x});
        const float sMinY = std::min({s.screen[0].y, s.screen[1].y, s.screen[2].y});
        const float sMaxY = std::max({s.screen[0].y, s.screen[1].y, s.screen[2].y});
        const bool inside =
            sMinX >= float(c.windowX - 2) && sMaxX <= float(c.windowX + c.windowW + 2) &&
            sMinY >= float(c.windowY - 2) && sMaxY <= float(c.windowY + c.windowH + 2);
        if (!inside && double(x1 - x0 + 1) * double(y1 - y0 + 1) > 64.0) {
            glm::dvec2 texel[3];
            for (int k = 0; k < 3; ++k)
                texel[k] = glm::dvec2(double(uv[k].x) * width, double(uv[k].y) * height);
            double minX, maxX, minY, maxY;
            if (c.windowPreimage(s, texel, minX, maxX, minY, maxY)) {
                x0 = std::max(x0, int(std::floor(minX)) - 1);
                x1 = std::min(x1, int(std::floor(maxX)) + 1);
                y0 = std::max(y0, int(std::floor(minY)) - 1);
                y1 = std::min(y1, int(std::floor(maxY)) + 1);
            }
        }
        if (x0 > x1 || y0 > y1)
            continue;
        if (double(x1 - x0 + 1) * double(y1 - y0 + 1) > 4.0 * double(width) * double(height))
            continue; // spread over many repeats of the texture (see create())
        const bool wrap = x0 < 0 || y0 < 0 || x1 >= width || y1 >= height;

        ProjectedVertex p[3];
        for (int k = 0; k < 3; ++k)
            p[k] = c.vertices[s.vertex[std::size_t(r.corner[k])]];
        const float invArea = float(1.0 / double(r.area));
        std::uint8_t* pixels = page.image.rgba.data();
        std::uint32_t lastTile = kNone;
        std::int32_t slot = -1;
        float* alpha = nullptr;
        const std::uint8_t* before = nullptr;
        bool tileTouched = false;
        int tileWidth = 0;

        scanUv(
            r, x0, x1, y0, y1,
            [&](int x, int y, std::int64_t e0, std::int64_t e1, std::int64_t e2) {
                const float l0 = float(e0) * invArea, l1 = float(e1) * invArea,
                            l2 = float(e2) * invArea;
                const float w = l0 * p[0].w + l1 * p[1].w + l2 * p[2].w;
                if (!(w > kMinW))
                    return;
                const float px = (l0 * p[0].sx + l1 * p[1].sx + l2 * p[2].sx) / w;
                const float py = (l0 * p[0].sy + l1 * p[1].sy + l2 * p[2].sy) / w;
                // The map's fragment at the texel's pixel (as Context::mapAt()). Texels up to a
                // pixel outside the map's box can be at its surface's outline.
                const float fx = px - windowX, fy = py - windowY;
                if (!(fx >= -1.0f && fx < windowW + 1.0f && fy >= -1.0f && fy < windowH + 1.0f))
                    return;
                const std::uint32_t mapped =
                    fx >= 0.0f && fx < windowW && fy >= 0.0f && fy < windowH
                        ? window[std::size_t(fy) * windowStride + std::size_t(fx)]
                        : kNone;
                // On its surface (as Context::onMapSurface()).
                bool onMap = mapped == own;
                if (!onMap && mapped != kNone) {
                    const glm::vec3 point = l0 * p[0].view + l1 * p[1].view + l2 * p[2].view;
                    const glm::vec4& plane = setups[mapped].plane;
                    onMap = plane != glm::vec4(0.0f) &&
                            std::fabs(glm::dot(glm::vec3(plane), point) + plane.w) <=
                                -point.z * toleranceScale + toleranceOffset;
                }
                const float distance = glm::length(glm::vec2(px, py) - center);
                if (!(distance < radius))
                    return;
                if (!onMap &&
                    !c.coveredAtEdge(stack, own, l0 * p[0].view + l1 * p[1].view + l2 * p[2].view,
                                     px, py))
                    return;
                const float weight = brush.falloff(distance, radius);
                if (!(weight > 0.0f))
                    return;
                const int tx = wrap ? wrapIndex(x, width) : x;
                const int ty = wrap ? wrapIndex(y, height) : y;
                const std::uint32_t tile =
                    std::uint32_t(ty / kTextureTile) * tilesX + std::uint32_t(tx / kTextureTile);
                if (tile != lastTile) {
                    lastTile = tile;
                    slot = c.slotFor(*this, pageIndex, tile);
                    alpha = c.slots[std::size_t(slot)].alpha.data();
                    before = c.slots[std::size_t(slot)].before.data();
                    tileTouched = false;
                    tileWidth = std::min(kTextureTile, width - (tx / kTextureTile) * kTextureTile);
                }
                const std::size_t local = std::size_t(ty % kTextureTile) * std::size_t(tileWidth) +
                                          std::size_t(tx % kTextureTile);
                const float old = alpha[local];
                const float cover = std::max(old, std::min(dabOpacity, old + flowOpacity * weight));
                if (!(cover > old))
                    return;
                alpha[local] = cover;
                if (!tileTouched) {
                    tileTouched = true;
                    c.touch(slot);
                }
                blend(pixels, std::size_t(ty) * std::size_t(width) + std::size_t(tx),
                      before + local * 4, cover);
            });
    }

    padTouched();
    c.keys.clear();
    for (const std::uint32_t slot : c.touched)
        c.keys.push_back(c.slots[slot].key);
    texelRectsFromTiles(c.keys, m_pages, c.changes.texels);
    return c.changes;
}

// ---------------------------------------------------------------------------------------------
// VertexColorTarget

VertexColorTarget::VertexColorTarget(std::shared_ptr<const Mesh> mesh,
                                     std::shared_ptr<const MeshTopology> topology,
                                     const PaintTargetOptions& options)
    : PaintTarget(std::move(mesh), std::move(topology), options) {}

VertexColorTarget::~VertexColorTarget() = default;

Result<std::unique_ptr<VertexColorTarget>>
VertexColorTarget::create(std::shared_ptr<const Mesh> mesh,
                          std::shared_ptr<const MeshTopology> topology,
                          const PaintTargetOptions& options) {
    if (!mesh)
        return Error{"no mesh to paint"};
    if (const Status valid = mesh->validate(); !valid)
        return Error{"cannot paint the mesh: " + valid.error(), ErrorKind::BadInput};
    if (!topology || topology->triangleCount() != mesh->triangleCount())
        topology = std::make_shared<const MeshTopology>(buildMeshTopology(*mesh));
    std::unique_ptr<VertexColorTarget> target(new VertexColorTarget(mesh, topology, options));
    const std::size_t n = mesh->vertexCount();
    // Each vertex takes the factor of the first triangle using it (a vertex shared by materials
    // of different factors cannot keep both looks).
    std::vector<std::uint8_t> assigned(n, 0u);
    target->m_colors.assign(n, glm::vec4(1.0f));
    if (mesh->hasColors())
        for (std::size_t v = 0; v < n; ++v)
            for (int k = 0; k < 4; ++k)
                target->m_colors[v][k] =
                    std::isfinite(mesh->colors[v][k]) ? mesh->colors[v][k] : 1.0f;
    for (std::size_t t = 0; t < mesh->triangleCount(); ++t) {
        const glm::vec4 factor = mesh->materials[mesh->triangleMaterial[t]].baseColorFactor;
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = mesh->indices[3 * t + std::size_t(c)];
            if (!assigned[v]) {
                assigned[v] = 1;
                target->m_colors[v] *= factor;
            }
        }
    }
    target->m_original = target->m_colors;
    target->m_vertexDab.assign(n, 0u);
    const std::uint32_t blocks = std::uint32_t((n + kVertexBlock - 1) / kVertexBlock);
    target->setUpStrokeTiles({blocks}, kVertexBlock, kVertexBlock * sizeof(glm::vec4));
    return Result<std::unique_ptr<VertexColorTarget>>(std::move(target));
}

std::optional<glm::vec4> VertexColorTarget::colorAt(std::uint32_t triangle,
                                                    const glm::vec3& weights) const {
    const Mesh& m = mesh();
    glm::vec3 w;
    if (!normalizedWeights(m, triangle, weights, w))
        return std::nullopt;
    glm::vec4 color(0.0f);
    for (int c = 0; c < 3; ++c)
        color += w[c] * m_colors[m.indices[3 * std::size_t(triangle) + std::size_t(c)]];
    return color;
}

std::size_t VertexColorTarget::bytes() const {
    const Context& c = *m_context;
    return sizeof(*this) + (m_colors.capacity() + m_original.capacity()) * sizeof(glm::vec4) +
           m_vertexDab.capacity() * sizeof(std::uint32_t) +
           c.vertices.capacity() * sizeof(ProjectedVertex) +
           c.vertexView.capacity() * sizeof(std::uint32_t) +
           (c.triangleDab.capacity() + c.triangleLocal.capacity()) * sizeof(std::uint32_t) +
           c.window.capacity() * sizeof(std::uint32_t) +
           c.slots.size() * (c.elementsPerTile * sizeof(float) + c.bytesPerTile);
}

std::size_t VertexColorTarget::tileBytes(TileKey key) const {
    const std::size_t n = m_colors.size();
    const std::size_t first = std::size_t(key.tile) * kVertexBlock;
    if (key.page != 0 || first >= n)
        return 0;
    return std::min<std::size_t>(kVertexBlock, n - first) * sizeof(glm::vec4);
}

bool VertexColorTarget::readTile(TileKey key, std::span<std::uint8_t> out) const {
    const std::size_t size = tileBytes(key);
    if (size == 0 || out.size() != size)
        return false;
    std::memcpy(out.data(), &m_colors[std::size_t(key.tile) * kVertexBlock], size);
    return true;
}

bool VertexColorTarget::writeTile(TileKey key, std::span<const std::uint8_t> bytes) {
    const std::size_t size = tileBytes(key);
    if (size == 0 || bytes.size() != size)
        return false;
    std::memcpy(&m_colors[std::size_t(key.tile) * kVertexBlock], bytes.data(), size);
    return true;
}

PaintChanges VertexColorTarget::changes(const TileUndoRecord& record) const {
    PaintChanges result;
    std::vector<TileKey> keys;
    for (std::size_t i = 0; i < record.tileCount(); ++i)
        if (tileBytes(record.tile(i)) > 0)
            keys.push_back(record.tile(i));
    vertexRangesFromBlocks(keys, std::uint32_t(m_colors.size()), result.vertices);
    return result;
}

const PaintChanges& VertexColorTarget::paintElements(std::span<const PaintElement> elements) {
    Context& c = *m_context;
    const float cover = c.beginElements();
    if (!(cover > 0.0f))
        return c.changes;
    for (const PaintElement& e : elements) {
        const std::uint32_t v = e.index;
        if (e.page != 0 || v >= m_colors.size())
            continue;
        const std::int32_t slot = c.slotFor(*this, 0, v / kVertexBlock);
        StrokeTile& st = c.slots[std::size_t(slot)];
        const std::size_t local = v % kVertexBlock;
        if (!(cover > st.alpha[local]))
            continue;
        st.alpha[local] = cover;
        c.touch(slot);
        glm::vec4 before;
        std::memcpy(&before, &st.before[local * sizeof(glm::vec4)], sizeof(glm::vec4));
        const glm::vec4 target = c.brush.eraser ? m_original[v] : c.colorLinear;
        m_colors[v] = cover >= 1.0f ? target : before + (target - before) * cover;
    }
    c.keys.clear();
    for (const std::uint32_t slot : c.touched)
        c.keys.push_back(c.slots[slot].key);
    vertexRangesFromBlocks(c.keys, std::uint32_t(m_colors.size()), c.changes.vertices);
    return c.changes;
}

const PaintChanges& VertexColorTarget::paint(const Layers& layers, const Dab& dab) {
    Context& c = *m_context;
    c.changes.clear();
    if (!c.inStroke || !c.beginDab(layers, dab))
        return c.changes;
    const Brush& brush = c.brush;
    for (std::size_t si = 0; si < c.setups.size(); ++si) {
        const TriangleSetup& s = c.setups[si];
        for (const std::uint32_t v : s.vertex) {
            if (m_vertexDab[v] == c.dab)
                continue;
            m_vertexDab[v] = c.dab;
            const ProjectedVertex& p = c.vertices[v];
            const float px = p.sx / p.w, py = p.sy / p.w;
            const std::uint32_t mapped = c.mapAt(px, py);
            if (mapped == kNone)
                continue;
            // The vertex is a corner of the fragment's triangle, or lies on its plane.
            const std::array<std::uint32_t, 3>& corners = c.setups[mapped].vertex;
            const bool corner = corners[0] == v || corners[1] == v || corners[2] == v;
            if (!corner && !c.onMapSurface(std::uint32_t(si), p.view, mapped))
                continue;
            const float weight = brush.falloff(glm::length(glm::vec2(px, py) - c.center), c.radius);
            if (!(weight > 0.0f))
                continue;
            const std::int32_t slot = c.slotFor(*this, 0, v / kVertexBlock);
            StrokeTile& st = c.slots[std::size_t(slot)];
            const std::size_t local = v % kVertexBlock;
            const float old = st.alpha[local];
            const float cover = c.coverAfter(old, weight);
            if (!(cover > old))
                continue;
            st.alpha[local] = cover;
            c.touch(slot);
            glm::vec4 before;
            std::memcpy(&before, &st.before[local * sizeof(glm::vec4)], sizeof(glm::vec4));
            const glm::vec4 target = brush.eraser ? m_original[v] : c.colorLinear;
            m_colors[v] = cover >= 1.0f ? target : before + (target - before) * cover;
        }
    }
    c.keys.clear();
    for (const std::uint32_t slot : c.touched)
        c.keys.push_back(c.slots[slot].key);
    vertexRangesFromBlocks(c.keys, std::uint32_t(m_colors.size()), c.changes.vertices);
    return c.changes;
}

// ---------------------------------------------------------------------------------------------

Result<std::unique_ptr<PaintTarget>> makePaintTarget(std::shared_ptr<const Mesh> mesh,
                                                     std::shared_ptr<const MeshTopology> topology,
                                                     const PaintTargetOptions& options) {
    const bool texture =
        options.kind ? *options.kind == PaintTargetKind::Texture : (mesh && mesh->hasUvs());
    if (texture) {
        auto target = TextureTarget::create(std::move(mesh), std::move(topology), options);
        if (!target)
            return target.takeError();
        return Result<std::unique_ptr<PaintTarget>>(std::move(target).value());
    }
    auto target = VertexColorTarget::create(std::move(mesh), std::move(topology), options);
    if (!target)
        return target.takeError();
    return Result<std::unique_ptr<PaintTarget>>(std::move(target).value());
}

} // namespace core
