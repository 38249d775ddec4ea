// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/base/result.h"
#include "core/model/camera.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"

namespace render {

/**
 * A MeshRenderer frame drawn a slice at a time into its own framebuffer, so that a frame of
 * millions of triangles on a software rasterizer never holds its caller for long: each
 * advance() draws the next slice, and the frame starts again by itself when the view, the
 * options, or the renderer's mesh, colours or textures changed since the last call. The slices
 * together give MeshRenderer::draw()'s pixels. Needs the renderer's GL context current for
 * every call.
 */
class SlicedFrame {
public:
    /**
     * Draws the next slice, at most sliceTriangles triangles, of renderer.draw(view, options)
     * into the frame's framebuffer (made at the view's size with a window's depth format); the
     * bound framebuffer and viewport are kept. True once the frame is whole; an Error when no
     * framebuffer can be made for it.
     */
    core::Result<bool> advance(MeshRenderer& renderer, const core::View& view,
                               const DrawOptions& options, std::size_t sliceTriangles);
    /** Whether the frame advance() drew last is whole. */
    bool isWhole() const { return m_started && m_drawn >= m_triangles; }
    /** Triangles drawn so far of the frame. */
    std::size_t drawnTriangles() const { return m_drawn; }
    /** Copies the frame as drawn so far into framebuffer (GL name; 0 the default) at 0, 0. */
    void copyTo(unsigned framebuffer) const;
    /** Frees the framebuffer; the next advance() starts a frame. */
    void release();

private:
    /** What the frame is of: any change starts it again. */
    struct Key {
        core::View view;
        DrawOptions options;
        std::uint64_t renderer = 0;
        const MaterialTextures* textures = nullptr;
        std::uint64_t texturesRevision = 0;

        bool operator==(const Key& other) const;
    };

    OffscreenTarget m_target;
    Key m_key;
    bool m_started = false;
    std::size_t m_drawn = 0, m_triangles = 0;
};

} // namespace render
