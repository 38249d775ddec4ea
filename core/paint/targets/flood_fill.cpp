// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/targets/flood_fill.h"
#include "core/base/color.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "core/depth/depth_layers.h"
#include "core/paint/targets/uv_raster.h"

namespace core {

std::optional<FillMode> parseFillMode(std::string_view name) {
    if (name == "region")
        return FillMode::Region;
    if (name == "surface")
        return FillMode::Surface;
    if (name == "color")
        return FillMode::Color;
    return std::nullopt;
}

const char* fillModeName(FillMode mode) {
    switch (mode) {
    case FillMode::Region:
        return "region";
    case FillMode::Surface:
        return "surface";
    case FillMode::Color:
        return "color";
    }
    return "region";
}

namespace {

std::uint32_t vertexOf(const Mesh& mesh, std::uint32_t triangle, int corner) {
    return mesh.indices[3 * std::size_t(triangle) + std::size_t(corner)];
}

/**
 * The UV triangle of t on a page of width × height; false when a stroke paints no texels of it
 * (degenerate, or spread over many repeats of the texture: TextureTarget::create skips those).
 */
bool pageTriangle(const Mesh& mesh, std::uint32_t t, int width, int height, uv::UvTriangle& r) {
    glm::vec2 uvs[3];
    for (int c = 0; c < 3; ++c)
        uvs[c] = mesh.uvs[vertexOf(mesh, t, c)];
    if (!uv::setUpUv(uvs, width, height, r))
        return false;
    return double(r.maxX - r.minX + 1) * double(r.maxY - r.minY + 1) <=
           4.0 * double(width) * double(height);
}

/** Calls fn(texel index y * width + x) for every texel of r (wrapped into the page). */
template <typename Fn> void forEachTexel(const uv::UvTriangle& r, int width, int height, Fn&& fn) {
    uv::scanUv(r, r.minX, r.maxX, r.minY, r.maxY,
               [&](int x, int y, std::int64_t, std::int64_t, std::int64_t) {
                   fn(std::uint32_t(uv::wrapIndex(y, height)) * std::uint32_t(width) +
                      std::uint32_t(uv::wrapIndex(x, width)));
               });
}

/** A colour as compared: sRGB-encoded red, green, blue and alpha, 0..1. */
glm::vec4 encodedColor(const glm::vec4& linear) {
    return {encodeSrgb(linear.r), encodeSrgb(linear.g), encodeSrgb(linear.b),
            std::isfinite(linear.a) ? std::clamp(linear.a, 0.0f, 1.0f) : 0.0f};
}

/** Within tolerance: no channel differs by more (a hair of slack for float rounding). */
bool similar(const glm::vec4& a, const glm::vec4& b, float tolerance) {
    const glm::vec4 d = glm::abs(a - b);
    return std::max(std::max(d.r, d.g), std::max(d.b, d.a)) <= tolerance + 1e-6f;
}

constexpr double kMaxTexel = double(1 << 20); // as uv::setUpUv: texel indices fit an int

/**
 * A colour fill on a texture target (textureColorFill()): the component's triangles, which of
 * them covers each texel of their pages, and the links between texels across UV seams.
 */
struct TextureColorFill {
    /** A page the component's triangles use: which covers each texel, and the fill's visits. */
    struct Page {
        int width = 0, height = 0;
        std::vector<std::uint32_t> owner;
        std::vector<std::uint8_t> visited;
    };

    const TextureTarget& target;
    const Mesh& mesh;
    const MeshTopology& topology;
    const bool haveTopology;
    const std::vector<std::uint32_t> triangles;
    std::vector<Page> pages;
    // Texel to texel across UV seams, both ways, sorted: (node(page, texel), node(...)).
    std::vector<std::pair<std::uint64_t, std::uint64_t>> links;

    TextureColorFill(const TextureTarget& fillTarget, const MeshTopology& meshTopology,
                     std::uint32_t seed)
        : target(fillTarget), mesh(fillTarget.mesh()), topology(meshTopology),
          haveTopology(meshTopology.triangleCount() == mesh.triangleCount()),
          triangles(componentTriangles(meshTopology, seed)), pages(fillTarget.pageCount()) {}

    static std::uint64_t node(std::uint32_t page, std::uint32_t texel) {
        return (std::uint64_t(page) << 32) | texel;
    }
    /**
     * Texels are joined where their triangles meet on the surface: the same triangle, or two
     * sharing a corner (a chart's texels). Other charts can touch in UV space and stay apart.
     */
    bool adjacent(std::uint32_t a, std::uint32_t b) const {
        return a == b || (haveTopology && topology.sharedCorners(a, b) > 0);
    }
    /** Corner of triangle t in texel coordinates of its page. */
    glm::dvec2 texelPosition(std::uint32_t t, int corner) const {
        const Page& page = pages[target.trianglePage(t)];
        const glm::vec2 uv = mesh.uvs[vertexOf(mesh, t, corner)];
        return glm::dvec2(double(uv.x) * page.width, double(uv.y) * page.height);
    }

    void markOwners();
    std::uint32_t texelNear(std::uint32_t t, std::uint32_t p, glm::dvec2 q) const;
    void linkSeams();
    void linkEdge(std::uint32_t t, int e);
    std::vector<PaintElement> spread(std::uint32_t seedPage, std::uint32_t seedTexel,
                                     float tolerance);
};

/**
 * Which component triangle covers each texel of the pages they use (the last one where charts
 * overlap).
 */
void TextureColorFill::markOwners() {
    for (const std::uint32_t t : triangles) {
        const std::uint32_t p = target.trianglePage(t);
        Page& page = pages[p];
        if (page.owner.empty()) {
            page.width = target.page(p).width;
            page.height = target.page(p).height;
            const std::size_t texels = std::size_t(page.width) * std::size_t(page.height);
            page.owner.assign(texels, kNone);
            page.visited.assign(texels, 0u);
        }
        uv::UvTriangle r;
        if (pageTriangle(mesh, t, page.width, page.height, r))
            forEachTexel(r, page.width, page.height, [&](std::uint32_t i) { page.owner[i] = t; });
    }
}

/**
 * The texel of triangle t (on page p) nearest texel position q: its own or a neighbour's within
 * two texels (a point at a chart's rim has its centre outside), or kNone.
 */
std::uint32_t TextureColorFill::texelNear(std::uint32_t t, std::uint32_t p, glm::dvec2 q) const {
    const Page& page = pages[p];
    if (!(std::fabs(q.x) < kMaxTexel && std::fabs(q.y) < kMaxTexel))
        return kNone;
    const int cx = int(std::floor(q.x)), cy = int(std::floor(q.y));
    std::uint32_t best = kNone;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int radius = 0; radius <= 2 && best == kNone; ++radius) {
        for (int dy = -radius; dy <= radius; ++dy) {
            for (int dx = -radius; dx <= radius; ++dx) {
                if (std::max(std::abs(dx), std::abs(dy)) != radius)
                    continue;
                const std::uint32_t i =
                    std::uint32_t(uv::wrapIndex(cy + dy, page.height)) * std::uint32_t(page.width) +
                    std::uint32_t(uv::wrapIndex(cx + dx, page.width));
                const std::uint32_t owner = page.owner[i];
                if (owner == kNone || !adjacent(owner, t))
                    continue;
                const glm::dvec2 centre(double(cx + dx) + 0.5, double(cy + dy) + 0.5);
                const double d = glm::length(centre - q);
                if (d < bestDistance) {
                    bestDistance = d;
                    best = i;
                }
            }
        }
    }
    return best;
}

/** Across UV seams: the links of every edge the component's triangles share (sorted). */
void TextureColorFill::linkSeams() {
    if (!haveTopology)
        return;
    for (const std::uint32_t t : triangles)
        for (int e = 0; e < 3; ++e)
            linkEdge(t, e);
    std::sort(links.begin(), links.end());
    links.erase(std::unique(links.begin(), links.end()), links.end());
}

/**
 * Edge e of triangle t, when its neighbour there lies on another chart: texels along the edge,
 * one side's to the other's, sampled at half a texel along the edge and half a texel inside each
 * triangle.
 */
void TextureColorFill::linkEdge(std::uint32_t t, int e) {
    const std::uint32_t n = topology.edgeNeighbors[t][std::size_t(e)];
    if (n == kNone || n <= t || n >= mesh.triangleCount())
        return;
    const std::uint32_t wa = topology.corners[t][std::size_t(e)];
    const std::uint32_t wb = topology.corners[t][std::size_t((e + 1) % 3)];
    int ka = -1, kb = -1;
    for (int k = 0; k < 3; ++k) {
        if (topology.corners[n][std::size_t(k)] == wa && ka < 0)
            ka = k;
        else if (topology.corners[n][std::size_t(k)] == wb && kb < 0)
            kb = k;
    }
    if (ka < 0 || kb < 0)
        return;
    const std::uint32_t pt = target.trianglePage(t), pn = target.trianglePage(n);
    const glm::dvec2 at = texelPosition(t, e), bt = texelPosition(t, (e + 1) % 3),
                     ct = texelPosition(t, (e + 2) % 3);
    const glm::dvec2 an = texelPosition(n, ka), bn = texelPosition(n, kb),
                     cn = texelPosition(n, 3 - ka - kb);
    if (pt == pn && glm::length(at - an) < 1e-3 && glm::length(bt - bn) < 1e-3)
        return; // one chart: its texels are neighbours already
    const double length = std::max(glm::length(bt - at), glm::length(bn - an));
    if (!std::isfinite(length) || length > kMaxTexel)
        return;
    const int samples = std::clamp(int(std::ceil(2.0 * length)) + 1, 1, 8192);
    const auto inside = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, double s) {
        glm::dvec2 q = a + s * (b - a);
        const glm::dvec2 toCentre = (a + b + c) / 3.0 - q;
        const double d = glm::length(toCentre);
        if (d > 0.0)
            q += toCentre * std::min(0.5 / d, 1.0);
        return q;
    };
    for (int k = 0; k < samples; ++k) {
        const double s = (double(k) + 0.5) / double(samples);
        const std::uint32_t from = texelNear(t, pt, inside(at, bt, ct, s));
        const std::uint32_t to = texelNear(n, pn, inside(an, bn, cn, s));
        if (from == kNone || to == kNone)
            continue;
        links.emplace_back(node(pt, from), node(pn, to));
        links.emplace_back(node(pn, to), node(pt, from));
    }
}

/**
 * The texels of similar colour connected to the seed texel: breadth first over the 4 neighbours
 * of a page between adjacent triangles' texels and over the seams' links.
 */
std::vector<PaintElement> TextureColorFill::spread(std::uint32_t seedPage, std::uint32_t seedTexel,
                                                   float tolerance) {
    // Bytes are sRGB-encoded already: compare them as integers (|difference| / 255 within
    // the tolerance, as similar() would).
    const int limit = int(std::floor(tolerance * 255.0f + 255.0f * 1e-6f));
    const std::uint8_t* seedBytes = &target.page(seedPage).rgba[std::size_t(seedTexel) * 4];
    const std::array<int, 4> seedColor{seedBytes[0], seedBytes[1], seedBytes[2], seedBytes[3]};
    const auto similarTexel = [&](std::uint32_t page, std::uint32_t texel) {
        const std::uint8_t* c = &target.page(page).rgba[std::size_t(texel) * 4];
        return std::abs(c[0] - seedColor[0]) <= limit && std::abs(c[1] - seedColor[1]) <= limit &&
               std::abs(c[2] - seedColor[2]) <= limit && std::abs(c[3] - seedColor[3]) <= limit;
    };
    std::vector<PaintElement> result;
    std::vector<std::uint64_t> queue{node(seedPage, seedTexel)};
    pages[seedPage].visited[seedTexel] = 1;
    static constexpr int kSteps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::uint64_t id = queue[head];
        const auto p = std::uint32_t(id >> 32), texel = std::uint32_t(id);
        if (!similarTexel(p, texel))
            continue;
        result.push_back({p, texel});
        Page& page = pages[p];
        const std::uint32_t owner = page.owner[texel];
        const int x = int(texel % std::uint32_t(page.width));
        const int y = int(texel / std::uint32_t(page.width));
        for (const auto& step : kSteps) {
            const std::uint32_t next =
                std::uint32_t(uv::wrapIndex(y + step[1], page.height)) * std::uint32_t(page.width) +
                std::uint32_t(uv::wrapIndex(x + step[0], page.width));
            if (page.visited[next] || page.owner[next] == kNone ||
                !adjacent(owner, page.owner[next]))
                continue;
            page.visited[next] = 1;
            queue.push_back(node(p, next));
        }
        const auto range = std::equal_range(
            links.begin(), links.end(), std::pair<std::uint64_t, std::uint64_t>(id, 0),
            [](const auto& a, const auto& b) { return a.first < b.first; });
        for (auto it = range.first; it != range.second; ++it) {
            const auto np = std::uint32_t(it->second >> 32), nt = std::uint32_t(it->second);
            if (pages[np].visited[nt])
                continue;
            pages[np].visited[nt] = 1;
            queue.push_back(it->second);
        }
    }
    return result;
}

std::vector<PaintElement> textureColorFill(const TextureTarget& target,
                                           const MeshTopology& topology, std::uint32_t seed,
                                           glm::vec3 barycentric, float tolerance) {
    TextureColorFill fill(target, topology, seed);
    fill.markOwners();
    const std::uint32_t seedPage = target.trianglePage(seed);
    glm::dvec2 seedPosition(0.0);
    for (int c = 0; c < 3; ++c)
        seedPosition += double(barycentric[c]) * fill.texelPosition(seed, c);
    const std::uint32_t seedTexel = fill.texelNear(seed, seedPage, seedPosition);
    if (seedTexel == kNone)
        return {};
    fill.linkSeams();
    return fill.spread(seedPage, seedTexel, tolerance);
}

std::vector<PaintElement> vertexColorFill(const VertexColorTarget& target,
                                          const MeshTopology& topology, std::uint32_t seed,
                                          glm::vec3 barycentric, float tolerance) {
    const Mesh& mesh = target.mesh();
    const std::size_t vertices = mesh.vertexCount();
    const std::vector<std::uint32_t> triangles = componentTriangles(topology, seed);
    // Neighbours along triangle edges, as compressed rows.
    std::vector<std::uint32_t> offsets(vertices + 1, 0u);
    for (const std::uint32_t t : triangles)
        for (int c = 0; c < 3; ++c)
            offsets[vertexOf(mesh, t, c) + 1] += 2;
    for (std::size_t v = 0; v < vertices; ++v)
        offsets[v + 1] += offsets[v];
    std::vector<std::uint32_t> neighbors(offsets[vertices]);
    {
        std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
        for (const std::uint32_t t : triangles) {
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t v = vertexOf(mesh, t, c);
                neighbors[fill[v]++] = vertexOf(mesh, t, (c + 1) % 3);
                neighbors[fill[v]++] = vertexOf(mesh, t, (c + 2) % 3);
            }
        }
    }
    // Welded duplicates (seams, hard edges): the same surface point.
    const bool welded = topology.weldedVertex.size() == vertices;
    std::vector<std::uint32_t> weldOffsets, weldMembers;
    if (welded) {
        weldOffsets.assign(std::size_t(topology.weldedVertexCount) + 1, 0u);
        for (std::size_t v = 0; v < vertices; ++v)
            if (topology.weldedVertex[v] < topology.weldedVertexCount)
                ++weldOffsets[topology.weldedVertex[v] + 1];
        for (std::size_t w = 0; w < topology.weldedVertexCount; ++w)
            weldOffsets[w + 1] += weldOffsets[w];
        weldMembers.resize(weldOffsets.back());
        std::vector<std::uint32_t> fill(weldOffsets.begin(), weldOffsets.end() - 1);
        for (std::size_t v = 0; v < vertices; ++v)
            if (topology.weldedVertex[v] < topology.weldedVertexCount)
                weldMembers[fill[topology.weldedVertex[v]]++] = std::uint32_t(v);
    }

    int corner = 0;
    for (int c = 1; c < 3; ++c)
        if (barycentric[c] > barycentric[corner])
            corner = c;
    const std::uint32_t start = vertexOf(mesh, seed, corner);
    const std::vector<glm::vec4>& colors = target.colors();
    const glm::vec4 seedColor = encodedColor(colors[start]);
    std::vector<std::uint8_t> visited(vertices, 0u);
    std::vector<std::uint32_t> queue{start};
    visited[start] = 1;
    std::vector<PaintElement> result;
    const auto visit = [&](std::uint32_t v) {
        // Only vertices of the component's triangles (a welded duplicate may be unused).
        if (!visited[v] && offsets[v + 1] > offsets[v]) {
            visited[v] = 1;
            queue.push_back(v);
        }
    };
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const std::uint32_t v = queue[head];
        if (!similar(encodedColor(colors[v]), seedColor, tolerance))
            continue;
        result.push_back({0u, v});
        for (std::uint32_t i = offsets[v]; i < offsets[v + 1]; ++i)
            visit(neighbors[i]);
        if (welded && topology.weldedVertex[v] < topology.weldedVertexCount) {
            const std::uint32_t w = topology.weldedVertex[v];
            for (std::uint32_t i = weldOffsets[w]; i < weldOffsets[w + 1]; ++i)
                visit(weldMembers[i]);
        }
    }
    return result;
}

} // namespace

Dab regionFillDab(const DepthLayers& layers, std::uint32_t region, float opacity) {
    Dab dab;
    dab.opacity = opacity;
    const DepthStack& stack = layers.stack;
    const std::vector<Region>& regions = layers.segmentation.graph.regions;
    if (region >= regions.size() || layers.segmentation.region.size() != stack.fragmentCount())
        return dab;
    const Region& r = regions[region];
    const int x0 = std::max(r.minX, 0), y0 = std::max(r.minY, 0);
    const int x1 = std::min(r.maxX, stack.width - 1), y1 = std::min(r.maxY, stack.height - 1);
    if (x0 > x1 || y0 > y1)
        return dab;
    dab.layer = r.layer;
    dab.center = {0.5f * float(x0 + x1 + 1), 0.5f * float(y0 + y1 + 1)};
    // Every surface point seen in the region's pixels, or one pixel beyond, is within half the
    // (grown) diagonal of the centre.
    dab.radius = 0.5f * std::hypot(float(x1 - x0 + 3), float(y1 - y0 + 3)) + 2.0f;
    const auto add = [&](std::size_t pixel, std::uint32_t fragment) {
        const glm::vec2 centre(float(pixel % std::size_t(stack.width)) + 0.5f,
                               float(pixel / std::size_t(stack.width)) + 0.5f);
        dab.paintable.push_back({std::uint32_t(pixel), fragment, glm::length(centre - dab.center)});
    };
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const std::size_t pixel = std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
            const std::uint32_t f = stack.fragment(pixel, r.layer);
            if (f != kNone && layers.segmentation.region[f] == region)
                add(pixel, f);
        }
    }
    // The rim: where the region's surface ends (its fragment links to nothing on that side),
    // the pixel beyond is mapped to it too, so the sliver of surface between the last pixel
    // centres and its edge is filled (projection tests that a point lies on the fragment's
    // plane, so nothing behind is). Where it continues on another layer (a region boundary
    // across layers) nothing is added: that is the neighbouring region's.
    const Connectivity& links = layers.connectivity;
    if (links.links.size() != 4 * stack.fragmentCount())
        return dab;
    static constexpr int kSteps[4][2] = {{1, 0}, {-1, 0}, {0, -1}, {0, 1}}; // Direction order
    std::vector<std::uint8_t> claimed(stack.pixelCount(), 0u);
    for (const MapPixel& m : dab.paintable)
        claimed[m.pixel] = 1;
    const std::size_t inside = dab.paintable.size();
    for (std::size_t i = 0; i < inside; ++i) {
        const MapPixel m = dab.paintable[i];
        const int x = int(m.pixel % std::uint32_t(stack.width));
        const int y = int(m.pixel / std::uint32_t(stack.width));
        const auto extend = [&](int nx, int ny) {
            if (nx < 0 || ny < 0 || nx >= stack.width || ny >= stack.height)
                return;
            const std::size_t next = std::size_t(ny) * std::size_t(stack.width) + std::size_t(nx);
            if (!claimed[next]) {
                claimed[next] = 1;
                add(next, m.fragment);
            }
        };
        bool open[4];
        for (int d = 0; d < 4; ++d) {
            open[d] = links.link(m.fragment, d) == 0;
            if (open[d])
                extend(x + kSteps[d][0], y + kSteps[d][1]);
        }
        // A corner: the diagonal pixel beyond both open sides.
        for (const int h : {kRight, kLeft})
            for (const int v : {kUp, kDown})
                if (open[h] && open[v])
                    extend(x + kSteps[h][0], y + kSteps[v][1]);
    }
    return dab;
}

std::vector<std::uint32_t> componentTriangles(const MeshTopology& topology,
                                              std::uint32_t triangle) {
    if (triangle >= topology.triangleCount() ||
        topology.component.size() != topology.triangleCount())
        return {triangle};
    std::vector<std::uint32_t> result;
    const std::uint32_t component = topology.component[triangle];
    for (std::size_t t = 0; t < topology.component.size(); ++t)
        if (topology.component[t] == component)
            result.push_back(std::uint32_t(t));
    return result;
}

std::vector<PaintElement> triangleElements(const PaintTarget& target,
                                           std::span<const std::uint32_t> triangles) {
    const Mesh& mesh = target.mesh();
    std::vector<PaintElement> result;
    if (const auto* texture = dynamic_cast<const TextureTarget*>(&target)) {
        std::vector<std::vector<std::uint8_t>> marks(texture->pageCount());
        for (const std::uint32_t t : triangles) {
            if (t >= mesh.triangleCount())
                continue;
            const std::uint32_t p = texture->trianglePage(t);
            const Image& page = texture->page(p);
            std::vector<std::uint8_t>& mark = marks[p];
            if (mark.empty())
                mark.assign(std::size_t(page.width) * std::size_t(page.height), 0u);
            uv::UvTriangle r;
            if (!pageTriangle(mesh, t, page.width, page.height, r))
                continue;
            forEachTexel(r, page.width, page.height, [&](std::uint32_t i) {
                if (!mark[i]) {
                    mark[i] = 1;
                    result.push_back({p, i});
                }
            });
        }
    } else {
        std::vector<std::uint8_t> mark(mesh.vertexCount(), 0u);
        for (const std::uint32_t t : triangles) {
            if (t >= mesh.triangleCount())
                continue;
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t v = vertexOf(mesh, t, c);
                if (!mark[v]) {
                    mark[v] = 1;
                    result.push_back({0u, v});
                }
            }
        }
    }
    return result;
}

std::vector<PaintElement> similarColorElements(const PaintTarget& target,
                                               const MeshTopology& topology, std::uint32_t triangle,
                                               glm::vec3 barycentric, float tolerance) {
    if (triangle >= target.mesh().triangleCount())
        return {};
    const float t = std::isfinite(tolerance) ? std::clamp(tolerance, 0.0f, 1.0f) : 0.0f;
    if (const auto* texture = dynamic_cast<const TextureTarget*>(&target))
        return textureColorFill(*texture, topology, triangle, barycentric, t);
    if (const auto* colors = dynamic_cast<const VertexColorTarget*>(&target))
        return vertexColorFill(*colors, topology, triangle, barycentric, t);
    return {};
}

} // namespace core
