// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/brush/brush_preview.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace core {

std::vector<std::uint8_t> renderBrushPreview(const Brush& brush, int width, int height) {
    if (width <= 0 || height <= 0)
        return {};
    std::vector<float> cover(std::size_t(width) * std::size_t(height), 0.0f);
    const float w = float(width), h = float(height);
    // The brush's radius relative to the default 32 px, kept readable at this size.
    const float base = std::clamp(brush.radius / 32.0f, 0.25f, 1.0f) * 0.2f * h;
    const float margin = base * (1.0f + std::clamp(brush.jitter.scatter, 0.0f, 4.0f) * 0.5f);
    const auto path = [&](float t) {
        const float x = margin + t * (w - 2.0f * margin);
        const float y =
            0.5f * h - (0.5f * h - margin) * std::sin(2.0f * std::numbers::pi_v<float> * t);
        return glm::vec2(x, y);
    };

    SplitMix64 random{std::uint64_t(brush.seed) * 0x9E3779B97F4A7C15ull + 1};
    TipSampler sampler;
    const float spacing = std::max(0.02f, brush.spacing) * base;
    const int steps = 400;
    glm::vec2 last = path(0.0f);
    float travelled = spacing; // a dab at the start
    for (int i = 0; i <= steps; ++i) {
        const glm::vec2 p = path(float(i) / float(steps));
        travelled += glm::length(p - last);
        const glm::vec2 direction = p - last;
        last = p;
        if (travelled < spacing)
            continue;
        travelled = 0.0f;

        const BrushJitter& j = brush.jitter;
        float radius = base * (1.0f - std::clamp(j.size, 0.0f, 1.0f) * random.unit());
        const float opacity =
            brush.opacity * (1.0f - std::clamp(j.opacity, 0.0f, 1.0f) * random.unit());
        float angle = brush.angle;
        if (brush.angleMode == TipAngleMode::Stroke && glm::length(direction) > 0.0f)
            angle += std::atan2(direction.y, direction.x) * 180.0f / std::numbers::pi_v<float>;
        else if (brush.angleMode == TipAngleMode::Random)
            angle += 360.0f * random.unit();
        angle += j.angle * (2.0f * random.unit() - 1.0f);
        glm::vec2 center = p;
        if (j.scatter > 0.0f) {
            const float a = 2.0f * std::numbers::pi_v<float> * random.unit();
            center += glm::vec2(std::cos(a), std::sin(a)) * (j.scatter * base * random.unit());
        }
        radius = std::max(radius, 0.5f);
        sampler.setup(brush.tipImage(), brush.tipHardness(), radius,
                      angle * std::numbers::pi_v<float> / 180.0f);

        const int x0 = std::max(0, int(std::floor(center.x - radius)));
        const int x1 = std::min(width - 1, int(std::ceil(center.x + radius)));
        const int y0 = std::max(0, int(std::floor(center.y - radius)));
        const int y1 = std::min(height - 1, int(std::ceil(center.y + radius)));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 offset = glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - center;
                const float target = opacity * sampler.weight(offset, glm::length(offset));
                float& c = cover[std::size_t(y) * std::size_t(width) + std::size_t(x)];
                // Each dab adds flow towards its weight; the stroke never exceeds it.
                if (target > c)
                    c += (target - c) * std::clamp(brush.flow, 0.0f, 1.0f);
            }
    }
    std::vector<std::uint8_t> out(cover.size());
    for (std::size_t i = 0; i < cover.size(); ++i)
        out[i] = std::uint8_t(std::lround(std::clamp(cover[i], 0.0f, 1.0f) * 255.0f));
    return out;
}

} // namespace core
