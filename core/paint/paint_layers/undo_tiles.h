// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace core {

/**
 * One tile of a tiled store: a texture tile of one page, or a block of vertex colours. plane says
 * which of a store's planes it belongs to: 0 for the store's own data; a texture target keys its
 * paint layers' tiles by layer (see TextureTarget::planeKey()).
 */
struct TileKey {
    std::uint32_t page = 0;
    std::uint32_t tile = 0;
    std::uint64_t plane = 0;

    friend bool operator==(const TileKey&, const TileKey&) = default;
    friend auto operator<=>(const TileKey&, const TileKey&) = default;
};

/**
 * Something whose state is a set of fixed byte tiles, so undo can store only the tiles a step
 * touched (docs/architecture.md §3 step 6). Paint targets implement it.
 */
class TileStore {
public:
    virtual ~TileStore() = default;
    /** Size in bytes of tile key; 0 for a key the store does not have. */
    virtual std::size_t tileBytes(TileKey key) const = 0;
    /** Copies tile key into out (tileBytes(key) bytes); false (out untouched) if sizes differ. */
    virtual bool readTile(TileKey key, std::span<std::uint8_t> out) const = 0;
    /** Overwrites tile key with bytes; false (nothing written) if sizes differ. */
    virtual bool writeTile(TileKey key, std::span<const std::uint8_t> bytes) = 0;
};

/**
 * One undoable step: the touched tiles of a store and, for each, its bytes in the state the store
 * is not in. The record swaps those bytes with the store's on undo() and again on redo(), so it
 * costs one copy of the touched tiles and restores them byte for byte. A QUndoCommand can hold
 * one (it is movable) and call undo()/redo() on the target; bytes() lets a holder enforce a
 * memory budget.
 */
class TileUndoRecord {
public:
    TileUndoRecord() = default;
    TileUndoRecord(TileUndoRecord&&) noexcept = default;
    TileUndoRecord& operator=(TileUndoRecord&&) noexcept = default;
    TileUndoRecord(const TileUndoRecord&) = delete;
    TileUndoRecord& operator=(const TileUndoRecord&) = delete;

    /** Makes room for tiles of about totalBytes in all (optional). */
    void reserve(std::size_t tiles, std::size_t totalBytes);
    /** Adds a tile with its bytes before the step (the store holds the state after it). */
    void addTile(TileKey key, std::span<const std::uint8_t> before);

    /**
     * Puts the store back to the state before the step. Returns false, changing nothing, if the
     * step is already undone or a tile's size does not match the store (a record of another
     * store).
     */
    bool undo(TileStore& store);
    /** Puts the store into the state after the step again; false as undo() otherwise. */
    bool redo(TileStore& store);
    bool isUndone() const { return m_undone; }

    bool empty() const { return m_entries.empty(); }
    std::size_t tileCount() const { return m_entries.size(); }
    TileKey tile(std::size_t i) const { return m_entries[i].key; }
    /** The keys of the tiles, in the order added (for finding what to update after undo). */
    std::vector<TileKey> tiles() const;
    /** Memory held, in bytes (tile data, index and the object itself). */
    std::size_t bytes() const;

private:
    struct Entry {
        TileKey key;
        std::size_t offset = 0;
        std::size_t size = 0;
    };
    bool swapWith(TileStore& store);

    std::vector<Entry> m_entries;
    std::vector<std::uint8_t> m_data;
    bool m_undone = false;
};

} // namespace core
