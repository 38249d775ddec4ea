// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/base/result.h"
#include "core/model/mesh.h"

namespace render {

/** A framebuffer object with an RGBA8 color and a depth attachment, for headless rendering. */
class OffscreenTarget {
public:
    OffscreenTarget() = default;
    ~OffscreenTarget();
    OffscreenTarget(const OffscreenTarget&) = delete;
    OffscreenTarget& operator=(const OffscreenTarget&) = delete;

    /**
     * (Re)creates the attachments, the depth one 32-bit float or, with windowDepth, as a
     * window's (24-bit depth with 8-bit stencil), so what is drawn equals what the window would
     * show; needs a current context.
     */
    core::Status create(int width, int height, bool windowDepth = false);
    /** Binds the framebuffer and sets the viewport to its size. */
    void bind() const;
    unsigned framebuffer() const { return m_fbo; }
    int width() const { return m_width; }
    int height() const { return m_height; }
    /** Reads the color attachment back, top row first. */
    core::Image readColor() const;
    /** Frees the attachments (create() makes them again); the context must be current. */
    void release();

private:
    unsigned m_fbo = 0, m_color = 0, m_depth = 0;
    int m_width = 0, m_height = 0;
};

} // namespace render
