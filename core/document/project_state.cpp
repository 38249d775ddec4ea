// SPDX-License-Identifier: GPL-3.0-or-later
// Projects: a binary glTF whose asset.extras.layerpaint holds the app state. The state is read
// field by field: a file we wrote and someone edited should still open with its painting, so a
// bad value costs that value only. What makes the file unusable (not glTF, corrupted, a newer
// format) is refused as a whole.
#include "core/document/project_state.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <limits>
#include <new>

#include "core/base/color.h"
#include "core/document/document.h"
#include "core/document/script_symmetry.h"

namespace core {

namespace {

using Json = nlohmann::json;

constexpr float kMinThreshold = 1e-6f; // the GUI's slider spans 1e-5..1e-1; files may say more
constexpr float kMaxThreshold = 1.0f;

/**
 * f as the double with the shortest decimal form that reads back as f, so the file says 0.8, not
 * 0.800000011920929 (the JSON library prints doubles with 17 digits).
 */
double num(float f) {
    char text[32];
    const auto written = std::to_chars(text, text + sizeof text, f);
    double d = static_cast<double>(f);
    // from_chars, not strtod: the GUI runs in the user's locale (decimal commas).
    if (written.ec == std::errc())
        std::from_chars(text, written.ptr, d);
    return d;
}

Json vec4Json(const glm::vec4& v) {
    return Json::array({num(v.r), num(v.g), num(v.b), num(v.a)});
}

const char* testName(ConnectionTest test) {
    return test == ConnectionTest::Plain ? "plain" : "surface";
}

/** Reads fields of one object, collecting a warning per unusable value. */
class Reader {
public:
    Reader(const Json& object, std::string where, std::vector<std::string>* warnings)
        : m_object(object), m_where(std::move(where)), m_warnings(warnings) {}

    /** The member object key, or nullptr (with a warning if present but not an object). */
    const Json* object(const char* key) {
        const Json* v = find(key);
        if (v && !v->is_object()) {
            warn(key, "is not an object");
            return nullptr;
        }
        return v;
    }
    Reader child(const char* key) {
        const Json* v = object(key);
        return Reader(v ? *v : m_empty, m_where + "." + key, m_warnings);
    }
    bool has(const char* key) const { return m_object.is_object() && m_object.contains(key); }

    void number(const char* key, float& out, float lo, float hi) {
        const Json* v = find(key);
        if (!v)
            return;
        if (v->is_number()) {
            const double d = v->get<double>();
            if (std::isfinite(d) && d >= lo && d <= hi) {
                out = static_cast<float>(d);
                return;
            }
        }
        warn(key, "is not a number from " + std::to_string(lo) + " to " + std::to_string(hi));
    }
    void integer(const char* key, int& out, int lo, int hi) {
        const Json* v = find(key);
        if (!v)
            return;
        if (v->is_number_integer() && v->get<long long>() >= lo && v->get<long long>() <= hi) {
            out = static_cast<int>(v->get<long long>());
            return;
        }
        warn(key, "is not a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
    }
    void integer64(const char* key, long long& out, long long lo, long long hi) {
        const Json* v = find(key);
        if (!v)
            return;
        if (v->is_number_integer() && v->get<long long>() >= lo && v->get<long long>() <= hi) {
            out = v->get<long long>();
            return;
        }
        warn(key, "is not a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
    }
    void boolean(const char* key, bool& out) {
        const Json* v = find(key);
        if (!v)
            return;
        if (v->is_boolean())
            out = v->get<bool>();
        else
            warn(key, "is not true or false");
    }
    void string(const char* key, std::string& out) {
        const Json* v = find(key);
        if (!v)
            return;
        if (v->is_string())
            out = v->get<std::string>();
        else
            warn(key, "is not a string");
    }
    /** [r, g, b, a] with finite components in 0..1. */
    static bool color(const Json& v, glm::vec4& out) {
        if (!v.is_array() || v.size() != 4)
            return false;
        glm::vec4 c;
        for (int k = 0; k < 4; ++k) {
            const Json& x = v[static_cast<std::size_t>(k)];
            if (!x.is_number())
                return false;
            const double d = x.get<double>();
            if (!std::isfinite(d) || d < 0.0 || d > 1.0)
                return false;
            c[k] = static_cast<float>(d);
        }
        out = c;
        return true;
    }
    void color(const char* key, glm::vec4& out) {
        const Json* v = find(key);
        if (v && !color(*v, out))
            warn(key, "is not a colour [r, g, b, a] with components from 0 to 1");
    }
    void palette(const char* key, std::vector<glm::vec4>& out) {
        const Json* v = find(key);
        if (!v)
            return;
        if (!v->is_array()) {
            warn(key, "is not an array of colours");
            return;
        }
        out.clear();
        std::size_t bad = 0;
        for (const Json& entry : *v) {
            glm::vec4 c;
            if (!color(entry, c))
                ++bad;
            else if (out.size() < ProjectState::kMaxPaletteColors)
                out.push_back(c);
        }
        if (bad > 0)
            warn(key, "has " + std::to_string(bad) + " entries that are not colours (left out)");
    }
    void vec3(const char* key, glm::vec3& out) {
        const Json* v = find(key);
        if (!v)
            return;
        if (v->is_array() && v->size() == 3 && std::all_of(v->begin(), v->end(), [](const Json& x) {
                return x.is_number() && std::isfinite(x.get<double>()) &&
                       std::abs(x.get<double>()) < 1e30;
            })) {
            out = glm::vec3((*v)[0].get<float>(), (*v)[1].get<float>(), (*v)[2].get<float>());
            return;
        }
        warn(key, "is not a point [x, y, z] of finite numbers");
    }
    void warn(const char* key, const std::string& problem) {
        if (m_warnings)
            m_warnings->push_back("the project setting " + m_where + "." + key + " " + problem +
                                  "; the default is used");
    }

private:
    const Json* find(const char* key) const {
        if (!m_object.is_object())
            return nullptr;
        const auto it = m_object.find(key);
        return it == m_object.end() || it->is_null() ? nullptr : &*it;
    }

    const Json& m_object;
    std::string m_where;
    std::vector<std::string>* m_warnings;
    inline static const Json m_empty = Json::object();
};

/** The brush tip settings of brush into its JSON object (a loaded tip's image is the io's). */
void brushTipToJson(const Brush& b, Json& j) {
    j["tip"] = b.tip;
    if (b.tip == kUserTip)
        j["tip_name"] = b.userTipName;
    j["angle"] = num(b.angle);
    j["angle_mode"] = tipAngleModeName(b.angleMode);
    j["jitter"] = {{"size", num(b.jitter.size)},
                   {"opacity", num(b.jitter.opacity)},
                   {"angle", num(b.jitter.angle)},
                   {"scatter", num(b.jitter.scatter)}};
    j["seed"] = b.seed;
}

void readBrushTip(Reader& r, Brush& b) {
    std::string tip = b.tip;
    r.string("tip", tip);
    if (isBuiltinTip(tip) || tip == kUserTip)
        b.tip = tip;
    else
        r.warn("tip", "is not a brush tip");
    r.string("tip_name", b.userTipName);
    r.number("angle", b.angle, -360.0f, 360.0f);
    std::string mode = tipAngleModeName(b.angleMode);
    r.string("angle_mode", mode);
    if (!tipAngleModeFromName(mode, b.angleMode))
        r.warn("angle_mode", "is not fixed, stroke or random");
    Reader j = r.child("jitter");
    j.number("size", b.jitter.size, 0.0f, 1.0f);
    j.number("opacity", b.jitter.opacity, 0.0f, 1.0f);
    j.number("angle", b.jitter.angle, 0.0f, 180.0f);
    j.number("scatter", b.jitter.scatter, 0.0f, 4.0f);
    long long seed = b.seed;
    r.integer64("seed", seed, 0, 0xFFFFFFFFll);
    b.seed = std::uint32_t(seed);
}

/** extras.layerpaint.version: 1 when absent (the CLI's first files), else a whole number ≥ 1. */
Result<int> formatVersion(const Json& layerpaint) {
    const auto it = layerpaint.find("version");
    if (it == layerpaint.end())
        return 1;
    if (!it->is_number_integer() || it->get<long long>() < 1 ||
        it->get<long long>() > std::numeric_limits<int>::max())
        return Error{"the project format version (extras.layerpaint.version) is not a whole "
                     "number from 1"};
    return static_cast<int>(it->get<long long>());
}

std::string newerMessage(int version) {
    return "was saved by a newer LayerPaint (project format " + std::to_string(version) +
           "; this version reads up to " + std::to_string(kProjectFormatVersion) +
           "): update LayerPaint to open it";
}

// The sections of extras.layerpaint, each read from its own object in the file's order.

void readCameraSection(Reader& root, ProjectState& s) {
    if (!root.object("camera"))
        return;
    Reader r = root.child("camera");
    Camera c;
    r.vec3("target", c.target);
    r.number("yaw", c.yawDegrees, -1e6f, 1e6f);
    r.number("pitch", c.pitchDegrees, -90.0f, 90.0f);
    r.number("distance", c.distance, 1e-9f, 1e30f);
    r.number("fov_y", c.fovYDegrees, 1.0f, 170.0f);
    r.boolean("orthographic", c.orthographic);
    s.camera = c;
}

void readBrushSection(Reader& root, ProjectState& s) {
    Reader r = root.child("brush");
    Brush& b = s.brush;
    r.color("color", b.color);
    r.number("radius", b.radius, 0.5f, 2048.0f);
    r.number("hardness", b.hardness, 0.0f, 1.0f);
    r.number("opacity", b.opacity, 0.0f, 1.0f);
    r.number("flow", b.flow, 0.0f, 1.0f);
    r.number("spacing", b.spacing, 0.01f, 4.0f);
    r.boolean("eraser", b.eraser);
    r.boolean("pressure_radius", b.pressureRadius);
    r.boolean("pressure_opacity", b.pressureOpacity);
    r.number("track_radius", b.trackRadius, 0.0f, 1e5f);
    readBrushTip(r, b);
    s.foreground = b.color; // files without colours: the brush's is the foreground
}

void readColorsSection(Reader& root, ProjectState& s) {
    Reader r = root.child("colors");
    r.color("foreground", s.foreground);
    r.color("background", s.background);
    r.palette("palette", s.palette);
}

void readSegmentationSection(Reader& root, ProjectState& s) {
    Reader r = root.child("segmentation");
    r.number("threshold", s.layers.threshold, kMinThreshold, kMaxThreshold);
    std::string test = testName(s.layers.test);
    r.string("test", test);
    if (test == "plain")
        s.layers.test = ConnectionTest::Plain;
    else if (test == "surface")
        s.layers.test = ConnectionTest::Surface;
    else
        r.warn("test", "is neither \"plain\" nor \"surface\"");
    bool twoSided = !s.layers.cullBackFaces;
    r.boolean("two_sided", twoSided);
    s.layers.cullBackFaces = !twoSided;
}

void readPaintTargetSection(Reader& root, ProjectState& s) {
    Reader r = root.child("paint_target");
    std::string kind = "auto";
    r.string("kind", kind);
    if (kind == "texture")
        s.target.kind = PaintTargetKind::Texture;
    else if (kind == "vertex-colors")
        s.target.kind = PaintTargetKind::VertexColors;
    else if (kind != "auto")
        r.warn("kind", "is not \"texture\", \"vertex-colors\" or \"auto\"");
    r.integer("resolution", s.target.resolution, 512, 8192);
}

void readStabilizerSection(Reader& root, ProjectState& s) {
    Reader r = root.child("stabilizer");
    r.boolean("on", s.brush.stabilizer);
    r.number("length", s.brush.stabilizerLength, 0.0f, 1000.0f);
    r.number("smoothing", s.brush.stabilizerSmoothing, 0.0f, 1.0f);
    r.boolean("catch_up", s.brush.stabilizerCatchUp);
}

void readPopUpSection(Reader& root, ProjectState& s) {
    Reader r = root.child("pop_up");
    r.boolean("automatic", s.autoPopUp);
    r.boolean("transparency", s.popUpTransparency);
}

/** paint_layers.layers[i].fill.base_color from sRGB-encoded to linear, where it is 3 numbers. */
void upgradeFillColorsToLinear(Json& layerpaint) {
    const auto stack = layerpaint.find("paint_layers");
    if (stack == layerpaint.end() || !stack->is_object())
        return;
    const auto layers = stack->find("layers");
    if (layers == stack->end() || !layers->is_array())
        return;
    for (Json& layer : *layers) {
        if (!layer.is_object() || !layer.contains("fill") || !layer["fill"].is_object())
            continue;
        Json& fill = layer["fill"];
        const auto color = fill.find("base_color");
        if (color == fill.end() || !color->is_array() || color->size() != 3 ||
            !std::all_of(color->begin(), color->end(), [](const Json& c) { return c.is_number(); }))
            continue; // the reader names what is wrong with it
        for (Json& c : *color)
            c = decodeSrgb(c.get<double>());
    }
}

} // namespace

Json projectStateToJson(const ProjectState& s) {
    Json j = {{"format", "LayerPaint project"}, {"version", kProjectFormatVersion}};
    if (!s.source.empty())
        j["source"] = s.source;
    if (s.camera) {
        const Camera& c = *s.camera;
        j["camera"] = {{"target", Json::array({num(c.target.x), num(c.target.y), num(c.target.z)})},
                       {"yaw", num(c.yawDegrees)},
                       {"pitch", num(c.pitchDegrees)},
                       {"distance", num(c.distance)},
                       {"fov_y", num(c.fovYDegrees)},
                       {"orthographic", c.orthographic}};
    }
    const Brush& b = s.brush;
    j["brush"] = {{"color", vec4Json(b.color)},
                  {"radius", num(b.radius)},
                  {"hardness", num(b.hardness)},
                  {"opacity", num(b.opacity)},
                  {"flow", num(b.flow)},
                  {"spacing", num(b.spacing)},
                  {"eraser", b.eraser},
                  {"pressure_radius", b.pressureRadius},
                  {"pressure_opacity", b.pressureOpacity},
                  {"track_radius", num(b.trackRadius)}};
    brushTipToJson(b, j["brush"]);
    Json palette = Json::array();
    for (std::size_t i = 0; i < s.palette.size() && i < ProjectState::kMaxPaletteColors; ++i)
        palette.push_back(vec4Json(s.palette[i]));
    j["colors"] = {{"foreground", vec4Json(s.foreground)},
                   {"background", vec4Json(s.background)},
                   {"palette", std::move(palette)}};
    j["segmentation"] = {{"threshold", num(s.layers.threshold)},
                         {"test", testName(s.layers.test)},
                         {"two_sided", !s.layers.cullBackFaces}};
    j["paint_target"] = {{"kind", !s.target.kind ? "auto"
                                  : *s.target.kind == PaintTargetKind::VertexColors
                                      ? "vertex-colors"
                                      : "texture"},
                         {"resolution", s.target.resolution}};
    j["symmetry"] = brushSymmetryJson(s.brush);
    // The stroke stabilizer (Brush's stabilizer fields), beside the brush's other settings.
    j["stabilizer"] = {{"on", s.brush.stabilizer},
                       {"length", num(s.brush.stabilizerLength)},
                       {"smoothing", num(s.brush.stabilizerSmoothing)},
                       {"catch_up", s.brush.stabilizerCatchUp}};
    j["layer_aware"] = s.layerAware;
    j["pop_up"] = {{"automatic", s.autoPopUp}, {"transparency", s.popUpTransparency}};
    if (!s.recoveryFor.empty())
        j["recovery_for"] = s.recoveryFor;
    if (s.paintLayers)
        j["paint_layers"] = paintLayersToJson(*s.paintLayers);
    return j;
}

Json upgradeProjectJson(Json j, int from) {
    if (from <= 1) {
        // Version 1 (the CLI's paint results): {"script": ..., "model": ...}. The model is the
        // source; the script stays as information. There was no other state: defaults apply.
        if (j.contains("model") && j["model"].is_string() && !j.contains("source"))
            j["source"] = j["model"];
        j.erase("model");
        from = 2;
    }
    if (from == 2) {
        // Version 2 had no paint layers: the painting is all in the base (the textures).
        j.erase("paint_layers");
        from = 3;
    }
    if (from == 3) {
        // Version 3 kept a fill layer's colour sRGB-encoded; every colour of the file is linear.
        upgradeFillColorsToLinear(j);
        from = 4;
    }
    // Later upgrades go here: if (from == 4) { ...; from = 5; }
    j["version"] = from;
    return j;
}

Result<ProjectState> projectStateFromJson(const Json& layerpaint,
                                          std::vector<std::string>* warnings) {
    if (!layerpaint.is_object())
        return Error{"extras.layerpaint is not a JSON object"};
    Result<int> version = formatVersion(layerpaint);
    if (!version)
        return version.takeError();
    if (*version > kProjectFormatVersion)
        return Error{newerMessage(*version)};
    const Json j =
        *version < kProjectFormatVersion ? upgradeProjectJson(layerpaint, *version) : layerpaint;
    ProjectState s;
    s.formatVersion = *version;
    Reader root(j, "extras.layerpaint", warnings);
    root.string("source", s.source);
    root.string("recovery_for", s.recoveryFor);
    readCameraSection(root, s);
    readBrushSection(root, s);
    readColorsSection(root, s);
    readSegmentationSection(root, s);
    readPaintTargetSection(root, s);
    readStabilizerSection(root, s);
    if (const Json* symmetry = root.object("symmetry"))
        if (Status st = applyBrushSymmetry(s.brush, *symmetry); !st)
            root.warn("symmetry", st.error());
    root.boolean("layer_aware", s.layerAware);
    readPopUpSection(root, s);
    if (const auto it = j.find("paint_layers"); it != j.end()) {
        Result<SavedPaintLayers> layers = paintLayersFromJson(*it, warnings);
        if (!layers)
            return layers.takeError(); // the planes in the file could not be matched
        s.paintLayers = std::make_shared<const SavedPaintLayers>(std::move(layers).value());
    }
    return s;
}

ProjectState captureProjectState(const Document& doc, ProjectState base) {
    ProjectState s = std::move(base);
    s.formatVersion = kProjectFormatVersion;
    s.recoveryFor.clear(); // autosaves set it after
    if (s.source.empty())
        s.source = doc.name();
    s.camera = doc.camera();
    s.brush = doc.brush();
    s.foreground = doc.brush().color; // the colour panel, where there is one, sets its own
    s.layers = doc.depthLayerOptions();
    s.target = doc.paintTargetOptions();
    // The target in use is what the file holds: an automatic choice is saved as what it chose.
    if (doc.hasPaintTarget())
        s.target.kind = doc.paintTargetKind();
    // A layout's UVs are the painted mesh's, which the project holds: none is made on opening.
    s.target.automaticUvs = false;
    s.layerAware = doc.layerAware();
    s.autoPopUp = doc.autoPopUp();
    s.paintLayers = capturePaintLayers(doc);
    return s;
}

Status applyProjectState(Document& doc, const ProjectState& state) {
    DepthLayerOptions layers = doc.depthLayerOptions();
    layers.threshold = state.layers.threshold;
    layers.test = state.layers.test;
    layers.cullBackFaces = state.layers.cullBackFaces;
    doc.setDepthLayerOptions(layers);
    doc.brush() = state.brush;
    doc.setLayerAware(state.layerAware);
    doc.setAutoPopUp(state.autoPopUp);
    if (state.camera) {
        Camera& c = doc.camera(); // framed by setMesh: keeps the scene's extent for clipping
        c.target = state.camera->target;
        c.yawDegrees = state.camera->yawDegrees;
        c.pitchDegrees = state.camera->pitchDegrees;
        c.distance = state.camera->distance;
        c.fovYDegrees = state.camera->fovYDegrees;
        c.orthographic = state.camera->orthographic;
    }
    if (doc.meshSerial() == 0 || doc.mesh().triangleCount() == 0)
        return {};
    // A project keeps the UVs of a layout it was painted on; opening one never lays out anew
    // (that can take seconds, and is the user's choice).
    const Status target = needsUvLayout(doc.mesh(), state.target)
                              ? Status(Error{"the model has no texture coordinates (UVs)"})
                              : doc.setPaintTarget(state.target);
    if (target) {
        if (!state.paintLayers)
            return {};
        Status restored;
        try {
            restored = restorePaintLayers(doc, *state.paintLayers);
        } catch (const std::bad_alloc&) {
            restored = Error{"they are too large for this machine's memory"};
        }
        if (!restored)
            return Error{"the paint layers cannot be restored (" + restored.error() + ")"};
        return {};
    }
    PaintTargetOptions fallback = state.target;
    fallback.kind.reset();
    if (const Status automatic = doc.setPaintTarget(fallback); !automatic)
        return Error{"no paint target can be made (" + automatic.error() + ")"};
    return Error{"the saved paint target cannot be used (" + target.error() +
                 "); painting goes into the automatic one"};
}

} // namespace core
