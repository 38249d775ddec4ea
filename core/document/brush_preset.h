// SPDX-License-Identifier: GPL-3.0-or-later
// Brush presets: a named brush kept as the keys of the set-brush script operation, so a preset,
// a script and a project describe a brush the same way. The starter set the app ships with.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/document/script_tips.h"
#include "core/paint/brush/dab.h"

namespace core {

/** A brush with a name (the colour is kept but choosing a preset leaves the artist's colour). */
struct BrushPreset {
    std::string name;
    Brush brush;

    friend bool operator==(const BrushPreset&, const BrushPreset&) = default;
};

/** The value of "format" in a preset file. */
inline constexpr const char* kBrushPresetFormat = "layerpaint-brush";
/** The longest name a preset keeps (in bytes). */
inline constexpr std::size_t kMaxPresetNameBytes = 200;

/**
 * The preset as JSON: {"format": "layerpaint-brush", "version": 1, "name": ..., "brush": {the
 * set-brush keys of every field}}. A loaded tip image is named by its file path.
 */
nlohmann::json brushPresetToJson(const BrushPreset& preset);
/**
 * The preset in value, its brush built by the set-brush operation's own code from the default
 * brush (keys it lacks keep their defaults); an image tip is loaded through load. An Error saying
 * what is wrong.
 */
Result<BrushPreset> brushPresetFromJson(const nlohmann::json& value, const TipLoader& load);
/**
 * The preset in a file's text (a .lpbrush file): an Error "FILE: problem" naming fileName.
 */
Result<BrushPreset> parseBrushPresetFile(const std::string& text, const std::string& fileName,
                                         const TipLoader& load);

/** The presets a first start offers: soft and hard brushes, textured tips, material brushes. */
std::vector<BrushPreset> starterBrushPresets();

} // namespace core
