// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/depth/surface_geometry.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "core/base/parallel.h"

namespace core {

namespace {

/**
 * A view with fewer fragments than 1/kSparseView of the mesh's triangles finds its triangles'
 * entries through a table the size of the fragments, not a word per mesh triangle.
 */
constexpr std::size_t kSparseView = 8;

/** Where triangle id's search starts in an entry table (a power of two of slots). */
template <typename Table> std::size_t homeSlot(const Table& table, std::uint32_t id) {
    return std::size_t((std::uint64_t(id) * 0x9E3779B97F4A7C15ull) >>
                       (64 - std::countr_zero(table.size())));
}

/**
 * The slot of triangle id in an entry table (a power of two of slots, never full): the one that
 * holds id, else the free one where it would go.
 */
template <typename Table> auto& slotOf(Table& table, std::uint32_t id) {
    const std::size_t mask = table.size() - 1;
    std::size_t i = homeSlot(table, id);
    while (table[i].id != id && table[i].id != kNone)
        i = (i + 1) & mask;
    return table[i];
}

/** How a view carries the mesh's triangle planes into its view space. */
struct PlaneMapping {
    glm::dmat4 planeToView{1.0};
    /** The view scales uniformly: mapped unit normals stay unit, no plane is normalized. */
    bool uniform = false;
};

PlaneMapping planeMappingOf(const View& view) {
    // A plane (n, w) of the mesh's space is (n, w) times the inverse view matrix in view space;
    // the sign of the determinant keeps the normal on the side the winding gives after a mirror.
    const glm::dmat4 toView(view.view);
    const glm::dmat3 linear(toView);
    const double side = glm::determinant(linear) < 0.0 ? -1.0 : 1.0;
    PlaneMapping mapping;
    mapping.planeToView = glm::transpose(glm::inverse(toView)) * side;
    // A rotation and uniform scale (any camera's view, to a few float roundings) keeps unit
    // normals unit once scaled back: then no plane needs its own normalization.
    const glm::dmat3 gram = glm::transpose(linear) * linear;
    const double scale2 = gram[0][0];
    bool uniform = scale2 > 0.0 && std::isfinite(scale2);
    for (int i = 0; i < 3 && uniform; ++i)
        for (int j = 0; j < 3; ++j)
            uniform = uniform && std::abs(gram[i][j] - (i == j ? scale2 : 0.0)) <= 4e-6 * scale2;
    if (uniform)
        mapping.planeToView *= std::sqrt(scale2);
    mapping.uniform = uniform;
    return mapping;
}

/** The scratch of one makeSurfaceGeometry() call: the mesh, its topology and the mapping. */
struct SurfaceBuild {
    const Mesh& mesh;
    const MeshTopology& topology;
    std::size_t count = 0; // the mesh's triangles
    bool haveTopology = false;
    bool havePlanes = false;
    PlaneMapping mapping;

    /** Triangle t's plane in view space, corners and component. */
    void computePlane(std::size_t t, SurfaceTriangle& tri) const {
        if (haveTopology) {
            tri.corners = topology.corners[t];
            tri.component = topology.component[t];
        }
        const glm::vec4 own = havePlanes ? topology.planes[t] : trianglePlane(mesh, t);
        const glm::dvec4 plane = mapping.planeToView * glm::dvec4(own);
        if (mapping.uniform) {
            tri.plane = glm::vec4(plane);
            return;
        }
        const double length = glm::length(glm::dvec3(plane));
        if (length > 0.0 && std::isfinite(length))
            tri.plane = glm::vec4(plane * (1.0 / length));
    }
};

/** Every triangle, by id: independent per triangle, split over threads (on every view change). */
void computeAllPlanes(const SurfaceBuild& build, SurfaceGeometry& geometry) {
    geometry.triangles.resize(build.count);
    parallelRanges(int(build.count), 0, [&](int, int begin, int end) {
        for (std::size_t t = std::size_t(begin); t < std::size_t(end); ++t)
            build.computePlane(t, geometry.triangles[t]);
    });
}

/**
 * Gives each fragment its triangle's entry (fragmentEntry), numbering the triangles not met
 * before; returns the triangle ids by entry. entrySlot(t) is triangle t's entry word (kNone while
 * t is new), home(t) where its search starts. Without a branch on whether the triangle is new (on
 * the trefoil, over half of them are, in no pattern the predictor learns), and with the slots of
 * fragments ahead prefetched: a large mesh's slots are scattered over megabytes.
 */
template <typename SlotFn, typename HomeFn>
std::vector<std::uint32_t> numberFragments(const std::vector<std::uint32_t>& fragmentTriangles,
                                           std::size_t count, SurfaceGeometry& geometry,
                                           SlotFn&& entrySlot, HomeFn&& home) {
    // Room for every fragment's triangle to be new (at most the mesh's), plus the slot that
    // every fragment writes whether or not its triangle is new; cut to the triangles met.
    std::vector<std::uint32_t> ids(std::min(fragmentTriangles.size(), count + 1));
    std::uint32_t next = 0;
    for (std::size_t f = 0; f < fragmentTriangles.size(); ++f) {
        if (f + 16 < fragmentTriangles.size() && fragmentTriangles[f + 16] < count)
            __builtin_prefetch(home(fragmentTriangles[f + 16]));
        const std::uint32_t t = fragmentTriangles[f];
        std::uint32_t e = kNone;
        if (t < count) {
            std::uint32_t& slot = entrySlot(t);
            const bool fresh = slot == kNone;
            e = fresh ? next : slot;
            slot = e;
            ids[next] = t;
            next += fresh ? 1 : 0;
        }
        geometry.fragmentEntry[f] = e;
    }
    ids.resize(next);
    return ids;
}

/**
 * Numbers the triangles the view shows as the fragments first show them (the connectivity then
 * reads them nearly in order, not scattered by id): through a word per mesh triangle when the
 * view shows a good share of the mesh, else through a table the size of the fragments. Returns
 * the triangle ids by entry.
 */
std::vector<std::uint32_t> numberViewTriangles(std::size_t count, const DepthStack& stack,
                                               SurfaceGeometry& geometry) {
    const std::vector<std::uint32_t>& fragmentTriangles = stack.triangle;
    geometry.fragmentEntry.resize(fragmentTriangles.size());
    if (count <= kSparseView * fragmentTriangles.size()) {
        geometry.entry.assign(count, kNone);
        std::uint32_t* entry = geometry.entry.data();
        return numberFragments(
            fragmentTriangles, count, geometry,
            [entry](std::uint32_t t) -> std::uint32_t& { return entry[t]; },
            [entry](std::uint32_t t) { return entry + t; });
    }
    // Far more triangles than fragments: a table of twice as many slots as fragments.
    geometry.entryTable.resize(
        std::bit_ceil(std::max<std::size_t>(2 * fragmentTriangles.size(), 16)));
    std::vector<SurfaceGeometry::EntrySlot>& table = geometry.entryTable;
    return numberFragments(
        fragmentTriangles, count, geometry,
        [&table](std::uint32_t t) -> std::uint32_t& {
            SurfaceGeometry::EntrySlot& slot = slotOf(table, t);
            slot.id = t; // a new triangle's entry is still kNone
            return slot.entry;
        },
        [&table](std::uint32_t t) { return &table[homeSlot(table, t)]; });
}

/**
 * The planes of the triangles ids names, by entry, over the threads (each plane depends on its
 * triangle only). In entry order: the writes stream, and the reads follow the view's rows,
 * prefetched ahead (reading the mesh in id order instead, when most of it is in view, was slower).
 */
void computeViewPlanes(const SurfaceBuild& build, const std::vector<std::uint32_t>& ids,
                       SurfaceGeometry& geometry) {
    const MeshTopology& topology = build.topology;
    geometry.triangles.resize(ids.size());
    parallelRanges(int(ids.size()), 0, [&](int, int begin, int end) {
        for (int i = begin; i < end; ++i) {
            if (build.haveTopology && i + 16 < end) {
                const std::uint32_t ahead = ids[std::size_t(i + 16)];
                __builtin_prefetch(&topology.corners[ahead]);
                __builtin_prefetch(&topology.component[ahead]);
                if (build.havePlanes)
                    __builtin_prefetch(&topology.planes[ahead]);
            }
            build.computePlane(ids[std::size_t(i)], geometry.triangles[std::size_t(i)]);
        }
    });
}

} // namespace

std::uint32_t SurfaceGeometry::entryOf(std::uint32_t id) const {
    if (!entry.empty())
        return id < entry.size() ? entry[id] : kNone;
    if (entryTable.empty())
        return id < triangles.size() ? id : kNone;
    return slotOf(entryTable, id).entry;
}

PixelRays PixelRays::fromView(const View& view) {
    const glm::dmat4 invProj = glm::inverse(glm::dmat4(view.proj));
    // (origin, direction) of the ray through window position (px, py), parameterized by depth.
    auto rayThrough = [&](double px, double py, glm::dvec3& origin, glm::dvec3& direction) {
        const double nx = px / double(view.width) * 2.0 - 1.0;
        const double ny = 1.0 - py / double(view.height) * 2.0;
        const glm::dvec4 a = invProj * glm::dvec4(nx, ny, -1.0, 1.0);
        const glm::dvec4 b = invProj * glm::dvec4(nx, ny, 1.0, 1.0);
        const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
        direction = (pb - pa) / (pa.z - pb.z);
        origin = pa + pa.z * direction;
    };
    glm::dvec3 o0, d0, o1, d1, o2, d2;
    rayThrough(0.0, 0.0, o0, d0);
    rayThrough(1.0, 0.0, o1, d1);
    rayThrough(0.0, 1.0, o2, d2);
    PixelRays rays;
    const auto finite = [](const glm::dvec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    if (!finite(o0) || !finite(d0) || !finite(o1) || !finite(d1) || !finite(o2) || !finite(d2))
        return rays;
    rays.origin0 = glm::vec3(o0);
    rays.originDx = glm::vec3(o1 - o0);
    rays.originDy = glm::vec3(o2 - o0);
    rays.direction0 = glm::vec3(d0);
    rays.directionDx = glm::vec3(d1 - d0);
    rays.directionDy = glm::vec3(d2 - d0);
    return rays;
}

SurfaceGeometry makeSurfaceGeometry(const Mesh& mesh, const MeshTopology& topology,
                                    const View& view, const DepthStack* stack) {
    SurfaceGeometry geometry;
    geometry.rays = PixelRays::fromView(view);
    SurfaceBuild build{mesh, topology, mesh.triangleCount()};
    build.haveTopology = topology.triangleCount() == build.count;
    build.havePlanes = build.haveTopology && topology.planes.size() == build.count;
    build.mapping = planeMappingOf(view);
    if (!stack) {
        computeAllPlanes(build, geometry);
        return geometry;
    }
    // Only the triangles the view shows, numbered as the fragments first show them.
    const std::vector<std::uint32_t> ids = numberViewTriangles(build.count, *stack, geometry);
    computeViewPlanes(build, ids, geometry);
    return geometry;
}

} // namespace core
