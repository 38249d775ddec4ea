// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/undo_tiles.h"

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

bool UndoHistory::push(TileUndoRecord record) {
    // A new step makes the undone ones unreachable.
    while (m_steps.size() > m_next) {
        m_bytes -= m_steps.back().bytes();
        m_steps.pop_back();
    }
    if (record.empty() || record.isUndone())
        return false;
    const std::size_t size = record.bytes();
    if (size > m_budget) {
        // Too big to keep. The older steps must go too: undoing them over this step's changes
        // would restore a mix of states on the tiles both touched.
        m_dropped += m_steps.size() + 1;
        clear();
        return false;
    }
    m_steps.push_back(std::move(record));
    m_bytes += size;
    m_next = m_steps.size();
    enforceBudget();
    return true;
}

const TileUndoRecord* UndoHistory::undo(TileStore& store) {
    if (!canUndo())
        return nullptr;
    TileUndoRecord& record = m_steps[m_next - 1];
    if (!record.undo(store))
        return nullptr;
    --m_next;
    return &record;
}

const TileUndoRecord* UndoHistory::redo(TileStore& store) {
    if (!canRedo())
        return nullptr;
    TileUndoRecord& record = m_steps[m_next];
    if (!record.redo(store))
        return nullptr;
    ++m_next;
    return &record;
}

void UndoHistory::setBudget(std::size_t budgetBytes) {
    m_budget = budgetBytes;
    enforceBudget();
}

void UndoHistory::clear() {
    m_steps.clear();
    m_next = 0;
    m_bytes = 0;
}

void UndoHistory::enforceBudget() {
    // The oldest step goes first: it is the least likely to be wanted back.
    while (m_bytes > m_budget && m_next > 0) {
        m_bytes -= m_steps.front().bytes();
        m_steps.pop_front();
        --m_next;
        ++m_dropped;
    }
    // Only a lowered budget gets here with steps left: drop the furthest redo steps.
    while (m_bytes > m_budget && !m_steps.empty()) {
        m_bytes -= m_steps.back().bytes();
        m_steps.pop_back();
        ++m_dropped;
    }
}

} // namespace core
