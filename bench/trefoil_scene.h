// SPDX-License-Identifier: GPL-3.0-or-later
// The scene every benchmark measures: the built-in trefoil knot at the paper's size (144K
// vertices) seen at 1280 × 720, as layerpaint-cli bench and the README's tables use it.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "core/depth/depth_layers.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/model/mesh_topology.h"
#include "core/paint/tracking/stroke_tracker.h"

namespace bench {

struct TrefoilScene {
    std::shared_ptr<core::Mesh> mesh;
    std::shared_ptr<core::MeshTopology> topology;
    core::View view;
    /** build_layers of the view with the CPU capture (the same stack as the GL capture's). */
    core::DepthLayers layers;
    /** Window positions 5 px apart along the knot's centre line, all the way round (a 200 Hz
     *  tablet at 1000 px/s), crossing over and under the other strands. */
    std::vector<core::StrokePoint> path;
};

/**
 * Built once on first use (about a second); the benchmarks only read it. With
 * LAYERPAINT_BENCH_MODEL naming a model file, the layer benchmarks (capture, planes,
 * connectivity, segmentation) measure that model instead, framed as `layerpaint-cli bench`
 * frames it, at LAYERPAINT_BENCH_SIZE (WIDTHxHEIGHT, default 1280x720); the stroke benchmarks
 * follow the trefoil's centre line and need the trefoil.
 */
inline const TrefoilScene& trefoilScene() {
    static const TrefoilScene scene = [] {
        TrefoilScene s;
        int width = 1280, height = 720;
        if (const char* size = std::getenv("LAYERPAINT_BENCH_SIZE"))
            std::sscanf(size, "%dx%d", &width, &height);
        if (const char* path = std::getenv("LAYERPAINT_BENCH_MODEL")) {
            auto loaded = core::loadMeshInProcess(path);
            if (!loaded) {
                std::fprintf(stderr, "%s\n", loaded.error().c_str());
                std::exit(1);
            }
            s.mesh = std::make_shared<core::Mesh>(std::move(loaded).value());
            core::Camera camera;
            camera.frame(s.mesh->bounds());
            camera.orbit(30.0f, 20.0f);
            s.view = camera.view(width, height);
        } else {
            s.mesh = std::make_shared<core::Mesh>(core::makeTrefoil());
            s.view =
                core::Camera::fromOrbit(s.mesh->bounds(), 30.0f, 20.0f, 1.6f).view(width, height);
        }
        s.topology = std::make_shared<core::MeshTopology>(core::buildMeshTopology(*s.mesh));
        core::CpuDepthCapturer capturer;
        capturer.setMesh(*s.mesh);
        auto built = core::buildDepthLayers(capturer, *s.mesh, *s.topology, s.view, {});
        if (built)
            s.layers = std::move(built).value();
        // The tube's centre line, as core::makeTrefoil() sweeps it.
        constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
        for (float t = 0.0f; t < kTwoPi; t += 0.0005f) {
            const glm::vec3 centre(std::sin(t) + 2.0f * std::sin(2.0f * t),
                                   std::cos(t) - 2.0f * std::cos(2.0f * t), -std::sin(3.0f * t));
            const glm::vec2 q(s.view.project(centre));
            if (s.path.empty() || glm::length(q - s.path.back().position) >= 5.0f)
                s.path.push_back({q, 1.0f});
        }
        return s;
    }();
    return scene;
}

} // namespace bench
