// SPDX-License-Identifier: GPL-3.0-or-later
// Orbiting a large mesh: one frame of the full mesh against one of its stand-in (what the
// viewport draws while the camera moves), each from a new orbit angle, at 1280 × 720 in a
// headless EGL context; and the simplification itself. The trefoil is made with
// LAYERPAINT_BENCH_TRIANGLES triangles (default 2,000,000; the README's figures use 10,000,000).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/model/stand_in.h"
#include "render/depth_capture.h"
#include "render/gl_context.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"

namespace {

constexpr std::size_t kStandInTriangles = 250'000; // the viewport's default

/** The trefoil with about LAYERPAINT_BENCH_TRIANGLES triangles, made once. */
const core::Mesh& largeMesh() {
    static const core::Mesh mesh = [] {
        double triangles = 2e6;
        if (const char* env = std::getenv("LAYERPAINT_BENCH_TRIANGLES"))
            triangles = std::max(1e4, std::atof(env));
        // 3 strips × segments × radial × 2 triangles, with segments ≈ 10 × radial.
        const int radial = std::max(8, int(std::sqrt(triangles / 60.0)));
        const int segments = std::max(8, int(triangles / (6.0 * radial)));
        return core::makeTrefoil(segments, radial);
    }();
    return mesh;
}

const core::StandIn& largeStandIn() {
    static const core::StandIn standIn = [] {
        auto made = core::simplifyForDisplay(largeMesh(), kStandInTriangles);
        return made ? std::move(made).value() : core::StandIn{};
    }();
    return standIn;
}

void OrbitFrame(benchmark::State& state, bool standIn) {
    static std::unique_ptr<render::HeadlessContext> context;
    if (!context) {
        auto created = render::HeadlessContext::create();
        if (!created) {
            state.SkipWithError(created.error().c_str());
            return;
        }
        context = std::move(created).value();
    }
    const core::Mesh& mesh = largeMesh();
    render::MeshRenderer renderer;
    render::OffscreenTarget target;
    if (!renderer.initialize() || !target.create(1280, 720)) {
        state.SkipWithError("the renderer or its target could not be made");
        return;
    }
    renderer.setMesh(mesh);
    if (standIn)
        renderer.setStandIn(largeStandIn().indices, largeStandIn().triangleMaterial);
    render::DrawOptions options;
    options.standIn = standIn;
    float yaw = 30.0f;
    const auto frame = [&] {
        const core::View view =
            core::Camera::fromOrbit(mesh.bounds(), yaw, 20.0f, 1.6f).view(1280, 720);
        yaw += 2.0f;
        return render::timePlainPass(renderer, target, view, options);
    };
    frame(); // compiles, uploads
    for (auto _ : state)
        state.SetIterationTime(frame() / 1000.0);
    state.counters["triangles"] = double(renderer.lastDrawnTriangles());
    renderer.release();
}
BENCHMARK_CAPTURE(OrbitFrame, full_mesh, false)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(3)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(OrbitFrame, stand_in, true)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(10)
    ->Repetitions(3)
    ->ReportAggregatesOnly(true);

void SimplifyStandIn(benchmark::State& state) {
    const core::Mesh& mesh = largeMesh();
    for (auto _ : state) {
        auto made = core::simplifyForDisplay(mesh, kStandInTriangles);
        benchmark::DoNotOptimize(made);
    }
    state.counters["triangles"] = double(mesh.triangleCount());
}
BENCHMARK(SimplifyStandIn)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

} // namespace
