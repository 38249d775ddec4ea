// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/paint_layers/undo_tiles.h"

#include <algorithm>
#include <cstring>
#include <utility>

namespace core {

void TileUndoRecord::reserve(std::size_t tiles, std::size_t totalBytes) {
    m_entries.reserve(tiles);
    m_data.reserve(totalBytes);
}

void TileUndoRecord::addTile(TileKey key, std::span<const std::uint8_t> before) {
    m_entries.push_back({key, m_data.size(), before.size()});
    m_data.insert(m_data.end(), before.begin(), before.end());
}

std::vector<TileKey> TileUndoRecord::tiles() const {
    std::vector<TileKey> keys;
    keys.reserve(m_entries.size());
    for (const Entry& e : m_entries)
        keys.push_back(e.key);
    return keys;
}

std::size_t TileUndoRecord::bytes() const {
    return sizeof(*this) + m_entries.capacity() * sizeof(Entry) + m_data.capacity();
}

bool TileUndoRecord::swapWith(TileStore& store) {
    // Check every tile first so a mismatched store is left untouched, not half swapped.
    std::size_t largest = 0;
    for (const Entry& e : m_entries) {
        if (store.tileBytes(e.key) != e.size)
            return false;
        largest = std::max(largest, e.size);
    }
    std::vector<std::uint8_t> current(largest);
    for (const Entry& e : m_entries) {
        const std::span<std::uint8_t> mine(m_data.data() + e.offset, e.size);
        const std::span<std::uint8_t> scratch(current.data(), e.size);
        store.readTile(e.key, scratch);
        store.writeTile(e.key, mine);
        std::memcpy(mine.data(), scratch.data(), e.size);
    }
    return true;
}

bool TileUndoRecord::undo(TileStore& store) {
    if (m_undone || !swapWith(store))
        return false;
    m_undone = true;
    return true;
}

bool TileUndoRecord::redo(TileStore& store) {
    if (!m_undone || !swapWith(store))
        return false;
    m_undone = false;
    return true;
}

} // namespace core
