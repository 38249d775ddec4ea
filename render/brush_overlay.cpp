// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/brush_overlay.h"

#include <algorithm>

#include <epoxy/gl.h>

#include "render/shader_library.h"

namespace render {

struct BrushOverlay::Impl {
    ShaderProgram program;
    GLuint vao = 0; // core profile: a draw needs one, even without attributes
    GLuint maps = 0;
    int width = 0, height = 0;
};

BrushOverlay::BrushOverlay() : m_impl(std::make_unique<Impl>()) {}

BrushOverlay::~BrushOverlay() {
    release();
}

core::Status BrushOverlay::initialize() {
    auto program = ShaderProgram::build({"brush_overlay.vert", "brush_overlay.frag"});
    if (!program)
        return core::Error{program.error()};
    m_impl->program = std::move(program).value();
    if (!m_impl->vao)
        glCreateVertexArrays(1, &m_impl->vao);
    return {};
}

void BrushOverlay::setMaps(int width, int height, std::span<const std::uint8_t> rgba,
                           PixelRect rect) {
    Impl& d = *m_impl;
    if (width <= 0 || height <= 0 || rgba.size() != std::size_t(width) * std::size_t(height) * 4)
        return;
    if (!d.maps || width != d.width || height != d.height) {
        if (d.maps)
            glDeleteTextures(1, &d.maps);
        glCreateTextures(GL_TEXTURE_2D, 1, &d.maps);
        glTextureStorage2D(d.maps, 1, GL_RGBA8, width, height);
        glTextureParameteri(d.maps, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(d.maps, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        d.width = width;
        d.height = height;
        rect = {0, 0, width, height};
    }
    const int x0 = std::clamp(rect.x, 0, width), y0 = std::clamp(rect.y, 0, height);
    const int x1 = std::clamp(rect.x + rect.width, x0, width);
    const int y1 = std::clamp(rect.y + rect.height, y0, height);
    if (x0 == x1 || y0 == y1)
        return;
    glPixelStorei(GL_UNPACK_ROW_LENGTH, width); // alignment stays the default (RGBA8 rows)
    glTextureSubImage2D(d.maps, 0, x0, y0, x1 - x0, y1 - y0, GL_RGBA, GL_UNSIGNED_BYTE,
                        rgba.data() + (std::size_t(y0) * width + x0) * 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

void BrushOverlay::draw(const BrushOverlayOptions& options) {
    Impl& d = *m_impl;
    if (!d.program.valid() || options.viewWidth <= 0 || options.viewHeight <= 0)
        return;
    const bool maps = !options.maps.empty() && d.maps;
    const bool ring = options.radius > 0.0f;
    if (!maps && !ring)
        return;
    glViewport(0, 0, options.viewWidth, options.viewHeight);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    d.program.use();
    glUniform2f(d.program.uniform("uViewSize"), float(options.viewWidth),
                float(options.viewHeight));
    glUniform1i(d.program.uniform("uMaps"), 0);
    const GLint rectLocation = d.program.uniform("uRect");
    const GLint ringLocation = d.program.uniform("uRing");
    glBindVertexArray(d.vao);
    if (maps) {
        // Texel (x, y) is pixel (x, y) of the view: the shader fetches with y down.
        const PixelRect& r = options.maps;
        glBindTextureUnit(0, d.maps);
        glUniform1i(ringLocation, 0);
        glUniform4f(rectLocation, float(r.x), float(r.y), float(std::min(r.x + r.width, d.width)),
                    float(std::min(r.y + r.height, d.height)));
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    if (ring) {
        const float extent = options.radius + 3.0f;
        glUniform1i(ringLocation, 1);
        glUniform2f(d.program.uniform("uCenter"), options.center.x, options.center.y);
        glUniform1f(d.program.uniform("uRadius"), options.radius);
        glUniform4f(rectLocation, options.center.x - extent, options.center.y - extent,
                    options.center.x + extent, options.center.y + extent);
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }
    glBindVertexArray(0);
    glUseProgram(0);
    glDisable(GL_BLEND);
}

void BrushOverlay::release() {
    if (!m_impl)
        return;
    Impl& d = *m_impl;
    if (d.maps)
        glDeleteTextures(1, &d.maps);
    if (d.vao)
        glDeleteVertexArrays(1, &d.vao);
    d.maps = d.vao = 0;
    d.width = d.height = 0;
    d.program = ShaderProgram();
}

} // namespace render
