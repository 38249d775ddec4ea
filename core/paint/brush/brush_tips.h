// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

namespace core {

/**
 * A brush tip's grayscale alpha (0 none .. 255 full weight), row-major, top row first. The image
 * spans the dab's square [-R, R]² (R the dab radius); what lies outside the dab's disc is cut.
 */
struct TipImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> alpha;

    friend bool operator==(const TipImage&, const TipImage&) = default;
};

/** The largest side a user tip keeps; larger images are scaled down to it (box filter). */
inline constexpr int kMaxTipSide = 256;

/** How a dab's tip is turned. */
enum class TipAngleMode : std::uint8_t {
    Fixed,  // Brush::angle
    Stroke, // the stroke's direction plus Brush::angle
    Random, // a random turn per dab (from the stroke's seed)
};
const char* tipAngleModeName(TipAngleMode mode);
/** The mode named name ("fixed", "stroke", "random"); false if there is none. */
bool tipAngleModeFromName(std::string_view name, TipAngleMode& mode);

/** Random variation per dab, drawn from the stroke's seed. Zero everywhere: none. */
struct BrushJitter {
    float size = 0.0f;    // 0..1: a dab's radius is scaled by 1 - size × u
    float opacity = 0.0f; // 0..1: its opacity by 1 - opacity × u
    float angle = 0.0f;   // 0..180 degrees either way
    float scatter = 0.0f; // 0..4 radii: the centre moves up to this far from the path

    bool any() const { return size > 0.0f || opacity > 0.0f || angle > 0.0f || scatter > 0.0f; }
    friend bool operator==(const BrushJitter&, const BrushJitter&) = default;
};

/** The name of the classic round tip (Brush::falloff with the brush's hardness). */
inline constexpr std::string_view kRoundTip = "round";
/** The tip name that means the brush's loaded image (Brush::userTip). */
inline constexpr std::string_view kUserTip = "user";
/** The built-in tips in display order: the round ones first, then the textured ones. */
std::span<const std::string_view> builtinTipNames();
bool isBuiltinTip(std::string_view name);
/** How a built-in tip is laid along a stroke so that it looks like itself. */
struct TipCharacter {
    float spacing = 0.15f; // as Brush::spacing
    TipAngleMode angleMode = TipAngleMode::Fixed;
    BrushJitter jitter;
};
/**
 * The spacing, turn and jitter of built-in tip name, which choosing it in the Brush panel sets:
 * textured tips need their dabs apart and varied, or they paint a solid, streaky line. The
 * round tips' (and an unknown name's) are the brush's defaults.
 */
TipCharacter tipCharacter(std::string_view name);

/**
 * The procedurally made image of a built-in textured tip (deterministic, the same on every
 * machine); nullptr for the round tips and unknown names.
 */
const TipImage* builtinTipImage(std::string_view name);

/**
 * Converts an RGBA8 image (straight alpha) to a tip: luminance (dark paints; white is empty)
 * times alpha, scaled down to kMaxTipSide. Empty if the image is empty.
 */
TipImage tipFromRgba(int width, int height, std::span<const std::uint8_t> rgba);

/**
 * The round dab's weight in [0, 1] at distance d from the centre of a dab of radius r. Inline: a
 * dab calls it per texel.
 */
inline float roundFalloff(float d, float r, float hardness) {
    if (!(r > 0.0f) || d >= r)
        return 0.0f;
    const float t = d / r;
    const float h = std::clamp(hardness, 0.0f, 1.0f);
    if (t <= h)
        return 1.0f;
    // Smooth from full weight at the hard core to nothing at the rim.
    const float s = (t - h) / (1.0f - h);
    return 1.0f - s * s * (3.0f - 2.0f * s);
}

/**
 * A fixed-algorithm PRNG (SplitMix64): the same numbers on every platform and library, so a
 * stroke's jitter replays exactly from its seed.
 */
struct SplitMix64 {
    std::uint64_t state = 0;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /** Uniform in [0, 1), 24 bits. */
    float unit() { return float(next() >> 40) * (1.0f / 16777216.0f); }
};

/**
 * The weight of one dab's tip at a screen offset: the round falloff, or the tip image turned by
 * the dab's angle and scaled to its radius, sampled bilinearly.
 */
class TipSampler {
public:
    /** image nullptr: the round falloff with hardness. angle in radians, clockwise on screen. */
    void setup(const TipImage* image, float hardness, float radius, float angle);
    bool textured() const { return m_image != nullptr; }
    /** The round falloff's parameters (those weight() uses without an image). */
    float radius() const { return m_radius; }
    float hardness() const { return m_hardness; }

    /** Weight at offset (pixels from the dab centre, y down), distance = |offset|. */
    float weight(glm::vec2 offset, float distance) const {
        if (!m_image)
            return roundFalloff(distance, m_radius, m_hardness);
        if (!(distance < m_radius))
            return 0.0f;
        // Into the tip's frame (turned back by the angle), then texel coordinates.
        const float u = (m_cos * offset.x + m_sin * offset.y) * m_scaleX + m_halfW;
        const float v = (-m_sin * offset.x + m_cos * offset.y) * m_scaleY + m_halfH;
        return sample(u - 0.5f, v - 0.5f);
    }

private:
    float sample(float x, float y) const;

    const TipImage* m_image = nullptr;
    float m_hardness = 0.5f, m_radius = 0.0f;
    float m_cos = 1.0f, m_sin = 0.0f;
    float m_scaleX = 0.0f, m_scaleY = 0.0f, m_halfW = 0.0f, m_halfH = 0.0f;
};

} // namespace core
