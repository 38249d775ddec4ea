// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "core/paint/undo_tiles.h"

namespace {

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

TEST(TileUndoRecord, UndoAndRedoRestoreTheTilesExactly) {
    FakeStore store({16, 32, 7});
    const auto before = store.tiles;
    core::TileUndoRecord record = store.paint({0, 2}, 100);
    const auto after = store.tiles;
    ASSERT_NE(before, after);
    EXPECT_EQ(record.tileCount(), 2u);
    EXPECT_GE(record.bytes(), 16u + 7u);

    EXPECT_TRUE(record.undo(store));
    EXPECT_EQ(store.tiles, before);
    EXPECT_TRUE(record.isUndone());
    EXPECT_FALSE(record.undo(store)); // already undone: nothing happens
    EXPECT_EQ(store.tiles, before);

    EXPECT_TRUE(record.redo(store));
    EXPECT_EQ(store.tiles, after);
    EXPECT_FALSE(record.redo(store));
    EXPECT_TRUE(record.undo(store));
    EXPECT_EQ(store.tiles, before);
}

TEST(TileUndoRecord, AMismatchedStoreIsLeftUntouched) {
    FakeStore store({16, 32});
    core::TileUndoRecord record = store.paint({0, 1}, 50);
    FakeStore other({16, 8}); // tile 1 has another size
    const auto otherBefore = other.tiles;
    EXPECT_FALSE(record.undo(other));
    EXPECT_EQ(other.tiles, otherBefore);
    EXPECT_FALSE(record.isUndone());
}

TEST(UndoHistory, UndoRedoAndANewStepForgetsTheRedoSteps) {
    FakeStore store({64, 64, 64});
    core::UndoHistory history;
    const auto s0 = store.tiles;
    ASSERT_TRUE(history.push(store.paint({0}, 10)));
    const auto s1 = store.tiles;
    ASSERT_TRUE(history.push(store.paint({0, 1}, 20)));
    const auto s2 = store.tiles;
    EXPECT_EQ(history.undoCount(), 2u);

    ASSERT_NE(history.undo(store), nullptr);
    EXPECT_EQ(store.tiles, s1);
    ASSERT_NE(history.undo(store), nullptr);
    EXPECT_EQ(store.tiles, s0);
    EXPECT_EQ(history.undo(store), nullptr);
    EXPECT_EQ(history.redoCount(), 2u);

    ASSERT_NE(history.redo(store), nullptr);
    EXPECT_EQ(store.tiles, s1);
    ASSERT_TRUE(history.push(store.paint({2}, 30)));
    EXPECT_FALSE(history.canRedo());
    const auto s3 = store.tiles;
    ASSERT_NE(history.undo(store), nullptr);
    EXPECT_EQ(store.tiles, s1);
    ASSERT_NE(history.redo(store), nullptr);
    EXPECT_EQ(store.tiles, s3);
    (void)s2;
}

TEST(UndoHistory, EmptyRecordsAreIgnored) {
    core::UndoHistory history;
    EXPECT_FALSE(history.push(core::TileUndoRecord()));
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(history.bytes(), 0u);
}

TEST(UndoHistory, TheBudgetDropsTheOldestStepsAndKeepsMemoryWithinIt) {
    FakeStore store({1000, 1000, 1000, 1000});
    core::TileUndoRecord probe = store.paint({0}, 1);
    const std::size_t stepBytes = probe.bytes();
    ASSERT_TRUE(probe.undo(store));
    const std::size_t budget = 3 * stepBytes + stepBytes / 2; // room for three steps
    core::UndoHistory history(budget);

    std::vector<std::vector<std::vector<std::uint8_t>>> states{store.tiles};
    for (int i = 0; i < 10; ++i) {
        ASSERT_TRUE(history.push(store.paint({std::uint32_t(i % 4)}, std::uint8_t(10 * i))));
        states.push_back(store.tiles);
        EXPECT_LE(history.bytes(), budget);
    }
    EXPECT_EQ(history.undoCount(), 3u);
    EXPECT_EQ(history.droppedCount(), 7u);
    // The newest three steps still undo exactly; older ones are gone.
    for (int i = 0; i < 3; ++i) {
        ASSERT_NE(history.undo(store), nullptr);
        EXPECT_EQ(store.tiles, states[states.size() - 2 - std::size_t(i)]);
    }
    EXPECT_FALSE(history.canUndo());

    // Lowering the budget drops more: the oldest (here the redo side is all there is).
    history.setBudget(stepBytes + stepBytes / 2);
    EXPECT_LE(history.bytes(), history.budget());
    EXPECT_EQ(history.redoCount(), 1u);
    ASSERT_NE(history.redo(store), nullptr);
    EXPECT_EQ(store.tiles, states[states.size() - 3]);
}

TEST(UndoHistory, AStepBiggerThanTheBudgetClearsTheHistory) {
    // Older steps cannot stay: undoing them over the lost step would mix states.
    FakeStore store({100, 100});
    FakeStore big({5000});
    core::UndoHistory history(1000);
    ASSERT_TRUE(history.push(store.paint({1}, 3)));
    EXPECT_FALSE(history.push(big.paint({0}, 4)));
    EXPECT_FALSE(history.canUndo());
    EXPECT_EQ(history.bytes(), 0u);
    EXPECT_EQ(history.droppedCount(), 2u);
}

} // namespace
