// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdint>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "core/document/history.h"
#include "tests/core/fake_tile_store.h"

namespace history_test {

using test::FakeStore;

core::HistoryStep step(core::TileUndoRecord record, core::StepKind kind = core::StepKind::Stroke) {
    core::HistoryStep s{kind, {}};
    s.parts.emplace_back(std::move(record));
    return s;
}

core::HistoryStep orderStep(std::uint64_t depthLayersSerial) {
    core::HistoryStep s{core::StepKind::PopUp, {}};
    s.parts.emplace_back(core::OrderChange{{{0, 1}, {0, 0}}, {{1, 0}, {0, 0}}, depthLayersSerial});
    return s;
}

/** What Document does with a step's paint parts. */
bool undo(core::History& history, FakeStore& store) {
    core::HistoryStep* s = history.nextUndo();
    if (!s)
        return false;
    for (auto it = s->parts.rbegin(); it != s->parts.rend(); ++it)
        if (auto* record = std::get_if<core::TileUndoRecord>(&*it)) {
            EXPECT_TRUE(record->undo(store));
        }
    history.undone();
    return true;
}

bool redo(core::History& history, FakeStore& store) {
    core::HistoryStep* s = history.nextRedo();
    if (!s)
        return false;
    for (auto& part : s->parts)
        if (auto* record = std::get_if<core::TileUndoRecord>(&part)) {
            EXPECT_TRUE(record->redo(store));
        }
    history.redone();
    return true;
}

TEST(History, UndoRedoAndANewStepForgetsTheRedoSteps) {
    FakeStore store({64, 64, 64});
    core::History history;
    const auto s0 = store.tiles;
    ASSERT_TRUE(history.push(step(store.paint({0}, 10))));
    const auto s1 = store.tiles;
    ASSERT_TRUE(history.push(step(store.paint({0, 1}, 20))));
    const auto s2 = store.tiles;
    EXPECT_EQ(history.undoCount(), 2u);

    ASSERT_TRUE(undo(history, store));
    EXPECT_EQ(store.tiles, s1);
    ASSERT_TRUE(undo(history, store));
    EXPECT_EQ(store.tiles, s0);
    EXPECT_FALSE(undo(history, store));
    EXPECT_EQ(history.redoCount(), 2u);

    ASSERT_TRUE(redo(history, store));
    EXPECT_EQ(store.tiles, s1);
    ASSERT_TRUE(history.push(step(store.paint({2}, 30))));
    EXPECT_FALSE(history.canRedo());
    const auto s3 = store.tiles;
    ASSERT_TRUE(undo(history, store));
    EXPECT_EQ(store.tiles, s1);
    ASSERT_TRUE(redo(history, store));
    EXPECT_EQ(store.tiles, s3);
    (void)s2;
}

TEST(History, EmptyRecordsAreIgnored) {
    core::History history;
    EXPECT_FALSE(history.push(core::HistoryStep{}));
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(history.bytes(), 0u);
}

TEST(History, TheBudgetDropsTheOldestStepsAndKeepsMemoryWithinIt) {
    FakeStore store({1000, 1000, 1000, 1000});
    core::HistoryStep probe = step(store.paint({0}, 1));
    const std::size_t stepBytes = probe.bytes();
    ASSERT_TRUE(std::get<core::TileUndoRecord>(probe.parts[0]).undo(store));
    const std::size_t budget = 3 * stepBytes + stepBytes / 2; // room for three steps
    core::History history(budget);

    std::vector<std::vector<std::vector<std::uint8_t>>> states{store.tiles};
    for (int i = 0; i < 10; ++i) {
        ASSERT_TRUE(history.push(step(store.paint({std::uint32_t(i % 4)}, std::uint8_t(10 * i)))));
        states.push_back(store.tiles);
        EXPECT_LE(history.bytes(), budget);
    }
    EXPECT_EQ(history.undoCount(), 3u);
    EXPECT_EQ(history.droppedCount(), 7u);
    // The newest three steps still undo exactly; older ones are gone.
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(undo(history, store));
        EXPECT_EQ(store.tiles, states[states.size() - 2 - std::size_t(i)]);
    }
    EXPECT_FALSE(history.canUndo());

    // Lowering the budget drops more: the oldest (here the redo side is all there is).
    history.setBudget(stepBytes + stepBytes / 2);
    EXPECT_LE(history.bytes(), history.budget());
    EXPECT_EQ(history.redoCount(), 1u);
    ASSERT_TRUE(redo(history, store));
    EXPECT_EQ(store.tiles, states[states.size() - 3]);
}

TEST(History, AStepBiggerThanTheBudgetClearsTheHistory) {
    // Older steps cannot stay: undoing them over the lost step would mix states.
    FakeStore store({100, 100});
    FakeStore big({5000});
    core::History history(1000);
    ASSERT_TRUE(history.push(step(store.paint({1}, 3))));
    EXPECT_FALSE(history.push(step(big.paint({0}, 4))));
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(history.bytes(), 0u);
    EXPECT_EQ(history.droppedCount(), 2u);
}

TEST(History, UndoingBackToTheSavedStateIsTheSavedStateAgain) {
    FakeStore store({64, 64});
    core::History history;
    EXPECT_TRUE(history.atSavedState()); // as loaded
    history.push(step(store.paint({0}, 1)));
    EXPECT_FALSE(history.atSavedState());
    history.markSaved();
    EXPECT_TRUE(history.atSavedState());
    history.push(step(store.paint({1}, 2)));
    EXPECT_FALSE(history.atSavedState());
    ASSERT_TRUE(undo(history, store));
    EXPECT_TRUE(history.atSavedState());
    ASSERT_TRUE(undo(history, store));
    EXPECT_FALSE(history.atSavedState());
    ASSERT_TRUE(redo(history, store));
    EXPECT_TRUE(history.atSavedState());
    // A new step from before the saved state makes it unreachable.
    ASSERT_TRUE(undo(history, store));
    history.push(step(store.paint({1}, 3)));
    EXPECT_FALSE(history.atSavedState());
    ASSERT_TRUE(undo(history, store));
    EXPECT_FALSE(history.atSavedState());
}

TEST(History, OrderStepsOfOtherLayersAreDroppedAndPaintStays) {
    FakeStore store({64});
    core::History history;
    history.push(step(store.paint({0}, 1)));
    history.push(orderStep(1));
    core::HistoryStep both = step(store.paint({0}, 2));
    both.parts.push_back(std::move(orderStep(1).parts.front()));
    history.push(std::move(both));
    history.push(orderStep(2));
    ASSERT_EQ(history.undoCount(), 4u);
    history.dropStaleOrders(2);
    EXPECT_EQ(history.undoCount(), 3u); // the order-only step of layers 1 is gone
    EXPECT_EQ(history.nextUndo()->kind, core::StepKind::PopUp);
    history.dropStaleOrders(3);
    ASSERT_EQ(history.undoCount(), 2u);
    EXPECT_EQ(history.nextUndo()->parts.size(), 1u); // the stroke keeps its paint
    EXPECT_TRUE(std::holds_alternative<core::TileUndoRecord>(history.nextUndo()->parts[0]));
}

TEST(History, SquashMakesTheStepsSinceAMarkOne) {
    FakeStore store({64, 64});
    core::History history;
    history.push(step(store.paint({0}, 1)));
    const auto s1 = store.tiles;
    const std::uint64_t mark = history.mark();
    EXPECT_FALSE(history.squash(mark, core::StepKind::Script)); // nothing done since
    history.push(step(store.paint({1}, 2)));
    history.push(step(store.paint({0}, 3)));
    history.push(step(store.paint({1}, 4)));
    ASSERT_TRUE(undo(history, store)); // a redo step: forgotten by the squash
    ASSERT_TRUE(history.squash(mark, core::StepKind::Script));
    ASSERT_EQ(history.undoCount(), 2u);
    EXPECT_FALSE(history.canRedo());
    EXPECT_EQ(history.undoKind(), core::StepKind::Script);
    ASSERT_TRUE(undo(history, store));
    EXPECT_EQ(store.tiles, s1); // parts undone last to first
    // A mark undone past, or dropped, cannot be squashed to.
    ASSERT_TRUE(undo(history, store));
    history.push(step(store.paint({0}, 5)));
    EXPECT_FALSE(history.squash(mark, core::StepKind::Script));
}

} // namespace history_test
