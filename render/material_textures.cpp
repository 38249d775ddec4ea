// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/material_textures.h"

namespace render {

void MaterialTextures::create(const std::vector<core::Image>& textures) {
    release();
    m_baseColor.resize(textures.size());
    m_metallicRoughness.resize(textures.size());
    for (std::size_t i = 0; i < textures.size(); ++i)
        if (!textures[i].empty())
            m_baseColor[i].create(textures[i]);
}

void MaterialTextures::setMetallicRoughness(std::uint32_t texture, const core::Image& image) {
    if (texture >= m_baseColor.size() || m_baseColor[texture].id() == 0 || image.empty())
        return;
    m_metallicRoughness[texture] = PaintTexture();
    m_metallicRoughness[texture].create(image, true);
}

void MaterialTextures::updateTexels(std::uint32_t texture, int x, int y, int width, int height,
                                    const core::Image& image) {
    if (texture < m_baseColor.size())
        m_baseColor[texture].update(image, x, y, width, height);
}

void MaterialTextures::updateMetallicRoughness(std::uint32_t texture, int x, int y, int width,
                                               int height, const core::Image& image) {
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

void MaterialTextures::release() {
    m_baseColor.clear();
    m_metallicRoughness.clear();
}

} // namespace render
