// SPDX-License-Identifier: GPL-3.0-or-later
// DepthStack's row spans against a scan of every pixel.
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/depth/depth_stack.h"

namespace layer_stack_test {

/** A stack of the given size whose pixel p has counts[p] fragments (depths and ids unused). */
core::DepthStack stackWith(int width, int height, const std::vector<std::uint32_t>& counts) {
    core::DepthStack stack;
    stack.width = width;
    stack.height = height;
    stack.offsets.assign(counts.size() + 1, 0u);
    for (std::size_t p = 0; p < counts.size(); ++p)
        stack.offsets[p + 1] = stack.offsets[p] + counts[p];
    stack.depth.assign(stack.offsets.back(), 1.0f);
    stack.triangle.assign(stack.offsets.back(), 0u);
    return stack;
}

/** The span by looking at every pixel of the row. */
std::pair<int, int> scannedSpan(const core::DepthStack& stack, int y) {
    int first = -1, last = -1;
    for (int x = 0; x < stack.width; ++x)
        if (stack.layerCount(std::size_t(y) * std::size_t(stack.width) + std::size_t(x)) > 0) {
            if (first < 0)
                first = x;
            last = x;
        }
    return first < 0 ? std::pair{0, 0} : std::pair{first, last + 1};
}

TEST(DepthStack, RowSpanRunsFromTheFirstToTheLastPixelWithFragments) {
    // Rows: empty; first pixel only; last pixel only; a gap inside; full; one in the middle.
    const std::vector<std::uint32_t> counts = {
        0, 0, 0, 0, 0, //
        2, 0, 0, 0, 0, //
        0, 0, 0, 0, 1, //
        0, 3, 0, 0, 1, //
        1, 1, 2, 1, 1, //
        0, 0, 4, 0, 0, //
    };
    const core::DepthStack stack = stackWith(5, 6, counts);
    const std::vector<std::pair<int, int>> expected = {{0, 0}, {0, 1}, {4, 5},
                                                       {1, 5}, {0, 5}, {2, 3}};
    for (int y = 0; y < stack.height; ++y)
        EXPECT_EQ(stack.rowSpan(y), expected[std::size_t(y)]) << "row " << y;
}

TEST(DepthStack, RowSpanAgreesWithAScanOnSparseRows) {
    std::mt19937 random(17);
    for (const int width : {1, 2, 3, 64, 1281}) {
        const int height = 40;
        std::vector<std::uint32_t> counts(std::size_t(width) * std::size_t(height));
        for (int y = 0; y < height; ++y) {
            // From empty rows to full ones.
            const double fill = double(y % 10) / 9.0;
            for (int x = 0; x < width; ++x)
                counts[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
                    std::bernoulli_distribution(fill * fill * 0.5)(random) ? 1u + random() % 3u
                                                                           : 0u;
        }
        const core::DepthStack stack = stackWith(width, height, counts);
        for (int y = 0; y < height; ++y)
            EXPECT_EQ(stack.rowSpan(y), scannedSpan(stack, y)) << width << " wide, row " << y;
    }
}

} // namespace layer_stack_test
