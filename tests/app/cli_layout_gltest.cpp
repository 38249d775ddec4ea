// SPDX-License-Identifier: GPL-3.0-or-later
// The headless tool on a model without UVs: `--target texture` (export and paint) and the script
// operation set-target with kind texture make the automatic UV layout, and what they write has
// the layout's UVs and the paint in its texture.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "tests/app/cli_run.h"

namespace cli_layout_gltest {

namespace fs = std::filesystem;
using nlohmann::json;

using cli_test::CliRun;

class CliLayout : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("lpcli_layout_" + std::to_string(::getpid()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
        // A box of eight vertices, without texture coordinates.
        std::ofstream(file("box.obj")) << "v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\n"
                                          "v -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n"
                                          "f 5 6 8\nf 5 8 7\nf 2 1 3\nf 2 3 4\n"
                                          "f 1 5 7\nf 1 7 3\nf 6 2 4\nf 6 4 8\n"
                                          "f 7 8 4\nf 7 4 3\nf 1 2 6\nf 1 6 5\n";
    }
    void TearDown() override { fs::remove_all(m_dir); }

    std::string file(const std::string& name) const { return (m_dir / name).string(); }
    CliRun run(const std::vector<std::string>& args) const { return cli_test::runCli(args, m_dir); }

    /** Texels of page whose colour is pure red (the strokes' colour). */
    static std::size_t redTexels(const core::Image& page) {
        std::size_t red = 0;
        for (std::size_t i = 0; i + 3 < page.rgba.size(); i += 4)
            red += page.rgba[i] == 255 && page.rgba[i + 1] == 0 && page.rgba[i + 2] == 0;
        return red;
    }

    fs::path m_dir;
};

const json kStroke = {{"op", "stroke"}, {"points", {{140, 110}, {160, 120}, {180, 130}}}};

TEST_F(CliLayout, ExportWithTargetTextureWritesTheLayoutsUvs) {
    const CliRun r = run({"export", file("box.obj"), "--target", "texture", "--resolution", "512",
                          "--out", file("box.glb")});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    core::Result<core::Mesh> box = core::loadMesh(file("box.glb"));
    ASSERT_TRUE(box.ok()) << box.error();
    EXPECT_TRUE(box->hasUvs());
    EXPECT_EQ(box->triangleCount(), 12u);
    EXPECT_GT(box->vertexCount(), 8u) << "seams split vertices";
    ASSERT_EQ(box->textures.size(), 1u);
    EXPECT_EQ(box->textures[0].width, 512);
}

TEST_F(CliLayout, PaintWithTargetTexturePaintsIntoTheLayout) {
    std::ofstream(file("s.json")) << json{
        {"size", "320x240"},
        {"orbit", "30,20,1.6"},
        {"operations",
         {{{"op", "set-brush"}, {"color", "#ff0000"}, {"radius", 8}},
          kStroke}}}.dump();
    const CliRun r = run({"paint", file("box.obj"), "--target", "texture", "--resolution", "512",
                          "--script", file("s.json"), "--out", file("p.glb"), "--cpu"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    core::Result<core::Project> p = core::loadProject(file("p.glb"));
    ASSERT_TRUE(p.ok()) << p.error();
    EXPECT_TRUE(p->mesh.hasUvs());
    ASSERT_EQ(p->mesh.textures.size(), 1u);
    EXPECT_GT(redTexels(p->mesh.textures[0]), 50u);
    EXPECT_TRUE(p->mesh.colors.empty());
}

TEST_F(CliLayout, ScriptOperationSetTargetTextureMakesTheLayout) {
    std::ofstream(file("s.json")) << json{
        {"size", "320x240"},
        {"orbit", "30,20,1.6"},
        {"operations",
         {{{"op", "set-target"}, {"kind", "texture"}, {"resolution", 512}},
          {{"op", "set-brush"}, {"color", "#ff0000"}, {"radius", 8}},
          kStroke}}}.dump();
    const CliRun r = run(
        {"paint", file("box.obj"), "--script", file("s.json"), "--out", file("p.glb"), "--cpu"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    core::Result<core::Project> p = core::loadProject(file("p.glb"));
    ASSERT_TRUE(p.ok()) << p.error();
    EXPECT_TRUE(p->mesh.hasUvs());
    ASSERT_EQ(p->mesh.textures.size(), 1u);
    EXPECT_GT(redTexels(p->mesh.textures[0]), 50u);

    // Reopened, the project paints on the same UVs without a new layout.
    const CliRun again = run({"export", file("p.glb"), "--out", file("again.glb")});
    ASSERT_EQ(again.exitCode, 0) << again.err;
    core::Result<core::Mesh> reopened = core::loadMesh(file("again.glb"));
    ASSERT_TRUE(reopened.ok()) << reopened.error();
    EXPECT_EQ(reopened->uvs, p->mesh.uvs);
}

} // namespace cli_layout_gltest
