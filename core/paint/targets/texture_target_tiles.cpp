// SPDX-License-Identifier: GPL-3.0-or-later
// TextureTarget's undo tiles and refreshes: the bytes of a tile of the base or of a paint layer's
// channels or mask, reading and writing them (undo, redo), the changed texel rectangles and the
// composite recomputed for given tiles.
#include <algorithm>
#include <atomic>
#include <cstring>
#include <span>
#include <vector>

#include "core/base/helper_threads.h"
#include "core/base/parallel.h"
#include "core/paint/targets/paint_context.h"
#include "core/paint/targets/paint_target.h"
#include "core/paint/targets/texture_tile_layout.h"

namespace core {

namespace {

/** Tiles of kTextureTile texels → merged rectangles along tile rows (keys sorted). */
void texelRectsFromTiles(std::vector<TileKey>& keys, const std::vector<TextureTarget::Page>& pages,
                         std::vector<TexelRect>& out) {
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 0; i < keys.size();) {
        const TextureTarget::Page& page = pages[keys[i].page];
        const std::uint32_t row = keys[i].tile / std::uint32_t(page.tilesX);
        std::size_t j = i + 1;
        while (j < keys.size() && keys[j].page == keys[i].page &&
               keys[j].tile == keys[j - 1].tile + 1 &&
               keys[j].tile / std::uint32_t(page.tilesX) == row)
            ++j;
        const int tx0 = int(keys[i].tile % std::uint32_t(page.tilesX));
        const int tx1 = int(keys[j - 1].tile % std::uint32_t(page.tilesX));
        TexelRect rect;
        rect.page = keys[i].page;
        rect.x = tx0 * kTextureTile;
        rect.y = int(row) * kTextureTile;
        rect.width = std::min((tx1 + 1) * kTextureTile, page.image.width) - rect.x;
        rect.height = std::min(rect.y + kTextureTile, page.image.height) - rect.y;
        out.push_back(rect);
        i = j;
    }
}

} // namespace

std::size_t TextureTarget::bytes() const {
    std::size_t total = sizeof(*this);
    for (const Page& p : m_pages)
        total += p.original.rgba.capacity() + p.coverage.capacity() +
                 p.padOffsets.capacity() * sizeof(std::uint32_t) +
                 p.padPairs.capacity() * sizeof(PadPair);
    for (std::uint32_t p = 0; p < m_pages.size(); ++p)
        total += m_stack->baseColor(p).capacity() + m_stack->baseMetallicRoughness(p).capacity() +
                 page(p).rgba.capacity() + metallicRoughnessPage(p).rgba.capacity();
    return total + m_stack->layerBytes() + contextBytes();
}

std::size_t TextureTarget::tileBytes(TileKey key) const {
    if (key.page >= m_pages.size())
        return 0;
    const Page& p = m_pages[key.page];
    if (key.tile >= std::uint32_t(p.tilesX * p.tilesY))
        return 0;
    const int tx = int(key.tile % std::uint32_t(p.tilesX)),
              ty = int(key.tile / std::uint32_t(p.tilesX));
    const int w = std::min(kTextureTile, p.image.width - tx * kTextureTile);
    const int h = std::min(kTextureTile, p.image.height - ty * kTextureTile);
    const std::size_t texels = std::size_t(w) * std::size_t(h);
    if (key.plane == 0)
        return texels * 4;
    if (!layerOfPlane(key.plane))
        return 0;
    return texels * ((key.plane & 1) != 0 ? 1 : kPaintLayerTexelBytes);
}

std::optional<std::size_t> TextureTarget::layerOfPlane(std::uint64_t plane) const {
    return m_stack->indexOf(plane / 2);
}

namespace {

/**
 * Calls fn(byte offset in the page, byte offset in the tile, bytes) for each row of tile of page
 * p, whose bytes are size (tileBytes()).
 */
template <typename Fn>
void forEachTileRow(const TextureTarget::Page& p, std::uint32_t tile, std::size_t size, Fn&& fn) {
    const int tx = int(tile % std::uint32_t(p.tilesX)), ty = int(tile / std::uint32_t(p.tilesX));
    const int w = std::min(kTextureTile, p.image.width - tx * kTextureTile);
    const std::size_t rowBytes = std::size_t(w) * 4;
    for (std::size_t r = 0; r < size / rowBytes; ++r) {
        const std::size_t y = std::size_t(ty * kTextureTile) + r;
        fn((y * std::size_t(p.image.width) + std::size_t(tx * kTextureTile)) * 4, r * rowBytes,
           rowBytes);
    }
}

} // namespace

bool TextureTarget::readTile(TileKey key, std::span<std::uint8_t> out) const {
    const std::size_t size = tileBytes(key);
    if (size == 0 || out.size() != size)
        return false;
    const TileKey planeTile{key.page, key.tile};
    if (key.plane != 0) {
        const PaintLayer& layer = m_stack->layer(*layerOfPlane(key.plane));
        if ((key.plane & 1) != 0) {
            if (layer.mask)
                return layer.mask->readTile(planeTile, out);
            std::fill(out.begin(), out.end(), std::uint8_t(255));
            return true;
        }
        const std::size_t n = size / kPaintLayerTexelBytes;
        for (std::size_t c = 0; c < kPaintChannels; ++c) {
            const std::size_t bytes = n * std::size_t(channelTexelBytes(PaintChannel(c)));
            const std::span<std::uint8_t> part = out.subspan(channelOffset(c, n), bytes);
            if (layer.channels[c])
                layer.channels[c]->readTile(planeTile, part);
            else
                std::fill(part.begin(), part.end(), std::uint8_t(0));
        }
        return true;
    }
    const Page& p = m_pages[key.page];
    const std::vector<std::uint8_t>& base = m_stack->baseColor(key.page);
    forEachTileRow(p, key.tile, size, [&](std::size_t pageAt, std::size_t tileAt, std::size_t n) {
        std::memcpy(out.data() + tileAt, &base[pageAt], n);
    });
    return true;
}

bool TextureTarget::writeTile(TileKey key, std::span<const std::uint8_t> bytes) {
    const std::size_t size = tileBytes(key);
    if (size == 0 || bytes.size() != size)
        return false;
    const TileKey planeTile{key.page, key.tile};
    if (key.plane != 0) {
        const std::size_t index = *layerOfPlane(key.plane);
        if ((key.plane & 1) != 0) {
            m_stack->maskPlane(index).writeTile(planeTile, bytes);
        } else {
            const std::size_t n = size / kPaintLayerTexelBytes;
            for (std::size_t c = 0; c < kPaintChannels; ++c) {
                const auto channel = PaintChannel(c);
                const std::span<const std::uint8_t> part =
                    bytes.subspan(channelOffset(c, n), n * std::size_t(channelTexelBytes(channel)));
                const bool blank =
                    std::all_of(part.begin(), part.end(), [](std::uint8_t b) { return b == 0; });
                if (!blank || m_stack->layer(index).channels[c])
                    m_stack->channelPlane(index, channel)->writeTile(planeTile, part);
            }
        }
    } else {
        Page& p = m_pages[key.page];
        std::vector<std::uint8_t>& base = m_stack->baseColor(key.page);
        forEachTileRow(p, key.tile, size,
                       [&](std::size_t pageAt, std::size_t tileAt, std::size_t n) {
                           std::memcpy(&base[pageAt], bytes.data() + tileAt, n);
                       });
    }
    // Undo and redo write tiles outside strokes: the composite follows at once.
    if (!inStroke())
        m_stack->updateTile(key.page, key.tile);
    else if (key.plane != m_context->strokePlane)
        m_stack->dropStrokeCache(); // not the stroke's plane: what lies below it may change
    return true;
}

void TextureTarget::addChanges(std::vector<TileKey>& keys, PaintChanges& out) const {
    // The composite changes where any plane of a tile did.
    for (TileKey& key : keys)
        key.plane = 0;
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    texelRectsFromTiles(keys, m_pages, out.texels);
}

PaintChanges TextureTarget::refresh(std::vector<TileKey> tiles) {
    for (TileKey& key : tiles)
        key.plane = 0;
    std::sort(tiles.begin(), tiles.end());
    tiles.erase(std::unique(tiles.begin(), tiles.end()), tiles.end());
    tiles.erase(std::remove_if(tiles.begin(), tiles.end(),
                               [&](const TileKey& k) {
                                   return k.page >= m_pages.size() ||
                                          k.tile >= std::uint32_t(m_pages[k.page].tilesX *
                                                                  m_pages[k.page].tilesY);
                               }),
                tiles.end());
    parallelRanges(int(tiles.size()), 0, [&](int, int begin, int end) {
        for (int k = begin; k < end; ++k)
            m_stack->updateTile(tiles[std::size_t(k)].page, tiles[std::size_t(k)].tile);
    });
    PaintChanges changes;
    addChanges(tiles, changes);
    return changes;
}

void TextureTarget::refreshTouched() {
    Context& c = *m_context;
    const auto refresh = [&](const StrokeTile& s, std::vector<TexelSpan>& rows) {
        if (s.x0 >= s.x1 || s.y0 >= s.y1)
            return;
        const Page& page = m_pages[s.key.page];
        TileRect rect;
        rect.x = int(s.key.tile % std::uint32_t(page.tilesX)) * kTextureTile + s.x0;
        rect.y = int(s.key.tile / std::uint32_t(page.tilesX)) * kTextureTile + s.y0;
        rect.width = s.x1 - s.x0;
        rect.height = s.y1 - s.y0;
        // Only the texels the dab wrote in each row: its bounding box holds many more.
        const int tileX = rect.x - s.x0;
        rows.resize(std::size_t(rect.height));
        for (int y = s.y0; y < s.y1; ++y) {
            const int x0 = s.rowX0[std::size_t(y)], x1 = s.rowX1[std::size_t(y)];
            rows[std::size_t(y - s.y0)] =
                x0 < x1 ? TexelSpan{tileX + x0, tileX + x1} : TexelSpan{tileX, tileX};
        }
        m_stack->updateRect(s.key.page, s.key.tile, rect, rows);
    };
    // Without paint layers a refresh copies the base's bytes: not worth a second thread.
    if (m_stack->size() == 0 || c.touched.size() < 2) {
        for (const std::uint32_t slot : c.touched)
            refresh(c.slots[slot], c.rows);
        return;
    }
    // Each tile's composite on its own: the tiles in any order, on every helper.
    std::atomic<std::size_t> next{0};
    HelperThreads& helpers = HelperThreads::shared();
    helpers.run(helpers.width(), [&](int part) {
        std::vector<TexelSpan> own;
        std::vector<TexelSpan>& rows = part == 0 ? c.rows : own;
        for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < c.touched.size();)
            refresh(c.slots[c.touched[k]], rows);
    });
}

} // namespace core
