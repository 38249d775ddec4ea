// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/paint/paint_layers/undo_tiles.h"

namespace core {

/** The size of one page of a paint target: a texture, or vertices laid out in rows. */
struct PageSize {
    int width = 0;
    int height = 0;

    friend bool operator==(const PageSize&, const PageSize&) = default;
};

/** A tile's texels within its page. */
struct TileRect {
    int x = 0, y = 0, width = 0, height = 0;
};

/** Texels [x0, x1) of one row of a TileRect. */
struct TexelSpan {
    int x0 = 0, x1 = 0;
};

/**
 * A sparse image over pages: each page is cut into tiles of kPlaneTile² texels (edge tiles are
 * smaller) of texelBytes bytes each, and a tile holds memory only once written; before that it
 * reads as the plane's fill value. Paint layers keep their channels and masks in these, so memory
 * grows with what was painted, not with the number of layers. A TileStore (key: page, tile), so
 * undo records restore it; writing a tile that is all fill value releases its memory again.
 */
class TiledPlane : public TileStore {
public:
    static constexpr int kPlaneTile = 64;

    TiledPlane(std::vector<PageSize> pages, int texelBytes, std::array<std::uint8_t, 4> fill);

    const std::vector<PageSize>& pages() const { return m_pages; }
    int texelBytes() const { return m_texelBytes; }
    /** The value an unwritten texel has (the first texelBytes() bytes). */
    const std::array<std::uint8_t, 4>& fill() const { return m_fill; }

    std::uint32_t tilesAcross(std::uint32_t page) const;
    std::uint32_t tileCount(std::uint32_t page) const;
    TileRect tileRect(std::uint32_t page, std::uint32_t tile) const;
    /** The tile holding texel (x, y) of page. */
    std::uint32_t tileAt(std::uint32_t page, int x, int y) const;

    /** The tile's texels (row by row, tileRect().width per row), or nullptr if never written. */
    const std::uint8_t* tile(std::uint32_t page, std::uint32_t tile) const;
    /** The tile's texels for writing; an unwritten tile is made, filled with the fill value. */
    std::uint8_t* writableTile(std::uint32_t page, std::uint32_t tile);
    /** Whether any tile of page holds memory. */
    bool anyTile(std::uint32_t page) const;

    /** Texel (x, y) of page: in its tile, or the fill value. */
    const std::uint8_t* texel(std::uint32_t page, int x, int y) const;
    std::uint8_t* writableTexel(std::uint32_t page, int x, int y);

    /** Bytes of tile data held (what painting has cost). */
    std::size_t allocatedBytes() const { return m_allocated; }
    std::size_t allocatedTiles() const;
    /** Every tile that holds memory, page by page in tile order. */
    std::vector<TileKey> writtenTiles() const;

    // TileStore: every tile of every page has its full size, written or not.
    std::size_t tileBytes(TileKey key) const override;
    bool readTile(TileKey key, std::span<std::uint8_t> out) const override;
    bool writeTile(TileKey key, std::span<const std::uint8_t> bytes) override;

private:
    bool isFill(std::span<const std::uint8_t> bytes) const;

    std::vector<PageSize> m_pages;
    int m_texelBytes;
    std::array<std::uint8_t, 4> m_fill;
    std::vector<std::vector<std::vector<std::uint8_t>>> m_tiles; // page, tile: texels or empty
    std::size_t m_allocated = 0;
};

} // namespace core
