// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/paint_layers/tiled_plane.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace core {

namespace {

/** Fills out with copies of the texel fill (texelBytes bytes; out holds whole texels). */
void fillTexels(std::span<std::uint8_t> out, const std::uint8_t* fill, std::size_t texelBytes) {
    if (out.empty())
        return;
    if (std::all_of(fill, fill + texelBytes, [&](std::uint8_t b) { return b == fill[0]; })) {
        std::memset(out.data(), fill[0], out.size());
        return;
    }
    // The fill texel, then the filled part copied onto the rest, doubling.
    std::memcpy(out.data(), fill, texelBytes);
    for (std::size_t done = texelBytes; done < out.size(); done *= 2)
        std::memcpy(out.data() + done, out.data(), std::min(done, out.size() - done));
}

} // namespace

TiledPlane::TiledPlane(std::vector<PageSize> pages, int texelBytes,
                       std::array<std::uint8_t, 4> fill)
    : m_pages(std::move(pages)), m_texelBytes(std::clamp(texelBytes, 1, 4)), m_fill(fill) {
    m_tiles.resize(m_pages.size());
    for (std::uint32_t p = 0; p < m_pages.size(); ++p)
        m_tiles[p].resize(tileCount(p));
}

std::uint32_t TiledPlane::tilesAcross(std::uint32_t page) const {
    return std::uint32_t((std::max(m_pages[page].width, 0) + kPlaneTile - 1) / kPlaneTile);
}

std::uint32_t TiledPlane::tileCount(std::uint32_t page) const {
    const auto down =
        std::uint32_t((std::max(m_pages[page].height, 0) + kPlaneTile - 1) / kPlaneTile);
    return tilesAcross(page) * down;
}

TileRect TiledPlane::tileRect(std::uint32_t page, std::uint32_t tile) const {
    const std::uint32_t across = std::max(tilesAcross(page), 1u);
    TileRect r;
    r.x = int(tile % across) * kPlaneTile;
    r.y = int(tile / across) * kPlaneTile;
    r.width = std::min(kPlaneTile, m_pages[page].width - r.x);
    r.height = std::min(kPlaneTile, m_pages[page].height - r.y);
    return r;
}

std::uint32_t TiledPlane::tileAt(std::uint32_t page, int x, int y) const {
    return std::uint32_t(y / kPlaneTile) * tilesAcross(page) + std::uint32_t(x / kPlaneTile);
}

const std::uint8_t* TiledPlane::tile(std::uint32_t page, std::uint32_t tile) const {
    const std::vector<std::uint8_t>& t = m_tiles[page][tile];
    return t.empty() ? nullptr : t.data();
}

std::uint8_t* TiledPlane::writableTile(std::uint32_t page, std::uint32_t tile) {
    std::vector<std::uint8_t>& t = m_tiles[page][tile];
    if (t.empty()) {
        const TileRect r = tileRect(page, tile);
        const std::size_t texels = std::size_t(r.width) * std::size_t(r.height);
        const auto texelBytes = std::size_t(m_texelBytes);
        t.resize(texels * texelBytes); // zeros: a blank paint layer's fill
        const auto fillEnd = m_fill.begin() + std::ptrdiff_t(texelBytes);
        if (std::any_of(m_fill.begin(), fillEnd, [](std::uint8_t b) { return b; }))
            fillTexels(t, m_fill.data(), texelBytes);
        m_allocated += t.size();
    }
    return t.data();
}

bool TiledPlane::anyTile(std::uint32_t page) const {
    return std::any_of(m_tiles[page].begin(), m_tiles[page].end(),
                       [](const std::vector<std::uint8_t>& t) { return !t.empty(); });
}

const std::uint8_t* TiledPlane::texel(std::uint32_t page, int x, int y) const {
    const std::uint32_t t = tileAt(page, x, y);
    const std::uint8_t* data = tile(page, t);
    if (data == nullptr)
        return m_fill.data();
    const TileRect r = tileRect(page, t);
    return data + (std::size_t(y - r.y) * std::size_t(r.width) + std::size_t(x - r.x)) *
                      std::size_t(m_texelBytes);
}

std::uint8_t* TiledPlane::writableTexel(std::uint32_t page, int x, int y) {
    const std::uint32_t t = tileAt(page, x, y);
    const TileRect r = tileRect(page, t);
    return writableTile(page, t) +
           (std::size_t(y - r.y) * std::size_t(r.width) + std::size_t(x - r.x)) *
               std::size_t(m_texelBytes);
}

std::size_t TiledPlane::allocatedTiles() const {
    std::size_t n = 0;
    for (const auto& page : m_tiles)
        for (const auto& t : page)
            n += t.empty() ? 0 : 1;
    return n;
}

std::vector<TileKey> TiledPlane::writtenTiles() const {
    std::vector<TileKey> keys;
    for (std::uint32_t p = 0; p < m_tiles.size(); ++p)
        for (std::uint32_t t = 0; t < m_tiles[p].size(); ++t)
            if (!m_tiles[p][t].empty())
                keys.push_back({p, t});
    return keys;
}

std::size_t TiledPlane::tileBytes(TileKey key) const {
    if (key.page >= m_pages.size() || key.tile >= m_tiles[key.page].size())
        return 0;
    const TileRect r = tileRect(key.page, key.tile);
    return std::size_t(r.width) * std::size_t(r.height) * std::size_t(m_texelBytes);
}

bool TiledPlane::readTile(TileKey key, std::span<std::uint8_t> out) const {
    const std::size_t size = tileBytes(key);
    if (size == 0 || out.size() != size)
        return false;
    if (const std::uint8_t* data = tile(key.page, key.tile))
        std::memcpy(out.data(), data, size);
    else
        fillTexels(out, m_fill.data(), std::size_t(m_texelBytes));
    return true;
}

bool TiledPlane::writeTile(TileKey key, std::span<const std::uint8_t> bytes) {
    const std::size_t size = tileBytes(key);
    if (size == 0 || bytes.size() != size)
        return false;
    std::vector<std::uint8_t>& t = m_tiles[key.page][key.tile];
    if (isFill(bytes)) {
        m_allocated -= t.size();
        std::vector<std::uint8_t>().swap(t);
        return true;
    }
    std::memcpy(writableTile(key.page, key.tile), bytes.data(), size);
    return true;
}

bool TiledPlane::isFill(std::span<const std::uint8_t> bytes) const {
    for (std::size_t i = 0; i < bytes.size(); i += std::size_t(m_texelBytes))
        if (std::memcmp(bytes.data() + i, m_fill.data(), std::size_t(m_texelBytes)) != 0)
            return false;
    return true;
}

} // namespace core
