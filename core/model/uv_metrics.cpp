// SPDX-License-Identifier: GPL-3.0-or-later
// Quality figures of an automatic UV layout, measured on the laid-out mesh itself.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <glm/geometric.hpp>

#include "core/base/parallel.h"
#include "core/model/mesh_topology.h"
#include "core/model/uv_layout.h"
#include "core/paint/targets/uv_raster.h"

namespace core {

namespace {

/** The value below which `fraction` of the total weight lies, of (value, weight) pairs. */
double weightedPercentile(std::vector<std::pair<double, double>> values, double fraction) {
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    double total = 0.0;
    for (const auto& v : values)
        total += v.second;
    double sum = 0.0;
    for (const auto& v : values) {
        sum += v.second;
        if (sum >= fraction * total)
            return v.first;
    }
    return values.back().first;
}

/** Per triangle: its 3D area and its signed UV area in texels. */
struct TriangleAreas {
    std::vector<double> area3d, areaUv;
};

TriangleAreas measureTriangleAreas(const Mesh& mesh, double res, unsigned threads) {
    const std::size_t n = mesh.triangleCount();
    TriangleAreas a;
    a.area3d.resize(n);
    a.areaUv.resize(n);
    parallelRanges(int(n), threads, [&](int, int begin, int end) {
        for (int t = begin; t < end; ++t) {
            glm::dvec3 p[3];
            glm::dvec2 q[3];
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = mesh.indices[3 * std::size_t(t) + std::size_t(k)];
                p[k] = glm::dvec3(mesh.positions[v]);
                q[k] = glm::dvec2(mesh.uvs[v]) * res;
            }
            a.area3d[std::size_t(t)] = 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
            a.areaUv[std::size_t(t)] = 0.5 * ((q[1].x - q[0].x) * (q[2].y - q[0].y) -
                                              (q[1].y - q[0].y) * (q[2].x - q[0].x));
        }
    });
    return a;
}

/**
 * Stretch (UV area share over 3D area share, either way up) and texel density spread over the
 * triangles that are not degenerate; flipped and collapsed ones counted.
 */
void measureStretchAndDensity(const TriangleAreas& a, double degenerate, UvLayoutMetrics& m) {
    const std::vector<double>&area3d = a.area3d, &areaUv = a.areaUv;
    const std::size_t n = area3d.size();
    double total3d = 0.0, totalUv = 0.0;
    for (std::size_t t = 0; t < n; ++t)
        if (area3d[t] > degenerate) {
            total3d += area3d[t];
            totalUv += std::max(areaUv[t], 0.0);
        }
    std::vector<std::pair<double, double>> stretch, density;
    stretch.reserve(n);
    density.reserve(n);
    for (std::size_t t = 0; t < n; ++t) {
        if (!(area3d[t] > degenerate))
            continue;
        if (!(areaUv[t] > 0.0)) {
            ++(areaUv[t] < 0.0 ? m.flippedTriangles : m.collapsedTriangles);
            stretch.emplace_back(std::numeric_limits<double>::infinity(), area3d[t]);
            continue;
        }
        const double r = (areaUv[t] / totalUv) / (area3d[t] / total3d);
        stretch.emplace_back(std::max(r, 1.0 / r), area3d[t]);
        density.emplace_back(std::sqrt(areaUv[t] / area3d[t]), area3d[t]);
    }
    m.stretchP95 = weightedPercentile(stretch, 0.95);
    {
        std::vector<std::pair<double, double>> counted = stretch;
        for (auto& v : counted)
            v.second = 1.0;
        m.stretchP95Triangles = weightedPercentile(std::move(counted), 0.95);
    }
    for (const auto& v : stretch)
        m.stretchMax = std::max(m.stretchMax, v.first);
    const double lowDensity = weightedPercentile(density, 0.05);
    m.texelDensitySpread = lowDensity > 0.0 ? weightedPercentile(density, 0.95) / lowDensity : 0.0;
}

/** Coverage per page with the painting's own fill rule: packing efficiency and overlaps. */
void measureCoverage(const UvLayout& layout, UvLayoutMetrics& m) {
    const Mesh& mesh = layout.mesh;
    const std::size_t n = mesh.triangleCount();
    const std::uint32_t pages = std::max(layout.pageCount, 1u);
    const std::size_t pageTexels = std::size_t(layout.resolution) * std::size_t(layout.resolution);
    std::vector<std::uint8_t> count(pageTexels * pages, 0u);
    for (std::size_t t = 0; t < n; ++t) {
        const std::uint32_t chart = t < layout.triangleChart.size() ? layout.triangleChart[t] : 0u;
        const std::uint32_t page = chart < layout.chartPage.size() ? layout.chartPage[chart] : 0u;
        if (page >= pages)
            continue;
        glm::vec2 uv[3];
        for (int k = 0; k < 3; ++k)
            uv[k] = mesh.uvs[mesh.indices[3 * t + std::size_t(k)]];
        uv::UvTriangle r;
        if (!uv::setUpUv(uv, layout.resolution, layout.resolution, r))
            continue;
        std::uint8_t* base = count.data() + pageTexels * page;
        uv::scanUv(r, std::max(r.minX, 0), std::min(r.maxX, layout.resolution - 1),
                   std::max(r.minY, 0), std::min(r.maxY, layout.resolution - 1),
                   [&](int x, int y, auto, auto, auto) {
                       std::uint8_t& c =
                           base[std::size_t(y) * std::size_t(layout.resolution) + std::size_t(x)];
                       if (c < 2)
                           ++c;
                   });
    }
    std::uint64_t covered = 0;
    for (std::uint8_t c : count) {
        covered += c >= 1;
        m.overlappingTexels += c >= 2;
    }
    m.packingEfficiency = double(covered) / (double(pageTexels) * pages);
}

/** Seams: edges of the welded surface between triangles of different charts. */
void measureSeams(const UvLayout& layout, double side, UvLayoutMetrics& m) {
    const Mesh& mesh = layout.mesh;
    const std::size_t n = mesh.triangleCount();
    const MeshTopology topo = buildMeshTopology(mesh);
    for (std::size_t t = 0; t < n && t < layout.triangleChart.size(); ++t)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t u = topo.edgeNeighbors[t][std::size_t(e)];
            if (u == 0xffffffffu || u <= t || layout.triangleChart[u] == layout.triangleChart[t])
                continue;
            const glm::vec3 a = mesh.positions[mesh.indices[3 * t + std::size_t(e)]];
            const glm::vec3 b = mesh.positions[mesh.indices[3 * t + std::size_t((e + 1) % 3)]];
            m.seamLength += double(glm::length(b - a));
        }
    m.seamLengthUnitCube = side > 0.0 ? m.seamLength / side : 0.0;
}

} // namespace

UvLayoutMetrics measureUvLayout(const UvLayout& layout, unsigned threads) {
    UvLayoutMetrics m;
    const Mesh& mesh = layout.mesh;
    const std::size_t n = mesh.triangleCount();
    m.charts = layout.chartCount;
    m.pages = layout.pageCount;
    m.triangles = n;
    m.vertices = mesh.vertexCount();
    if (n == 0 || !mesh.hasUvs() || layout.resolution <= 0)
        return m;
    const double side = double(mesh.bounds().longestSide());
    const double degenerate = 1e-12 * side * side;
    measureStretchAndDensity(measureTriangleAreas(mesh, double(layout.resolution), threads),
                             degenerate, m);
    measureCoverage(layout, m);
    measureSeams(layout, side, m);
    return m;
}

} // namespace core
