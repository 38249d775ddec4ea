// SPDX-License-Identifier: GPL-3.0-or-later
// Texture export presets: which image files a texture set becomes, and what each of their
// components holds (the packed maps that game engines and other tools expect).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/result.h"

namespace core {

/** What a texture set offers a preset, per texel. */
enum class SetChannel {
    BaseColor, // RGB, sRGB-encoded
    Opacity,   // the base colour's alpha
    Roughness,
    Metallic,
    Normal,    // RGB, tangent space, OpenGL convention (+Y up) before the preset's own
    Occlusion, // ambient occlusion with the material's strength applied
    Emissive,  // RGB, sRGB-encoded: emissive factor × map
};

/** How many components channel has (3 for the colours and the normal, else 1). */
int channelComponents(SetChannel channel);
/** Whether the channel's values are sRGB-encoded colour (decoded when a format holds linear). */
bool isColorChannel(SetChannel channel);
/** The channel's name in preset files ("baseColor", "roughness", ...). */
const char* channelName(SetChannel channel);

/** One component of a written map: a channel's component (or 1 − it), or a constant. */
struct MapComponent {
    std::optional<SetChannel> channel; // none: constant
    int component = 0;                 // of the channel, 0 .. channelComponents() − 1
    bool inverted = false;             // 1 − the value (smoothness = 1 − roughness)
    float constant = 0.0f;             // 0 .. 1

    bool operator==(const MapComponent&) const = default;
};

/** One image file a preset writes per texture set. */
struct PresetMap {
    std::string name; // $channel in the file-name template ("BaseColor", "ORM", ...)
    /** 1 (grey), 2 (grey and alpha), 3 (RGB) or 4 (RGBA) components. */
    std::vector<MapComponent> components;

    bool operator==(const PresetMap&) const = default;
};

enum class NormalConvention { OpenGl, DirectX }; // DirectX: green (Y) flipped
enum class MapFileFormat { Png, Tiff, Exr, Tga };

constexpr int kPadToFill = -1; // padding that fills every texel outside the charts
constexpr int kMaxPadding = 1024;

/**
 * A texture export preset. fileName is a template: $mesh (the model's file name without its
 * extension), $textureSet (the set's name: its first material's) and $channel (the map's name)
 * are replaced, each reduced to letters, digits, '-' and '_'; the format's extension is added.
 */
struct ExportPreset {
    std::string id;   // "gltf", "unreal", ... for the built-in ones, empty for a file's
    std::string name; // as shown
    std::string fileName = "$mesh_$textureSet_$channel";
    NormalConvention normal = NormalConvention::OpenGl;
    MapFileFormat format = MapFileFormat::Png;
    int bitDepth = 8;         // PNG and TIFF 8 or 16, TGA 8, EXR 16 (half) or 32 (float)
    int padding = kPadToFill; // texels grown around the charts, or every empty one
    std::vector<PresetMap> maps;

    bool operator==(const ExportPreset&) const = default;
};

/** glTF metallic-roughness, Unreal Engine, Unity (URP/HDRP) and ORM (Godot, Blender). */
const std::vector<ExportPreset>& builtinPresets();
/** The built-in preset with this id ("gltf", "unreal", "unity", "orm"), or nullopt. */
std::optional<ExportPreset> builtinPreset(std::string_view id);

/** The extension of format with the dot (".png", ".tif", ".exr", ".tga"). */
const char* mapFileExtension(MapFileFormat format);
/** "png", "tiff", "exr", "tga" ↔ the format. */
const char* mapFileFormatName(MapFileFormat format);
std::optional<MapFileFormat> parseMapFileFormat(std::string_view name);

/** An Error saying what is wrong with preset (maps, bit depth for the format, template), or ok. */
Status checkPreset(const ExportPreset& preset);

/**
 * A preset from its JSON text (see docs/texture-export.md); label names the text in errors.
 * Checked with checkPreset().
 */
Result<ExportPreset> parsePreset(std::string_view json, const std::string& label);
/** The JSON text of preset, as parsePreset() reads it. */
std::string presetJson(const ExportPreset& preset);
/** A built-in preset's id, else a preset file's path (at most 1 MiB). */
Result<ExportPreset> findPreset(const std::string& idOrPath);

/**
 * template with $mesh, $textureSet and $channel replaced (each part reduced to a file-name
 * part), without extension. An Error for any other $word.
 */
Result<std::string> expandFileName(std::string_view fileNameTemplate, const std::string& mesh,
                                   const std::string& textureSet, const std::string& channel);

} // namespace core
