// SPDX-License-Identifier: GPL-3.0-or-later
// Encoding an image to PNG, TIFF or EXR in memory, through OpenImageIO: the one place that does it
// (texture exports, OBJ textures, the images inside glTF files).
#pragma once

#include <cstdint>
#include <vector>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/io/export.h"
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

} // namespace core
