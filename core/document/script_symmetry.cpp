// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/script_symmetry.h"

#include <string>
#include <string_view>

namespace core {

using nlohmann::json;

namespace {

/** One setting of a "symmetry" object: read into s (false if value is not one), and what it must
 * be. */
struct SymmetrySetting {
    std::string_view key;
    bool (*read)(const json& value, BrushSymmetry& s);
    std::string (*want)();
};

constexpr SymmetrySetting kSymmetrySettings[] = {
    {"mirror",
     [](const json& value, BrushSymmetry& s) {
         return value.is_string() && symmetryMirrorFromName(value.get<std::string>(), s);
     },
     [] { return std::string("a string of the letters x, y and z, each at most once"); }},
    {"center",
     [](const json& value, BrushSymmetry& s) {
         return value.is_string() && symmetryCenterFromName(value.get<std::string>(), s.center);
     },
     [] { return std::string("\"bbox\" or \"origin\""); }},
    {"radial",
     [](const json& value, BrushSymmetry& s) {
         const bool ok = value.is_number_integer() && value.get<long long>() >= 1 &&
                         value.get<long long>() <= BrushSymmetry::kMaxRadial;
         if (ok)
             s.radial = int(value.get<long long>());
         return ok;
     },
     [] { return "a whole number from 1 to " + std::to_string(BrushSymmetry::kMaxRadial); }},
    {"axis",
     [](const json& value, BrushSymmetry& s) {
         return value.is_string() && symmetryAxisFromName(value.get<std::string>(), s.axis);
     },
     [] { return std::string("\"x\", \"y\" or \"z\""); }},
};

const SymmetrySetting* symmetrySetting(const std::string& key) {
    for (const SymmetrySetting& setting : kSymmetrySettings)
        if (setting.key == key)
            return &setting;
    return nullptr;
}

} // namespace

Status applyBrushSymmetry(Brush& brush, const json& symmetry) {
    BrushSymmetry s = brush.symmetry;
    if (symmetry.is_boolean() && !symmetry.get<bool>()) {
        brush.symmetry = BrushSymmetry{};
        return {};
    }
    if (!symmetry.is_object())
        return Error{"\"symmetry\" must be false or an object with \"mirror\", \"center\", "
                     "\"radial\" and \"axis\"",
                     ErrorKind::BadInput};
    for (const auto& [key, value] : symmetry.items()) {
        const SymmetrySetting* setting = symmetrySetting(key);
        if (!setting)
            return Error{"unknown \"symmetry\" setting \"" + key + "\"", ErrorKind::BadInput};
        if (!setting->read(value, s))
            return Error{"\"symmetry\" \"" + key + "\" must be " + setting->want(),
                         ErrorKind::BadInput};
    }
    brush.symmetry = s;
    return {};
}

json brushSymmetryJson(const Brush& brush) {
    const BrushSymmetry& s = brush.symmetry;
    return {{"mirror", symmetryMirrorName(s)},
            {"center", symmetryCenterName(s.center)},
            {"radial", s.radial},
            {"axis", symmetryAxisName(s.axis)}};
}

} // namespace core
