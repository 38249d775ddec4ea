// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/blend_modes.h"

#include <algorithm>
#include <cmath>

namespace core {

namespace {

float multiply(float b, float s) {
    return b * s;
}
float screen(float b, float s) {
    return b + s - b * s;
}
float hardLight(float b, float s) {
    return s <= 0.5f ? multiply(b, 2.0f * s) : screen(b, 2.0f * s - 1.0f);
}
float softLight(float b, float s) {
    if (s <= 0.5f)
        return b - (1.0f - 2.0f * s) * b * (1.0f - b);
    const float d = b <= 0.25f ? ((16.0f * b - 12.0f) * b + 4.0f) * b : std::sqrt(b);
    return b + (2.0f * s - 1.0f) * (d - b);
}

} // namespace

float blend(BlendMode mode, float below, float layer) {
    float r = layer;
    switch (mode) {
    case BlendMode::Normal:
        r = layer;
        break;
    case BlendMode::Multiply:
        r = multiply(below, layer);
        break;
    case BlendMode::Screen:
        r = screen(below, layer);
        break;
    case BlendMode::Overlay:
        r = hardLight(layer, below); // overlay is hard light with the operands swapped
        break;
    case BlendMode::SoftLight:
        r = softLight(below, layer);
        break;
    case BlendMode::Add:
        r = below + layer;
        break;
    case BlendMode::Subtract:
        r = below - layer;
        break;
    case BlendMode::Darken:
        r = std::min(below, layer);
        break;
    case BlendMode::Lighten:
        r = std::max(below, layer);
        break;
    case BlendMode::Difference:
        r = std::abs(below - layer);
        break;
    }
    return std::clamp(r, 0.0f, 1.0f);
}

std::string_view blendModeName(BlendMode mode) {
    switch (mode) {
    case BlendMode::Normal:
        return "normal";
    case BlendMode::Multiply:
        return "multiply";
    case BlendMode::Screen:
        return "screen";
    case BlendMode::Overlay:
        return "overlay";
    case BlendMode::SoftLight:
        return "soft-light";
    case BlendMode::Add:
        return "add";
    case BlendMode::Subtract:
        return "subtract";
    case BlendMode::Darken:
        return "darken";
    case BlendMode::Lighten:
        return "lighten";
    case BlendMode::Difference:
        return "difference";
    }
    return "normal";
}

std::optional<BlendMode> blendModeFromName(std::string_view name) {
    for (BlendMode mode : kBlendModes)
        if (blendModeName(mode) == name)
            return mode;
    return std::nullopt;
}

} // namespace core
