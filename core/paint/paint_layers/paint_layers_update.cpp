// SPDX-License-Identifier: GPL-3.0-or-later
// PaintLayerStack's composite updates: a whole tile (updateTile()), or during a stroke the texels
// a dab touched, from the layers below the stroke's layer kept per tile; in one pass per texel
// where every layer blends in the Normal mode over the base, else layer by layer over a
// rectangle (paint_layers_blend.cpp). Gives the bytes compositeTexel() gives (the same float
// operations in the same order per texel).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <mutex>
#include <optional>
#include <type_traits>
#include <unordered_map>

#include "core/paint/paint_layers/layer_sources.h"
#include "core/paint/paint_layers/paint_layers.h"

namespace core {

namespace {

constexpr unsigned kAllChannels = 7;
/** Tiles whose lower layers a stroke keeps at most (80 KB each); past that it recomputes them. */
constexpr std::size_t kMaxKeptTiles = 512;

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
#if defined(__SSE2__)
using layer_bytes::fromBytes4;
using layer_bytes::toBytes4;
#endif

/**
 * What composeOverBase() blends over the base: per paint layer and channel that takes part its
 * source, in the layers' order, and per channel the topmost one (nullptr: none).
 */
struct NormalSources {
    std::array<ChannelSource, 3 * 8> sources;
    std::size_t count = 0;
    std::array<const ChannelSource*, kPaintChannels> top{};
    // Whether the topmost source of every channel with one is a paint layer's texels at full
    // opacity without a mask (see topSources()).
    bool opaqueTops = false;
};

/**
 * The sources of channels of layers [from, to) in tile of page (channelCount channels at most);
 * false when one blends in another mode than Normal (or there are too many).
 */
bool normalSources(std::span<const std::unique_ptr<PaintLayer>> layers, std::size_t from,
                   std::size_t to, std::size_t channelCount, unsigned channels, std::uint32_t page,
                   std::uint32_t tile, NormalSources& out) {
    for (std::size_t l = from; l < to; ++l) {
        for (std::size_t c = 0; c < channelCount; ++c) {
            if ((channels & (1u << c)) == 0)
                continue;
            const std::optional<ChannelSource> src = channelSource(*layers[l], c, page, tile);
            if (!src)
                continue;
            if (layers[l]->settings.blend != BlendMode::Normal || out.count == out.sources.size())
                return false;
            out.sources[out.count++] = *src;
        }
    }
    return true;
}

/**
 * Each channel's topmost source. Where it is a paint layer's texels at full opacity without a
 * mask, a texel it covers fully (coverage byte 255) ends with that layer's bytes: the blend gives
 * v + 1·(l - v), within 2⁻²³ of l = fromByte(b), and toByte() of that is b whatever v the layers
 * below left. A channel without a source keeps the base's bytes.
 */
void topSources(NormalSources& s) {
    s.opaqueTops = byteRoundTrips() && fromByte(255) == 1.0f;
    for (std::size_t j = 0; j < s.count; ++j)
        s.top[s.sources[j].first == 0 ? 0 : s.sources[j].first - 2] = &s.sources[j];
    for (const ChannelSource* src : s.top)
        s.opaqueTops =
            s.opaqueTops &&
            (src == nullptr || (src->texels != nullptr && !src->masked && src->opacity == 1.0f));
}

/**
 * The composite's texels an update writes: rect (or its rows) of the tile whose rectangle is
 * tile, in channels, and the page's bytes (as PaintLayerStack::pageBytes()).
 */
struct CompositeTexels {
    const TileRect& rect;
    std::span<const TexelSpan> rows;
    TileRect tile;
    unsigned channels = 0;
    std::size_t width = 0;
    const std::uint8_t* baseColor = nullptr;
    std::uint8_t* color = nullptr;
    const std::uint8_t* baseMr = nullptr;
    std::uint8_t* mr = nullptr; // nullptr: no material channel to write
};

/**
 * The texels of t from the sources s, texel by texel: as baseValues(), blendLayers() and
 * updateRect()'s store, the same operations on each value in the same order.
 */
void composeTexels(const NormalSources& s, const CompositeTexels& t) {
    // What the texel loop reads, as locals: its byte stores could alias the structs' members
    // (the sources it reads per texel anyway).
    const std::array<ChannelSource, 3 * 8>& sources = s.sources;
    const std::size_t count = s.count;
    const std::array<const ChannelSource*, kPaintChannels> top = s.top;
    const bool opaqueTops = s.opaqueTops;
    const unsigned channels = t.channels;
    const std::uint8_t *baseColor = t.baseColor, *baseMr = t.baseMr;
    std::uint8_t *color = t.color, *mr = t.mr;
    const bool material = mr != nullptr;
    const auto topByte = [&](std::size_t ch, std::size_t local, int k, std::uint8_t base) {
        const ChannelSource* src = top[ch];
        return src != nullptr ? src->texels[local * std::size_t(src->comps + 1) + std::size_t(k)]
                              : base;
    };
    forEachTexel(t.rect, t.rows, t.tile, t.width, [&](std::size_t i, std::size_t local) {
        if (opaqueTops && std::all_of(top.begin(), top.end(), [&](const ChannelSource* src) {
                return src == nullptr ||
                       src->texels[local * std::size_t(src->comps + 1) + std::size_t(src->comps)] ==
                           255;
            })) {
            if ((channels & 1u) != 0) {
                for (int k = 0; k < 3; ++k)
                    color[i + std::size_t(k)] = topByte(0, local, k, baseColor[i + std::size_t(k)]);
                color[i + 3] = baseColor[i + 3];
            }
            if (material) {
                mr[i] = baseMr[i];
                if ((channels & 2u) != 0)
                    mr[i + 1] = topByte(1, local, 0, baseMr[i + 1]);
                if ((channels & 4u) != 0)
                    mr[i + 2] = topByte(2, local, 0, baseMr[i + 2]);
                mr[i + 3] = baseMr[i + 3];
            }
            return;
        }
        float v[5] = {};
        if ((channels & 1u) != 0)
            for (std::size_t k = 0; k < 3; ++k)
                v[k] = fromByte(baseColor[i + k]);
        if (baseMr != nullptr) {
            if ((channels & 2u) != 0)
                v[3] = fromByte(baseMr[i + 1]);
            if ((channels & 4u) != 0)
                v[4] = fromByte(baseMr[i + 2]);
        }
        for (std::size_t j = 0; j < count; ++j) {
            const ChannelSource& src = sources[j];
            const std::uint8_t* texel = nullptr;
            const float a = coverageOf(src, local, texel);
            if (!(a > 0.0f))
                continue;
            for (int k = 0; k < src.comps; ++k) {
                const float layer =
                    texel != nullptr ? fromByte(texel[k]) : src.fill[std::size_t(k)];
                float& value = v[src.first + std::size_t(k)];
                value += a * (blendAs<BlendMode::Normal>(value, layer) - value);
            }
        }
        if ((channels & 1u) != 0) {
            color[i] = toByte(v[0]);
            color[i + 1] = toByte(v[1]);
            color[i + 2] = toByte(v[2]);
            color[i + 3] = baseColor[i + 3];
        }
        if (material) {
            mr[i] = baseMr[i];
            if ((channels & 2u) != 0)
                mr[i + 1] = toByte(v[3]);
            if ((channels & 4u) != 0)
                mr[i + 2] = toByte(v[4]);
            mr[i + 3] = baseMr[i + 3];
        }
    });
}

#if defined(__SSE2__)
/**
 * Whether composeInLanes() can compose s: one unmasked paint layer's texels per channel at most
 * (painting a paint layer with nothing below it in this tile).
 */
bool fitsLanes(const NormalSources& s) {
    bool lanes = true;
    for (std::size_t j = 0; j < s.count; ++j)
        lanes = lanes && s.sources[j].texels != nullptr && !s.sources[j].masked &&
                s.top[s.sources[j].first == 0 ? 0 : s.sources[j].first - 2] == &s.sources[j];
    return lanes;
}

/**
 * composeTexels() of sources that fitsLanes(): a texel's colour in four lanes (red, green, blue
 * and an unused one), its roughness and metallic in lanes 1 and 2, the operations of the texel
 * loop there. Without branches per texel: where the layer's coverage is 0 the blend gives the
 * value below exactly (v + 0·(l − v)), so every texel takes the blend. A channel not painted here
 * (or without a source) keeps its bytes: colour's fourth byte and the first and fourth of
 * roughness-metallic are the base's.
 */
void composeInLanes(const NormalSources& s, const CompositeTexels& t) {
    // min and max clamp as std::clamp does for values that are not NaN (bytes give none).
    const auto blend4 = [](__m128 below, __m128 layer, __m128 a) {
        const __m128 over = _mm_min_ps(_mm_max_ps(layer, _mm_setzero_ps()), _mm_set1_ps(1.0f));
        return _mm_add_ps(below, _mm_mul_ps(a, _mm_sub_ps(over, below)));
    };
    static constexpr std::uint8_t kNothing[4] = {};
    const std::array<const ChannelSource*, kPaintChannels>& top = s.top;
    const unsigned channels = t.channels;
    const std::uint8_t *baseColor = t.baseColor, *baseMr = t.baseMr;
    std::uint8_t *color = t.color, *mr = t.mr;
    const bool material = mr != nullptr;
    const bool colour = (channels & 1u) != 0;
    const std::uint8_t* colourTexels = colour && top[0] != nullptr ? top[0]->texels : kNothing;
    const std::size_t colourStep = colour && top[0] != nullptr ? 4 : 0;
    const __m128 colourOpacity = _mm_set1_ps(top[0] != nullptr ? top[0]->opacity : 0.0f);
    const std::uint8_t* rough =
        (channels & 2u) != 0 && top[1] != nullptr ? top[1]->texels : nullptr;
    const std::uint8_t* metal =
        (channels & 4u) != 0 && top[2] != nullptr ? top[2]->texels : nullptr;
    const __m128 mrOpacity = _mm_setr_ps(0.0f, rough != nullptr ? top[1]->opacity : 0.0f,
                                         metal != nullptr ? top[2]->opacity : 0.0f, 0.0f);
    const std::uint32_t mrPainted =
        ((channels & 2u) != 0 ? 0x0000ff00u : 0u) | ((channels & 4u) != 0 ? 0x00ff0000u : 0u);
    const auto word = [](const std::uint8_t* p) {
        std::uint32_t w;
        std::memcpy(&w, p, 4);
        return w;
    };
    const auto bytesOf = [](__m128 v) { return layer_bytes::packBytes4(toBytes4(v)); };
    forEachTexel(t.rect, t.rows, t.tile, t.width, [&](std::size_t i, std::size_t local) {
        if (colour) {
            const __m128 layer = fromBytes4(colourTexels + local * colourStep);
            const __m128 a =
                _mm_mul_ps(_mm_shuffle_ps(layer, layer, _MM_SHUFFLE(3, 3, 3, 3)), colourOpacity);
            const std::uint32_t bytes = bytesOf(blend4(fromBytes4(baseColor + i), layer, a));
            const std::uint32_t out = (bytes & 0x00ffffffu) | (word(baseColor + i) & 0xff000000u);
            std::memcpy(color + i, &out, 4);
        }
        if (material) {
            std::uint32_t values = 0, covers = 0;
            if (rough != nullptr) {
                values |= std::uint32_t(rough[local * 2]) << 8;
                covers |= std::uint32_t(rough[local * 2 + 1]) << 8;
            }
            if (metal != nullptr) {
                values |= std::uint32_t(metal[local * 2]) << 16;
                covers |= std::uint32_t(metal[local * 2 + 1]) << 16;
            }
            const __m128 a =
                _mm_mul_ps(fromBytes4(reinterpret_cast<const std::uint8_t*>(&covers)), mrOpacity);
            const std::uint32_t bytes =
                bytesOf(blend4(fromBytes4(baseMr + i),
                               fromBytes4(reinterpret_cast<const std::uint8_t*>(&values)), a));
            const std::uint32_t out = (bytes & mrPainted) | (word(baseMr + i) & 0xff0000ffu) |
                                      (word(mr + i) & ~(mrPainted | 0xff0000ffu));
            std::memcpy(mr + i, &out, 4);
        }
    });
}
#endif

/** The channels updateRect() recomputes and the first layer it blends over the values below. */
struct UpdateScope {
    unsigned channels = 0;
    std::size_t from = 0;
};

/**
 * What updateRect() recomputes: every channel from the base up, or during a stroke (inStroke)
 * the stroke's channels over the layers below its layer (all channels when that layer is gone).
 */
UpdateScope updateScope(const PaintLayerStack& stack, bool inStroke, std::uint64_t strokeLayer,
                        unsigned strokeChannels) {
    const unsigned all = stack.hasMaterialChannels() ? kAllChannels : 1u;
    UpdateScope scope{all, 0};
    if (!inStroke)
        return scope;
    scope.channels = strokeChannels;
    if (strokeLayer != 0) {
        if (const std::optional<std::size_t> index = stack.indexOf(strokeLayer))
            scope.from = *index;
        else
            scope.channels = all;
    }
    return scope;
}

/**
 * One past the last of layers that touches tile of page (0: none does); the layers above it
 * change nothing there.
 */
std::size_t touchingEnd(std::span<const std::unique_ptr<PaintLayer>> layers, std::uint32_t page,
                        std::uint32_t tile) {
    std::size_t end = 0;
    for (std::size_t l = 0; l < layers.size(); ++l)
        if (layers[l]->touchesTile(page, tile))
            end = l + 1;
    return end;
}

/**
 * The values of the layers below the stroke's kept in below for key (page << 32 | tile): made
 * by make (into the whole tile's values, size floats) the first time while there is room;
 * nullptr when there is none.
 */
template <typename Make>
const std::vector<float>* keptBelow(std::unordered_map<std::uint64_t, std::vector<float>>& below,
                                    std::mutex& lock, std::uint64_t key, std::size_t size,
                                    Make&& make) {
    const std::vector<float>* kept = nullptr;
    bool keep = false;
    {
        const std::lock_guard guard(lock);
        if (const auto found = below.find(key); found != below.end())
            kept = &found->second;
        else
            keep = below.size() < kMaxKeptTiles;
    }
    if (keep) {
        std::vector<float> values(size);
        make(values.data());
        const std::lock_guard guard(lock); // elements stay where they are on insertion
        kept = &below.emplace(key, std::move(values)).first->second;
    }
    return kept;
}

/**
 * Copies the values of rect (or its rows) in channels from kept (the values of the whole tile,
 * whose rectangle is tile) to values (n texels a value plane).
 */
void copyKept(const std::vector<float>& kept, const TileRect& tile, const TileRect& rect,
              std::span<const TexelSpan> rows, unsigned channels, float* values, std::size_t n) {
    const std::size_t tn = std::size_t(tile.width) * std::size_t(tile.height);
    for (std::size_t v = 0; v < 5; ++v) {
        if ((channels & (1u << (v < 3 ? 0 : v - 2))) == 0)
            continue;
        std::size_t at = 0;
        for (int y = rect.y; y < rect.y + rect.height; ++y) {
            const TexelSpan span = rowOf(rect, rows, y);
            if (span.x1 <= span.x0)
                continue;
            const float* src = kept.data() + v * tn +
                               std::size_t(y - tile.y) * std::size_t(tile.width) +
                               std::size_t(span.x0 - tile.x);
            std::copy_n(src, span.x1 - span.x0, values + v * n + at);
            at += std::size_t(span.x1 - span.x0);
        }
    }
}

/**
 * Stores values (n texels a value plane) of t as bytes of the composite, t's channels; the
 * other bytes are the base's.
 */
void storeValues(const float* values, std::size_t n, const CompositeTexels& t) {
    const unsigned channels = t.channels;
    const std::size_t width = t.width;
    const std::uint8_t *baseColor = t.baseColor, *baseMr = t.baseMr;
    std::uint8_t *color = t.color, *mr = t.mr;
    const TileRect& rect = t.rect;
    const std::span<const TexelSpan> rows = t.rows;
    const bool material = mr != nullptr;
    std::size_t at = 0;
    for (int y = rect.y; y < rect.y + rect.height; ++y)
        for (int x = rowOf(rect, rows, y).x0, x1 = rowOf(rect, rows, y).x1; x < x1; ++x, ++at) {
            const std::size_t i = (std::size_t(y) * width + std::size_t(x)) * 4;
            if ((channels & 1u) != 0) {
                color[i] = toByte(values[at]);
                color[i + 1] = toByte(values[n + at]);
                color[i + 2] = toByte(values[2 * n + at]);
                color[i + 3] = baseColor[i + 3];
            }
            if (material) {
                mr[i] = baseMr[i];
                if ((channels & 2u) != 0)
                    mr[i + 1] = toByte(values[3 * n + at]);
                if ((channels & 4u) != 0)
                    mr[i + 2] = toByte(values[4 * n + at]);
                mr[i + 3] = baseMr[i + 3];
            }
        }
}

} // namespace

PaintLayerStack::PageBytes PaintLayerStack::pageBytes(std::uint32_t page, unsigned channels) {
    const bool material = hasMaterialChannels() && (channels & 6u) != 0;
    return {std::size_t(m_pages[page].width), m_baseColor[page].data(),
            m_compositeColor[page].rgba.data(),
            material ? m_baseMetallicRoughness[page].data() : nullptr,
            material ? m_compositeMr[page].rgba.data() : nullptr};
}

void PaintLayerStack::copyBase(std::uint32_t page, const TileRect& rect, unsigned channels,
                               std::span<const TexelSpan> rows) {
    const auto [width, baseColor, color, baseMr, mr] = pageBytes(page, channels);
    const bool material = mr != nullptr;
    for (int y = rect.y; y < rect.y + rect.height; ++y) {
        const TexelSpan span = rowOf(rect, rows, y);
        if (span.x1 <= span.x0)
            continue;
        const std::size_t i = (std::size_t(y) * width + std::size_t(span.x0)) * 4;
        const std::size_t bytes = std::size_t(span.x1 - span.x0) * 4;
        if ((channels & 1u) != 0)
            std::memcpy(color + i, baseColor + i, bytes);
        if (material) {
            if ((channels & 6u) == 6u) {
                std::memcpy(mr + i, baseMr + i, bytes);
            } else {
                // Roughness (byte 1) or metallic (byte 2) alone; bytes 0 and 3 are the base's.
                const std::size_t keep = (channels & 2u) != 0 ? 2 : 1;
                for (std::size_t j = i; j < i + bytes; j += 4) {
                    const std::uint8_t kept = mr[j + keep];
                    std::memcpy(mr + j, baseMr + j, 4);
                    mr[j + keep] = kept;
                }
            }
        }
    }
}

bool PaintLayerStack::composeOverBase(std::uint32_t page, std::uint32_t tile, const TileRect& rect,
                                      std::size_t from, std::size_t to, unsigned channels,
                                      std::span<const TexelSpan> rows) {
    // What blendLayers() reads, per layer and channel that takes part: the Normal mode only.
    NormalSources sources;
    const std::size_t channelCount = hasMaterialChannels() ? kPaintChannels : 1;
    if (!normalSources(m_layers, from, to, channelCount, channels, page, tile, sources))
        return false;
    topSources(sources);
    const PageBytes pixels = pageBytes(page, channels);
    const CompositeTexels texels{rect,         rows,          tileRectOf(m_pages[page], tile),
                                 channels,     pixels.width,  pixels.baseColor,
                                 pixels.color, pixels.baseMr, pixels.mr};
#if defined(__SSE2__)
    if (fitsLanes(sources)) {
        composeInLanes(sources, texels);
        return true;
    }
#endif
    composeTexels(sources, texels);
    return true;
}

void PaintLayerStack::beginStroke(std::uint64_t layerId, unsigned channels) {
    m_below.clear();
    m_inStroke = true;
    m_strokeLayer = layerId;
    m_strokeChannels = channels & (hasMaterialChannels() ? kAllChannels : 1u);
}

void PaintLayerStack::endStroke() {
    m_inStroke = false;
    m_below = {};
}

void PaintLayerStack::dropStrokeCache() {
    m_below.clear();
}

void PaintLayerStack::updateTile(std::uint32_t page, std::uint32_t tile) {
    const UpdateScope all = updateScope(*this, false, 0, 0);
    recompute(page, tile, tileRectOf(m_pages.at(page), tile), {}, all.channels, all.from);
}

void PaintLayerStack::updateRect(std::uint32_t page, std::uint32_t tile, const TileRect& rect,
                                 std::span<const TexelSpan> rows) {
    const UpdateScope scope = updateScope(*this, m_inStroke, m_strokeLayer, m_strokeChannels);
    recompute(page, tile, rect, rows, scope.channels, scope.from);
}

void PaintLayerStack::recompute(std::uint32_t page, std::uint32_t tile, const TileRect& rect,
                                std::span<const TexelSpan> rows, unsigned channels,
                                std::size_t from) {
    if (rect.width <= 0 || rect.height <= 0 || channels == 0)
        return;
    const TileRect tr = tileRectOf(m_pages.at(page), tile);
    const std::size_t n = texelsOf(rect, rows);
    const std::size_t end = touchingEnd(m_layers, page, tile);
    if (end == 0 && byteRoundTrips()) {
        copyBase(page, rect, channels, rows);
        return;
    }
    bool belowTouches = false;
    for (std::size_t l = 0; l < std::min(from, end) && !belowTouches; ++l)
        belowTouches = m_layers[l]->touchesTile(page, tile);
    if (!belowTouches && composeOverBase(page, tile, rect, from, end, channels, rows))
        return;

    // Per thread: updates of different tiles may run at the same time.
    thread_local std::vector<float> scratch;
    scratch.resize(5 * n);
    float* values = scratch.data();
    if (!belowTouches) {
        baseValues(page, rect, channels, values, rows);
    } else {
        // The layers below the stroke's: kept per tile for the stroke (whole tile, once).
        const std::vector<float>* kept =
            keptBelow(m_below, m_belowLock, (std::uint64_t(page) << 32) | tile,
                      5 * std::size_t(tr.width) * std::size_t(tr.height), [&](float* below) {
                          baseValues(page, tr, channels, below);
                          blendLayers(page, tile, tr, 0, from, channels, below, {}, true);
                      });
        if (kept != nullptr) {
            copyKept(*kept, tr, rect, rows, channels, values, n);
        } else {
            baseValues(page, rect, channels, values, rows);
            blendLayers(page, tile, rect, 0, from, channels, values, rows, true);
        }
    }
    blendLayers(page, tile, rect, from, std::max(from, end), channels, values, rows, !belowTouches);
    const PageBytes pixels = pageBytes(page, channels);
    storeValues(values, n,
                {rect, rows, tr, channels, pixels.width, pixels.baseColor, pixels.color,
                 pixels.baseMr, pixels.mr});
}

} // namespace core
