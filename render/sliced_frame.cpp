// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/sliced_frame.h"

#include <epoxy/gl.h>

namespace render {

bool SlicedFrame::Key::operator==(const Key& other) const {
    return view.view == other.view.view && view.proj == other.view.proj &&
           view.width == other.view.width && view.height == other.view.height &&
           options == other.options && renderer == other.renderer && textures == other.textures &&
           texturesRevision == other.texturesRevision;
}

core::Result<bool> SlicedFrame::advance(MeshRenderer& renderer, const core::View& view,
                                        const DrawOptions& options, std::size_t sliceTriangles) {
    const Key key{view, options, renderer.revision(), &renderer.textures(),
                  renderer.textures().revision()};
    const bool fresh = !m_started || !(key == m_key);
    if (fresh) {
        if (!m_target.framebuffer() || m_target.width() != view.width ||
            m_target.height() != view.height)
            if (const core::Status made = m_target.create(view.width, view.height, true); !made) {
                release(); // the next call starts again
                return core::Error{made.error()};
            }
        m_key = key;
        m_started = true;
        m_drawn = 0;
        m_triangles = renderer.frameTriangles(options);
    }
    if (isWhole() && !fresh) // a fresh frame is cleared even without triangles
        return true;
    GLint framebuffer = 0, viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_target.framebuffer());
    m_drawn = renderer.drawSlice(view, options, m_drawn, std::max<std::size_t>(sliceTriangles, 1));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(framebuffer));
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    return isWhole();
}

void SlicedFrame::copyTo(unsigned framebuffer) const {
    if (!m_target.framebuffer())
        return;
    glBlitNamedFramebuffer(m_target.framebuffer(), framebuffer, 0, 0, m_target.width(),
                           m_target.height(), 0, 0, m_target.width(), m_target.height(),
                           GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

void SlicedFrame::release() {
    m_target.release();
    m_started = false;
    m_drawn = m_triangles = 0;
}

} // namespace render
