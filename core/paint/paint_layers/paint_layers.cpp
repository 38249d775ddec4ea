// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/paint_layers/paint_layers.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/base/parallel.h"

namespace core {

namespace {

using layer_bytes::fromByte;
using layer_bytes::toByte;

int components(PaintChannel channel) {
    return channel == PaintChannel::BaseColor ? 3 : 1;
}

/** Where values[] keeps a channel: base colour 0..2, roughness 3, metallic 4. */
int firstValue(PaintChannel channel) {
    return channel == PaintChannel::BaseColor ? 0 : channel == PaintChannel::Roughness ? 3 : 4;
}

std::optional<std::array<float, 3>> fillValue(const ChannelValues& fill, PaintChannel channel) {
    switch (channel) {
    case PaintChannel::BaseColor:
        if (fill.baseColor)
            return std::array<float, 3>{fill.baseColor->x, fill.baseColor->y, fill.baseColor->z};
        break;
    case PaintChannel::Roughness:
        if (fill.roughness)
            return std::array<float, 3>{*fill.roughness, 0.0f, 0.0f};
        break;
    case PaintChannel::Metallic:
        if (fill.metallic)
            return std::array<float, 3>{*fill.metallic, 0.0f, 0.0f};
        break;
    }
    return std::nullopt;
}

/** A layer's value and effective coverage (opacity and mask included) at a texel. */
struct Sample {
    std::array<float, 3> value{};
    float a = 0.0f;
};

bool sampleLayer(const PaintLayer& layer, PaintChannel channel, std::uint32_t page, int x, int y,
                 Sample& s) {
    const PaintLayerSettings& st = layer.settings;
    const int n = components(channel);
    if (st.kind == PaintLayerKind::Fill) {
        const std::optional<std::array<float, 3>> v = fillValue(st.fill, channel);
        if (!v)
            return false;
        s.value = *v;
        s.a = 1.0f;
    } else {
        const TiledPlane* plane = layer.channels[std::size_t(channel)].get();
        if (plane == nullptr)
            return false;
        const std::uint8_t* t = plane->texel(page, x, y);
        s.a = fromByte(t[n]);
        for (int k = 0; k < n; ++k)
            s.value[std::size_t(k)] = fromByte(t[k]);
    }
    s.a *= std::clamp(st.opacity, 0.0f, 1.0f);
    if (layer.mask)
        s.a *= fromByte(layer.mask->texel(page, x, y)[0]);
    return s.a > 0.0f;
}

} // namespace

bool PaintLayer::touchesTile(std::uint32_t page, std::uint32_t tile) const {
    if (!settings.visible || settings.opacity <= 0.0f)
        return false;
    if (settings.kind == PaintLayerKind::Fill)
        return true;
    for (const auto& plane : channels)
        if (plane && plane->tile(page, tile) != nullptr)
            return true;
    return false;
}

int channelTexelBytes(PaintChannel channel) {
    return components(channel) + 1;
}

void writeMaskAsGrey(const TiledPlane& mask, std::uint32_t page, const TileRect& rect,
                     Image& image) {
    const int x0 = std::max(rect.x, 0), y0 = std::max(rect.y, 0);
    const int x1 = std::min(rect.x + rect.width, image.width);
    const int y1 = std::min(rect.y + rect.height, image.height);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::uint8_t v = mask.texel(page, x, y)[0];
            std::uint8_t* out =
                &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
            out[0] = out[1] = out[2] = v;
            out[3] = 255;
        }
}

std::int16_t emptyTexelByte(float value) {
    using layer_bytes::toByte;
    if (!(value >= 0.0f && value <= 1.0f))
        return -1;
    if (value == 0.0f)
        return toByte(value);
    // Below this a·value could leave the normal floats, where the bound does not hold.
    if (value < kEmptyTexelMinCoverage)
        return -1;
    // A power of two: a·value and (a·value)/a are exact.
    int exponent = 0;
    if (std::frexp(value, &exponent) == 0.5f)
        return toByte(value);
    // (a·value)/a is value·(1 + d1)·(1 + d2), |d| ≤ 2⁻²⁴: within 2.1 units in the last place
    // of value, 4.2 steps of the binade below. toByte() never falls as its argument grows, so
    // equal bytes 8 steps either side hold for every float between.
    float below = value, above = value;
    for (int step = 0; step < 8; ++step) {
        below = std::nextafter(below, 0.0f);
        above = std::nextafter(above, 2.0f);
    }
    return toByte(below) == toByte(above) ? toByte(value) : std::int16_t(-1);
}

std::size_t PaintLayer::bytes() const {
    std::size_t n = mask ? mask->allocatedBytes() : 0;
    for (const auto& plane : channels)
        n += plane ? plane->allocatedBytes() : 0;
    return n;
}

PaintLayerStack::PaintLayerStack(std::vector<PageSize> pages,
                                 std::vector<std::vector<std::uint8_t>> baseColor,
                                 std::vector<std::vector<std::uint8_t>> baseMetallicRoughness)
    : m_pages(std::move(pages)), m_baseColor(std::move(baseColor)),
      m_baseMetallicRoughness(std::move(baseMetallicRoughness)) {
    m_baseColor.resize(m_pages.size());
    for (std::size_t p = 0; p < m_pages.size(); ++p) {
        const std::size_t texels = std::size_t(m_pages[p].width) * std::size_t(m_pages[p].height);
        m_baseColor[p].resize(texels * 4, 255);
        if (!m_baseMetallicRoughness.empty()) {
            m_baseMetallicRoughness.resize(m_pages.size());
            m_baseMetallicRoughness[p].resize(texels * 4, 255);
        }
    }
    for (std::size_t p = 0; p < m_pages.size(); ++p) {
        m_compositeColor.push_back({m_pages[p].width, m_pages[p].height, m_baseColor[p]});
        if (hasMaterialChannels())
            m_compositeMr.push_back(
                {m_pages[p].width, m_pages[p].height, m_baseMetallicRoughness[p]});
    }
}

std::optional<std::size_t> PaintLayerStack::indexOf(std::uint64_t id) const {
    for (std::size_t i = 0; i < m_layers.size(); ++i)
        if (m_layers[i]->id == id)
            return i;
    return std::nullopt;
}

std::unique_ptr<PaintLayer> PaintLayerStack::makeLayer(PaintLayerSettings settings) {
    auto layer = std::make_unique<PaintLayer>();
    layer->id = m_nextId++;
    layer->settings = std::move(settings);
    return layer;
}

std::unique_ptr<TiledPlane> PaintLayerStack::makePlane(int texelBytes,
                                                       std::array<std::uint8_t, 4> fill) const {
    return std::make_unique<TiledPlane>(m_pages, texelBytes, fill);
}

std::size_t PaintLayerStack::add(PaintLayerSettings settings, std::size_t index) {
    dropStrokeCache();
    index = std::min(index, m_layers.size());
    m_layers.insert(m_layers.begin() + std::ptrdiff_t(index), makeLayer(std::move(settings)));
    return index;
}

std::size_t PaintLayerStack::duplicate(std::size_t index) {
    dropStrokeCache();
    const PaintLayer& from = *m_layers.at(index);
    PaintLayerSettings settings = from.settings;
    settings.name += " copy";
    std::unique_ptr<PaintLayer> copy = makeLayer(std::move(settings));
    for (std::size_t c = 0; c < kPaintChannels; ++c)
        if (from.channels[c])
            copy->channels[c] = std::make_unique<TiledPlane>(*from.channels[c]);
    if (from.mask)
        copy->mask = std::make_unique<TiledPlane>(*from.mask);
    m_layers.insert(m_layers.begin() + std::ptrdiff_t(index + 1), std::move(copy));
    return index + 1;
}

std::unique_ptr<PaintLayer> PaintLayerStack::take(std::size_t index) {
    dropStrokeCache();
    std::unique_ptr<PaintLayer> layer = std::move(m_layers.at(index));
    m_layers.erase(m_layers.begin() + std::ptrdiff_t(index));
    return layer;
}

void PaintLayerStack::insert(std::unique_ptr<PaintLayer> layer, std::size_t index) {
    dropStrokeCache();
    index = std::min(index, m_layers.size());
    m_nextId = std::max(m_nextId, layer->id + 1);
    m_layers.insert(m_layers.begin() + std::ptrdiff_t(index), std::move(layer));
}

void PaintLayerStack::move(std::size_t from, std::size_t to) {
    if (m_layers.empty())
        return;
    from = std::min(from, m_layers.size() - 1);
    to = std::min(to, m_layers.size() - 1);
    std::unique_ptr<PaintLayer> layer = take(from);
    insert(std::move(layer), to);
}

void PaintLayerStack::setSettings(std::size_t index, PaintLayerSettings settings) {
    dropStrokeCache();
    m_layers.at(index)->settings = std::move(settings);
}

TiledPlane* PaintLayerStack::channelPlane(std::size_t index, PaintChannel channel) {
    if (channel != PaintChannel::BaseColor && !hasMaterialChannels())
        return nullptr;
    std::unique_ptr<TiledPlane>& plane = m_layers.at(index)->channels[std::size_t(channel)];
    if (!plane)
        plane = makePlane(channelTexelBytes(channel), {0, 0, 0, 0});
    return plane.get();
}

TiledPlane& PaintLayerStack::maskPlane(std::size_t index) {
    std::unique_ptr<TiledPlane>& mask = m_layers.at(index)->mask;
    if (!mask)
        mask = makePlane(1, {255, 255, 255, 255});
    return *mask;
}

std::unique_ptr<TiledPlane> PaintLayerStack::takeMask(std::size_t index) {
    dropStrokeCache();
    return std::move(m_layers.at(index)->mask);
}

void PaintLayerStack::compositeTexel(std::uint32_t page, int x, int y, std::size_t end,
                                     std::array<float, 5>& values) const {
    const std::size_t i = (std::size_t(y) * std::size_t(m_pages[page].width) + std::size_t(x)) * 4;
    const std::uint8_t* color = m_baseColor[page].data() + i;
    values = {fromByte(color[0]), fromByte(color[1]), fromByte(color[2]), 1.0f, 0.0f};
    if (hasMaterialChannels()) {
        values[3] = fromByte(m_baseMetallicRoughness[page][i + 1]);
        values[4] = fromByte(m_baseMetallicRoughness[page][i + 2]);
    }
    const std::size_t channels = hasMaterialChannels() ? kPaintChannels : 1;
    for (std::size_t l = 0; l < end; ++l) {
        const PaintLayer& layer = *m_layers[l];
        if (!layer.settings.visible)
            continue;
        for (std::size_t c = 0; c < channels; ++c) {
            const auto channel = PaintChannel(c);
            Sample s;
            if (!sampleLayer(layer, channel, page, x, y, s))
                continue;
            const int first = firstValue(channel);
            for (int k = 0; k < components(channel); ++k) {
                float& v = values[std::size_t(first + k)];
                v += s.a * (blend(layer.settings.blend, v, s.value[std::size_t(k)]) - v);
            }
        }
    }
}

std::vector<TileKey> PaintLayerStack::allTiles() const {
    std::vector<TileKey> tiles;
    for (std::uint32_t p = 0; p < m_pages.size(); ++p) {
        const std::uint32_t across =
            std::uint32_t((m_pages[p].width + TiledPlane::kPlaneTile - 1) / TiledPlane::kPlaneTile);
        const std::uint32_t down = std::uint32_t((m_pages[p].height + TiledPlane::kPlaneTile - 1) /
                                                 TiledPlane::kPlaneTile);
        for (std::uint32_t t = 0; t < across * down; ++t)
            tiles.push_back({p, t});
    }
    return tiles;
}

std::vector<TileKey> PaintLayerStack::tilesCovered(const PaintLayer& layer) const {
    if (layer.settings.kind == PaintLayerKind::Fill)
        return allTiles();
    std::vector<TileKey> tiles;
    for (const auto& plane : layer.channels)
        if (plane) {
            const std::vector<TileKey> written = plane->writtenTiles();
            tiles.insert(tiles.end(), written.begin(), written.end());
        }
    std::sort(tiles.begin(), tiles.end());
    tiles.erase(std::unique(tiles.begin(), tiles.end()), tiles.end());
    return tiles;
}

void PaintLayerStack::updateAll() {
    const std::vector<TileKey> tiles = allTiles();
    parallelRanges(int(tiles.size()), 0, [&](int, int begin, int end) {
        for (int k = begin; k < end; ++k)
            updateTile(tiles[std::size_t(k)].page, tiles[std::size_t(k)].tile);
    });
}

bool PaintLayerStack::mergeDown(std::size_t index,
                                std::vector<std::unique_ptr<PaintLayer>>* removed) {
    if (index == 0 || index >= m_layers.size())
        return false;
    dropStrokeCache();
    PaintLayer& upper = *m_layers[index];
    PaintLayer& lower = *m_layers[index - 1];
    auto merged = std::make_unique<PaintLayer>();
    merged->id = lower.id;
    merged->settings = lower.settings;
    merged->settings.kind = PaintLayerKind::Paint;
    merged->settings.opacity = 1.0f;
    merged->settings.fill = {};
    const std::size_t channels = hasMaterialChannels() ? kPaintChannels : 1;
    for (std::size_t c = 0; c < channels; ++c) {
        const auto channel = PaintChannel(c);
        const int n = components(channel);
        auto plane = makePlane(channelTexelBytes(channel), {0, 0, 0, 0});
        for (std::uint32_t p = 0; p < m_pages.size(); ++p) {
            for (std::uint32_t t = 0; t < plane->tileCount(p); ++t) {
                const bool inUpper = upper.settings.visible && upper.touchesTile(p, t);
                const bool inLower = lower.settings.kind == PaintLayerKind::Fill ||
                                     (lower.channels[c] && lower.channels[c]->tile(p, t));
                if (!inUpper && !inLower)
                    continue;
                const TileRect r = plane->tileRect(p, t);
                for (int y = r.y; y < r.y + r.height; ++y)
                    for (int x = r.x; x < r.x + r.width; ++x) {
                        Sample lo, up;
                        const bool hasLo = sampleLayer(lower, channel, p, x, y, lo);
                        const bool hasUp = inUpper && sampleLayer(upper, channel, p, x, y, up);
                        if (!hasLo && !hasUp)
                            continue;
                        if (!hasLo)
                            lo.a = 0.0f;
                        if (!hasUp)
                            up.a = 0.0f;
                        // The upper layer composited onto the lower one as onto a backdrop with
                        // that coverage: what the two give over anything below a normal layer.
                        const float a = up.a + lo.a * (1.0f - up.a);
                        std::uint8_t* out = plane->writableTexel(p, x, y);
                        for (int k = 0; k < n; ++k) {
                            const float cl = lo.value[std::size_t(k)];
                            const float cu = up.value[std::size_t(k)];
                            const float mixed =
                                (1.0f - lo.a) * cu + lo.a * blend(upper.settings.blend, cl, cu);
                            const float premultiplied = up.a * mixed + (1.0f - up.a) * lo.a * cl;
                            out[k] = toByte(a > 0.0f ? premultiplied / a : 0.0f);
                        }
                        out[n] = toByte(a);
                    }
            }
        }
        if (plane->allocatedTiles() > 0)
            merged->channels[c] = std::move(plane);
    }
    if (removed) {
        removed->clear();
        removed->push_back(std::move(m_layers[index - 1]));
        removed->push_back(std::move(m_layers[index]));
    }
    m_layers[index - 1] = std::move(merged);
    m_layers.erase(m_layers.begin() + std::ptrdiff_t(index));
    return true;
}

void PaintLayerStack::flatten(std::string name, std::vector<std::unique_ptr<PaintLayer>>* removed) {
    dropStrokeCache();
    PaintLayerSettings settings;
    settings.name = std::move(name);
    std::unique_ptr<PaintLayer> flat = makeLayer(std::move(settings));
    const std::size_t channels = hasMaterialChannels() ? kPaintChannels : 1;
    for (std::size_t c = 0; c < channels; ++c) {
        const auto channel = PaintChannel(c);
        const int n = components(channel), first = firstValue(channel);
        auto plane = makePlane(channelTexelBytes(channel), {0, 0, 0, 0});
        for (std::uint32_t p = 0; p < m_pages.size(); ++p)
            for (std::uint32_t t = 0; t < plane->tileCount(p); ++t) {
                const TileRect r = plane->tileRect(p, t);
                for (int y = r.y; y < r.y + r.height; ++y)
                    for (int x = r.x; x < r.x + r.width; ++x) {
                        bool covered = false;
                        for (const auto& layer : m_layers) {
                            Sample s;
                            if (layer->settings.visible &&
                                sampleLayer(*layer, channel, p, x, y, s)) {
                                covered = true;
                                break;
                            }
                        }
                        if (!covered)
                            continue;
                        std::array<float, 5> values{};
                        compositeTexel(p, x, y, m_layers.size(), values);
                        std::uint8_t* out = plane->writableTexel(p, x, y);
                        for (int k = 0; k < n; ++k)
                            out[k] = toByte(values[std::size_t(first + k)]);
                        out[n] = 255;
                    }
            }
        if (plane->allocatedTiles() > 0)
            flat->channels[c] = std::move(plane);
    }
    if (removed)
        *removed = std::move(m_layers);
    m_layers.clear();
    m_layers.push_back(std::move(flat));
}

const std::vector<std::uint8_t>&
PaintLayerStack::compositeMetallicRoughness(std::uint32_t page) const {
    return compositeMetallicRoughnessImage(page).rgba;
}

const Image& PaintLayerStack::compositeMetallicRoughnessImage(std::uint32_t page) const {
    static const Image none;
    return hasMaterialChannels() ? m_compositeMr[page] : none;
}

const std::vector<std::uint8_t>& PaintLayerStack::baseMetallicRoughness(std::uint32_t page) const {
    static const std::vector<std::uint8_t> none;
    return hasMaterialChannels() ? m_baseMetallicRoughness[page] : none;
}

std::size_t PaintLayerStack::layerBytes() const {
    std::size_t n = 0;
    for (const auto& layer : m_layers)
        n += layer->bytes();
    return n;
}

} // namespace core
