// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/texture_sets/export_preset.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "core/base/text.h"
#include "core/io/json_nesting.h"

namespace core {

namespace {

using Json = nlohmann::json;

constexpr std::size_t kMaxPresetBytes = 1u << 20;
constexpr std::size_t kMaxMaps = 32;
constexpr std::size_t kMaxNameBytes = 200;

constexpr std::array kChannels = {SetChannel::BaseColor, SetChannel::Opacity, SetChannel::Roughness,
                                  SetChannel::Metallic,  SetChannel::Normal,  SetChannel::Occlusion,
                                  SetChannel::Emissive};
constexpr std::array<const char*, 4> kComponentNames = {"r", "g", "b", "a"};

MapComponent of(SetChannel channel, int component = 0, bool inverted = false) {
    return MapComponent{channel, component, inverted, 0.0f};
}

MapComponent constant(float value) {
    return MapComponent{std::nullopt, 0, false, value};
}

std::vector<MapComponent> rgbOf(SetChannel channel) {
    return {of(channel, 0), of(channel, 1), of(channel, 2)};
}

PresetMap baseColorAndOpacity(const char* name) {
    std::vector<MapComponent> c = rgbOf(SetChannel::BaseColor);
    c.push_back(of(SetChannel::Opacity));
    return {name, c};
}

PresetMap occlusionRoughnessMetallic(const char* name) {
    return {name, {of(SetChannel::Occlusion), of(SetChannel::Roughness), of(SetChannel::Metallic)}};
}

ExportPreset preset(const char* id, const char* name, NormalConvention normal,
                    std::vector<PresetMap> maps) {
    ExportPreset p;
    p.id = id;
    p.name = name;
    p.normal = normal;
    p.maps = std::move(maps);
    return p;
}

std::vector<ExportPreset> makeBuiltinPresets() {
    const PresetMap normal{"Normal", rgbOf(SetChannel::Normal)};
    return {
        preset("gltf", "glTF metallic-roughness", NormalConvention::OpenGl,
               {baseColorAndOpacity("BaseColor"),
                occlusionRoughnessMetallic("OcclusionRoughnessMetallic"),
                normal,
                {"Emissive", rgbOf(SetChannel::Emissive)}}),
        preset("unreal", "Unreal Engine", NormalConvention::DirectX,
               {{"BaseColor", rgbOf(SetChannel::BaseColor)},
                occlusionRoughnessMetallic("OcclusionRoughnessMetallic"),
                normal,
                {"Emissive", rgbOf(SetChannel::Emissive)},
                {"Opacity", {of(SetChannel::Opacity)}}}),
        // Unity's mask map: metallic, occlusion, detail mask (white: details everywhere, as
        // Unity assumes without a mask map) and smoothness.
        preset("unity", "Unity (URP, HDRP)", NormalConvention::OpenGl,
               {baseColorAndOpacity("BaseMap"),
                {"MaskMap",
                 {of(SetChannel::Metallic), of(SetChannel::Occlusion), constant(1.0f),
                  of(SetChannel::Roughness, 0, true)}},
                normal,
                {"Emission", rgbOf(SetChannel::Emissive)}}),
        preset("orm", "ORM (Godot, Blender)", NormalConvention::OpenGl,
               {baseColorAndOpacity("BaseColor"),
                occlusionRoughnessMetallic("ORM"),
                normal,
                {"Emission", rgbOf(SetChannel::Emissive)}}),
    };
}

std::optional<SetChannel> channelNamed(std::string_view name) {
    for (SetChannel c : kChannels)
        if (name == channelName(c))
            return c;
    return std::nullopt;
}

std::string knownChannels() {
    std::string out;
    for (SetChannel c : kChannels)
        out += std::string(out.empty() ? "" : ", ") + channelName(c);
    return out + ", smoothness";
}

/** "roughness", "1-roughness", "smoothness", "baseColor.g", "normal" (with n components). */
Result<std::vector<MapComponent>> parseSource(const Json& value, std::size_t wanted,
                                              const std::string& where) {
    if (value.is_number()) {
        const double v = value.get<double>();
        if (wanted != 1 || !(v >= 0.0 && v <= 1.0))
            return Error{where + ": a constant is one value from 0 to 1"};
        return std::vector<MapComponent>{constant(float(v))};
    }
    if (!value.is_string())
        return Error{where + ": expected a channel name or a number"};
    std::string text = value.get<std::string>();
    bool inverted = false;
    if (text.starts_with("1-")) {
        inverted = true;
        text.erase(0, 2);
    }
    if (text == "smoothness") {
        text = "roughness";
        inverted = !inverted;
    }
    std::optional<int> component;
    if (const std::size_t dot = text.find('.'); dot != std::string::npos) {
        const std::string c = text.substr(dot + 1);
        for (int k = 0; k < 4; ++k)
            if (c == kComponentNames[std::size_t(k)])
                component = k;
        if (!component)
            return Error{where + ": unknown component “" + printable(c) + "” (use r, g or b)"};
        text.erase(dot);
    }
    const std::optional<SetChannel> channel = channelNamed(text);
    if (!channel)
        return Error{where + ": unknown channel “" + printable(text) +
                     "” (known: " + knownChannels() + ")"};
    const int n = channelComponents(*channel);
    if (component && *component >= n)
        return Error{where + ": " + channelName(*channel) + " has no component " +
                     kComponentNames[std::size_t(*component)]};
    std::vector<MapComponent> out;
    if (component || n == 1) {
        out.push_back(of(*channel, component.value_or(0), inverted));
    } else {
        for (int k = 0; k < n; ++k)
            out.push_back(of(*channel, k, inverted));
    }
    if (out.size() != wanted)
        return Error{where + ": " + std::to_string(wanted) + " component(s) wanted, " +
                     channelName(*channel) + " gives " + std::to_string(out.size()) +
                     (out.size() > 1
                          ? " (name one, as in " + std::string(channelName(*channel)) + ".r)"
                          : "")};
    return out;
}

Result<PresetMap> parseMap(const Json& entry, const std::string& where) {
    if (!entry.is_object())
        return Error{where + ": expected an object"};
    PresetMap map;
    const auto name = entry.find("name");
    if (name == entry.end() || !name->is_string() || name->get<std::string>().empty())
        return Error{where + ": has no name"};
    map.name = name->get<std::string>();
    const std::string at = where + " (“" + printable(map.name) + "”)";
    // The slots: grey (or r), g, b, a; rgb fills r, g and b; rgba all four.
    std::array<std::optional<MapComponent>, 4> slots;
    bool grey = false;
    for (const auto& [key, value] : entry.items()) {
        if (key == "name")
            continue;
        std::vector<int> targets;
        if (key == "rgb")
            targets = {0, 1, 2};
        else if (key == "rgba")
            targets = {0, 1, 2, 3};
        else if (key == "grey" || key == "gray")
            targets = {0}, grey = true;
        else
            for (int k = 0; k < 4; ++k)
                if (key == kComponentNames[std::size_t(k)])
                    targets = {k};
        if (targets.empty())
            return Error{at + ": unknown key “" + printable(key) +
                         "” (use name, grey, r, g, b, a, rgb or rgba)"};
        Result<std::vector<MapComponent>> source =
            parseSource(value, targets.size(), at + ": " + key);
        if (!source)
            return source.takeError();
        for (std::size_t i = 0; i < targets.size(); ++i) {
            if (slots[std::size_t(targets[i])])
                return Error{at + ": component " + kComponentNames[std::size_t(targets[i])] +
                             " is given twice"};
            slots[std::size_t(targets[i])] = (*source)[i];
        }
    }
    if (grey && (slots[1] || slots[2]))
        return Error{at + ": a grey map has no g or b"};
    if (!slots[0])
        return Error{at + ": gives no value for " + (grey ? "grey" : "r")};
    if (grey || (!slots[1] && !slots[2])) {
        map.components.push_back(*slots[0]);
        if (slots[3])
            map.components.push_back(*slots[3]);
        return map;
    }
    for (int k = 1; k < 3; ++k)
        if (!slots[std::size_t(k)])
            return Error{at + ": gives no value for " + kComponentNames[std::size_t(k)]};
    for (int k = 0; k < (slots[3] ? 4 : 3); ++k)
        map.components.push_back(*slots[std::size_t(k)]);
    return map;
}

Json sourceJson(const MapComponent& c, bool wholeChannel) {
    if (!c.channel)
        return c.constant;
    std::string text = channelName(*c.channel);
    if (!wholeChannel && channelComponents(*c.channel) > 1)
        text += std::string(".") + kComponentNames[std::size_t(c.component)];
    if (c.inverted)
        return *c.channel == SetChannel::Roughness ? std::string("smoothness") : "1-" + text;
    return text;
}

Json mapJson(const PresetMap& map) {
    Json out = {{"name", map.name}};
    const auto& c = map.components;
    const auto wholeRgb = [&] {
        return c.size() >= 3 && c[0].channel && channelComponents(*c[0].channel) == 3 &&
               c[1] == MapComponent{c[0].channel, 1, c[0].inverted, 0.0f} &&
               c[2] == MapComponent{c[0].channel, 2, c[0].inverted, 0.0f};
    };
    if (c.size() <= 2) {
        out["grey"] = sourceJson(c[0], false);
        if (c.size() == 2)
            out["a"] = sourceJson(c[1], false);
        return out;
    }
    if (wholeRgb()) {
        out["rgb"] = sourceJson(c[0], true);
    } else {
        for (std::size_t k = 0; k < 3; ++k)
            out[kComponentNames[k]] = sourceJson(c[k], false);
    }
    if (c.size() == 4)
        out["a"] = sourceJson(c[3], false);
    return out;
}

} // namespace

int channelComponents(SetChannel channel) {
    switch (channel) {
    case SetChannel::BaseColor:
    case SetChannel::Normal:
    case SetChannel::Emissive:
        return 3;
    default:
        return 1;
    }
}

bool isColorChannel(SetChannel channel) {
    return channel == SetChannel::BaseColor || channel == SetChannel::Emissive;
}

const char* channelName(SetChannel channel) {
    switch (channel) {
    case SetChannel::BaseColor:
        return "baseColor";
    case SetChannel::Opacity:
        return "opacity";
    case SetChannel::Roughness:
        return "roughness";
    case SetChannel::Metallic:
        return "metallic";
    case SetChannel::Normal:
        return "normal";
    case SetChannel::Occlusion:
        return "occlusion";
    case SetChannel::Emissive:
        return "emissive";
    }
    return "";
}

const std::vector<ExportPreset>& builtinPresets() {
    static const std::vector<ExportPreset> presets = makeBuiltinPresets();
    return presets;
}

std::optional<ExportPreset> builtinPreset(std::string_view id) {
    for (const ExportPreset& p : builtinPresets())
        if (p.id == id)
            return p;
    return std::nullopt;
}

const char* mapFileExtension(MapFileFormat format) {
    switch (format) {
    case MapFileFormat::Png:
        return ".png";
    case MapFileFormat::Tiff:
        return ".tif";
    case MapFileFormat::Exr:
        return ".exr";
    case MapFileFormat::Tga:
        return ".tga";
    }
    return ".png";
}

const char* mapFileFormatName(MapFileFormat format) {
    switch (format) {
    case MapFileFormat::Png:
        return "png";
    case MapFileFormat::Tiff:
        return "tiff";
    case MapFileFormat::Exr:
        return "exr";
    case MapFileFormat::Tga:
        return "tga";
    }
    return "png";
}

std::optional<MapFileFormat> parseMapFileFormat(std::string_view name) {
    for (MapFileFormat f :
         {MapFileFormat::Png, MapFileFormat::Tiff, MapFileFormat::Exr, MapFileFormat::Tga})
        if (name == mapFileFormatName(f))
            return f;
    if (name == "tif")
        return MapFileFormat::Tiff;
    return std::nullopt;
}

Status checkPreset(const ExportPreset& preset) {
    const std::string label = preset.name.empty() ? std::string("the preset")
                                                  : "the preset “" + printable(preset.name) + "”";
    if (preset.maps.empty())
        return Error{label + " writes no map"};
    if (preset.maps.size() > kMaxMaps)
        return Error{label + " has more than " + std::to_string(kMaxMaps) + " maps"};
    const bool depthOk =
        preset.format == MapFileFormat::Exr   ? preset.bitDepth == 16 || preset.bitDepth == 32
        : preset.format == MapFileFormat::Tga ? preset.bitDepth == 8
                                              : preset.bitDepth == 8 || preset.bitDepth == 16;
    if (!depthOk)
        return Error{label + ": " + mapFileFormatName(preset.format) + " cannot hold " +
                     std::to_string(preset.bitDepth) +
                     "-bit values (PNG and TIFF 8 or 16, TGA "
                     "8, EXR 16 or 32)"};
    if (preset.padding != kPadToFill && (preset.padding < 0 || preset.padding > kMaxPadding))
        return Error{label + ": the padding must be 0 to " + std::to_string(kMaxPadding) +
                     " texels, or fill"};
    if (preset.fileName.size() > kMaxNameBytes)
        return Error{label + ": the file-name template is too long"};
    for (const char c : preset.fileName)
        if (c == '/' || c == '\\' || static_cast<unsigned char>(c) < 0x20)
            return Error{label + ": the file-name template “" + printable(preset.fileName) +
                         "” may not hold path separators or control characters"};
    if (preset.fileName.empty() || preset.fileName.front() == '.')
        return Error{label + ": the file-name template may not be empty or start with a dot"};
    std::set<std::string> names;
    for (const PresetMap& map : preset.maps) {
        if (map.name.empty() || map.name.size() > kMaxNameBytes)
            return Error{label + ": a map has no name, or one that is too long"};
        if (map.components.empty() || map.components.size() > 4)
            return Error{label + ": the map “" + printable(map.name) + "” needs 1 to 4 components"};
        if (!names.insert(fileNamePart(map.name, "map")).second)
            return Error{label + ": two maps are named “" + printable(map.name) + "”"};
    }
    Result<std::string> expanded = expandFileName(preset.fileName, "m", "s", "c");
    if (!expanded)
        return Error{label + ": " + expanded.error()};
    if (preset.maps.size() > 1 && preset.fileName.find("$channel") == std::string::npos)
        return Error{label + ": the file-name template needs $channel to tell its maps apart"};
    return {};
}

Result<ExportPreset> parsePreset(std::string_view text, const std::string& label) {
    if (text.size() > kMaxPresetBytes)
        return Error{label + ": a preset file is at most 1 MiB"};
    if (jsonNestingTooDeep(text))
        return Error{label + ": the JSON nests too deeply"};
    Json json = Json::parse(text, nullptr, false);
    if (json.is_discarded() || !json.is_object())
        return Error{label + ": not a JSON object"};
    ExportPreset preset;
    const auto stringField = [&](const char* key, std::string& out) -> Status {
        const auto it = json.find(key);
        if (it == json.end())
            return {};
        if (!it->is_string())
            return Error{label + ": “" + key + "” must be a string"};
        out = it->get<std::string>();
        return {};
    };
    std::string normal = "opengl", format = "png";
    for (const auto& [key, out] :
         {std::pair{"name", &preset.name}, std::pair{"fileName", &preset.fileName},
          std::pair{"normal", &normal}, std::pair{"format", &format}})
        if (Status s = stringField(key, *out); !s)
            return s.takeError();
    if (preset.name.empty())
        preset.name = "Custom";
    if (normal == "directx")
        preset.normal = NormalConvention::DirectX;
    else if (normal != "opengl")
        return Error{label + ": “normal” is opengl or directx"};
    const std::optional<MapFileFormat> f = parseMapFileFormat(format);
    if (!f)
        return Error{label + ": unknown format “" + printable(format) +
                     "” (use png, tiff, exr or tga)"};
    preset.format = *f;
    preset.bitDepth = preset.format == MapFileFormat::Exr ? 16 : 8;
    if (const auto it = json.find("bitDepth"); it != json.end()) {
        if (!it->is_number_integer())
            return Error{label + ": “bitDepth” must be 8, 16 or 32"};
        preset.bitDepth = int(std::clamp<std::int64_t>(it->get<std::int64_t>(), -1, 64));
    }
    if (const auto it = json.find("padding"); it != json.end()) {
        if (it->is_string() && it->get<std::string>() == "fill")
            preset.padding = kPadToFill;
        else if (it->is_number_integer())
            preset.padding =
                int(std::clamp<std::int64_t>(it->get<std::int64_t>(), -2, kMaxPadding + 1));
        else
            return Error{label + ": “padding” is a number of texels or \"fill\""};
    }
    const auto maps = json.find("maps");
    if (maps == json.end() || !maps->is_array() || maps->empty())
        return Error{label + ": “maps” must list the files to write"};
    if (maps->size() > kMaxMaps)
        return Error{label + ": more than " + std::to_string(kMaxMaps) + " maps"};
    for (std::size_t i = 0; i < maps->size(); ++i) {
        Result<PresetMap> map = parseMap((*maps)[i], label + ": map " + std::to_string(i + 1));
        if (!map)
            return map.takeError();
        preset.maps.push_back(std::move(*map));
    }
    if (Status s = checkPreset(preset); !s)
        return Error{label + ": " + s.error()};
    return preset;
}

std::string presetJson(const ExportPreset& preset) {
    Json maps = Json::array();
    for (const PresetMap& map : preset.maps)
        maps.push_back(mapJson(map));
    Json out = {{"name", preset.name},
                {"fileName", preset.fileName},
                {"normal", preset.normal == NormalConvention::DirectX ? "directx" : "opengl"},
                {"format", mapFileFormatName(preset.format)},
                {"bitDepth", preset.bitDepth},
                {"maps", maps}};
    if (preset.padding == kPadToFill)
        out["padding"] = "fill";
    else
        out["padding"] = preset.padding;
    return out.dump(2) + "\n";
}

Result<ExportPreset> findPreset(const std::string& idOrPath) {
    if (std::optional<ExportPreset> builtin = builtinPreset(idOrPath))
        return *builtin;
    std::ifstream in(idOrPath, std::ios::binary);
    if (!in) {
        std::string ids;
        for (const ExportPreset& p : builtinPresets())
            ids += (ids.empty() ? "" : ", ") + p.id;
        return Error{idOrPath + ": neither a built-in preset (" + ids +
                     ") nor a preset file that can be read"};
    }
    std::string text(kMaxPresetBytes + 1, '\0');
    in.read(text.data(), std::streamsize(text.size()));
    text.resize(std::size_t(in.gcount()));
    return parsePreset(text, idOrPath);
}

Result<std::string> expandFileName(std::string_view fileNameTemplate, const std::string& mesh,
                                   const std::string& textureSet, const std::string& channel) {
    std::string out;
    for (std::size_t i = 0; i < fileNameTemplate.size();) {
        if (fileNameTemplate[i] != '$') {
            out.push_back(fileNameTemplate[i++]);
            continue;
        }
        std::size_t end = i + 1;
        while (end < fileNameTemplate.size() &&
               (std::isalnum(static_cast<unsigned char>(fileNameTemplate[end])) != 0))
            ++end;
        const std::string_view word = fileNameTemplate.substr(i + 1, end - i - 1);
        if (word == "mesh")
            out += fileNamePart(mesh, "model");
        else if (word == "textureSet")
            out += fileNamePart(textureSet, "set");
        else if (word == "channel")
            out += fileNamePart(channel, "map");
        else
            return Error{"unknown “$" + printable(word) +
                         "” in the file-name template (use $mesh, $textureSet and $channel)"};
        i = end;
    }
    return out;
}

} // namespace core
