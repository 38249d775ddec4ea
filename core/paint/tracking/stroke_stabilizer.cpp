// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/tracking/stroke_stabilizer.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace core {

namespace {
constexpr float kMaxLength = 1000.0f;
// At full smoothing a sample still moves the pointer by this share, so it never stops.
constexpr float kMaxKeep = 0.95f;
} // namespace

StrokePoint StrokeStabilizer::begin(const StrokePoint& point, const Brush& brush) {
    m_active = true;
    m_on = brush.stabilizer;
    m_catchUp = brush.stabilizerCatchUp;
    // Settings from a file or a slider: NaN and out-of-range values become the nearest sane ones.
    m_length = std::isfinite(brush.stabilizerLength)
                   ? std::clamp(brush.stabilizerLength, 0.0f, kMaxLength)
                   : 0.0f;
    m_keep = std::isfinite(brush.stabilizerSmoothing)
                 ? kMaxKeep * std::clamp(brush.stabilizerSmoothing, 0.0f, 1.0f)
                 : 0.0f;
    m_tip = m_pointer = point.position;
    m_raw = point;
    return point;
}

std::optional<StrokePoint> StrokeStabilizer::move(const StrokePoint& point) {
    if (!m_active || !m_on)
        return point;
    if (!std::isfinite(point.position.x) || !std::isfinite(point.position.y))
        return std::nullopt;
    m_raw = point;
    m_pointer += (1.0f - m_keep) * (point.position - m_pointer);
    const glm::vec2 string = m_pointer - m_tip;
    const float distance = glm::length(string);
    if (distance <= m_length)
        return std::nullopt;
    m_tip += string * ((distance - m_length) / distance);
    return StrokePoint{m_tip, point.pressure};
}

std::optional<StrokePoint> StrokeStabilizer::release() {
    const bool catchUp = m_active && m_on && m_catchUp && m_raw.position != m_tip;
    m_active = false;
    if (!catchUp)
        return std::nullopt;
    m_tip = m_pointer = m_raw.position;
    return m_raw;
}

} // namespace core
