// SPDX-License-Identifier: GPL-3.0-or-later
// The brush's symmetry as JSON: set-brush's "symmetry" object in scripts and sessions, and the
// same object in a project's state.
#pragma once

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/paint/brush/dab.h"

namespace core {

/**
 * Applies a "symmetry" object to brush: any of "mirror" ("", "x", "xy", "xyz", ...), "center"
 * ("bbox" or "origin"), "radial" (1 to 16 copies, the stroke included) and "axis" ("x", "y",
 * "z"); false turns it all off. An Error naming the setting (brush unchanged) for anything else.
 */
Status applyBrushSymmetry(Brush& brush, const nlohmann::json& symmetry);

/** The "symmetry" object of brush. */
nlohmann::json brushSymmetryJson(const Brush& brush);

} // namespace core
