// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/offscreen_target.h"

#include <cstring>

#include <epoxy/gl.h>

namespace render {

OffscreenTarget::~OffscreenTarget() {
    release();
}

void OffscreenTarget::release() {
    if (m_fbo)
        glDeleteFramebuffers(1, &m_fbo);
    if (m_color)
        glDeleteRenderbuffers(1, &m_color);
    if (m_depth)
        glDeleteRenderbuffers(1, &m_depth);
    m_fbo = m_color = m_depth = 0;
}

core::Status OffscreenTarget::create(int width, int height, bool windowDepth) {
    release();
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
    if (width <= 0 || height <= 0 || width > maxSize || height > maxSize)
        return core::Error{"offscreen target: size " + std::to_string(width) + "x" +
                           std::to_string(height) + " is not supported (maximum " +
                           std::to_string(maxSize) + ")"};
    m_width = width;
    m_height = height;
    glCreateRenderbuffers(1, &m_color);
    glNamedRenderbufferStorage(m_color, GL_RGBA8, width, height);
    glCreateRenderbuffers(1, &m_depth);
    glNamedRenderbufferStorage(m_depth, windowDepth ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT32F,
                               width, height);
    glCreateFramebuffers(1, &m_fbo);
    glNamedFramebufferRenderbuffer(m_fbo, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_color);
    glNamedFramebufferRenderbuffer(m_fbo,
                                   windowDepth ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                                   GL_RENDERBUFFER, m_depth);
    if (glCheckNamedFramebufferStatus(m_fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        release();
        return core::Error{"offscreen target: framebuffer incomplete"};
    }
    return {};
}

void OffscreenTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
    glViewport(0, 0, m_width, m_height);
}

core::Image OffscreenTarget::readColor() const {
    core::Image image;
    image.width = m_width;
    image.height = m_height;
    image.rgba.resize(std::size_t(m_width) * m_height * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_fbo);
    glReadPixels(0, 0, m_width, m_height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    // GL's rows start at the bottom; images here are top row first.
    const std::size_t rowBytes = std::size_t(m_width) * 4;
    std::vector<std::uint8_t> row(rowBytes);
    for (int y = 0; y < m_height / 2; ++y) {
        std::uint8_t* a = image.rgba.data() + y * rowBytes;
        std::uint8_t* b = image.rgba.data() + (m_height - 1 - y) * rowBytes;
        std::memcpy(row.data(), a, rowBytes);
        std::memcpy(a, b, rowBytes);
        std::memcpy(b, row.data(), rowBytes);
    }
    return image;
}

} // namespace render
