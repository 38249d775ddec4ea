// SPDX-License-Identifier: GPL-3.0-or-later
// `bench`: the paper's Table 2 figures on this machine, next to a plain z-buffer pass of the same
// mesh and view measured in the same run (docs/architecture.md §4, §5).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <thread>

#include <sys/resource.h>

#include <epoxy/gl.h>
#include <nlohmann/json.hpp>

#include "app/cli_commands.h"
#include "app/cli_timing.h"
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

    for (const std::string& model : models) {
        PeakMemory modelMemory; // loading and the uploads, once per model
        PeakMemory::reset();
        auto mesh = core::loadMesh(model);
        modelMemory.mark("load");
        if (!mesh)
            return fail(mesh.error());
        render::MeshRenderer renderer;
        render::GlDepthCapturer capturer;
        render::DepthCompositor compositor;
        for (const core::Status& s :
             {renderer.initialize(), capturer.initialize(), compositor.initialize()})
            if (!s)
                return fail(s.error());
        renderer.setMesh(*mesh);
        capturer.setMesh(*mesh);
        if (const core::Status s = compositor.setMesh(*mesh); !s)
            return fail(model + ": " + s.error());
        // The controller, as the GUI drives it: build_layers and strokes go through it.
        core::Document doc;
        doc.setMesh(*mesh, model);
        render::GlConnectivityEngine engine(render::parseConnectivityBackend(args.connectivity)
                                                .value_or(render::ConnectivityBackend::Auto));
        doc.setConnectivityEngine(&engine);
        render::GpuConnectivity gpuConnectivity;
        if (const core::Status s = gpuConnectivity.initialize(); !s)
            return fail(s.error());
        modelMemory.mark("mesh_upload");

        const core::PaintTargetOptions strokeTargetOptions = doc.paintTargetOptions();
        for (const std::string& size : args.sizes) {
            CameraArgs cameraArgs = args.camera;
            cameraArgs.size = size;
            auto view = makeView(cameraArgs, *mesh);
            if (!view)
                return fail(view.error());
            render::OffscreenTarget target;
            if (const core::Status s = target.create(view->width, view->height); !s)
                return fail(s.error());

            // The strokes' target, new for each size (timePaintLayers() below replaces it); the
            // history does not keep the one it replaces.
            core::PaintTargetOptions targetOptions = strokeTargetOptions;
            if (args.targetSize > 0) {
                targetOptions.kind = core::PaintTargetKind::Texture;
                targetOptions.resolution = args.targetSize;
            }
            if (const core::Status s = doc.setPaintTarget(targetOptions); !s)
                return fail(model + ": " + s.error());
            doc.history().clear();
            const core::PaintTarget* strokeTarget = doc.currentPaintTarget();
            const bool strokeTexture =
                strokeTarget && strokeTarget->kind() == core::PaintTargetKind::Texture;
            const json targetJson = {
                {"kind", strokeTexture ? "texture" : "vertex-colors"},
                {"resolution", strokeTexture ? doc.paintTargetOptions().resolution : 0}};
            Samples samples;
            PeakMemory memory = modelMemory;
            std::vector<double> tipMoves; // move_stroke with a textured tip turning along the path
            std::vector<double> symmetricMoves; // and with 4-way symmetry
            std::size_t fragments = 0, regions = 0, layerCount = 0;
            // One warm-up round (shader compilation, buffer growth), then the measured runs,
            // alternating the baseline with the measured work so load affects both alike.
            for (int run = -1; run < runs; ++run) {
                render::DrawOptions plainOptions;
                plainOptions.cullBackFaces = true;
                PeakMemory::reset();
                const double plain = render::timePlainPass(renderer, target, *view, plainOptions);
                memory.mark("plain_pass");
                const auto start = Clock::now();
                if (const core::Status s = doc.buildDepthLayers(capturer, *view); !s)
                    return fail(model + ": " + s.error());
                const double build = msSince(start);
                memory.mark("build_layers");
                const core::DepthLayers* layers = doc.depthLayers();
                if (const core::Status s = compositor.setDepthLayers(*layers); !s)
                    return fail(model + ": " + s.error());
                target.bind();
                // The first draw after a build also shades every fragment once; later draws
                // (paint, pop-up, hover) only pick and compose. Both are reported.
                const auto timedDraw = [&](const render::CompositeOptions& options) {
                    glFinish();
                    const auto drawStart = Clock::now();
                    compositor.draw(options);
                    glFinish();
                    return msSince(drawStart);
                };
                const double firstDraw = timedDraw({});
                const double draw = timedDraw({});
                // A click-to-pop-up at the centre until the picture shows it: the order, the
                // ranks and a draw that picks again. Then a draw with see-through pop-ups.
                glFinish();
                const auto popStart = Clock::now();
                doc.popUpAt({float(view->width) / 2.0f, float(view->height) / 2.0f});
                compositor.setRegionRanks(doc.regionOrder().prunedRanks(false));
                compositor.draw({});
                glFinish();
                const double popUp = msSince(popStart);
                render::CompositeOptions seeThrough;
                seeThrough.popUpOpacity = 0.55f;
                compositor.setRegionRanks(doc.regionOrder().prunedRanks(true));
                timedDraw(seeThrough); // picks again, keeping the fragments under see-through ones
                const double seeThroughDraw = timedDraw(seeThrough);
                memory.mark("draw_layers");
                core::RegionOrder initial = doc.regionOrder();
                initial.reset();
                doc.setRegionOrder(std::move(initial)); // strokes start as they always did
                // Both connectivity engines on the same stack, so the choice can be checked.
                core::ConnectivityOptions connectivityOptions;
                connectivityOptions.unitScale = core::unitScale(*mesh);
                const auto cpuStart = Clock::now();
                core::computeConnectivity(layers->stack, connectivityOptions, &layers->geometry);
                const double cpuConnectivity = msSince(cpuStart);
                double gpuConnectivityMs = 0.0;
                if (!gpuConnectivity.compute(layers->stack, connectivityOptions, &layers->geometry,
                                             &gpuConnectivityMs))
                    gpuConnectivityMs = -1.0;
                memory.mark("connectivity_cpu_gpu");
                const StrokeTimes stroke = timeStroke(doc, *view);
                const core::Brush roundBrush = doc.brush();
                doc.brush().tip = "chalk";
                doc.brush().angleMode = core::TipAngleMode::Stroke;
                doc.brush().jitter.angle = 20.0f;
                const StrokeTimes tipStroke = timeStroke(doc, *view);
                // The same textured tip with 4-way symmetry (mirror X and Z: three copies).
                doc.brush().symmetry.mirrorX = true;
                doc.brush().symmetry.mirrorZ = true;
                const StrokeTimes symmetricStroke = timeStroke(doc, *view);
                doc.brush() = roundBrush;
                memory.mark("strokes");
                if (run < 0)
                    continue;
                tipMoves.insert(tipMoves.end(), tipStroke.moves.begin(), tipStroke.moves.end());
                symmetricMoves.insert(symmetricMoves.end(), symmetricStroke.moves.begin(),
                                      symmetricStroke.moves.end());
                samples.startStroke.insert(samples.startStroke.end(), stroke.starts.begin(),
                                           stroke.starts.end());
                samples.moveStroke.insert(samples.moveStroke.end(), stroke.moves.begin(),
                                          stroke.moves.end());
                samples.dab.insert(samples.dab.end(), stroke.dabs.begin(), stroke.dabs.end());
                const core::DepthLayerTimings& t = layers->timings;
                samples.plain.push_back(plain);
                samples.captureGpu.push_back(t.capture.gpuMs);
                samples.captureResolve.push_back(t.capture.resolveMs);
                samples.connectivity.push_back(t.connectivityMs);
                samples.surface.push_back(t.surfaceMs);
                samples.segmentation.push_back(t.segmentationMs - t.graphMs);
                samples.graph.push_back(t.graphMs);
                samples.buildDepthLayers.push_back(build);
                samples.drawLayers.push_back(draw);
                samples.firstDraw.push_back(firstDraw);
                samples.popUp.push_back(popUp);
                samples.seeThroughDraw.push_back(seeThroughDraw);
                samples.connectivityCpu.push_back(cpuConnectivity);
                samples.connectivityGpu.push_back(gpuConnectivityMs);
                fragments = layers->stack.fragmentCount();
                regions = layers->segmentation.graph.regions.size();
                layerCount = layers->stack.maxLayers();
            }
            const PaintLayerTimes paintLayers = timePaintLayers(doc, *view, runs);
            memory.mark("paint_layers");
            const double plain = median(samples.plain), build = median(samples.buildDepthLayers);
            json row = {
                {"model", model},
                {"vertices", mesh->vertexCount()},
                {"triangles", mesh->triangleCount()},
                {"size", size},
                {"runs", runs},
                {"layers", layerCount},
                {"fragments", fragments},
                {"regions", regions},
                {"plain_pass_ms", plain},
                {"build_layers_ms", build},
                {"build_layers_over_plain", plain > 0 ? build / plain : 0.0},
                {"capture_gpu_ms", median(samples.captureGpu)},
                {"capture_resolve_ms", median(samples.captureResolve)},
                {"connectivity_ms", median(samples.connectivity)},
                {"connectivity_engine", render::connectivityBackendName(engine.backend())},
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
                {"stroke_target", targetJson},
                {"move_stroke_textured_tip_ms", median(tipMoves)},
                {"move_stroke_symmetric_4_ms", median(symmetricMoves)},
                {"peak_rss_mib", memory.toJson()},
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
            std::cerr << model << ' ' << size << ": build_layers " << build
                      << " ms = " << (plain > 0 ? build / plain : 0.0) << " × plain pass (" << plain
                      << " ms), draw_layers " << median(samples.drawLayers) << " ms, start_stroke "
                      << median(samples.startStroke) << " ms, move_stroke "
                      << median(samples.moveStroke) << " ms, peak RSS "
                      << memory.toJson()["all"].get<double>() << " MiB\n";
            results.push_back(std::move(row));
        }
        compositor.release();
        renderer.release();
    }
    const json out = {{"renderer", render::HeadlessContext::rendererName()},
                      {"threads", std::thread::hardware_concurrency()},
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
