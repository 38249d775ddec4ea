// SPDX-License-Identifier: GPL-3.0-or-later
// The document's own script operations, one handler each: settings, painting, the camera and
// the regions. Every value is checked before use; an error says what is wrong with the operation.
#include "core/document/script_ops.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "core/base/color.h"
#include "core/document/document.h"
#include "core/document/script.h"
#include "core/document/script_paint_layers.h"
#include "core/document/script_stroke.h"
#include "core/document/script_symmetry.h"
#include "core/document/script_tips.h"
#include "core/paint/targets/flood_fill.h"

namespace core {

namespace {
using nlohmann::json;

float number(const json& op, const char* key, float fallback, float lo, float hi) {
    if (!op.contains(key))
        return fallback;
    if (!op[key].is_number())
        throw ScriptOpError{std::string("\"") + key + "\" must be a number"};
    const double v = op[key].get<double>();
    if (!std::isfinite(v) || v < lo || v > hi)
        throw ScriptOpError{std::string("\"") + key + "\" must be between " + std::to_string(lo) +
                            " and " + std::to_string(hi)};
    return float(v);
}

bool boolean(const json& op, const char* key, bool fallback) {
    if (!op.contains(key))
        return fallback;
    if (!op[key].is_boolean())
        throw ScriptOpError{std::string("\"") + key + "\" must be true or false"};
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
            throw ScriptOpError{"\"color\" must be #rrggbb or #rrggbbaa"};
        c = glm::vec4(float(r), float(g), float(b), float(a)) / 255.0f;
    } else if (value.is_array() && (value.size() == 3 || value.size() == 4)) {
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (!value[i].is_number() || !(value[i].get<double>() >= 0.0) ||
                !(value[i].get<double>() <= 1.0))
                throw ScriptOpError{"\"color\" entries must be numbers from 0 to 1"};
            c[int(i)] = value[i].get<float>();
        }
    } else {
        throw ScriptOpError{"\"color\" must be #rrggbb or [r, g, b] (sRGB, 0 to 1)"};
    }
    return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b), c.a};
}

/** "color_linear": [r, g, b, a], linear, each 0 to 1. */
glm::vec4 linearColor(const json& c) {
    if (!c.is_array() || c.size() != 4)
        throw ScriptOpError{"\"color_linear\" must be [r, g, b, a] (linear, 0 to 1)"};
    glm::vec4 out(0.0f);
    for (int k = 0; k < 4; ++k) {
        if (!c[std::size_t(k)].is_number() || !(c[std::size_t(k)].get<double>() >= 0.0) ||
            !(c[std::size_t(k)].get<double>() <= 1.0))
            throw ScriptOpError{"\"color_linear\" entries must be numbers from 0 to 1"};
        out[k] = c[std::size_t(k)].get<float>();
    }
    return out;
}

/** An [x, y] pixel of the view (origin top-left). */
glm::vec2 pixelAt(const json& value, const char* what) {
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
        throw ScriptOpError{std::string("\"") + what +
                            "\" must be [x, y] (pixels from the top-left)"};
    const glm::vec2 p(value[0].get<float>(), value[1].get<float>());
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw ScriptOpError{std::string("\"") + what + "\" must be finite"};
    return p;
}

std::vector<glm::vec2> pixels(const json& op, const char* key) {
    if (!op.contains(key) || !op[key].is_array() || op[key].empty())
        throw ScriptOpError{std::string("\"") + key + "\" must be a non-empty array of [x, y]"};
    std::vector<glm::vec2> points;
    for (const json& p : op[key])
        points.push_back(pixelAt(p, key));
    return points;
}

std::vector<StrokePoint> strokePoints(const json& op) {
    if (!op.contains("points") || !op["points"].is_array() || op["points"].empty())
        throw ScriptOpError{"\"points\" must be a non-empty array of [x, y] or [x, y, pressure]"};
    std::vector<StrokePoint> points;
    for (const json& p : op["points"]) {
        if (!p.is_array() || p.size() < 2 || p.size() > 3 || !p[0].is_number() ||
            !p[1].is_number() || (p.size() == 3 && !p[2].is_number()))
            throw ScriptOpError{"each point must be [x, y] or [x, y, pressure]"};
        StrokePoint point;
        point.position = {p[0].get<float>(), p[1].get<float>()};
        point.pressure = p.size() == 3 ? p[2].get<float>() : 1.0f;
        if (!std::isfinite(point.position.x) || !std::isfinite(point.position.y) ||
            !(point.pressure >= 0.0f && point.pressure <= 1.0f))
            throw ScriptOpError{"a point is not finite or its pressure is outside 0..1"};
        points.push_back(point);
    }
    return points;
}

/** A camera pose as the project files write it (target, yaw, pitch, distance, fov_y, ...). */
Camera cameraPose(const json& value, Camera camera) {
    if (!value.is_object())
        throw ScriptOpError{"\"camera\" must be an object"};
    if (value.contains("target")) {
        const json& t = value["target"];
        if (!t.is_array() || t.size() != 3 || !t[0].is_number() || !t[1].is_number() ||
            !t[2].is_number())
            throw ScriptOpError{"\"target\" must be [x, y, z]"};
        camera.target = {t[0].get<float>(), t[1].get<float>(), t[2].get<float>()};
        if (!std::isfinite(camera.target.x) || !std::isfinite(camera.target.y) ||
            !std::isfinite(camera.target.z))
            throw ScriptOpError{"\"target\" must be finite"};
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
        throw ScriptOpError{std::string("\"") + key + "\" must be an array of 16 numbers"};
    glm::mat4 m(1.0f);
    for (int i = 0; i < 16; ++i) {
        const json& x = v[std::size_t(i)];
        if (!x.is_number() || !std::isfinite(x.get<double>()))
            throw ScriptOpError{std::string("\"") + key +
                                "\" has an entry that is not a finite number"};
        m[i / 4][i % 4] = x.get<float>();
    }
    return m;
}

// Settings.

void runSetMode(ScriptOp& s) {
    s.doc.setLayerAware(boolean(s.op, "layer_aware", s.doc.layerAware()));
    s.doc.setAutoPopUp(boolean(s.op, "auto_pop_up", s.doc.autoPopUp()));
}

/** set-brush's numbers and switches (radius ... pressure_opacity) applied to b. */
void applyBrushNumbers(const json& op, Brush& b) {
    b.radius = number(op, "radius", b.radius, 0.5f, 2048.0f);
    b.hardness = number(op, "hardness", b.hardness, 0.0f, 1.0f);
    b.opacity = number(op, "opacity", b.opacity, 0.0f, 1.0f);
    b.flow = number(op, "flow", b.flow, 0.0f, 1.0f);
    b.spacing = number(op, "spacing", b.spacing, 0.01f, 4.0f);
    b.trackRadius = number(op, "track_radius", b.trackRadius, 0.0f, 1e5f);
    b.eraser = boolean(op, "eraser", b.eraser);
    b.pressureRadius = boolean(op, "pressure_radius", b.pressureRadius);
    b.pressureOpacity = boolean(op, "pressure_opacity", b.pressureOpacity);
}

void runSetBrush(ScriptOp& s) {
    const json& op = s.op;
    Brush b = s.doc.brush();
    // The channels first: a colour given beside them is the base colour's value.
    if (op.contains("channels"))
        throwIfError(applyBrushChannels(b, op["channels"]));
    if (op.contains("color"))
        b.color = color(op["color"]);
    if (op.contains("color_linear"))
        b.color = linearColor(op["color_linear"]);
    applyBrushNumbers(op, b);
    if (op.contains("stabilizer"))
        throwIfError(applyBrushStabilizer(b, op["stabilizer"]));
    if (op.contains("symmetry"))
        throwIfError(applyBrushSymmetry(b, op["symmetry"]));
    throwIfError(
        applyBrushTip(b, op, [&s](const std::string& path) { return s.host.loadTip(path); }));
    PressureCurve curve = s.doc.pressureCurve();
    curve.gamma = number(op, "pressure_curve", curve.gamma, PressureCurve::kMinGamma,
                         PressureCurve::kMaxGamma);
    s.doc.brush() = b;
    s.doc.setPressureCurve(curve);
}

void runSetTarget(ScriptOp& s) {
    Result<PaintTargetOptions> options = targetOptionsFromJson(s.op);
    if (!options)
        throw ScriptOpError{options.error()};
    throwIfError(s.doc.setPaintTarget(*options));
}

void runRaiseTextureSize(ScriptOp& s) {
    const json& op = s.op;
    if (!op.contains("material") || !op["material"].is_number_integer() ||
        op["material"].get<long long>() < 0 || op["material"].get<long long>() > 0xFFFFFFFFll)
        throw ScriptOpError{"\"material\" must be a material's number (from 0)"};
    if (!op.contains("width") || !op["width"].is_number_integer() ||
        op["width"].get<long long>() < 1 || op["width"].get<long long>() > 16384)
        throw ScriptOpError{"\"width\" must be a whole number from 1 to 16384"};
    if (s.doc.paintTarget() == nullptr)
        throw ScriptOpError{"there is no paint target"};
    throwIfError(
        s.doc.raiseTextureSize(op["material"].get<std::uint32_t>(), op["width"].get<int>()));
}

void runShowLayer(ScriptOp& s) {
    // The Single Layer view: strokes, fills, picks and pop-ups use that depth layer's
    // fragments; 0 shows every layer.
    const json& op = s.op;
    if (!op.contains("layer") || !op["layer"].is_number_unsigned() ||
        op["layer"].get<std::uint64_t>() > 4096)
        throw ScriptOpError{"\"layer\" must be a depth layer number (0 for all layers)"};
    s.doc.setShownLayer(op["layer"].get<std::uint32_t>());
}

void runSetSegmentation(ScriptOp& s) {
    const json& op = s.op;
    DepthLayerOptions options = s.doc.depthLayerOptions();
    options.threshold = number(op, "threshold", options.threshold, 1e-6f, 1.0f);
    if (op.contains("test")) {
        if (op["test"] == "plain")
            options.test = ConnectionTest::Plain;
        else if (op["test"] == "surface")
            options.test = ConnectionTest::Surface;
        else
            throw ScriptOpError{"\"test\" must be \"plain\" or \"surface\""};
    }
    options.cullBackFaces = !boolean(op, "two_sided", !options.cullBackFaces);
    s.doc.setDepthLayerOptions(options);
}

// Painting.

void runStroke(ScriptOp& s) {
    const std::vector<StrokePoint> points = strokePoints(s.op);
    s.needDepthLayers();
    throwIfError(s.doc.beginStroke(points.front(), s.changes));
    for (std::size_t k = 1; k < points.size(); ++k)
        s.doc.moveStroke(points[k], s.changes);
    s.doc.endStroke();
}

/** fill's "mode": region (the default), surface or color. */
FillMode fillMode(const json& op) {
    if (!op.contains("mode"))
        return FillMode::Region;
    const auto parsed =
        op["mode"].is_string() ? parseFillMode(op["mode"].get<std::string>()) : std::nullopt;
    if (!parsed)
        throw ScriptOpError{"\"mode\" must be \"region\", \"surface\" or \"color\""};
    return *parsed;
}

void runFill(ScriptOp& s) {
    const glm::vec2 at = pixelAt(s.op.value("at", json()), "at");
    const FillMode mode = fillMode(s.op);
    const float tolerance = number(s.op, "tolerance", 0.1f, 0.0f, 1.0f);
    s.needDepthLayers();
    throwIfError(s.doc.fill(at, mode, tolerance, s.changes));
}

void runPick(ScriptOp& s) {
    // The eyedropper: the brush takes the surface colour of the visible fragment.
    const glm::vec2 at = pixelAt(s.op.value("at", json()), "at");
    s.needDepthLayers();
    const DepthStack& stack = s.doc.depthLayers()->stack;
    if (!(at.x >= 0.0f && at.y >= 0.0f && at.x < float(stack.width) && at.y < float(stack.height)))
        throw ScriptOpError{"pick position " + s.op["at"].dump() + " is outside the view"};
    const std::size_t pixel = std::size_t(at.y) * std::size_t(stack.width) + std::size_t(at.x);
    const std::optional<glm::vec4> picked = s.doc.pickColor(pixel);
    if (!picked)
        throw ScriptOpError{"nothing to pick at " + s.op["at"].dump() +
                            ": no surface is visible there"};
    s.doc.brush().color = *picked;
}

void runUndo(ScriptOp& s) {
    s.doc.undo(s.changes);
}

void runRedo(ScriptOp& s) {
    s.doc.redo(s.changes);
}

// The camera.

void runOrbit(ScriptOp& s) {
    if (!s.op.contains("orbit") || !s.op["orbit"].is_string())
        throw ScriptOpError{"\"orbit\" must be a string yaw,pitch,distance"};
    Result<Camera> camera =
        parseOrbitCamera(s.op["orbit"].get<std::string>(), s.doc.mesh().bounds());
    if (!camera)
        throw ScriptOpError{camera.error()};
    s.doc.camera() = *camera; // a project keeps the last orbit view
    s.setView(camera->view(s.view.width, s.view.height));
}

void runView(ScriptOp& s) {
    // The exact view of a recorded session: its size and camera pose.
    const json& op = s.op;
    int width = s.view.width, height = s.view.height;
    if (op.contains("size")) {
        Result<std::pair<int, int>> size =
            op["size"].is_string()
                ? parseViewSize(op["size"].get<std::string>())
                : Result<std::pair<int, int>>(Error{"\"size\" must be a string WxH"});
        if (!size)
            throw ScriptOpError{size.error()};
        std::tie(width, height) = *size;
    }
    s.doc.camera() = cameraPose(op.value("camera", json::object()), s.doc.camera());
    View view = s.doc.camera().view(width, height);
    if (op.contains("view") || op.contains("proj")) {
        view.view = matrix(op, "view");
        view.proj = matrix(op, "proj");
    }
    s.setView(view);
}

void runOrbitAbout(ScriptOp& s) {
    // Layer-aware rotation about the visible surface point at a pixel.
    const glm::vec2 at = pixelAt(s.op.value("at", json()), "at");
    const float yaw = number(s.op, "yaw", 0.0f, -3600.0f, 3600.0f);
    const float pitch = number(s.op, "pitch", 0.0f, -3600.0f, 3600.0f);
    s.needDepthLayers();
    const std::optional<glm::vec3> pivot = s.doc.surfacePoint(at);
    if (!pivot)
        throw ScriptOpError{"no surface to orbit about at [" + std::to_string(int(at.x)) + ", " +
                            std::to_string(int(at.y)) + "]"};
    s.setView(s.view.orbitedAbout(*pivot, yaw, pitch));
}

// The regions.

void runBuildLayers(ScriptOp& s) {
    s.doc.clearDepthLayers();
    s.needDepthLayers();
}

void runPopUp(ScriptOp& s) {
    // The paper's intentional pop-up: a click at a pixel (cycling on repeats), or a region of
    // the region graph.
    const json& op = s.op;
    s.needDepthLayers();
    if (op.contains("region")) {
        if (!op["region"].is_number_unsigned() ||
            !s.doc.popUpRegion(op["region"].get<std::uint32_t>()))
            throw ScriptOpError{"\"region\" must be a region id of this view"};
        return;
    }
    const glm::vec2 at = pixelAt(op.value("at", json()), "at");
    if (s.doc.popUpAt(at) == kNone)
        throw ScriptOpError{"nothing to pop up at [" + std::to_string(int(at.x)) + ", " +
                            std::to_string(int(at.y)) + "]"};
}

void runHide(ScriptOp& s) {
    // Paint-to-hide with a brush of radius pixels, in the order of the op's start (what one op
    // reveals, it does not hide): at each point of "at", or along "path".
    const bool path = s.op.contains("path");
    const std::vector<glm::vec2> points = pixels(s.op, path ? "path" : "at");
    const float radius = number(s.op, "radius", 0.0f, 0.0f, 4096.0f);
    s.needDepthLayers();
    s.doc.beginHide();
    for (std::size_t k = 0; k < points.size(); ++k)
        s.doc.hideAlong(path && k > 0 ? points[k - 1] : points[k], points[k], radius);
    s.doc.endHide();
}

void runUnhide(ScriptOp& s) {
    if (!s.op.contains("regions") || !s.op["regions"].is_array())
        throw ScriptOpError{"\"regions\" must be an array of region ids"};
    std::vector<std::uint32_t> regions;
    for (const json& r : s.op["regions"]) {
        if (!r.is_number_unsigned() || r.get<std::uint64_t>() > kNone)
            throw ScriptOpError{"\"regions\" must be an array of region ids"};
        regions.push_back(r.get<std::uint32_t>());
    }
    s.needDepthLayers();
    s.doc.unhideRegions(regions);
}

void runUnhideAll(ScriptOp& s) {
    s.needDepthLayers();
    s.doc.unhideAll();
}

void runResetOrder(ScriptOp& s) {
    s.needDepthLayers();
    s.doc.resetRegionOrder();
}

constexpr ScriptOpEntry kDocumentOperations[] = {
    {"set-mode", runSetMode},
    {"set-brush", runSetBrush},
    {"set-target", runSetTarget},
    {"raise-texture-size", runRaiseTextureSize},
    {"show-layer", runShowLayer},
    {"set-segmentation", runSetSegmentation},
    {"stroke", runStroke},
    {"fill", runFill},
    {"pick", runPick},
    {"undo", runUndo},
    {"redo", runRedo},
    {"orbit", runOrbit},
    {"view", runView},
    {"orbit-about", runOrbitAbout},
    {"build-layers", runBuildLayers},
    {"popup", runPopUp},
    {"hide", runHide},
    {"unhide", runUnhide},
    {"unhide-all", runUnhideAll},
    {"reset-order", runResetOrder},
};

} // namespace

std::span<const ScriptOpEntry> documentOperations() {
    return kDocumentOperations;
}

} // namespace core
