// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/depth/depth_layers.h"
#include "render/depth_capture.h"

namespace render {

/** core::DepthCapturer on OpenGL: build_layers' capture step through render::DepthCapture. */
class GlDepthCapturer : public core::DepthCapturer {
public:
    /** Compiles the capture shaders; needs the current context, used for every later call. */
    core::Status initialize() { return m_capture.initialize(); }
    void setMesh(const core::Mesh& mesh) override { m_capture.setMesh(mesh); }
    core::Result<core::DepthStack> capture(const core::View& view, const core::CaptureFaces& faces,
                                           core::CaptureStats* stats) override;
    DepthCapture& depthCapture() { return m_capture; }

private:
    DepthCapture m_capture;
};

} // namespace render
