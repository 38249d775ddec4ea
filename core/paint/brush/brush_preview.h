// SPDX-License-Identifier: GPL-3.0-or-later
// A brush's preview: a short S-shaped stroke painted with the brush's tip, spacing, flow, angle
// and jitter onto a small image (no mesh, no GL), for the presets panel.
#pragma once

#include <cstdint>
#include <vector>

#include "core/paint/brush/dab.h"

namespace core {

/**
 * The coverage (0 none .. 255 full) of an S-stroke across a width × height image, row-major, top
 * row first. The radius is scaled to the image (the brush's own relative to 32 px), so every
 * preset's shape shows; within the stroke dabs build up to the brush's opacity, as on a model.
 */
std::vector<std::uint8_t> renderBrushPreview(const Brush& brush, int width, int height);

} // namespace core
