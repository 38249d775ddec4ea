// SPDX-License-Identifier: GPL-3.0-or-later
// Flattening one chart of the automatic UV layout: least-squares conformal maps (Lévy et al.
// 2002) with two pinned vertices, solved as sparse normal equations; planar charts are projected.
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <glm/geometric.hpp>

#include "core/model/uv_layout_internal.h"
#include "core/paint/targets/uv_raster.h"

namespace core::uvl {

namespace {

/** Charts filling less than this share of their smallest box, over kCrookedMinTexels, split. */
constexpr double kCrookedFill = 0.55;
constexpr double kCrookedMinTexels = 48.0 * 48.0;

double signedArea(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

/** The convex hull of points, counter-clockwise (Andrew's monotone chain). */
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> p) {
    std::sort(p.begin(), p.end(), [](const glm::dvec2& a, const glm::dvec2& b) {
        return a.x != b.x ? a.x < b.x : a.y < b.y;
    });
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3)
        return p;
    std::vector<glm::dvec2> hull(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && signedArea(hull[k - 2], hull[k - 1], p[i]) <= 0.0)
            --k;
        hull[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && signedArea(hull[k - 2], hull[k - 1], p[i]) <= 0.0)
            --k;
        hull[k++] = p[i];
    }
    hull.resize(k - 1);
    return hull;
}

/**
 * Turns a chart's uvs so the smallest rectangle around them is axis-aligned (one side of it lies
 * on a side of the convex hull), and returns that rectangle's area. Masks of rectangular and
 * long charts then have no empty corners, and the packer's quarter turns cover the rest.
 */
double alignToSmallestBox(std::vector<glm::dvec2>& uv) {
    const std::vector<glm::dvec2> hull = convexHull(uv);
    double bestArea = std::numeric_limits<double>::infinity();
    glm::dvec2 bestAxis(1.0, 0.0);
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const glm::dvec2 e = hull[(i + 1) % hull.size()] - hull[i];
        const double len = glm::length(e);
        if (!(len > 0.0))
            continue;
        const glm::dvec2 a = e / len, b(-a.y, a.x);
        double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
        for (const glm::dvec2& q : hull) {
            const double s[2] = {glm::dot(q, a), glm::dot(q, b)};
            for (int k = 0; k < 2; ++k) {
                lo[k] = std::min(lo[k], s[k]);
                hi[k] = std::max(hi[k], s[k]);
            }
        }
        const double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
        if (area < bestArea * (1.0 - 1e-9)) {
            bestArea = area;
            bestAxis = a;
        }
    }
    if (std::isinf(bestArea))
        return 0.0;
    glm::dvec2 lo(1e300);
    for (glm::dvec2& q : uv) {
        q = {glm::dot(q, bestAxis), bestAxis.x * q.y - bestAxis.y * q.x};
        lo = glm::min(lo, q);
    }
    for (glm::dvec2& q : uv)
        q -= lo;
    return bestArea;
}

/** A unit vector perpendicular to n. */
glm::dvec3 perpendicular(const glm::dvec3& n) {
    const glm::dvec3 a = std::fabs(n.x) < 0.6   ? glm::dvec3(1, 0, 0)
                         : std::fabs(n.y) < 0.6 ? glm::dvec3(0, 1, 0)
                                                : glm::dvec3(0, 0, 1);
    return glm::normalize(glm::cross(n, a));
}

/** A local vertex of a chart that lies on the side from local vertex a to b, at s of its length. */
struct OnSide {
    std::uint32_t vertex, a, b;
    double s;
    auto operator<=>(const OnSide&) const = default;
};

/**
 * The chart's T-junctions: corners of its triangles lying inside a side of another of its
 * triangles that they touch along a contact. localOf maps welded vertices to local ones.
 */
template <typename LocalOf>
std::vector<OnSide> tJunctions(const Surface& surface, const Chart& chart, LocalOf localOf) {
    std::vector<OnSide> found;
    for (std::uint32_t t : chart.triangles)
        for (std::uint32_t e = 0; e < 3; ++e) {
            const std::uint32_t side = 3 * t + e;
            const std::uint32_t a = surface.cornerOfSide(side, 0),
                                b = surface.cornerOfSide(side, 1);
            const glm::dvec3 p = surface.position[a], d = surface.position[b] - p;
            const double lengthSquared = glm::dot(d, d);
            for (const std::uint32_t other : surface.contactsOf(side)) {
                if (!std::binary_search(chart.triangles.begin(), chart.triangles.end(), other / 3))
                    continue;
                for (int end = 0; end < 2; ++end) {
                    const std::uint32_t v = surface.cornerOfSide(other, end);
                    const double s = glm::dot(surface.position[v] - p, d) / lengthSquared;
                    if (v != a && v != b && s > 1e-9 && s < 1.0 - 1e-9)
                        found.push_back({localOf(v), localOf(a), localOf(b), s});
                }
            }
        }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
}

/** Puts each T-junction's vertex onto its side in uv, so the chart has no gap there. */
void closeTJunctions(Chart& chart, const std::vector<OnSide>& junctions) {
    for (int pass = 0; pass < 2; ++pass) // a second pass for sides whose ends moved
        for (const OnSide& j : junctions)
            chart.uv[j.vertex] = chart.uv[j.a] + (chart.uv[j.b] - chart.uv[j.a]) * j.s;
}

/**
 * Least-squares conformal map with vertices pinA and pinB held at their given uv; each
 * T-junction's vertex is held near its place on its side by a heavily weighted row.
 */
bool solveLscm(const Surface& surface, Chart& chart, std::uint32_t pinA, std::uint32_t pinB,
               const std::vector<OnSide>& junctions) {
    const std::size_t n = chart.vertices.size();
    std::vector<int> freeIndex(n, -1);
    int freeCount = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (i != pinA && i != pinB)
            freeIndex[i] = freeCount++;
    using Triplet = Eigen::Triplet<double>;
    std::vector<Triplet> triplets;
    triplets.reserve(chart.triangles.size() * 12);
    Eigen::VectorXd rhs =
        Eigen::VectorXd::Zero(Eigen::Index(2 * (chart.triangles.size() + junctions.size())));
    int row = 0;
    for (std::size_t k = 0; k < chart.triangles.size(); ++k) {
        const std::uint32_t t = chart.triangles[k];
        if (surface.degenerate(t))
            continue;
        const std::array<std::uint32_t, 3>& c = chart.local[k];
        const glm::dvec3 p0 = surface.position[chart.vertices[c[0]]];
        const glm::dvec3 p1 = surface.position[chart.vertices[c[1]]];
        const glm::dvec3 p2 = surface.position[chart.vertices[c[2]]];
        // The triangle in its own plane, counter-clockwise seen from its normal.
        const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
        const double l1 = glm::length(e1);
        if (!(l1 > 0.0))
            continue;
        const glm::dvec3 x = e1 / l1;
        const glm::dvec3 y = glm::normalize(glm::cross(surface.normal[t], x));
        const std::complex<double> z[3] = {
            {0.0, 0.0}, {l1, 0.0}, {glm::dot(e2, x), glm::dot(e2, y)}};
        const double twiceArea = l1 * z[2].imag();
        if (!(twiceArea > 0.0))
            continue;
        const double weight = 1.0 / std::sqrt(twiceArea);
        // Conformal (holomorphic) maps zero Σ_j (z_{j+2} − z_{j+1}) · U_j.
        for (int j = 0; j < 3; ++j) {
            const std::complex<double> w = (z[(j + 2) % 3] - z[(j + 1) % 3]) * weight;
            const std::uint32_t v = c[std::size_t(j)];
            if (freeIndex[v] >= 0) {
                const int col = 2 * freeIndex[v];
                triplets.emplace_back(row, col, w.real());
                triplets.emplace_back(row, col + 1, -w.imag());
                triplets.emplace_back(row + 1, col, w.imag());
                triplets.emplace_back(row + 1, col + 1, w.real());
            } else {
                const glm::dvec2 u = chart.uv[v];
                rhs[row] -= w.real() * u.x - w.imag() * u.y;
                rhs[row + 1] -= w.imag() * u.x + w.real() * u.y;
            }
        }
        row += 2;
    }
    // vertex − (1 − s) a − s b = 0, in u and in v; the conformal rows are lengths of about the
    // same size, so the weight makes a gap cost far more than a little angle distortion.
    constexpr double kJunctionWeight = 32.0;
    for (const OnSide& j : junctions) {
        const std::pair<std::uint32_t, double> terms[3] = {{j.vertex, kJunctionWeight},
                                                           {j.a, -kJunctionWeight * (1.0 - j.s)},
                                                           {j.b, -kJunctionWeight * j.s}};
        for (const auto& [v, w] : terms) {
            if (freeIndex[v] >= 0) {
                triplets.emplace_back(row, 2 * freeIndex[v], w);
                triplets.emplace_back(row + 1, 2 * freeIndex[v] + 1, w);
            } else {
                rhs[row] -= w * chart.uv[v].x;
                rhs[row + 1] -= w * chart.uv[v].y;
            }
        }
        row += 2;
    }
    if (freeCount == 0)
        return true;
    Eigen::SparseMatrix<double> a(row, 2 * freeCount);
    a.setFromTriplets(triplets.begin(), triplets.end());
    triplets = {};
    const Eigen::SparseMatrix<double> at = a.transpose();
    const Eigen::SparseMatrix<double> normal = at * a;
    const Eigen::VectorXd atb = at * rhs.head(row);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    solver.compute(normal);
    if (solver.info() != Eigen::Success)
        return false;
    const Eigen::VectorXd solution = solver.solve(atb);
    if (solver.info() != Eigen::Success || !solution.allFinite())
        return false;
    for (std::size_t i = 0; i < n; ++i)
        if (freeIndex[i] >= 0)
            chart.uv[i] = {solution[2 * freeIndex[i]], solution[2 * freeIndex[i] + 1]};
    return true;
}

/** The area of triangle a's part inside triangle b (both counter-clockwise). */
double sharedArea(const std::array<glm::dvec2, 3>& a, const std::array<glm::dvec2, 3>& b) {
    // Sutherland–Hodgman: a clipped by each of b's sides in turn.
    std::array<glm::dvec2, 9> poly{}, next{};
    int count = 3;
    std::copy(a.begin(), a.end(), poly.begin());
    for (int e = 0; e < 3 && count > 0; ++e) {
        const glm::dvec2 p = b[std::size_t(e)], q = b[std::size_t((e + 1) % 3)];
        const auto inside = [&](const glm::dvec2& x) {
            return (q.x - p.x) * (x.y - p.y) - (q.y - p.y) * (x.x - p.x);
        };
        int out = 0;
        for (int i = 0; i < count; ++i) {
            const glm::dvec2 u = poly[std::size_t(i)], v = poly[std::size_t((i + 1) % count)];
            const double du = inside(u), dv = inside(v);
            if (du >= 0.0)
                next[std::size_t(out++)] = u;
            if ((du >= 0.0) != (dv >= 0.0) && out < 9)
                next[std::size_t(out++)] = u + (v - u) * (du / (du - dv));
        }
        count = std::min(out, 9);
        poly = next;
    }
    double area = 0.0;
    for (int i = 0; i < count; ++i) {
        const glm::dvec2 u = poly[std::size_t(i)], v = poly[std::size_t((i + 1) % count)];
        area += u.x * v.y - u.y * v.x;
    }
    return 0.5 * area;
}

/**
 * True when two triangles of the chart overlap in uv by more than rounding: however thin the
 * overlap, some density could put a texel centre in it. Candidates are the pairs whose boxes
 * share a cell of a grid about twice as fine as the triangles.
 */
bool overlapsItself(const Chart& chart) {
    const std::size_t n = chart.local.size();
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const glm::dvec2& p : chart.uv) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
    if (!(extent > 0.0) || n < 2)
        return false;
    std::vector<std::array<glm::dvec2, 3>> tri(n);
    double total = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        for (int c = 0; c < 3; ++c)
            tri[k][std::size_t(c)] = chart.uv[chart.local[k][std::size_t(c)]];
        total += std::max(signedArea(tri[k][0], tri[k][1], tri[k][2]), 0.0);
    }
    const double cell = std::max(std::sqrt(total / double(n)), extent / 1024.0);
    const int cells = int(std::ceil(extent / cell)) + 1;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> entries; // (cell, triangle)
    for (std::uint32_t k = 0; k < n; ++k) {
        const glm::dvec2 a = glm::min(tri[k][0], glm::min(tri[k][1], tri[k][2])) - lo;
        const glm::dvec2 b = glm::max(tri[k][0], glm::max(tri[k][1], tri[k][2])) - lo;
        const int x0 = std::clamp(int(a.x / cell), 0, cells - 1);
        const int x1 = std::clamp(int(b.x / cell), 0, cells - 1);
        const int y0 = std::clamp(int(a.y / cell), 0, cells - 1);
        const int y1 = std::clamp(int(b.y / cell), 0, cells - 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                entries.emplace_back(std::uint32_t(y * cells + x), k);
    }
    for (const auto& [i, j] : pairsSharingACell(entries)) {
        const double smaller = std::min(signedArea(tri[i][0], tri[i][1], tri[i][2]),
                                        signedArea(tri[j][0], tri[j][1], tri[j][2]));
        if (sharedArea(tri[i], tri[j]) > 1e-9 * smaller + 1e-18 * extent * extent)
            return true;
    }
    return false;
}

/** The local index of welded vertex v in chart.vertices (sorted). */
std::uint32_t localVertex(const Chart& chart, std::uint32_t v) {
    return std::uint32_t(std::lower_bound(chart.vertices.begin(), chart.vertices.end(), v) -
                         chart.vertices.begin());
}

/**
 * The chart's vertices (its triangles' welded corners, ascending), each triangle's corners as
 * local indices and its 3D area; returns the area-weighted normal sum.
 */
glm::dvec3 indexChartVertices(const Surface& surface, Chart& chart) {
    const MeshTopology& topo = *surface.topology;
    chart.vertices.clear();
    for (std::uint32_t t : chart.triangles)
        for (std::uint32_t v : topo.corners[t])
            chart.vertices.push_back(v);
    std::sort(chart.vertices.begin(), chart.vertices.end());
    chart.vertices.erase(std::unique(chart.vertices.begin(), chart.vertices.end()),
                         chart.vertices.end());
    chart.local.resize(chart.triangles.size());
    chart.area = 0.0;
    glm::dvec3 normalSum(0.0);
    for (std::size_t k = 0; k < chart.triangles.size(); ++k) {
        const std::uint32_t t = chart.triangles[k];
        for (int c = 0; c < 3; ++c)
            chart.local[k][std::size_t(c)] = localVertex(chart, topo.corners[t][std::size_t(c)]);
        if (!surface.degenerate(t)) {
            chart.area += surface.area[t];
            normalSum += surface.normal[t] * surface.area[t];
        }
    }
    return normalSum;
}

/** The chart's vertices projected onto the plane through its first one across mean. */
void projectOntoPlane(const Surface& surface, const glm::dvec3& mean, Chart& chart) {
    const glm::dvec3 axisU = perpendicular(mean);
    const glm::dvec3 axisV = glm::cross(mean, axisU);
    const glm::dvec3 origin = surface.position[chart.vertices[0]];
    for (std::size_t i = 0; i < chart.vertices.size(); ++i) {
        const glm::dvec3 d = surface.position[chart.vertices[i]] - origin;
        chart.uv[i] = {glm::dot(d, axisU), glm::dot(d, axisV)};
    }
}

bool isPlanarChart(const Surface& surface, const Chart& chart, const glm::dvec3& mean) {
    bool planar = true;
    for (std::uint32_t t : chart.triangles)
        if (!surface.degenerate(t) && glm::dot(surface.normal[t], mean) < 1.0 - 1e-9)
            planar = false;
    return planar;
}

/**
 * The conformal map pinned at the projection's two extreme vertices along its longer side; the
 * projection stays when they coincide or the solve fails.
 */
void mapConformally(const Surface& surface, Chart& chart, const std::vector<OnSide>& junctions) {
    glm::dvec2 lo(1e300), hi(-1e300);
    std::uint32_t lowest[2] = {0, 0}, highest[2] = {0, 0};
    for (std::uint32_t i = 0; i < std::uint32_t(chart.uv.size()); ++i)
        for (int a = 0; a < 2; ++a) {
            if (chart.uv[i][a] < lo[a]) {
                lo[a] = chart.uv[i][a];
                lowest[a] = i;
            }
            if (chart.uv[i][a] > hi[a]) {
                hi[a] = chart.uv[i][a];
                highest[a] = i;
            }
        }
    const int axis = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;
    if (lowest[axis] != highest[axis]) {
        const std::vector<glm::dvec2> projected = chart.uv;
        if (!solveLscm(surface, chart, lowest[axis], highest[axis], junctions))
            chart.uv = projected;
    }
}

/**
 * The uv turned over if mirrored, scaled so its area is the chart's 3D area and moved to start
 * at 0; false when it has no area (or none that is finite).
 */
bool scaleToChartArea(Chart& chart) {
    double uvArea = 0.0;
    for (const auto& c : chart.local)
        uvArea += signedArea(chart.uv[c[0]], chart.uv[c[1]], chart.uv[c[2]]);
    if (uvArea < 0.0) { // mirrored: turn it over
        for (glm::dvec2& p : chart.uv)
            p.x = -p.x;
        uvArea = -uvArea;
    }
    if (!(uvArea > 0.0) || !std::isfinite(uvArea))
        return false;
    const double scale = std::sqrt(chart.area / uvArea);
    glm::dvec2 lo(1e300);
    for (glm::dvec2& p : chart.uv) {
        p *= scale;
        lo = glm::min(lo, p);
    }
    for (glm::dvec2& p : chart.uv)
        p -= lo;
    return true;
}

/** Flipped if a triangle is turned over or crushed; Stretched if over 5% of the area is
 *  stretched beyond maxStretch; else Good. */
FlattenOutcome measureStretch(const Surface& surface, const Chart& chart, double maxStretch) {
    double stretchedArea = 0.0;
    for (std::size_t k = 0; k < chart.local.size(); ++k) {
        const std::uint32_t t = chart.triangles[k];
        if (surface.degenerate(t))
            continue;
        const auto& c = chart.local[k];
        const double r =
            signedArea(chart.uv[c[0]], chart.uv[c[1]], chart.uv[c[2]]) / surface.area[t];
        if (!(r > 1e-4))
            return FlattenOutcome::Flipped;
        if (std::max(r, 1.0 / r) > maxStretch)
            stretchedArea += surface.area[t];
    }
    if (chart.triangles.size() > 1 && stretchedArea > 0.05 * chart.area)
        return FlattenOutcome::Stretched;
    return FlattenOutcome::Good;
}

} // namespace

FlattenOutcome flattenChart(const Surface& surface, Chart& chart, double maxStretch,
                            double density) {
    const glm::dvec3 normalSum = indexChartVertices(surface, chart);
    chart.uv.assign(chart.vertices.size(), glm::dvec2(0.0));
    if (!(glm::length(normalSum) > 0.0))
        return FlattenOutcome::Good; // no area: a point

    // Projection onto the plane of the mean normal: the result for planar charts, the pins'
    // places otherwise.
    const glm::dvec3 mean = glm::normalize(normalSum);
    projectOntoPlane(surface, mean, chart);
    const std::vector<OnSide> junctions =
        tJunctions(surface, chart, [&](std::uint32_t v) { return localVertex(chart, v); });
    if (!isPlanarChart(surface, chart, mean))
        mapConformally(surface, chart, junctions);
    closeTJunctions(chart, junctions);

    if (!scaleToChartArea(chart))
        return FlattenOutcome::Flipped;
    if (const FlattenOutcome stretch = measureStretch(surface, chart, maxStretch);
        stretch != FlattenOutcome::Good)
        return stretch;
    // Turned first, so the overlap test sees the chart as it will be packed.
    const double box = alignToSmallestBox(chart.uv);
    if (chart.triangles.size() > 1 && overlapsItself(chart))
        return FlattenOutcome::Overlapping;
    // A chart filling little of its smallest box (an L, a C, a zig-zag strip) leaves room that
    // others rarely fill: split it where it is large enough for the room to matter.
    if (chart.triangles.size() > 1 && box * density * density > kCrookedMinTexels &&
        chart.area < kCrookedFill * box)
        return FlattenOutcome::Crooked;
    return FlattenOutcome::Good;
}

} // namespace core::uvl
