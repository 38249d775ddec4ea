// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/script_tips.h"

#include <cmath>

namespace core {

namespace {

using nlohmann::json;

Status readNumber(const json& obj, const char* key, float lo, float hi, float& out) {
    if (!obj.contains(key))
        return {};
    const json& v = obj[key];
    if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() < lo ||
        v.get<double>() > hi)
        return Error{std::string("\"") + key + "\" must be a number from " +
                     std::to_string(int(lo)) + " to " + std::to_string(int(hi))};
    out = v.get<float>();
    return {};
}

} // namespace

Status applyBrushTip(Brush& brush, const json& op, const TipLoader& load) {
    Brush b = brush;
    if (op.contains("tip")) {
        if (!op["tip"].is_string() || op["tip"].get<std::string>().empty())
            return Error{"\"tip\" must be a built-in tip name or an image file"};
        const std::string tip = op["tip"].get<std::string>();
        if (isBuiltinTip(tip)) {
            b.tip = tip;
        } else if (tip == b.userTipName && b.userTip) {
            b.tip = std::string(kUserTip); // the loaded tip, again
        } else {
            if (!load)
                return Error{tip + ": not a built-in tip, and image tips cannot be loaded here"};
            auto image = load(tip);
            if (!image)
                return image.takeError();
            b.tip = std::string(kUserTip);
            b.userTip = std::move(image).value();
            b.userTipName = tip;
        }
    }
    if (Status s = readNumber(op, "angle", -360.0f, 360.0f, b.angle); !s)
        return s;
    if (op.contains("angle_mode")) {
        if (!op["angle_mode"].is_string() ||
            !tipAngleModeFromName(op["angle_mode"].get<std::string>(), b.angleMode))
            return Error{"\"angle_mode\" must be \"fixed\", \"stroke\" or \"random\""};
    }
    if (op.contains("jitter")) {
        const json& j = op["jitter"];
        if (!j.is_object())
            return Error{"\"jitter\" must be an object {size, opacity, angle, scatter}"};
        for (const auto& [key, value] : j.items())
            if (key != "size" && key != "opacity" && key != "angle" && key != "scatter")
                return Error{"\"jitter\" has an unknown key \"" + key + "\""};
        if (Status s = readNumber(j, "size", 0.0f, 1.0f, b.jitter.size); !s)
            return s;
        if (Status s = readNumber(j, "opacity", 0.0f, 1.0f, b.jitter.opacity); !s)
            return s;
        if (Status s = readNumber(j, "angle", 0.0f, 180.0f, b.jitter.angle); !s)
            return s;
        if (Status s = readNumber(j, "scatter", 0.0f, 4.0f, b.jitter.scatter); !s)
            return s;
    }
    if (op.contains("seed")) {
        if (!op["seed"].is_number_unsigned() || op["seed"].get<std::uint64_t>() > 0xFFFFFFFFull)
            return Error{"\"seed\" must be a whole number from 0 to 4294967295"};
        b.seed = op["seed"].get<std::uint32_t>();
    }
    brush = std::move(b);
    return {};
}

void addBrushTipJson(const Brush& brush, json& op) {
    op["tip"] = brush.tip == kUserTip ? brush.userTipName : brush.tip;
    op["angle"] = brush.angle;
    op["angle_mode"] = tipAngleModeName(brush.angleMode);
    op["jitter"] = {{"size", brush.jitter.size},
                    {"opacity", brush.jitter.opacity},
                    {"angle", brush.jitter.angle},
                    {"scatter", brush.jitter.scatter}};
    op["seed"] = brush.seed;
}

} // namespace core
