// SPDX-License-Identifier: GPL-3.0-or-later
// `bench`: the paper's Table 2 figures on this machine, next to a plain z-buffer pass of the same
// mesh and view measured in the same run (docs/architecture.md §4, §5).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <thread>

#include <sys/resource.h>

#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

#include "app/cli_commands.h"
#include "app/cli_timing.h"
#include "core/base/huge_pages.h"
#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/io/mesh_io.h"
#include "core/paint/targets/paint_target.h"
#include "render/depth_compositor.h"
#include "render/gl_context.h"
#include "render/gl_depth_capturer.h"
#include "render/gpu_connectivity.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"

namespace cli {

namespace {
using nlohmann::json;
/**
 * Peak resident memory (VmHWM) in MiB. Between stages the peak is reset to the current size
 * (/proc/self/clear_refs, "5"), so each stage reports its own peak; where that is refused, the
 * peaks are the process's so far (also ru_maxrss where /proc is missing).
 */
struct PeakMemory {
    std::map<std::string, double> stages; // the largest peak of each stage over the runs

    static void reset() {
        std::ofstream clear("/proc/self/clear_refs");
        clear << "5";
    }
    static double peakMiB() {
        std::ifstream status("/proc/self/status");
        std::string line;
        while (std::getline(status, line))
            if (line.rfind("VmHWM:", 0) == 0)
                return std::stod(line.substr(6)) / 1024.0; // kB
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        return double(usage.ru_maxrss) / 1024.0;
    }
    /** Records the peak since the last reset as `stage`'s and starts the next stage. */
    void mark(const std::string& stage) {
        double& peak = stages[stage];
        peak = std::max(peak, peakMiB());
        reset();
    }
    json toJson() const {
        json out = json::object();
        double all = 0.0;
        for (const auto& [stage, peak] : stages) {
            out[stage] = std::round(peak * 10.0) / 10.0;
            all = std::max(all, peak);
        }
        out["all"] = std::round(all * 10.0) / 10.0;
        return out;
    }
};

/** Medians of every timed part over the runs of one model at one size. */
struct Samples {
    std::vector<double> plain, captureGpu, captureResolve, surface, connectivity, segmentation,
        graph, buildDepthLayers, drawLayers, firstDraw, startStroke, moveStroke, dab,
        connectivityCpu, connectivityGpu, popUp, seeThroughDraw;
};

struct StrokeTimes {
    std::vector<double> starts;
    std::vector<double> moves;
    std::vector<double> dabs; // the paint target's share, per dab
};

/**
 * A fixed long stroke at R = 32 px: left to right across the middle row of the view in 4 px
 * steps. Where the row leaves the surface the stroke ends, and it starts again where the row
 * meets the surface next. Moves that paint are timed (including the dabs on the target).
 */
StrokeTimes timeStroke(core::Document& doc, const core::View& view) {
    StrokeTimes times;
    const core::DepthStack& stack = doc.depthLayers()->stack;
    const int y = view.height / 2;
    doc.brush().radius = 32.0f;
    core::PaintChanges changes;
    int strokes = 0;
    for (int x = view.width / 10; x < view.width * 9 / 10; x += 4) {
        const core::StrokePoint point{{float(x) + 0.5f, float(y) + 0.5f}, 1.0f};
        const bool onSurface = stack.layerCount(std::size_t(y) * view.width + x) > 0;
        if (!onSurface) {
            if (doc.inStroke())
                doc.endStroke();
            continue;
        }
        const auto start = Clock::now();
        if (!doc.inStroke()) {
            if (!doc.beginStroke(point, changes))
                return times;
            times.starts.push_back(msSince(start));
            ++strokes;
            continue;
        }
        doc.moveStroke(point, changes);
        const double ms = msSince(start);
        if (!changes.empty()) { // a move shorter than the dab spacing only updates the path
            times.moves.push_back(ms);
            const core::Document::DabStats& dabs = doc.lastDabStats();
            if (dabs.dabs > 0)
                times.dabs.push_back(dabs.targetMs / double(dabs.dabs));
        }
    }
    if (doc.inStroke())
        doc.endStroke();
    // Leave the target as it was for the next run.
    for (int i = 0; i < strokes; ++i)
        doc.undo(changes);
    return times;
}
constexpr int kPaintLayerTexture = 4096;
constexpr int kPaintLayers = 8;

struct PaintLayerTimes {
    std::vector<double> moveNone, dabNone, moveLayers, dabLayers;
    std::size_t stackBytes = 0, targetBytes = 0;
    std::string error;
};

/**
 * The paint-layer stack's cost on a kPaintLayerTexture² texture target: the bench stroke on the
 * base, then with kPaintLayers paint layers painting the top one in all three channels (each dab
 * recomputes the composite's touched tiles), and the stack's memory after it. Leaves the
 * document's target replaced.
 */
PaintLayerTimes timePaintLayers(core::Document& doc, const core::View& view, int runs) {
    PaintLayerTimes times;
    core::PaintTargetOptions options = doc.paintTargetOptions();
    options.kind = core::PaintTargetKind::Texture;
    options.resolution = kPaintLayerTexture;
    if (const core::Status s = doc.setPaintTarget(options); !s) {
        times.error = s.error();
        return times;
    }
    const core::Brush brush = doc.brush();
    for (int run = 0; run < std::max(1, runs / 2); ++run) {
        const StrokeTimes none = timeStroke(doc, view);
        times.moveNone.insert(times.moveNone.end(), none.moves.begin(), none.moves.end());
        times.dabNone.insert(times.dabNone.end(), none.dabs.begin(), none.dabs.end());
    }
    core::PaintChanges changes;
    for (int i = 0; i < kPaintLayers; ++i) {
        core::PaintLayerSettings settings;
        settings.name = "layer " + std::to_string(i + 1);
        if (auto added = doc.addPaintLayer(settings, changes); !added) {
            times.error = added.error();
            return times;
        }
    }
    doc.brush().paintBaseColor = true;
    doc.brush().paintRoughness = true;
    doc.brush().paintMetallic = true;
    for (int run = 0; run < std::max(1, runs / 2); ++run) {
        const StrokeTimes layered = timeStroke(doc, view);
        times.moveLayers.insert(times.moveLayers.end(), layered.moves.begin(), layered.moves.end());
        times.dabLayers.insert(times.dabLayers.end(), layered.dabs.begin(), layered.dabs.end());
    }
    // Painted once more and kept, for the memory the layers hold.
    core::PaintChanges kept;
    const int y = view.height / 2;
    const core::DepthStack& stack = doc.depthLayers()->stack;
    for (int x = view.width / 10; x < view.width * 9 / 10; ++x)
        if (stack.layerCount(std::size_t(y) * view.width + x) > 0) {
            if (doc.beginStroke({{float(x) + 0.5f, float(y) + 0.5f}, 1.0f}, kept))
                doc.endStroke();
            break;
        }
    if (const core::PaintTarget* painted = doc.currentPaintTarget();
        painted && painted->paintLayers()) {
        times.stackBytes = painted->paintLayers()->paintLayerStack().layerBytes();
        times.targetBytes = painted->bytes();
    }
    doc.brush() = brush;
    return times;
}

/**
 * One model's bench: the mesh uploaded to the plain renderer, the capturer and the compositor,
 * and the controller as the GUI drives it (build_layers and strokes go through it).
 */
struct ModelBench {
    std::string model;
    core::Mesh mesh;
    render::MeshRenderer renderer;
    render::GlDepthCapturer capturer;
    render::DepthCompositor compositor;
    core::Document doc;
    std::optional<render::GlConnectivityEngine> engine;
    render::GpuConnectivity gpuConnectivity;
    PeakMemory memory; // loading and the uploads, once per model
    core::PaintTargetOptions strokeTargetOptions;
};

/** One size of a model's bench: its view and target, and the samples of its measured runs. */
struct SizeBench {
    std::string size;
    core::View view;
    render::OffscreenTarget target;
    json targetJson; // the strokes' target
    Samples samples;
    PeakMemory memory;
    std::vector<double> tipMoves;       // move_stroke with a textured tip turning along the path
    std::vector<double> symmetricMoves; // and with 4-way symmetry
    std::size_t fragments = 0, regions = 0, layerCount = 0;
};

/** What one run measures (the warm-up run's figures are dropped). */
struct Run {
    double plain = 0.0, build = 0.0, firstDraw = 0.0, draw = 0.0, popUp = 0.0, seeThroughDraw = 0.0,
           cpuConnectivity = 0.0, gpuConnectivity = 0.0;
    StrokeTimes stroke, tipStroke, symmetricStroke;
};

/** Loads model and uploads it everywhere; an Error with the message the command fails with. */
core::Status setUpModel(ModelBench& bench, const std::string& model, const BenchArgs& args) {
    bench.model = model;
    PeakMemory::reset();
    auto mesh = core::loadMesh(model);
    bench.memory.mark("load");
    if (!mesh)
        return mesh.takeError();
    bench.mesh = std::move(mesh).value();
    for (const core::Status& s :
         {bench.renderer.initialize(), bench.capturer.initialize(), bench.compositor.initialize()})
        if (!s)
            return s;
    bench.renderer.setMesh(bench.mesh);
    bench.capturer.setMesh(bench.mesh);
    if (const core::Status s = bench.compositor.setMesh(bench.mesh); !s)
        return core::Error{model + ": " + s.error()};
    bench.doc.setMesh(bench.mesh, model);
    bench.engine.emplace(render::parseConnectivityBackend(args.connectivity)
                             .value_or(render::ConnectivityBackend::Auto));
    bench.doc.setConnectivityEngine(&*bench.engine);
    if (const core::Status s = bench.gpuConnectivity.initialize(); !s)
        return s;
    bench.memory.mark("mesh_upload");
    bench.strokeTargetOptions = bench.doc.paintTargetOptions();
    return {};
}

/**
 * The view and offscreen target of one size, and the strokes' target, new for each size
 * (timePaintLayers() replaces it); the history does not keep the one it replaces.
 */
core::Status setUpSize(ModelBench& bench, SizeBench& sized, const BenchArgs& args) {
    CameraArgs cameraArgs = args.camera;
    cameraArgs.size = sized.size;
    auto view = makeView(cameraArgs, bench.mesh);
    if (!view)
        return view.takeError();
    sized.view = *view;
    if (const core::Status s = sized.target.create(sized.view.width, sized.view.height); !s)
        return s;
    core::PaintTargetOptions targetOptions = bench.strokeTargetOptions;
    if (args.targetSize > 0) {
        targetOptions.kind = core::PaintTargetKind::Texture;
        targetOptions.resolution = args.targetSize;
    }
    if (const core::Status s = bench.doc.setPaintTarget(targetOptions); !s)
        return core::Error{bench.model + ": " + s.error()};
    bench.doc.history().clear();
    const core::PaintTarget* strokeTarget = bench.doc.currentPaintTarget();
    const bool strokeTexture =
        strokeTarget && strokeTarget->kind() == core::PaintTargetKind::Texture;
    sized.targetJson = {
        {"kind", strokeTexture ? "texture" : "vertex-colors"},
        {"resolution", strokeTexture ? bench.doc.paintTargetOptions().resolution : 0}};
    sized.memory = bench.memory;
    return {};
}

/** The plain z-buffer pass, then build_layers through the document, handed to the compositor. */
core::Status timePlainAndBuild(ModelBench& bench, SizeBench& sized, Run& run) {
    render::DrawOptions plainOptions;
    plainOptions.cullBackFaces = true;
    PeakMemory::reset();
    run.plain = render::timePlainPass(bench.renderer, sized.target, sized.view, plainOptions);
    sized.memory.mark("plain_pass");
    const auto start = Clock::now();
    if (const core::Status s = bench.doc.buildDepthLayers(bench.capturer, sized.view); !s)
        return core::Error{bench.model + ": " + s.error()};
    run.build = msSince(start);
    sized.memory.mark("build_layers");
    if (const core::Status s = bench.compositor.setDepthLayers(*bench.doc.depthLayers()); !s)
        return core::Error{bench.model + ": " + s.error()};
    return {};
}

/**
 * The draws of the built layers: the first after the build, a later one, a click-to-pop-up and a
 * draw with see-through pop-ups. Leaves the region order as the build made it.
 */
void timeDraws(ModelBench& bench, SizeBench& sized, Run& run) {
    render::DepthCompositor& compositor = bench.compositor;
    core::Document& doc = bench.doc;
    sized.target.bind();
    // The first draw after a build also shades every fragment once; later draws (paint,
    // pop-up, hover) only pick and compose. Both are reported.
    const auto timedDraw = [&](const render::CompositeOptions& options) {
        glFinish();
        const auto drawStart = Clock::now();
        compositor.draw(options);
        glFinish();
        return msSince(drawStart);
    };
    run.firstDraw = timedDraw({});
    run.draw = timedDraw({});
    // A click-to-pop-up at the centre until the picture shows it: the order, the ranks and a
    // draw that picks again. Then a draw with see-through pop-ups.
    glFinish();
    const auto popStart = Clock::now();
    doc.popUpAt({float(sized.view.width) / 2.0f, float(sized.view.height) / 2.0f});
    compositor.setRegionRanks(doc.regionOrder().prunedRanks(false));
    compositor.draw({});
    glFinish();
    run.popUp = msSince(popStart);
    render::CompositeOptions seeThrough;
    seeThrough.popUpOpacity = 0.55f;
    compositor.setRegionRanks(doc.regionOrder().prunedRanks(true));
    timedDraw(seeThrough); // picks again, keeping the fragments under see-through ones
    run.seeThroughDraw = timedDraw(seeThrough);
    sized.memory.mark("draw_layers");
    core::RegionOrder initial = doc.regionOrder();
    initial.reset();
    doc.setRegionOrder(std::move(initial)); // strokes start as they always did
}

/** Both connectivity engines on the same stack, so the choice can be checked. */
void timeConnectivityEngines(ModelBench& bench, SizeBench& sized, Run& run) {
    const core::DepthLayers* layers = bench.doc.depthLayers();
    core::ConnectivityOptions connectivityOptions;
    connectivityOptions.unitScale = core::unitScale(bench.mesh);
    const auto cpuStart = Clock::now();
    core::computeConnectivity(layers->stack, connectivityOptions, &layers->geometry);
    run.cpuConnectivity = msSince(cpuStart);
    run.gpuConnectivity = 0.0;
    if (!bench.gpuConnectivity.compute(layers->stack, connectivityOptions, &layers->geometry,
                                       &run.gpuConnectivity))
        run.gpuConnectivity = -1.0;
    sized.memory.mark("connectivity_cpu_gpu");
}

/** The bench stroke with the round brush, a textured tip, and the tip with 4-way symmetry. */
void timeStrokes(ModelBench& bench, SizeBench& sized, Run& run) {
    core::Document& doc = bench.doc;
    run.stroke = timeStroke(doc, sized.view);
    const core::Brush roundBrush = doc.brush();
    doc.brush().tip = "chalk";
    doc.brush().angleMode = core::TipAngleMode::Stroke;
    doc.brush().jitter.angle = 20.0f;
    run.tipStroke = timeStroke(doc, sized.view);
    // The same textured tip with 4-way symmetry (mirror X and Z: three copies).
    doc.brush().symmetry.mirrorX = true;
    doc.brush().symmetry.mirrorZ = true;
    run.symmetricStroke = timeStroke(doc, sized.view);
    doc.brush() = roundBrush;
    sized.memory.mark("strokes");
}

void append(std::vector<double>& to, const std::vector<double>& values) {
    to.insert(to.end(), values.begin(), values.end());
}

/** A measured run's figures added to the size's samples. */
void record(const ModelBench& bench, SizeBench& sized, const Run& run) {
    Samples& samples = sized.samples;
    append(sized.tipMoves, run.tipStroke.moves);
    append(sized.symmetricMoves, run.symmetricStroke.moves);
    append(samples.startStroke, run.stroke.starts);
    append(samples.moveStroke, run.stroke.moves);
    append(samples.dab, run.stroke.dabs);
    const core::DepthLayers* layers = bench.doc.depthLayers();
    const core::DepthLayerTimings& t = layers->timings;
    samples.plain.push_back(run.plain);
    samples.captureGpu.push_back(t.capture.gpuMs);
    samples.captureResolve.push_back(t.capture.resolveMs);
    samples.connectivity.push_back(t.connectivityMs);
    samples.surface.push_back(t.surfaceMs);
    samples.segmentation.push_back(t.segmentationMs - t.graphMs);
    samples.graph.push_back(t.graphMs);
    samples.buildDepthLayers.push_back(run.build);
    samples.drawLayers.push_back(run.draw);
    samples.firstDraw.push_back(run.firstDraw);
    samples.popUp.push_back(run.popUp);
    samples.seeThroughDraw.push_back(run.seeThroughDraw);
    samples.connectivityCpu.push_back(run.cpuConnectivity);
    samples.connectivityGpu.push_back(run.gpuConnectivity);
    sized.fragments = layers->stack.fragmentCount();
    sized.regions = layers->segmentation.graph.regions.size();
    sized.layerCount = layers->stack.maxLayers();
}

/**
 * One warm-up run (shader compilation, buffer growth), then the measured runs, alternating the
 * baseline with the measured work so load affects both alike.
 */
core::Status runSize(ModelBench& bench, SizeBench& sized, int runs) {
    for (int r = -1; r < runs; ++r) {
        Run run;
        if (const core::Status s = timePlainAndBuild(bench, sized, run); !s)
            return s;
        timeDraws(bench, sized, run);
        timeConnectivityEngines(bench, sized, run);
        timeStrokes(bench, sized, run);
        if (r >= 0)
            record(bench, sized, run);
    }
    return {};
}

/** The result row of one model at one size. */
json resultRow(const ModelBench& bench, const SizeBench& sized, const PaintLayerTimes& paintLayers,
               int runs) {
    const Samples& samples = sized.samples;
    const double plain = median(samples.plain), build = median(samples.buildDepthLayers);
    return {
        {"model", bench.model},
        {"vertices", bench.mesh.vertexCount()},
        {"triangles", bench.mesh.triangleCount()},
        {"size", sized.size},
        {"runs", runs},
        {"layers", sized.layerCount},
        {"fragments", sized.fragments},
        {"regions", sized.regions},
        {"plain_pass_ms", plain},
        {"build_layers_ms", build},
        {"build_layers_over_plain", plain > 0 ? build / plain : 0.0},
        {"capture_gpu_ms", median(samples.captureGpu)},
        {"capture_resolve_ms", median(samples.captureResolve)},
        {"connectivity_ms", median(samples.connectivity)},
        {"connectivity_engine", render::connectivityBackendName(bench.engine->backend())},
        {"connectivity_cpu_ms", median(samples.connectivityCpu)},
        {"connectivity_gpu_ms", median(samples.connectivityGpu)},
        {"surface_planes_ms", median(samples.surface)},
        {"segmentation_ms", median(samples.segmentation)},
        {"graph_ms", median(samples.graph)},
        {"draw_layers_ms", median(samples.drawLayers)},
        {"first_draw_after_build_ms", median(samples.firstDraw)},
        {"pop_up_ms", median(samples.popUp)},
        {"draw_layers_see_through_ms", median(samples.seeThroughDraw)},
        {"start_stroke_ms", median(samples.startStroke)},
        {"move_stroke_ms", median(samples.moveStroke)},
        {"move_stroke_p95_ms", percentile(samples.moveStroke, 0.95)},
        {"dab_on_target_ms", median(samples.dab)},
        {"stroke_target", sized.targetJson},
        {"move_stroke_textured_tip_ms", median(sized.tipMoves)},
        {"move_stroke_symmetric_4_ms", median(sized.symmetricMoves)},
        {"peak_rss_mib", sized.memory.toJson()},
        {"paint_layers",
         {{"texture", kPaintLayerTexture},
          {"layers", kPaintLayers},
          {"move_stroke_no_layers_ms", median(paintLayers.moveNone)},
          {"dab_no_layers_ms", median(paintLayers.dabNone)},
          {"move_stroke_ms", median(paintLayers.moveLayers)},
          {"dab_on_top_layer_ms", median(paintLayers.dabLayers)},
          {"stack_bytes", paintLayers.stackBytes},
          {"target_bytes", paintLayers.targetBytes},
          {"error", paintLayers.error}}},
    };
}

/** The line on stderr that sums up one model at one size. */
void printSummary(const ModelBench& bench, const SizeBench& sized) {
    const Samples& samples = sized.samples;
    const double plain = median(samples.plain), build = median(samples.buildDepthLayers);
    std::cerr << bench.model << ' ' << sized.size << ": build_layers " << build
              << " ms = " << (plain > 0 ? build / plain : 0.0) << " × plain pass (" << plain
              << " ms), draw_layers " << median(samples.drawLayers) << " ms, start_stroke "
              << median(samples.startStroke) << " ms, move_stroke " << median(samples.moveStroke)
              << " ms, peak RSS " << sized.memory.toJson()["all"].get<double>() << " MiB\n";
}

/** Every size of one model, each a row of results; an Error with the command's message. */
core::Status benchModel(const std::string& model, const BenchArgs& args, int runs, json& results) {
    ModelBench bench;
    if (const core::Status s = setUpModel(bench, model, args); !s)
        return s;
    for (const std::string& size : args.sizes) {
        SizeBench sized;
        sized.size = size;
        if (const core::Status s = setUpSize(bench, sized, args); !s)
            return s;
        if (const core::Status s = runSize(bench, sized, runs); !s)
            return s;
        const PaintLayerTimes paintLayers = timePaintLayers(bench.doc, sized.view, runs);
        sized.memory.mark("paint_layers");
        json row = resultRow(bench, sized, paintLayers, runs);
        printSummary(bench, sized);
        results.push_back(std::move(row));
    }
    bench.compositor.release();
    bench.renderer.release();
    return {};
}

} // namespace

int runBench(const BenchArgs& args) {
    auto context = render::HeadlessContext::create();
    if (!context)
        return fail(context.error());
    const int runs = std::max(args.runs, 1);
    json results = json::array();
    std::vector<std::string> models = args.models;
    if (models.empty())
        models = {"builtin:trefoil"};
    for (const std::string& model : models)
        if (const core::Status s = benchModel(model, args, runs, results); !s)
            return fail(s.error());
    const json out = {{"renderer", render::HeadlessContext::rendererName()},
                      {"threads", std::thread::hardware_concurrency()},
                      {"huge_pages", core::usesHugePages()},
                      {"results", results}};
    if (!args.jsonOut.empty()) {
        std::ofstream file(args.jsonOut);
        file << jsonText(out, 2) << '\n';
        if (!file)
            return fail(args.jsonOut + ": write failed");
    }
    std::cout << jsonText(out, 2) << '\n';
    return 0;
}

} // namespace cli
