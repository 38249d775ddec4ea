// SPDX-License-Identifier: GPL-3.0-or-later
// Brush tips (core/paint/brush/brush_tips.h): the built-in set, a turned tip's weights, the seeded
// jitter of a stroke's dabs, and what a textured tip paints on a texture.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/depth/depth_layers.h"
#include "core/model/mesh_topology.h"
#include "core/paint/brush/brush_tips.h"
#include "core/paint/targets/paint_target.h"
#include "core/paint/tracking/stroke_tracker.h"
#include "tests/core/captured_scenes.h"
#include "tests/core/test_scenes.h"

namespace brush_tips_test {

using core_test::addQuad;
using core_test::pixelView;
using core_test::Quad;

using Scene = core_test::PaintScene;

/** A 200 × 200 view filled by one textured quad. */
Scene quadScene() {
    core::Mesh mesh;
    addQuad(mesh, Quad{{0.0f, 0.0f}, {200.0f, 200.0f}, 5.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 4});
    return core_test::paintScene(std::move(mesh), pixelView(200, 200));
}

std::vector<core::Dab> strokeDabs(const Scene& scene, const core::Brush& brush) {
    core::StrokeTracker tracker;
    EXPECT_TRUE(tracker.setDepthLayers(scene.layers));
    std::vector<core::Dab> dabs;
    tracker.startStroke({{40.0f, 60.0f}, 1.0f}, brush, dabs);
    tracker.moveStroke({{160.0f, 80.0f}, 1.0f}, dabs);
    tracker.moveStroke({{120.0f, 150.0f}, 1.0f}, dabs);
    tracker.endStroke();
    return dabs;
}

/** The page bytes after painting brush's stroke on a fresh texture target. */
std::vector<std::uint8_t> paintedBytes(const Scene& scene, const core::Brush& brush) {
    core::PaintTargetOptions options;
    options.resolution = 256;
    auto target = core::TextureTarget::create(scene.mesh, scene.topology, options);
    EXPECT_TRUE(target.ok()) << target.error();
    (*target)->beginStroke(brush);
    for (const core::Dab& dab : strokeDabs(scene, brush))
        (*target)->paint(scene.layers, dab);
    (*target)->endStroke();
    return (*target)->page(0).rgba;
}

core::Brush jitteryBrush(std::uint32_t seed) {
    core::Brush brush;
    brush.radius = 14.0f;
    brush.tip = "spatter";
    brush.angleMode = core::TipAngleMode::Random;
    brush.jitter = {0.5f, 0.4f, 30.0f, 1.0f};
    brush.seed = seed;
    return brush;
}

TEST(BrushTips, TheBuiltInSetIsCompleteAndMadeOnce) {
    const auto names = core::builtinTipNames();
    ASSERT_GE(names.size(), 8u);
    for (const char* n :
         {"round-soft", "round-hard", "square", "spatter", "chalk", "bristle", "star", "noise"})
        EXPECT_TRUE(core::isBuiltinTip(n)) << n;
    EXPECT_FALSE(core::isBuiltinTip("no-such-tip"));
    EXPECT_EQ(core::builtinTipImage("round"), nullptr);
    std::set<std::vector<std::uint8_t>> distinct;
    for (const std::string_view n : names) {
        const core::TipImage* image = core::builtinTipImage(n);
        if (!image)
            continue;
        EXPECT_EQ(image, core::builtinTipImage(n));
        ASSERT_EQ(image->alpha.size(), std::size_t(image->width) * std::size_t(image->height));
        EXPECT_GT(*std::max_element(image->alpha.begin(), image->alpha.end()), 200) << n;
        EXPECT_EQ(image->alpha.front(), 0) << n; // the corners lie outside the dab's disc
        distinct.insert(image->alpha);
    }
    EXPECT_EQ(distinct.size(), names.size() - 3); // six textured tips, all different
}

TEST(BrushTips, ATurnedTipWeighsLikeTheTipImageTurned) {
    // At radius 64 one screen pixel is one texel of the 128² star, so a quarter turn of the
    // sampler must give the image turned a quarter (clockwise, y down): R[y][x] = I[127 - x][y].
    const core::TipImage& star = *core::builtinTipImage("star");
    ASSERT_EQ(star.width, 128);
    core::TipSampler turned, upright;
    turned.setup(&star, 0.5f, 64.0f, 0.5f * std::numbers::pi_v<float>);
    upright.setup(&star, 0.5f, 64.0f, 0.0f);
    int compared = 0, differentFromUpright = 0;
    for (int y = 0; y < 128; ++y) {
        for (int x = 0; x < 128; ++x) {
            const glm::vec2 o(float(x) + 0.5f - 64.0f, float(y) + 0.5f - 64.0f);
            const float d = glm::length(o);
            if (d >= 63.0f)
                continue;
            const float expected = star.alpha[std::size_t(127 - x) * 128 + std::size_t(y)] / 255.0f;
            ASSERT_NEAR(turned.weight(o, d), expected, 1e-3f) << x << "," << y;
            EXPECT_NEAR(upright.weight(o, d),
                        star.alpha[std::size_t(y) * 128 + std::size_t(x)] / 255.0f, 1e-5f);
            differentFromUpright += std::fabs(turned.weight(o, d) - upright.weight(o, d)) > 0.5f;
            ++compared;
        }
    }
    EXPECT_GT(compared, 12000);
    EXPECT_GT(differentFromUpright, 500); // a five-pointed star is not its own quarter turn
    // Outside the disc nothing is painted, whatever the image holds there.
    EXPECT_EQ(upright.weight({64.0f, 0.0f}, 64.0f), 0.0f);
}

TEST(BrushTips, RoundTipsAreTheRoundFalloff) {
    core::Brush brush;
    brush.hardness = 0.3f;
    core::TipSampler s;
    s.setup(brush.tipImage(), brush.tipHardness(), 20.0f, 1.0f);
    for (float d = 0.0f; d < 21.0f; d += 0.37f)
        EXPECT_EQ(s.weight({d, 0.0f}, d), brush.falloff(d, 20.0f));
    brush.tip = "round-hard";
    EXPECT_EQ(brush.tipHardness(), 1.0f);
    brush.tip = "round-soft";
    EXPECT_EQ(brush.tipHardness(), 0.0f);
}

TEST(BrushTips, ARoundHardTipPaintsTheSameBytesAsAHardRoundBrush) {
    const Scene scene = quadScene();
    core::Brush hard;
    hard.radius = 12.0f;
    hard.hardness = 1.0f;
    core::Brush tip = hard;
    tip.hardness = 0.2f;
    tip.tip = "round-hard";
    tip.angleMode = core::TipAngleMode::Random; // turning a round tip changes nothing
    EXPECT_EQ(paintedBytes(scene, hard), paintedBytes(scene, tip));
}

TEST(BrushTips, JitterReplaysExactlyFromTheSeed) {
    const Scene scene = quadScene();
    const auto a = strokeDabs(scene, jitteryBrush(7));
    const auto b = strokeDabs(scene, jitteryBrush(7));
    const auto c = strokeDabs(scene, jitteryBrush(8));
    ASSERT_GT(a.size(), 20u);
    ASSERT_EQ(a.size(), b.size());
    std::set<float> radii, angles;
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].center, b[i].center);
        EXPECT_EQ(a[i].radius, b[i].radius);
        EXPECT_EQ(a[i].opacity, b[i].opacity);
        EXPECT_EQ(a[i].angle, b[i].angle);
        EXPECT_EQ(a[i].paintable.size(), b[i].paintable.size());
        EXPECT_LE(a[i].radius, 14.0f);
        EXPECT_GE(a[i].radius, 7.0f);
        radii.insert(a[i].radius);
        angles.insert(a[i].angle);
    }
    EXPECT_GT(radii.size(), a.size() / 2);
    EXPECT_GT(angles.size(), a.size() / 2);
    bool differs = a.size() != c.size();
    for (std::size_t i = 0; !differs && i < a.size(); ++i)
        differs = a[i].center != c[i].center || a[i].radius != c[i].radius;
    EXPECT_TRUE(differs);

    // The same bytes on the texture from the same seed, others from another.
    const auto bytes7 = paintedBytes(scene, jitteryBrush(7));
    EXPECT_EQ(bytes7, paintedBytes(scene, jitteryBrush(7)));
    EXPECT_NE(bytes7, paintedBytes(scene, jitteryBrush(8)));
}

TEST(BrushTips, SpacingFollowsTheJitteredSize) {
    // Without scatter each dab is spacing × the previous dab's (jittered) radius further along.
    const Scene scene = quadScene();
    core::Brush brush;
    brush.radius = 20.0f;
    brush.spacing = 0.5f;
    brush.jitter.size = 0.6f;
    brush.seed = 3;
    core::StrokeTracker tracker;
    ASSERT_TRUE(tracker.setDepthLayers(scene.layers));
    std::vector<core::Dab> dabs;
    tracker.startStroke({{20.0f, 100.0f}, 1.0f}, brush, dabs);
    tracker.moveStroke({{180.0f, 100.0f}, 1.0f}, dabs);
    ASSERT_GT(dabs.size(), 10u);
    for (std::size_t i = 1; i < dabs.size(); ++i)
        EXPECT_NEAR(dabs[i].center.x - dabs[i - 1].center.x, 0.5f * dabs[i - 1].radius, 1e-3f);
}

TEST(BrushTips, FollowingTheStrokeTurnsTheTipAlongThePath) {
    const Scene scene = quadScene();
    core::Brush brush;
    brush.tip = "bristle";
    brush.angleMode = core::TipAngleMode::Stroke;
    brush.angle = 90.0f;
    core::StrokeTracker tracker;
    ASSERT_TRUE(tracker.setDepthLayers(scene.layers));
    std::vector<core::Dab> dabs;
    tracker.startStroke({{100.0f, 20.0f}, 1.0f}, brush, dabs);
    tracker.moveStroke({{100.0f, 180.0f}, 1.0f}, dabs); // straight down: +90°
    ASSERT_GT(dabs.size(), 2u);
    EXPECT_NEAR(dabs.back().angle, std::numbers::pi_v<float>, 1e-5f);
}

TEST(BrushTips, ScatteredDabsStayOnTheSurface) {
    const Scene scene = quadScene();
    const auto dabs = strokeDabs(scene, jitteryBrush(11));
    int off = 0;
    for (const core::Dab& dab : dabs) {
        EXPECT_EQ(dab.layer, 1u);
        EXPECT_FALSE(dab.paintable.empty());
        off += dab.center.x != std::round(dab.center.x);
    }
    EXPECT_GT(off, 0);
}

TEST(BrushTips, UserImagesBecomeAlphaTips) {
    // Black opaque paints fully, white or transparent not at all; big images are scaled down.
    std::vector<std::uint8_t> rgba(1000 * 600 * 4, 255);
    for (int y = 0; y < 600; ++y)
        for (int x = 0; x < 500; ++x)
            std::fill_n(&rgba[(std::size_t(y) * 1000 + std::size_t(x)) * 4], 3, std::uint8_t(0));
    const core::TipImage tip = core::tipFromRgba(1000, 600, rgba);
    EXPECT_LE(std::max(tip.width, tip.height), core::kMaxTipSide);
    EXPECT_EQ(tip.width, 250);
    EXPECT_EQ(tip.height, 150);
    EXPECT_EQ(tip.alpha[0], 255);
    EXPECT_EQ(tip.alpha[249], 0);
    EXPECT_TRUE(core::tipFromRgba(0, 0, {}).alpha.empty());
}

} // namespace brush_tips_test
