// SPDX-License-Identifier: GPL-3.0-or-later
// What the paint layers' composite updates (paint_layers_update.cpp) and blends
// (paint_layers_blend.cpp) share: tile rectangles and rows, one channel of a paint layer over a
// tile as its source, and the blend mode chosen once for a loop.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>

#include "core/paint/paint_layers/paint_layers.h"

namespace core::layer_sources {

using layer_bytes::fromByte;
using layer_bytes::toByte;

/** Calls fn with mode as a compile-time constant (std::integral_constant<BlendMode, mode>). */
template <typename Fn> void withMode(BlendMode mode, Fn&& fn) {
    switch (mode) {
    case BlendMode::Normal:
        return fn(std::integral_constant<BlendMode, BlendMode::Normal>{});
    case BlendMode::Multiply:
        return fn(std::integral_constant<BlendMode, BlendMode::Multiply>{});
    case BlendMode::Screen:
        return fn(std::integral_constant<BlendMode, BlendMode::Screen>{});
    case BlendMode::Overlay:
        return fn(std::integral_constant<BlendMode, BlendMode::Overlay>{});
    case BlendMode::SoftLight:
        return fn(std::integral_constant<BlendMode, BlendMode::SoftLight>{});
    case BlendMode::Add:
        return fn(std::integral_constant<BlendMode, BlendMode::Add>{});
    case BlendMode::Subtract:
        return fn(std::integral_constant<BlendMode, BlendMode::Subtract>{});
    case BlendMode::Darken:
        return fn(std::integral_constant<BlendMode, BlendMode::Darken>{});
    case BlendMode::Lighten:
        return fn(std::integral_constant<BlendMode, BlendMode::Lighten>{});
    case BlendMode::Difference:
        return fn(std::integral_constant<BlendMode, BlendMode::Difference>{});
    }
}

inline TileRect tileRectOf(const PageSize& size, std::uint32_t tile) {
    const int across =
        std::max(1, (size.width + TiledPlane::kPlaneTile - 1) / TiledPlane::kPlaneTile);
    TileRect r;
    r.x = int(tile % std::uint32_t(across)) * TiledPlane::kPlaneTile;
    r.y = int(tile / std::uint32_t(across)) * TiledPlane::kPlaneTile;
    r.width = std::min(size.width, r.x + TiledPlane::kPlaneTile) - r.x;
    r.height = std::min(size.height, r.y + TiledPlane::kPlaneTile) - r.y;
    return r;
}

/** The texels [x0, x1) of row y of rect to visit: rows[y - rect.y], or the whole row. */
inline TexelSpan rowOf(const TileRect& rect, std::span<const TexelSpan> rows, int y) {
    return rows.empty() ? TexelSpan{rect.x, rect.x + rect.width} : rows[std::size_t(y - rect.y)];
}

/**
 * Calls fn(i, local) for every texel of rect (or of its rows): i is its first byte in the
 * page's four-byte texels (width texels a row), local its index in its tile, whose rectangle is
 * tile.
 */
template <typename Fn>
void forEachTexel(const TileRect& rect, std::span<const TexelSpan> rows, const TileRect& tile,
                  std::size_t width, Fn&& fn) {
    for (int y = rect.y; y < rect.y + rect.height; ++y) {
        const TexelSpan span = rowOf(rect, rows, y);
        const std::size_t row = std::size_t(y - tile.y) * std::size_t(tile.width);
        for (int x = span.x0; x < span.x1; ++x)
            fn((std::size_t(y) * width + std::size_t(x)) * 4, row + std::size_t(x - tile.x));
    }
}

/** How many texels rect (or its rows) holds. */
inline std::size_t texelsOf(const TileRect& rect, std::span<const TexelSpan> rows) {
    if (rows.empty())
        return std::size_t(rect.width) * std::size_t(rect.height);
    std::size_t n = 0;
    for (const TexelSpan& r : rows)
        n += r.x1 > r.x0 ? std::size_t(r.x1 - r.x0) : 0;
    return n;
}

/** What blending one channel of a paint layer over a tile reads. */
struct ChannelSource {
    const std::uint8_t* texels = nullptr; // nullptr: a fill
    std::array<float, 3> fill{};
    const std::uint8_t* mask = nullptr;
    std::uint8_t maskFill = 255;
    bool masked = false;
    float opacity = 1.0f;
    int comps = 1;         // 3 for base colour, 1 for roughness and metallic
    std::size_t first = 0; // its first of the 5 value planes
};

/**
 * How much of src texel local takes (its coverage times the layer's opacity and mask), with
 * texel set to its bytes (nullptr for a fill).
 */
inline float coverageOf(const ChannelSource& src, std::size_t local, const std::uint8_t*& texel) {
    float a = 1.0f;
    texel = nullptr;
    if (src.texels != nullptr) {
        texel = src.texels + local * std::size_t(src.comps + 1);
        a = fromByte(texel[src.comps]);
    }
    a *= src.opacity;
    if (src.masked)
        a *= fromByte(src.mask != nullptr ? src.mask[local] : src.maskFill);
    return a;
}

/**
 * Channel c of layer in tile of page, or nothing when it changes no texel there: hidden, fully
 * transparent, a paint layer that never wrote the tile, or a fill without a value for c.
 */
inline std::optional<ChannelSource> channelSource(const PaintLayer& layer, std::size_t c,
                                                  std::uint32_t page, std::uint32_t tile) {
    const PaintLayerSettings& st = layer.settings;
    ChannelSource src;
    src.opacity = std::clamp(st.opacity, 0.0f, 1.0f);
    if (!st.visible || !(src.opacity > 0.0f))
        return std::nullopt; // every texel's coverage is 0 (or NaN): compositeTexel() skips them
    src.comps = c == 0 ? 3 : 1;
    src.first = c == 0 ? 0 : c + 2;
    src.masked = layer.mask != nullptr;
    src.mask = src.masked ? layer.mask->tile(page, tile) : nullptr;
    src.maskFill = src.masked ? layer.mask->fill()[0] : 255;
    if (st.kind == PaintLayerKind::Fill) {
        if (c == 0 && st.fill.baseColor)
            src.fill = {st.fill.baseColor->x, st.fill.baseColor->y, st.fill.baseColor->z};
        else if (c == 1 && st.fill.roughness)
            src.fill[0] = *st.fill.roughness;
        else if (c == 2 && st.fill.metallic)
            src.fill[0] = *st.fill.metallic;
        else
            return std::nullopt;
    } else {
        const TiledPlane* plane = layer.channels[c].get();
        src.texels = plane != nullptr ? plane->tile(page, tile) : nullptr;
        if (src.texels == nullptr)
            return std::nullopt; // unwritten: coverage 0 everywhere
    }
    return src;
}

/**
 * Whether every byte b gives b again through fromByte() and toByte(): then a texel no layer
 * touches composites to its base bytes, which can be copied.
 */
inline bool byteRoundTrips() {
    static const bool roundTrips = [] {
        for (int b = 0; b < 256; ++b)
            if (toByte(fromByte(std::uint8_t(b))) != std::uint8_t(b))
                return false;
        return true;
    }();
    return roundTrips;
}

} // namespace core::layer_sources
