// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/script_paint_layers.h"

#include <cmath>
#include <cstdio>

#include "core/base/color.h"
#include "core/document/document.h"
#include "core/document/script_ops.h"
#include "core/paint/paint_layers/blend_modes.h"

namespace core {

namespace {

using json = nlohmann::json;

float unitValue(const json& value, const char* what) {
    if (!value.is_number() || !(value.get<double>() >= 0.0) || !(value.get<double>() <= 1.0))
        throw ScriptOpError{std::string("\"") + what + "\" must be a number from 0 to 1"};
    return value.get<float>();
}

bool flag(const json& op, const char* key, bool fallback) {
    if (!op.contains(key))
        return fallback;
    if (!op[key].is_boolean())
        throw ScriptOpError{std::string("\"") + key + "\" must be true or false"};
    return op[key].get<bool>();
}

/** "#rrggbb" or [r, g, b] (sRGB, 0..1) as sRGB values. */
glm::vec3 srgbColor(const json& value, const char* what) {
    if (value.is_string()) {
        const std::string s = value.get<std::string>();
        unsigned r = 0, g = 0, b = 0;
        if (s.size() != 7 || std::sscanf(s.c_str(), "#%2x%2x%2x", &r, &g, &b) != 3)
            throw ScriptOpError{std::string("\"") + what + "\" must be #rrggbb"};
        return glm::vec3(float(r), float(g), float(b)) / 255.0f;
    }
    if (value.is_array() && value.size() == 3)
        return {unitValue(value[0], what), unitValue(value[1], what), unitValue(value[2], what)};
    throw ScriptOpError{std::string("\"") + what + "\" must be #rrggbb or [r, g, b] (0 to 1)"};
}

/**
 * The paint layer op names with "layer": an index (0 = the lowest), a name, or "base" (0); the
 * selected layer without one.
 */
std::uint64_t layerId(const PaintLayerTarget& target, const json& op, bool baseAllowed) {
    const PaintLayerStack& stack = target.paintLayerStack();
    std::uint64_t id = target.selection().layer;
    if (op.contains("layer")) {
        const json& ref = op["layer"];
        if (ref.is_number_unsigned()) {
            if (ref.get<std::uint64_t>() >= stack.size())
                throw ScriptOpError{"there is no paint layer " + ref.dump() + " (there are " +
                                    std::to_string(stack.size()) + ")"};
            id = stack.layer(ref.get<std::size_t>()).id;
        } else if (ref == "base") {
            id = 0;
        } else if (ref.is_string()) {
            id = 0;
            for (std::size_t i = stack.size(); i-- > 0;)
                if (stack.layer(i).settings.name == ref.get<std::string>()) {
                    id = stack.layer(i).id;
                    break;
                }
            if (id == 0)
                throw ScriptOpError{"there is no paint layer named " + ref.dump()};
        } else {
            throw ScriptOpError{"\"layer\" must be a paint layer's index, its name or \"base\""};
        }
    }
    if (id == 0 && !baseAllowed)
        throw ScriptOpError{"the operation needs a paint layer, not the base"};
    return id;
}

/**
 * The document's texture target (made if need be, any stroke ended): every paint-layer operation
 * asks for it first, so its error comes before any other.
 */
PaintLayerTarget& readyPaintLayerTarget(ScriptOp& s) {
    Result<PaintLayerTarget*> ready = s.doc.paintLayerTarget();
    if (!ready)
        throw ScriptOpError{ready.error()};
    return **ready;
}

/** layer-add's "kind": paint (the default) or fill. */
PaintLayerKind layerKindOf(const json& op) {
    const std::string kind = op.value("kind", json("paint")).is_string()
                                 ? op.value("kind", std::string("paint"))
                                 : std::string();
    if (kind == "fill")
        return PaintLayerKind::Fill;
    if (kind != "paint")
        throw ScriptOpError{"\"kind\" must be \"paint\" or \"fill\""};
    return PaintLayerKind::Paint;
}

void runLayerAdd(ScriptOp& s) {
    const PaintLayerTarget& target = readyPaintLayerTarget(s);
    const json& op = s.op;
    PaintLayerSettings settings;
    settings.name = op.contains("name") && op["name"].is_string()
                        ? op["name"].get<std::string>()
                        : "Paint Layer " + std::to_string(target.paintLayerStack().size() + 1);
    settings.kind = layerKindOf(op);
    if (op.contains("values")) {
        const json& v = op["values"];
        if (!v.is_object())
            throw ScriptOpError{"\"values\" must be an object"};
        if (v.contains("base_color"))
            settings.fill.baseColor = srgbColor(v["base_color"], "base_color");
        if (v.contains("roughness"))
            settings.fill.roughness = unitValue(v["roughness"], "roughness");
        if (v.contains("metallic"))
            settings.fill.metallic = unitValue(v["metallic"], "metallic");
    }
    if (op.contains("opacity"))
        settings.opacity = unitValue(op["opacity"], "opacity");
    Result<std::uint64_t> id = s.doc.addPaintLayer(std::move(settings), s.changes);
    if (!id)
        throw ScriptOpError{id.error()};
}

void runLayerSelect(ScriptOp& s) {
    const PaintLayerTarget& target = readyPaintLayerTarget(s);
    throwIfError(s.doc.selectPaint({layerId(target, s.op, true), false}));
}

void runMaskSelect(ScriptOp& s) {
    const PaintLayerTarget& target = readyPaintLayerTarget(s);
    throwIfError(s.doc.selectPaint({layerId(target, s.op, false), true}));
}

/** layer-set's "blend": a blend mode's name. */
BlendMode blendModeOf(const json& value) {
    const auto mode =
        value.is_string() ? blendModeFromName(value.get<std::string>()) : std::nullopt;
    if (!mode)
        throw ScriptOpError{"\"blend\" must be a blend mode's name (normal, multiply, screen, "
                            "overlay, soft-light, ...)"};
    return *mode;
}

/** layer-set's "values" on a fill layer's settings: the channels named change, null leaves one
 * alone. */
void setFillValues(const json& v, PaintLayerSettings& settings) {
    if (!v.is_object())
        throw ScriptOpError{"\"values\" must be an object"};
    if (settings.kind != PaintLayerKind::Fill)
        throw ScriptOpError{"\"values\" are a fill layer's; this is a paint layer"};
    ChannelValues& fill = settings.fill;
    if (v.contains("base_color"))
        fill.baseColor = v["base_color"].is_null()
                             ? std::nullopt
                             : std::optional(srgbColor(v["base_color"], "base_color"));
    if (v.contains("roughness"))
        fill.roughness = v["roughness"].is_null()
                             ? std::nullopt
                             : std::optional(unitValue(v["roughness"], "roughness"));
    if (v.contains("metallic"))
        fill.metallic = v["metallic"].is_null()
                            ? std::nullopt
                            : std::optional(unitValue(v["metallic"], "metallic"));
}

void runLayerSet(ScriptOp& s) {
    const PaintLayerTarget& target = readyPaintLayerTarget(s);
    const json& op = s.op;
    const std::uint64_t id = layerId(target, op, false);
    PaintLayerSettings settings =
        target.paintLayerStack().layer(*target.paintLayerStack().indexOf(id)).settings;
    if (op.contains("name")) {
        if (!op["name"].is_string())
            throw ScriptOpError{"\"name\" must be a string"};
        settings.name = op["name"].get<std::string>();
    }
    if (op.contains("opacity"))
        settings.opacity = unitValue(op["opacity"], "opacity");
    if (op.contains("blend"))
        settings.blend = blendModeOf(op["blend"]);
    settings.visible = flag(op, "visible", settings.visible);
    settings.lockTransparency = flag(op, "lock", settings.lockTransparency);
    if (op.contains("values"))
        setFillValues(op["values"], settings);
    throwIfError(s.doc.setPaintLayerSettings(id, std::move(settings), s.changes));
}

void runLayerMove(ScriptOp& s) {
    const PaintLayerTarget& target = readyPaintLayerTarget(s);
    const std::uint64_t id = layerId(target, s.op, false);
    if (!s.op.contains("index") || !s.op["index"].is_number_unsigned())
        throw ScriptOpError{"\"index\" must be the layer's new index (0 = the lowest)"};
    throwIfError(s.doc.movePaintLayer(id, s.op["index"].get<std::size_t>(), s.changes));
}

void runLayerDelete(ScriptOp& s) {
    const PaintLayerTarget& target = readyPaintLayerTarget(s);
    throwIfError(s.doc.deletePaintLayer(layerId(target, s.op, false), s.changes));
}

void runLayerDuplicate(ScriptOp& s) {
    const PaintLayerTarget& target = readyPaintLayerTarget(s);
    Result<std::uint64_t> id = s.doc.duplicatePaintLayer(layerId(target, s.op, false), s.changes);
    if (!id)
        throw ScriptOpError{id.error()};
}

void runLayerMergeDown(ScriptOp& s) {
    const PaintLayerTarget& target = readyPaintLayerTarget(s);
    throwIfError(s.doc.mergePaintLayerDown(layerId(target, s.op, false), s.changes));
}

void runLayerFlatten(ScriptOp& s) {
    readyPaintLayerTarget(s); // its error first, as for every paint-layer operation
    const std::string flat = s.op.contains("name") && s.op["name"].is_string()
                                 ? s.op["name"].get<std::string>()
                                 : std::string("Flattened");
    throwIfError(s.doc.flattenPaintLayers(flat, s.changes));
}

void runMaskAdd(ScriptOp& s) {
    const PaintLayerTarget& target = readyPaintLayerTarget(s);
    throwIfError(s.doc.addPaintLayerMask(layerId(target, s.op, false), s.changes));
}

void runMaskDelete(ScriptOp& s) {
    const PaintLayerTarget& target = readyPaintLayerTarget(s);
    throwIfError(s.doc.deletePaintLayerMask(layerId(target, s.op, false), s.changes));
}

constexpr ScriptOpEntry kPaintLayerOperations[] = {
    {"layer-add", runLayerAdd},
    {"layer-select", runLayerSelect},
    {"mask-select", runMaskSelect},
    {"layer-set", runLayerSet},
    {"layer-move", runLayerMove},
    {"layer-delete", runLayerDelete},
    {"layer-duplicate", runLayerDuplicate},
    {"layer-merge-down", runLayerMergeDown},
    {"layer-flatten", runLayerFlatten},
    {"mask-add", runMaskAdd},
    {"mask-delete", runMaskDelete},
};

} // namespace

std::span<const ScriptOpEntry> paintLayerOperations() {
    return kPaintLayerOperations;
}

Status applyBrushChannels(Brush& brush, const json& channels) {
    try {
        if (!channels.is_object())
            throw ScriptOpError{"\"channels\" must be an object with \"base_color\", "
                                "\"roughness\" and \"metallic\" (any of them)"};
        for (const auto& [key, value] : channels.items())
            if (key != "base_color" && key != "roughness" && key != "metallic")
                throw ScriptOpError{"unknown channel \"" + key + "\""};
        Brush b = brush;
        b.paintBaseColor = channels.contains("base_color");
        if (b.paintBaseColor && !channels["base_color"].is_boolean()) {
            const glm::vec3 c = srgbColor(channels["base_color"], "base_color");
            b.color = {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b), b.color.a};
        } else if (b.paintBaseColor && !channels["base_color"].get<bool>()) {
            b.paintBaseColor = false;
        }
        b.paintRoughness = channels.contains("roughness");
        if (b.paintRoughness)
            b.roughness = unitValue(channels["roughness"], "roughness");
        b.paintMetallic = channels.contains("metallic");
        if (b.paintMetallic)
            b.metallic = unitValue(channels["metallic"], "metallic");
        brush = b;
    } catch (const ScriptOpError& e) {
        return Error{e.message, ErrorKind::BadInput};
    }
    return {};
}

json brushChannelsJson(const Brush& brush) {
    json channels = json::object();
    if (brush.paintBaseColor)
        channels["base_color"] = true;
    if (brush.paintRoughness)
        channels["roughness"] = brush.roughness;
    if (brush.paintMetallic)
        channels["metallic"] = brush.metallic;
    return channels;
}

} // namespace core
