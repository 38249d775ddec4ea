// SPDX-License-Identifier: GPL-3.0-or-later
// Scripts: the operations a user performs, as JSON, replayed through the Document. Every value
// is checked before use; an error names the operation and the problem.
#include "core/document/script.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <span>
#include <string_view>
#include <unordered_map>

#include "core/document/document.h"
#include "core/document/script_ops.h"
#include "core/document/script_paint_layers.h"
#include "core/document/script_stroke.h"
#include "core/document/script_symmetry.h"
#include "core/document/script_tips.h"

namespace core {

using nlohmann::json;

Result<PaintTargetOptions> targetOptionsFromJson(const json& t) {
    if (!t.is_object())
        return Error{"\"target\" must be an object with \"kind\" and \"resolution\""};
    PaintTargetOptions options;
    if (t.contains("kind")) {
        if (t["kind"] == "vertex-colors")
            options.kind = PaintTargetKind::VertexColors;
        else if (t["kind"] == "texture")
            options.kind = PaintTargetKind::Texture;
        else if (t["kind"] != "auto")
            return Error{"\"kind\" must be \"texture\", \"vertex-colors\" or \"auto\""};
    }
    if (t.contains("resolution")) {
        if (!t["resolution"].is_number_integer() || t["resolution"].get<long long>() < 1 ||
            t["resolution"].get<long long>() > 16384)
            return Error{"\"resolution\" must be a whole number from 1 to 16384"};
        options.resolution = t["resolution"].get<int>();
    }
    if (t.contains("automatic_uvs")) {
        if (!t["automatic_uvs"].is_boolean())
            return Error{"\"automatic_uvs\" must be true or false"};
        options.automaticUvs = t["automatic_uvs"].get<bool>();
    }
    return options;
}

Result<Script> parseScript(const json& value) {
    Script script;
    if (value.is_array()) {
        script.operations = value;
        return script;
    }
    if (!value.is_object())
        return Error{"expected an array of operations or an object"};
    if (!value.contains("operations") || !value["operations"].is_array())
        return Error{"expected an \"operations\" array"};
    script.operations = value["operations"];
    if (value.contains("size")) {
        if (!value["size"].is_string())
            return Error{"\"size\" must be a string WIDTHxHEIGHT"};
        script.size = value["size"].get<std::string>();
    }
    if (value.contains("orbit")) {
        if (!value["orbit"].is_string())
            return Error{"\"orbit\" must be a string yaw,pitch,distance"};
        script.orbit = value["orbit"].get<std::string>();
    }
    if (value.contains("target")) {
        Result<PaintTargetOptions> target = targetOptionsFromJson(value["target"]);
        if (!target)
            return target.takeError();
        script.target = *target;
    }
    return script;
}

Result<Script> readScript(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return Error{path + ": cannot be opened"};
    const json value = json::parse(in, nullptr, false);
    if (value.is_discarded())
        return Error{path + ": not valid JSON"};
    Result<Script> script = parseScript(value);
    if (!script)
        return Error{path + ": " + script.error(), script.errorKind()};
    return script;
}

json scriptToJson(const Script& script) {
    json j = json::object();
    if (script.size)
        j["size"] = *script.size;
    if (script.orbit)
        j["orbit"] = *script.orbit;
    if (script.target) {
        const PaintTargetOptions& t = *script.target;
        j["target"] = {{"kind", !t.kind                                    ? "auto"
                                : *t.kind == PaintTargetKind::VertexColors ? "vertex-colors"
                                                                           : "texture"},
                       {"resolution", t.resolution}};
        if (t.automaticUvs)
            j["target"]["automatic_uvs"] = true;
    }
    j["operations"] = script.operations;
    return j;
}

Result<std::pair<int, int>> parseViewSize(const std::string& size) {
    int width = 0, height = 0;
    char x = 0, extra = 0;
    if (std::sscanf(size.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 ||
        (x != 'x' && x != 'X') || width <= 0 || height <= 0 || width > 16384 || height > 16384)
        return Error{size + ": expected WIDTHxHEIGHT, each 1 to 16384"};
    return std::pair{width, height};
}

Result<Camera> parseOrbitCamera(const std::string& orbit, const Bounds& bounds) {
    float yaw = 0, pitch = 0, distance = 0;
    char c1 = 0, c2 = 0, end = 0;
    if (std::sscanf(orbit.c_str(), "%f%c%f%c%f%c", &yaw, &c1, &pitch, &c2, &distance, &end) != 5 ||
        c1 != ',' || c2 != ',' || !(distance > 0.0f) || !std::isfinite(yaw) ||
        !std::isfinite(pitch) || !std::isfinite(distance))
        return Error{orbit + ": expected yaw,pitch,distance (degrees, unit-cube units > 0)"};
    return Camera::fromOrbit(bounds, yaw, pitch, distance);
}

json setBrushOperation(const Brush& b, const PressureCurve& curve) {
    json op = {{"op", "set-brush"},
               {"color_linear", {b.color.r, b.color.g, b.color.b, b.color.a}},
               {"radius", b.radius},
               {"hardness", b.hardness},
               {"opacity", b.opacity},
               {"flow", b.flow},
               {"spacing", b.spacing},
               {"track_radius", b.trackRadius},
               {"eraser", b.eraser},
               {"pressure_radius", b.pressureRadius},
               {"pressure_opacity", b.pressureOpacity},
               {"pressure_curve", curve.gamma},
               {"channels", brushChannelsJson(b)},
               {"stabilizer", brushStabilizerJson(b)},
               {"symmetry", brushSymmetryJson(b)}};
    addBrushTipJson(b, op);
    return op;
}

json viewOperation(const Camera& c, const View& view) {
    json op = {{"op", "view"},
               {"size", std::to_string(view.width) + "x" + std::to_string(view.height)},
               {"camera",
                {{"target", {c.target.x, c.target.y, c.target.z}},
                 {"yaw", c.yawDegrees},
                 {"pitch", c.pitchDegrees},
                 {"distance", c.distance},
                 {"fov_y", c.fovYDegrees},
                 {"orthographic", c.orthographic}}}};
    const View own = c.view(view.width, view.height);
    if (own.view != view.view || own.proj != view.proj) {
        const auto matrix = [](const glm::mat4& m) {
            json values = json::array();
            for (int col = 0; col < 4; ++col)
                for (int row = 0; row < 4; ++row)
                    values.push_back(m[col][row]);
            return values;
        };
        op["view"] = matrix(view.view);
        op["proj"] = matrix(view.proj);
    }
    return op;
}

void ScriptOp::needDepthLayers() {
    if (doc.depthLayers())
        return;
    throwIfError(host.buildDepthLayers(doc, view));
}

void ScriptOp::setView(const View& newView) {
    view = newView;
    doc.clearDepthLayers();
    host.viewChanged(view);
}

namespace {

/** Every operation's handler by its name, from the lists of script_ops.h. */
const std::unordered_map<std::string_view, ScriptOpHandler>& operationTable() {
    static const std::unordered_map<std::string_view, ScriptOpHandler> table = [] {
        std::unordered_map<std::string_view, ScriptOpHandler> byName;
        for (const std::span<const ScriptOpEntry> list :
             {documentOperations(), lineOperations(), paintLayerOperations()})
            for (const ScriptOpEntry& entry : list)
                byName.emplace(entry.name, entry.run);
        return byName;
    }();
    return table;
}

/** The handler of operation's "op"; throws if operation has no name or the name is unknown. */
ScriptOpHandler handlerOf(const json& operation) {
    if (!operation.is_object() || !operation.contains("op") || !operation["op"].is_string())
        throw ScriptOpError{"an operation must be an object with an \"op\" name"};
    const std::string& name = operation["op"].get_ref<const std::string&>();
    const auto found = operationTable().find(name);
    if (found == operationTable().end())
        throw ScriptOpError{"unknown operation \"" + name + "\""};
    return found->second;
}

} // namespace

ScriptRunner::ScriptRunner(Document& doc, ScriptHost& host, const View& view)
    : m_doc(doc), m_host(host), m_view(view) {}

Status ScriptRunner::runAll(const Script& script, const ProgressFn& progress) {
    const std::size_t n = script.operations.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (!reportProgress(progress, double(i) / double(n)))
            return Error{"cancelled", ErrorKind::Cancelled};
        if (Status s = run(script.operations[i]); !s)
            return s;
    }
    reportProgress(progress, 1.0);
    return {};
}

Status ScriptRunner::run(const json& operation) {
    const std::size_t index = ++m_count;
    try {
        ScriptOp op{operation, m_doc, m_host, m_view, {}};
        handlerOf(operation)(op);
    } catch (const ScriptOpError& e) {
        return Error{"operation " + std::to_string(index) + ": " + e.message, ErrorKind::BadInput};
    }
    return {};
}

} // namespace core
