// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <vector>

#include "core/model/mesh.h"

namespace render {

/**
 * A base colour texture as both renderers sample it (GL_SRGB8_ALPHA8, mipmapped, repeating)
 * whose rectangles can be replaced while painting: update() uploads the changed texels and
 * recomputes only the mip texels above them, so a dab costs its own size, not the texture's.
 * Needs a current GL context for every call, the one it was created in.
 */
class PaintTexture {
public:
    PaintTexture() = default;
    ~PaintTexture();
    PaintTexture(PaintTexture&& other) noexcept;
    PaintTexture& operator=(PaintTexture&& other) noexcept;
    PaintTexture(const PaintTexture&) = delete;
    PaintTexture& operator=(const PaintTexture&) = delete;

    /**
     * Uploads image (sRGB RGBA8, rows top first) with its mip levels; with linear, the bytes are
     * plain values (GL_RGBA8, e.g. glTF metallic-roughness), filtered as they are.
     */
    void create(const core::Image& image, bool linear = false);
    /**
     * Replaces texels [x, x + width) × [y, y + height) with those of image (the same size as the
     * texture; the rectangle is clamped to it) and updates the mip levels above them, filtered
     * in linear space. The first call reads the mip levels back once to keep a CPU copy.
     */
    void update(const core::Image& image, int x, int y, int width, int height);
    unsigned id() const { return m_id; }
    int width() const { return m_width; }
    int height() const { return m_height; }
    /** Frees the texture; the context must be current. */
    void release();

private:
    unsigned m_id = 0;
    int m_width = 0;
    int m_height = 0;
    int m_levels = 0;
    bool m_linear = false;
    /** Levels 1.. as the GL holds them (RGBA8 rows); empty until the first update. */
    std::vector<std::vector<std::uint8_t>> m_mips;
};

} // namespace render
