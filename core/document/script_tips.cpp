// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/script_tips.h"

#include <algorithm>
#include <cmath>
#include <iterator>

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

/** "tip": a built-in name, the loaded image tip again, or an image file loaded through load. */
Status applyTipName(Brush& b, const json& value, const TipLoader& load) {
    if (!value.is_string() || value.get<std::string>().empty())
        return Error{"\"tip\" must be a built-in tip name or an image file"};
    const std::string tip = value.get<std::string>();
    if (isBuiltinTip(tip)) {
        b.tip = tip;
        return {};
    }
    if (tip == b.userTipName && b.userTip) {
        b.tip = std::string(kUserTip); // the loaded tip, again
        return {};
    }
    if (!load)
        return Error{tip + ": not a built-in tip, and image tips cannot be loaded here"};
    auto image = load(tip);
    if (!image)
        return image.takeError();
    b.tip = std::string(kUserTip);
    b.userTip = std::move(image).value();
    b.userTipName = tip;
    return {};
}

/** One key of "jitter": its range and the field it sets. */
struct JitterKey {
    const char* key;
    float lo, hi;
    float BrushJitter::*field;
};

constexpr JitterKey kJitterKeys[] = {
    {"size", 0.0f, 1.0f, &BrushJitter::size},
    {"opacity", 0.0f, 1.0f, &BrushJitter::opacity},
    {"angle", 0.0f, 180.0f, &BrushJitter::angle},
    {"scatter", 0.0f, 4.0f, &BrushJitter::scatter},
};

/** "jitter": an object with any of size, opacity, angle and scatter. */
Status applyJitter(BrushJitter& jitter, const json& j) {
    if (!j.is_object())
        return Error{"\"jitter\" must be an object {size, opacity, angle, scatter}"};
    for (const auto& item : j.items()) {
        const std::string& key = item.key();
        if (std::none_of(std::begin(kJitterKeys), std::end(kJitterKeys),
                         [&key](const JitterKey& k) { return key == k.key; }))
            return Error{"\"jitter\" has an unknown key \"" + key + "\""};
    }
    for (const JitterKey& k : kJitterKeys)
        if (Status s = readNumber(j, k.key, k.lo, k.hi, jitter.*k.field); !s)
            return s;
    return {};
}

} // namespace

Status applyBrushTip(Brush& brush, const json& op, const TipLoader& load) {
    Brush b = brush;
    if (op.contains("tip"))
        if (Status s = applyTipName(b, op["tip"], load); !s)
            return s;
    if (Status s = readNumber(op, "angle", -360.0f, 360.0f, b.angle); !s)
        return s;
    if (op.contains("angle_mode")) {
        if (!op["angle_mode"].is_string() ||
            !tipAngleModeFromName(op["angle_mode"].get<std::string>(), b.angleMode))
            return Error{"\"angle_mode\" must be \"fixed\", \"stroke\" or \"random\""};
    }
    if (op.contains("jitter"))
        if (Status s = applyJitter(b.jitter, op["jitter"]); !s)
            return s;
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
