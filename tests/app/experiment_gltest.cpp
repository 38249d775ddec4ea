// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's Experiment 1 through the headless tool: one long stroke along a strand of the
// trefoil that passes under another. Checked on the saved .glb, not on internal state.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/io/mesh_io.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "tests/app/cli_run.h"

namespace experiment_gltest {

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
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint8_t* px = cli_test::centreTexel(mesh, t);
        if (px[0] > 200 && px[1] < 100 && px[2] < 100)
            ++painted[std::size_t(core::trefoilSegmentOfTriangle(t))];
    }
    return painted;
}

using cli_test::paintScript;

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
    const std::optional<core::Mesh> mesh =
        paintScript("builtin:trefoil", script, "experiment1_" + tag);
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

/** Red texels of the saved texture inside the UV rectangle [origin, origin + size). */
int redTexelsIn(const core::Mesh& mesh, glm::vec2 origin, float size) {
    if (mesh.textures.empty())
        return -1;
    const core::Image& texture = mesh.textures.front();
    int red = 0;
    for (int y = int(origin.y * float(texture.height)); y < int((origin.y + size) * texture.height);
         ++y)
        for (int x = int(origin.x * float(texture.width));
             x < int((origin.x + size) * texture.width); ++x) {
            const std::uint8_t* px = &texture.rgba[(std::size_t(y) * texture.width + x) * 4];
            red += px[0] > 200 && px[1] < 80 && px[2] < 80;
        }
    return red;
}

json mark(glm::vec2 at) {
    return {{"op", "stroke"},
            {"points", {{at.x - 4, at.y, 1.0}, {at.x, at.y, 1.0}, {at.x + 4, at.y, 1.0}}}};
}

const json kRedBrush = {{"op", "set-brush"}, {"color", "#ff0000"}, {"radius", 5}, {"hardness", 1}};

// The paper's Experiment 2: from one view of the hexagonal ring, pop up the inner wall hidden
// behind the outer one and paint it, without turning the view.
TEST(PaperExperiments, HexRingInnerWallIsPaintedAfterAPopUpFromTheSameView) {
    // Slightly above the ring, looking at it side on: at the image centre the near outer wall
    // (layer 1) covers the far inner wall (layer 2); the near inner wall faces away.
    const glm::vec2 centre(kWidth / 2.0f, kHeight / 2.0f);
    const auto paint = [&](bool popUp, const std::string& tag) {
        json operations = json::array({kRedBrush});
        if (popUp)
            operations.push_back({{"op", "popup"}, {"at", {centre.x, centre.y}}});
        operations.push_back(mark(centre));
        return paintScript("builtin:hexring",
                           {{"size", std::to_string(kWidth) + "x" + std::to_string(kHeight)},
                            {"orbit", "0,12,1.8"},
                            {"target", {{"resolution", 1024}}},
                            {"operations", operations}},
                           tag);
    };
    // Tiles of the 5 × 5 atlas: per side k the outer wall, inner wall, top and bottom caps.
    const auto wallPaint = [](const core::Mesh& mesh, int wall) {
        int red = 0;
        for (int k = 0; k < 6; ++k) {
            const int tile = 4 * k + wall;
            red += redTexelsIn(mesh, {0.2f * float(tile % 5), 0.2f * float(tile / 5)}, 0.2f);
        }
        return red;
    };
    const auto popped = paint(true, "experiment2_popup");
    ASSERT_TRUE(popped);
    EXPECT_GT(wallPaint(*popped, 1), 20) << "the inner wall got no paint";
    EXPECT_EQ(wallPaint(*popped, 0), 0) << "the outer wall in front got paint";
    // Without the pop-up the same mark lands on the outer wall in front.
    const auto plain = paint(false, "experiment2_plain");
    ASSERT_TRUE(plain);
    EXPECT_GT(wallPaint(*plain, 0), 20);
    EXPECT_EQ(wallPaint(*plain, 1), 0);
}

// The paper's Experiment 3: four bodies in a row, one behind the other; from one view, pop up
// each hidden body in turn by clicking the same spot and paint a mark on each.
TEST(PaperExperiments, EachBodyOfTheRowGetsItsMarkFromOneView) {
    const glm::vec2 centre(kWidth / 2.0f, kHeight / 2.0f);
    json operations = json::array({kRedBrush, mark(centre)});
    for (int body = 1; body < 4; ++body) {
        operations.push_back({{"op", "popup"}, {"at", {centre.x, centre.y}}});
        operations.push_back(mark(centre));
    }
    const auto mesh = paintScript("builtin:row",
                                  {{"size", std::to_string(kWidth) + "x" + std::to_string(kHeight)},
                                   {"orbit", "0,0,2.5"},
                                   {"target", {{"resolution", 1024}}},
                                   {"operations", operations}},
                                  "experiment3");
    ASSERT_TRUE(mesh);
    std::vector<int> red;
    for (int body = 0; body < 4; ++body)
        red.push_back(redTexelsIn(*mesh, {0.5f * float(body % 2), 0.5f * float(body / 2)}, 0.5f));
    for (int body = 0; body < 4; ++body)
        EXPECT_GT(red[std::size_t(body)], 20) << "body " << body + 1 << " has no mark";
    // One mark each: the marks are alike in size (the bodies are further away, so smaller).
    EXPECT_LT(*std::max_element(red.begin(), red.end()),
              8 * *std::min_element(red.begin(), red.end()));
}

} // namespace experiment_gltest
