// SPDX-License-Identifier: GPL-3.0-or-later
// Projects: the state's JSON, save → load → the same paint and settings, upgrades of older
// formats, refusal of newer and corrupted files with messages naming them, and that the file is
// plain glTF to other tools (tinygltf and Assimp read it).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/base/color.h"
#include "core/document/document.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/model/builtin_models.h"
#include "tests/core/test_files.h"

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace project_test {

using core_test::readFile;
using core_test::TempDir;
using core_test::writeFile;

std::uint32_t u32(const std::string& b, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, b.data() + at, 4);
    return v;
}

void putU32(std::string& b, std::size_t at, std::uint32_t v) {
    std::memcpy(b.data() + at, &v, 4);
}

void putU32BigEndian(std::string& b, std::size_t at, std::uint32_t v) {
    for (int k = 0; k < 4; ++k)
        b[at + std::size_t(k)] = static_cast<char>(v >> (24 - 8 * k));
}

/** The CRC-32 PNG chunks carry (ISO 3309). */
std::uint32_t crc32(const char* data, std::size_t size) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= static_cast<std::uint8_t>(data[i]);
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

/** A state with every field away from its default. */
core::ProjectState unusualState() {
    core::ProjectState s;
    s.source = "/models/cup \xc3\xa9.obj";
    core::Camera c;
    c.target = {0.25f, -1.5f, 3.0f};
    c.yawDegrees = 123.5f;
    c.pitchDegrees = -33.25f;
    c.distance = 4.75f;
    c.fovYDegrees = 30.0f;
    c.orthographic = true;
    s.camera = c;
    s.brush.color = {0.1f, 0.2f, 0.3f, 0.9f};
    s.brush.radius = 17.5f;
    s.brush.hardness = 0.8f;
    s.brush.opacity = 0.6f;
    s.brush.flow = 0.4f;
    s.brush.spacing = 0.3f;
    s.brush.eraser = true;
    s.brush.pressureRadius = false;
    s.brush.pressureOpacity = true;
    s.brush.trackRadius = 99.0f;
    s.foreground = {0.5f, 0.25f, 0.125f, 1.0f};
    s.background = {0.0f, 0.0f, 1.0f, 0.5f};
    s.palette = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0.2f, 0.4f, 0.6f, 0.8f}};
    s.layers.threshold = 0.0123f;
    s.layers.test = core::ConnectionTest::Plain;
    s.layers.cullBackFaces = false;
    s.target.kind = core::PaintTargetKind::VertexColors;
    s.target.resolution = 1024;
    s.layerAware = false;
    s.autoPopUp = false;
    s.popUpTransparency = true;
    s.recoveryFor = "/home/artist/cup.glb";
    return s;
}

void expectSameCamera(const core::Camera& a, const core::Camera& b) {
    EXPECT_EQ(a.target, b.target);
    EXPECT_EQ(a.yawDegrees, b.yawDegrees);
    EXPECT_EQ(a.pitchDegrees, b.pitchDegrees);
    EXPECT_EQ(a.distance, b.distance);
    EXPECT_EQ(a.fovYDegrees, b.fovYDegrees);
    EXPECT_EQ(a.orthographic, b.orthographic);
}

void expectSameState(const core::ProjectState& a, const core::ProjectState& b) {
    EXPECT_EQ(a.source, b.source);
    ASSERT_EQ(a.camera.has_value(), b.camera.has_value());
    if (a.camera) {
        expectSameCamera(*a.camera, *b.camera);
    }
    EXPECT_EQ(a.brush.color, b.brush.color);
    EXPECT_EQ(a.brush.radius, b.brush.radius);
    EXPECT_EQ(a.brush.hardness, b.brush.hardness);
    EXPECT_EQ(a.brush.opacity, b.brush.opacity);
    EXPECT_EQ(a.brush.flow, b.brush.flow);
    EXPECT_EQ(a.brush.spacing, b.brush.spacing);
    EXPECT_EQ(a.brush.eraser, b.brush.eraser);
    EXPECT_EQ(a.brush.pressureRadius, b.brush.pressureRadius);
    EXPECT_EQ(a.brush.pressureOpacity, b.brush.pressureOpacity);
    EXPECT_EQ(a.brush.trackRadius, b.brush.trackRadius);
    EXPECT_EQ(a.foreground, b.foreground);
    EXPECT_EQ(a.background, b.background);
    EXPECT_EQ(a.palette, b.palette);
    EXPECT_EQ(a.layers.threshold, b.layers.threshold);
    EXPECT_EQ(a.layers.test, b.layers.test);
    EXPECT_EQ(a.layers.cullBackFaces, b.layers.cullBackFaces);
    EXPECT_EQ(a.target.kind, b.target.kind);
    EXPECT_EQ(a.target.resolution, b.target.resolution);
    EXPECT_EQ(a.layerAware, b.layerAware);
    EXPECT_EQ(a.autoPopUp, b.autoPopUp);
    EXPECT_EQ(a.popUpTransparency, b.popUpTransparency);
    EXPECT_EQ(a.recoveryFor, b.recoveryFor);
}

/** Paints a few strokes across the middle of doc's view (CPU capture) and returns the view. */
core::View paintSomething(core::Document& doc, int width = 320, int height = 240) {
    doc.camera() = core::Camera::fromOrbit(doc.mesh().bounds(), 30.0f, 20.0f, 1.6f);
    const core::View view = doc.camera().view(width, height);
    core::CpuDepthCapturer capturer;
    capturer.setMesh(doc.mesh());
    const core::Status built = doc.buildDepthLayers(capturer, view);
    EXPECT_TRUE(built.ok()) << built.error();
    const core::DepthStack& stack = doc.depthLayers()->stack;
    core::PaintChanges changes;
    int strokes = 0;
    for (int y = height / 3; y < 2 * height / 3 && strokes < 3; y += 20) {
        int first = -1, last = -1;
        for (int x = 0; x < width; ++x)
            if (stack.layerCount(std::size_t(y) * std::size_t(width) + std::size_t(x)) > 0) {
                if (first < 0)
                    first = x;
                last = x;
            }
        if (first < 0 || last - first < 20)
            continue;
        const core::Status begun =
            doc.beginStroke({{float(first) + 2.0f, float(y) + 0.5f}, 1.0f}, changes);
        EXPECT_TRUE(begun.ok()) << begun.error();
        for (int x = first + 4; x < last - 2; x += 3)
            doc.moveStroke({{float(x) + 0.5f, float(y) + 0.5f}, 1.0f}, changes);
        doc.endStroke();
        ++strokes;
        doc.brush().color = {0.1f, 0.7f, 0.2f, 1.0f};
    }
    EXPECT_GT(strokes, 0);
    return view;
}

std::vector<std::vector<std::uint8_t>> pages(core::Document& doc) {
    std::vector<std::vector<std::uint8_t>> out;
    const auto* texture = dynamic_cast<const core::TextureTarget*>(doc.paintTarget());
    if (texture)
        for (std::size_t i = 0; i < texture->pageCount(); ++i)
            out.push_back(texture->page(i).rgba);
    return out;
}

/** Loads path as a project into a fresh document, applying its state. */
void reopen(const std::string& path, core::Document& doc, core::ProjectState& state) {
    core::Result<core::Project> project = core::loadProject(path);
    ASSERT_TRUE(project.ok()) << project.error();
    ASSERT_TRUE(project->state.has_value());
    EXPECT_TRUE(project->mesh.warnings.empty()) << project->mesh.warnings.front();
    state = *project->state;
    doc.setMesh(std::move(project->mesh), path);
    const core::Status applied = core::applyProjectState(doc, state);
    EXPECT_TRUE(applied.ok()) << applied.error();
}

TEST(ProjectState, JsonRoundTripKeepsEveryField) {
    const core::ProjectState state = unusualState();
    const Json j = core::projectStateToJson(state);
    EXPECT_EQ(j["version"], core::kProjectFormatVersion);
    std::vector<std::string> warnings;
    core::Result<core::ProjectState> back = core::projectStateFromJson(j, &warnings);
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_EQ(back->formatVersion, core::kProjectFormatVersion);
    expectSameState(state, *back);
    // Through text too (what the file holds).
    back = core::projectStateFromJson(Json::parse(j.dump()), &warnings);
    ASSERT_TRUE(back.ok()) << back.error();
    expectSameState(state, *back);

    // Defaults survive as defaults, without a camera.
    const core::ProjectState defaults;
    back = core::projectStateFromJson(core::projectStateToJson(defaults));
    ASSERT_TRUE(back.ok());
    expectSameState(defaults, *back);
    EXPECT_FALSE(back->camera.has_value());
}

TEST(ProjectState, BadValuesKeepTheirDefaultsWithAWarning) {
    Json j = core::projectStateToJson(unusualState());
    j["brush"]["radius"] = "big";
    j["brush"]["hardness"] = 7;
    j["colors"]["background"] = {1, 2};
    j["colors"]["palette"] =
        Json::array({Json::array({1, 0, 0, 1}), "red", Json::array({0, 0, 1, 1})});
    j["segmentation"]["test"] = "magic";
    j["paint_target"]["resolution"] = 100000;
    j["camera"]["distance"] = -1;
    j["pop_up"] = 3;
    j["unknown_future_field"] = {{"x", 1}}; // ignored without a word
    std::vector<std::string> warnings;
    core::Result<core::ProjectState> s = core::projectStateFromJson(j, &warnings);
    ASSERT_TRUE(s.ok()) << s.error();
    const core::ProjectState defaults;
    EXPECT_EQ(s->brush.radius, defaults.brush.radius);
    EXPECT_EQ(s->brush.hardness, defaults.brush.hardness);
    EXPECT_EQ(s->brush.opacity, 0.6f); // the good ones are kept
    EXPECT_EQ(s->background, defaults.background);
    EXPECT_EQ(s->palette, (std::vector<glm::vec4>{{1, 0, 0, 1}, {0, 0, 1, 1}}));
    EXPECT_EQ(s->layers.test, defaults.layers.test);
    EXPECT_EQ(s->target.resolution, defaults.target.resolution);
    ASSERT_TRUE(s->camera.has_value());
    EXPECT_EQ(s->camera->distance, core::Camera().distance);
    EXPECT_EQ(s->camera->yawDegrees, 123.5f);
    EXPECT_EQ(s->autoPopUp, defaults.autoPopUp);
    ASSERT_EQ(warnings.size(), 8u);
    EXPECT_NE(warnings[0].find("extras.layerpaint.camera.distance"), std::string::npos)
        << warnings[0];
    bool namesRadius = false;
    for (const std::string& w : warnings)
        namesRadius = namesRadius ||
                      w.find("extras.layerpaint.brush.radius is not a number") != std::string::npos;
    EXPECT_TRUE(namesRadius);
}

TEST(ProjectState, NewerVersionsAndBadVersionsAreRefused) {
    Json j = core::projectStateToJson({});
    j["version"] = core::kProjectFormatVersion + 1;
    core::Result<core::ProjectState> s = core::projectStateFromJson(j);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().find("newer LayerPaint"), std::string::npos) << s.error();
    EXPECT_NE(s.error().find("format " + std::to_string(core::kProjectFormatVersion + 1)),
              std::string::npos)
        << s.error();
    for (const Json& bad : {Json(0), Json(-3), Json(1.5), Json("2"), Json::array()}) {
        j["version"] = bad;
        s = core::projectStateFromJson(j);
        ASSERT_FALSE(s.ok()) << bad;
        EXPECT_NE(s.error().find("version"), std::string::npos) << s.error();
    }
    EXPECT_FALSE(core::projectStateFromJson(Json::array()).ok());
}

TEST(ProjectState, AFillLayersColourIsStoredLinearAndComesBackExactly) {
    // #3399e6 as the panel sets it (sRGB-encoded): the file holds it linear, as every colour.
    core::SavedPaintLayers saved;
    core::SavedPaintLayer fill;
    fill.id = 1;
    fill.settings.kind = core::PaintLayerKind::Fill;
    fill.settings.fill.baseColor = glm::vec3(0x33, 0x99, 0xe6) / 255.0f;
    saved.layers.push_back(fill);
    const Json j = core::paintLayersToJson(saved);
    const Json& color = j["layers"][0]["fill"]["base_color"];
    EXPECT_NEAR(color[0].get<double>(), core::srgbToLinear(std::uint8_t(0x33)), 1e-6);
    EXPECT_NEAR(color[1].get<double>(), core::srgbToLinear(std::uint8_t(0x99)), 1e-6);
    EXPECT_NEAR(color[2].get<double>(), core::srgbToLinear(std::uint8_t(0xe6)), 1e-6);
    core::Result<core::SavedPaintLayers> back = core::paintLayersFromJson(j, nullptr);
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_EQ(back->layers[0].settings.fill.baseColor, fill.settings.fill.baseColor);
    // Every byte a colour dialog gives comes back as the same float.
    for (int b = 0; b < 256; ++b) {
        const float v = float(b) / 255.0f;
        EXPECT_EQ(float(core::encodeSrgb(core::decodeSrgb(double(v)))), v) << b;
    }

    // Version 3 kept it sRGB-encoded: opened, it is the same colour.
    Json v3 = {{"version", 3}, {"paint_layers", j}};
    v3["paint_layers"]["layers"][0]["fill"]["base_color"] = {0.2, 0.6, 230.0 / 255.0};
    const Json upgraded = core::upgradeProjectJson(v3, 3);
    core::Result<core::SavedPaintLayers> old =
        core::paintLayersFromJson(upgraded["paint_layers"], nullptr);
    ASSERT_TRUE(old.ok()) << old.error();
    const glm::vec3 c = *old->layers[0].settings.fill.baseColor;
    EXPECT_NEAR(c.x, 0.2f, 1e-6f);
    EXPECT_NEAR(c.y, 0.6f, 1e-6f);
    EXPECT_NEAR(c.z, 230.0f / 255.0f, 1e-6f);
}

TEST(ProjectState, Version1IsUpgraded) {
    // What `layerpaint-cli paint` wrote before projects had a version.
    const Json v1 = {{"script", "strokes.json"}, {"model", "builtin:trefoil"}};
    const Json upgraded = core::upgradeProjectJson(v1, 1);
    EXPECT_EQ(upgraded["version"], core::kProjectFormatVersion);
    EXPECT_EQ(upgraded["source"], "builtin:trefoil");
    EXPECT_FALSE(upgraded.contains("model"));
    EXPECT_EQ(upgraded["script"], "strokes.json");
    // A current one is left alone.
    const Json current = core::projectStateToJson(unusualState());
    EXPECT_EQ(core::upgradeProjectJson(current, core::kProjectFormatVersion), current);

    std::vector<std::string> warnings;
    core::Result<core::ProjectState> s = core::projectStateFromJson(v1, &warnings);
    ASSERT_TRUE(s.ok()) << s.error();
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(s->formatVersion, 1);
    EXPECT_EQ(s->source, "builtin:trefoil");
    EXPECT_FALSE(s->camera.has_value());
    core::ProjectState expected;
    expected.source = "builtin:trefoil";
    expectSameState(expected, *s);

    // A whole version-1 file opens as a project with the default settings.
    TempDir dir;
    const std::string path = dir.file("old.glb");
    ASSERT_TRUE(core::saveGlb(path, core::makeTrefoil(20, 8), {{"layerpaint", v1}}).ok());
    core::Result<core::Project> project = core::loadProject(path);
    ASSERT_TRUE(project.ok()) << project.error();
    ASSERT_TRUE(project->state.has_value());
    EXPECT_EQ(project->state->formatVersion, 1);
    EXPECT_EQ(project->state->source, "builtin:trefoil");
    // Saved again, it is the current version.
    ASSERT_TRUE(core::saveProject(path, project->mesh, *project->state).ok());
    core::Result<Json> extras = core::readGlbExtras(path);
    ASSERT_TRUE(extras.ok());
    EXPECT_EQ((*extras)["layerpaint"]["version"], core::kProjectFormatVersion);
}

TEST(Project, TextureSaveLoadKeepsPaintCameraAndSettings) {
    TempDir dir;
    core::Document doc;
    doc.setMesh(core::makeTrefoil(60, 16), "builtin:trefoil");
    core::PaintTargetOptions options;
    options.resolution = 512;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    paintSomething(doc);
    doc.camera().orbit(12.0f, -5.0f);
    doc.camera().orthographic = true;
    doc.brush().radius = 21.0f;
    doc.brush().hardness = 0.9f;
    doc.setLayerAware(false);
    core::DepthLayerOptions layers = doc.depthLayerOptions();
    layers.threshold = 0.004f;
    layers.test = core::ConnectionTest::Plain;
    doc.setDepthLayerOptions(layers);

    core::ProjectState state = core::captureProjectState(doc);
    EXPECT_EQ(state.source, "builtin:trefoil");
    ASSERT_EQ(state.target.kind, core::PaintTargetKind::Texture);
    state.palette = {{0.1f, 0.7f, 0.2f, 1.0f}, {0.8f, 0.1f, 0.1f, 1.0f}};
    state.autoPopUp = false;
    state.popUpTransparency = true;
    const std::vector<std::vector<std::uint8_t>> painted = pages(doc);
    ASSERT_EQ(painted.size(), 1u);
    const std::string path = dir.file("knot.glb");
    const core::Status saved = core::saveProject(path, doc, state);
    ASSERT_TRUE(saved.ok()) << saved.error();

    core::Document reopened;
    core::ProjectState back;
    reopen(path, reopened, back);
    expectSameState(state, back);
    EXPECT_EQ(pages(reopened), painted) << "the painted texture differs after reopening";
    expectSameCamera(reopened.camera(), doc.camera());
    EXPECT_EQ(reopened.brush().radius, 21.0f);
    EXPECT_EQ(reopened.brush().hardness, 0.9f);
    EXPECT_FALSE(reopened.layerAware());
    EXPECT_FALSE(reopened.autoPopUp());
    EXPECT_EQ(reopened.depthLayerOptions().threshold, 0.004f);
    EXPECT_EQ(reopened.depthLayerOptions().test, core::ConnectionTest::Plain);
    // The same geometry, triangle for triangle.
    ASSERT_EQ(reopened.mesh().triangleCount(), doc.mesh().triangleCount());
    for (std::size_t i = 0; i < doc.mesh().indices.size(); i += 97)
        EXPECT_EQ(reopened.mesh().positions[reopened.mesh().indices[i]],
                  doc.mesh().positions[doc.mesh().indices[i]]);

    // Painting goes on in the reopened document, and saving again gives the same picture.
    paintSomething(reopened);
    EXPECT_NE(pages(reopened), painted);
    const std::string again = dir.file("knot2.glb");
    ASSERT_TRUE(core::saveProject(again, reopened, core::captureProjectState(reopened)).ok());
    core::Document third;
    core::ProjectState thirdState;
    reopen(again, third, thirdState);
    EXPECT_EQ(pages(third), pages(reopened));
}

TEST(Project, VertexColorSaveLoadKeepsPaint) {
    TempDir dir;
    core::Document doc;
    doc.setMesh(core::makeTrefoil(60, 16), "builtin:trefoil");
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::VertexColors;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    paintSomething(doc);
    const auto* colors = dynamic_cast<const core::VertexColorTarget*>(doc.paintTarget());
    ASSERT_NE(colors, nullptr);
    const std::vector<glm::vec4> painted = colors->colors();
    ASSERT_NE(painted, colors->originalColors());

    const std::string path = dir.file("knot.glb");
    ASSERT_TRUE(core::saveProject(path, doc, core::captureProjectState(doc)).ok());
    core::Document reopened;
    core::ProjectState back;
    reopen(path, reopened, back);
    EXPECT_EQ(back.target.kind, core::PaintTargetKind::VertexColors);
    const auto* again = dynamic_cast<const core::VertexColorTarget*>(reopened.paintTarget());
    ASSERT_NE(again, nullptr);
    EXPECT_EQ(again->colors(), painted);
}

TEST(Project, PlainModelsHaveNoState) {
    EXPECT_FALSE(core::loadProject("builtin:hexring")->state.has_value());
    TempDir dir;
    const std::string path = dir.file("plain.glb");
    ASSERT_TRUE(core::saveGlb(path, core::makeTrefoil(20, 8)).ok());
    core::Result<core::Project> plain = core::loadProject(path);
    ASSERT_TRUE(plain.ok()) << plain.error();
    EXPECT_FALSE(plain->state.has_value());
    const fs::path obj = fs::path(LAYERPAINT_ASSIMP_MODELS) / "OBJ/box.obj";
    if (fs::exists(obj)) {
        core::Result<core::Project> o = core::loadProject(obj.string());
        ASSERT_TRUE(o.ok()) << o.error();
        EXPECT_FALSE(o->state.has_value());
    }
}

TEST(Project, TargetThatCannotBeMadeFallsBackToTheAutomaticOne) {
    core::Mesh mesh = core::makeTrefoil(20, 8);
    mesh.uvs.clear();
    core::Document doc;
    doc.setMesh(std::move(mesh), "no uvs");
    core::ProjectState state;
    state.target.kind = core::PaintTargetKind::Texture;
    const core::Status status = core::applyProjectState(doc, state);
    EXPECT_FALSE(status.ok());
    EXPECT_NE(status.error().find("automatic"), std::string::npos) << status.error();
    EXPECT_EQ(doc.paintTargetKind(), core::PaintTargetKind::VertexColors);
    EXPECT_TRUE(doc.hasPaintTarget());
}

TEST(Project, NewerProjectIsRefusedNamingTheFile) {
    TempDir dir;
    const std::string path = dir.file("future.glb");
    Json state = core::projectStateToJson({});
    state["version"] = 99;
    ASSERT_TRUE(core::saveGlb(path, core::makeTrefoil(20, 8), {{"layerpaint", state}}).ok());
    core::Result<core::Project> p = core::loadProject(path);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().rfind(path + ": ", 0), 0u) << p.error();
    EXPECT_NE(p.error().find("newer LayerPaint (project format 99"), std::string::npos)
        << p.error();
    // extras.layerpaint of the wrong type.
    ASSERT_TRUE(core::saveGlb(path, core::makeTrefoil(20, 8), {{"layerpaint", 5}}).ok());
    p = core::loadProject(path);
    ASSERT_FALSE(p.ok());
    EXPECT_NE(p.error().find("extras.layerpaint is not a JSON object"), std::string::npos);
}

TEST(Project, CorruptedProjectsAreRefusedWithClearMessages) {
    TempDir dir;
    core::Document doc;
    doc.setMesh(core::makeTrefoil(40, 12), "builtin:trefoil");
    core::PaintTargetOptions options;
    options.resolution = 512;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    paintSomething(doc, 160, 120);
    const std::string good = dir.file("good.glb");
    ASSERT_TRUE(core::saveProject(good, doc, core::captureProjectState(doc)).ok());
    const std::string bytes = readFile(good);
    const std::uint32_t jsonLength = u32(bytes, 12);
    const std::size_t binHeader = 20 + jsonLength;
    const std::string jsonText = bytes.substr(20, jsonLength);

    struct Case {
        std::string name;
        std::string bytes;
        std::string expected; // part of the message
    };
    std::vector<Case> cases;
    // Truncated at many points: in the header, the JSON, the BIN header, the BIN data.
    for (std::size_t at : {std::size_t{0}, std::size_t{7}, std::size_t{19}, std::size_t{40},
                           binHeader - 1, binHeader + 4, bytes.size() / 2, bytes.size() - 1})
        cases.push_back({"truncated at " + std::to_string(at), bytes.substr(0, at), ""});
    // Wrong chunk lengths.
    {
        std::string b = bytes;
        putU32(b, 12, jsonLength + 8); // JSON chunk swallows the BIN header
        cases.push_back({"JSON length too long", b, ""});
        b = bytes;
        putU32(b, 12, jsonLength - 8);
        cases.push_back({"JSON length too short", b, ""});
        b = bytes;
        putU32(b, binHeader, u32(bytes, binHeader) + 64);
        cases.push_back({"BIN length past the end", b, "BIN chunk runs past the end"});
        b = bytes;
        putU32(b, 8, static_cast<std::uint32_t>(bytes.size() + 1000));
        cases.push_back({"header length past the end", b, "truncated"});
        b = bytes;
        putU32(b, 4, 1);
        cases.push_back({"GLB version 1", b, "version 1 is not supported"});
    }
    // Bad JSON.
    {
        // A colon in the middle of the JSON becomes a brace: never valid JSON, whatever the
        // project holds (a byte overwritten inside a string value may well be).
        std::string b = bytes;
        const std::size_t colon = b.find(':', 20 + jsonLength / 2);
        ASSERT_LT(colon, 20 + std::size_t(jsonLength));
        b[colon] = '{';
        cases.push_back({"bad JSON", b, "malformed at line 1"});
        b = bytes;
        const std::size_t extrasAt = jsonText.find("\"layerpaint\"");
        ASSERT_NE(extrasAt, std::string::npos);
        b[20 + extrasAt] = '!';
        cases.push_back({"broken extras", b, "malformed at line 1"});
    }
    // Huge declared sizes (the JSON is rewritten and the container rebuilt around it).
    const auto rebuild = [&](const Json& json) {
        std::string text = json.dump();
        text.resize((text.size() + 3) & ~std::size_t{3}, ' ');
        std::string out = bytes.substr(0, 20);
        putU32(out, 12, static_cast<std::uint32_t>(text.size()));
        out += text;
        out += bytes.substr(binHeader);
        putU32(out, 8, static_cast<std::uint32_t>(out.size()));
        return out;
    };
    const Json root = Json::parse(jsonText);
    {
        Json j = root;
        j["buffers"][0]["byteLength"] = 4294967295ull;
        cases.push_back({"huge buffer", rebuild(j), ""});
        j = root;
        j["accessors"][0]["count"] = 4000000000ull;
        cases.push_back({"huge accessor count", rebuild(j), ""});
        j = root;
        j["bufferViews"][0]["byteLength"] = 4294967295ull;
        cases.push_back({"huge buffer view", rebuild(j), ""});
        j = root;
        j["bufferViews"][0]["byteOffset"] = 18446744073709551615ull;
        cases.push_back({"huge offset", rebuild(j), ""});
        j = root;
        j["accessors"][0]["byteOffset"] = 2147483647;
        cases.push_back({"accessor offset past the view", rebuild(j), ""});
    }
    // A PNG whose header declares an enormous image.
    {
        std::string b = bytes;
        const std::size_t png = b.find("\x89PNG\r\n\x1a\n", binHeader);
        ASSERT_NE(png, std::string::npos);
        // IHDR: length at +8, type at +12, width and height at +16 and +20, CRC at +29.
        putU32BigEndian(b, png + 16, 0x7FFFFFFFu);
        putU32BigEndian(b, png + 20, 0x7FFFFFFFu);
        putU32BigEndian(b, png + 29, crc32(b.data() + png + 12, 17));
        cases.push_back({"huge image", b, "image 0"});
    }

    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const std::string path = dir.file("bad.glb");
        writeFile(path, c.bytes);
        core::Result<core::Project> p = core::loadProject(path);
        ASSERT_FALSE(p.ok()) << c.name << " was accepted";
        std::printf("[ refused  ] %s: %s\n", c.name.c_str(), p.error().c_str());
        EXPECT_EQ(p.error().rfind(path + ": ", 0), 0u) << p.error();
        EXPECT_EQ(p.error().find('\n'), std::string::npos) << p.error();
        if (!c.expected.empty()) {
            EXPECT_NE(p.error().find(c.expected), std::string::npos) << p.error();
        }
    }
    // The good file still opens.
    EXPECT_TRUE(core::loadProject(good).ok());
}

TEST(Project, FileOpensInOtherGltfTools) {
    TempDir dir;
    core::Document doc;
    doc.setMesh(core::makeTrefoil(60, 16), "builtin:trefoil");
    core::PaintTargetOptions options;
    options.resolution = 512;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    paintSomething(doc);
    const std::string path = dir.file("knot.glb");
    ASSERT_TRUE(core::saveProject(path, doc, core::captureProjectState(doc)).ok());
    const core::Mesh painted = doc.paintedMesh();

    // tinygltf, with its own image decoder.
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, path)) << err;
    EXPECT_TRUE(err.empty()) << err;
    EXPECT_TRUE(warn.empty()) << warn;
    ASSERT_EQ(model.meshes.size(), 1u);
    ASSERT_EQ(model.images.size(), 1u);
    EXPECT_EQ(model.images[0].width, painted.textures[0].width);
    EXPECT_EQ(model.images[0].height, painted.textures[0].height);
    ASSERT_EQ(model.images[0].component, 4);
    EXPECT_EQ(model.images[0].image, painted.textures[0].rgba);
    std::size_t indices = 0;
    for (const tinygltf::Primitive& p : model.meshes[0].primitives)
        indices += std::size_t(model.accessors[std::size_t(p.indices)].count);
    EXPECT_EQ(indices, painted.indices.size());
    ASSERT_TRUE(model.asset.extras.IsObject());
    EXPECT_TRUE(model.asset.extras.Has("layerpaint"));

    // Assimp.
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    std::size_t faces = 0;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        faces += scene->mMeshes[m]->mNumFaces;
    EXPECT_EQ(faces, painted.triangleCount());
    EXPECT_GE(scene->mNumTextures + scene->mNumMaterials, 1u);
}

} // namespace project_test
