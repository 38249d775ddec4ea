// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "core/paint/paint_layers/undo_tiles.h"

namespace test {

/** A store of numbered tiles of different sizes, one page. */
class FakeStore : public core::TileStore {
public:
    explicit FakeStore(std::vector<std::size_t> sizes) {
        for (std::size_t i = 0; i < sizes.size(); ++i)
            tiles.emplace_back(sizes[i], std::uint8_t(i));
    }
    std::size_t tileBytes(core::TileKey key) const override {
        return key.page == 0 && key.tile < tiles.size() ? tiles[key.tile].size() : 0;
    }
    bool readTile(core::TileKey key, std::span<std::uint8_t> out) const override {
        if (tileBytes(key) == 0 || out.size() != tileBytes(key))
            return false;
        std::copy(tiles[key.tile].begin(), tiles[key.tile].end(), out.begin());
        return true;
    }
    bool writeTile(core::TileKey key, std::span<const std::uint8_t> bytes) override {
        if (tileBytes(key) == 0 || bytes.size() != tileBytes(key))
            return false;
        std::copy(bytes.begin(), bytes.end(), tiles[key.tile].begin());
        return true;
    }

    /** Changes tiles like a paint step would and returns its record. */
    core::TileUndoRecord paint(std::vector<std::uint32_t> which, std::uint8_t value) {
        core::TileUndoRecord record;
        for (const std::uint32_t t : which) {
            record.addTile({0, t}, tiles[t]);
            for (std::size_t i = 0; i < tiles[t].size(); ++i)
                tiles[t][i] = std::uint8_t(value + i);
        }
        return record;
    }

    std::vector<std::vector<std::uint8_t>> tiles;
};

} // namespace test
