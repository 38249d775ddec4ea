// SPDX-License-Identifier: GPL-3.0-or-later
// The headless tool's contract (docs/architecture.md §4), checked by running the real binary.
#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

#include <OpenImageIO/imageio.h>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/depth/cpu_capture.h"
#include "core/depth/depth_layers.h"
#include "core/io/mesh_io.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "tests/app/cli_run.h"

namespace cli_gltest {

namespace fs = std::filesystem;
using nlohmann::json;

using cli_test::CliRun;
using cli_test::readFile;

/** The folder of this test process for the CLI's output. */
fs::path outputFolder() {
    return fs::temp_directory_path() / ("lpcli_" + std::to_string(::getpid()));
}

/** Removes the output folder when the process's tests are done. */
class OutputFolderCleanup : public testing::Environment {
public:
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(outputFolder(), ec);
    }
};
[[maybe_unused]] testing::Environment* const kCleanup =
    testing::AddGlobalTestEnvironment(new OutputFolderCleanup);

/** Runs layerpaint-cli with arguments, its output kept in a folder of this test process. */
CliRun runCli(const std::vector<std::string>& args) {
    const fs::path dir = outputFolder();
    fs::create_directories(dir);
    return cli_test::runCli(args, dir);
}

std::vector<std::uint32_t> readUInt32Image(const fs::path& path, int& width, int& height) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in)
        return {};
    width = in->spec().width;
    height = in->spec().height;
    std::vector<std::uint32_t> pixels(std::size_t(width) * height);
    in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT32, pixels.data());
    return pixels;
}

const std::string kBox =
    std::string(LAYERPAINT_ASSIMP_MODELS) + "/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";

TEST(Cli, RunsWithHugePagesWhereTheKernelGivesThemOnRequest) {
    // Started without glibc's setting, it starts again with it (bench says whether its malloc
    // has it): a large model's arrays then fill without a page fault every 4 KiB.
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    const std::string mode{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "layerpaint_cli";
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / "huge_pages.json";
    const std::string command = std::string("env -u GLIBC_TUNABLES -u LAYERPAINT_HUGE_PAGES '") +
                                LAYERPAINT_CLI + "' bench builtin:hexring --runs 1 --size 64x48 " +
                                "--json '" + file.string() + "' > /dev/null 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    const nlohmann::json result = nlohmann::json::parse(cli_test::readFile(file), nullptr, false);
    ASSERT_TRUE(result.is_object() && result.contains("huge_pages"));
    EXPECT_EQ(result["huge_pages"].get<bool>(), mode.find("[madvise]") != std::string::npos)
        << mode;
}

TEST(Cli, InfoPrintsTheModelSummary) {
    const CliRun run = runCli({"info", "builtin:trefoil"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json info = json::parse(run.out);
    EXPECT_EQ(info["vertices"], 144000);
    EXPECT_EQ(info["triangles"], 284886);
    EXPECT_EQ(info["has_uvs"], true);
    EXPECT_EQ(info["materials"].size(), 1u);
    EXPECT_LT(info["bounds"]["min"][0].get<double>(), -2.5);
}

TEST(Cli, InfoOfATexturedGltf) {
    if (!fs::exists(kBox))
        GTEST_SKIP() << "assimp-testmodels not installed";
    const CliRun run = runCli({"info", kBox});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json info = json::parse(run.out);
    EXPECT_EQ(info["vertices"], 24);
    EXPECT_EQ(info["triangles"], 12);
    EXPECT_EQ(info["materials"][0]["base_color_texture"]["width"], 211); // CesiumLogoFlat.png
    // Strokes go into that texture at its size, not into a 2048² one.
    EXPECT_EQ(info["materials"][0]["paint_texture"], json({{"width", 211}, {"height", 211}}));
    // Its six faces share the logo: the UVs stay, with a warning.
    ASSERT_EQ(info["warnings"].size(), 1u);
    EXPECT_NE(info["warnings"][0].get<std::string>().find("covered by two or more triangles"),
              std::string::npos);
}

TEST(Cli, InfoOfAMaterialWithoutATextureNamesTheNewTexturesSize) {
    const CliRun run = runCli({"info", "builtin:knot?triangles=2000"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json info = json::parse(run.out);
    EXPECT_EQ(info["materials"][0]["paint_texture"], json({{"width", 2048}, {"height", 2048}}));
}

TEST(Cli, BadInputIsOneLineOnStderrAndAFailureCode) {
    const fs::path empty = fs::temp_directory_path() / "layerpaint cli empty.obj";
    std::ofstream(empty).close();
    for (const std::string& model :
         {empty.string(), std::string("/no/such/model.glb"), std::string("builtin:teapot")}) {
        const CliRun run = runCli({"info", model});
        EXPECT_NE(run.exitCode, 0) << model;
        EXPECT_TRUE(run.out.empty()) << model;
        ASSERT_FALSE(run.err.empty()) << model;
        EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
        EXPECT_NE(run.err.find(model), std::string::npos) << run.err;
    }
    const CliRun badSize = runCli({"layers", "builtin:row", "--size", "12by7", "--out", "/tmp/x"});
    EXPECT_NE(badSize.exitCode, 0);
    EXPECT_NE(badSize.err.find("--size"), std::string::npos);
}

/** A file's names may hold any bytes; info still prints JSON (found by the fuzz run). */
TEST(Cli, InfoPrintsJsonForNamesThatAreNotUtf8) {
    const fs::path obj = fs::temp_directory_path() / "layerpaint cli latin1.obj";
    std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl T\xffim\nf 1 2 3\n";
    const CliRun run = runCli({"info", obj.string()});
    fs::remove(obj);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json info = json::parse(run.out);
    bool replaced = false;
    for (const json& material : info["materials"])
        replaced = replaced || material["name"] == "T\xef\xbf\xbdim"; // U+FFFD for the byte
    EXPECT_TRUE(replaced) << run.out;
}

/** The OFF file that crashes Assimp 5.2: the importer process stops, the CLI reports it. */
TEST(Cli, AFileThatCrashesTheParserIsAnErrorNotACrash) {
    const std::string crasher = std::string(LAYERPAINT_TEST_DATA) + "/crashers/off-assimp-segv.off";
    const CliRun run = runCli({"info", crasher});
    EXPECT_EQ(run.exitCode, 1) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
    EXPECT_EQ(run.err.rfind("layerpaint-cli: " + crasher + ": the importer stopped: ", 0), 0u)
        << run.err;
}

/** layers --cpu writes exactly what the controller computes in process. */
TEST(Cli, LayersWritesTheFilesOfTheContract) {
    const fs::path out = fs::temp_directory_path() / "layerpaint_cli_layers";
    fs::remove_all(out);
    const CliRun run = runCli({"layers", "builtin:hexring", "--orbit", "20,35,2.5", "--size",
                               "160x120", "--cpu", "--out", out.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;

    auto mesh = core::loadMesh("builtin:hexring");
    ASSERT_TRUE(mesh);
    core::Camera camera = core::Camera::fromOrbit(mesh->bounds(), 20, 35, 2.5f);
    core::CpuDepthCapturer capturer;
    capturer.setMesh(*mesh);
    const core::MeshTopology topology = core::buildMeshTopology(*mesh);
    auto layers = core::buildDepthLayers(capturer, *mesh, topology, camera.view(160, 120), {});
    ASSERT_TRUE(layers);

    const json summary = json::parse(readFile(out / "summary.json"));
    const auto perLayer = layers->stack.fragmentsPerLayer();
    ASSERT_GE(perLayer.size(), 2u); // the inner wall lies behind the outer one
    EXPECT_EQ(summary["layers"], perLayer.size());
    EXPECT_EQ(summary["regions"], layers->segmentation.graph.regions.size());
    const json regions = json::parse(readFile(out / "regions.json"));
    ASSERT_EQ(regions.size(), layers->segmentation.graph.regions.size());
    std::uint64_t regionPixels = 0;
    for (const json& r : regions)
        regionPixels += r["pixels"].get<std::uint64_t>();
    EXPECT_EQ(regionPixels, layers->stack.fragmentCount());

    for (std::uint32_t layer = 1; layer <= perLayer.size(); ++layer) {
        const std::string n = std::to_string(layer);
        for (const char* name : {"depth_", "conn_"})
            EXPECT_TRUE(fs::exists(out / (name + n + (name[0] == 'd' ? ".exr" : ".png"))));
        int w = 0, h = 0;
        const auto tri = readUInt32Image(out / ("tri_" + n + ".tif"), w, h);
        const auto region = readUInt32Image(out / ("region_" + n + ".tif"), w, h);
        ASSERT_EQ(w, 160);
        ASSERT_EQ(h, 120);
        for (std::size_t p = 0; p < tri.size(); ++p) {
            const std::uint32_t f = layers->stack.fragment(p, layer);
            ASSERT_EQ(tri[p], f == core::kNone ? 0 : layers->stack.triangle[f] + 1);
            ASSERT_EQ(region[p], f == core::kNone ? 0 : layers->segmentation.region[f] + 1);
        }
    }
    EXPECT_FALSE(fs::exists(out / ("tri_" + std::to_string(perLayer.size() + 1) + ".tif")));
    // mesh.ply: the header announces the flattened triangles in id order.
    const std::string ply = readFile(out / "mesh.ply");
    EXPECT_NE(ply.find("element face " + std::to_string(mesh->triangleCount())), std::string::npos);
}

TEST(Cli, LayersScriptPopsUpAndHidesBeforeWritingTheVisibleMap) {
    const fs::path out = fs::temp_directory_path() / "layerpaint_cli_visible";
    fs::remove_all(out);
    const std::vector<std::string> common = {"layers", "builtin:hexring", "--orbit", "20,35,2.5",
                                             "--size", "160x120",         "--cpu"};
    auto args = common;
    args.insert(args.end(), {"--out", (out / "plain").string()});
    CliRun run = runCli(args);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    int w = 0, h = 0;
    const auto tri1 = readUInt32Image(out / "plain" / "tri_1.tif", w, h);
    const auto tri2 = readUInt32Image(out / "plain" / "tri_2.tif", w, h);
    const auto plain = readUInt32Image(out / "plain" / "visible.tif", w, h);
    ASSERT_EQ(plain.size(), std::size_t(160 * 120));
    // Without a script: layer 1 wherever there is a surface.
    std::size_t deep = tri2.size();
    for (std::size_t p = 0; p < plain.size(); ++p) {
        ASSERT_EQ(plain[p], tri1[p] ? 1u : 0u) << p;
        if (tri2[p] && deep == tri2.size() && p % 160 > 2 && p % 160 < 157)
            deep = p;
    }
    ASSERT_LT(deep, tri2.size()) << "no pixel with two layers";
    const int x = int(deep % 160), y = int(deep / 160);

    // Pop up at a two-layer pixel: layer 2 shows there; then hide what shows at a layer-1-only
    // pixel.
    std::size_t single = 0;
    while (single < tri1.size() && !(tri1[single] && !tri2[single]))
        ++single;
    ASSERT_LT(single, tri1.size());
    const json script = {{"operations",
                          {{{"op", "popup"}, {"at", {x, y}}},
                           {{"op", "hide"}, {"at", {{int(single % 160), int(single / 160)}}}}}}};
    fs::create_directories(out);
    std::ofstream(out / "script.json") << script.dump();
    args = common;
    args.insert(args.end(),
                {"--out", (out / "script").string(), "--script", (out / "script.json").string()});
    run = runCli(args);
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const auto visible = readUInt32Image(out / "script" / "visible.tif", w, h);
    ASSERT_EQ(visible.size(), plain.size());
    EXPECT_EQ(visible[deep], 2u);
    EXPECT_EQ(visible[single], 0u); // hidden, nothing behind it
    std::size_t second = 0;
    for (std::size_t p = 0; p < visible.size(); ++p) {
        ASSERT_LE(visible[p], tri2[p] ? 2u : 1u);
        second += visible[p] == 2;
    }
    EXPECT_GT(second, 20u); // the whole popped-up region, not one pixel

    // A pop-up on background is a clear error naming the script and the operation.
    std::ofstream(out / "bad.json") << json::array({{{"op", "popup"}, {"at", {0, 0}}}}).dump();
    args = common;
    args.insert(args.end(),
                {"--out", (out / "bad").string(), "--script", (out / "bad.json").string()});
    run = runCli(args);
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.err.find("bad.json: operation 1: nothing to pop up"), std::string::npos)
        << run.err;
}

TEST(Cli, OrbitAboutKeepsThePickedPointUnderThePixel) {
    const fs::path out = fs::temp_directory_path() / "layerpaint_cli_orbit_about";
    fs::remove_all(out);
    fs::create_directories(out);
    // Turning about the surface point under a pixel keeps that point under the pixel.
    constexpr int kWidth = 160, kHeight = 120, kX = 84, kY = 62;
    constexpr float kYaw = 50.0f, kPitch = 20.0f;
    const json script = {
        {"operations",
         {{{"op", "orbit-about"}, {"at", {kX, kY}}, {"yaw", kYaw}, {"pitch", kPitch}}}}};
    std::ofstream(out / "script.json") << script.dump();
    const CliRun run =
        runCli({"layers", "builtin:row", "--orbit", "0,0,1.2", "--size", "160x120", "--cpu",
                "--out", out.string(), "--script", (out / "script.json").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const std::size_t pixel = std::size_t(kY * kWidth + kX);

    // Before the turn (the layer images and summary.json are of the starting view): the point P
    // seen at the pixel's centre, from the tool's depth image and matrices.
    int w = 0, h = 0;
    const auto before = readUInt32Image(out / "tri_1.tif", w, h);
    ASSERT_EQ(before.size(), std::size_t(kWidth * kHeight));
    ASSERT_NE(before[pixel], 0u);
    std::vector<float> depth(before.size(), 0.0f);
    {
        auto in = OIIO::ImageInput::open((out / "depth_1.exr").string());
        ASSERT_TRUE(in);
        ASSERT_TRUE(in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, depth.data()));
    }
    ASSERT_GT(depth[pixel], 0.0f);
    const json summary = json::parse(readFile(out / "summary.json"));
    const auto viewMatrix = summary["view"].get<std::vector<float>>();
    const auto projMatrix = summary["proj"].get<std::vector<float>>();
    ASSERT_EQ(viewMatrix.size(), 16u);
    ASSERT_EQ(projMatrix.size(), 16u);
    core::View view;
    view.width = kWidth;
    view.height = kHeight;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) {
            view.view[c][r] = viewMatrix[std::size_t(c * 4 + r)];
            view.proj[c][r] = projMatrix[std::size_t(c * 4 + r)];
        }
    const glm::vec2 centre(float(kX) + 0.5f, float(kY) + 0.5f);
    const glm::vec3 point = view.unproject(centre, depth[pixel]);

    // After the turn: visible.tif is the map of the view the script ended in. It must be the map
    // of the view turned about P, whose front surface at the pixel is P's triangle at P's depth.
    const core::View turned = view.orbitedAbout(point, kYaw, kPitch);
    const glm::vec3 projected = turned.project(point);
    EXPECT_NEAR(projected.x, centre.x, 0.01f);
    EXPECT_NEAR(projected.y, centre.y, 0.01f);
    auto mesh = core::loadMesh("builtin:row");
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    const core::DepthStack after = core::captureDepthLayersCpu(*mesh, turned);
    const std::uint32_t front = after.fragment(pixel, 1);
    ASSERT_NE(front, core::kNone);
    EXPECT_EQ(after.triangle[front] + 1, before[pixel]);
    const float pointDepth = -(turned.view * glm::vec4(point, 1.0f)).z;
    EXPECT_NEAR(after.depth[front], pointDepth, 1e-4f * pointDepth);

    const auto visible = readUInt32Image(out / "visible.tif", w, h);
    ASSERT_EQ(visible.size(), before.size());
    EXPECT_EQ(visible[pixel], 1u);
    // The tool turned about P: its map is the turned view's, and differs from the starting
    // view's. The tolerance is far below what a pivot one pixel to the side gives (about 100).
    const auto differing = [&](const core::DepthStack& stack) {
        std::size_t n = 0;
        for (std::size_t p = 0; p < visible.size(); ++p)
            n += (visible[p] != 0) != (stack.layerCount(p) > 0);
        return n;
    };
    constexpr std::size_t kTolerance = 3;
    EXPECT_LE(differing(after), kTolerance);
    ASSERT_GT(depth[pixel + 1], 0.0f);
    const glm::vec3 beside = view.unproject(centre + glm::vec2(1.0f, 0.0f), depth[pixel + 1]);
    EXPECT_GT(
        differing(core::captureDepthLayersCpu(*mesh, view.orbitedAbout(beside, kYaw, kPitch))),
        10 * kTolerance);
    std::size_t changed = 0;
    for (std::size_t p = 0; p < visible.size(); ++p)
        changed += (visible[p] != 0) != (before[p] != 0);
    EXPECT_GT(changed, 1000u);
}

TEST(Cli, LayersOnOpenGlMatchesTheCpuCapture) {
    const fs::path gl = fs::temp_directory_path() / "layerpaint_cli_gl";
    const fs::path cpu = fs::temp_directory_path() / "layerpaint_cli_cpu";
    const std::vector<std::string> common = {"layers",    "builtin:trefoil", "--orbit",
                                             "20,15,1.6", "--size",          "320x240"};
    auto withOut = [&](const fs::path& dir, bool useCpu) {
        std::vector<std::string> args = common;
        if (useCpu)
            args.push_back("--cpu");
        args.insert(args.end(), {"--out", dir.string()});
        return args;
    };
    const CliRun glRun = runCli(withOut(gl, false));
    ASSERT_EQ(glRun.exitCode, 0) << glRun.err;
    const CliRun cpuRun = runCli(withOut(cpu, true));
    ASSERT_EQ(cpuRun.exitCode, 0) << cpuRun.err;
    const json a = json::parse(readFile(gl / "summary.json"));
    const json b = json::parse(readFile(cpu / "summary.json"));
    EXPECT_EQ(a["capture"], "gl");
    EXPECT_EQ(a["layers"], b["layers"]);
    EXPECT_EQ(a["fragments_per_layer"], b["fragments_per_layer"]);
    EXPECT_EQ(a["regions"], b["regions"]);
}

TEST(Cli, CameraFileGivesTheSameViewAsOrbit) {
    const fs::path a = fs::temp_directory_path() / "layerpaint_cli_orbit";
    const fs::path b = fs::temp_directory_path() / "layerpaint_cli_camera";
    ASSERT_EQ(runCli({"layers", "builtin:row", "--orbit", "30,10,3", "--size", "200x100", "--cpu",
                      "--out", a.string()})
                  .exitCode,
              0);
    const json summary = json::parse(readFile(a / "summary.json"));
    const fs::path cameraFile = fs::temp_directory_path() / "layerpaint_camera.json";
    std::ofstream(cameraFile) << json{{"view", summary["view"]}, {"proj", summary["proj"]}}.dump();
    const CliRun run = runCli({"layers", "builtin:row", "--camera", cameraFile.string(), "--size",
                               "200x100", "--cpu", "--out", b.string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    const json other = json::parse(readFile(b / "summary.json"));
    EXPECT_EQ(other["fragments_per_layer"], summary["fragments_per_layer"]);
    EXPECT_EQ(other["regions"], summary["regions"]);
}

/** builtin:row's four bodies: per body, how many triangles have rgb (±3) at their centre texel. */
std::array<int, 4> rowTrianglesOfColor(const core::Mesh& mesh, std::array<int, 3> rgb) {
    std::array<int, 4> count{};
    const std::size_t perBody = mesh.triangleCount() / 4;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint8_t* px = cli_test::centreTexel(mesh, t);
        if (std::abs(px[0] - rgb[0]) <= 3 && std::abs(px[1] - rgb[1]) <= 3 &&
            std::abs(px[2] - rgb[2]) <= 3)
            ++count[std::min<std::size_t>(t / perBody, 3)];
    }
    return count;
}

/** Replays script on builtin:row and loads the saved .glb. */
core::Mesh paintRow(const json& script, const std::string& tag) {
    std::optional<core::Mesh> mesh =
        cli_test::paintScript("builtin:row", script, "cli_fill_" + tag);
    return mesh ? std::move(*mesh) : core::Mesh{};
}

TEST(Cli, PaintFillModesFillWhatTheySayOnTheSavedModel) {
    // At orbit 25,10,1.2 and 320x240, the front body (0) covers x 53..141, y 114..173 and the
    // others peek out behind it to the right.
    const json view = {{"size", "320x240"}, {"orbit", "25,10,1.2"}};
    const auto script = [&](json operations) {
        json s = view;
        s["operations"] = std::move(operations);
        return s;
    };
    const std::array<int, 3> green{0, 255, 0}, red{255, 0, 0};
    constexpr int kPerBody = 3968;
    const json setGreen = {{"op", "set-brush"}, {"color", "#00ff00"}};

    // surface: all of body 0, nothing else; undone: nothing.
    auto counts = rowTrianglesOfColor(
        paintRow(script({setGreen, {{"op", "fill"}, {"at", {80, 140}}, {"mode", "surface"}}}),
                 "surface"),
        green);
    EXPECT_EQ(counts, (std::array<int, 4>{kPerBody, 0, 0, 0}));
    counts = rowTrianglesOfColor(
        paintRow(script({setGreen,
                         {{"op", "fill"}, {"at", {80, 140}}, {"mode", "surface"}},
                         {{"op", "undo"}}}),
                 "undo"),
        green);
    EXPECT_EQ(counts, (std::array<int, 4>{0, 0, 0, 0}));

    // region: body 0's side facing the view, not its back, nothing else.
    counts = rowTrianglesOfColor(
        paintRow(script({setGreen, {{"op", "fill"}, {"at", {80, 140}}, {"mode", "region"}}}),
                 "region"),
        green);
    EXPECT_GT(counts[0], kPerBody / 4);
    EXPECT_LT(counts[0], kPerBody * 3 / 4);
    EXPECT_EQ(counts[1] + counts[2] + counts[3], 0);

    // color: a hard red band across body 0, then a fill on the body's colour: the rest of body 0
    // turns green around the back, the band stays red.
    const core::Mesh painted = paintRow(
        script({{{"op", "set-brush"}, {"color", "#ff0000"}, {"radius", 5}, {"hardness", 1.0}},
                {{"op", "stroke"}, {"points", {{40, 145}, {160, 145}}}},
                setGreen,
                {{"op", "fill"}, {"at", {80, 125}}, {"mode", "color"}, {"tolerance", 0.1}}}),
        "color");
    const auto greens = rowTrianglesOfColor(painted, green);
    const auto reds = rowTrianglesOfColor(painted, red);
    EXPECT_GT(reds[0], 20);
    EXPECT_GT(greens[0], kPerBody / 2);
    EXPECT_EQ(reds[0] + greens[0], kPerBody);
    EXPECT_EQ(greens[1] + greens[2] + greens[3], 0);
    EXPECT_EQ(reds[1] + reds[2] + reds[3], 0);

    // A bad mode: one line naming the script and the operation.
    const fs::path bad = fs::temp_directory_path() / "layerpaint_cli_fill_bad.json";
    std::ofstream(bad) << script({{{"op", "fill"}, {"at", {80, 140}}, {"mode", "bucket"}}}).dump();
    const CliRun run =
        runCli({"paint", "builtin:row", "--script", bad.string(), "--out",
                (fs::temp_directory_path() / "layerpaint_cli_fill_bad.glb").string()});
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.err.find("operation 1: \"mode\" must be"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find(bad.string()), std::string::npos) << run.err;
}

TEST(Cli, PickSetsTheBrushToTheSurfaceColourUnderThePoint) {
    // Paint red at a, switch the brush to blue, pick at a, paint at b: b must come out red.
    // Conventional painting: the stroke paints what is visible (a may be near a crossing).
    auto trefoil = core::makeBuiltinModel("trefoil");
    ASSERT_TRUE(trefoil);
    const core::View view =
        core::Camera::fromOrbit(trefoil->bounds(), 20.0f, 15.0f, 1.6f).view(320, 240);
    const glm::vec3 a = view.project(core::trefoilCurve(0.3f));
    const glm::vec3 b = view.project(core::trefoilCurve(3.5f));
    const auto point = [](const glm::vec3& p, float dx) { return json::array({p.x + dx, p.y}); };
    const json script = {
        {"size", "320x240"},
        {"orbit", "20,15,1.6"},
        {"target", {{"kind", "texture"}, {"resolution", 512}}},
        {"operations",
         {{{"op", "set-mode"}, {"layer_aware", false}},
          {{"op", "set-brush"}, {"color", "#ff0000"}, {"radius", 5}, {"hardness", 1.0}},
          {{"op", "stroke"}, {"points", {point(a, -2.0f), point(a, 2.0f)}}},
          {{"op", "set-brush"}, {"color", "#0000ff"}},
          {{"op", "pick"}, {"at", point(a, 0.0f)}},
          {{"op", "stroke"}, {"points", {point(b, -2.0f), point(b, 2.0f)}}}}}};
    const fs::path dir = fs::temp_directory_path() / "layerpaint_cli_pick";
    fs::create_directories(dir);
    std::ofstream(dir / "script.json") << script.dump();
    const CliRun run =
        runCli({"paint", "builtin:trefoil", "--script", (dir / "script.json").string(), "--out",
                (dir / "result.glb").string()});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    auto mesh = core::loadMesh((dir / "result.glb").string());
    ASSERT_TRUE(mesh) << mesh.error();
    ASSERT_FALSE(mesh->textures.empty());
    int red = 0, blue = 0;
    const std::vector<std::uint8_t>& rgba = mesh->textures[0].rgba;
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
        red += rgba[i] > 200 && rgba[i + 1] < 60 && rgba[i + 2] < 60;
        blue += rgba[i] < 60 && rgba[i + 1] < 60 && rgba[i + 2] > 200;
    }
    EXPECT_EQ(blue, 0);
    // Two strokes' worth of red: the second one is not missing.
    json first = script;
    while (first["operations"].size() > 3) // up to the first stroke
        first["operations"].erase(first["operations"].size() - 1);
    std::ofstream(dir / "first.json") << first.dump();
    const CliRun once =
        runCli({"paint", "builtin:trefoil", "--script", (dir / "first.json").string(), "--out",
                (dir / "first.glb").string()});
    ASSERT_EQ(once.exitCode, 0) << once.err;
    auto firstMesh = core::loadMesh((dir / "first.glb").string());
    ASSERT_TRUE(firstMesh) << firstMesh.error();
    int firstRed = 0;
    const std::vector<std::uint8_t>& firstRgba = firstMesh->textures[0].rgba;
    for (std::size_t i = 0; i + 3 < firstRgba.size(); i += 4)
        firstRed += firstRgba[i] > 200 && firstRgba[i + 1] < 60 && firstRgba[i + 2] < 60;
    EXPECT_GT(firstRed, 0);
    EXPECT_GT(red, firstRed + firstRed / 2) << red << " red texels, " << firstRed << " after a";

    // Background: a clear error naming the operation, and no output.
    const json miss = {{"size", "320x240"},
                       {"orbit", "20,15,1.6"},
                       {"operations", {{{"op", "pick"}, {"at", {1, 1}}}}}};
    std::ofstream(dir / "miss.json") << miss.dump();
    fs::remove(dir / "miss.glb");
    const CliRun failed =
        runCli({"paint", "builtin:trefoil", "--script", (dir / "miss.json").string(), "--out",
                (dir / "miss.glb").string()});
    EXPECT_NE(failed.exitCode, 0);
    EXPECT_NE(failed.err.find("operation 1: nothing to pick at [1,1]"), std::string::npos)
        << failed.err;
    EXPECT_FALSE(fs::exists(dir / "miss.glb"));
}

} // namespace cli_gltest
