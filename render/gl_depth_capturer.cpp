// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/gl_depth_capturer.h"

namespace render {

core::Result<core::DepthStack> GlDepthCapturer::capture(const core::View& view,
                                                        const core::CaptureFaces& faces,
                                                        core::CaptureStats* stats) {
    DepthCapture::Options options;
    options.cullBackFaces = faces.cullBackFaces;
    options.shownBackFaces = faces.shownBackFaces;
    DepthCapture::Timings timings;
    auto stack = m_capture.capture(view, options, &timings);
    if (stats)
        *stats = {timings.gpuMs, timings.resolveMs, timings.recaptures};
    return stack;
}

} // namespace render
