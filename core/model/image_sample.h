// SPDX-License-Identifier: GPL-3.0-or-later
// One channel of an image read at a uv: where a texture target's roughness and metallic start,
// and the alpha a MASK material is tested with.
#pragma once

#include <glm/vec2.hpp>

#include "core/model/mesh.h"

namespace core {

/**
 * Channel (0..3) of image at uv (glTF's uvs: (0, 0) the top-left corner), bilinear between texel
 * centres, repeating; the byte's value over 255, as stored (no sRGB decoding). 0 for a uv that is
 * not finite.
 */
float sampleChannel(const Image& image, glm::vec2 uv, int channel);

} // namespace core
