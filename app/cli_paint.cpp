// SPDX-License-Identifier: GPL-3.0-or-later
// `paint`: replays a JSON script of operations through the controller (core::Document) — the
// code path of the GUI's clicks — and saves the result as a project (core/project.h), as the
// GUI's File ▸ Save does. A project as MODEL continues with its paint, settings and view.
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/cli_commands.h"
#include "core/document/document.h"
#include "core/io/gltf_export.h"
#include "core/io/mesh_io.h"
#include "core/io/project_file.h"
#include "core/paint/flood_fill.h"
#include "render/gl_context.h"
#include "render/gl_layer_capturer.h"

namespace cli {

namespace {
using nlohmann::json;

/** A script error: names the script, the operation's index and the problem. */
struct ScriptError {
    std::string message;
};

float number(const json& op, const char* key, float fallback, float lo, float hi) {
    if (!op.contains(key))
        return fallback;
    if (!op[key].is_number())
        throw ScriptError{std::string("\"") + key + "\" must be a number"};
    const float v = op[key].get<float>();
    if (!std::isfinite(v) || v < lo || v > hi)
        throw ScriptError{std::string("\"") + key + "\" must be between " + std::to_string(lo) +
                          " and " + std::to_string(hi)};
    return v;
}

bool boolean(const json& op, const char* key, bool fallback) {
    if (!op.contains(key))
        return fallback;
    if (!op[key].is_boolean())
        throw ScriptError{std::string("\"") + key + "\" must be true or false"};
    return op[key].get<bool>();
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
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
            throw ScriptError{"\"color\" must be #rrggbb or #rrggbbaa"};
        c = glm::vec4(r, g, b, a) / 255.0f;
    } else if (value.is_array() && (value.size() == 3 || value.size() == 4)) {
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (!value[i].is_number() || value[i].get<float>() < 0.0f ||
                value[i].get<float>() > 1.0f)
                throw ScriptError{"\"color\" entries must be numbers from 0 to 1"};
            c[int(i)] = value[i].get<float>();
        }
    } else {
        throw ScriptError{"\"color\" must be #rrggbb or [r, g, b] (sRGB, 0 to 1)"};
    }
    return {srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b), c.a};
}

std::vector<core::StrokePoint> strokePoints(const json& op) {
    if (!op.contains("points") || !op["points"].is_array() || op["points"].empty())
        throw ScriptError{"\"points\" must be a non-empty array of [x, y] or [x, y, pressure]"};
    std::vector<core::StrokePoint> points;
    for (const json& p : op["points"]) {
        if (!p.is_array() || p.size() < 2 || p.size() > 3 || !p[0].is_number() ||
            !p[1].is_number() || (p.size() == 3 && !p[2].is_number()))
            throw ScriptError{"each point must be [x, y] or [x, y, pressure]"};
        core::StrokePoint point;
        point.position = {p[0].get<float>(), p[1].get<float>()};
        point.pressure = p.size() == 3 ? p[2].get<float>() : 1.0f;
        if (!std::isfinite(point.position.x) || !std::isfinite(point.position.y) ||
            !(point.pressure >= 0.0f && point.pressure <= 1.0f))
            throw ScriptError{"a point is not finite or its pressure is outside 0..1"};
        points.push_back(point);
    }
    return points;
}

/** An [x, y] pixel of the view (origin top-left). */
glm::vec2 pixelAt(const json& value, const char* what) {
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
        throw ScriptError{std::string("\"") + what + "\" must be [x, y]"};
    const glm::vec2 p(value[0].get<float>(), value[1].get<float>());
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw ScriptError{std::string("\"") + what + "\" must be finite"};
    return p;
}

/** Runs the operations on doc; layers are built (by capturer) whenever an operation needs them. */
void replay(const json& operations, core::Document& doc, core::LayerCapturer& capturer,
            CameraArgs camera, core::View& view) {
    const auto ensureLayers = [&] {
        if (doc.layers())
            return;
        if (const core::Status s = doc.buildLayers(capturer, view); !s)
            throw ScriptError{s.error()};
    };
    core::PaintChanges changes; // the GPU copy is not needed headless
    for (std::size_t i = 0; i < operations.size(); ++i) {
        const json& op = operations[i];
        try {
            if (!op.is_object() || !op.contains("op") || !op["op"].is_string())
                throw ScriptError{"an operation must be an object with an \"op\" name"};
            const std::string name = op["op"].get<std::string>();
            if (name == "set-mode") {
                doc.setLayerAware(boolean(op, "layer_aware", doc.layerAware()));
            } else if (name == "set-brush") {
                core::Brush& b = doc.brush();
                if (op.contains("color"))
                    b.color = color(op["color"]);
                b.radius = number(op, "radius", b.radius, 0.5f, 2048.0f);
                b.hardness = number(op, "hardness", b.hardness, 0.0f, 1.0f);
                b.opacity = number(op, "opacity", b.opacity, 0.0f, 1.0f);
                b.flow = number(op, "flow", b.flow, 0.0f, 1.0f);
                b.spacing = number(op, "spacing", b.spacing, 0.01f, 4.0f);
                b.trackRadius = number(op, "track_radius", b.trackRadius, 0.0f, 1e5f);
                b.eraser = boolean(op, "eraser", b.eraser);
                b.pressureRadius = boolean(op, "pressure_radius", b.pressureRadius);
                b.pressureOpacity = boolean(op, "pressure_opacity", b.pressureOpacity);
            } else if (name == "stroke") {
                const std::vector<core::StrokePoint> points = strokePoints(op);
                ensureLayers();
                if (const core::Status s = doc.beginStroke(points.front(), changes); !s)
                    throw ScriptError{s.error()};
                for (std::size_t k = 1; k < points.size(); ++k)
                    doc.moveStroke(points[k], changes);
                doc.endStroke();
            } else if (name == "fill") {
                if (!op.contains("at") || !op["at"].is_array() || op["at"].size() != 2 ||
                    !op["at"][0].is_number() || !op["at"][1].is_number())
                    throw ScriptError{"\"at\" must be [x, y] (pixels from the top-left)"};
                const glm::vec2 at(op["at"][0].get<float>(), op["at"][1].get<float>());
                if (!std::isfinite(at.x) || !std::isfinite(at.y))
                    throw ScriptError{"\"at\" must be finite"};
                core::FillMode mode = core::FillMode::Region;
                if (op.contains("mode")) {
                    const auto parsed = op["mode"].is_string()
                                            ? core::parseFillMode(op["mode"].get<std::string>())
                                            : std::nullopt;
                    if (!parsed)
                        throw ScriptError{"\"mode\" must be \"region\", \"surface\" or \"color\""};
                    mode = *parsed;
                }
                const float tolerance = number(op, "tolerance", 0.1f, 0.0f, 1.0f);
                ensureLayers();
                if (const core::Status s = doc.fill(at, mode, tolerance, changes); !s)
                    throw ScriptError{s.error()};
            } else if (name == "pick") {
                // The eyedropper: the brush takes the surface colour of the visible fragment.
                const json& at = op.contains("at") ? op["at"] : json();
                if (!at.is_array() || at.size() != 2 || !at[0].is_number() || !at[1].is_number())
                    throw ScriptError{"\"at\" must be [x, y] in pixels"};
                const double x = at[0].get<double>(), y = at[1].get<double>();
                ensureLayers();
                const core::LayerStack& stack = doc.layers()->stack;
                if (!(x >= 0.0 && y >= 0.0 && x < stack.width && y < stack.height))
                    throw ScriptError{"pick position " + at.dump() + " is outside the view"};
                const std::size_t pixel =
                    std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
                const std::optional<glm::vec4> picked = doc.pickColor(pixel);
                if (!picked)
                    throw ScriptError{"nothing to pick at " + at.dump() +
                                      ": no surface is visible there"};
                doc.brush().color = *picked;
            } else if (name == "undo") {
                doc.undo(changes);
            } else if (name == "redo") {
                doc.redo(changes);
            } else if (name == "orbit") {
                if (!op.contains("orbit") || !op["orbit"].is_string())
                    throw ScriptError{"\"orbit\" must be a string yaw,pitch,distance"};
                camera.orbit = op["orbit"].get<std::string>();
                camera.cameraFile.clear();
                auto c = makeCamera(camera, doc.mesh());
                auto v = makeView(camera, doc.mesh());
                if (!c || !v)
                    throw ScriptError{c ? v.error() : c.error()};
                doc.camera() = *c; // the project keeps the last orbit view
                view = *v;
                doc.clearLayers();
            } else if (name == "build-layers") {
                doc.clearLayers();
                ensureLayers();
            } else if (name == "popup") {
                // The paper's intentional pop-up: a click at a pixel, cycling on repeats.
                const glm::vec2 at = pixelAt(op.value("at", json()), "at");
                ensureLayers();
                if (doc.popUpAt(at) == core::kNone)
                    throw ScriptError{"nothing to pop up at [" + std::to_string(int(at.x)) + ", " +
                                      std::to_string(int(at.y)) + "]"};
            } else if (name == "hide") {
                // Paint-to-hide at points (a brush of radius pixels), in the order of the op's
                // start: what one op reveals, it does not hide.
                if (!op.contains("at") || !op["at"].is_array() || op["at"].empty())
                    throw ScriptError{"\"at\" must be a non-empty array of [x, y]"};
                const float radius = number(op, "radius", 0.0f, 0.0f, 4096.0f);
                ensureLayers();
                const std::vector<std::uint32_t> ranks = doc.regionRanks();
                for (const json& point : op["at"]) {
                    const glm::vec2 at = pixelAt(point, "at");
                    doc.hideAlong(at, at, radius, ranks);
                }
            } else if (name == "unhide-all" || name == "reset-order") {
                ensureLayers();
                core::RegionOrder order = doc.regionOrder();
                if (name == "unhide-all")
                    order.unhideAll();
                else
                    order.reset();
                doc.setRegionOrder(std::move(order));
            } else if (name == "orbit-about") {
                // Layer-aware rotation about the visible surface point at a pixel.
                const glm::vec2 at = pixelAt(op.value("at", json()), "at");
                const float yaw = number(op, "yaw", 0.0f, -3600.0f, 3600.0f);
                const float pitch = number(op, "pitch", 0.0f, -3600.0f, 3600.0f);
                ensureLayers();
                const std::optional<glm::vec3> pivot = doc.surfacePoint(at);
                if (!pivot)
                    throw ScriptError{"no surface to orbit about at [" + std::to_string(int(at.x)) +
                                      ", " + std::to_string(int(at.y)) + "]"};
                view = view.orbitedAbout(*pivot, yaw, pitch);
                doc.clearLayers();
            } else {
                throw ScriptError{"unknown operation \"" + name + "\""};
            }
        } catch (const ScriptError& e) {
            throw ScriptError{"operation " + std::to_string(i + 1) + ": " + e.message};
        }
    }
}
} // namespace

core::Result<json> readScript(const std::string& path) {
    std::ifstream in(path);
    if (!in)
        return core::Error{path + ": cannot be opened"};
    json script = json::parse(in, nullptr, false);
    if (script.is_discarded())
        return core::Error{path + ": not valid JSON"};
    if (script.is_object()) {
        if (!script.contains("operations") || !script["operations"].is_array())
            return core::Error{path + ": expected an \"operations\" array"};
    } else if (!script.is_array()) {
        return core::Error{path + ": expected an array of operations or an object"};
    }
    return script;
}

core::Status applyScriptSettings(const json& script, const std::string& path, core::Document& doc,
                                 CameraArgs& camera) {
    if (!script.is_object())
        return {};
    if (script.contains("size") && script["size"].is_string())
        camera.size = script["size"].get<std::string>();
    if (script.contains("orbit") && script["orbit"].is_string() && camera.cameraFile.empty())
        camera.orbit = script["orbit"].get<std::string>();
    if (script.contains("target") && script["target"].is_object()) {
        const json& t = script["target"];
        core::PaintTargetOptions options;
        if (t.contains("kind") && t["kind"] == "vertex-colors")
            options.kind = core::PaintTargetKind::VertexColors;
        else if (t.contains("kind") && t["kind"] == "texture")
            options.kind = core::PaintTargetKind::Texture;
        if (t.contains("resolution") && t["resolution"].is_number_integer())
            options.resolution = t["resolution"].get<int>();
        if (const core::Status s = doc.resetPaintTarget(options); !s)
            return core::Error{path + ": " + s.error()};
    }
    return {};
}

core::Status replayScript(const json& script, const std::string& path, core::Document& doc,
                          core::LayerCapturer& capturer, const CameraArgs& camera,
                          core::View& view) {
    try {
        replay(script.is_object() ? script["operations"] : script, doc, capturer, camera, view);
    } catch (const ScriptError& e) {
        return core::Error{path + ": " + e.message};
    }
    return {};
}

int runPaint(const PaintArgs& args) {
    auto script = readScript(args.script);
    if (!script)
        return fail(script.error());
    // A project continues with its paint and settings; a plain model starts afresh.
    auto project = core::loadProject(args.model);
    if (!project)
        return fail(project.error());
    core::Document doc;
    doc.setMesh(std::move(project->mesh), args.model);
    core::ProjectState base;
    if (project->state) {
        base = *project->state;
        if (const core::Status s = core::applyProjectState(doc, base); !s)
            std::cerr << "layerpaint-cli: " << args.model << ": " << s.error() << '\n';
    }

    CameraArgs camera = args.camera;
    if (const core::Status s = applyScriptSettings(*script, args.script, doc, camera); !s)
        return fail(s.error());
    // Without --orbit or --camera a project is painted from its saved view.
    const core::Camera* saved = project->state && project->state->camera ? &doc.camera() : nullptr;
    auto view = makeView(camera, doc.mesh(), saved);
    if (!view)
        return fail(view.error());
    if (camera.cameraFile.empty()) {
        auto orbitCamera = makeCamera(camera, doc.mesh(), saved);
        if (orbitCamera)
            doc.camera() = *orbitCamera;
    }

    std::unique_ptr<render::HeadlessContext> context;
    std::unique_ptr<core::LayerCapturer> capturer;
    if (args.cpuCapture) {
        capturer = std::make_unique<core::CpuLayerCapturer>();
    } else {
        auto created = render::HeadlessContext::create();
        if (!created)
            return fail(created.error() + " (use --cpu to capture without OpenGL)");
        context = std::move(created).value();
        auto gl = std::make_unique<render::GlLayerCapturer>();
        if (const core::Status s = gl->initialize(); !s)
            return fail(s.error());
        capturer = std::move(gl);
    }
    capturer->setMesh(doc.mesh());

    if (const core::Status s = replayScript(*script, args.script, doc, *capturer, camera, *view);
        !s)
        return fail(s.error());
    // The same save as the GUI's: a project with the script's end state.
    const core::ProjectState state = core::captureProjectState(doc, base);
    if (const core::Status s = core::saveProject(args.out, doc, state); !s)
        return fail(s.error());
    return 0;
}

} // namespace cli
