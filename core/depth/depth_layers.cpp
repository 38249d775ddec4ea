// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/depth/depth_layers.h"

#include <chrono>

#include "core/depth/alpha_mask.h"
#include "core/depth/cpu_capture.h"

namespace core {

namespace {
double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}
} // namespace

Result<DepthStack> CpuDepthCapturer::capture(const View& view, const CaptureFaces& faces,
                                             CaptureStats* stats) {
    const auto start = std::chrono::steady_clock::now();
    CpuCaptureOptions options;
    options.cullBackFaces = faces.cullBackFaces;
    options.shownBackFaces = faces.shownBackFaces;
    DepthStack stack = captureDepthLayersCpu(m_mesh, view, options);
    if (stats)
        *stats = {0.0, millisecondsSince(start), 0};
    return stack;
}

Result<DepthLayers> buildDepthLayers(DepthCapturer& capturer, const Mesh& mesh,
                                     const MeshTopology& topology, const View& view,
                                     const DepthLayerOptions& options, ConnectivityEngine* engine) {
    CaptureStats stats;
    auto stack = capturer.capture(view, {options.cullBackFaces, topology.shownBackFaces}, &stats);
    if (!stack)
        return stack.takeError();
    return finishDepthLayers(std::move(stack).value(), stats, mesh, topology, view, options,
                             engine);
}

DepthLayers finishDepthLayers(DepthStack stack, const CaptureStats& captureStats, const Mesh& mesh,
                              const MeshTopology& topology, const View& view,
                              const DepthLayerOptions& options, ConnectivityEngine* engine) {
    DepthLayers layers;
    layers.view = view;
    layers.options = options;
    layers.stack = std::move(stack);
    dropMaskedFragments(layers.stack, mesh, view);
    layers.timings.capture = captureStats;
    const auto start = std::chrono::steady_clock::now();
    layers.geometry = makeSurfaceGeometry(mesh, topology, view, &layers.stack);
    layers.timings.surfaceMs = millisecondsSince(start);
    resegmentDepthLayers(layers, mesh, options, engine);
    return layers;
}

void resegmentDepthLayers(DepthLayers& layers, const Mesh& mesh, const DepthLayerOptions& options,
                          ConnectivityEngine* engine) {
    const bool cull = layers.options.cullBackFaces;
    layers.options = options;
    layers.options.cullBackFaces = cull;

    ConnectivityOptions connectivity;
    connectivity.test = options.test;
    connectivity.threshold = options.threshold;
    connectivity.unitScale = unitScale(mesh);
    connectivity.threads = options.threads;
    auto start = std::chrono::steady_clock::now();
    layers.connectivity = engine
                              ? engine->compute(layers.stack, connectivity, &layers.geometry)
                              : computeConnectivity(layers.stack, connectivity, &layers.geometry);
    layers.timings.connectivityMs = millisecondsSince(start);

    start = std::chrono::steady_clock::now();
    SegmentationTimings segmentation;
    layers.segmentation =
        segmentDepthLayers(layers.stack, layers.connectivity, options.threads, &segmentation);
    layers.timings.segmentationMs = millisecondsSince(start);
    layers.timings.graphMs = segmentation.graphMs;
}

} // namespace core
