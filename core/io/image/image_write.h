// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <string>

#include "core/base/result.h"

namespace core {

enum class PixelType { UInt8, UInt16, UInt32, Float32 };

/**
 * Writes a width × height image with `channels` interleaved channels, rows top first, through
 * OpenImageIO (the image codecs module, image_codecs.h); the format follows the file extension
 * (.png, .tif, .exr, ...). Returns an Error naming the file if the format cannot hold the pixel
 * type or the write fails.
 */
Status writeImage(const std::string& path, int width, int height, int channels, PixelType type,
                  const void* pixels);

} // namespace core
