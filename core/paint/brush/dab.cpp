// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/brush/dab.h"

#include <algorithm>
#include <cmath>

namespace core {

float Brush::falloff(float d, float r) const {
    return roundFalloff(d, r, hardness);
}

void Brush::chooseTip(std::string_view name) {
    const TipCharacter character = tipCharacter(name);
    tip = std::string(name);
    spacing = character.spacing;
    angleMode = character.angleMode;
    jitter = character.jitter;
}

float Brush::tipHardness() const {
    if (tip == "round-soft")
        return 0.0f;
    if (tip == "round-hard")
        return 1.0f;
    return hardness;
}

const TipImage* Brush::tipImage() const {
    if (tip == kUserTip)
        return userTip.get();
    return builtinTipImage(tip);
}

float PressureCurve::apply(float pressure) const {
    if (!std::isfinite(pressure))
        return 1.0f;
    const float p = std::clamp(pressure, 0.0f, 1.0f);
    const float g = std::isfinite(gamma) ? std::clamp(gamma, kMinGamma, kMaxGamma) : 1.0f;
    return g == 1.0f ? p : std::pow(p, g);
}

} // namespace core
