// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/script_stroke.h"

#include <cmath>
#include <string>
#include <string_view>

#include "core/document/document.h"
#include "core/document/script_ops.h"

namespace core {

using nlohmann::json;

namespace {

/** [x, y] or [x, y, pressure] (pixels from the top-left, pressure 0..1). */
StrokePoint pointAt(const json& op, const char* key) {
    const std::string what = std::string("\"") + key + "\"";
    if (!op.contains(key))
        throw ScriptOpError{what + " is missing"};
    const json& p = op[key];
    if (!p.is_array() || p.size() < 2 || p.size() > 3 || !p[0].is_number() || !p[1].is_number() ||
        (p.size() == 3 && !p[2].is_number()))
        throw ScriptOpError{what + " must be [x, y] or [x, y, pressure]"};
    StrokePoint point;
    point.position = {p[0].get<float>(), p[1].get<float>()};
    point.pressure = p.size() == 3 ? p[2].get<float>() : 1.0f;
    if (!std::isfinite(point.position.x) || !std::isfinite(point.position.y) ||
        !(point.pressure >= 0.0f && point.pressure <= 1.0f))
        throw ScriptOpError{what + " is not finite or its pressure is outside 0..1"};
    return point;
}

float unitRange(const json& value, const char* key, float lo, float hi) {
    if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < lo ||
        value.get<double>() > hi)
        throw ScriptOpError{std::string("\"stabilizer\" \"") + key + "\" must be a number from " +
                            std::to_string(int(lo)) + " to " + std::to_string(int(hi))};
    return value.get<float>();
}

bool flag(const json& value, const char* key) {
    if (!value.is_boolean())
        throw ScriptOpError{std::string("\"stabilizer\" \"") + key + "\" must be true or false"};
    return value.get<bool>();
}

/** One setting of set-brush's "stabilizer" object, applied to a brush. */
struct StabilizerSetting {
    std::string_view key;
    void (*apply)(const json& value, Brush& b);
};

constexpr StabilizerSetting kStabilizerSettings[] = {
    {"on", [](const json& v, Brush& b) { b.stabilizer = flag(v, "on"); }},
    {"length",
     [](const json& v, Brush& b) { b.stabilizerLength = unitRange(v, "length", 0.0f, 1000.0f); }},
    {"smoothing", [](const json& v,
                     Brush& b) { b.stabilizerSmoothing = unitRange(v, "smoothing", 0.0f, 1.0f); }},
    {"catch_up", [](const json& v, Brush& b) { b.stabilizerCatchUp = flag(v, "catch_up"); }},
};

const StabilizerSetting& stabilizerSetting(const std::string& key) {
    for (const StabilizerSetting& setting : kStabilizerSettings)
        if (setting.key == key)
            return setting;
    throw ScriptOpError{"unknown \"stabilizer\" setting \"" + key + "\""};
}

void runLine(ScriptOp& s) {
    s.needDepthLayers();
    throwIfError(s.doc.line(pointAt(s.op, "from"), pointAt(s.op, "to"), s.changes));
}

void runLineTo(ScriptOp& s) {
    s.needDepthLayers();
    throwIfError(s.doc.lineTo(pointAt(s.op, "to"), s.changes));
}

constexpr ScriptOpEntry kLineOperations[] = {
    {"line", runLine},
    {"line-to", runLineTo},
};

} // namespace

std::span<const ScriptOpEntry> lineOperations() {
    return kLineOperations;
}

Status applyBrushStabilizer(Brush& brush, const json& stabilizer) {
    try {
        Brush b = brush;
        if (stabilizer.is_boolean()) {
            b.stabilizer = stabilizer.get<bool>();
        } else if (stabilizer.is_object()) {
            for (const auto& [key, value] : stabilizer.items())
                stabilizerSetting(key).apply(value, b);
        } else {
            throw ScriptOpError{"\"stabilizer\" must be true, false or an object with \"on\", "
                                "\"length\", \"smoothing\" and \"catch_up\""};
        }
        brush = b;
    } catch (const ScriptOpError& e) {
        return Error{e.message, ErrorKind::BadInput};
    }
    return {};
}

json brushStabilizerJson(const Brush& brush) {
    return {{"on", brush.stabilizer},
            {"length", brush.stabilizerLength},
            {"smoothing", brush.stabilizerSmoothing},
            {"catch_up", brush.stabilizerCatchUp}};
}

} // namespace core
