// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/base/color.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace core {

double decodeSrgb(double encoded) {
    const double c = std::clamp(std::isfinite(encoded) ? encoded : 0.0, 0.0, 1.0);
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double encodeSrgb(double linear) {
    const double c = std::clamp(std::isfinite(linear) ? linear : 0.0, 0.0, 1.0);
    return c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

SrgbTables::SrgbTables() {
    for (int k = 0; k < 256; ++k) {
        decode[std::size_t(k)] = float(decodeSrgb(k / 255.0));
        threshold[std::size_t(k)] =
            k < 255 ? float(decodeSrgb((k + 0.5) / 255.0)) : std::numeric_limits<float>::infinity();
    }
    int code = 0;
    for (int i = 0; i <= kCoarse; ++i) {
        const float x = float(i) / float(kCoarse);
        while (x >= threshold[std::size_t(code)])
            ++code;
        coarse[std::size_t(i)] = std::uint8_t(code);
    }
}

const SrgbTables& SrgbTables::get() {
    static const SrgbTables tables;
    return tables;
}

float srgbToLinear(float encoded) {
    const float c = std::clamp(std::isfinite(encoded) ? encoded : 0.0f, 0.0f, 1.0f);
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float encodeSrgb(float linear) {
    const float c = std::clamp(std::isfinite(linear) ? linear : 0.0f, 0.0f, 1.0f);
    return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

} // namespace core
