// SPDX-License-Identifier: GPL-3.0-or-later
// A loaded brush tip inside a project file: a PNG among the project's attached images, named by
// extras.layerpaint.brush.tip_image, so that reopening the project restores the brush.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/project/project_file_paint_layers.h"
#include "core/paint/brush/dab.h"

namespace core {

/**
 * Adds brush's loaded tip (if it uses one) to additions as a PNG attachment and records its
 * place in layerpaint (extras.layerpaint) as brush.tip_image. An Error if it cannot be encoded.
 */
Status addBrushTipImage(const Brush& brush, nlohmann::json& layerpaint, GlbAdditions& additions);

/**
 * Restores brush's loaded tip from the project at path (layerpaint: its extras.layerpaint),
 * decoded by loadImages (in the importer process). An Error (no path) saying what is wrong.
 */
Status readBrushTipImage(const std::string& path, const nlohmann::json& layerpaint,
                         const LoadLimits& limits, GlbImageLoader loadImages, Brush& brush);

/**
 * Loads an image file (PNG, TIFF, ... decoded in the importer process) as a brush tip. An
 * Error "FILE: problem" for a file that is no image or holds nothing to paint with.
 */
Result<std::shared_ptr<const TipImage>> loadTipImageFile(const std::string& path,
                                                         const LoadLimits& limits = {});

} // namespace core
