// SPDX-License-Identifier: GPL-3.0-or-later
// The projection context's work for each dab (see paint_context.h): projecting the mesh into the
// view, setting up the triangles that may reach the dab's paintable map, the window onto that map
// and the stroke tiles.
#include "core/paint/targets/paint_context.h"

#include <limits>

#include <glm/common.hpp>
#include <glm/mat4x4.hpp>

namespace core {

std::size_t PaintTarget::Context::maxKeptViews() const {
    // A kept view holds a projection per vertex and an entry per triangle; a small mesh keeps
    // a view for each copy of a symmetric stroke, a huge one fewer (at least the current one).
    constexpr std::size_t kMaxKept = 7, kBudget = std::size_t(256) << 20;
    const std::size_t perView = mesh->vertexCount() * (sizeof(ProjectedVertex) + 4) +
                                mesh->triangleCount() * sizeof(TriangleView);
    return std::min(kMaxKept, kBudget / std::max<std::size_t>(perView, 1));
}

void PaintTarget::Context::updateView(const View& v) {
    ViewState& c = current;
    if (c.shows(v))
        return;
    // Another view: the current one is kept, and v's comes back if it was kept.
    if (c.have) {
        const auto kept = std::find_if(keptViews.begin(), keptViews.end(),
                                       [&](const ViewState& k) { return k.shows(v); });
        if (kept != keptViews.end()) {
            std::swap(c, *kept);
            return;
        }
        if (keptViews.size() < maxKeptViews())
            keptViews.emplace_back();
        // When all places are taken the last one is given up: views taken in turn (a stroke's
        // copies) then keep all but one of theirs.
        if (!keptViews.empty())
            std::swap(c, keptViews.back());
    }
    c.have = true;
    c.view = v;
    prepareView();
    if (++c.serial == 0) {
        std::fill(c.vertexView.begin(), c.vertexView.end(), 0u);
        std::fill(c.triangleView.begin(), c.triangleView.end(), TriangleView{});
        c.serial = 1;
    }
    c.viewTriangleCount = 0;
    c.halfWidth = 0.5f * float(v.width);
    c.halfHeight = 0.5f * float(v.height);
    c.rays = PixelRays::fromView(v);
    c.footprintScale = std::max(glm::length(c.rays.directionDx), glm::length(c.rays.directionDy));
    c.footprintOffset = std::max(glm::length(c.rays.originDx), glm::length(c.rays.originDy));
}

void PaintTarget::Context::prepareView() {
    ViewState& c = current;
    c.vertices.resize(mesh->vertexCount());
    c.vertexView.resize(mesh->vertexCount(), 0u);
    c.triangleView.resize(mesh->triangleCount());
}

const ProjectedVertex& PaintTarget::Context::vertex(std::uint32_t v) {
    ViewState& c = current;
    ProjectedVertex& p = c.vertices[v];
    if (c.vertexView[v] != c.serial) {
        c.vertexView[v] = c.serial;
        const glm::vec4 eye = c.view.view * glm::vec4(mesh->positions[v], 1.0f);
        const glm::vec4 clip = c.view.proj * eye;
        p.view = glm::vec3(eye);
        p.w = clip.w;
        p.sx = (clip.x + clip.w) * c.halfWidth;
        p.sy = (clip.w - clip.y) * c.halfHeight;
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

const ViewTriangle& PaintTarget::Context::viewTriangle(std::uint32_t t) {
    using S = ViewState;
    S& c = current;
    TriangleView& entry = c.triangleView[t];
    if (entry.serial == c.serial)
        return c.viewChunks[entry.index >> S::kViewChunkBits][entry.index & (S::kViewChunk - 1)];
    // Past a budget (a long stroke over most of a huge mesh) start the cache again; the views
    // kept share it.
    constexpr std::size_t kMaxViewTriangles = std::size_t(1) << 21;
    if (c.viewTriangleCount >= kMaxViewTriangles / (keptViews.size() + 1)) {
        c.viewTriangleCount = 0;
        std::fill(c.triangleView.begin(), c.triangleView.end(), TriangleView{});
    }
    entry.serial = c.serial;
    entry.index = std::uint32_t(c.viewTriangleCount);
    if ((c.viewTriangleCount >> S::kViewChunkBits) == c.viewChunks.size())
        c.viewChunks.push_back(std::make_unique<ViewTriangle[]>(S::kViewChunk));
    ViewTriangle& v = c.viewChunks[c.viewTriangleCount >> S::kViewChunkBits]
                                  [c.viewTriangleCount & (S::kViewChunk - 1)];
    ++c.viewTriangleCount;
    v = ViewTriangle{};
    TriangleSetup& s = v.setup;
    v.usable = setUpTriangle(t, s);
    if (!v.usable)
        return v;
    // Front faces are clockwise in window coordinates (counter-clockwise in NDC).
    const glm::vec2 e1 = s.screen[1] - s.screen[0], e2 = s.screen[2] - s.screen[0];
    v.front = e1.x * e2.y - e1.y * e2.x < 0.0f;
    // Its surface points project inside its screen bounding box; points in a pixel next to the
    // map can be painted (coveredAtEdge()), so the box reaches one pixel further.
    v.x0 = std::floor(std::min({s.screen[0].x, s.screen[1].x, s.screen[2].x})) - 1.0f;
    v.x1 = std::floor(std::max({s.screen[0].x, s.screen[1].x, s.screen[2].x})) + 1.0f;
    v.y0 = std::floor(std::min({s.screen[0].y, s.screen[1].y, s.screen[2].y})) - 1.0f;
    v.y1 = std::floor(std::max({s.screen[0].y, s.screen[1].y, s.screen[2].y})) + 1.0f;
    return v;
}

bool PaintTarget::Context::overlapsMap(const ViewTriangle& t) const {
    // A map pixel in the triangle's widened box, counted from the window's prefix sums.
    const float x0 = std::max(t.x0, float(windowX));
    const float x1 = std::min(t.x1, float(windowX + windowW - 1));
    const float y0 = std::max(t.y0, float(windowY));
    const float y1 = std::min(t.y1, float(windowY + windowH - 1));
    if (!(x0 <= x1 && y0 <= y1))
        return false;
    const std::size_t stride = std::size_t(windowW) + 1;
    const std::size_t ax = std::size_t(int(x0) - windowX), bx = std::size_t(int(x1) - windowX) + 1;
    const std::size_t ay = std::size_t(int(y0) - windowY), by = std::size_t(int(y1) - windowY) + 1;
    const std::uint32_t* sums = windowSums.data();
    return sums[by * stride + bx] + sums[ay * stride + ax] !=
           sums[ay * stride + bx] + sums[by * stride + ax];
}

namespace {

/** Whether map pixel m lies in stack and its fragment's triangle in a mesh of triangles. */
bool validMapPixel(const DepthStack& stack, const MapPixel& m, std::size_t triangles) {
    return m.pixel < stack.pixelCount() && m.fragment < stack.fragmentCount() &&
           stack.triangle[m.fragment] < triangles;
}

} // namespace

bool PaintTarget::Context::beginDab(const DepthLayers& layers, const Dab& d) {
    if (!setUpDab(layers, d) || !placeWindow(layers.stack, d))
        return false;
    mapFragmentTriangles(layers.stack, d);
    sumWindow();
    addNeighbourTriangles();
    return !setups.empty();
}

bool PaintTarget::Context::setUpDab(const DepthLayers& layers, const Dab& d) {
    cullBackFaces = layers.options.cullBackFaces;
    updateView(layers.view);
    nextDab();
    center = d.center;
    radius = d.radius;
    tip.setup(brush.tipImage(), brush.tipHardness(), radius, d.angle);
    dabOpacity = std::clamp(d.opacity, 0.0f, 1.0f);
    flowOpacity = std::clamp(brush.flow, 0.0f, 1.0f) * dabOpacity;
    toleranceScale = options.relativeTolerance + options.pixelTolerance * current.footprintScale;
    toleranceOffset = options.pixelTolerance * current.footprintOffset;
    touched.clear();
    setups.clear();
    return radius > 0.0f && dabOpacity > 0.0f && flowOpacity > 0.0f;
}

bool PaintTarget::Context::placeWindow(const DepthStack& st, const Dab& d) {
    const std::size_t triangles = mesh->triangleCount();
    int minX = std::numeric_limits<int>::max(), minY = minX, maxX = -1, maxY = -1;
    for (const MapPixel& m : d.paintable) {
        if (!validMapPixel(st, m, triangles))
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
    return true;
}

void PaintTarget::Context::mapFragmentTriangles(const DepthStack& st, const Dab& d) {
    const std::size_t triangles = mesh->triangleCount();
    for (const MapPixel& m : d.paintable) {
        if (!validMapPixel(st, m, triangles))
            continue;
        const int x = int(m.pixel % std::uint32_t(st.width)),
                  y = int(m.pixel / std::uint32_t(st.width));
        const std::uint32_t t = st.triangle[m.fragment];
        TriangleMark& mark = marks[t];
        if (mark.dab != dab) {
            mark.dab = dab;
            const ViewTriangle& v = viewTriangle(t);
            if (v.usable) {
                mark.local = std::uint32_t(setups.size());
                setups.push_back(v.setup);
            } else {
                mark.local = kNone;
            }
        }
        window[std::size_t(y - windowY) * std::size_t(windowW) + std::size_t(x - windowX)] =
            mark.local;
    }
}

void PaintTarget::Context::sumWindow() {
    const std::size_t stride = std::size_t(windowW) + 1;
    windowSums.assign(stride * (std::size_t(windowH) + 1), 0u);
    for (std::size_t y = 0; y < std::size_t(windowH); ++y) {
        const std::uint32_t* row = window.data() + y * std::size_t(windowW);
        const std::uint32_t* above = windowSums.data() + y * stride;
        std::uint32_t* sums = windowSums.data() + (y + 1) * stride;
        std::uint32_t inRow = 0;
        for (std::size_t x = 0; x < std::size_t(windowW); ++x) {
            inRow += row[x] != kNone ? 1u : 0u;
            sums[x + 1] = above[x + 1] + inRow;
        }
    }
}

void PaintTarget::Context::addNeighbourTriangles() {
    const std::size_t triangles = mesh->triangleCount();
    if (!topology || topology->edgeNeighbors.size() != triangles)
        return;
    for (std::size_t i = 0; i < setups.size(); ++i) {
        const std::array<std::uint32_t, 3> next = topology->edgeNeighbors[setups[i].triangle];
        for (const std::uint32_t n : next) {
            if (n >= triangles || marks[n].dab == dab)
                continue;
            marks[n].dab = dab;
            marks[n].local = kNone;
            const ViewTriangle& v = viewTriangle(n);
            if (!v.usable || (cullBackFaces && !v.front && !topology->showsBackFace(n)) ||
                !overlapsMap(v))
                continue;
            marks[n].local = std::uint32_t(setups.size());
            setups.push_back(v.setup);
        }
    }
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
    s.key = {page, tile, strokePlane};
    s.dab = 0;
    std::fill(s.alpha.begin(), s.alpha.end(), 0.0f);
    const std::size_t size = store.tileBytes(s.key);
    store.readTile(s.key, std::span<std::uint8_t>(s.before.data(), size));
    slot = std::int32_t(slotsUsed++);
    return slot;
}

} // namespace core
