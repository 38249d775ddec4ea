// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

namespace core {

/** One tile of a tiled store: a texture tile of one page, or a block of vertex colours. */
struct TileKey {
    std::uint32_t page = 0;
    std::uint32_t tile = 0;

    friend bool operator==(const TileKey&, const TileKey&) = default;
    friend auto operator<=>(const TileKey&, const TileKey&) = default;
};

/**
 * Something whose state is a set of fixed byte tiles, so undo can store only the tiles a step
 * touched (DESIGN.md §3 step 6). Paint targets implement it.
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

/**
 * A linear undo history under a byte budget (DESIGN.md §6): when the records exceed it, the
 * oldest steps are dropped (they can no longer be undone) instead of growing without bound.
 */
class UndoHistory {
public:
    static constexpr std::size_t kDefaultBudget = std::size_t(256) << 20; // 256 MiB

    explicit UndoHistory(std::size_t budgetBytes = kDefaultBudget) : m_budget(budgetBytes) {}

    /**
     * Adds a finished step: forgets the redo steps, then drops the oldest steps while over
     * budget. Returns false for an empty or undone record (ignored), and for one bigger than the
     * whole budget (then nothing can be undone any more: the history is cleared).
     */
    bool push(TileUndoRecord record);
    /** Undoes the newest step on store; the record (for PaintTarget::changes()), or nullptr. */
    const TileUndoRecord* undo(TileStore& store);
    /** Redoes the step undone last; the record, or nullptr if there is none. */
    const TileUndoRecord* redo(TileStore& store);

    bool canUndo() const { return m_next > 0; }
    bool canRedo() const { return m_next < m_steps.size(); }
    std::size_t undoCount() const { return m_next; }
    std::size_t redoCount() const { return m_steps.size() - m_next; }
    /** Steps dropped so far to stay within the budget. */
    std::size_t droppedCount() const { return m_dropped; }

    /** Memory held by the records, in bytes; never more than budget(). */
    std::size_t bytes() const { return m_bytes; }
    std::size_t budget() const { return m_budget; }
    /** Changes the budget, dropping the oldest steps (then the furthest redo steps) to fit. */
    void setBudget(std::size_t budgetBytes);
    /** Forgets every step (e.g. when the paint target is replaced). */
    void clear();

private:
    void enforceBudget();

    std::deque<TileUndoRecord> m_steps; // oldest first; [0, m_next) can be undone
    std::size_t m_next = 0;
    std::size_t m_bytes = 0;
    std::size_t m_budget;
    std::size_t m_dropped = 0;
};

} // namespace core
