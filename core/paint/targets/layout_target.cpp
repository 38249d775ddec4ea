// SPDX-License-Identifier: GPL-3.0-or-later
// Texture targets for meshes without UVs: the automatic UV layout, and the rule that decides
// when a mesh without UVs is better painted into a texture than into its vertex colours.
#include "core/paint/targets/layout_target.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/model/camera.h"
#include "core/model/uv_layout.h"

namespace core {

Result<std::unique_ptr<TextureTarget>>
makeLayoutTarget(const Mesh& mesh, const PaintTargetOptions& options, const ProgressFn& progress) {
    // The layout is most of the work; making the target (coverage, seam padding) the rest.
    constexpr double kLayoutShare = 0.9;
    UvLayoutOptions layoutOptions;
    layoutOptions.resolution = std::clamp(options.resolution, 512, 8192);
    layoutOptions.padding = std::clamp(options.padding, 1, 64);
    ProgressFn layoutProgress;
    if (progress)
        layoutProgress = [&progress](double f) { return progress(f * kLayoutShare); };
    Result<UvLayout> layout = makeUvLayout(mesh, layoutOptions, layoutProgress);
    if (!layout)
        return layout.takeError();
    auto laidOut = std::make_shared<const Mesh>(std::move(layout->mesh));
    PaintTargetOptions targetOptions = options;
    targetOptions.kind = PaintTargetKind::Texture;
    targetOptions.resolution = layoutOptions.resolution;
    // The layout's page is new: there is no texture of the file to paint into.
    targetOptions.reuseTextures = false;
    auto target = TextureTarget::create(std::move(laidOut), nullptr, targetOptions);
    if (!target)
        return target.takeError();
    if (!reportProgress(progress, 1.0))
        return cancelledError();
    return target;
}

bool needsUvLayout(const Mesh& mesh, const PaintTargetOptions& options) {
    return options.kind == PaintTargetKind::Texture && (!mesh.hasUvs() || options.automaticUvs);
}

std::vector<PageSize> texturePageSizes(const Mesh& mesh, const PaintTargetOptions& options) {
    PaintTargetOptions texture = options;
    texture.kind = PaintTargetKind::Texture;
    if (!needsUvLayout(mesh, texture))
        return TextureTarget::materialPageSizes(mesh, options);
    const int resolution = std::clamp(options.resolution, 512, 8192);
    return std::vector<PageSize>(mesh.materials.size(), PageSize{resolution, resolution});
}

Result<std::unique_ptr<PaintTarget>>
makePaintTargetWithLayout(std::shared_ptr<const Mesh> mesh,
                          std::shared_ptr<const MeshTopology> topology,
                          const PaintTargetOptions& options, const ProgressFn& progress) {
    if (!mesh || !needsUvLayout(*mesh, options)) {
        auto target = makePaintTarget(std::move(mesh), std::move(topology), options);
        if (target && !reportProgress(progress, 1.0))
            return cancelledError();
        return target;
    }
    auto target = makeLayoutTarget(*mesh, options, progress);
    if (!target)
        return target.takeError();
    return Result<std::unique_ptr<PaintTarget>>(std::move(target).value());
}

double vertexSpacingPixels(const Mesh& mesh) {
    const std::size_t triangles = mesh.triangleCount();
    if (triangles == 0 || mesh.indices.size() < 3 * triangles)
        return 0.0;
    Camera camera;
    constexpr float kAspect = 16.0f / 9.0f;
    camera.frame(mesh.bounds(), kAspect, kFrameMargin);
    const double pixelsPerUnit =
        kReferenceViewHeight /
        (2.0 * double(camera.distance) * std::tan(glm::radians(double(camera.fovYDegrees)) * 0.5));
    struct Weighted {
        double edge = 0.0;
        double area = 0.0;
    };
    std::vector<Weighted> edges;
    edges.reserve(triangles);
    double totalArea = 0.0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::vec3& a = mesh.positions[mesh.indices[3 * t]];
        const glm::vec3& b = mesh.positions[mesh.indices[3 * t + 1]];
        const glm::vec3& c = mesh.positions[mesh.indices[3 * t + 2]];
        const double area = 0.5 * double(glm::length(glm::cross(b - a, c - a)));
        if (!(area > 0.0) || !std::isfinite(area))
            continue;
        const double edge =
            double(std::max({glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)}));
        edges.push_back({edge, area});
        totalArea += area;
    }
    if (edges.empty())
        return 0.0;
    std::sort(edges.begin(), edges.end(),
              [](const Weighted& x, const Weighted& y) { return x.edge < y.edge; });
    double below = 0.0;
    for (const Weighted& w : edges) {
        below += w.area;
        if (below >= 0.5 * totalArea)
            return w.edge * pixelsPerUnit;
    }
    return edges.back().edge * pixelsPerUnit;
}

PaintTargetKind defaultTargetKind(const Mesh& mesh, float brushRadius) {
    if (mesh.hasUvs())
        return PaintTargetKind::Texture;
    return vertexSpacingPixels(mesh) > 0.25 * double(brushRadius) ? PaintTargetKind::Texture
                                                                  : PaintTargetKind::VertexColors;
}

} // namespace core
