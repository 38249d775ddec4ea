// SPDX-License-Identifier: GPL-3.0-or-later
// The script operations on paint layers (layer-add, layer-select, layer-set, ...), whose handlers
// script_paint_layers.cpp lists for ScriptRunner (paintLayerOperations() in script_ops.h), and
// set-brush's "channels" object.
#pragma once

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/paint/brush/dab.h"

namespace core {

/**
 * Applies a set-brush operation's "channels" object to brush: the channels it names are painted
 * (with its values), the others not. An Error for anything else than such an object.
 */
Status applyBrushChannels(Brush& brush, const nlohmann::json& channels);

/** The "channels" object of brush for a set-brush operation (the base colour as true). */
nlohmann::json brushChannelsJson(const Brush& brush);

} // namespace core
