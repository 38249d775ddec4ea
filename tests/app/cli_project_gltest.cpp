// SPDX-License-Identifier: GPL-3.0-or-later
// The headless tool's projects and exports: `paint --out` writes a project with the script's end
// state (the GUI's save path), a project given to `paint` continues where it stopped, and
// `export` writes every format from a project.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "core/io/gltf/gltf_export.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/paint/targets/paint_target.h"
#include "tests/app/cli_run.h"

namespace cli_project_gltest {

namespace fs = std::filesystem;
using nlohmann::json;

using cli_test::CliRun;
using cli_test::readFile;

class CliProject : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("lpcli_project_" + std::to_string(::getpid()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string file(const std::string& name) const { return (m_dir / name).string(); }

    CliRun run(const std::vector<std::string>& args) const { return cli_test::runCli(args, m_dir); }

    void writeScript(const std::string& name, const json& script) const {
        std::ofstream(file(name)) << script.dump();
    }

    fs::path m_dir;
};

const json kFirstScript = {
    {"size", "320x240"},
    {"orbit", "20,15,1.6"},
    {"target", {{"kind", "texture"}, {"resolution", 1024}}},
    {"operations",
     {{{"op", "set-mode"}, {"layer_aware", false}},
      {{"op", "set-brush"}, {"color", "#ff0000"}, {"radius", 9}, {"hardness", 0.75}},
      {{"op", "stroke"}, {"points", {{120, 100}, {140, 120}, {160, 140}}}}}}};

TEST_F(CliProject, PaintSavesAProjectWithTheScriptsState) {
    writeScript("a.json", kFirstScript);
    const CliRun r = run({"paint", "builtin:trefoil", "--script", file("a.json"), "--out",
                          file("knot.glb"), "--cpu"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    core::Result<core::Project> p = core::loadProject(file("knot.glb"));
    ASSERT_TRUE(p.ok()) << p.error();
    ASSERT_TRUE(p->state.has_value());
    const core::ProjectState& s = *p->state;
    EXPECT_EQ(s.formatVersion, core::kProjectFormatVersion);
    EXPECT_EQ(s.source, "builtin:trefoil");
    EXPECT_EQ(s.brush.radius, 9.0f);
    EXPECT_EQ(s.brush.hardness, 0.75f);
    EXPECT_NEAR(s.brush.color.r, 1.0f, 1e-6f);
    EXPECT_FALSE(s.layerAware);
    EXPECT_EQ(s.target.kind, core::PaintTargetKind::Texture);
    EXPECT_EQ(s.target.resolution, 1024);
    ASSERT_TRUE(s.camera.has_value());
    EXPECT_EQ(s.camera->yawDegrees, 20.0f);
    EXPECT_EQ(s.camera->pitchDegrees, 15.0f);
    ASSERT_EQ(p->mesh.textures.size(), 1u);
    EXPECT_EQ(p->mesh.textures[0].width, 1024);
    // Red paint landed in the texture.
    std::size_t red = 0;
    for (std::size_t i = 0; i < p->mesh.textures[0].rgba.size(); i += 4)
        red += p->mesh.textures[0].rgba[i] == 255 && p->mesh.textures[0].rgba[i + 1] == 0;
    EXPECT_GT(red, 50u);

    // Saving over it keeps the previous version as the backup.
    const CliRun again = run({"paint", "builtin:trefoil", "--script", file("a.json"), "--out",
                              file("knot.glb"), "--cpu"});
    ASSERT_EQ(again.exitCode, 0) << again.err;
    EXPECT_TRUE(fs::exists(file("knot.glb.bak")));
}

TEST_F(CliProject, PaintContinuesAProject) {
    writeScript("a.json", kFirstScript);
    ASSERT_EQ(run({"paint", "builtin:trefoil", "--script", file("a.json"), "--out", file("one.glb"),
                   "--cpu"})
                  .exitCode,
              0);
    // No brush settings, no orbit: the project's brush, mode, target and view carry on.
    writeScript("b.json",
                json{{"size", "320x240"},
                     {"operations", {{{"op", "stroke"}, {"points", {{150, 90}, {170, 95}}}}}}});
    const CliRun r = run(
        {"paint", file("one.glb"), "--script", file("b.json"), "--out", file("two.glb"), "--cpu"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    core::Result<core::Project> one = core::loadProject(file("one.glb"));
    core::Result<core::Project> two = core::loadProject(file("two.glb"));
    ASSERT_TRUE(one.ok() && two.ok());
    ASSERT_TRUE(two->state.has_value());
    EXPECT_EQ(two->state->source, "builtin:trefoil");
    EXPECT_EQ(two->state->brush.radius, 9.0f);
    EXPECT_FALSE(two->state->layerAware);
    EXPECT_EQ(two->state->camera->yawDegrees, 20.0f);
    ASSERT_EQ(two->mesh.textures.size(), 1u);
    const std::vector<std::uint8_t>& a = one->mesh.textures[0].rgba;
    const std::vector<std::uint8_t>& b = two->mesh.textures[0].rgba;
    ASSERT_EQ(a.size(), b.size());
    std::size_t kept = 0, added = 0;
    for (std::size_t i = 0; i < a.size(); i += 4) {
        const bool wasRed = a[i] == 255 && a[i + 1] == 0;
        const bool isRed = b[i] == 255 && b[i + 1] == 0;
        kept += wasRed && isRed;
        added += !wasRed && isRed;
        EXPECT_FALSE(wasRed && !isRed) << "paint of the first session was lost";
    }
    EXPECT_GT(kept, 50u);
    EXPECT_GT(added, 50u);
}

TEST_F(CliProject, ExportWritesEveryFormat) {
    writeScript("a.json", kFirstScript);
    ASSERT_EQ(run({"paint", "builtin:trefoil", "--script", file("a.json"), "--out",
                   file("knot.glb"), "--cpu"})
                  .exitCode,
              0);
    core::Result<core::Project> project = core::loadProject(file("knot.glb"));
    ASSERT_TRUE(project.ok());
    const core::Mesh& painted = project->mesh;
    for (const char* name : {"export.glb", "export.obj", "export.ply"}) {
        SCOPED_TRACE(name);
        const CliRun r = run({"export", file("knot.glb"), "--out", file(name)});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        const json report = json::parse(r.out);
        EXPECT_GE(report["export_ms"].get<double>(), 0.0);
        core::Result<core::Mesh> back = core::loadMesh(file(name));
        ASSERT_TRUE(back.ok()) << back.error();
        EXPECT_EQ(back->triangleCount(), painted.triangleCount());
        if (std::string(name) != "export.ply") {
            ASSERT_EQ(back->textures.size(), 1u);
            EXPECT_TRUE(back->textures[0].rgba == painted.textures[0].rgba);
        } else {
            EXPECT_TRUE(back->hasColors());
        }
    }
    EXPECT_TRUE(fs::exists(file("export.mtl")));
    EXPECT_TRUE(fs::exists(file("export_1.png")));
    for (const char* name : {"paint.png", "paint.tif", "paint.exr"}) {
        const CliRun r = run({"export", file("knot.glb"), "--out", file(name)});
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
        EXPECT_TRUE(fs::exists(file(name)));
    }
    const CliRun wide =
        run({"export", file("knot.glb"), "--out", file("paint16.png"), "--format", "png16"});
    ASSERT_EQ(wide.exitCode, 0) << wide.err;

    // A plain model converts; a vertex-colour model has no texture to export.
    ASSERT_EQ(run({"export", "builtin:hexring", "--out", file("ring.obj")}).exitCode, 0);
    const CliRun none =
        run({"export", "builtin:hexring", "--out", file("ring.png"), "--target", "vertex-colors"});
    EXPECT_NE(none.exitCode, 0);
    EXPECT_NE(none.err.find("vertex colours"), std::string::npos) << none.err;
    const CliRun unknown = run({"export", "builtin:hexring", "--out", file("ring.xyz")});
    EXPECT_NE(unknown.exitCode, 0);
    EXPECT_NE(unknown.err.find("unknown export format"), std::string::npos) << unknown.err;
}

TEST_F(CliProject, ExportThroughAPresetWritesEachMapOfTheTextureSet) {
    writeScript("a.json", kFirstScript);
    ASSERT_EQ(run({"paint", "builtin:trefoil", "--script", file("a.json"), "--out",
                   file("knot.glb"), "--cpu"})
                  .exitCode,
              0);
    const CliRun r = run({"export", file("knot.glb"), "--preset", "unity", "--out", file("unity"),
                          "--size", "256", "--map-format", "tga"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json report = json::parse(r.out);
    EXPECT_EQ(report["format"], "tga");
    const std::vector<std::string> expected = {
        "knot_trefoil_BaseMap.tga", "knot_trefoil_MaskMap.tga", "knot_trefoil_Normal.tga",
        "knot_trefoil_Emission.tga"};
    ASSERT_EQ(report["files"].size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const fs::path written = report["files"][i].get<std::string>();
        EXPECT_EQ(written.filename().string(), expected[i]);
        core::Result<core::Image> image = core::loadImageFile(written.string());
        ASSERT_TRUE(image.ok()) << image.error();
        EXPECT_EQ(image->width, 256);
    }
    // The painted red reaches the base map (a 1024² stroke seen at 256²).
    core::Result<core::Image> base = core::loadImageFile(file("unity/knot_trefoil_BaseMap.tga"));
    ASSERT_TRUE(base.ok());
    bool red = false;
    for (std::size_t i = 0; i < base->rgba.size(); i += 4)
        red = red || (base->rgba[i] > 200 && base->rgba[i + 1] < 60 && base->rgba[i + 2] < 60);
    EXPECT_TRUE(red);

    const CliRun unknown =
        run({"export", file("knot.glb"), "--preset", "frostbite", "--out", file("x")});
    EXPECT_NE(unknown.exitCode, 0);
    EXPECT_NE(unknown.err.find("gltf, unreal, unity, orm"), std::string::npos) << unknown.err;
    const CliRun both = run(
        {"export", file("knot.glb"), "--preset", "unity", "--format", "png", "--out", file("x")});
    EXPECT_NE(both.exitCode, 0);
    const CliRun depth = run({"export", file("knot.glb"), "--preset", "unity", "--map-format",
                              "tga", "--bit-depth", "16", "--out", file("x")});
    EXPECT_NE(depth.exitCode, 0);
    EXPECT_NE(depth.err.find("cannot hold 16-bit"), std::string::npos) << depth.err;
}

TEST_F(CliProject, PaintAndExportSayWhatLoadingCorrected) {
    json state = core::projectStateToJson({});
    state["brush"]["opacity"] = 7; // out of range: the default is used, with a warning
    ASSERT_TRUE(core::saveGlb(file("odd.glb"), core::loadMesh("builtin:row").value(),
                              {{"layerpaint", state}})
                    .ok());
    writeScript("a.json", kFirstScript);
    const CliRun exported = run({"export", file("odd.glb"), "--out", file("x.obj")});
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    EXPECT_NE(exported.err.find("layerpaint-cli: warning: "), std::string::npos) << exported.err;
    EXPECT_NE(exported.err.find("opacity"), std::string::npos) << exported.err;
    const json out = json::parse(exported.out);
    ASSERT_EQ(out["warnings"].size(), 1u) << out.dump();
    EXPECT_NE(out["warnings"][0].get<std::string>().find("opacity"), std::string::npos);
    const CliRun painted = run(
        {"paint", file("odd.glb"), "--script", file("a.json"), "--out", file("y.glb"), "--cpu"});
    ASSERT_EQ(painted.exitCode, 0) << painted.err;
    EXPECT_NE(painted.err.find("layerpaint-cli: warning: "), std::string::npos) << painted.err;
}

TEST_F(CliProject, MessagesQuotingAFileAreOneEscapedLine) {
    const std::string name = file("a\nlayerpaint-cli: forged\x1b[2J.glb");
    const CliRun r = run({"export", name, "--out", file("x.obj")});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("a\\nlayerpaint-cli: forged\\x1b[2J.glb"), std::string::npos) << r.err;
}

TEST_F(CliProject, NewerProjectIsRefusedByPaintAndExport) {
    json state = core::projectStateToJson({});
    state["version"] = core::kProjectFormatVersion + 5;
    ASSERT_TRUE(core::saveGlb(file("future.glb"), core::loadMesh("builtin:row").value(),
                              {{"layerpaint", state}})
                    .ok());
    writeScript("a.json", kFirstScript);
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"paint", file("future.glb"), "--script", file("a.json"), "--out",
                                   file("x.glb"), "--cpu"},
          std::vector<std::string>{"export", file("future.glb"), "--out", file("x.obj")}}) {
        const CliRun r = run(args);
        EXPECT_NE(r.exitCode, 0);
        EXPECT_NE(r.err.find(file("future.glb") + ": was saved by a newer LayerPaint"),
                  std::string::npos)
            << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(file("x.glb")));
    EXPECT_FALSE(fs::exists(file("x.obj")));
}

TEST_F(CliProject, ExportPerLayerWritesEachPaintLayersChannelsAndMask) {
    json script = kFirstScript;
    script["operations"] = {
        {{"op", "set-mode"}, {"layer_aware", false}},
        {{"op", "layer-add"}, {"name", "Rust & chrome/1"}},
        {{"op", "set-brush"},
         {"radius", 9},
         {"hardness", 1.0},
         {"channels", {{"base_color", "#00ff00"}, {"roughness", 0.2}, {"metallic", 1.0}}}},
        {{"op", "stroke"}, {"points", {{120, 100}, {140, 120}, {160, 140}}}},
        {{"op", "mask-add"}},
        {{"op", "layer-add"},
         {"name", "tint"},
         {"kind", "fill"},
         {"values", {{"roughness", 0.6}}}}};
    writeScript("layers.json", script);
    ASSERT_EQ(run({"paint", "builtin:trefoil", "--script", file("layers.json"), "--out",
                   file("layers.glb"), "--cpu"})
                  .exitCode,
              0);
    const CliRun r = run({"export", file("layers.glb"), "--out", file("out.png"), "--per-layer"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const json report = json::parse(r.out);
    std::vector<std::string> files;
    for (const auto& f : report.at("files"))
        files.push_back(fs::path(f.get<std::string>()).filename().string());
    for (const char* expected :
         {"out.png", "out_roughness.png", "out_metallic.png",
          "out_layer-1-Rust-chrome-1_basecolor.png", "out_layer-1-Rust-chrome-1_roughness.png",
          "out_layer-1-Rust-chrome-1_metallic.png", "out_layer-1-Rust-chrome-1_mask.png",
          "out_layer-2-tint_roughness.png"})
        EXPECT_NE(std::find(files.begin(), files.end(), expected), files.end())
            << expected << " not in " << r.out;
    // The fill layer has roughness only.
    EXPECT_FALSE(fs::exists(file("out_layer-2-tint_basecolor.png")));

    // The painted layer's roughness: 0.2 where painted (covered), nothing elsewhere.
    core::Result<core::Image> rough =
        core::loadImageFile(file("out_layer-1-Rust-chrome-1_roughness.png"));
    ASSERT_TRUE(rough) << rough.error();
    std::size_t painted = 0, clear = 0;
    for (std::size_t i = 0; i < rough->rgba.size(); i += 4) {
        if (rough->rgba[i + 3] == 255) {
            ++painted;
            EXPECT_EQ(rough->rgba[i], 51);
        } else if (rough->rgba[i + 3] == 0) {
            ++clear;
        }
    }
    EXPECT_GT(painted, 50u);
    EXPECT_GT(clear, rough->rgba.size() / 8);
    core::Result<core::Image> fill = core::loadImageFile(file("out_layer-2-tint_roughness.png"));
    ASSERT_TRUE(fill) << fill.error();
    EXPECT_EQ(fill->rgba[0], 153);

    // Without a paint texture there are no paint layers: a clear error.
    const CliRun none = run({"export", "builtin:hexring", "--out", file("ring.png"), "--target",
                             "vertex-colors", "--per-layer"});
    EXPECT_NE(none.exitCode, 0);
}

} // namespace cli_project_gltest
