// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <functional>
#include <string_view>

namespace render {

/** Whether a GL_RENDERER string names a software rasterizer (llvmpipe, softpipe, SwiftShader). */
bool isSoftwareRenderer(std::string_view rendererName);
/** The same for the current context's GL_RENDERER; false without a current context. */
bool isSoftwareRenderer();

/** Pieces drawInPieces() cuts a large draw into on a software rasterizer. */
inline constexpr int kSoftwareDrawPieces = 8;
/** Triangles of the smallest piece: a smaller draw is not cut. */
inline constexpr std::size_t kMinDrawPiece = 8192;
/** A frame is cut when it has a triangle for every this many pixels of its view, or more. */
inline constexpr std::size_t kPixelsPerTriangleToCut = 4;

/**
 * Pieces for each draw of a frame of `triangles` triangles in a view of `pixels` pixels:
 * kSoftwareDrawPieces on a software rasterizer (software) when the frame has a triangle for every
 * kPixelsPerTriangleToCut pixels or more, else 1. A frame with fewer triangles spends its time
 * rasterizing, not binning, and there the flushes cost more than they overlap (the
 * 2CylinderEngine's 121K triangles at 1920×1080: its layer capture was 4 ms slower cut).
 */
int drawPieces(bool software, std::size_t triangles, std::size_t pixels);

/**
 * Calls draw(first, count) for consecutive pieces of the triangles [first, first + count), at
 * most `pieces` of them and none under kMinDrawPiece triangles unless the draw is, with glFlush()
 * after every piece but the last. llvmpipe shades and bins a draw's triangles on the calling
 * thread and rasterizes them on its own threads only once the scene is flushed (or full), so
 * without the flushes its threads wait for the whole binning; with them, one piece is rasterized
 * while the next is binned. The pixels are those of one draw: GL keeps the triangles' order.
 */
void drawInPieces(std::size_t first, std::size_t count, int pieces,
                  const std::function<void(std::size_t first, std::size_t count)>& draw);

} // namespace render
