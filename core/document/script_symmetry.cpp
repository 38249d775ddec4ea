// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/script_symmetry.h"

#include <string>

namespace core {

using nlohmann::json;

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
        bool ok = false;
        std::string want;
        if (key == "mirror") {
            ok = value.is_string() && symmetryMirrorFromName(value.get<std::string>(), s);
            want = "a string of the letters x, y and z, each at most once";
        } else if (key == "center") {
            ok = value.is_string() && symmetryCenterFromName(value.get<std::string>(), s.center);
            want = "\"bbox\" or \"origin\"";
        } else if (key == "radial") {
            ok = value.is_number_integer() && value.get<long long>() >= 1 &&
                 value.get<long long>() <= BrushSymmetry::kMaxRadial;
            if (ok)
                s.radial = int(value.get<long long>());
            want = "a whole number from 1 to " + std::to_string(BrushSymmetry::kMaxRadial);
        } else if (key == "axis") {
            ok = value.is_string() && symmetryAxisFromName(value.get<std::string>(), s.axis);
            want = "\"x\", \"y\" or \"z\"";
        } else {
            return Error{"unknown \"symmetry\" setting \"" + key + "\"", ErrorKind::BadInput};
        }
        if (!ok)
            return Error{"\"symmetry\" \"" + key + "\" must be " + want, ErrorKind::BadInput};
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
