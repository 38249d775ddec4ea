// SPDX-License-Identifier: GPL-3.0-or-later
// Encoding an image to PNG, TIFF, EXR or TGA in memory, through OpenImageIO: the one place that
// does it (texture exports, texture sets through presets, OBJ textures, the images inside glTF
// files).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/io/export.h"
#include "core/io/texture_sets/export_preset.h"
#include "core/model/mesh.h"

namespace core {

/**
 * image (sRGB RGBA8, rows top first, straight alpha) encoded as format (Png8, Png16, Tiff or
 * Exr; see exportTexture() for what each holds). Fully opaque images are written as RGB. Returns
 * the file's bytes, or an Error with the problem (no path; ErrorKind::Cancelled when progress
 * asked to stop).
 */
Result<std::vector<std::uint8_t>> encodeImage(const Image& image, ExportFormat format,
                                              const ProgressFn& progress = {});

/**
 * width × height pixels of components (1 grey, 2 grey and alpha, 3 RGB, 4 RGBA) values each,
 * interleaved, from 0 to 65535, rows top first, encoded as format at bitDepth (PNG and TIFF 8 or
 * 16, TGA 8, EXR 16 (half) or 32 (float)); alpha straight. colour[k] says component k holds
 * sRGB-encoded colour: decoded to linear for EXR, and a PNG whose first component is colour is
 * marked sRGB. The file's bytes, or an Error as encodeImage() gives it.
 */
Result<std::vector<std::uint8_t>> encodeValues(const std::uint16_t* values, int width, int height,
                                               int components, const std::array<bool, 4>& colour,
                                               MapFileFormat format, int bitDepth,
                                               const ProgressFn& progress = {});

} // namespace core
