// SPDX-License-Identifier: GPL-3.0-or-later
// The script's stroke tools: set-brush's "stabilizer" object and the straight-line operations
// (line, line-to), for ScriptRunner (core/document/script.cpp).
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/paint/brush/dab.h"

namespace core {

class Document;

/**
 * Runs op if name is a straight-line operation ("line" with "from" and "to", "line-to" with
 * "to"; points [x, y] or [x, y, pressure]): its Status. Nothing for any other name. The caller
 * builds the layers first (needsLayers).
 */
std::optional<Status> runLineOperation(Document& doc, const std::string& name,
                                       const nlohmann::json& op);
/** Whether name is an operation runLineOperation() runs. */
bool isLineOperation(const std::string& name);

/**
 * Applies a set-brush operation's "stabilizer" to brush: false / true, or an object with any of
 * "on", "length" (pixels, 0 to 1000), "smoothing" (0 to 1) and "catch_up". An Error (brush
 * unchanged) for anything else.
 */
Status applyBrushStabilizer(Brush& brush, const nlohmann::json& stabilizer);

/** The "stabilizer" object of brush for a set-brush operation. */
nlohmann::json brushStabilizerJson(const Brush& brush);

} // namespace core
