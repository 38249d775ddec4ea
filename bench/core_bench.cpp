// SPDX-License-Identifier: GPL-3.0-or-later
// Micro-benchmarks of the CPU stages on the trefoil at 1280 × 720 (docs/architecture.md §5):
// capture, pixel connectivity, segmentation, the stroke's BFS maps and one dab on a texture.
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/trefoil_scene.h"
#include "core/depth/connectivity.h"
#include "core/depth/cpu_capture.h"
#include "core/paint/paint_layers/paint_layers.h"
#include "core/paint/paint_layers/undo_tiles.h"
#include "core/paint/targets/paint_target.h"
#include "core/paint/tracking/stroke_tracker.h"
#include "core/regions/segmentation.h"

namespace {

using bench::trefoilScene;
using bench::TrefoilScene;

/** Arg: worker threads, 1 and 2; milliseconds of real time. */
void oneAndTwoThreads(benchmark::internal::Benchmark* b) {
    b->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
}

/** A per-fragment time (the unit of docs/architecture.md §5's budget), from the benchmark's. */
benchmark::Counter perFragment(const TrefoilScene& s) {
    return benchmark::Counter(double(s.layers.stack.fragmentCount()),
                              benchmark::Counter::kIsIterationInvariantRate |
                                  benchmark::Counter::kInvert);
}

core::Brush brush32() {
    core::Brush brush;
    brush.radius = 32.0f;
    brush.hardness = 0.5f;
    brush.flow = 0.5f;
    return brush;
}

void CpuCapture(benchmark::State& state) {
    const TrefoilScene& s = trefoilScene();
    for (auto _ : state) {
        const core::DepthStack stack = core::captureDepthLayersCpu(*s.mesh, s.view);
        benchmark::DoNotOptimize(stack.depth.data());
    }
    state.counters["fragments"] = double(s.layers.stack.fragmentCount());
}
BENCHMARK(CpuCapture)->Unit(benchmark::kMillisecond)->UseRealTime();

/**
 * The surface or the plain connection test, in eight lanes where the processor has AVX2 or in
 * four (wideLanes false); arg: worker threads.
 */
void Connectivity(benchmark::State& state, core::ConnectionTest test, bool wideLanes) {
    const TrefoilScene& s = trefoilScene();
    core::ConnectivityOptions options;
    options.test = test;
    options.wideLanes = wideLanes;
    options.unitScale = core::unitScale(*s.mesh);
    options.threads = unsigned(state.range(0));
    for (auto _ : state) {
        const core::Connectivity links =
            core::computeConnectivity(s.layers.stack, options, &s.layers.geometry);
        benchmark::DoNotOptimize(links.links.data());
    }
    state.counters["per_fragment"] = perFragment(s);
}
BENCHMARK_CAPTURE(Connectivity, surface, core::ConnectionTest::Surface, true)
    ->Apply(oneAndTwoThreads);
BENCHMARK_CAPTURE(Connectivity, surface_four_lanes, core::ConnectionTest::Surface, false)
    ->Apply(oneAndTwoThreads);
BENCHMARK_CAPTURE(Connectivity, plain, core::ConnectionTest::Plain, true)->Apply(oneAndTwoThreads);

void SurfacePlanes(benchmark::State& state) {
    const TrefoilScene& s = trefoilScene();
    for (auto _ : state) {
        const core::SurfaceGeometry geometry =
            core::makeSurfaceGeometry(*s.mesh, *s.topology, s.view, &s.layers.stack);
        benchmark::DoNotOptimize(geometry.triangles.data());
    }
}
BENCHMARK(SurfacePlanes)->Unit(benchmark::kMillisecond)->UseRealTime();

/** Regions and the region graph from the links; arg: worker threads. */
void Segmentation(benchmark::State& state) {
    const TrefoilScene& s = trefoilScene();
    std::size_t regions = 0;
    for (auto _ : state) {
        const core::Segmentation segmentation = core::segmentDepthLayers(
            s.layers.stack, s.layers.connectivity, unsigned(state.range(0)));
        regions = segmentation.graph.regions.size();
        benchmark::DoNotOptimize(segmentation.region.data());
    }
    state.counters["regions"] = double(regions);
    state.counters["per_fragment"] = perFragment(s);
}
BENCHMARK(Segmentation)->Apply(oneAndTwoThreads);

/** The points of the path where a stroke starts with a dab (on the surface). */
std::vector<core::StrokePoint> startPoints(const TrefoilScene& s, core::StrokeTracker& tracker) {
    std::vector<core::StrokePoint> points;
    std::vector<core::Dab> dabs;
    for (std::size_t i = 0; i < s.path.size(); i += 4) {
        dabs.clear();
        if (tracker.startStroke(s.path[i], brush32(), dabs) > 0)
            points.push_back(s.path[i]);
    }
    return points;
}

/**
 * The tracker given the scene's layers and the path's points on the surface; empty (after
 * SkipWithError) when either is not there.
 */
std::vector<core::StrokePoint> readyToStroke(benchmark::State& state, const TrefoilScene& s,
                                             core::StrokeTracker& tracker) {
    if (!tracker.setDepthLayers(s.layers)) {
        state.SkipWithError("the scene's layers are not usable");
        return {};
    }
    std::vector<core::StrokePoint> points = startPoints(s, tracker);
    if (points.empty())
        state.SkipWithError("no point of the path is on the surface");
    return points;
}

/** start_stroke: the first dab's BFS over (x, y, layer), its paintable map Mp (R = 32 px). */
void StartStroke(benchmark::State& state) {
    const TrefoilScene& s = trefoilScene();
    core::StrokeTracker tracker;
    const std::vector<core::StrokePoint> points = readyToStroke(state, s, tracker);
    if (points.empty())
        return;
    const core::Brush brush = brush32();
    std::vector<core::Dab> dabs;
    std::size_t next = 0, mapPixels = 0, count = 0;
    for (auto _ : state) {
        dabs.clear();
        tracker.startStroke(points[next], brush, dabs);
        next = (next + 1) % points.size();
        for (const core::Dab& dab : dabs)
            mapPixels += dab.paintable.size();
        ++count;
    }
    state.counters["mp_pixels"] = count ? double(mapPixels) / double(count) : 0.0;
}
BENCHMARK(StartStroke)->Unit(benchmark::kMillisecond)->UseRealTime();

/**
 * move_stroke: a 5 px move along the knot, tracked from the last dab through Mt (across the
 * crossings, onto hidden strands), with its dabs' Mp. At the end of the path the stroke starts
 * again (not timed).
 */
void MoveStroke(benchmark::State& state) {
    const TrefoilScene& s = trefoilScene();
    core::StrokeTracker tracker;
    if (!tracker.setDepthLayers(s.layers) || s.path.size() < 2) {
        state.SkipWithError("the scene's layers are not usable");
        return;
    }
    const core::Brush brush = brush32();
    std::vector<core::Dab> dabs;
    tracker.startStroke(s.path[0], brush, dabs);
    std::size_t next = 1, dabCount = 0, moves = 0;
    for (auto _ : state) {
        dabs.clear();
        dabCount += tracker.moveStroke(s.path[next], dabs);
        ++moves;
        if (++next == s.path.size()) {
            state.PauseTiming();
            tracker.endStroke();
            dabs.clear();
            tracker.startStroke(s.path[0], brush, dabs);
            next = 1;
            state.ResumeTiming();
        }
    }
    state.counters["dabs_per_move"] = moves ? double(dabCount) / double(moves) : 0.0;
}
BENCHMARK(MoveStroke)->Unit(benchmark::kMillisecond)->UseRealTime();

/** The rest of the trackable map Mt out to R_max = 128 px, as the brush overlay needs it. */
void CompleteTrackableMap(benchmark::State& state) {
    const TrefoilScene& s = trefoilScene();
    core::StrokeTracker tracker;
    const std::vector<core::StrokePoint> points = readyToStroke(state, s, tracker);
    if (points.empty())
        return;
    const core::Brush brush = brush32();
    std::vector<core::Dab> dabs;
    std::size_t next = 0;
    for (auto _ : state) {
        state.PauseTiming();
        dabs.clear();
        tracker.startStroke(points[next], brush, dabs);
        next = (next + 1) % points.size();
        state.ResumeTiming();
        tracker.completeTrackableMap();
        benchmark::DoNotOptimize(tracker.trackablePixels().data());
    }
}
BENCHMARK(CompleteTrackableMap)->Unit(benchmark::kMillisecond)->UseRealTime();

/**
 * One dab on the texture target (a 2048² page): projection painting of the texels whose surface
 * points fall in the dab's Mp, with the stroke's undo tiles. The dabs are the tracker's along the
 * knot, painted in order within one stroke.
 */
void DabOnTexture(benchmark::State& state) {
    const TrefoilScene& s = trefoilScene();
    core::StrokeTracker tracker;
    if (!tracker.setDepthLayers(s.layers)) {
        state.SkipWithError("the scene's layers are not usable");
        return;
    }
    const core::Brush brush = brush32();
    std::vector<core::Dab> dabs;
    tracker.startStroke(s.path[0], brush, dabs);
    for (std::size_t i = 1; i < s.path.size(); ++i)
        tracker.moveStroke(s.path[i], dabs);
    auto target = core::TextureTarget::create(s.mesh, s.topology);
    if (!target || dabs.empty()) {
        state.SkipWithError(target ? "the stroke made no dab" : target.error().c_str());
        return;
    }
    std::size_t next = 0, mapPixels = 0, count = 0;
    (*target)->beginStroke(brush);
    for (auto _ : state) {
        const core::PaintChanges& changes = (*target)->paint(s.layers, dabs[next]);
        benchmark::DoNotOptimize(&changes);
        mapPixels += dabs[next].paintable.size();
        ++count;
        next = (next + 1) % dabs.size();
    }
    const core::TileUndoRecord record = (*target)->endStroke();
    benchmark::DoNotOptimize(record.bytes());
    state.counters["mp_pixels"] = count ? double(mapPixels) / double(count) : 0.0;
    state.counters["texture"] = double((*target)->page(0).width);
}
BENCHMARK(DabOnTexture)->Unit(benchmark::kMillisecond)->UseRealTime();

/**
 * One dab on paint layer 8 of 8 of a 4096² texture target, in all three channels, with the
 * composite of the tiles it touched recomputed (as layerpaint-cli bench's paint_layers part).
 */
void DabOnPaintLayer(benchmark::State& state) {
    const TrefoilScene& s = trefoilScene();
    core::StrokeTracker tracker;
    if (!tracker.setDepthLayers(s.layers)) {
        state.SkipWithError("the scene's layers are not usable");
        return;
    }
    core::Brush brush = brush32();
    brush.paintBaseColor = brush.paintRoughness = brush.paintMetallic = true;
    std::vector<core::Dab> dabs;
    tracker.startStroke(s.path[0], brush, dabs);
    for (std::size_t i = 1; i < s.path.size(); ++i)
        tracker.moveStroke(s.path[i], dabs);
    core::PaintTargetOptions options;
    options.resolution = 4096;
    auto target = core::TextureTarget::create(s.mesh, s.topology, options);
    if (!target || dabs.empty()) {
        state.SkipWithError(target ? "the stroke made no dab" : target.error().c_str());
        return;
    }
    core::PaintLayerStack& stack = (*target)->paintLayerStack();
    for (int i = 0; i < 8; ++i)
        stack.add({.name = "layer " + std::to_string(i + 1)}, stack.size());
    (*target)->setSelection({stack.layer(stack.size() - 1).id, false});
    std::size_t next = 0;
    (*target)->beginStroke(brush);
    for (auto _ : state) {
        const core::PaintChanges& changes = (*target)->paint(s.layers, dabs[next]);
        benchmark::DoNotOptimize(&changes);
        next = (next + 1) % dabs.size();
    }
    const core::TileUndoRecord record = (*target)->endStroke();
    benchmark::DoNotOptimize(record.bytes());
}
BENCHMARK(DabOnPaintLayer)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace
