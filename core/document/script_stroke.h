// SPDX-License-Identifier: GPL-3.0-or-later
// The script's stroke tools: set-brush's "stabilizer" object, and the straight-line operations
// (line with "from" and "to", line-to with "to"; points [x, y] or [x, y, pressure]), whose
// handlers script_stroke.cpp lists for ScriptRunner (lineOperations() in script_ops.h).
#pragma once

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/paint/brush/dab.h"

namespace core {

/**
 * Applies a set-brush operation's "stabilizer" to brush: false / true, or an object with any of
 * "on", "length" (pixels, 0 to 1000), "smoothing" (0 to 1) and "catch_up". An Error (brush
 * unchanged) for anything else.
 */
Status applyBrushStabilizer(Brush& brush, const nlohmann::json& stabilizer);

/** The "stabilizer" object of brush for a set-brush operation. */
nlohmann::json brushStabilizerJson(const Brush& brush);

} // namespace core
