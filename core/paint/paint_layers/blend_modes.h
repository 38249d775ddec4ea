// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

namespace core {

/**
 * How a paint layer combines with what lies under it. The formulas are those of the W3C
 * Compositing and Blending specification (separable modes) on values in 0..1, applied per
 * channel: base colour components as stored (sRGB-encoded, as painters expect a multiply or a
 * screen to look), roughness and metallic as they are.
 */
enum class BlendMode : std::uint8_t {
    Normal,
    Multiply,
    Screen,
    Overlay,
    SoftLight,
    Add,
    Subtract,
    Darken,
    Lighten,
    Difference,
};

inline constexpr std::array<BlendMode, 10> kBlendModes = {
    BlendMode::Normal,    BlendMode::Multiply,  BlendMode::Screen,   BlendMode::Overlay,
    BlendMode::SoftLight, BlendMode::Add,       BlendMode::Subtract, BlendMode::Darken,
    BlendMode::Lighten,   BlendMode::Difference};

/** B(below, layer): the mode's result where the layer fully covers, clamped to 0..1. */
float blend(BlendMode mode, float below, float layer);

/**
 * blend() for a mode known at compile time, so that a loop over many texels chooses the mode
 * once (blend() is this, chosen per call).
 */
template <BlendMode Mode> inline float blendAs(float below, float layer) {
    const auto screen = [](float b, float s) { return b + s - b * s; };
    float r = layer;
    if constexpr (Mode == BlendMode::Multiply) {
        r = below * layer;
    } else if constexpr (Mode == BlendMode::Screen) {
        r = screen(below, layer);
    } else if constexpr (Mode == BlendMode::Overlay) {
        // Overlay is hard light with the operands swapped.
        r = below <= 0.5f ? layer * (2.0f * below) : screen(layer, 2.0f * below - 1.0f);
    } else if constexpr (Mode == BlendMode::SoftLight) {
        if (layer <= 0.5f) {
            r = below - (1.0f - 2.0f * layer) * below * (1.0f - below);
        } else {
            const float d = below <= 0.25f ? ((16.0f * below - 12.0f) * below + 4.0f) * below
                                           : std::sqrt(below);
            r = below + (2.0f * layer - 1.0f) * (d - below);
        }
    } else if constexpr (Mode == BlendMode::Add) {
        r = below + layer;
    } else if constexpr (Mode == BlendMode::Subtract) {
        r = below - layer;
    } else if constexpr (Mode == BlendMode::Darken) {
        r = std::min(below, layer);
    } else if constexpr (Mode == BlendMode::Lighten) {
        r = std::max(below, layer);
    } else if constexpr (Mode == BlendMode::Difference) {
        r = std::abs(below - layer);
    }
    return std::clamp(r, 0.0f, 1.0f);
}

/** The name scripts and project files use ("normal", "multiply", "soft-light", ...). */
std::string_view blendModeName(BlendMode mode);
/** The mode of a name blendModeName() gives; nothing for any other text. */
std::optional<BlendMode> blendModeFromName(std::string_view name);

} // namespace core
