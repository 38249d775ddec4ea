// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <variant>
#include <vector>

#include "core/paint/paint_layers/undo_tiles.h"
#include "core/paint/targets/paint_target.h"
#include "core/regions/region_order.h"

namespace core {

/** What a step of the history did; the GUI names steps by kind ("Undo Paint Stroke"). */
enum class StepKind : std::uint8_t {
    Stroke,      // a paint stroke, with the pop-ups it caused
    Fill,        // a flood fill
    PopUp,       // an intentional pop-up (click, region graph)
    Hide,        // a paint-to-hide stroke
    Unhide,      // unhiding chosen regions, or all of them
    ResetOrder,  // back to the original region order
    PaintTarget, // the paint target replaced (another kind or resolution)
    Script,      // a script replayed as one step
    PaintLayers, // paint layers added, removed, reordered, changed, merged, or selected
};

/** A stable lower-case name of kind ("stroke", "pop-up", ...), e.g. for scripts and logs. */
const char* stepKindName(StepKind kind);

/** A change of the region order of one build of the layers (region ids belong to it). */
struct OrderChange {
    RegionOrderState before;
    RegionOrderState after;
    std::uint64_t depthLayersSerial = 0;

    std::size_t bytes() const;
};

/** The paint target replaced by another: holds the one that is not in use. */
struct TargetSwap {
    std::unique_ptr<PaintTarget> other;
    PaintTargetOptions otherOptions;

    std::size_t bytes() const;
};

/**
 * A change of the texture target's paint layers. Applying it swaps the state held here with the
 * target's, so the same call undoes and redoes it:
 * - Swap: the count layers at index are exchanged with held (add, delete, duplicate, merge down,
 *   flatten);
 * - Move: the layer at from moves to to (and from, to swap);
 * - Settings: the settings of the layer with id are exchanged with settings;
 * - Mask: the mask of the layer with id is exchanged with mask (nullptr: none);
 * and, always, the target's selection is exchanged with selection (selecting alone is no change:
 * it makes no undo step).
 */
struct PaintLayerChange {
    enum class Kind : std::uint8_t { Swap, Move, Settings, Mask };
    Kind kind = Kind::Swap;
    std::size_t index = 0, count = 0;
    std::vector<std::unique_ptr<PaintLayer>> held;
    std::size_t from = 0, to = 0;
    std::uint64_t id = 0;
    PaintLayerSettings settings;
    std::unique_ptr<TiledPlane> mask;
    PaintSelection selection;

    std::size_t bytes() const;
};

/** One part of a step: paint tiles, a region order change or a paint target swap. */
using StepPart = std::variant<TileUndoRecord, OrderChange, TargetSwap, PaintLayerChange>;

/** One undoable step: its parts are undone last to first and redone first to last. */
struct HistoryStep {
    StepKind kind = StepKind::Stroke;
    std::vector<StepPart> parts;

    bool empty() const { return parts.empty(); }
    std::size_t bytes() const;
};

/**
 * The document's one linear history of everything a user changes (paint, region order, paint
 * target), under a byte budget: when the steps exceed it, the oldest are dropped (they can no
 * longer be undone). It stores steps; Document applies them. Region order changes are only
 * meaningful for the layers they were made on: dropStaleOrders() forgets the others.
 */
class History {
public:
    static constexpr std::size_t kDefaultBudget = std::size_t(256) << 20; // 256 MiB

    explicit History(std::size_t budgetBytes = kDefaultBudget) : m_budget(budgetBytes) {}

    /**
     * Adds a finished step (already applied): forgets the redo steps, then drops the oldest steps
     * while over budget. Returns false for an
     * empty step (ignored) and for one bigger than the whole budget (then nothing can be undone
     * any more: the history is cleared, since undoing older steps over it would mix states).
     */
    bool push(HistoryStep step);

    /** The step the next undo() takes back, or nullptr. Document applies it, then calls undone().
     */
    HistoryStep* nextUndo();
    /** The step the next redo() applies again, or nullptr; Document then calls redone(). */
    HistoryStep* nextRedo();
    void undone();
    void redone();

    bool canUndo() const { return m_next > 0; }
    bool canRedo() const { return m_next < m_steps.size(); }
    std::optional<StepKind> undoKind() const;
    std::optional<StepKind> redoKind() const;
    /** Steps held (undoCount() + redoCount()) and the kind of step i, oldest first. */
    std::size_t size() const { return m_steps.size(); }
    StepKind kindAt(std::size_t i) const { return m_steps[i].step.kind; }
    std::size_t undoCount() const { return m_next; }
    std::size_t redoCount() const { return m_steps.size() - m_next; }
    /** Steps dropped so far to stay within the budget. */
    std::size_t droppedCount() const { return m_dropped; }

    /** Memory held by the steps, in bytes; never more than budget(). */
    std::size_t bytes() const { return m_bytes; }
    std::size_t budget() const { return m_budget; }
    /** Changes the budget, dropping the oldest steps (then the furthest redo steps) to fit. */
    void setBudget(std::size_t budgetBytes);
    /** Forgets every step (a new model); the state as it is now counts as the saved one. */
    void clear();

    /**
     * Forgets the region order changes made on other layers than depthLayersSerial (their region
     * ids are gone); steps left with nothing are removed. Call when the layers are replaced.
     */
    void dropStaleOrders(std::uint64_t depthLayersSerial);

    /** The current state, for squash(): steps done after it can become one. */
    std::uint64_t mark() const { return stateId(); }
    /**
     * Makes the steps done since mark one step of kind (e.g. a replayed script, whose own undo
     * and redo operations work step by step while it runs) and forgets the redo steps. False,
     * changing nothing, when the state of mark is no longer in the history (dropped, or undone
     * past) or nothing was done since.
     */
    bool squash(std::uint64_t mark, StepKind kind);

    /** Remembers the current state as the saved one (after a save or a load). */
    void markSaved();
    /** True while undo/redo has come back to the state of the last markSaved(). */
    bool atSavedState() const;
    /** undoCount() at the saved state, if undo/redo can reach it. */
    std::optional<std::size_t> savedIndex() const;

    /** Changes with every push, undo, redo and drop, so a view can tell it must refresh. */
    std::uint64_t revision() const { return m_revision; }

    /**
     * Calls listener after every change of the history: a step pushed, undone, redone, dropped
     * or squashed, the budget, the saved mark, clear(). It runs on the thread that made the
     * change, inside the Document operation that made it, and must not change the history.
     * Returns an id for unsubscribe().
     */
    std::uint64_t subscribe(std::function<void()> listener);
    void unsubscribe(std::uint64_t id);

private:
    struct Entry {
        HistoryStep step;
        std::size_t bytes = 0;
        std::uint64_t id = 0;
    };
    void enforceBudget();
    void dropFront();
    /** clear() without telling the listeners (push() clears as part of its own change). */
    void reset();
    void notify() const;
    std::uint64_t stateId() const;

    std::deque<Entry> m_steps; // oldest first; [0, m_next) can be undone
    std::size_t m_next = 0;
    std::size_t m_bytes = 0;
    std::size_t m_budget;
    std::size_t m_dropped = 0;
    std::vector<std::pair<std::uint64_t, std::function<void()>>> m_listeners;
    std::uint64_t m_nextListener = 1;
    std::uint64_t m_nextId = 1;
    std::uint64_t m_baseId = 0;  // the state before the oldest kept step
    std::uint64_t m_savedId = 0; // the saved state's id; none when it cannot be reached
    std::uint64_t m_revision = 0;
};

} // namespace core
