// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "core/base/color.h"
#include "core/depth/depth_layers.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/model/mesh_topology.h"
#include "core/paint/paint_layers/undo_tiles.h"
#include "core/paint/targets/paint_target.h"
#include "tests/core/captured_scenes.h"
#include "tests/core/test_scenes.h"

namespace paint_target_test {

using core::kNone;
using core_test::addQuad;
using core_test::paintScene;
using core_test::pixelView;
using core_test::Quad;
using Scene = core_test::PaintScene;

/** All pixels whose centre is within radius of center and that have a fragment on layer. */
core::Dab makeDab(const core::DepthStack& stack, glm::vec2 center, float radius,
                  std::uint32_t layer = 1) {
    core::Dab dab;
    dab.center = center;
    dab.radius = radius;
    dab.layer = layer;
    for (int y = 0; y < stack.height; ++y) {
        for (int x = 0; x < stack.width; ++x) {
            const float d = glm::length(glm::vec2(float(x) + 0.5f, float(y) + 0.5f) - center);
            if (d > radius)
                continue;
            const std::size_t pixel = std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
            const std::uint32_t f = stack.fragment(pixel, layer);
            if (f != kNone)
                dab.paintable.push_back({std::uint32_t(pixel), f, d});
        }
    }
    return dab;
}

bool inMap(const core::Dab& dab, int width, glm::vec2 p) {
    const std::uint32_t pixel =
        std::uint32_t(std::floor(p.y)) * std::uint32_t(width) + std::uint32_t(std::floor(p.x));
    return std::any_of(dab.paintable.begin(), dab.paintable.end(),
                       [&](const core::MapPixel& m) { return m.pixel == pixel; });
}

/**
 * Whether window position p, on the map's surface, is in a pixel the map left out only for its
 * centre lying outside the dab's circle, beside a map pixel (of the 2 × 2 block of pixel centres
 * around p): the paint goes on to the circle there, not only to the pixels' saw-tooth.
 */
bool atDabRim(const core::Dab& dab, int width, glm::vec2 p) {
    const glm::vec2 cell = glm::floor(p);
    if (glm::length(cell + 0.5f - dab.center) < dab.radius)
        return false;
    const float nx = p.x - cell.x < 0.5f ? -1.0f : 1.0f;
    const float ny = p.y - cell.y < 0.5f ? -1.0f : 1.0f;
    for (const glm::vec2 step : {glm::vec2(nx, 0.0f), glm::vec2(0.0f, ny), glm::vec2(nx, ny)})
        if (inMap(dab, width, cell + 0.5f + step))
            return true;
    return false;
}

core::Brush hardBrush() {
    core::Brush brush;
    brush.color = {0.2f, 0.6f, 0.9f, 1.0f};
    brush.hardness = 1.0f; // weight 1 everywhere inside the radius
    brush.opacity = 1.0f;
    brush.flow = 1.0f;
    return brush;
}

const std::uint8_t* texel(const core::Image& image, int x, int y) {
    return &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
}

bool sameTexel(const core::Image& a, const core::Image& b, int x, int y) {
    return std::equal(texel(a, x, y), texel(a, x, y) + 4, texel(b, x, y));
}

std::unique_ptr<core::TextureTarget> textureTarget(const Scene& scene,
                                                   core::PaintTargetOptions options = {}) {
    auto target = core::TextureTarget::create(scene.mesh, scene.topology, options);
    EXPECT_TRUE(target.ok()) << target.error();
    return std::move(target).value();
}

/** Paints one stroke of dabs and returns its record. */
core::TileUndoRecord stroke(core::PaintTarget& target, const core::DepthLayers& layers,
                            const core::Brush& brush, const std::vector<core::Dab>& dabs) {
    target.beginStroke(brush);
    for (const core::Dab& dab : dabs)
        target.paint(layers, dab);
    return target.endStroke();
}

/**
 * Checks every texel of page 0 of a single-quad scene: painted (with the full brush colour)
 * exactly when its centre projects inside the dab's circle into a pixel of the map, or beside
 * one at the circle (atDabRim). Texels within `margin` pixels of the circle or of a pixel border
 * are not judged.
 */
void expectFootprint(const core::TextureTarget& target, const Quad& quad, const core::Dab& dab,
                     int viewWidth, const core::Brush& brush, float margin,
                     bool requireAll = true) {
    const core::Image& page = target.page(0);
    const core::Image& original = target.originalPage(0);
    const std::uint8_t color[4] = {core::linearToSrgb(brush.color.r),
                                   core::linearToSrgb(brush.color.g),
                                   core::linearToSrgb(brush.color.b), 255};
    int painted = 0, missed = 0, stray = 0;
    for (int y = 0; y < page.height; ++y) {
        for (int x = 0; x < page.width; ++x) {
            const glm::vec2 uv((float(x) + 0.5f) / float(page.width),
                               (float(y) + 0.5f) / float(page.height));
            const bool changed = !sameTexel(page, original, x, y);
            if (!quad.hasUv(uv)) {
                continue; // outside the chart: padding, judged elsewhere
            }
            const glm::vec2 p = quad.pixelOfUv(uv);
            const float d = glm::length(p - dab.center);
            const bool nearEdge = std::fabs(d - dab.radius) < margin ||
                                  std::fabs(p.x - std::round(p.x)) < margin ||
                                  std::fabs(p.y - std::round(p.y)) < margin;
            const bool expected =
                d < dab.radius && (inMap(dab, viewWidth, p) || atDabRim(dab, viewWidth, p));
            if (changed) {
                ++painted;
                EXPECT_TRUE(std::equal(color, color + 4, texel(page, x, y)))
                    << "texel " << x << "," << y << " partly painted";
            }
            if (nearEdge)
                continue;
            if (expected && !changed)
                ++missed;
            if (!expected && changed)
                ++stray;
        }
    }
    EXPECT_GT(painted, 0);
    if (requireAll) {
        EXPECT_EQ(missed, 0) << "unpainted texels inside the dab";
    }
    EXPECT_EQ(stray, 0) << "painted texels outside the dab";
}

TEST(TextureTarget, PaintsExactlyTheTexelsInsideTheDab) {
    const core::View view = pixelView(200, 200);
    core::Mesh mesh;
    const Quad quad{{20.0f, 20.0f}, {180.0f, 180.0f}, 5.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 3};
    addQuad(mesh, quad);
    const Scene scene = paintScene(std::move(mesh), view);
    core::PaintTargetOptions options;
    options.resolution = 512;
    auto target = textureTarget(scene, options);
    ASSERT_EQ(target->pageCount(), 1u);
    EXPECT_EQ(target->page(0).width, 512);
    EXPECT_EQ(target->pageSource(0), -1);

    const core::Dab dab = makeDab(scene.layers.stack, {100.3f, 97.7f}, 20.0f);
    ASSERT_FALSE(dab.paintable.empty());
    target->beginStroke(hardBrush());
    const core::PaintChanges& changes = target->paint(scene.layers, dab);
    EXPECT_FALSE(changes.texels.empty());
    // Every changed texel lies in a reported rectangle.
    const core::Image& page = target->page(0);
    for (int y = 0; y < page.height; ++y) {
        for (int x = 0; x < page.width; ++x) {
            if (sameTexel(page, target->originalPage(0), x, y))
                continue;
            EXPECT_TRUE(std::any_of(changes.texels.begin(), changes.texels.end(),
                                    [&](const core::TexelRect& r) {
                                        return x >= r.x && x < r.x + r.width && y >= r.y &&
                                               y < r.y + r.height;
                                    }))
                << x << "," << y;
        }
    }
    target->endStroke();
    expectFootprint(*target, quad, dab, view.width, hardBrush(), 0.01f);
}

TEST(TextureTarget, NewTextureKeepsTheLook) {
    const core::View view = pixelView(64, 64);
    core::Mesh mesh;
    addQuad(mesh, {{8.0f, 8.0f}, {56.0f, 56.0f}, 5.0f, {0.1f, 0.1f}, {0.9f, 0.9f}, 2});
    mesh.materials[0].baseColorFactor = {0.25f, 0.5f, 1.0f, 1.0f};
    mesh.colors.assign(mesh.positions.size(), glm::vec4(0.5f, 1.0f, 1.0f, 1.0f));
    const Scene scene = paintScene(std::move(mesh), view);
    auto target = textureTarget(scene);
    const core::Image& page = target->page(0);
    const std::uint8_t* px = texel(page, page.width / 2, page.height / 2);
    EXPECT_EQ(px[0], core::linearToSrgb(0.125f));
    EXPECT_EQ(px[1], core::linearToSrgb(0.5f));
    EXPECT_EQ(px[2], core::linearToSrgb(1.0f));
    EXPECT_EQ(px[3], 255);
    EXPECT_EQ(target->drawMaterials()[0].baseColorFactor, glm::vec4(1.0f));
    EXPECT_EQ(target->drawMaterials()[0].baseColorTexture, 0);
}

TEST(TextureTarget, SrgbConversionRoundTripsEveryByte) {
    for (int v = 0; v < 256; ++v)
        EXPECT_EQ(core::linearToSrgb(core::srgbToLinear(std::uint8_t(v))), v);
}

/** Densities: texels 4× smaller and 4× larger than pixels, on a quad of many small triangles. */
struct DensityCase {
    const char* name;
    int viewSize;
    Quad quad;
    int textureSize; // an existing texture this size
};

class TextureDensity : public ::testing::TestWithParam<DensityCase> {};

TEST_P(TextureDensity, NoHoleInsideTheDab) {
    const DensityCase& c = GetParam();
    const core::View view = pixelView(c.viewSize, c.viewSize);
    core::Mesh mesh;
    addQuad(mesh, c.quad);
    core::Image image;
    image.width = image.height = c.textureSize;
    image.rgba.assign(std::size_t(c.textureSize) * std::size_t(c.textureSize) * 4, 200);
    mesh.textures.push_back(image);
    mesh.materials[0].baseColorFactor = glm::vec4(1.0f);
    mesh.materials[0].baseColorTexture = 0;
    const Scene scene = paintScene(std::move(mesh), view);
    auto target = textureTarget(scene);
    ASSERT_EQ(target->pageSource(0), 0);
    EXPECT_EQ(target->page(0).rgba, scene.mesh->textures[0].rgba); // painted in place

    const glm::vec2 center = (c.quad.p0 + c.quad.p1) * 0.5f + glm::vec2(0.37f, -0.21f);
    const core::Dab dab = makeDab(scene.layers.stack, center, 24.0f);
    stroke(*target, scene.layers, hardBrush(), {dab});
    expectFootprint(*target, c.quad, dab, view.width, hardBrush(), 0.01f);
}

INSTANTIATE_TEST_SUITE_P(
    Densities, TextureDensity,
    ::testing::Values(
        // 128 pixels over 512 texels, 8 × 8 px cells.
        DensityCase{"FourTimes", 160,
                    Quad{{16.0f, 16.0f}, {144.0f, 144.0f}, 5.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 16},
                    512},
        // 128 pixels over 32 texels on triangles of 0.2 px² (most cover no pixel centre, so
        // have no fragment); cells of 0.64 px keep texel centres off the triangle edges.
        DensityCase{"QuarterTinyTriangles", 160,
                    Quad{{16.3f, 16.3f}, {144.3f, 144.3f}, 5.0f, {0.0f, 0.0f}, {0.25f, 0.25f}, 200},
                    128},
        // Texels 4 px wide on a coarse grid.
        DensityCase{"Quarter", 160,
                    Quad{{16.3f, 16.3f}, {144.3f, 144.3f}, 5.0f, {0.0f, 0.0f}, {0.25f, 0.25f}, 4},
                    128}),
    [](const ::testing::TestParamInfo<DensityCase>& param) {
        return std::string(param.param.name);
    });

/** A big back quad (left half of the texture) and a smaller front quad (right half). */
struct TwoQuads {
    // Off the pixel borders by a quarter pixel, so no vertex projects onto one.
    Quad back{{20.25f, 20.25f}, {180.25f, 180.25f}, 10.0f, {0.0f, 0.0f}, {0.5f, 1.0f}, 4};
    Quad front{{50.25f, 50.25f}, {150.25f, 150.25f}, 5.0f, {0.5f, 0.0f}, {1.0f, 1.0f}, 4};
    core::View view = pixelView(200, 200);
    Scene scene;
    TwoQuads() {
        core::Mesh mesh;
        addQuad(mesh, back);
        addQuad(mesh, front);
        scene = paintScene(std::move(mesh), view);
    }
};

TEST(TextureTarget, ADabOnLayerTwoPaintsOnlyTheHiddenSurface) {
    TwoQuads s;
    core::PaintTargetOptions options;
    options.resolution = 512;
    options.padding = 0;
    auto target = textureTarget(s.scene, options);
    const glm::vec2 center(100.5f, 100.5f);
    const core::Dab dab = makeDab(s.scene.layers.stack, center, 30.0f, 2);
    ASSERT_FALSE(dab.paintable.empty());
    stroke(*target, s.scene.layers, hardBrush(), {dab});

    const core::Image& page = target->page(0);
    int backPainted = 0;
    for (int y = 0; y < page.height; ++y) {
        for (int x = 0; x < page.width; ++x) {
            if (sameTexel(page, target->originalPage(0), x, y))
                continue;
            const glm::vec2 uv((float(x) + 0.5f) / float(page.width),
                               (float(y) + 0.5f) / float(page.height));
            ASSERT_TRUE(s.back.hasUv(uv)) << "the occluder got paint at texel " << x << "," << y;
            const glm::vec2 p = s.back.pixelOfUv(uv);
            EXPECT_LT(glm::length(p - center), 30.0f + 0.01f);
            ++backPainted;
        }
    }
    // The disc on the back quad is 30 px in radius: 256 texels per 160 px.
    EXPECT_GT(backPainted,
              int(0.9f * 3.14159f * 30.0f * 30.0f * (256.0f / 160.0f) * (512.0f / 160.0f)));

    // The same dab on layer 1 paints the front quad only.
    auto front = textureTarget(s.scene, options);
    stroke(*front, s.scene.layers, hardBrush(), {makeDab(s.scene.layers.stack, center, 30.0f, 1)});
    const core::Image& frontPage = front->page(0);
    for (int y = 0; y < frontPage.height; ++y)
        for (int x = 0; x < frontPage.width / 2; ++x)
            ASSERT_TRUE(sameTexel(frontPage, front->originalPage(0), x, y));
}

TEST(TextureTarget, OverlappingDabsNeverExceedTheStrokeOpacity) {
    const core::View view = pixelView(100, 100);
    core::Mesh mesh;
    const Quad quad{{10.0f, 10.0f}, {90.0f, 90.0f}, 5.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 2};
    addQuad(mesh, quad);
    mesh.materials[0].baseColorFactor = {0.8f, 0.3f, 0.1f, 1.0f};
    const Scene scene = paintScene(std::move(mesh), view);
    core::PaintTargetOptions options;
    options.resolution = 512;

    core::Brush brush = hardBrush();
    brush.opacity = 0.5f;
    brush.flow = 0.25f;
    std::vector<core::Dab> dabs;
    for (int i = 0; i < 20; ++i) {
        core::Dab dab = makeDab(scene.layers.stack, {50.0f + 0.3f * float(i % 3), 50.0f}, 15.0f);
        dab.opacity = brush.opacity;
        dabs.push_back(std::move(dab));
    }
    auto many = textureTarget(scene, options);
    stroke(*many, scene.layers, brush, dabs);

    // One dab with full flow reaches the same, and that is lerp(before, colour, 0.5).
    core::Brush once = brush;
    once.flow = 1.0f;
    auto single = textureTarget(scene, options);
    stroke(*single, scene.layers, once, {dabs[0]});
    const core::Image& a = many->page(0);
    const core::Image& b = single->page(0);
    const int cx = a.width / 2, cy = a.height / 2;
    EXPECT_TRUE(sameTexel(a, b, cx, cy));
    // Colour mixes on the sRGB-encoded values (as through a paint layer).
    const std::uint8_t* before = texel(many->originalPage(0), cx, cy);
    const std::uint8_t* after = texel(a, cx, cy);
    const auto encoded = [&](int k) { return float(core::linearToSrgb(brush.color[k])) / 255.0f; };
    for (int k = 0; k < 3; ++k) {
        const float from = float(before[k]) / 255.0f;
        EXPECT_NEAR(after[k], (from + (encoded(k) - from) * 0.5f) * 255.0f, 0.51f);
    }
    // No texel went beyond half way anywhere.
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        for (int k = 0; k < 3; ++k) {
            const float from = float(many->originalPage(0).rgba[i + std::size_t(k)]) / 255.0f;
            const float now = float(a.rgba[i + std::size_t(k)]) / 255.0f;
            EXPECT_LE(std::fabs(now - from), std::fabs(encoded(k) - from) * 0.5f + 0.01f);
        }
    }
}

TEST(TextureTarget, EraserRestoresTheOriginalBytes) {
    const core::View view = pixelView(120, 120);
    core::Mesh mesh;
    addQuad(mesh, {{10.0f, 10.0f}, {110.0f, 110.0f}, 5.0f, {0.2f, 0.2f}, {0.8f, 0.8f}, 5});
    core::Image image;
    image.width = 300;
    image.height = 200;
    std::mt19937 random(7);
    for (int i = 0; i < image.width * image.height * 4; ++i)
        image.rgba.push_back(std::uint8_t(random()));
    mesh.textures.push_back(image);
    mesh.materials[0].baseColorFactor = glm::vec4(1.0f);
    mesh.materials[0].baseColorTexture = 0;
    const Scene scene = paintScene(std::move(mesh), view);
    auto target = textureTarget(scene);
    ASSERT_EQ(target->page(0).rgba, image.rgba);

    core::Brush soft;
    soft.color = {1.0f, 0.0f, 0.5f, 0.7f};
    soft.hardness = 0.2f;
    soft.opacity = 0.8f;
    core::Dab dab = makeDab(scene.layers.stack, {50.0f, 60.0f}, 20.0f);
    dab.opacity = 0.8f;
    // The last dab reaches over the chart border, so seam padding gets paint too.
    stroke(*target, scene.layers, soft,
           {dab, makeDab(scene.layers.stack, {65.0f, 60.0f}, 20.0f),
            makeDab(scene.layers.stack, {15.0f, 60.0f}, 20.0f)});
    EXPECT_NE(target->page(0).rgba, image.rgba);

    // A partial eraser stroke, then a full one covering everything painted.
    core::Brush eraser = hardBrush();
    eraser.eraser = true;
    core::Dab half = makeDab(scene.layers.stack, {55.0f, 60.0f}, 30.0f);
    half.opacity = 0.5f;
    stroke(*target, scene.layers, eraser, {half});
    EXPECT_NE(target->page(0).rgba, image.rgba);
    stroke(*target, scene.layers, eraser, {makeDab(scene.layers.stack, {57.0f, 60.0f}, 60.0f)});
    EXPECT_EQ(target->page(0).rgba, image.rgba);
}

TEST(TextureTarget, SeamPaddingFillsTexelsOutsideTheChart) {
    const core::View view = pixelView(200, 200);
    core::Mesh mesh;
    // uv 0.25..0.75 of 512 texels: the chart covers texels 128..383.
    const Quad quad{{20.0f, 20.0f}, {180.0f, 180.0f}, 5.0f, {0.25f, 0.25f}, {0.75f, 0.75f}, 2};
    addQuad(mesh, quad);
    const Scene scene = paintScene(std::move(mesh), view);
    core::PaintTargetOptions options;
    options.resolution = 512;
    options.padding = 4;
    auto target = textureTarget(scene, options);
    const std::vector<std::uint8_t>& coverage = target->coverage(0);
    const auto cov = [&](int x, int y) { return coverage[std::size_t(y) * 512 + std::size_t(x)]; };
    EXPECT_EQ(cov(128, 200), 1);
    EXPECT_EQ(cov(383, 200), 1);
    for (int x = 124; x < 128; ++x)
        EXPECT_EQ(cov(x, 200), 2);
    EXPECT_EQ(cov(123, 200), 0);
    EXPECT_EQ(cov(384, 200), 2);
    EXPECT_EQ(cov(388, 200), 0);
    EXPECT_EQ(cov(124, 124), 2); // corners are padded diagonally
    EXPECT_EQ(cov(123, 123), 0);

    // A dab over the chart's left edge: the padding texels of painted rows get the paint.
    const core::Dab dab = makeDab(scene.layers.stack, {22.0f, 100.0f}, 15.0f);
    stroke(*target, scene.layers, hardBrush(), {dab});
    const core::Image& page = target->page(0);
    const core::Image& original = target->originalPage(0);
    int paddedRows = 0;
    for (int y = 0; y < 512; ++y) {
        const bool edgePainted = !sameTexel(page, original, 128, y);
        for (int x = 124; x < 128; ++x)
            EXPECT_EQ(!sameTexel(page, original, x, y), edgePainted) << x << "," << y;
        EXPECT_TRUE(sameTexel(page, original, 123, y));
        paddedRows += edgePainted;
    }
    EXPECT_GT(paddedRows, 20);
}

TEST(TextureTarget, UndoAndRedoAreByteExact) {
    const core::View view = pixelView(160, 160);
    core::Mesh mesh;
    addQuad(mesh, {{10.0f, 10.0f}, {150.0f, 150.0f}, 5.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 6});
    const Scene scene = paintScene(std::move(mesh), view);
    core::PaintTargetOptions options;
    options.resolution = 1024;
    auto target = textureTarget(scene, options);
    const auto s0 = target->page(0).rgba;
    core::Brush brush;
    brush.color = {0.1f, 0.9f, 0.3f, 1.0f};
    brush.hardness = 0.3f;
    std::vector<core::Dab> dabs1, dabs2;
    for (int i = 0; i < 6; ++i)
        dabs1.push_back(makeDab(scene.layers.stack, {30.0f + 6.0f * float(i), 60.0f}, 12.0f));
    for (int i = 0; i < 6; ++i)
        dabs2.push_back(makeDab(scene.layers.stack, {50.0f, 40.0f + 6.0f * float(i)}, 12.0f));
    core::TileUndoRecord first = stroke(*target, scene.layers, brush, dabs1);
    const auto s1 = target->page(0).rgba;
    brush.color = {0.9f, 0.2f, 0.1f, 0.5f};
    core::TileUndoRecord second = stroke(*target, scene.layers, brush, dabs2);
    const auto s2 = target->page(0).rgba;
    ASSERT_NE(s0, s1);
    ASSERT_NE(s1, s2);
    // Only touched tiles are stored: far less than the 4 MiB texture.
    EXPECT_LT(first.bytes() + second.bytes(), target->page(0).rgba.size() / 2);

    ASSERT_TRUE(second.undo(*target));
    EXPECT_EQ(target->page(0).rgba, s1);
    EXPECT_FALSE(target->changes(second).texels.empty());
    ASSERT_TRUE(first.undo(*target));
    EXPECT_EQ(target->page(0).rgba, s0);
    ASSERT_TRUE(first.redo(*target));
    EXPECT_EQ(target->page(0).rgba, s1);
    ASSERT_TRUE(second.redo(*target));
    EXPECT_EQ(target->page(0).rgba, s2);

    // A stroke that changes nothing (outside the mesh) leaves no record.
    EXPECT_TRUE(
        stroke(*target, scene.layers, brush, {makeDab(scene.layers.stack, {3, 3}, 2)}).empty());
}

TEST(TextureTarget, MaterialsWithTexturesAndFactorsGetTheirOwnPages) {
    const core::View view = pixelView(100, 100);
    core::Mesh mesh;
    addQuad(mesh, {{0.0f, 0.0f}, {50.0f, 100.0f}, 5.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 1});
    addQuad(mesh, {{50.0f, 0.0f}, {100.0f, 100.0f}, 5.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 1});
    addQuad(mesh, {{0.0f, 0.0f}, {100.0f, 50.0f}, 6.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 1});
    core::Image image;
    image.width = image.height = 16;
    image.rgba.assign(16 * 16 * 4, 128);
    mesh.textures.push_back(image);
    mesh.materials = {{"plain", glm::vec4(1.0f), 0},
                      {"tinted", glm::vec4(0.5f, 1.0f, 1.0f, 1.0f), 0},
                      {"untextured", glm::vec4(0.2f, 0.4f, 0.6f, 1.0f), -1}};
    mesh.triangleMaterial = {0, 0, 1, 1, 2, 2};
    const Scene scene = paintScene(std::move(mesh), view);
    auto target = textureTarget(scene);
    ASSERT_EQ(target->pageCount(), 3u);
    EXPECT_EQ(target->page(0).rgba, image.rgba); // kept byte for byte
    EXPECT_EQ(target->pageSource(1), 0);         // the texture with the tint baked in
    EXPECT_EQ(texel(target->page(1), 3, 3)[0],
              core::linearToSrgb(0.5f * core::srgbToLinear(std::uint8_t(128))));
    EXPECT_EQ(target->pageSource(2), -1);
    EXPECT_EQ(target->page(2).width, 2048);
    for (std::size_t m = 0; m < 3; ++m)
        EXPECT_EQ(target->drawMaterials()[m].baseColorTexture, int(m));
    EXPECT_EQ(target->trianglePage(2), 1u);
}

TEST(TextureTarget, RejectsMeshesWithoutUvs) {
    core::Mesh mesh;
    addQuad(mesh, {{0.0f, 0.0f}, {10.0f, 10.0f}}, false);
    auto shared = std::make_shared<core::Mesh>(mesh);
    EXPECT_FALSE(core::TextureTarget::create(shared, nullptr).ok());
    auto target = core::makePaintTarget(shared, nullptr);
    ASSERT_TRUE(target.ok());
    EXPECT_EQ((*target)->kind(), core::PaintTargetKind::VertexColors);
    EXPECT_FALSE(core::makePaintTarget(nullptr, nullptr).ok());
}

TEST(VertexColorTarget, PaintsTheVerticesInsideTheDabOnItsLayer) {
    TwoQuads s;
    core::Mesh mesh = *s.scene.mesh;
    mesh.uvs.clear();
    const Scene scene = paintScene(std::move(mesh), s.view);
    auto made = core::makePaintTarget(scene.mesh, scene.topology);
    ASSERT_TRUE(made.ok()) << made.error();
    core::PaintTarget& target = **made;
    ASSERT_EQ(target.kind(), core::PaintTargetKind::VertexColors);
    auto& colors = static_cast<core::VertexColorTarget&>(target);
    EXPECT_EQ(colors.colors()[0], glm::vec4(0.5f, 0.5f, 0.5f, 1.0f)); // factor baked in
    const std::size_t backVertices = 25;                              // 5 × 5 grid

    for (const std::uint32_t layer : {1u, 2u}) {
        const glm::vec2 center(101.0f, 99.0f);
        const core::Dab dab = makeDab(scene.layers.stack, center, 45.0f, layer);
        target.beginStroke(hardBrush());
        const core::PaintChanges& changes = target.paint(scene.layers, dab);
        EXPECT_FALSE(changes.vertices.empty());
        core::TileUndoRecord record = target.endStroke();
        int painted = 0;
        for (std::size_t v = 0; v < colors.colors().size(); ++v) {
            const bool changed = colors.colors()[v] != colors.originalColors()[v];
            const glm::vec3 p = scene.mesh->positions[v];
            const bool onLayer = layer == 1 ? v >= backVertices : v < backVertices;
            const bool expected = onLayer && glm::length(glm::vec2(p) - center) < 45.0f &&
                                  inMap(dab, s.view.width, glm::vec2(p) + 0.001f);
            EXPECT_EQ(changed, expected) << "vertex " << v << " layer " << layer;
            if (changed) {
                EXPECT_EQ(colors.colors()[v], hardBrush().color);
            }
            painted += changed;
        }
        EXPECT_GT(painted, 0);
        ASSERT_TRUE(record.undo(target));
        EXPECT_EQ(colors.colors(), colors.originalColors());
        ASSERT_TRUE(record.redo(target));
        EXPECT_NE(colors.colors(), colors.originalColors());
        ASSERT_TRUE(record.undo(target));
    }
}

// ---------------------------------------------------------------------------------------------
// The trefoil at the paper's size: 144K vertices, 1280 × 720, a 2048² texture.

class TrefoilPaint : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        s_scene = new Scene(paintScene(core::makeTrefoil(), trefoilView()));
    }
    static void TearDownTestSuite() {
        delete s_scene;
        s_scene = nullptr;
    }
    static core::View trefoilView() {
        const core::Camera camera =
            core::Camera::fromOrbit(core::makeTrefoil(20, 8).bounds(), 20.0f, 15.0f, 1.6f);
        return camera.view(1280, 720);
    }
    /** A centre whose whole disc of radius has fragments on layer (and the first layer). */
    static glm::vec2 findCenter(float radius, std::uint32_t layer) {
        const core::DepthStack& stack = s_scene->layers.stack;
        for (int y = int(radius) + 8; y < stack.height - int(radius) - 8; y += 7) {
            for (int x = int(radius) + 8; x < stack.width - int(radius) - 8; x += 7) {
                bool all = true;
                for (int dy = -int(radius); dy <= int(radius) && all; dy += 2)
                    for (int dx = -int(radius); dx <= int(radius) && all; dx += 2)
                        if (dx * dx + dy * dy <= int(radius * radius))
                            all = stack.fragment(std::size_t(y + dy) * std::size_t(stack.width) +
                                                     std::size_t(x + dx),
                                                 layer) != kNone;
                if (all)
                    return {float(x) + 0.5f, float(y) + 0.5f};
            }
        }
        return {-1.0f, -1.0f};
    }
    /**
     * Checks the texels of the triangles near the dab: every painted one lies on the dab's layer
     * within the radius; every one inside the radius whose own triangle is the map fragment's
     * at its pixel is painted (no holes).
     */
    static void checkDab(const core::TextureTarget& target, const core::Dab& dab) {
        const core::Mesh& mesh = *s_scene->mesh;
        const core::DepthLayers& layers = s_scene->layers;
        const core::DepthStack& stack = layers.stack;
        const core::Image& page = target.page(0);
        const core::Image& original = target.originalPage(0);
        std::vector<std::uint32_t> mapFragment(stack.pixelCount(), kNone);
        for (const core::MapPixel& m : dab.paintable)
            mapFragment[m.pixel] = m.fragment;
        int painted = 0, checked = 0, checkedNear = 0;
        std::vector<std::uint8_t> seen(page.rgba.size() / 4, 0);
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            glm::vec3 pos[3], win[3];
            glm::vec2 uv[3];
            bool near = false;
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t v = mesh.indices[3 * t + std::size_t(c)];
                pos[c] = mesh.positions[v];
                uv[c] = mesh.uvs[v] * glm::vec2(float(page.width), float(page.height));
                win[c] = layers.view.project(pos[c]);
                near = near || glm::length(glm::vec2(win[c]) - dab.center) < dab.radius + 4.0f;
            }
            if (!near)
                continue;
            const float area = (uv[1].x - uv[0].x) * (uv[2].y - uv[0].y) -
                               (uv[2].x - uv[0].x) * (uv[1].y - uv[0].y);
            const int x0 = int(std::floor(std::min({uv[0].x, uv[1].x, uv[2].x})));
            const int x1 = int(std::ceil(std::max({uv[0].x, uv[1].x, uv[2].x})));
            const int y0 = int(std::floor(std::min({uv[0].y, uv[1].y, uv[2].y})));
            const int y1 = int(std::ceil(std::max({uv[0].y, uv[1].y, uv[2].y})));
            for (int y = y0; y <= y1; ++y) {
                for (int x = x0; x <= x1; ++x) {
                    const glm::vec2 q(float(x) + 0.5f, float(y) + 0.5f);
                    const float b1 = ((q.x - uv[0].x) * (uv[2].y - uv[0].y) -
                                      (uv[2].x - uv[0].x) * (q.y - uv[0].y)) /
                                     area;
                    const float b2 = ((uv[1].x - uv[0].x) * (q.y - uv[0].y) -
                                      (q.x - uv[0].x) * (uv[1].y - uv[0].y)) /
                                     area;
                    const float b0 = 1.0f - b1 - b2;
                    if (b0 < 1e-4f || b1 < 1e-4f || b2 < 1e-4f)
                        continue; // centres on or near edges: judged by the neighbour
                    const glm::vec3 point = b0 * pos[0] + b1 * pos[1] + b2 * pos[2];
                    const glm::vec3 w = layers.view.project(point);
                    const glm::vec2 p(w);
                    const bool changed = !sameTexel(page, original, x, y);
                    const float d = glm::length(p - dab.center);
                    const std::size_t pixel =
                        std::size_t(std::floor(p.y)) * std::size_t(stack.width) +
                        std::size_t(std::floor(p.x));
                    const std::uint32_t f = p.x >= 0 && p.y >= 0 && p.x < float(stack.width) &&
                                                    p.y < float(stack.height)
                                                ? mapFragment[pixel]
                                                : kNone;
                    if (changed) {
                        seen[std::size_t(y) * std::size_t(page.width) + std::size_t(x)] = 1;
                        EXPECT_LT(d, dab.radius + 1e-3f);
                        // In the map, or where the outline of the map's surface crosses a pixel
                        // beside it: nothing at the texel's pixel is on that surface or in front.
                        std::uint32_t beside = f;
                        if (beside == kNone) {
                            const int px = int(std::floor(p.x)), py = int(std::floor(p.y));
                            ASSERT_TRUE(px >= 0 && py >= 0 && px < stack.width &&
                                        py < stack.height);
                            for (int dy = -1; dy <= 1 && beside == kNone; ++dy)
                                for (int dx = -1; dx <= 1 && beside == kNone; ++dx)
                                    if (px + dx >= 0 && py + dy >= 0 && px + dx < stack.width &&
                                        py + dy < stack.height)
                                        beside = mapFragment[std::size_t(py + dy) *
                                                                 std::size_t(stack.width) +
                                                             std::size_t(px + dx)];
                            ASSERT_NE(beside, kNone) << "painted texel outside the map";
                            // At the dab's rim the pixel's centre (outside the circle) may
                            // have seen this very surface.
                            const bool rim =
                                glm::length(glm::floor(p) + 0.5f - dab.center) >= dab.radius;
                            for (std::uint32_t g = stack.offsets[pixel];
                                 g < stack.offsets[pixel + 1]; ++g)
                                EXPECT_GT(stack.depth[g], w.z - (rim ? 0.01f : 0.0f))
                                    << "painted texel under a surface";
                        }
                        // On the map's surface (strands are 1.21 apart, the tube 0.9 wide).
                        EXPECT_NEAR(w.z, stack.depth[beside], 0.3f);
                    }
                    if (f == kNone || !(d < dab.radius - 0.05f))
                        continue;
                    // Its own triangle is the map's fragment there, or (a triangle too small to
                    // have a fragment) its point is at the fragment's depth: it must get paint.
                    if (stack.triangle[f] == t) {
                        ++checked;
                        EXPECT_TRUE(changed) << "hole at texel " << x << "," << y;
                    } else if (std::fabs(w.z - stack.depth[f]) < 0.003f) {
                        ++checkedNear;
                        EXPECT_TRUE(changed) << "hole at texel " << x << "," << y
                                             << " of a triangle without the fragment";
                    }
                }
            }
        }
        for (std::size_t i = 0; i < seen.size(); ++i)
            painted += seen[i];
        EXPECT_GT(checked, 1000);
        EXPECT_GT(checkedNear, 10);
        EXPECT_GT(painted, checked / 2);
    }

    static Scene* s_scene;
};

Scene* TrefoilPaint::s_scene = nullptr;

TEST_F(TrefoilPaint, LayerOneDabHasNoHolesAndStaysOnItsSurface) {
    ASSERT_EQ(s_scene->mesh->vertexCount(), 144000u);
    const glm::vec2 center = findCenter(32.0f, 1);
    ASSERT_GE(center.x, 0.0f);
    auto target = textureTarget(*s_scene);
    ASSERT_EQ(target->page(0).width, 2048);
    const core::Dab dab = makeDab(s_scene->layers.stack, center, 32.0f, 1);
    const core::TileUndoRecord record = stroke(*target, s_scene->layers, hardBrush(), {dab});
    EXPECT_FALSE(record.empty());
    checkDab(*target, dab);
}

TEST_F(TrefoilPaint, LayerTwoDabPaintsTheHiddenStrand) {
    const glm::vec2 center = findCenter(12.0f, 2);
    ASSERT_GE(center.x, 0.0f) << "no crossing in view";
    auto target = textureTarget(*s_scene);
    const core::Dab dab = makeDab(s_scene->layers.stack, center, 12.0f, 2);
    stroke(*target, s_scene->layers, hardBrush(), {dab});
    checkDab(*target, dab);
}

} // namespace paint_target_test
