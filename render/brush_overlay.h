// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include <glm/vec2.hpp>

#include "core/base/result.h"

namespace render {

/** A pixel rectangle, y down: [x, x + width) × [y, y + height). */
struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;
    bool empty() const { return width <= 0 || height <= 0; }
};

struct BrushOverlayOptions {
    int viewWidth = 0, viewHeight = 0;
    /** Draw the maps within this rectangle (empty: none). */
    PixelRect maps;
    /** The brush outline: a ring of radius pixels about center (pixels, y down); 0: none. */
    glm::vec2 center{0.0f};
    float radius = 0.0f;
};

/**
 * Drawn over the view while painting: the brush outline and, optionally, the paintable and
 * trackable maps Mp/Mt (the paper's Figure 4) from a view-sized RGBA texture that is updated
 * rectangle by rectangle. Only the rectangles drawn are shaded, so it stays cheap on llvmpipe.
 * Needs a current GL context for every call, the one it was initialized in.
 */
class BrushOverlay {
public:
    BrushOverlay();
    ~BrushOverlay();
    BrushOverlay(const BrushOverlay&) = delete;
    BrushOverlay& operator=(const BrushOverlay&) = delete;

    /** Compiles the shaders; an Error if they fail. */
    core::Status initialize();
    /**
     * Uploads rect of rgba (straight alpha, width × height pixels, rows top first, as
     * core::StrokeTracker::fillOverlay writes it); a new size uploads all of it.
     */
    void setMaps(int width, int height, std::span<const std::uint8_t> rgba, PixelRect rect);
    /** Blends the overlay over the bound framebuffer; leaves blending disabled. */
    void draw(const BrushOverlayOptions& options);
    /** Frees every GL object; the context must be current. Called by the destructor too. */
    void release();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace render
