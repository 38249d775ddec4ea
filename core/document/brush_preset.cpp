// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/brush_preset.h"

#include "core/document/document.h"
#include "core/document/script.h"

namespace core {

using nlohmann::json;

namespace {

/** Runs the preset's set-brush operation: nothing it does needs layers. */
class PresetHost : public ScriptHost {
public:
    explicit PresetHost(const TipLoader& load) : m_load(load) {}
    Status buildDepthLayers(Document&, const View&) override {
        return Error{"a brush preset cannot build layers"};
    }
    Result<std::shared_ptr<const TipImage>> loadTip(const std::string& path) override {
        if (!m_load)
            return Error{path + ": image tips cannot be loaded here"};
        return m_load(path);
    }

private:
    const TipLoader& m_load;
};

} // namespace

json brushPresetToJson(const BrushPreset& preset) {
    json brush = setBrushOperation(preset.brush, PressureCurve{});
    // The pressure curve is a preference of the artist's pen, not of a brush.
    brush.erase("op");
    brush.erase("pressure_curve");
    return {{"format", kBrushPresetFormat},
            {"version", 1},
            {"name", preset.name},
            {"brush", std::move(brush)}};
}

Result<BrushPreset> brushPresetFromJson(const json& value, const TipLoader& load) {
    if (!value.is_object())
        return Error{"a brush preset must be a JSON object"};
    if (!value.contains("format") || value["format"] != kBrushPresetFormat)
        return Error{std::string("not a brush preset (\"format\" must be \"") + kBrushPresetFormat +
                     "\")"};
    if (value.contains("version") &&
        (!value["version"].is_number_integer() || value["version"].get<long long>() != 1))
        return Error{"unsupported brush preset version (this version reads 1)"};
    if (!value.contains("name") || !value["name"].is_string() ||
        value["name"].get<std::string>().empty())
        return Error{"\"name\" must be a non-empty string"};
    if (value["name"].get<std::string>().size() > kMaxPresetNameBytes)
        return Error{"\"name\" is longer than " + std::to_string(kMaxPresetNameBytes) + " bytes"};
    if (!value.contains("brush") || !value["brush"].is_object())
        return Error{"\"brush\" must be an object of set-brush keys"};

    json op = value["brush"];
    op["op"] = "set-brush";
    op.erase("pressure_curve");
    Document scratch; // the set-brush operation's own checks and defaults
    PresetHost host(load);
    ScriptRunner runner(scratch, host, View{});
    if (Status s = runner.run(op); !s) {
        // The runner names the operation ("operation 1: ..."); a preset has only the brush.
        std::string message = s.error();
        if (const auto colon = message.find(": ");
            message.rfind("operation ", 0) == 0 && colon != std::string::npos)
            message = message.substr(colon + 2);
        return Error{"\"brush\": " + message};
    }
    return BrushPreset{value["name"].get<std::string>(), scratch.brush()};
}

Result<BrushPreset> parseBrushPresetFile(const std::string& text, const std::string& fileName,
                                         const TipLoader& load) {
    const json value = json::parse(text, nullptr, false);
    if (value.is_discarded())
        return Error{fileName + ": not valid JSON"};
    Result<BrushPreset> preset = brushPresetFromJson(value, load);
    if (!preset)
        return Error{fileName + ": " + preset.error(), preset.errorKind()};
    return preset;
}

std::vector<BrushPreset> starterBrushPresets() {
    std::vector<BrushPreset> presets;
    const auto add = [&](const char* name, auto&& set) {
        Brush b;
        b.color = {0.05f, 0.05f, 0.06f, 1.0f};
        set(b);
        presets.push_back({name, b});
    };
    add("Soft Round", [](Brush& b) {
        b.tip = "round-soft";
        b.radius = 32.0f;
        b.hardness = 0.0f;
        b.flow = 0.6f;
    });
    add("Hard Ink", [](Brush& b) {
        b.tip = "round-hard";
        b.radius = 6.0f;
        b.hardness = 1.0f;
        b.spacing = 0.08f;
        b.pressureRadius = true;
    });
    add("Chalk", [](Brush& b) {
        b.tip = "chalk";
        b.radius = 20.0f;
        b.opacity = 0.85f;
        b.angleMode = TipAngleMode::Random;
        b.jitter.opacity = 0.3f;
        b.seed = 7;
    });
    add("Spatter", [](Brush& b) {
        b.chooseTip("spatter"); // apart, scattered, turned at random
        b.radius = 24.0f;
        b.seed = 11;
    });
    add("Metal Paint", [](Brush& b) {
        b.radius = 28.0f;
        b.hardness = 0.7f;
        b.color = {0.56f, 0.57f, 0.58f, 1.0f};
        b.paintRoughness = true;
        b.paintMetallic = true;
        b.metallic = 1.0f;
        b.roughness = 0.3f;
    });
    add("Rough Matte", [](Brush& b) {
        b.radius = 28.0f;
        b.hardness = 0.5f;
        b.paintBaseColor = false;
        b.paintRoughness = true;
        b.roughness = 0.9f;
    });
    add("Eraser Soft", [](Brush& b) {
        b.tip = "round-soft";
        b.radius = 24.0f;
        b.hardness = 0.0f;
        b.eraser = true;
    });
    add("Stabilized Liner", [](Brush& b) {
        b.tip = "round-hard";
        b.radius = 4.0f;
        b.hardness = 1.0f;
        b.spacing = 0.08f;
        b.stabilizer = true;
        b.stabilizerLength = 40.0f;
        b.stabilizerSmoothing = 0.3f;
        b.stabilizerCatchUp = true;
    });
    return presets;
}

} // namespace core
