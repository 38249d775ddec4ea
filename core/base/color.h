// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstdint>

namespace core {

/**
 * sRGB transfer function tables: exact decoding of bytes and correctly rounded encoding of linear
 * values to bytes (the painting hot path encodes through these, so they are inline).
 */
struct SrgbTables {
    std::array<float, 256> decode{};
    // threshold[k]: the linear value from which code k + 1 is the nearest; +inf for k = 255.
    std::array<float, 256> threshold{};
    // coarse[i]: the code of linear i / kCoarse, a lower bound for any value in its cell.
    static constexpr int kCoarse = 4096;
    std::array<std::uint8_t, kCoarse + 1> coarse{};

    /** The tables (made once, thread-safe). */
    static const SrgbTables& get();

    /** Linear value to the nearest sRGB-encoded byte (clamped to 0..1, correctly rounded). */
    std::uint8_t encode(float x) const {
        if (!(x > 0.0f))
            return 0;
        if (x >= 1.0f)
            return 255;
        // The coarse table is at most a code or two short (the curve is steepest near 0).
        int code = coarse[std::size_t(x * float(kCoarse))];
        while (x >= threshold[std::size_t(code)])
            ++code;
        return std::uint8_t(code);
    }

private:
    SrgbTables();
};

/** sRGB-encoded byte to linear (exact table). */
inline float srgbToLinear(std::uint8_t value) {
    return SrgbTables::get().decode[value];
}
/** Linear value to the nearest sRGB-encoded byte (clamped to 0..1, correctly rounded). */
inline std::uint8_t linearToSrgb(float value) {
    return SrgbTables::get().encode(value);
}
/** sRGB-encoded value in 0..1 (clamped; NaN as 0) to linear, without rounding to bytes. */
float srgbToLinear(float encoded);
/** Linear value (clamped to 0..1; NaN as 0) to sRGB-encoded, without rounding to bytes. */
float encodeSrgb(float linear);
/**
 * srgbToLinear() and encodeSrgb() in double: a float taken through both comes back as the same
 * float (what a file that stores linear colours needs to give back sRGB values exactly).
 */
double decodeSrgb(double encoded);
double encodeSrgb(double linear);

} // namespace core
