// SPDX-License-Identifier: GPL-3.0-or-later
// The script operations on paint layers (layer-add, layer-select, layer-set, ...), for
// ScriptRunner (core/document/script.cpp).
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/paint/brush/dab.h"

namespace core {

class Document;

/**
 * Runs op if name is a paint-layer operation: its Status (an Error saying what is wrong with
 * op). Nothing for any other name.
 */
std::optional<Status> runPaintLayerOperation(Document& doc, const std::string& name,
                                             const nlohmann::json& op);

/**
 * Applies a set-brush operation's "channels" object to brush: the channels it names are painted
 * (with its values), the others not. An Error for anything else than such an object.
 */
Status applyBrushChannels(Brush& brush, const nlohmann::json& channels);

/** The "channels" object of brush for a set-brush operation (the base colour as true). */
nlohmann::json brushChannelsJson(const Brush& brush);

} // namespace core
