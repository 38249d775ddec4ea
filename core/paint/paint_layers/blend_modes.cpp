// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/paint_layers/blend_modes.h"

#include <algorithm>
#include <cmath>

namespace core {

float blend(BlendMode mode, float below, float layer) {
    switch (mode) {
    case BlendMode::Normal:
        return blendAs<BlendMode::Normal>(below, layer);
    case BlendMode::Multiply:
        return blendAs<BlendMode::Multiply>(below, layer);
    case BlendMode::Screen:
        return blendAs<BlendMode::Screen>(below, layer);
    case BlendMode::Overlay:
        return blendAs<BlendMode::Overlay>(below, layer);
    case BlendMode::SoftLight:
        return blendAs<BlendMode::SoftLight>(below, layer);
    case BlendMode::Add:
        return blendAs<BlendMode::Add>(below, layer);
    case BlendMode::Subtract:
        return blendAs<BlendMode::Subtract>(below, layer);
    case BlendMode::Darken:
        return blendAs<BlendMode::Darken>(below, layer);
    case BlendMode::Lighten:
        return blendAs<BlendMode::Lighten>(below, layer);
    case BlendMode::Difference:
        return blendAs<BlendMode::Difference>(below, layer);
    }
    return std::clamp(layer, 0.0f, 1.0f);
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
