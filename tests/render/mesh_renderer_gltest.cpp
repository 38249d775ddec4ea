// SPDX-License-Identifier: GPL-3.0-or-later
// Renders through a headless EGL context (llvmpipe on CI) and compares with a CPU rasterization.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/builtin_models.h"
#include "core/camera.h"
#include "render/gl_context.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"
#include "render/shader_library.h"

namespace {

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        auto context = render::HeadlessContext::create();
        ASSERT_TRUE(context) << context.error();
        s_context = std::move(context).value();
    }
    static void TearDownTestSuite() { s_context.reset(); }
    static std::unique_ptr<render::HeadlessContext> s_context;
};
std::unique_ptr<render::HeadlessContext> GlTest::s_context;

/** Pixel-centre coverage of the mesh's triangles, rows top first (the CPU reference). */
std::vector<std::uint8_t> cpuCoverage(const core::Mesh& mesh, const core::View& view) {
    std::vector<std::uint8_t> mask(std::size_t(view.width) * view.height, 0);
    std::vector<glm::vec3> projected(mesh.vertexCount());
    for (std::size_t i = 0; i < projected.size(); ++i)
        projected[i] = view.project(mesh.positions[i]);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::vec3 a = projected[mesh.indices[3 * t]], b = projected[mesh.indices[3 * t + 1]],
                        c = projected[mesh.indices[3 * t + 2]];
        const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        if (area == 0.0f)
            continue;
        const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
        const int x1 = std::min(view.width - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
        const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}))));
        const int y1 = std::min(view.height - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const float px = float(x) + 0.5f, py = float(y) + 0.5f;
                const auto edge = [&](glm::vec3 p, glm::vec3 q) {
                    return ((q.x - p.x) * (py - p.y) - (px - p.x) * (q.y - p.y)) * area;
                };
                if (edge(a, b) >= 0 && edge(b, c) >= 0 && edge(c, a) >= 0)
                    mask[std::size_t(y) * view.width + x] = 1;
            }
    }
    return mask;
}

TEST_F(GlTest, ContextIsOpenGl45Core) {
    EXPECT_FALSE(render::HeadlessContext::rendererName().empty());
}

TEST_F(GlTest, MissingShaderIsReportedByName) {
    auto program = render::ShaderProgram::build({"no_such.vert"});
    ASSERT_FALSE(program);
    EXPECT_NE(program.error().find("no_such.vert"), std::string::npos);
    EXPECT_FALSE(render::shaderSource("mesh.vert").empty());
}

TEST_F(GlTest, TrefoilSilhouetteMatchesCpuRasterization) {
    const core::Mesh mesh = core::makeTrefoil();
    core::Camera camera;
    camera.frame(mesh.bounds());
    camera.orbit(20.0f, 15.0f);
    const core::View view = camera.view(320, 240);

    render::OffscreenTarget target;
    ASSERT_TRUE(target.create(view.width, view.height));
    render::MeshRenderer renderer;
    const core::Status init = renderer.initialize();
    ASSERT_TRUE(init) << init.error();
    renderer.setMesh(mesh);
    target.bind();
    render::DrawOptions options;
    options.background = {0.0f, 0.0f, 0.0f, 1.0f};
    renderer.draw(view, options);
    const core::Image image = target.readColor();
    renderer.release();

    const std::vector<std::uint8_t> expected = cpuCoverage(mesh, view);
    int covered = 0, mismatched = 0, expectedCount = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const std::uint8_t* px = &image.rgba[i * 4];
        const bool drawn = px[0] > 0 || px[1] > 0 || px[2] > 0;
        covered += drawn;
        expectedCount += expected[i];
        mismatched += drawn != bool(expected[i]);
    }
    // The knot covers a sizeable part of the view, not all of it.
    EXPECT_GT(expectedCount, int(expected.size() / 8));
    EXPECT_LT(expectedCount, int(expected.size() / 2));
    // Only pixels on the silhouette may differ (rasterization rules at shared edges).
    EXPECT_LT(mismatched, expectedCount / 100) << "covered " << covered << " of " << expectedCount;

    // Lit surface: the shade varies and nothing is pure white or black inside the silhouette.
    int minGreen = 255, maxGreen = 0;
    for (std::size_t i = 0; i < expected.size(); ++i)
        if (expected[i]) {
            minGreen = std::min<int>(minGreen, image.rgba[i * 4 + 1]);
            maxGreen = std::max<int>(maxGreen, image.rgba[i * 4 + 1]);
        }
    EXPECT_GT(maxGreen - minGreen, 60);
    EXPECT_LT(maxGreen, 255);
}

} // namespace
