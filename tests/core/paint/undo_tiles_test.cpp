// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "core/paint/paint_layers/undo_tiles.h"
#include "tests/core/fake_tile_store.h"

namespace undo_tiles_test {

using test::FakeStore;

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

} // namespace undo_tiles_test
