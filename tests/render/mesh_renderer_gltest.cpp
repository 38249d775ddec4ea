// SPDX-License-Identifier: GPL-3.0-or-later
// Renders through a headless EGL context (llvmpipe on CI) and compares with a CPU rasterization.
#include <algorithm>
#include <cmath>
#include <span>

#include <gtest/gtest.h>

#include "tests/render/gl_test.h"

#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "render/gl_context.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"
#include "render/shader_library.h"
#include "render/software_gl.h"

namespace mesh_renderer_gltest {

using render_test::GlTest;

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

TEST_F(GlTest, LargeDrawsAreCutIntoConsecutivePiecesOnSoftwareRasterizers) {
    // Cut on a software rasterizer when there is a triangle for every 4 pixels or more.
    EXPECT_EQ(render::drawPieces(true, 230400, 1280 * 720), render::kSoftwareDrawPieces);
    EXPECT_EQ(render::drawPieces(true, 230399, 1280 * 720), 1);
    EXPECT_EQ(render::drawPieces(false, 10'000'000, 1280 * 720), 1);
    using Pieces = std::vector<std::pair<std::size_t, std::size_t>>;
    const auto cut = [](std::size_t first, std::size_t count, int pieces) {
        Pieces out;
        render::drawInPieces(first, count, pieces,
                             [&](std::size_t f, std::size_t n) { out.emplace_back(f, n); });
        return out;
    };
    EXPECT_EQ(cut(100, 100000, 8), (Pieces{{100, 12500},
                                           {12600, 12500},
                                           {25100, 12500},
                                           {37600, 12500},
                                           {50100, 12500},
                                           {62600, 12500},
                                           {75100, 12500},
                                           {87600, 12500}}));
    EXPECT_EQ(cut(0, 100000, 1), (Pieces{{0, 100000}}));
    // No piece under kMinDrawPiece triangles, but for the last.
    EXPECT_EQ(cut(0, 20000, 8), (Pieces{{0, 8192}, {8192, 8192}, {16384, 3616}}));
    EXPECT_EQ(cut(7, 5000, 8), (Pieces{{7, 5000}}));
    EXPECT_TRUE(cut(0, 0, 8).empty());
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

/** Draws mesh into a fresh offscreen target, optionally changing the renderer before the draw. */
template <typename Change>
core::Image drawMesh(const core::Mesh& mesh, const core::View& view, Change change) {
    render::OffscreenTarget target;
    EXPECT_TRUE(target.create(view.width, view.height));
    render::MeshRenderer renderer;
    EXPECT_TRUE(renderer.initialize());
    renderer.setMesh(mesh);
    change(renderer);
    target.bind();
    renderer.draw(view);
    core::Image image = target.readColor();
    renderer.release();
    return image;
}

int largeDifferences(const core::Image& a, const core::Image& b, int tolerance) {
    int count = 0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i)
        count += std::abs(int(a.rgba[i]) - int(b.rgba[i])) > tolerance;
    return count;
}

TEST_F(GlTest, TexelUpdatesLookLikeAFreshUpload) {
    core::Mesh mesh = core::makeTrefoil();
    core::Image texture;
    texture.width = 300; // odd mip sizes on the way down
    texture.height = 200;
    texture.rgba.resize(std::size_t(texture.width) * texture.height * 4);
    for (int y = 0; y < texture.height; ++y)
        for (int x = 0; x < texture.width; ++x) {
            std::uint8_t* px = &texture.rgba[(std::size_t(y) * texture.width + x) * 4];
            px[0] = std::uint8_t(x * 255 / texture.width);
            px[1] = std::uint8_t(y * 255 / texture.height);
            px[2] = 128;
            px[3] = 255;
        }
    mesh.textures = {texture};
    for (core::Material& material : mesh.materials)
        material.baseColorTexture = 0;
    core::Camera camera;
    camera.frame(mesh.bounds());
    const core::View view = camera.view(160, 120); // minified: the mip levels show

    core::Image painted = texture;
    for (int y = 40; y < 150; ++y)
        for (int x = 33; x < 217; ++x) {
            std::uint8_t* px = &painted.rgba[(std::size_t(y) * painted.width + x) * 4];
            px[0] = 230;
            px[1] = 20;
            px[2] = 10;
        }
    core::Mesh paintedMesh = mesh;
    paintedMesh.textures = {painted};
    const core::Image fresh = drawMesh(paintedMesh, view, [](render::MeshRenderer&) {});
    const core::Image updated = drawMesh(mesh, view, [&](render::MeshRenderer& renderer) {
        renderer.textures().updateTexels(0, 33, 40, 184, 110, painted);
    });
    const core::Image unchanged = drawMesh(mesh, view, [](render::MeshRenderer&) {});
    // The update shows, and like an upload of the whole painted texture (the GL's mipmap
    // filter and the linear-space one may round apart).
    EXPECT_GT(largeDifferences(unchanged, fresh, 24), 500);
    EXPECT_LT(largeDifferences(updated, fresh, 6), int(fresh.rgba.size() / 200));
}

TEST_F(GlTest, TextureUploadsLeaveThePixelStoreAtTheDefaultsQtDrawsTextWith) {
    // Qt's text over the view (the channel legend) uploads glyphs with the GL's default
    // pixel-store state: an upload that left another alignment or row length garbled them.
    core::Mesh mesh = core::makeTrefoil();
    core::Image texture{30, 20, std::vector<std::uint8_t>(30 * 20 * 4, 200)};
    mesh.textures = {texture};
    for (core::Material& material : mesh.materials)
        material.baseColorTexture = 0;
    core::Camera camera;
    camera.frame(mesh.bounds());
    GLint alignment = 0, rowLength = -1;
    drawMesh(mesh, camera.view(64, 48), [&](render::MeshRenderer& renderer) {
        renderer.textures().updateTexels(0, 3, 4, 10, 5, texture);
        glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
        glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
    });
    EXPECT_EQ(alignment, 4);
    EXPECT_EQ(rowLength, 0);
}

TEST_F(GlTest, VertexColourUpdatesLookLikeAFreshUpload) {
    core::Mesh mesh = core::makeTrefoil();
    mesh.colors.assign(mesh.vertexCount(), glm::vec4(1.0f));
    core::Camera camera;
    camera.frame(mesh.bounds());
    const core::View view = camera.view(160, 120);
    core::Mesh painted = mesh;
    const std::uint32_t first = 1000, count = 30000;
    for (std::uint32_t i = first; i < first + count; ++i)
        painted.colors[i] = {0.9f, 0.1f, 0.1f, 1.0f};
    const core::Image fresh = drawMesh(painted, view, [](render::MeshRenderer&) {});
    const core::Image updated = drawMesh(mesh, view, [&](render::MeshRenderer& renderer) {
        renderer.updateVertexColors(
            first, std::span<const glm::vec4>(painted.colors.data() + first, count));
    });
    const core::Image unchanged = drawMesh(mesh, view, [](render::MeshRenderer&) {});
    EXPECT_GT(largeDifferences(unchanged, fresh, 24), 100);
    EXPECT_EQ(largeDifferences(updated, fresh, 1), 0);
}

/** Two quads facing away from a camera on +Z: quad 0 (triangles 0, 1) of a double-sided
 * material, quad 1 (triangles 2, 3) of a single-sided one. */
core::Mesh backFacingQuads() {
    core::Mesh mesh;
    for (const float x : {-0.6f, 0.1f}) {
        const auto base = std::uint32_t(mesh.positions.size());
        mesh.positions.insert(
            mesh.positions.end(),
            {{x, -0.3f, 0.0f}, {x + 0.5f, -0.3f, 0.0f}, {x + 0.5f, 0.3f, 0.0f}, {x, 0.3f, 0.0f}});
        // Clockwise seen from +Z.
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 2, base + 1, base, base + 3, base + 2});
    }
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 0.0f, -1.0f));
    mesh.materials.resize(2);
    mesh.materials[0].doubleSided = true;
    mesh.triangleMaterial = {0, 0, 1, 1};
    return mesh;
}

TEST_F(GlTest, ShownBackFacesAreDrawnWhileTheOthersAreCulled) {
    const core::Mesh mesh = backFacingQuads();
    core::Camera camera;
    camera.sceneRadius = 1.0f;
    camera.distance = 2.0f;
    const core::View view = camera.view(64, 48);
    const std::vector<std::uint32_t> shown = {0, 1};
    const auto drawn = [&view](const core::Image& image, float worldX) {
        const glm::vec3 p = view.project(glm::vec3(worldX, 0.0f, 0.0f));
        const std::uint8_t* px =
            &image.rgba[(std::size_t(p.y) * std::size_t(view.width) + std::size_t(p.x)) * 4];
        return px[0] + px[1] + px[2] > 0;
    };
    const auto draw = [&](std::span<const std::uint32_t> list, bool standIn) {
        render::OffscreenTarget target;
        EXPECT_TRUE(target.create(view.width, view.height));
        render::MeshRenderer renderer;
        EXPECT_TRUE(renderer.initialize());
        renderer.setMesh(mesh, nullptr, list);
        if (standIn)
            renderer.setStandIn(mesh.indices, mesh.triangleMaterial);
        target.bind();
        render::DrawOptions options;
        options.background = {0.0f, 0.0f, 0.0f, 1.0f};
        options.standIn = standIn;
        options.cullBackFaces = true;
        renderer.draw(view, options);
        core::Image image = target.readColor();
        renderer.release();
        return image;
    };
    for (const bool standIn : {false, true}) {
        const core::Image withList = draw(shown, standIn);
        EXPECT_TRUE(drawn(withList, -0.35f)) << "stand-in " << standIn;
        EXPECT_FALSE(drawn(withList, 0.35f)) << "stand-in " << standIn;
        const core::Image without = draw({}, standIn);
        EXPECT_FALSE(drawn(without, -0.35f)) << "stand-in " << standIn;
    }
}

TEST_F(GlTest, AnAlphaMaskedMaterialShowsWhatIsBehindWhereItsAlphaIsLow) {
    // A grey quad in front (texture transparent on its left half) over a red quad behind.
    core::Mesh mesh;
    for (const float z : {0.2f, -0.2f}) {
        const auto base = std::uint32_t(mesh.positions.size());
        mesh.positions.insert(
            mesh.positions.end(),
            {{-0.5f, -0.4f, z}, {0.5f, -0.4f, z}, {0.5f, 0.4f, z}, {-0.5f, 0.4f, z}});
        mesh.uvs.insert(mesh.uvs.end(), {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}});
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    mesh.triangleMaterial = {0, 0, 1, 1};
    core::Image texture{8, 8, {}};
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            texture.rgba.insert(texture.rgba.end(), {200, 200, 200, std::uint8_t(x < 4 ? 0 : 255)});
    mesh.textures = {texture};
    mesh.materials.resize(2);
    mesh.materials[0].baseColorTexture = 0;
    mesh.materials[1].baseColorFactor = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    core::Camera camera;
    camera.sceneRadius = 1.0f;
    camera.distance = 2.0f;
    const core::View view = camera.view(64, 48);
    const auto redAt = [&](float worldX) {
        const core::Image image = drawMesh(mesh, view, [](render::MeshRenderer&) {});
        const glm::vec3 p = view.project(glm::vec3(worldX, 0.0f, 0.2f));
        const std::uint8_t* px =
            &image.rgba[(std::size_t(p.y) * std::size_t(view.width) + std::size_t(p.x)) * 4];
        return px[0] > 2 * px[1] + 20;
    };
    EXPECT_FALSE(redAt(-0.3f)) << "opaque: the grey quad hides the red one";
    mesh.materials[0].alphaMode = core::AlphaMode::Mask;
    EXPECT_TRUE(redAt(-0.3f)) << "masked: the red quad shows through the transparent half";
    EXPECT_FALSE(redAt(0.3f)) << "masked: the opaque half still hides it";
}

} // namespace mesh_renderer_gltest
