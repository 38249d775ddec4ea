// SPDX-License-Identifier: GPL-3.0-or-later
// The lazy-mouse stroke stabilizer (core/paint/tracking/stroke_stabilizer.h) on its own: a jittered
// path comes out smooth, the tip trails by the string's length, release catches up or not, and off
// it passes every point through.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/paint/tracking/stroke_stabilizer.h"

namespace stroke_stabilizer_test {

using core::StrokePoint;
using core::StrokeStabilizer;

constexpr float kRadius = 200.0f; // of the smooth path, a circle about kCentre
const glm::vec2 kCentre(300.0f, 300.0f);

/** Deterministic jitter in [-1, 1] (a fixed linear congruential sequence). */
struct Jitter {
    std::uint32_t state = 12345u;
    float next() {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 23) - 1.0f;
    }
};

/** A hand's half circle: points every 2 px of arc, each pushed up to amplitude px off it. */
std::vector<glm::vec2> jitteredArc(float amplitude) {
    std::vector<glm::vec2> points;
    Jitter jitter;
    const int n = int(std::numbers::pi_v<float> * kRadius / 2.0f);
    for (int i = 0; i <= n; ++i) {
        const float a = std::numbers::pi_v<float> * float(i) / float(n);
        const glm::vec2 onPath = kCentre + kRadius * glm::vec2(std::cos(a), std::sin(a));
        points.push_back(onPath + amplitude * glm::vec2(jitter.next(), jitter.next()));
    }
    return points;
}

float offPath(glm::vec2 p) {
    return std::fabs(glm::length(p - kCentre) - kRadius);
}

/**
 * The largest turn (radians) between consecutive chords of a path resampled every step pixels:
 * how much it zigzags at that scale (sub-pixel moves alone would say nothing).
 */
float largestTurn(const std::vector<glm::vec2>& path, float step = 4.0f) {
    std::vector<glm::vec2> samples{path.front()};
    for (const glm::vec2 p : path)
        if (glm::distance(p, samples.back()) >= step)
            samples.push_back(p);
    float worst = 0.0f;
    for (std::size_t i = 2; i < samples.size(); ++i) {
        const glm::vec2 a = glm::normalize(samples[i - 1] - samples[i - 2]);
        const glm::vec2 b = glm::normalize(samples[i] - samples[i - 1]);
        worst = std::max(worst, std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f)));
    }
    return worst;
}

/** Root mean square of offPath over points from index first on. */
float rmsOffPath(const std::vector<glm::vec2>& path, std::size_t first = 0) {
    double sum = 0.0;
    for (std::size_t i = first; i < path.size(); ++i)
        sum += double(offPath(path[i])) * double(offPath(path[i]));
    return float(std::sqrt(sum / double(path.size() - first)));
}

core::Brush stabilized(float length, float smoothing = 0.0f, bool catchUp = true) {
    core::Brush brush;
    brush.stabilizer = true;
    brush.stabilizerLength = length;
    brush.stabilizerSmoothing = smoothing;
    brush.stabilizerCatchUp = catchUp;
    return brush;
}

/** The tip's path for input (the first point starts it; the release's catch-up last). */
std::vector<glm::vec2> run(StrokeStabilizer& s, const std::vector<glm::vec2>& input,
                           const core::Brush& brush, bool release = true) {
    std::vector<glm::vec2> out{s.begin({input.front(), 1.0f}, brush).position};
    for (std::size_t i = 1; i < input.size(); ++i)
        if (const auto tip = s.move({input[i], 1.0f}))
            out.push_back(tip->position);
    if (release)
        if (const auto rest = s.release())
            out.push_back(rest->position);
    return out;
}

TEST(StrokeStabilizer, AJitteredPathComesOutSmooth) {
    const std::vector<glm::vec2> input = jitteredArc(4.0f);
    ASSERT_GT(rmsOffPath(input), 2.0f) << "the input is really jittered";

    // The smooth path: what the string makes of the hand without jitter, a circle whose radius
    // is shorter by the string cutting inside (√(R² - length²) once the string is tight).
    StrokeStabilizer clean;
    const std::vector<glm::vec2> smooth = run(clean, jitteredArc(0.0f), stabilized(24.0f), false);
    const float smoothRadius = glm::distance(smooth.back(), kCentre);
    EXPECT_NEAR(smoothRadius, std::sqrt(kRadius * kRadius - 24.0f * 24.0f), 0.2f);
    const auto offSmooth = [&](glm::vec2 p) {
        return std::fabs(glm::distance(p, kCentre) - smoothRadius);
    };

    StrokeStabilizer s;
    const std::vector<glm::vec2> tips = run(s, input, stabilized(24.0f), false);
    ASSERT_GT(tips.size(), 50u);
    float worst = 0.0f;
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < tips.size(); ++i) {
        if (glm::distance(tips[i], tips.front()) < 48.0f)
            continue; // the string tightens first
        worst = std::max(worst, offSmooth(tips[i]));
        sum += double(offSmooth(tips[i])) * double(offSmooth(tips[i]));
        ++n;
    }
    ASSERT_GT(n, 40u);
    const float rms = float(std::sqrt(sum / double(n)));
    std::printf("[ stabilizer ] off the smooth path: raw rms %.2f px, stabilized worst %.2f rms "
                "%.2f px; largest turn raw %.2f, stabilized %.2f rad\n",
                rmsOffPath(input), worst, rms, largestTurn(input), largestTurn(tips));
    // The jitter (up to 4 px each way) is down to a third, within 2 px of the smooth path.
    EXPECT_LT(worst, 2.0f);
    EXPECT_LT(rms, 0.4f * rmsOffPath(input));
    // And it no longer zigzags: the raw path turns by tens of degrees every few pixels.
    EXPECT_GT(largestTurn(input), 0.8f);
    EXPECT_LT(largestTurn(tips), 0.3f);
}

TEST(StrokeStabilizer, SmoothingAveragesTheInputFirst) {
    const std::vector<glm::vec2> input = jitteredArc(4.0f);
    StrokeStabilizer plain, smoothed;
    const std::vector<glm::vec2> a = run(plain, input, stabilized(6.0f), false);
    const std::vector<glm::vec2> b = run(smoothed, input, stabilized(6.0f, 0.8f), false);
    EXPECT_LT(largestTurn(b), largestTurn(a));
}

TEST(StrokeStabilizer, TheTipTrailsByTheStringAndCatchesUpAtRelease) {
    const std::vector<glm::vec2> line{{0, 0}, {10, 0}, {20, 0}, {30, 0}, {100, 0}};
    StrokeStabilizer s;
    std::vector<glm::vec2> tips = run(s, line, stabilized(25.0f), false);
    // Within the string nothing moves; past it the tip is the length behind the pointer.
    EXPECT_EQ(tips.size(), 3u);
    EXPECT_NEAR(tips.back().x, 75.0f, 1e-4f);
    EXPECT_NEAR(glm::length(s.pointer() - s.tip()), 25.0f, 1e-4f);
    EXPECT_TRUE(s.stabilizing());
    const auto rest = s.release();
    ASSERT_TRUE(rest);
    EXPECT_EQ(rest->position, glm::vec2(100.0f, 0.0f)) << "no lag left after release";
    EXPECT_FALSE(s.active());

    StrokeStabilizer noCatchUp;
    tips = run(noCatchUp, line, stabilized(25.0f, 0.0f, false));
    EXPECT_NEAR(tips.back().x, 75.0f, 1e-4f) << "the stroke stops at the string's end";
}

TEST(StrokeStabilizer, OffItPassesEveryPointThrough) {
    const std::vector<glm::vec2> input = jitteredArc(4.0f);
    StrokeStabilizer s;
    core::Brush brush = stabilized(24.0f);
    brush.stabilizer = false;
    const std::vector<glm::vec2> out = run(s, input, brush);
    EXPECT_EQ(out, input);
}

TEST(StrokeStabilizer, NonsenseSettingsAndInputDoNotBreakIt) {
    core::Brush brush = stabilized(std::nanf(""), -3.0f);
    StrokeStabilizer s;
    s.begin({{5.0f, 5.0f}, 1.0f}, brush);
    EXPECT_EQ(s.length(), 0.0f);
    EXPECT_FALSE(s.move({{std::nanf(""), 1.0f}, 1.0f}));
    const auto tip = s.move({{9.0f, 5.0f}, 1.0f});
    ASSERT_TRUE(tip);
    EXPECT_EQ(tip->position, glm::vec2(9.0f, 5.0f));
}

} // namespace stroke_stabilizer_test
