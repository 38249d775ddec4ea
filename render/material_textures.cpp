// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/material_textures.h"

#include <algorithm>

#include <epoxy/gl.h>

namespace render {

void MaterialTextures::create(const std::vector<core::Image>& textures) {
    release();
    ++m_revision;
    m_baseColor.resize(textures.size());
    m_metallicRoughness.resize(textures.size());
    m_linearViews.assign(textures.size(), 0);
    for (std::size_t i = 0; i < textures.size(); ++i)
        if (!textures[i].empty()) {
            m_baseColor[i].create(textures[i]);
            m_linearViews[i] = makeLinearView(m_baseColor[i].id());
        }
}

unsigned MaterialTextures::makeLinearView(unsigned texture) {
    GLint levels = 0;
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    GLuint view = 0;
    glGenTextures(1, &view);
    glTextureView(view, GL_TEXTURE_2D, texture, GL_RGBA8, 0, GLuint(std::max(levels, 1)), 0, 1);
    glTextureParameteri(view, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(view, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(view, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(view, GL_TEXTURE_WRAP_T, GL_REPEAT);
    return view;
}

void MaterialTextures::setMetallicRoughness(std::uint32_t texture, const core::Image& image) {
    if (texture >= m_baseColor.size() || m_baseColor[texture].id() == 0 || image.empty())
        return;
    ++m_revision;
    m_metallicRoughness[texture] = PaintTexture();
    m_metallicRoughness[texture].create(image, true);
}

void MaterialTextures::updateTexels(std::uint32_t texture, int x, int y, int width, int height,
                                    const core::Image& image) {
    ++m_revision;
    if (texture < m_baseColor.size())
        m_baseColor[texture].update(image, x, y, width, height);
}

void MaterialTextures::updateMetallicRoughness(std::uint32_t texture, int x, int y, int width,
                                               int height, const core::Image& image) {
    ++m_revision;
    if (texture < m_metallicRoughness.size() && m_metallicRoughness[texture].id() != 0)
        m_metallicRoughness[texture].update(image, x, y, width, height);
}

const PaintTexture* MaterialTextures::baseColor(std::size_t texture) const {
    return texture < m_baseColor.size() && m_baseColor[texture].id() != 0 ? &m_baseColor[texture]
                                                                          : nullptr;
}

const PaintTexture* MaterialTextures::metallicRoughness(std::size_t texture) const {
    return texture < m_metallicRoughness.size() && m_metallicRoughness[texture].id() != 0
               ? &m_metallicRoughness[texture]
               : nullptr;
}

unsigned MaterialTextures::linearView(std::size_t texture) const {
    return texture < m_linearViews.size() ? m_linearViews[texture] : 0u;
}

void MaterialTextures::release() {
    ++m_revision;
    for (unsigned view : m_linearViews)
        if (view)
            glDeleteTextures(1, &view);
    m_linearViews.clear();
    m_baseColor.clear();
    m_metallicRoughness.clear();
}

} // namespace render
