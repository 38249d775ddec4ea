// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/uv_layout.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/base/parallel.h"
#include "core/model/uv_layout_internal.h"

namespace core {

namespace {

using uvl::Chart;

Error cancelled() {
    return Error{"the UV layout was cancelled", ErrorKind::Cancelled};
}

std::string checkOptions(const UvLayoutOptions& o) {
    if (o.resolution < 64 || o.resolution > 16384)
        return "the page resolution must be 64 to 16384 texels";
    if (o.padding < 0 || o.padding > 256)
        return "the padding must be 0 to 256 texels";
    if (!std::isfinite(o.texelsPerUnit) || o.texelsPerUnit < 0.0)
        return "the texel density must be a positive number or 0 (fit one page)";
    if (!(o.maxNormalDeviationDegrees > 0.0f && o.maxNormalDeviationDegrees < 180.0f) ||
        !(o.sharpEdgeDegrees > 0.0f && o.sharpEdgeDegrees <= 180.0f))
        return "the chart angles must be between 0 and 180 degrees";
    if (o.smallChartTexels < 0 || o.smallChartTexels > 65536)
        return "the small chart size must be 0 to 65536 texels";
    if (!(o.maxChartStretch > 1.0f))
        return "the chart stretch limit must be above 1";
    return {};
}

/** Sides this close to one line (relative to the model's size) touch: the welding's distance. */
constexpr double kContactTolerance = 1e-5;

uvl::Surface makeSurface(const Mesh& mesh, const MeshTopology& topo, unsigned threads) {
    uvl::Surface s;
    s.topology = &topo;
    s.position.assign(topo.weldedVertexCount, glm::dvec3(0.0));
    std::vector<std::uint8_t> seen(topo.weldedVertexCount, 0u);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const std::uint32_t w = topo.weldedVertex[v];
        if (!seen[w]) {
            seen[w] = 1;
            s.position[w] = glm::dvec3(mesh.positions[v]);
        }
    }
    const double side = double(mesh.bounds().longestSide());
    s.degenerateArea = 1e-12 * side * side;
    const std::size_t n = topo.triangleCount();
    s.normal.assign(n, glm::dvec3(0.0));
    s.area.assign(n, 0.0);
    parallelRanges(int(n), threads, [&](int, int begin, int end) {
        for (int t = begin; t < end; ++t) {
            const auto& c = topo.corners[std::size_t(t)];
            const glm::dvec3 g = glm::cross(s.position[c[1]] - s.position[c[0]],
                                            s.position[c[2]] - s.position[c[0]]);
            const double len = glm::length(g);
            s.area[std::size_t(t)] = 0.5 * len;
            if (len > 0.0 && std::isfinite(len))
                s.normal[std::size_t(t)] = g / len;
        }
    });
    for (std::size_t t = 0; t < n; ++t)
        if (s.degenerate(std::uint32_t(t)))
            s.normal[t] = glm::dvec3(0.0);
    uvl::findContacts(s, kContactTolerance * side);
    return s;
}

/**
 * Flattens every chart, splitting those that fold over or stretch until all are good. Rounds of
 * flattening run in parallel; what a round gives depends only on its charts, so the result does
 * not depend on the thread count.
 */
Result<std::vector<Chart>> flattenAll(const uvl::Surface& surface,
                                      std::vector<std::vector<std::uint32_t>> pending,
                                      const UvLayoutOptions& options, double density,
                                      const ProgressFn& progress, double from, double to) {
    std::vector<Chart> done;
    const double total = double(std::max<std::size_t>(surface.area.size(), 1));
    std::atomic<bool> stop{false};
    std::size_t finishedTriangles = 0;
    double reported = 0.0; // charts split again take back what they reported: never report less
    for (int round = 0; !pending.empty(); ++round) {
        std::vector<Chart> work(pending.size());
        std::vector<uvl::FlattenOutcome> outcome(pending.size());
        for (std::size_t i = 0; i < pending.size(); ++i)
            work[i].triangles = std::move(pending[i]);
        pending.clear();
        if (round >= 48) { // give up on what is left: one chart per triangle always flattens
            for (Chart& c : work)
                for (std::uint32_t t : c.triangles)
                    pending.push_back({t});
            continue;
        }
        std::atomic<std::size_t> next{0}, doneTriangles{0};
        const unsigned threads = resolveThreadCount(options.threads);
        parallelRanges(int(threads), threads, [&](int part, int, int) {
            for (std::size_t i = next++; i < work.size() && !stop; i = next++) {
                outcome[i] =
                    uvl::flattenChart(surface, work[i], double(options.maxChartStretch), density);
                doneTriangles += work[i].triangles.size();
                if (part == 0) {
                    const double f = double(finishedTriangles + doneTriangles.load()) / total;
                    reported = std::max(reported, std::min(f, 1.0));
                    if (!reportProgress(progress, from + (to - from) * reported))
                        stop = true;
                }
            }
        });
        if (stop)
            return cancelled();
        for (std::size_t i = 0; i < work.size(); ++i) {
            if (outcome[i] == uvl::FlattenOutcome::Good || work[i].triangles.size() == 1) {
                finishedTriangles += work[i].triangles.size();
                done.push_back(std::move(work[i]));
                continue;
            }
            auto parts = uvl::splitChart(surface, work[i].triangles);
            for (auto& part : parts)
                if (!part.empty())
                    pending.push_back(std::move(part));
        }
    }
    std::sort(done.begin(), done.end(),
              [](const Chart& a, const Chart& b) { return a.triangles[0] < b.triangles[0]; });
    return done;
}

/** The largest density (texels per model unit) at which the charts fit one page. */
Result<std::pair<double, uvl::Packing>> packOnePage(const std::vector<Chart>& charts,
                                                    const UvLayoutOptions& options,
                                                    const ProgressFn& progress, double from,
                                                    double to) {
    double area = 0.0;
    for (const Chart& c : charts)
        area += c.area;
    const double pageArea = double(options.resolution) * double(options.resolution);
    double density = area > 0.0 ? std::sqrt(0.7 * pageArea / area) : 1.0;
    std::optional<uvl::Packing> best;
    double bestDensity = 0.0, failedDensity = std::numeric_limits<double>::infinity();
    std::atomic<bool> cancel{false};
    constexpr int kAttempts = 18;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        Result<uvl::Packing> packing = uvl::packCharts(charts, density, options, 1, cancel);
        if (packing.cancelled())
            return cancelled();
        if (packing.ok()) {
            best = std::move(packing.value());
            bestDensity = density;
        } else {
            failedDensity = density;
        }
        if (!reportProgress(progress, from + (to - from) * double(attempt + 1) / kAttempts))
            return cancelled();
        if (std::isinf(failedDensity))
            density *= 1.15;
        else if (!best)
            density *= 0.8;
        else if (failedDensity / bestDensity < 1.005)
            break;
        else
            density = std::sqrt(bestDensity * failedDensity);
        if (!best && density < 1e-300)
            break;
    }
    if (!best)
        return Error{std::to_string(charts.size()) + " charts do not fit on one " +
                         std::to_string(options.resolution) + "×" +
                         std::to_string(options.resolution) + " page with " +
                         std::to_string(options.padding) +
                         " texels of padding; use a larger resolution or less padding",
                     ErrorKind::BadInput};
    return std::make_pair(bestDensity, std::move(*best));
}

/** What makeUvLayout cannot lay out: bad options, an invalid or empty mesh. */
Status checkLayoutInput(const Mesh& mesh, const UvLayoutOptions& options) {
    if (const std::string problem = checkOptions(options); !problem.empty())
        return Error{"cannot lay out UVs: " + problem, ErrorKind::BadInput};
    if (const Status valid = mesh.validate(); !valid)
        return Error{"cannot lay out UVs of the mesh: " + valid.error(), ErrorKind::BadInput};
    if (mesh.triangleCount() == 0)
        return Error{"cannot lay out UVs of a mesh without triangles", ErrorKind::BadInput};
    if (mesh.triangleCount() >= std::size_t(kNone))
        return Error{"cannot lay out UVs of more than 4 billion triangles", ErrorKind::BadInput};
    return {};
}

/** The density the charts will have, near enough to look for overlaps at texel size. */
double expectedDensity(const uvl::Surface& surface, const UvLayoutOptions& options) {
    double surfaceArea = 0.0;
    for (std::size_t t = 0; t < surface.area.size(); ++t)
        if (!surface.degenerate(std::uint32_t(t)))
            surfaceArea += surface.area[t];
    return options.texelsPerUnit > 0.0 ? options.texelsPerUnit
           : surfaceArea > 0.0         ? std::sqrt(0.7 * double(options.resolution) *
                                                   double(options.resolution) / surfaceArea)
                                       : 1.0;
}

/** The charts packed at the options' density on as many pages as they need, or at the largest
 *  that fits one page (density 0); density becomes the one used. */
Status packAllCharts(const std::vector<Chart>& charts, const UvLayoutOptions& options,
                     const ProgressFn& progress, double& density, uvl::Packing& packing) {
    density = options.texelsPerUnit;
    if (density > 0.0) {
        std::atomic<bool> cancel{false};
        Result<uvl::Packing> packed = uvl::packCharts(charts, density, options, 4096, cancel);
        if (!packed)
            return Error{"cannot lay out UVs at " + std::to_string(density) +
                             " texels per unit: " + packed.error(),
                         packed.errorKind()};
        packing = std::move(packed.value());
        return {};
    }
    auto packed = packOnePage(charts, options, progress, 0.6, 0.95);
    if (!packed)
        return packed.takeError();
    density = packed->first;
    packing = std::move(packed->second);
    return {};
}

/** The layout's numbers and each triangle's chart and page; slot becomes each triangle's place
 *  in its chart. */
void assignCharts(const std::vector<Chart>& charts, const uvl::Packing& packing,
                  std::size_t triangles, UvLayout& layout, std::vector<std::uint32_t>& slot) {
    layout.chartCount = std::uint32_t(charts.size());
    layout.pageCount = packing.pageCount;
    layout.chartPage.resize(charts.size());
    layout.triangleChart.assign(triangles, kNone);
    slot.assign(triangles, 0u);
    for (std::uint32_t c = 0; c < charts.size(); ++c) {
        layout.chartPage[c] = packing.placements[c].page;
        for (std::uint32_t k = 0; k < charts[c].triangles.size(); ++k) {
            layout.triangleChart[charts[c].triangles[k]] = c;
            slot[charts[c].triangles[k]] = k;
        }
    }
}

/** The laid-out mesh: one vertex per (input vertex, chart), numbered in order of first use. */
void buildLayoutMesh(const Mesh& mesh, const std::vector<Chart>& charts,
                     const uvl::Packing& packing, double density,
                     const std::vector<std::uint32_t>& slot, UvLayout& layout) {
    Mesh& out = layout.mesh;
    out.materials = mesh.materials;
    out.textures = mesh.textures;
    out.textureSources = mesh.textureSources;
    out.textureOrigins = mesh.textureOrigins;
    out.source = mesh.source; // written back with these uvs through sourceVertices
    out.warnings = mesh.warnings;
    out.triangleMaterial = mesh.triangleMaterial;
    out.objects = mesh.objects; // the triangles keep their order
    out.indices.resize(mesh.indices.size());
    std::unordered_map<std::uint64_t, std::uint32_t> copies;
    copies.reserve(mesh.vertexCount() * 5 / 4);
    const double invResolution = 1.0 / double(layout.resolution);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t c = layout.triangleChart[t];
        const Chart& chart = charts[c];
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.indices[3 * t + std::size_t(k)];
            const auto [it, added] = copies.try_emplace((std::uint64_t(v) << 32) | c,
                                                        std::uint32_t(layout.sourceVertex.size()));
            if (added) {
                layout.sourceVertex.push_back(v);
                const glm::dvec2 uv = chart.uv[chart.local[slot[t]][std::size_t(k)]];
                const glm::dvec2 texel = uvl::placeUv(packing.placements[c], uv, density);
                out.uvs.emplace_back(glm::vec2(texel * invResolution));
            }
            out.indices[3 * t + std::size_t(k)] = it->second;
        }
    }
    out.positions.reserve(layout.sourceVertex.size());
    out.normals.reserve(layout.sourceVertex.size());
    if (mesh.source) {
        out.sourceVertices.reserve(layout.sourceVertex.size());
        for (std::uint32_t v : layout.sourceVertex)
            out.sourceVertices.push_back(mesh.sourceVertices.empty() ? v : mesh.sourceVertices[v]);
    }
    for (std::uint32_t v : layout.sourceVertex) {
        out.positions.push_back(mesh.positions[v]);
        out.normals.push_back(mesh.normals[v]);
        if (mesh.hasColors())
            out.colors.push_back(mesh.colors[v]);
    }
}

} // namespace

Result<UvLayout> makeUvLayout(const Mesh& mesh, const UvLayoutOptions& options,
                              const ProgressFn& progress) {
    if (Status input = checkLayoutInput(mesh, options); !input)
        return input.takeError();
    if (!reportProgress(progress, 0.0))
        return cancelled();

    // Triangle order, materials and winding stay as they are; only vertices are copied.
    const MeshTopology topology = buildMeshTopology(mesh);
    const uvl::Surface surface = makeSurface(mesh, topology, options.threads);
    std::vector<std::vector<std::uint32_t>> grown = uvl::growCharts(surface, options);
    if (!reportProgress(progress, 0.1))
        return cancelled();
    Result<std::vector<Chart>> flattened = flattenAll(
        surface, std::move(grown), options, expectedDensity(surface, options), progress, 0.1, 0.6);
    if (!flattened)
        return flattened.takeError();
    const std::vector<Chart>& charts = flattened.value();
    double density = 0.0;
    uvl::Packing packing;
    if (Status packed = packAllCharts(charts, options, progress, density, packing); !packed)
        return packed.takeError();

    UvLayout layout;
    layout.resolution = options.resolution;
    layout.padding = options.padding;
    layout.smallChartTexels = options.smallChartTexels;
    layout.smallChartPadding =
        std::min(options.padding, 2 * uvl::smallChartRadius(options.padding));
    layout.texelsPerUnit = density;
    std::vector<std::uint32_t> slot; // a triangle's place in its chart
    assignCharts(charts, packing, mesh.triangleCount(), layout, slot);
    buildLayoutMesh(mesh, charts, packing, density, slot, layout);
    if (!reportProgress(progress, 1.0))
        return cancelled();
    return layout;
}

} // namespace core
