// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "core/paint/paint_layers/blend_modes.h"

namespace blend_modes_test {

using core::blend;
using core::BlendMode;

// Known values, worked out by hand from the W3C separable blend formulas.
TEST(BlendModes, KnownValuesOfEveryMode) {
    EXPECT_FLOAT_EQ(blend(BlendMode::Normal, 0.3f, 0.8f), 0.8f);
    EXPECT_FLOAT_EQ(blend(BlendMode::Multiply, 0.5f, 0.4f), 0.2f);
    EXPECT_FLOAT_EQ(blend(BlendMode::Screen, 0.5f, 0.4f), 0.7f);
    EXPECT_FLOAT_EQ(blend(BlendMode::Overlay, 0.25f, 0.6f), 0.3f); // 2·below·layer
    EXPECT_FLOAT_EQ(blend(BlendMode::Overlay, 0.75f, 0.6f), 0.8f); // 1 - 2(1-b)(1-s)
    EXPECT_FLOAT_EQ(blend(BlendMode::SoftLight, 0.5f, 0.25f), 0.375f);
    EXPECT_NEAR(blend(BlendMode::SoftLight, 0.16f, 0.75f), 0.279168f, 1e-6f);
    EXPECT_NEAR(blend(BlendMode::SoftLight, 0.64f, 0.75f), 0.72f, 1e-6f);
    EXPECT_FLOAT_EQ(blend(BlendMode::Add, 0.2f, 0.5f), 0.7f);
    EXPECT_FLOAT_EQ(blend(BlendMode::Add, 0.7f, 0.5f), 1.0f); // clamped
    EXPECT_FLOAT_EQ(blend(BlendMode::Subtract, 0.7f, 0.5f), 0.2f);
    EXPECT_FLOAT_EQ(blend(BlendMode::Subtract, 0.3f, 0.5f), 0.0f); // clamped
    EXPECT_FLOAT_EQ(blend(BlendMode::Darken, 0.3f, 0.5f), 0.3f);
    EXPECT_FLOAT_EQ(blend(BlendMode::Lighten, 0.3f, 0.5f), 0.5f);
    EXPECT_FLOAT_EQ(blend(BlendMode::Difference, 0.2f, 0.7f), 0.5f);
}

TEST(BlendModes, NeutralLayerValuesLeaveTheBelowAlone) {
    for (float b : {0.0f, 0.1f, 0.5f, 0.9f, 1.0f}) {
        EXPECT_FLOAT_EQ(blend(BlendMode::Multiply, b, 1.0f), b);
        EXPECT_FLOAT_EQ(blend(BlendMode::Screen, b, 0.0f), b);
        EXPECT_FLOAT_EQ(blend(BlendMode::Add, b, 0.0f), b);
        EXPECT_FLOAT_EQ(blend(BlendMode::Subtract, b, 0.0f), b);
        EXPECT_FLOAT_EQ(blend(BlendMode::SoftLight, b, 0.5f), b);
        EXPECT_FLOAT_EQ(blend(BlendMode::Difference, b, 0.0f), b);
    }
}

TEST(BlendModes, NamesRoundTripAndUnknownNamesAreRefused) {
    for (BlendMode mode : core::kBlendModes)
        EXPECT_EQ(core::blendModeFromName(core::blendModeName(mode)), mode);
    EXPECT_EQ(core::blendModeFromName("soft-light"), BlendMode::SoftLight);
    EXPECT_FALSE(core::blendModeFromName("Multiply").has_value());
    EXPECT_FALSE(core::blendModeFromName("").has_value());
}

} // namespace blend_modes_test
