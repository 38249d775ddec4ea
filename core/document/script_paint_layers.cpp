// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/script_paint_layers.h"

#include <cmath>
#include <cstdio>

#include "core/base/color.h"
#include "core/document/document.h"
#include "core/paint/paint_layers/blend_modes.h"

namespace core {

namespace {

using json = nlohmann::json;

struct PaintLayerOpError {
    std::string message;
};

float unitValue(const json& value, const char* what) {
    if (!value.is_number() || !(value.get<double>() >= 0.0) || !(value.get<double>() <= 1.0))
        throw PaintLayerOpError{std::string("\"") + what + "\" must be a number from 0 to 1"};
    return value.get<float>();
}

bool flag(const json& op, const char* key, bool fallback) {
    if (!op.contains(key))
        return fallback;
    if (!op[key].is_boolean())
        throw PaintLayerOpError{std::string("\"") + key + "\" must be true or false"};
    return op[key].get<bool>();
}

/** "#rrggbb" or [r, g, b] (sRGB, 0..1) as sRGB values. */
glm::vec3 srgbColor(const json& value, const char* what) {
    if (value.is_string()) {
        const std::string s = value.get<std::string>();
        unsigned r = 0, g = 0, b = 0;
        if (s.size() != 7 || std::sscanf(s.c_str(), "#%2x%2x%2x", &r, &g, &b) != 3)
            throw PaintLayerOpError{std::string("\"") + what + "\" must be #rrggbb"};
        return glm::vec3(float(r), float(g), float(b)) / 255.0f;
    }
    if (value.is_array() && value.size() == 3)
        return {unitValue(value[0], what), unitValue(value[1], what), unitValue(value[2], what)};
    throw PaintLayerOpError{std::string("\"") + what + "\" must be #rrggbb or [r, g, b] (0 to 1)"};
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
                throw PaintLayerOpError{"there is no paint layer " + ref.dump() + " (there are " +
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
                throw PaintLayerOpError{"there is no paint layer named " + ref.dump()};
        } else {
            throw PaintLayerOpError{
                "\"layer\" must be a paint layer's index, its name or \"base\""};
        }
    }
    if (id == 0 && !baseAllowed)
        throw PaintLayerOpError{"the operation needs a paint layer, not the base"};
    return id;
}

void check(const Status& status) {
    if (!status)
        throw PaintLayerOpError{status.error()};
}

} // namespace

Status applyBrushChannels(Brush& brush, const json& channels) {
    try {
        if (!channels.is_object())
            throw PaintLayerOpError{"\"channels\" must be an object with \"base_color\", "
                                    "\"roughness\" and \"metallic\" (any of them)"};
        for (const auto& [key, value] : channels.items())
            if (key != "base_color" && key != "roughness" && key != "metallic")
                throw PaintLayerOpError{"unknown channel \"" + key + "\""};
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
    } catch (const PaintLayerOpError& e) {
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

std::optional<Status> runPaintLayerOperation(Document& doc, const std::string& name,
                                             const json& op) {
    if (name.rfind("layer-", 0) != 0 && name.rfind("mask-", 0) != 0)
        return std::nullopt;
    try {
        Result<PaintLayerTarget*> ready = doc.paintLayerTarget();
        if (!ready)
            throw PaintLayerOpError{ready.error()};
        PaintLayerTarget& target = **ready;
        PaintChanges changes; // the caller refreshes its own copy of the target
        if (name == "layer-add") {
            PaintLayerSettings settings;
            settings.name =
                op.contains("name") && op["name"].is_string()
                    ? op["name"].get<std::string>()
                    : "Paint Layer " + std::to_string(target.paintLayerStack().size() + 1);
            const std::string kind = op.value("kind", json("paint")).is_string()
                                         ? op.value("kind", std::string("paint"))
                                         : std::string();
            if (kind == "fill")
                settings.kind = PaintLayerKind::Fill;
            else if (kind != "paint")
                throw PaintLayerOpError{"\"kind\" must be \"paint\" or \"fill\""};
            if (op.contains("values")) {
                const json& v = op["values"];
                if (!v.is_object())
                    throw PaintLayerOpError{"\"values\" must be an object"};
                if (v.contains("base_color"))
                    settings.fill.baseColor = srgbColor(v["base_color"], "base_color");
                if (v.contains("roughness"))
                    settings.fill.roughness = unitValue(v["roughness"], "roughness");
                if (v.contains("metallic"))
                    settings.fill.metallic = unitValue(v["metallic"], "metallic");
            }
            if (op.contains("opacity"))
                settings.opacity = unitValue(op["opacity"], "opacity");
            Result<std::uint64_t> id = doc.addPaintLayer(std::move(settings), changes);
            if (!id)
                throw PaintLayerOpError{id.error()};
        } else if (name == "layer-select") {
            check(doc.selectPaint({layerId(target, op, true), false}));
        } else if (name == "mask-select") {
            check(doc.selectPaint({layerId(target, op, false), true}));
        } else if (name == "layer-set") {
            const std::uint64_t id = layerId(target, op, false);
            PaintLayerSettings s =
                target.paintLayerStack().layer(*target.paintLayerStack().indexOf(id)).settings;
            if (op.contains("name")) {
                if (!op["name"].is_string())
                    throw PaintLayerOpError{"\"name\" must be a string"};
                s.name = op["name"].get<std::string>();
            }
            if (op.contains("opacity"))
                s.opacity = unitValue(op["opacity"], "opacity");
            if (op.contains("blend")) {
                const auto mode = op["blend"].is_string()
                                      ? blendModeFromName(op["blend"].get<std::string>())
                                      : std::nullopt;
                if (!mode)
                    throw PaintLayerOpError{"\"blend\" must be a blend mode's name (normal, "
                                            "multiply, screen, overlay, soft-light, ...)"};
                s.blend = *mode;
            }
            s.visible = flag(op, "visible", s.visible);
            s.lockTransparency = flag(op, "lock", s.lockTransparency);
            if (op.contains("values")) {
                // A fill layer's values: the channels named change, null leaves one alone.
                const json& v = op["values"];
                if (!v.is_object())
                    throw PaintLayerOpError{"\"values\" must be an object"};
                if (s.kind != PaintLayerKind::Fill)
                    throw PaintLayerOpError{"\"values\" are a fill layer's; this is a paint layer"};
                if (v.contains("base_color"))
                    s.fill.baseColor =
                        v["base_color"].is_null()
                            ? std::nullopt
                            : std::optional(srgbColor(v["base_color"], "base_color"));
                if (v.contains("roughness"))
                    s.fill.roughness = v["roughness"].is_null()
                                           ? std::nullopt
                                           : std::optional(unitValue(v["roughness"], "roughness"));
                if (v.contains("metallic"))
                    s.fill.metallic = v["metallic"].is_null()
                                          ? std::nullopt
                                          : std::optional(unitValue(v["metallic"], "metallic"));
            }
            check(doc.setPaintLayerSettings(id, std::move(s), changes));
        } else if (name == "layer-move") {
            const std::uint64_t id = layerId(target, op, false);
            if (!op.contains("index") || !op["index"].is_number_unsigned())
                throw PaintLayerOpError{"\"index\" must be the layer's new index (0 = the lowest)"};
            check(doc.movePaintLayer(id, op["index"].get<std::size_t>(), changes));
        } else if (name == "layer-delete") {
            check(doc.deletePaintLayer(layerId(target, op, false), changes));
        } else if (name == "layer-duplicate") {
            Result<std::uint64_t> id = doc.duplicatePaintLayer(layerId(target, op, false), changes);
            if (!id)
                throw PaintLayerOpError{id.error()};
        } else if (name == "layer-merge-down") {
            check(doc.mergePaintLayerDown(layerId(target, op, false), changes));
        } else if (name == "layer-flatten") {
            const std::string flat = op.contains("name") && op["name"].is_string()
                                         ? op["name"].get<std::string>()
                                         : std::string("Flattened");
            check(doc.flattenPaintLayers(flat, changes));
        } else if (name == "mask-add") {
            check(doc.addPaintLayerMask(layerId(target, op, false), changes));
        } else if (name == "mask-delete") {
            check(doc.deletePaintLayerMask(layerId(target, op, false), changes));
        } else {
            throw PaintLayerOpError{"unknown operation \"" + name + "\""};
        }
    } catch (const PaintLayerOpError& e) {
        return Status(Error{e.message, ErrorKind::BadInput});
    }
    return Status{};
}

} // namespace core
