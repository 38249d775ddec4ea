// SPDX-License-Identifier: GPL-3.0-or-later
// Micro-benchmarks of the GL stages on the trefoil at 1280 × 720 in a headless EGL context (Mesa's
// llvmpipe on the development machines): the plain z-buffer pass they are compared with, the
// layer capture, build_layers, the connectivity compute pass and draw_layers.
#include <memory>
#include <string>

#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include "bench/trefoil_scene.h"
#include "core/regions/region_order.h"
#include "render/depth_capture.h"
#include "render/depth_compositor.h"
#include "render/gl_context.h"
#include "render/gl_depth_capturer.h"
#include "render/gpu_connectivity.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"

namespace {

using bench::trefoilScene;
using bench::TrefoilScene;

/** Makes the one headless context current (created on first use); false after SkipWithError. */
bool glContext(benchmark::State& state) {
    static std::unique_ptr<render::HeadlessContext> context;
    static std::string error;
    if (!context && error.empty()) {
        auto created = render::HeadlessContext::create();
        if (created) {
            context = std::move(created).value();
            // Shown once at the top of the output, next to the machine's description.
            benchmark::AddCustomContext("renderer", render::HeadlessContext::rendererName());
        } else {
            error = created.error();
        }
    }
    if (!context)
        state.SkipWithError(error.c_str());
    return context != nullptr;
}

/** capturer initialized with the scene's mesh; false after SkipWithError. */
bool readyCapturer(benchmark::State& state, render::GlDepthCapturer& capturer,
                   const TrefoilScene& s) {
    if (const core::Status status = capturer.initialize(); !status) {
        state.SkipWithError(status.error().c_str());
        return false;
    }
    capturer.setMesh(*s.mesh);
    return true;
}

/** One z-buffer pass, back faces culled (as the capture draws) or two-sided (as the viewer). */
void PlainPass(benchmark::State& state, bool culled) {
    if (!glContext(state))
        return;
    const TrefoilScene& s = trefoilScene();
    render::MeshRenderer renderer;
    render::OffscreenTarget target;
    if (!renderer.initialize() || !target.create(s.view.width, s.view.height)) {
        state.SkipWithError("the renderer or its target could not be made");
        return;
    }
    renderer.setMesh(*s.mesh);
    render::DrawOptions options;
    options.cullBackFaces = culled;
    render::timePlainPass(renderer, target, s.view, options); // compiles, uploads
    for (auto _ : state)
        benchmark::DoNotOptimize(render::timePlainPass(renderer, target, s.view, options));
    renderer.release();
}
BENCHMARK_CAPTURE(PlainPass, culled, true)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(PlainPass, two_sided, false)->Unit(benchmark::kMillisecond)->UseRealTime();

/** The capture: every front-facing fragment as per-pixel lists in CPU memory. */
void GlCapture(benchmark::State& state) {
    if (!glContext(state))
        return;
    const TrefoilScene& s = trefoilScene();
    render::GlDepthCapturer capturer;
    if (!readyCapturer(state, capturer, s))
        return;
    core::CaptureStats stats;
    if (auto warm = capturer.capture(s.view, {}, &stats); !warm) { // buffer sizes, shaders
        state.SkipWithError(warm.error().c_str());
        return;
    }
    double gpuMs = 0.0, resolveMs = 0.0;
    for (auto _ : state) {
        auto stack = capturer.capture(s.view, {}, &stats);
        benchmark::DoNotOptimize(stack->depth.data());
        gpuMs += stats.gpuMs;
        resolveMs += stats.resolveMs;
    }
    state.counters["fragments"] = double(s.layers.stack.fragmentCount());
    state.counters["gpu_ms"] = benchmark::Counter(gpuMs, benchmark::Counter::kAvgIterations);
    state.counters["resolve_ms"] =
        benchmark::Counter(resolveMs, benchmark::Counter::kAvgIterations);
}
BENCHMARK(GlCapture)->Unit(benchmark::kMillisecond)->UseRealTime();

/** build_layers as the GUI and the CLI run it: GL capture, then the chosen connectivity engine. */
void BuildLayersGl(benchmark::State& state) {
    if (!glContext(state))
        return;
    const TrefoilScene& s = trefoilScene();
    render::GlDepthCapturer capturer;
    if (!readyCapturer(state, capturer, s))
        return;
    render::GlConnectivityEngine engine;
    core::buildDepthLayers(capturer, *s.mesh, *s.topology, s.view, {}, &engine); // warm-up
    for (auto _ : state) {
        auto layers = core::buildDepthLayers(capturer, *s.mesh, *s.topology, s.view, {}, &engine);
        benchmark::DoNotOptimize(layers->segmentation.region.data());
    }
    state.SetLabel(std::string("connectivity on ") +
                   render::connectivityBackendName(engine.backend()));
}
BENCHMARK(BuildLayersGl)->Unit(benchmark::kMillisecond)->UseRealTime();

/**
 * The connectivity compute pass (surface or plain test): upload, dispatch and readback from an
 * idle GPU, on the same stack as the CPU benchmark.
 */
void GpuConnectivity(benchmark::State& state, core::ConnectionTest test) {
    if (!glContext(state))
        return;
    const TrefoilScene& s = trefoilScene();
    render::GpuConnectivity gpu;
    if (const core::Status status = gpu.initialize(); !status) {
        state.SkipWithError(status.error().c_str());
        return;
    }
    core::ConnectivityOptions options;
    options.test = test;
    options.unitScale = core::unitScale(*s.mesh);
    if (auto warm = gpu.compute(s.layers.stack, options, &s.layers.geometry); !warm) {
        state.SkipWithError(warm.error().c_str());
        return;
    }
    for (auto _ : state) {
        auto links = gpu.compute(s.layers.stack, options, &s.layers.geometry);
        benchmark::DoNotOptimize(links->links.data());
    }
    state.counters["per_fragment"] = benchmark::Counter(
        double(s.layers.stack.fragmentCount()),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    gpu.release();
}
BENCHMARK_CAPTURE(GpuConnectivity, surface, core::ConnectionTest::Surface)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(GpuConnectivity, plain, core::ConnectionTest::Plain)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

enum DrawCase { kComposite, kBoundaries, kSegmentation, kPoppedUp, kFirstAfterSetLayers };

/**
 * draw_layers: a redraw from the captured fragments (glFinish on both sides): the composite, with
 * region boundaries, the segmentation display, the composite with the largest layer-2 region
 * popped up (defeats the fragment search's early exit), and the first draw after setDepthLayers(),
 * which also shades every fragment.
 */
void DrawLayers(benchmark::State& state, DrawCase drawCase) {
    if (!glContext(state))
        return;
    const TrefoilScene& s = trefoilScene();
    render::DepthCompositor compositor;
    render::OffscreenTarget target;
    if (!compositor.initialize() || !compositor.setMesh(*s.mesh) ||
        !target.create(s.view.width, s.view.height)) {
        state.SkipWithError("the compositor or its target could not be made");
        return;
    }
    target.bind();
    render::CompositeOptions options;
    compositor.draw(options); // compiles the programs
    if (const core::Status status = compositor.setDepthLayers(s.layers); !status) {
        state.SkipWithError(status.error().c_str());
        return;
    }
    options.boundaries = drawCase == kBoundaries;
    if (drawCase == kSegmentation)
        options.display = render::DepthLayerDisplay::Segmentation;
    if (drawCase == kPoppedUp) {
        const core::RegionGraph& graph = s.layers.segmentation.graph;
        core::RegionOrder order(graph);
        std::uint32_t popped = core::kNone;
        for (const core::Region& region : graph.regions)
            if (region.layer == 2 &&
                (popped == core::kNone || region.pixels > graph.regions[popped].pixels))
                popped = region.id;
        if (popped == core::kNone) {
            state.SkipWithError("no region on layer 2");
            return;
        }
        order.popUp(popped);
        compositor.setRegionRanks(order.prunedRanks(false));
    }
    compositor.draw(options);
    glFinish();
    for (auto _ : state) {
        if (drawCase == kFirstAfterSetLayers) {
            state.PauseTiming();
            compositor.setDepthLayers(s.layers);
            glFinish();
            state.ResumeTiming();
        }
        compositor.draw(options);
        glFinish();
    }
    compositor.release();
}
BENCHMARK_CAPTURE(DrawLayers, composite, kComposite)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(DrawLayers, boundaries, kBoundaries)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(DrawLayers, segmentation, kSegmentation)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(DrawLayers, popped_up, kPoppedUp)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(DrawLayers, first_after_set_layers, kFirstAfterSetLayers)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace
