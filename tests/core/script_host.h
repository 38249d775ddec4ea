// SPDX-License-Identifier: GPL-3.0-or-later
// The script host of the core tests (no window, the CPU capturer builds the depth layers) and a
// session of scripts over the overlapping quads.
#pragma once

#include <gtest/gtest.h>

#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/document/script.h"
#include "core/paint/targets/paint_target.h"
#include "tests/core/test_scenes.h"

namespace core_test {

/** Builds a document's depth layers with the CPU capturer. */
class CpuScriptHost final : public core::ScriptHost {
public:
    core::Status buildDepthLayers(core::Document& doc, const core::View& view) override {
        capturer.setMesh(doc.mesh());
        return doc.buildDepthLayers(capturer, view);
    }
    core::CpuDepthCapturer capturer;
};

/**
 * overlappingQuads() in a document with a texture target of resolution², and a script runner on
 * it in the 96 × 64 pixelView.
 */
struct QuadsScriptSession {
    core::Document doc;
    CpuScriptHost host;
    core::ScriptRunner runner{doc, host, pixelView(96, 64)};

    explicit QuadsScriptSession(int resolution) {
        doc.setMesh(overlappingQuads(), "two quads");
        core::PaintTargetOptions options;
        options.resolution = resolution;
        EXPECT_TRUE(doc.setPaintTarget(options).ok());
    }
};

} // namespace core_test
