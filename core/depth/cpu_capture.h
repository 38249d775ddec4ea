// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <span>

#include "core/depth/depth_stack.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"

namespace core {

struct CpuCaptureOptions {
    bool cullBackFaces = true; // false: two-sided, back faces are captured too
    unsigned threads = 0;      // 0 = std::thread::hardware_concurrency()
    /** Ascending triangles whose back faces are captured anyway (MeshTopology::shownBackFaces). */
    std::span<const std::uint32_t> shownBackFaces = {};
};

/**
 * A CPU stand-in for the GL layer capture (render::DepthCapture), for tests and headless use
 * without GL: rasterizes every triangle at pixel centres with a fill rule like GL's (vertices
 * snapped to 1/256 pixel, a pixel centre on a shared edge covered exactly once) into a DepthStack
 * sorted front to back, ties by triangle id. Depth is the perspective-correct positive view depth.
 * Front faces are counter-clockwise in normalized device coordinates, as GL's default. No clipping:
 * a triangle with a vertex at or behind the eye plane (clip w <= 0) or beyond ±2^20 pixels is
 * skipped, and so are fragments outside the near/far planes. Results do not depend on the thread
 * count. An empty or invalid view gives a stack without fragments.
 */
DepthStack captureDepthLayersCpu(const Mesh& mesh, const View& view,
                                 const CpuCaptureOptions& options = {});

} // namespace core
