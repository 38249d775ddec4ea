// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/dab.h"

#include <algorithm>
#include <cmath>

namespace core {

float Brush::falloff(float d, float r) const {
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

float PressureCurve::apply(float pressure) const {
    if (!std::isfinite(pressure))
        return 1.0f;
    const float p = std::clamp(pressure, 0.0f, 1.0f);
    const float g = std::isfinite(gamma) ? std::clamp(gamma, kMinGamma, kMaxGamma) : 1.0f;
    return g == 1.0f ? p : std::pow(p, g);
}

} // namespace core
