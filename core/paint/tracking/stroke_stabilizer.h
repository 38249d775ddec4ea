// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <glm/vec2.hpp>

#include "core/paint/brush/dab.h"
#include "core/paint/tracking/stroke_tracker.h"

namespace core {

/**
 * The lazy-mouse ("string") stroke stabilizer, a filter on a stroke's input before the tracker.
 * The pointer pulls the brush tip on a string of Brush::stabilizerLength pixels: the tip stays
 * put while the pointer moves within the string's length and is dragged along the line to the
 * pointer when it moves further, so small jitter never reaches the stroke. With
 * Brush::stabilizerSmoothing the pointer itself is an exponential average of the input first
 * (weight of a new sample 1 - 0.95 × smoothing). Off (Brush::stabilizer false) it passes every
 * point through unchanged.
 */
class StrokeStabilizer {
public:
    /** Starts a stroke at point (the tip and the pointer both there); returns point. */
    StrokePoint begin(const StrokePoint& point, const Brush& brush);
    /**
     * The pointer moved to point: the tip's new position (with point's pressure), or nullopt when
     * the tip does not move (the stroke gets nothing).
     */
    std::optional<StrokePoint> move(const StrokePoint& point);
    /**
     * The stroke ends: with catch-up on (and the stabilizer on), the last raw input point, where
     * the stroke goes to close the string; otherwise nullopt (the stroke ends at the tip).
     * Ends the stroke.
     */
    std::optional<StrokePoint> release();

    bool active() const { return m_active; }
    /** Whether the stroke in progress is stabilized (its string is worth drawing). */
    bool stabilizing() const { return m_active && m_on; }
    /** The brush tip (where the stroke is) and the pointer (its end of the string), pixels. */
    glm::vec2 tip() const { return m_tip; }
    glm::vec2 pointer() const { return m_pointer; }
    float length() const { return m_length; }

private:
    bool m_active = false;
    bool m_on = false;
    bool m_catchUp = true;
    float m_length = 0.0f;
    float m_keep = 0.0f; // smoothing: the share of the old pointer position kept per sample
    glm::vec2 m_tip{0.0f}, m_pointer{0.0f};
    StrokePoint m_raw;
};

} // namespace core
