// SPDX-License-Identifier: GPL-3.0-or-later
// Brush tips through the headless tool: a textured, jittered stroke replays to the same bytes
// from the same seed, a loaded tip is kept in the project, and a bad tip file is one error line.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "core/io/export.h"
#include "core/io/gltf/glb_container.h"
#include "core/io/image/image_encode.h"
#include "core/io/project/project_file.h"
#include "tests/app/cli_run.h"

namespace cli_tips_gltest {

namespace fs = std::filesystem;
using cli_test::CliRun;
using nlohmann::json;

class CliTips : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("lpcli_tips_" + std::to_string(::getpid()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    std::string file(const std::string& name) const { return (m_dir / name).string(); }

    /** Paints script on the trefoil (GL capture) into NAME.glb; the project's first texture. */
    std::vector<std::uint8_t> paint(const json& brush, const std::string& name,
                                    CliRun* result = nullptr) {
        const json script = {
            {"size", "320x240"},
            {"orbit", "20,15,1.6"},
            {"target", {{"kind", "texture"}, {"resolution", 512}}},
            {"operations",
             {brush,
              {{"op", "stroke"}, {"points", {{90, 90}, {150, 120}, {220, 110}, {240, 160}}}}}}};
        std::ofstream(file(name + ".json")) << script.dump();
        const CliRun r = cli_test::runCli({"paint", "builtin:trefoil", "--script",
                                           file(name + ".json"), "--out", file(name + ".glb")},
                                          m_dir);
        if (result)
            *result = r;
        if (r.exitCode != 0)
            return {};
        auto project = core::loadProject(file(name + ".glb"));
        EXPECT_TRUE(project.ok()) << project.error();
        if (!project || project->mesh.textures.empty())
            return {};
        return project->mesh.textures[0].rgba;
    }

    fs::path m_dir;
};

json spatterBrush(std::uint32_t seed) {
    return {{"op", "set-brush"},
            {"color", "#2040ff"},
            {"radius", 14},
            {"tip", "spatter"},
            {"angle_mode", "random"},
            {"jitter", {{"size", 0.5}, {"opacity", 0.3}, {"angle", 40}, {"scatter", 1.5}}},
            {"seed", seed}};
}

TEST_F(CliTips, ASpatterStrokeWithJitterReplaysToTheSameBytes) {
    CliRun r;
    const auto first = paint(spatterBrush(42), "first", &r);
    ASSERT_FALSE(first.empty()) << r.err;
    EXPECT_EQ(first, paint(spatterBrush(42), "again"));
    const auto other = paint(spatterBrush(43), "other");
    ASSERT_EQ(other.size(), first.size());
    EXPECT_NE(other, first);
    json round = spatterBrush(42);
    round["tip"] = "round";
    round["jitter"] = {{"size", 0}, {"opacity", 0}, {"angle", 0}, {"scatter", 0}};
    EXPECT_NE(paint(round, "round"), first);
}

TEST_F(CliTips, ALoadedTipIsKeptInTheProject) {
    // A dark ring on white: the ring paints, the rest does not.
    core::Image ring;
    ring.width = ring.height = 40;
    ring.rgba.assign(40 * 40 * 4, 255);
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
            const float d = std::hypot(float(x) - 19.5f, float(y) - 19.5f);
            if (d > 10.0f && d < 17.0f)
                std::fill_n(&ring.rgba[std::size_t(y * 40 + x) * 4], 3, std::uint8_t(0));
        }
    auto png = core::encodeImage(ring, core::ExportFormat::Png8);
    ASSERT_TRUE(png.ok()) << png.error();
    std::ofstream(file("ring.png"), std::ios::binary)
        .write(reinterpret_cast<const char*>(png->data()), std::streamsize(png->size()));

    json brush = {{"op", "set-brush"}, {"radius", 20}, {"tip", file("ring.png")}, {"angle", 30}};
    CliRun r;
    ASSERT_FALSE(paint(brush, "ring", &r).empty()) << r.err;
    auto project = core::loadProject(file("ring.glb"));
    ASSERT_TRUE(project.ok()) << project.error();
    ASSERT_TRUE(project->state.has_value());
    const core::Brush& b = project->state->brush;
    EXPECT_EQ(b.tip, "user");
    EXPECT_EQ(b.userTipName, file("ring.png"));
    EXPECT_EQ(b.angle, 30.0f);
    ASSERT_TRUE(b.userTip);
    const core::TipImage expected = core::tipFromRgba(40, 40, ring.rgba);
    EXPECT_EQ(*b.userTip, expected);

    // Continuing the project paints with the restored tip, though the file is gone.
    fs::remove(file("ring.png"));
    std::ofstream(file("more.json"))
        << json{{"size", "320x240"},
                {"orbit", "20,15,1.6"},
                {"operations", {{{"op", "stroke"}, {"points", {{100, 100}, {200, 130}}}}}}}
               .dump();
    const CliRun more = cli_test::runCli(
        {"paint", file("ring.glb"), "--script", file("more.json"), "--out", file("more.glb")},
        m_dir);
    ASSERT_EQ(more.exitCode, 0) << more.err;
    auto again = core::loadProject(file("more.glb"));
    ASSERT_TRUE(again.ok()) << again.error();
    ASSERT_TRUE(again->state && again->state->brush.userTip);
    EXPECT_EQ(*again->state->brush.userTip, expected);
}

TEST_F(CliTips, AProjectWhoseTipCannotBeReadOpensWithTheRoundTipAndSaysSo) {
    core::Image dot{8, 8, {}};
    for (int i = 0; i < 8 * 8; ++i)
        dot.rgba.insert(dot.rgba.end(), {0, 0, 0, 255}); // black: paints everywhere
    auto png = core::encodeImage(dot, core::ExportFormat::Png8);
    ASSERT_TRUE(png.ok()) << png.error();
    std::ofstream(file("dot.png"), std::ios::binary)
        .write(reinterpret_cast<const char*>(png->data()), std::streamsize(png->size()));
    CliRun r;
    ASSERT_FALSE(paint({{"op", "set-brush"}, {"tip", file("dot.png")}}, "dot", &r).empty())
        << r.err;

    // The project's tip points at an image it does not have.
    std::ifstream in(file("dot.glb"), std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), {}};
    const auto layout = core::glb::readContainer(bytes);
    ASSERT_TRUE(layout.ok()) << layout.error();
    json gltf =
        json::parse(bytes.begin() + std::ptrdiff_t(layout->jsonOffset),
                    bytes.begin() + std::ptrdiff_t(layout->jsonOffset + layout->jsonLength));
    gltf["asset"]["extras"]["layerpaint"]["brush"]["tip_image"] = 9999;
    const std::vector<std::uint8_t> edited = core::glb::replaceJson(bytes, *layout, gltf.dump());
    std::ofstream(file("dot.glb"), std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(edited.data()), std::streamsize(edited.size()));

    const CliRun exported =
        cli_test::runCli({"export", file("dot.glb"), "--out", file("dot-out.png")}, m_dir);
    EXPECT_EQ(exported.exitCode, 0) << exported.err;
    EXPECT_NE(exported.err.find("layerpaint-cli: warning: " + file("dot.glb")), std::string::npos)
        << exported.err;
    EXPECT_NE(exported.err.find("the brush uses the round tip"), std::string::npos) << exported.err;
    const auto project = core::loadProject(file("dot.glb"));
    ASSERT_TRUE(project.ok()) << project.error();
    ASSERT_TRUE(project->state.has_value());
    EXPECT_EQ(project->state->brush.tip, "round");
}

TEST_F(CliTips, ABadTipFileIsOneErrorNamingIt) {
    std::ofstream(file("notes.png")) << "not an image at all";
    for (const std::string& name : {file("notes.png"), file("missing.tif")}) {
        CliRun r;
        paint({{"op", "set-brush"}, {"tip", name}}, "bad", &r);
        EXPECT_NE(r.exitCode, 0);
        EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

} // namespace cli_tips_gltest
