// SPDX-License-Identifier: GPL-3.0-or-later
// The brush tip keys of the set-brush script operation (tip, angle, angle_mode, jitter, seed),
// for ScriptRunner (core/document/script.cpp) and the session log.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/paint/brush/dab.h"

namespace core {

/** Decodes an image file into a tip (the host's importer process); an Error naming the file. */
using TipLoader = std::function<Result<std::shared_ptr<const TipImage>>(const std::string& path)>;

/**
 * Applies op's tip keys to brush: "tip" (a built-in name or an image file, loaded through load),
 * "angle" (degrees), "angle_mode" (fixed, stroke, random), "jitter" {size, opacity, angle,
 * scatter} and "seed". An Error saying what is wrong; brush is unchanged then.
 */
Status applyBrushTip(Brush& brush, const nlohmann::json& op, const TipLoader& load);

/** Adds brush's tip keys to a set-brush operation (a loaded tip as its file path). */
void addBrushTipJson(const Brush& brush, nlohmann::json& op);

} // namespace core
