// SPDX-License-Identifier: GPL-3.0-or-later
// core/paint/paint_layers/: the paint layers over a target's base: their tiled planes,
// blend modes, the composite, and the undo tiles that restore them.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/model/mesh.h"
#include "core/paint/paint_layers/blend_modes.h"
#include "core/paint/paint_layers/tiled_plane.h"

namespace core {

/** The material channels paint goes into (glTF metallic-roughness). */
enum class PaintChannel : std::uint8_t { BaseColor, Roughness, Metallic };
inline constexpr std::size_t kPaintChannels = 3;

/** A value for each channel, or none where a brush or a fill layer leaves the channel alone. */
struct ChannelValues {
    std::optional<glm::vec3> baseColor; // sRGB-encoded, 0..1
    std::optional<float> roughness;     // 0..1
    std::optional<float> metallic;      // 0..1

    friend bool operator==(const ChannelValues&, const ChannelValues&) = default;
};

enum class PaintLayerKind : std::uint8_t {
    Paint, // what brushes and fills put there, texel by texel
    Fill,  // uniform channel values everywhere (shaped by its mask)
};

/** What a paint layer is, apart from its texels. */
struct PaintLayerSettings {
    std::string name;
    PaintLayerKind kind = PaintLayerKind::Paint;
    float opacity = 1.0f;
    BlendMode blend = BlendMode::Normal;
    bool visible = true;
    /** Painting changes the colour of what is there, never how much is there. */
    bool lockTransparency = false;
    /** The values of a fill layer. */
    ChannelValues fill;

    friend bool operator==(const PaintLayerSettings&, const PaintLayerSettings&) = default;
};

/**
 * One paint layer: settings, a plane per channel it was painted in (base colour RGBA8 with A the
 * coverage; roughness and metallic as value and coverage bytes) and an optional mask (one byte,
 * 255 shows, 0 hides; unwritten texels show). Planes exist only once painted.
 */
struct PaintLayer {
    std::uint64_t id = 0;
    PaintLayerSettings settings;
    std::array<std::unique_ptr<TiledPlane>, kPaintChannels> channels;
    std::unique_ptr<TiledPlane> mask;

    /** Bytes of texel data held by its planes. */
    std::size_t bytes() const;
    /** Whether it can change anything in tile of page: shown, and a fill or holding that tile. */
    bool touchesTile(std::uint32_t page, std::uint32_t tile) const;
};

/** Bytes per texel of a channel's plane in a paint layer (value components + coverage). */
int channelTexelBytes(PaintChannel channel);

/**
 * Writes rect of page of a mask (a one-byte plane) into image (RGBA8 of the page's size) as grey:
 * each texel's byte as red, green and blue, alpha 255. What a mask view shows.
 */
void writeMaskAsGrey(const TiledPlane& mask, std::uint32_t page, const TileRect& rect,
                     Image& image);

/**
 * The stack of paint layers of a paint target over its read-only base (the model's own textures
 * or vertex colours as loaded), and the flattened result. Index 0 is the layer right above the
 * base. The composite is kept per page as RGBA8 base colour (the base's alpha kept) and, with
 * material channels, an RGBA8 metallic-roughness image as glTF stores it (G roughness, B
 * metallic); updateTile() recomputes one tile of it, so a stroke updates what it touched only.
 *
 * A texel's channel value c starts at the base's; each visible layer with coverage a (its
 * plane's coverage, 1 for a fill layer's set channel) under opacity o and mask m moves it to
 * c + a·o·m·(blend(mode, c, v) - c), v the layer's value.
 */
class PaintLayerStack {
public:
    /**
     * pages: the target's page sizes. baseColor: per page, width·height RGBA8 texels.
     * baseMetallicRoughness: per page RGBA8 (G roughness, B metallic), or empty for the material
     * without channels (vertex colours: base colour only).
     */
    PaintLayerStack(std::vector<PageSize> pages, std::vector<std::vector<std::uint8_t>> baseColor,
                    std::vector<std::vector<std::uint8_t>> baseMetallicRoughness);

    const std::vector<PageSize>& pages() const { return m_pages; }
    /** Whether roughness and metallic can be painted (texture targets). */
    bool hasMaterialChannels() const { return !m_baseMetallicRoughness.empty(); }

    std::size_t size() const { return m_layers.size(); }
    const PaintLayer& layer(std::size_t index) const { return *m_layers[index]; }
    /** The index of the layer with id, or nothing. */
    std::optional<std::size_t> indexOf(std::uint64_t id) const;

    /** Adds a layer at index (clamped; size() puts it on top); returns its index. */
    std::size_t add(PaintLayerSettings settings, std::size_t index);
    /** A copy of layer index right above it, named "NAME copy"; returns the copy's index. */
    std::size_t duplicate(std::size_t index);
    /** Takes layer index out of the stack (for an undo step to keep). */
    std::unique_ptr<PaintLayer> take(std::size_t index);
    /** Puts a layer taken before back at index (clamped). */
    void insert(std::unique_ptr<PaintLayer> layer, std::size_t index);
    /** Moves layer from to index to (both clamped). */
    void move(std::size_t from, std::size_t to);
    void setSettings(std::size_t index, PaintLayerSettings settings);
    /**
     * Merges layer index into the one below (index - 1), which keeps its name, blend mode and
     * visibility; the result has opacity 1 and no mask and looks the same over a normal lower
     * layer. Returns false (nothing changed) for index 0 or out of range.
     */
    bool mergeDown(std::size_t index, std::vector<std::unique_ptr<PaintLayer>>* removed = nullptr);
    /**
     * Replaces every layer with one normal paint layer that gives the same composite: the
     * composite where any visible layer covers, nothing elsewhere. Hidden layers are dropped.
     * removed, if given, receives the layers replaced (bottom first).
     */
    void flatten(std::string name, std::vector<std::unique_ptr<PaintLayer>>* removed = nullptr);

    /** The plane of a channel of layer index, made on first use (nullptr: no such channel). */
    TiledPlane* channelPlane(std::size_t index, PaintChannel channel);
    /** The mask of layer index, made (all showing) on first use. */
    TiledPlane& maskPlane(std::size_t index);
    /** Sets the mask of layer index (nullptr: none). */
    void setMask(std::size_t index, std::unique_ptr<TiledPlane> mask) {
        dropStrokeCache();
        m_layers.at(index)->mask = std::move(mask);
    }
    /** Removes the mask of layer index; the layer shows everywhere again. */
    std::unique_ptr<TiledPlane> takeMask(std::size_t index);

    /**
     * Recomputes tile (TiledPlane tiling) of page in the composite; may run on several threads
     * for different tiles.
     */
    void updateTile(std::uint32_t page, std::uint32_t tile);

    /**
     * Starts a stroke's composite updates (updateRect()): the stroke changes the layer with id
     * layerId (0: the base) in channels (a bit per PaintChannel; a mask stroke changes them all),
     * and nothing else changes until endStroke(). updateRect() then computes the layers below
     * that layer once per tile and keeps them. Any other change to the stack drops what is kept.
     */
    void beginStroke(std::uint64_t layerId, unsigned channels);
    /** Ends the stroke's updates and frees what they kept. */
    void endStroke();
    /** Forgets the layers below the stroke's layer as kept (something below it changed). */
    void dropStrokeCache();
    /**
     * Recomputes the texels rect (page coordinates, inside tile of page) of the composite, with
     * the same bytes as updateTile() and compositeTexel(); during a stroke only the stroke's
     * channels, the others
     * being up to date already. With rows (one per row of rect), only the texels [x0, x1) of
     * each row (page coordinates; x0 >= x1 for none): what a dab wrote, not its bounding box.
     * Calls for different tiles may run on different threads at the same time.
     */
    void updateRect(std::uint32_t page, std::uint32_t tile, const TileRect& rect,
                    std::span<const TexelSpan> rows = {});
    /** Recomputes the whole composite (on several threads). */
    void updateAll();
    const std::vector<std::uint8_t>& compositeBaseColor(std::uint32_t page) const {
        return m_compositeColor[page].rgba;
    }
    /** Empty without material channels. */
    const std::vector<std::uint8_t>& compositeMetallicRoughness(std::uint32_t page) const;
    /** The composite base colour of page as an image (what a viewport shows). */
    const Image& compositeImage(std::uint32_t page) const { return m_compositeColor[page]; }
    /** The composite metallic-roughness image of page (empty without material channels). */
    const Image& compositeMetallicRoughnessImage(std::uint32_t page) const;

    /**
     * The base's texels of page (RGBA8). Writable for painting on the base; call updateTile()
     * for what changed.
     */
    std::vector<std::uint8_t>& baseColor(std::uint32_t page) { return m_baseColor[page]; }
    const std::vector<std::uint8_t>& baseColor(std::uint32_t page) const {
        return m_baseColor[page];
    }
    /** The base's metallic-roughness texels of page (empty without material channels). */
    const std::vector<std::uint8_t>& baseMetallicRoughness(std::uint32_t page) const;
    /** Writable, as baseColor(); only with material channels. */
    std::vector<std::uint8_t>& baseMetallicRoughness(std::uint32_t page) {
        return m_baseMetallicRoughness.at(page);
    }
    /**
     * The tiles (TiledPlane tiling, plane 0) where layer can change the composite: every tile
     * for a fill layer, else the tiles its channel planes hold.
     */
    std::vector<TileKey> tilesCovered(const PaintLayer& layer) const;
    /** Every tile of every page. */
    std::vector<TileKey> allTiles() const;

    /** Bytes held by the layers' planes (not the base or the composite). */
    std::size_t layerBytes() const;

    /**
     * The composite values of texel (x, y) of page over layers [0, end) (linear 0..1 each),
     * worked out for that texel alone: the reference whose bytes (layer_bytes::toByte()) the
     * tile updates give.
     */
    void compositeTexel(std::uint32_t page, int x, int y, std::size_t end,
                        std::array<float, 5>& values) const;

private:
    std::unique_ptr<PaintLayer> makeLayer(PaintLayerSettings settings);
    std::unique_ptr<TiledPlane> makePlane(int texelBytes, std::array<std::uint8_t, 4> fill) const;
    /**
     * Recomputes channels of the texels rect (or its rows) of tile of page, blending layers
     * from `from` on over the values of those below (the base, or kept for the stroke).
     */
    void recompute(std::uint32_t page, std::uint32_t tile, const TileRect& rect,
                   std::span<const TexelSpan> rows, unsigned channels, std::size_t from);

    /**
     * Blends layers [from, to) over values (5 planes of rect.width·rect.height floats: base
     * colour, roughness, metallic) in the texels rect of tile of page, channels only. overBase:
     * values are the base's (baseValues()), so the layers from `from` that are the same in every
     * texel of the tile (fill layers) give each base byte one value, worked out once per byte.
     */
    void blendLayers(std::uint32_t page, std::uint32_t tile, const TileRect& rect, std::size_t from,
                     std::size_t to, unsigned channels, float* values,
                     std::span<const TexelSpan> rows = {}, bool overBase = false) const;
    /** Sets values (as blendLayers()) to the base's texels in rect, channels only. */
    void baseValues(std::uint32_t page, const TileRect& rect, unsigned channels, float* values,
                    std::span<const TexelSpan> rows = {}) const;
    /**
     * updateRect() when no layer below from touches the tile and layers [from, to) blend in the
     * Normal mode: base, layers and bytes in one pass per texel. False (nothing written) when a
     * layer uses another mode.
     */
    bool composeOverBase(std::uint32_t page, std::uint32_t tile, const TileRect& rect,
                         std::size_t from, std::size_t to, unsigned channels,
                         std::span<const TexelSpan> rows);
    /** Copies the base's bytes of channels to the composite in rect (no layer touches it). */
    void copyBase(std::uint32_t page, const TileRect& rect, unsigned channels,
                  std::span<const TexelSpan> rows);
    /** A page's row width and its base and composite bytes (material ones: null unless painted). */
    struct PageBytes {
        std::size_t width = 0;
        const std::uint8_t* baseColor = nullptr;
        std::uint8_t* color = nullptr;
        const std::uint8_t* baseMr = nullptr;
        std::uint8_t* mr = nullptr;
    };
    PageBytes pageBytes(std::uint32_t page, unsigned channels);

    std::vector<PageSize> m_pages;
    std::vector<std::vector<std::uint8_t>> m_baseColor;
    std::vector<std::vector<std::uint8_t>> m_baseMetallicRoughness;
    std::vector<std::unique_ptr<PaintLayer>> m_layers;
    std::vector<Image> m_compositeColor;
    std::vector<Image> m_compositeMr;
    std::uint64_t m_nextId = 1;
    // The stroke's updates (beginStroke()): its layer and channels, and per tile (page << 32 |
    // tile) the composite of the layers below its layer, as blendLayers() values of the tile.
    bool m_inStroke = false;
    std::uint64_t m_strokeLayer = 0;
    unsigned m_strokeChannels = 0;
    std::unordered_map<std::uint64_t, std::vector<float>> m_below;
    std::mutex m_belowLock; // updateRect() of different tiles at the same time
};

namespace layer_bytes {
/** std::lround(v·255) of v clamped to 0..1, without the library call: v + 0.5 is exact in double.
 */
inline std::uint8_t toByte(float v) {
    return std::uint8_t(int(double(std::clamp(v, 0.0f, 1.0f) * 255.0f) + 0.5));
}
inline float fromByte(std::uint8_t b) {
    return float(b) * (1.0f / 255.0f);
}

#if defined(__SSE2__)
/** fromByte() of the four bytes at p, lane by lane. */
inline __m128 fromBytes4(const std::uint8_t* p) {
    std::int32_t word;
    std::memcpy(&word, p, 4);
    const __m128i zero = _mm_setzero_si128();
    const __m128i ints = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(word), zero), zero);
    return _mm_mul_ps(_mm_cvtepi32_ps(ints), _mm_set1_ps(1.0f / 255.0f));
}

/**
 * toByte() of four values, lane by lane, in the lanes' low bytes. toByte() truncates
 * double(f) + 0.5 with f = clamp(v)·255, which is exact; here that is trunc(f), plus one where
 * f - trunc(f) (also exact) is at least 0.5. Values are not NaN.
 */
inline __m128i toBytes4(__m128 v) {
    const __m128 f = _mm_mul_ps(_mm_min_ps(_mm_max_ps(v, _mm_setzero_ps()), _mm_set1_ps(1.0f)),
                                _mm_set1_ps(255.0f));
    const __m128i whole = _mm_cvttps_epi32(f);
    const __m128 up = _mm_cmpge_ps(_mm_sub_ps(f, _mm_cvtepi32_ps(whole)), _mm_set1_ps(0.5f));
    return _mm_sub_epi32(whole, _mm_castps_si128(up));
}

/**
 * Source-over in lanes, as paintTexelOf() computes it: in the lanes of values, value over start
 * with the start's coverage a0 and stroke coverage a, divided by the new coverage out; in the
 * other lanes out itself (out / 1). Lanes whose out is not positive give 0.
 */
inline __m128 sourceOver4(__m128 values, __m128 value, __m128 start, __m128 a0, float a) {
    const __m128 av = _mm_set1_ps(a);
    const __m128 out = _mm_add_ps(av, _mm_mul_ps(a0, _mm_set1_ps(1.0f - a)));
    const __m128 premultiplied =
        _mm_add_ps(_mm_mul_ps(av, value), _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(1.0f - a), a0), start));
    const __m128 numerator =
        _mm_or_ps(_mm_and_ps(values, premultiplied), _mm_andnot_ps(values, out));
    const __m128 denominator =
        _mm_or_ps(_mm_and_ps(values, out), _mm_andnot_ps(values, _mm_set1_ps(1.0f)));
    return _mm_and_ps(_mm_cmpgt_ps(out, _mm_setzero_ps()), _mm_div_ps(numerator, denominator));
}

/** The four lanes of toBytes4() (0..255) as four bytes, lane 0 in the lowest. */
inline std::uint32_t packBytes4(__m128i bytes) {
    const __m128i words = _mm_packs_epi32(bytes, bytes);
    return std::uint32_t(_mm_cvtsi128_si32(_mm_packus_epi16(words, words)));
}

/** Stores the four lanes of toBytes4() (0..255) as four bytes at p. */
inline void storeBytes4(std::uint8_t* p, __m128i bytes) {
    const std::uint32_t word = packBytes4(bytes);
    std::memcpy(p, &word, 4);
}
#endif
} // namespace layer_bytes

/** The least coverage for which paintTexel() takes the bytes of emptyTexelByte(). */
inline constexpr float kEmptyTexelMinCoverage = 0x1p-60f;

/**
 * The byte paintTexel() gives a component painted with value into a texel that held nothing at
 * the stroke's start (coverage 0), where that byte does not depend on the stroke's coverage a
 * (kEmptyTexelMinCoverage..1); -1 where it does. There paintTexel() computes (a·value)/a: value
 * itself for 0 and powers of two, else a float within 2.1 units in the last place of value.
 */
std::int16_t emptyTexelByte(float value);

/**
 * A paint layer's texel after a stroke's paint of value (Components 1 or 3, 0..1) with stroke
 * coverage a (0..1) over its value at the stroke's start: source-over (the coverage grows) or,
 * with lockTransparency, only the colour moves towards value in proportion to a. texel and start
 * have Components + 1 bytes (the last is the coverage). empty, if given, holds emptyTexelByte()
 * of each value: a texel that held nothing takes those bytes without the arithmetic (the same
 * bytes). Always inlined: a dab calls it per texel and channel.
 */
template <int Components>
[[gnu::always_inline]] inline void paintTexelOf(std::uint8_t* texel, const std::uint8_t* start,
                                                const float* value, float a, bool lockTransparency,
                                                const std::int16_t* empty = nullptr) {
    using layer_bytes::fromByte;
    using layer_bytes::toByte;
    a = std::clamp(a, 0.0f, 1.0f);
    const float a0 = fromByte(start[Components]);
    if (lockTransparency) {
        for (int k = 0; k < Components; ++k) {
            const float c0 = fromByte(start[k]);
            texel[k] = a0 > 0.0f ? toByte(c0 + a * (value[k] - c0)) : start[k];
        }
        texel[Components] = start[Components];
        return;
    }
#if defined(__SSE2__)
    if constexpr (Components == 3) {
        // The arithmetic below lane by lane, the same operations in the same order: colour in
        // lanes 0..2, the coverage (out / 1) in lane 3. It gives the bytes of both short cuts.
        const __m128 start4 = layer_bytes::fromBytes4(start);
        const __m128 result =
            layer_bytes::sourceOver4(_mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0)),
                                     _mm_setr_ps(value[0], value[1], value[2], 0.0f), start4,
                                     _mm_shuffle_ps(start4, start4, _MM_SHUFFLE(3, 3, 3, 3)), a);
        layer_bytes::storeBytes4(texel, layer_bytes::toBytes4(result));
        return;
    }
#endif
    if (a == 1.0f) {
        // Full coverage: out is 1 + a0·0 = 1 and the premultiplied value is exactly value.
        for (int k = 0; k < Components; ++k)
            texel[k] = toByte(value[k]);
        texel[Components] = toByte(1.0f);
        return;
    }
    const float out = a + a0 * (1.0f - a);
    const bool wasEmpty = empty != nullptr && start[Components] == 0 && a >= kEmptyTexelMinCoverage;
    for (int k = 0; k < Components; ++k) {
        if (wasEmpty && empty[k] >= 0) {
            texel[k] = std::uint8_t(empty[k]);
            continue;
        }
        const float premultiplied = a * value[k] + (1.0f - a) * a0 * fromByte(start[k]);
        texel[k] = toByte(out > 0.0f ? premultiplied / out : 0.0f);
    }
    texel[Components] = toByte(out);
}
/**
 * paintTexelOf<1>() of two channels of one component at once (roughness and metallic): texels
 * first and second (either may be nullptr: not painted), their starts, values[0] and values[1].
 */
[[gnu::always_inline]] inline void paintTexelPair(std::uint8_t* first, std::uint8_t* second,
                                                  const std::uint8_t* startFirst,
                                                  const std::uint8_t* startSecond,
                                                  const float* values, float a,
                                                  bool lockTransparency) {
#if defined(__SSE2__)
    if (!lockTransparency) {
        // The arithmetic of paintTexelOf() lane by lane: the values in lanes 0 and 1, their
        // coverages (out / 1) in lanes 2 and 3.
        a = std::clamp(a, 0.0f, 1.0f);
        const std::uint8_t bytes[4] = {startFirst[0], startSecond[0], startFirst[1],
                                       startSecond[1]};
        const __m128 start4 = layer_bytes::fromBytes4(bytes);
        const __m128 result =
            layer_bytes::sourceOver4(_mm_castsi128_ps(_mm_setr_epi32(-1, -1, 0, 0)),
                                     _mm_setr_ps(values[0], values[1], 0.0f, 0.0f), start4,
                                     _mm_shuffle_ps(start4, start4, _MM_SHUFFLE(3, 2, 3, 2)), a);
        std::uint8_t texels[4];
        layer_bytes::storeBytes4(texels, layer_bytes::toBytes4(result));
        if (first != nullptr) {
            first[0] = texels[0];
            first[1] = texels[2];
        }
        if (second != nullptr) {
            second[0] = texels[1];
            second[1] = texels[3];
        }
        return;
    }
#endif
    if (first != nullptr)
        paintTexelOf<1>(first, startFirst, &values[0], a, lockTransparency);
    if (second != nullptr)
        paintTexelOf<1>(second, startSecond, &values[1], a, lockTransparency);
}
/** paintTexelOf() with the number of components (1 or 3) given at run time. */
inline void paintTexel(std::uint8_t* texel, const std::uint8_t* start, int components,
                       const float* value, float a, bool lockTransparency,
                       const std::int16_t* empty = nullptr) {
    if (components == 3)
        paintTexelOf<3>(texel, start, value, a, lockTransparency, empty);
    else
        paintTexelOf<1>(texel, start, value, a, lockTransparency, empty);
}
/** A paint layer's texel after erasing with coverage a: its coverage falls to start·(1 - a). */
inline void eraseTexel(std::uint8_t* texel, const std::uint8_t* start, int components, float a) {
    for (int k = 0; k < components; ++k)
        texel[k] = start[k];
    texel[components] = layer_bytes::toByte(layer_bytes::fromByte(start[components]) *
                                            (1.0f - std::clamp(a, 0.0f, 1.0f)));
}

} // namespace core
