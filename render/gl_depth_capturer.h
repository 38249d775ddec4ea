// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/depth/depth_layers.h"
#include "render/depth_capture.h"

namespace render {

/** core::LayerCapturer on OpenGL: build_layers' capture step through render::LayerCapture. */
class GlLayerCapturer : public core::LayerCapturer {
public:
    /** Compiles the capture shaders; needs the current context, used for every later call. */
    core::Status initialize() { return m_capture.initialize(); }
    void setMesh(const core::Mesh& mesh) override { m_capture.setMesh(mesh); }
    core::Result<core::LayerStack> capture(const core::View& view, bool cullBackFaces,
                                           core::CaptureStats* stats) override;
    LayerCapture& layerCapture() { return m_capture; }

private:
    LayerCapture m_capture;
};

} // namespace render
