// SPDX-License-Identifier: GPL-3.0-or-later
// core/depth/: the depth layers of one view (build_layers): the capture of every fragment
// into a DepthStack, pixel connectivity, and this header, which runs them and the segmentation.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "core/base/result.h"
#include "core/depth/connectivity.h"
#include "core/depth/depth_stack.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"
#include "core/regions/segmentation.h"

namespace core {

/** What the capture step costs, as reported by a DepthCapturer. */
struct CaptureStats {
    double gpuMs = 0.0;     // drawing the fragments (0 for a CPU capturer)
    double resolveMs = 0.0; // sorting them into the DepthStack
    int recaptures = 0;     // extra draws because a buffer had to grow
};

/**
 * Which faces a capture keeps: the front faces, and the back faces where cullBackFaces is off
 * (two-sided) or the triangle is one of shownBackFaces (ascending; MeshTopology::shownBackFaces).
 */
struct CaptureFaces {
    bool cullBackFaces = true;
    std::span<const std::uint32_t> shownBackFaces = {};
};

/**
 * The GPU part of build_layers (docs/architecture.md §2): render implements it on OpenGL; tests and
 * headless use without GL can use CpuDepthCapturer.
 */
class DepthCapturer {
public:
    virtual ~DepthCapturer() = default;
    /** Makes mesh the one captured from now on. */
    virtual void setMesh(const Mesh& mesh) = 0;
    /** Every fragment of view of the faces kept, or an Error. */
    virtual Result<DepthStack> capture(const View& view, const CaptureFaces& faces,
                                       CaptureStats* stats) = 0;
};

/** The CPU stand-in (core/cpu_capture.h). Keeps a copy of the mesh. */
class CpuDepthCapturer : public DepthCapturer {
public:
    void setMesh(const Mesh& mesh) override { m_mesh = mesh; }
    Result<DepthStack> capture(const View& view, const CaptureFaces& faces,
                               CaptureStats* stats) override;

private:
    Mesh m_mesh;
};

/**
 * Computes pixel connectivity for build_layers. Without one, core's CPU reference
 * (computeConnectivity) is used; render offers an OpenGL compute pass with the same output.
 */
class ConnectivityEngine {
public:
    virtual ~ConnectivityEngine() = default;
    virtual Connectivity compute(const DepthStack& stack, const ConnectivityOptions& options,
                                 const SurfaceGeometry* geometry) = 0;
};

struct DepthLayerOptions {
    ConnectionTest test = ConnectionTest::Surface;
    float threshold = 0.001f; // unit-cube units
    bool cullBackFaces = true;
    unsigned threads = 0; // 0 = hardware concurrency
};

/** Milliseconds of the parts of build_layers (the paper's Table 2 splits them like this). */
struct DepthLayerTimings {
    CaptureStats capture;
    double connectivityMs = 0.0;
    double surfaceMs = 0.0;      // the Surface test's planes of the triangles this view shows
    double segmentationMs = 0.0; // region labels and the region graph
    double graphMs = 0.0;        // ... of which assembling the region graph
    double totalMs() const {
        return capture.gpuMs + capture.resolveMs + surfaceMs + connectivityMs + segmentationMs;
    }
};

/** Everything build_layers derives from one view: layers, connectivity, regions, region graph. */
struct DepthLayers {
    View view;
    DepthLayerOptions options;
    DepthStack stack;
    SurfaceGeometry geometry; // the Surface test's per-view planes, kept for re-segmenting
    Connectivity connectivity;
    Segmentation segmentation;
    DepthLayerTimings timings;
};

/**
 * build_layers (docs/architecture.md §3 step 2): capture, pixel connectivity, segmentation, region
 * graph. topology must be buildMeshTopology(mesh). Returns the capture's Error if it fails.
 */
Result<DepthLayers> buildDepthLayers(DepthCapturer& capturer, const Mesh& mesh,
                                     const MeshTopology& topology, const View& view,
                                     const DepthLayerOptions& options,
                                     ConnectivityEngine* engine = nullptr);

/**
 * The CPU part of build_layers, for callers that capture themselves (the GUI captures on its GL
 * thread and finishes on a worker thread): connectivity, segmentation and region graph of stack.
 */
DepthLayers finishDepthLayers(DepthStack stack, const CaptureStats& captureStats, const Mesh& mesh,
                              const MeshTopology& topology, const View& view,
                              const DepthLayerOptions& options,
                              ConnectivityEngine* engine = nullptr);

/**
 * Recomputes connectivity and regions with new options (threshold, test) without capturing
 * again, as the threshold slider does. The capture options (cullBackFaces) are kept.
 */
void resegmentDepthLayers(DepthLayers& layers, const Mesh& mesh, const DepthLayerOptions& options,
                          ConnectivityEngine* engine = nullptr);

} // namespace core
