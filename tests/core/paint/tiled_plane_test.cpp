// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "core/paint/paint_layers/tiled_plane.h"
#include "core/paint/paint_layers/undo_tiles.h"

namespace tiled_plane_test {

using core::TiledPlane;

TEST(TiledPlane, UnwrittenTilesReadAsTheFillValueAndHoldNoMemory) {
    TiledPlane plane({{100, 70}, {64, 64}}, 2, {7, 9, 0, 0});
    EXPECT_EQ(plane.tileCount(0), 4u); // 2 × 2, the right and bottom ones narrower
    EXPECT_EQ(plane.tileCount(1), 1u);
    const core::TileRect edge = plane.tileRect(0, 3);
    EXPECT_EQ(edge.x, 64);
    EXPECT_EQ(edge.y, 64);
    EXPECT_EQ(edge.width, 36);
    EXPECT_EQ(edge.height, 6);
    EXPECT_EQ(plane.texel(0, 99, 69)[0], 7);
    EXPECT_EQ(plane.texel(0, 99, 69)[1], 9);
    EXPECT_EQ(plane.allocatedBytes(), 0u);

    plane.writableTexel(0, 99, 69)[0] = 42;
    EXPECT_EQ(plane.texel(0, 99, 69)[0], 42);
    EXPECT_EQ(plane.texel(0, 98, 69)[0], 7);
    EXPECT_EQ(plane.allocatedBytes(), 36u * 6u * 2u);
    EXPECT_EQ(plane.writtenTiles().size(), 1u);
    EXPECT_FALSE(plane.anyTile(1));
}

TEST(TiledPlane, UndoRestoresBytesAndGivesTheMemoryBack) {
    TiledPlane plane({{128, 128}}, 4, {0, 0, 0, 0});
    core::TileUndoRecord record;
    const core::TileKey key{0, plane.tileAt(0, 70, 10)};
    std::vector<std::uint8_t> before(plane.tileBytes(key));
    ASSERT_TRUE(plane.readTile(key, before));
    record.addTile(key, before);
    plane.writableTexel(0, 70, 10)[3] = 255;
    ASSERT_EQ(plane.allocatedTiles(), 1u);

    ASSERT_TRUE(record.undo(plane));
    EXPECT_EQ(plane.texel(0, 70, 10)[3], 0);
    EXPECT_EQ(plane.allocatedTiles(), 0u); // back to all fill value: no memory
    ASSERT_TRUE(record.redo(plane));
    EXPECT_EQ(plane.texel(0, 70, 10)[3], 255);
    EXPECT_EQ(plane.allocatedTiles(), 1u);

    std::vector<std::uint8_t> wrong(3);
    EXPECT_FALSE(plane.writeTile(key, wrong));
    EXPECT_EQ(plane.tileBytes({0, 99}), 0u);
}

} // namespace tiled_plane_test
