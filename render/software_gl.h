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

/** kSoftwareDrawPieces on a software rasterizer (the current context's), else 1. */
int drawPiecesForCurrentContext();

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
