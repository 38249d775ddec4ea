// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
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

/** The name scripts and project files use ("normal", "multiply", "soft-light", ...). */
std::string_view blendModeName(BlendMode mode);
/** The mode of a name blendModeName() gives; nothing for any other text. */
std::optional<BlendMode> blendModeFromName(std::string_view name);

} // namespace core
