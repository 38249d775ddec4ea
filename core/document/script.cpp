// SPDX-License-Identifier: GPL-3.0-or-later
// Scripts: the operations a user performs, as JSON, replayed through the Document. Every value
// is checked before use; an error names the operation and the problem.
#include "core/document/script.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <vector>

#include "core/base/color.h"
#include "core/document/document.h"
#include "core/document/project_state.h"
#include "core/document/script_paint_layers.h"
#include "core/document/script_stroke.h"
#include "core/document/script_symmetry.h"
#include "core/document/script_tips.h"
#include "core/paint/targets/flood_fill.h"

namespace core {

namespace {
using nlohmann::json;

/** A problem with one operation; the runner adds the operation's number. */
struct OpError {
    std::string message;
};

float number(const json& op, const char* key, float fallback, float lo, float hi) {
    if (!op.contains(key))
        return fallback;
    if (!op[key].is_number())
        throw OpError{std::string("\"") + key + "\" must be a number"};
    const double v = op[key].get<double>();
    if (!std::isfinite(v) || v < lo || v > hi)
        throw OpError{std::string("\"") + key + "\" must be between " + std::to_string(lo) +
                      " and " + std::to_string(hi)};
    return float(v);
}

bool boolean(const json& op, const char* key, bool fallback) {
    if (!op.contains(key))
        return fallback;
    if (!op[key].is_boolean())
        throw OpError{std::string("\"") + key + "\" must be true or false"};
    return op[key].get<bool>();
}

/** "#rrggbb", "#rrggbbaa" or [r, g, b(, a)] in sRGB 0..1, to linear RGBA. */
glm::vec4 color(const json& value) {
    glm::vec4 c(1.0f);
    if (value.is_string()) {
        const std::string s = value.get<std::string>();
        unsigned r = 0, g = 0, b = 0, a = 255;
        const bool ok =
            (s.size() == 7 && std::sscanf(s.c_str(), "#%2x%2x%2x", &r, &g, &b) == 3) ||
            (s.size() == 9 && std::sscanf(s.c_str(), "#%2x%2x%2x%2x", &r, &g, &b, &a) == 4);
        if (!ok)
            throw OpError{"\"color\" must be #rrggbb or #rrggbbaa"};
        c = glm::vec4(float(r), float(g), float(b), float(a)) / 255.0f;
    } else if (value.is_array() && (value.size() == 3 || value.size() == 4)) {
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (!value[i].is_number() || !(value[i].get<double>() >= 0.0) ||
                !(value[i].get<double>() <= 1.0))
                throw OpError{"\"color\" entries must be numbers from 0 to 1"};
            c[int(i)] = value[i].get<float>();
        }
    } else {
        throw OpError{"\"color\" must be #rrggbb or [r, g, b] (sRGB, 0 to 1)"};
    }
    return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b), c.a};
}

/** An [x, y] pixel of the view (origin top-left). */
glm::vec2 pixelAt(const json& value, const char* what) {
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
        throw OpError{std::string("\"") + what + "\" must be [x, y] (pixels from the top-left)"};
    const glm::vec2 p(value[0].get<float>(), value[1].get<float>());
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw OpError{std::string("\"") + what + "\" must be finite"};
    return p;
}

std::vector<glm::vec2> pixels(const json& op, const char* key) {
    if (!op.contains(key) || !op[key].is_array() || op[key].empty())
        throw OpError{std::string("\"") + key + "\" must be a non-empty array of [x, y]"};
    std::vector<glm::vec2> points;
    for (const json& p : op[key])
        points.push_back(pixelAt(p, key));
    return points;
}

std::vector<StrokePoint> strokePoints(const json& op) {
    if (!op.contains("points") || !op["points"].is_array() || op["points"].empty())
        throw OpError{"\"points\" must be a non-empty array of [x, y] or [x, y, pressure]"};
    std::vector<StrokePoint> points;
    for (const json& p : op["points"]) {
        if (!p.is_array() || p.size() < 2 || p.size() > 3 || !p[0].is_number() ||
            !p[1].is_number() || (p.size() == 3 && !p[2].is_number()))
            throw OpError{"each point must be [x, y] or [x, y, pressure]"};
        StrokePoint point;
        point.position = {p[0].get<float>(), p[1].get<float>()};
        point.pressure = p.size() == 3 ? p[2].get<float>() : 1.0f;
        if (!std::isfinite(point.position.x) || !std::isfinite(point.position.y) ||
            !(point.pressure >= 0.0f && point.pressure <= 1.0f))
            throw OpError{"a point is not finite or its pressure is outside 0..1"};
        points.push_back(point);
    }
    return points;
}

Result<PaintTargetOptions> targetOptions(const json& t) {
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
    return options;
}

/** A camera pose as the project files write it (target, yaw, pitch, distance, fov_y, ...). */
Camera cameraPose(const json& value, Camera camera) {
    if (!value.is_object())
        throw OpError{"\"camera\" must be an object"};
    if (value.contains("target")) {
        const json& t = value["target"];
        if (!t.is_array() || t.size() != 3 || !t[0].is_number() || !t[1].is_number() ||
            !t[2].is_number())
            throw OpError{"\"target\" must be [x, y, z]"};
        camera.target = {t[0].get<float>(), t[1].get<float>(), t[2].get<float>()};
        if (!std::isfinite(camera.target.x) || !std::isfinite(camera.target.y) ||
            !std::isfinite(camera.target.z))
            throw OpError{"\"target\" must be finite"};
    }
    camera.yawDegrees = number(value, "yaw", camera.yawDegrees, -1e6f, 1e6f);
    camera.pitchDegrees = number(value, "pitch", camera.pitchDegrees, -90.0f, 90.0f);
    camera.distance = number(value, "distance", camera.distance, 1e-9f, 1e30f);
    camera.fovYDegrees = number(value, "fov_y", camera.fovYDegrees, 1.0f, 170.0f);
    camera.orthographic = boolean(value, "orthographic", camera.orthographic);
    return camera;
}

/** A column-major 4x4 matrix of 16 finite numbers. */
glm::mat4 matrix(const json& op, const char* key) {
    const json& v = op.contains(key) ? op[key] : json();
    if (!v.is_array() || v.size() != 16)
        throw OpError{std::string("\"") + key + "\" must be an array of 16 numbers"};
    glm::mat4 m(1.0f);
    for (int i = 0; i < 16; ++i) {
        const json& x = v[std::size_t(i)];
        if (!x.is_number() || !std::isfinite(x.get<double>()))
            throw OpError{std::string("\"") + key + "\" has an entry that is not a finite number"};
        m[i / 4][i % 4] = x.get<float>();
    }
    return m;
}

} // namespace

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
        Result<PaintTargetOptions> target = targetOptions(value["target"]);
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

ScriptRunner::ScriptRunner(Document& doc, ScriptHost& host, const View& view)
    : m_doc(doc), m_host(host), m_view(view) {}

Status ScriptRunner::ensureDepthLayers() {
    if (m_doc.depthLayers())
        return {};
    return m_host.buildDepthLayers(m_doc, m_view);
}

void ScriptRunner::setView(const View& view) {
    m_view = view;
    m_doc.clearDepthLayers();
    m_host.viewChanged(m_view);
}

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

Status ScriptRunner::run(const json& op) {
    const std::size_t index = ++m_count;
    const auto need = [this] {
        if (Status s = ensureDepthLayers(); !s)
            throw OpError{s.error()};
    };
    PaintChanges changes; // the caller refreshes its own copy of the target
    try {
        if (!op.is_object() || !op.contains("op") || !op["op"].is_string())
            throw OpError{"an operation must be an object with an \"op\" name"};
        const std::string name = op["op"].get<std::string>();
        if (name == "set-mode") {
            m_doc.setLayerAware(boolean(op, "layer_aware", m_doc.layerAware()));
            m_doc.setAutoPopUp(boolean(op, "auto_pop_up", m_doc.autoPopUp()));
        } else if (name == "set-brush") {
            Brush b = m_doc.brush();
            // The channels first: a colour given beside them is the base colour's value.
            if (op.contains("channels"))
                if (Status st = applyBrushChannels(b, op["channels"]); !st)
                    throw OpError{st.error()};
            if (op.contains("color"))
                b.color = color(op["color"]);
            if (op.contains("color_linear")) {
                const json& c = op["color_linear"];
                if (!c.is_array() || c.size() != 4)
                    throw OpError{"\"color_linear\" must be [r, g, b, a] (linear, 0 to 1)"};
                for (int k = 0; k < 4; ++k) {
                    if (!c[std::size_t(k)].is_number() ||
                        !(c[std::size_t(k)].get<double>() >= 0.0) ||
                        !(c[std::size_t(k)].get<double>() <= 1.0))
                        throw OpError{"\"color_linear\" entries must be numbers from 0 to 1"};
                    b.color[k] = c[std::size_t(k)].get<float>();
                }
            }
            b.radius = number(op, "radius", b.radius, 0.5f, 2048.0f);
            b.hardness = number(op, "hardness", b.hardness, 0.0f, 1.0f);
            b.opacity = number(op, "opacity", b.opacity, 0.0f, 1.0f);
            b.flow = number(op, "flow", b.flow, 0.0f, 1.0f);
            b.spacing = number(op, "spacing", b.spacing, 0.01f, 4.0f);
            b.trackRadius = number(op, "track_radius", b.trackRadius, 0.0f, 1e5f);
            b.eraser = boolean(op, "eraser", b.eraser);
            b.pressureRadius = boolean(op, "pressure_radius", b.pressureRadius);
            b.pressureOpacity = boolean(op, "pressure_opacity", b.pressureOpacity);
            if (op.contains("stabilizer"))
                if (Status st = applyBrushStabilizer(b, op["stabilizer"]); !st)
                    throw OpError{st.error()};
            if (op.contains("symmetry"))
                if (Status st = applyBrushSymmetry(b, op["symmetry"]); !st)
                    throw OpError{st.error()};
            if (Status st = applyBrushTip(
                    b, op, [this](const std::string& path) { return m_host.loadTip(path); });
                !st)
                throw OpError{st.error()};
            PressureCurve curve = m_doc.pressureCurve();
            curve.gamma = number(op, "pressure_curve", curve.gamma, PressureCurve::kMinGamma,
                                 PressureCurve::kMaxGamma);
            m_doc.brush() = b;
            m_doc.setPressureCurve(curve);
        } else if (name == "set-target") {
            Result<PaintTargetOptions> options = targetOptions(op);
            if (!options)
                throw OpError{options.error()};
            if (Status s = m_doc.setPaintTarget(*options); !s)
                throw OpError{s.error()};
        } else if (name == "show-layer") {
            // The Single Layer view: strokes, fills, picks and pop-ups use that depth layer's
            // fragments; 0 shows every layer.
            if (!op.contains("layer") || !op["layer"].is_number_unsigned() ||
                op["layer"].get<std::uint64_t>() > 4096)
                throw OpError{"\"layer\" must be a depth layer number (0 for all layers)"};
            m_doc.setShownLayer(op["layer"].get<std::uint32_t>());
        } else if (name == "set-segmentation") {
            DepthLayerOptions options = m_doc.depthLayerOptions();
            options.threshold = number(op, "threshold", options.threshold, 1e-6f, 1.0f);
            if (op.contains("test")) {
                if (op["test"] == "plain")
                    options.test = ConnectionTest::Plain;
                else if (op["test"] == "surface")
                    options.test = ConnectionTest::Surface;
                else
                    throw OpError{"\"test\" must be \"plain\" or \"surface\""};
            }
            options.cullBackFaces = !boolean(op, "two_sided", !options.cullBackFaces);
            m_doc.setDepthLayerOptions(options);
        } else if (name == "stroke") {
            const std::vector<StrokePoint> points = strokePoints(op);
            need();
            if (Status s = m_doc.beginStroke(points.front(), changes); !s)
                throw OpError{s.error()};
            for (std::size_t k = 1; k < points.size(); ++k)
                m_doc.moveStroke(points[k], changes);
            m_doc.endStroke();
        } else if (name == "fill") {
            const glm::vec2 at = pixelAt(op.value("at", json()), "at");
            FillMode mode = FillMode::Region;
            if (op.contains("mode")) {
                const auto parsed = op["mode"].is_string()
                                        ? parseFillMode(op["mode"].get<std::string>())
                                        : std::nullopt;
                if (!parsed)
                    throw OpError{"\"mode\" must be \"region\", \"surface\" or \"color\""};
                mode = *parsed;
            }
            const float tolerance = number(op, "tolerance", 0.1f, 0.0f, 1.0f);
            need();
            if (Status s = m_doc.fill(at, mode, tolerance, changes); !s)
                throw OpError{s.error()};
        } else if (name == "pick") {
            // The eyedropper: the brush takes the surface colour of the visible fragment.
            const glm::vec2 at = pixelAt(op.value("at", json()), "at");
            need();
            const DepthStack& stack = m_doc.depthLayers()->stack;
            if (!(at.x >= 0.0f && at.y >= 0.0f && at.x < float(stack.width) &&
                  at.y < float(stack.height)))
                throw OpError{"pick position " + op["at"].dump() + " is outside the view"};
            const std::size_t pixel =
                std::size_t(at.y) * std::size_t(stack.width) + std::size_t(at.x);
            const std::optional<glm::vec4> picked = m_doc.pickColor(pixel);
            if (!picked)
                throw OpError{"nothing to pick at " + op["at"].dump() +
                              ": no surface is visible there"};
            m_doc.brush().color = *picked;
        } else if (name == "undo") {
            m_doc.undo(changes);
        } else if (name == "redo") {
            m_doc.redo(changes);
        } else if (name == "orbit") {
            if (!op.contains("orbit") || !op["orbit"].is_string())
                throw OpError{"\"orbit\" must be a string yaw,pitch,distance"};
            Result<Camera> camera =
                parseOrbitCamera(op["orbit"].get<std::string>(), m_doc.mesh().bounds());
            if (!camera)
                throw OpError{camera.error()};
            m_doc.camera() = *camera; // a project keeps the last orbit view
            setView(camera->view(m_view.width, m_view.height));
        } else if (name == "view") {
            // The exact view of a recorded session: its size and camera pose.
            int width = m_view.width, height = m_view.height;
            if (op.contains("size")) {
                Result<std::pair<int, int>> size =
                    op["size"].is_string()
                        ? parseViewSize(op["size"].get<std::string>())
                        : Result<std::pair<int, int>>(Error{"\"size\" must be a string WxH"});
                if (!size)
                    throw OpError{size.error()};
                std::tie(width, height) = *size;
            }
            m_doc.camera() = cameraPose(op.value("camera", json::object()), m_doc.camera());
            View view = m_doc.camera().view(width, height);
            if (op.contains("view") || op.contains("proj")) {
                view.view = matrix(op, "view");
                view.proj = matrix(op, "proj");
            }
            setView(view);
        } else if (name == "build-layers") {
            m_doc.clearDepthLayers();
            need();
        } else if (name == "popup") {
            // The paper's intentional pop-up: a click at a pixel (cycling on repeats), or a
            // region of the region graph.
            need();
            if (op.contains("region")) {
                if (!op["region"].is_number_unsigned() ||
                    !m_doc.popUpRegion(op["region"].get<std::uint32_t>()))
                    throw OpError{"\"region\" must be a region id of this view"};
            } else {
                const glm::vec2 at = pixelAt(op.value("at", json()), "at");
                if (m_doc.popUpAt(at) == kNone)
                    throw OpError{"nothing to pop up at [" + std::to_string(int(at.x)) + ", " +
                                  std::to_string(int(at.y)) + "]"};
            }
        } else if (name == "hide") {
            // Paint-to-hide with a brush of radius pixels, in the order of the op's start (what
            // one op reveals, it does not hide): at each point of "at", or along "path".
            const bool path = op.contains("path");
            const std::vector<glm::vec2> points = pixels(op, path ? "path" : "at");
            const float radius = number(op, "radius", 0.0f, 0.0f, 4096.0f);
            need();
            m_doc.beginHide();
            for (std::size_t k = 0; k < points.size(); ++k)
                m_doc.hideAlong(path && k > 0 ? points[k - 1] : points[k], points[k], radius);
            m_doc.endHide();
        } else if (name == "unhide") {
            if (!op.contains("regions") || !op["regions"].is_array())
                throw OpError{"\"regions\" must be an array of region ids"};
            std::vector<std::uint32_t> regions;
            for (const json& r : op["regions"]) {
                if (!r.is_number_unsigned() || r.get<std::uint64_t>() > kNone)
                    throw OpError{"\"regions\" must be an array of region ids"};
                regions.push_back(r.get<std::uint32_t>());
            }
            need();
            m_doc.unhideRegions(regions);
        } else if (name == "unhide-all") {
            need();
            m_doc.unhideAll();
        } else if (name == "reset-order") {
            need();
            m_doc.resetRegionOrder();
        } else if (name == "orbit-about") {
            // Layer-aware rotation about the visible surface point at a pixel.
            const glm::vec2 at = pixelAt(op.value("at", json()), "at");
            const float yaw = number(op, "yaw", 0.0f, -3600.0f, 3600.0f);
            const float pitch = number(op, "pitch", 0.0f, -3600.0f, 3600.0f);
            need();
            const std::optional<glm::vec3> pivot = m_doc.surfacePoint(at);
            if (!pivot)
                throw OpError{"no surface to orbit about at [" + std::to_string(int(at.x)) + ", " +
                              std::to_string(int(at.y)) + "]"};
            setView(m_view.orbitedAbout(*pivot, yaw, pitch));
        } else if (isLineOperation(name)) {
            need();
            if (const std::optional<Status> lineOp = runLineOperation(m_doc, name, op); !*lineOp)
                throw OpError{lineOp->error()};
        } else if (const std::optional<Status> paintLayerOp =
                       runPaintLayerOperation(m_doc, name, op)) {
            if (!*paintLayerOp)
                throw OpError{paintLayerOp->error()};
        } else {
            throw OpError{"unknown operation \"" + name + "\""};
        }
    } catch (const OpError& e) {
        return Error{"operation " + std::to_string(index) + ": " + e.message, ErrorKind::BadInput};
    }
    return {};
}

} // namespace core
