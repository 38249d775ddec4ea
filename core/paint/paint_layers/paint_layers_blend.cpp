// SPDX-License-Identifier: GPL-3.0-or-later
// PaintLayerStack's blending of layers over value planes, channel by channel: what a full tile
// update and a stroke's layers below its own compute when they cannot go in one pass per texel
// (paint_layers_update.cpp). Runs of fill layers over the base are worked out once per byte.
#include <array>
#include <cstring>
#include <utility>
#include <vector>

#include "core/paint/paint_layers/layer_sources.h"
#include "core/paint/paint_layers/paint_layers.h"

namespace core {

namespace {

using layer_bytes::fromByte;
using layer_bytes::toByte;
using layer_sources::byteRoundTrips;
using layer_sources::channelSource;
using layer_sources::ChannelSource;
using layer_sources::coverageOf;
using layer_sources::forEachTexel;
using layer_sources::rowOf;
using layer_sources::texelsOf;
using layer_sources::tileRectOf;
using layer_sources::withMode;

/**
 * Blends channel c of the layers from `from` on that are the same in every texel of tile of
 * page (fill layers without a mask or with an unwritten one; layers without channel c there
 * are passed) over values (n texels a plane), which hold the base's bytes: each base byte's
 * value is worked out once, with the operations blendLayers() makes per texel, in their order,
 * so the bytes are the same; then looked up per texel. Returns the first layer not blended.
 */
std::size_t foldUniformLayers(std::span<const std::unique_ptr<PaintLayer>> layers,
                              std::uint32_t page, std::uint32_t tile, std::size_t from,
                              std::size_t to, std::size_t c, float* values, std::size_t n) {
    if (!byteRoundTrips())
        return from;
    // The run: the layers up to the first whose channel c differs from texel to texel.
    std::vector<std::pair<ChannelSource, BlendMode>> run;
    std::size_t end = from;
    for (; end < to; ++end) {
        const std::optional<ChannelSource> src = channelSource(*layers[end], c, page, tile);
        if (!src)
            continue;
        if (src->texels != nullptr || (src->masked && src->mask != nullptr))
            break;
        const std::uint8_t* none = nullptr;
        if (coverageOf(*src, 0, none) > 0.0f)
            run.emplace_back(*src, layers[end]->settings.blend);
    }
    // One layer costs a lookup as much as its blend: only runs of more are worked out per byte.
    if (run.size() < 2)
        return from;
    const auto comps = std::size_t(run.front().first.comps);
    const std::size_t firstPlane = run.front().first.first;
    std::array<std::array<float, 256>, 3> table;
    for (std::size_t k = 0; k < comps; ++k)
        for (int b = 0; b < 256; ++b)
            table[k][std::size_t(b)] = fromByte(std::uint8_t(b));
    for (const auto& entry : run) {
        const ChannelSource& s = entry.first;
        const std::uint8_t* none = nullptr;
        const float a = coverageOf(s, 0, none);
        withMode(entry.second, [&](auto mode) {
            constexpr BlendMode kMode = decltype(mode)::value;
            for (std::size_t k = 0; k < comps; ++k)
                for (float& v : table[k])
                    v += a * (blendAs<kMode>(v, s.fill[k]) - v);
        });
    }
    for (std::size_t k = 0; k < comps; ++k) {
        float* plane = values + (firstPlane + k) * n;
        for (std::size_t at = 0; at < n; ++at)
            plane[at] = table[k][toByte(plane[at])];
    }
    return end;
}

} // namespace

void PaintLayerStack::baseValues(std::uint32_t page, const TileRect& rect, unsigned channels,
                                 float* values, std::span<const TexelSpan> rows) const {
    const std::size_t n = texelsOf(rect, rows);
    const std::size_t width = std::size_t(m_pages[page].width);
    const std::uint8_t* color = m_baseColor[page].data();
    const std::uint8_t* mr = hasMaterialChannels() ? m_baseMetallicRoughness[page].data() : nullptr;
    std::size_t at = 0;
    for (int y = rect.y; y < rect.y + rect.height; ++y)
        for (int x = rowOf(rect, rows, y).x0, x1 = rowOf(rect, rows, y).x1; x < x1; ++x, ++at) {
            const std::size_t i = (std::size_t(y) * width + std::size_t(x)) * 4;
            if ((channels & 1u) != 0)
                for (std::size_t k = 0; k < 3; ++k)
                    values[k * n + at] = fromByte(color[i + k]);
            // Without material channels roughness and metallic are never read.
            if (mr != nullptr) {
                if ((channels & 2u) != 0)
                    values[3 * n + at] = fromByte(mr[i + 1]);
                if ((channels & 4u) != 0)
                    values[4 * n + at] = fromByte(mr[i + 2]);
            }
        }
}

void PaintLayerStack::blendLayers(std::uint32_t page, std::uint32_t tile, const TileRect& rect,
                                  std::size_t from, std::size_t to, unsigned channels,
                                  float* values, std::span<const TexelSpan> rows,
                                  bool overBase) const {
    const std::size_t n = texelsOf(rect, rows);
    const TileRect tr = tileRectOf(m_pages[page], tile);
    const std::size_t channelCount = hasMaterialChannels() ? kPaintChannels : 1;
    // Channel by channel: a channel's values take only its own layers' channel, in their order.
    for (std::size_t c = 0; c < channelCount; ++c) {
        if ((channels & (1u << c)) == 0)
            continue;
        const std::size_t first =
            overBase ? foldUniformLayers(m_layers, page, tile, from, to, c, values, n) : from;
        for (std::size_t l = first; l < to; ++l) {
            const std::optional<ChannelSource> src = channelSource(*m_layers[l], c, page, tile);
            if (!src)
                continue;
            const ChannelSource& s = *src;
            withMode(m_layers[l]->settings.blend, [&](auto mode) {
                constexpr BlendMode kMode = decltype(mode)::value;
                std::size_t at = 0;
                for (int y = rect.y; y < rect.y + rect.height; ++y) {
                    const std::size_t row = std::size_t(y - tr.y) * std::size_t(tr.width);
                    const TexelSpan span = rowOf(rect, rows, y);
                    for (int x = span.x0; x < span.x1; ++x, ++at) {
                        const std::size_t local = row + std::size_t(x - tr.x);
                        const std::uint8_t* t = nullptr;
                        const float a = coverageOf(s, local, t);
                        if (!(a > 0.0f))
                            continue;
                        for (int k = 0; k < s.comps; ++k) {
                            const float layer =
                                t != nullptr ? fromByte(t[k]) : s.fill[std::size_t(k)];
                            float& v = values[(s.first + std::size_t(k)) * n + at];
                            v += a * (blendAs<kMode>(v, layer) - v);
                        }
                    }
                }
            });
        }
    }
}

} // namespace core
