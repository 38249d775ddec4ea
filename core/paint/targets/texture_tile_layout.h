// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to core/paint: how a texture target lays out a paint layer's channels in one undo tile
// (texture_target.cpp paints into it, texture_target_tiles.cpp reads and writes it).
#pragma once

#include <cstddef>

#include "core/paint/paint_layers/paint_layers.h"
#include "core/paint/targets/paint_target.h"

namespace core {

static_assert(TiledPlane::kPlaneTile == kTextureTile, "paint layers tile as the pages do");

/** Bytes per texel of a paint layer's channels as one undo tile: RGBA, roughness, metallic. */
inline constexpr std::size_t kPaintLayerTexelBytes = 8;
/** Where a channel's plane starts in such a tile of n texels, and its bytes per texel. */
inline std::size_t channelOffset(std::size_t channel, std::size_t n) {
    return channel == 0 ? 0 : channel == 1 ? n * 4 : n * 6;
}

} // namespace core
