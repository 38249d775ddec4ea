// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/paint_texture.h"

#include <algorithm>
#include <array>
#include <utility>

#include <epoxy/gl.h>

#include "core/base/color.h"
#include "core/paint/targets/paint_target.h"

namespace render {

namespace {

int levelSize(int size, int level) {
    return std::max(1, size >> level);
}
} // namespace

PaintTexture::~PaintTexture() {
    release();
}

PaintTexture::PaintTexture(PaintTexture&& other) noexcept
    : m_id(std::exchange(other.m_id, 0u)), m_width(other.m_width), m_height(other.m_height),
      m_levels(other.m_levels), m_linear(other.m_linear), m_mips(std::move(other.m_mips)) {}

PaintTexture& PaintTexture::operator=(PaintTexture&& other) noexcept {
    if (this != &other) {
        release();
        m_id = std::exchange(other.m_id, 0u);
        m_width = other.m_width;
        m_height = other.m_height;
        m_levels = other.m_levels;
        m_linear = other.m_linear;
        m_mips = std::move(other.m_mips);
    }
    return *this;
}

void PaintTexture::create(const core::Image& image, bool linear) {
    release();
    m_linear = linear;
    m_width = image.width;
    m_height = image.height;
    m_levels = 1;
    for (int size = std::max(image.width, image.height); size > 1; size /= 2)
        ++m_levels;
    glCreateTextures(GL_TEXTURE_2D, 1, &m_id);
    glTextureStorage2D(m_id, m_levels, linear ? GL_RGBA8 : GL_SRGB8_ALPHA8, image.width,
                       image.height);
    // RGBA8 rows are whole words: the GL's default alignment (4) fits, and it stays the default
    // for Qt's own uploads (its glyph cache garbles text under another alignment).
    glTextureSubImage2D(m_id, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.rgba.data());
    glGenerateTextureMipmap(m_id);
    glTextureParameteri(m_id, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(m_id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(m_id, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(m_id, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

void PaintTexture::update(const core::Image& image, int x, int y, int width, int height) {
    if (!m_id || image.width != m_width || image.height != m_height ||
        image.rgba.size() != std::size_t(m_width) * std::size_t(m_height) * 4)
        return;
    int x0 = std::clamp(x, 0, m_width), y0 = std::clamp(y, 0, m_height);
    int x1 = std::clamp(x + width, x0, m_width), y1 = std::clamp(y + height, y0, m_height);
    if (x0 == x1 || y0 == y1)
        return;
    glPixelStorei(GL_UNPACK_ROW_LENGTH, m_width);
    glTextureSubImage2D(m_id, 0, x0, y0, x1 - x0, y1 - y0, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.rgba.data() + (std::size_t(y0) * m_width + x0) * 4);

    if (m_mips.empty() && m_levels > 1) {
        // Once: the levels the GL generated, so later updates filter from the same data.
        m_mips.resize(std::size_t(m_levels - 1));
        for (int level = 1; level < m_levels; ++level) {
            auto& mip = m_mips[std::size_t(level - 1)];
            mip.resize(std::size_t(levelSize(m_width, level)) * levelSize(m_height, level) * 4);
            glGetTextureImage(m_id, level, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(mip.size()),
                              mip.data());
        }
    }

    // A 2 × 2 box filter in linear space, level by level, over the texels above the rectangle.
    std::array<float, 256> identity{};
    for (std::size_t i = 0; i < identity.size(); ++i)
        identity[i] = float(i);
    const std::array<float, 256>& toLinear = m_linear ? identity : core::SrgbTables::get().decode;
    const std::uint8_t* source = image.rgba.data();
    int sourceWidth = m_width, sourceHeight = m_height;
    for (int level = 1; level < m_levels; ++level) {
        const int w = levelSize(m_width, level), h = levelSize(m_height, level);
        x0 = std::min(x0 / 2, w - 1);
        y0 = std::min(y0 / 2, h - 1);
        x1 = std::min((x1 - 1) / 2 + 1, w);
        y1 = std::min((y1 - 1) / 2 + 1, h);
        std::vector<std::uint8_t>& mip = m_mips[std::size_t(level - 1)];
        for (int ty = y0; ty < y1; ++ty) {
            for (int tx = x0; tx < x1; ++tx) {
                float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
                for (int dy = 0; dy < 2; ++dy) {
                    const int sy = std::min(2 * ty + dy, sourceHeight - 1);
                    for (int dx = 0; dx < 2; ++dx) {
                        const int sx = std::min(2 * tx + dx, sourceWidth - 1);
                        const std::uint8_t* s = source + (std::size_t(sy) * sourceWidth + sx) * 4;
                        for (int c = 0; c < 3; ++c)
                            sum[c] += toLinear[s[c]];
                        sum[3] += float(s[3]);
                    }
                }
                std::uint8_t* out = mip.data() + (std::size_t(ty) * w + tx) * 4;
                for (int c = 0; c < 3; ++c)
                    out[c] = m_linear ? std::uint8_t(std::min(255.0f, 0.25f * sum[c] + 0.5f))
                                      : core::linearToSrgb(0.25f * sum[c]);
                out[3] = std::uint8_t(std::min(255.0f, 0.25f * sum[3] + 0.5f));
            }
        }
        glPixelStorei(GL_UNPACK_ROW_LENGTH, w);
        glTextureSubImage2D(m_id, level, x0, y0, x1 - x0, y1 - y0, GL_RGBA, GL_UNSIGNED_BYTE,
                            mip.data() + (std::size_t(y0) * w + x0) * 4);
        source = mip.data();
        sourceWidth = w;
        sourceHeight = h;
    }
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

void PaintTexture::release() {
    if (m_id)
        glDeleteTextures(1, &m_id);
    m_id = 0;
    m_mips.clear();
}

} // namespace render
