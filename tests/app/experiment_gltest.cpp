// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's Experiment 1 through the headless tool: one long stroke along a strand of the
// trefoil that passes under another. Checked on the saved .glb, not on internal state.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/builtin_models.h"
#include "core/camera.h"
#include "core/mesh_io.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kSegments = 3 * 399;
constexpr int kWidth = 640, kHeight = 480;
constexpr float kYaw = 20.0f, kPitch = 15.0f, kDistance = 1.6f;

float curveT(int segment) {
    return 2.0f * std::numbers::pi_v<float> * float(segment) / float(kSegments);
}

int segmentDistance(int a, int b) {
    const int d = std::abs(a - b) % kSegments;
    return std::min(d, kSegments - d);
}

struct Crossing {
    int hidden = -1;   // segment of the strand passing under
    int occluder = -1; // segment of the strand on top
};

/** The crossing whose strands overlap most closely on screen. */
Crossing findCrossing(const core::View& view) {
    std::vector<glm::vec3> p(kSegments);
    for (int i = 0; i < kSegments; ++i)
        p[std::size_t(i)] = view.project(core::trefoilCurve(curveT(i)));
    Crossing best;
    float bestDistance = 1e9f;
    for (int i = 0; i < kSegments; ++i)
        for (int j = i + 1; j < kSegments; ++j) {
            if (segmentDistance(i, j) < 200)
                continue;
            const float d =
                glm::distance(glm::vec2(p[std::size_t(i)]), glm::vec2(p[std::size_t(j)]));
            // Stay clear of the image border so the whole stroke is on screen.
            const glm::vec2 c(p[std::size_t(i)]);
            if (d < bestDistance && c.x > 60 && c.y > 60 && c.x < kWidth - 60 &&
                c.y < kHeight - 60) {
                bestDistance = d;
                const bool iBehind = p[std::size_t(i)].z > p[std::size_t(j)].z;
                best = {iBehind ? i : j, iBehind ? j : i};
            }
        }
    return best;
}

/** Per segment along the tube: how many of its triangles are painted red in the saved model. */
std::vector<int> paintedPerSegment(const core::Mesh& mesh) {
    std::vector<int> painted(kSegments, 0);
    const core::Image& texture = mesh.textures.at(0);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        glm::vec2 uv(0.0f);
        for (int k = 0; k < 3; ++k)
            uv += mesh.uvs[mesh.indices[3 * t + std::size_t(k)]] / 3.0f;
        const int x = std::clamp(int(uv.x * float(texture.width)), 0, texture.width - 1);
        const int y = std::clamp(int(uv.y * float(texture.height)), 0, texture.height - 1);
        const std::uint8_t* px = &texture.rgba[(std::size_t(y) * texture.width + x) * 4];
        if (px[0] > 200 && px[1] < 100 && px[2] < 100)
            ++painted[std::size_t(core::trefoilSegmentOfTriangle(t))];
    }
    return painted;
}

std::vector<int> paintStroke(bool layerAware, const Crossing& crossing, const core::View& view,
                             const std::string& tag) {
    json points = json::array();
    for (int s = -60; s <= 60; ++s) {
        const int segment = (crossing.hidden + s + kSegments) % kSegments;
        const glm::vec3 p = view.project(core::trefoilCurve(curveT(segment)));
        points.push_back({p.x, p.y, 1.0});
    }
    const json script = {
        {"size", std::to_string(kWidth) + "x" + std::to_string(kHeight)},
        {"orbit", "20,15,1.6"},
        {"operations",
         {{{"op", "set-mode"}, {"layer_aware", layerAware}},
          {{"op", "set-brush"}, {"color", "#ff0000"}, {"radius", 6}, {"hardness", 1.0}},
          {{"op", "stroke"}, {"points", points}}}}};
    const fs::path dir = fs::temp_directory_path() / ("layerpaint_experiment1_" + tag);
    fs::create_directories(dir);
    std::ofstream(dir / "script.json") << script.dump();
    const std::string command =
        std::string("'") + LAYERPAINT_CLI + "' paint builtin:trefoil --script '" +
        (dir / "script.json").string() + "' --out '" + (dir / "result.glb").string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    auto mesh = core::loadMesh((dir / "result.glb").string());
    EXPECT_TRUE(mesh) << mesh.error();
    if (!mesh)
        return {};
    EXPECT_EQ(mesh->triangleCount(), core::makeTrefoil().triangleCount());
    return paintedPerSegment(*mesh);
}

TEST(PaperExperiments, OneLongStrokePaintsTheHiddenStrandAndNotTheOccluder) {
    auto trefoil = core::makeBuiltinModel("trefoil");
    ASSERT_TRUE(trefoil);
    const core::View view =
        core::Camera::fromOrbit(trefoil->bounds(), kYaw, kPitch, kDistance).view(kWidth, kHeight);
    const Crossing crossing = findCrossing(view);
    ASSERT_GE(crossing.hidden, 0);

    const std::vector<int> layerAware = paintStroke(true, crossing, view, "aware");
    ASSERT_EQ(layerAware.size(), std::size_t(kSegments));
    // The hidden strand is painted along its whole length, under the crossing too ...
    for (int s = -50; s <= 50; ++s)
        EXPECT_GT(layerAware[std::size_t((crossing.hidden + s + kSegments) % kSegments)], 0)
            << "segment " << s << " from the crossing is unpainted";
    // ... and the strand on top is not touched.
    for (int s = -25; s <= 25; ++s)
        EXPECT_EQ(layerAware[std::size_t((crossing.occluder + s + kSegments) % kSegments)], 0)
            << "occluder segment " << s << " got paint";

    // A conventional painter paints whatever is in front: the occluder, not the strand below.
    const std::vector<int> conventional = paintStroke(false, crossing, view, "conventional");
    ASSERT_EQ(conventional.size(), std::size_t(kSegments));
    int occluderPainted = 0;
    for (int s = -25; s <= 25; ++s)
        occluderPainted +=
            conventional[std::size_t((crossing.occluder + s + kSegments) % kSegments)];
    EXPECT_GT(occluderPainted, 0);
    EXPECT_EQ(conventional[std::size_t(crossing.hidden)], 0);
}

} // namespace
