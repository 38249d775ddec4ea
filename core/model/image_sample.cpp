// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/image_sample.h"

#include <cmath>
#include <cstddef>

namespace core {

float sampleChannel(const Image& image, glm::vec2 uv, int channel) {
    const double x = double(uv.x) * image.width - 0.5, y = double(uv.y) * image.height - 0.5;
    if (!std::isfinite(x) || !std::isfinite(y))
        return 0.0f;
    const double fx = std::floor(x), fy = std::floor(y);
    const float ax = float(x - fx), ay = float(y - fy);
    const auto wrap = [](double i, int size) {
        const double m = std::fmod(i, double(size));
        return std::size_t(m < 0 ? m + size : m);
    };
    const std::size_t x0 = wrap(fx, image.width), x1 = wrap(fx + 1, image.width);
    const std::size_t y0 = wrap(fy, image.height), y1 = wrap(fy + 1, image.height);
    const auto at = [&](std::size_t tx, std::size_t ty) {
        return float(image.rgba[(ty * std::size_t(image.width) + tx) * 4 + std::size_t(channel)]);
    };
    const float top = at(x0, y0) * (1.0f - ax) + at(x1, y0) * ax;
    const float bottom = at(x0, y1) * (1.0f - ax) + at(x1, y1) * ax;
    return (top * (1.0f - ay) + bottom * ay) / 255.0f;
}

} // namespace core
