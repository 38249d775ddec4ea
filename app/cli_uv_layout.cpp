// SPDX-License-Identifier: GPL-3.0-or-later
// `layerpaint-cli uv-layout`: the automatic UV layout of a model and its quality figures.
#include "app/cli_uv_layout.h"

#include <fstream>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli_commands.h"
#include "app/cli_timing.h"
#include "core/base/parallel.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/image/image_write.h"
#include "core/io/mesh_io.h"
#include "core/model/uv_layout.h"
#include "core/paint/targets/layout_target.h"
#include "core/paint/targets/uv_raster.h"

namespace cli {

namespace {

/** The pages side by side: each chart in a colour of its own, texels covered twice in white. */
core::Status writeChartImage(const std::string& path, const core::UvLayout& layout) {
    const int size = layout.resolution;
    const int pages = int(std::max(layout.pageCount, 1u));
    const std::size_t width = std::size_t(size) * std::size_t(pages);
    std::vector<std::uint8_t> rgb(width * std::size_t(size) * 3, 0u);
    std::vector<std::uint8_t> count(width * std::size_t(size), 0u);
    const core::Mesh& mesh = layout.mesh;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t chart = layout.triangleChart[t];
        const int page = int(layout.chartPage[chart]);
        glm::vec2 uv[3];
        for (int k = 0; k < 3; ++k)
            uv[k] = mesh.uvs[mesh.indices[3 * t + std::size_t(k)]];
        core::uv::UvTriangle r;
        if (!core::uv::setUpUv(uv, size, size, r))
            continue;
        std::uint32_t h = chart * 2654435761u;
        h ^= h >> 15;
        const std::uint8_t colour[3] = {std::uint8_t(64 + (h & 127)),
                                        std::uint8_t(64 + ((h >> 8) & 127)),
                                        std::uint8_t(64 + ((h >> 16) & 127))};
        core::uv::scanUv(r, std::max(r.minX, 0), std::min(r.maxX, size - 1), std::max(r.minY, 0),
                         std::min(r.maxY, size - 1), [&](int x, int y, auto, auto, auto) {
                             const std::size_t i =
                                 std::size_t(y) * width + std::size_t(page * size + x);
                             const bool twice = count[i]++ > 0;
                             for (int c = 0; c < 3; ++c)
                                 rgb[3 * i + std::size_t(c)] = twice ? 255 : colour[c];
                         });
    }
    return core::writeImage(path, int(width), size, 3, core::PixelType::UInt8, rgb.data());
}

core::UvLayoutOptions layoutOptions(const UvLayoutArgs& args) {
    core::UvLayoutOptions options;
    options.resolution = args.resolution;
    options.padding = args.padding;
    options.texelsPerUnit = args.texelsPerUnit;
    options.threads = args.threads;
    if (args.maxDeviation > 0.0f)
        options.maxNormalDeviationDegrees = args.maxDeviation;
    if (args.sharpEdge > 0.0f)
        options.sharpEdgeDegrees = args.sharpEdge;
    return options;
}

/** What a layout run measured, beside the layout's own figures. */
struct LayoutRun {
    bool hadUvs = false;
    double loadSeconds = 0.0, layoutSeconds = 0.0;
};

nlohmann::json figuresJson(const UvLayoutArgs& args, const core::Mesh& mesh,
                           const core::UvLayoutOptions& options, const core::UvLayout& layout,
                           const LayoutRun& run) {
    const core::UvLayoutMetrics m = core::measureUvLayout(layout, args.threads);
    return {
        {"file", args.model},
        {"triangles", m.triangles},
        {"vertices_in", mesh.vertexCount()},
        {"vertices_out", m.vertices},
        {"had_uvs", run.hadUvs},
        {"vertex_spacing_px", core::vertexSpacingPixels(mesh)},
        {"default_target",
         core::defaultTargetKind(mesh, core::Brush{}.radius) == core::PaintTargetKind::Texture
             ? "texture"
             : "vertex-colors"},
        {"resolution", layout.resolution},
        {"padding", layout.padding},
        {"threads", core::resolveThreadCount(args.threads)},
        {"texels_per_unit", layout.texelsPerUnit},
        {"max_normal_deviation_degrees", options.maxNormalDeviationDegrees},
        {"sharp_edge_degrees", options.sharpEdgeDegrees},
        {"charts", m.charts},
        {"pages", m.pages},
        {"stretch_p95", m.stretchP95},
        {"stretch_p95_by_triangle", m.stretchP95Triangles},
        {"stretch_max", m.stretchMax},
        {"texel_density_spread", m.texelDensitySpread},
        {"packing_efficiency", m.packingEfficiency},
        {"overlapping_texels", m.overlappingTexels},
        {"flipped_triangles", m.flippedTriangles},
        {"collapsed_triangles", m.collapsedTriangles},
        {"seam_length", m.seamLength},
        {"seam_length_unit_cube", m.seamLengthUnitCube},
        {"load_seconds", run.loadSeconds},
        {"layout_seconds", run.layoutSeconds},
    };
}

/** The --json file, the --image of the charts and the --out mesh, each if asked for. */
core::Status writeOutputs(const UvLayoutArgs& args, const nlohmann::json& figures,
                          const core::UvLayout& layout) {
    if (!args.jsonOut.empty()) {
        std::ofstream file(args.jsonOut, std::ios::trunc);
        file << jsonText(figures, 2) << '\n';
        if (!file.flush())
            return core::Error{args.jsonOut + ": cannot write the file"};
    }
    if (!args.image.empty())
        if (const core::Status written = writeChartImage(args.image, layout); !written)
            return written;
    if (!args.out.empty())
        if (const core::Status saved = core::saveGlb(args.out, layout.mesh, {}, {}, false); !saved)
            return saved;
    return {};
}

} // namespace

int runUvLayout(const UvLayoutArgs& args) {
    LayoutRun run;
    const auto loadStart = Clock::now();
    core::Result<core::Mesh> mesh = core::loadMesh(args.model);
    if (!mesh)
        return fail(mesh.error());
    run.loadSeconds = msSince(loadStart) / 1000.0;
    run.hadUvs = mesh->hasUvs();
    if (run.hadUvs && !args.keepUvs)
        return fail(args.model + ": the model has texture coordinates already (--replace-uvs "
                                 "lays it out anyway)");
    if (run.hadUvs)
        mesh->uvs.clear();

    const core::UvLayoutOptions options = layoutOptions(args);
    const auto start = Clock::now();
    core::Result<core::UvLayout> layout = core::makeUvLayout(*mesh, options);
    run.layoutSeconds = msSince(start) / 1000.0;
    if (!layout)
        return fail(args.model + ": " + layout.error());
    const nlohmann::json out = figuresJson(args, *mesh, options, *layout, run);
    std::cout << jsonText(out, 2) << '\n';
    if (const core::Status s = writeOutputs(args, out, *layout); !s)
        return fail(s.error());
    return 0;
}

} // namespace cli
