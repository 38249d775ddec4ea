// SPDX-License-Identifier: GPL-3.0-or-later
// draw_layers on a headless EGL context (llvmpipe on CI): the composite against a plain render,
// single layers against the stack's counts, segmentation colours and region order against a CPU
// lookup of the visible fragment. Set LAYERPAINT_TEST_IMAGES=DIR to write the pictures as PNGs.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "tests/render/compositor_test.h"

#include "core/depth/depth_layers.h"
#include "core/io/image/image_write.h"
#include "core/io/mesh_io.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/model/mesh_topology.h"
#include "core/paint/tracking/stroke_tracker.h"
#include "core/regions/region_order.h"
#include "render/depth_compositor.h"
#include "render/gl_context.h"
#include "render/gl_depth_capturer.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"

namespace layer_compositor_gltest {

using core::kNone;

constexpr std::uint32_t kUnranked = 0xfffffffeu;

using render_test::channelDifference;
using render_test::DepthCompositorGlTest;
using render_test::expectMatchesPlainRender;
using render_test::orbitView;
using render_test::saveImage;

/** An sRGB colour as the framebuffer stores it. */
std::array<int, 3> toBytes(const glm::vec4& color) {
    return {int(std::lround(std::clamp(color.r, 0.0f, 1.0f) * 255.0f)),
            int(std::lround(std::clamp(color.g, 0.0f, 1.0f) * 255.0f)),
            int(std::lround(std::clamp(color.b, 0.0f, 1.0f) * 255.0f))};
}

bool near(const core::Image& image, std::size_t pixel, const glm::vec4& color, int tolerance) {
    const std::array<int, 3> expected = toBytes(color);
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(image.rgba[pixel * 4 + std::size_t(c)]) - expected[std::size_t(c)]) >
            tolerance)
            return false;
    return true;
}

/** The CPU lookup of the visible fragment (docs/architecture.md §3 step 3), kNone for background.
 */
std::uint32_t visibleFragment(const core::DepthLayers& layers,
                              const std::vector<std::uint32_t>& rank, std::size_t pixel) {
    std::uint32_t best = kNone, chosen = kNone;
    for (std::uint32_t f = layers.stack.offsets[pixel]; f < layers.stack.offsets[pixel + 1]; ++f) {
        const std::uint32_t region = layers.segmentation.region[f];
        const std::uint32_t r = region < rank.size() ? rank[region] : kUnranked;
        if (r < best) {
            best = r;
            chosen = f;
        }
    }
    return chosen;
}

/** The Boundaries overlay's rule on the CPU: fragment f at pixel ends its region somewhere. */
bool onBoundary(const core::DepthLayers& layers, std::size_t pixel, std::uint32_t f) {
    const core::DepthStack& stack = layers.stack;
    const int x = int(pixel % std::size_t(stack.width)), y = int(pixel / std::size_t(stack.width));
    const std::uint32_t layer = f - stack.offsets[pixel] + 1;
    const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, -1, 1}; // right, left, up, down
    for (int d = 0; d < 4; ++d) {
        const int nx = x + dx[d], ny = y + dy[d];
        if (nx < 0 || ny < 0 || nx >= stack.width || ny >= stack.height)
            continue;
        const std::size_t q = std::size_t(ny) * std::size_t(stack.width) + std::size_t(nx);
        if (stack.layerCount(q) == 0 || layers.connectivity.link(f, d) == layer)
            continue;
        const std::uint32_t g = stack.fragment(q, layer);
        if (g != kNone && layers.connectivity.link(g, d ^ 1) == layer)
            continue;
        return true;
    }
    return false;
}

std::vector<std::uint32_t> defaultRanks(const core::DepthLayers& layers) {
    std::vector<std::uint32_t> rank(layers.segmentation.graph.regions.size());
    for (std::size_t r = 0; r < rank.size(); ++r)
        rank[r] = std::uint32_t(r);
    return rank;
}

TEST_F(DepthCompositorGlTest, DefaultOrderMatchesPlainRender) {
    struct Case {
        const char* name;
        core::Mesh mesh;
        float yaw, pitch;
    };
    const Case cases[] = {{"trefoil", core::makeTrefoil(), 45.0f, 60.0f},
                          {"hexring", core::makeHexRing(), 10.0f, 25.0f}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const core::View view = orbitView(c.mesh, c.yaw, c.pitch, 320, 240, 0.6f);
        const core::DepthLayers layers = build(c.mesh, view);
        ASSERT_TRUE(m_compositor.hasDepthLayers());
        const render::CompositeOptions options;
        const core::Image composited = composite(layers, options);
        const core::Image rendered = plain(view, options.background);
        saveImage(composited, std::string(c.name) + "_composite");
        saveImage(rendered, std::string(c.name) + "_plain");
        expectMatchesPlainRender(composited, rendered, layers.stack);
    }
}

TEST_F(DepthCompositorGlTest, SingleLayerShowsExactlyThePixelsWithThatLayer) {
    const core::Mesh mesh = core::makeTrefoil(120, 40);
    const core::View view = orbitView(mesh, 45.0f, 60.0f, 320, 240, 0.6f);
    const core::DepthLayers layers = build(mesh, view);
    const std::uint32_t maxLayers = layers.stack.maxLayers();
    ASSERT_GE(maxLayers, 3u);
    render::CompositeOptions options;
    options.display = render::DepthLayerDisplay::SingleLayer;
    options.background = {0.0f, 0.0f, 0.0f, 0.0f}; // alpha 0 tells background from surface
    for (std::uint32_t k = 1; k <= maxLayers + 1; ++k) {
        SCOPED_TRACE("layer " + std::to_string(k));
        options.layer = k;
        const core::Image image = composite(layers, options);
        if (k <= 3)
            saveImage(image, "trefoil_layer" + std::to_string(k));
        std::size_t wrong = 0, shown = 0;
        for (std::size_t p = 0; p < layers.stack.pixelCount(); ++p) {
            const bool drawn = image.rgba[p * 4 + 3] != 0;
            shown += drawn;
            wrong += drawn != (layers.stack.layerCount(p) >= k);
        }
        EXPECT_EQ(wrong, 0u);
        const std::uint32_t expected = k <= maxLayers ? layers.stack.fragmentsPerLayer()[k - 1] : 0;
        EXPECT_EQ(shown, expected);
    }
}

TEST_F(DepthCompositorGlTest, SegmentationColoursTheVisibleRegion) {
    const core::Mesh mesh = core::makeTrefoil(120, 40);
    const core::View view = orbitView(mesh, 45.0f, 60.0f, 320, 240, 0.6f);
    const core::DepthLayers layers = build(mesh, view);
    const core::DepthStack& stack = layers.stack;
    ASSERT_EQ(layers.segmentation.region.size(), stack.fragmentCount());

    render::CompositeOptions options;
    options.display = render::DepthLayerDisplay::Segmentation;
    options.shadeSegmentation = false;
    core::Image image = composite(layers, options);
    saveImage(image, "trefoil_segmentation_flat");
    std::size_t wrong = 0;
    for (std::size_t p = 0; p < stack.pixelCount(); ++p) {
        const std::uint32_t f = stack.fragment(p, 1);
        const glm::vec4 expected =
            f == kNone ? options.background : render::regionColor(layers.segmentation.region[f]);
        wrong += !near(image, p, expected, 2);
    }
    EXPECT_EQ(wrong, 0u);

    // Hiding every layer-1 region uncovers layer 2 where there is one, background elsewhere.
    std::vector<std::uint32_t> rank = defaultRanks(layers);
    for (const core::Region& region : layers.segmentation.graph.regions)
        if (region.layer == 1)
            rank[region.id] = kNone;
    ASSERT_TRUE(m_compositor.setRegionRanks(rank));
    image = composite(layers, options);
    saveImage(image, "trefoil_segmentation_layer1_hidden");
    wrong = 0;
    std::size_t second = 0;
    for (std::size_t p = 0; p < stack.pixelCount(); ++p) {
        const std::uint32_t f = stack.fragment(p, 2);
        second += f != kNone;
        const glm::vec4 expected =
            f == kNone ? options.background : render::regionColor(layers.segmentation.region[f]);
        wrong += !near(image, p, expected, 2);
    }
    EXPECT_GT(second, stack.pixelCount() / 20);
    EXPECT_EQ(wrong, 0u);

    // Shaded, the hue stays: every covered pixel is a darkened region colour, never brighter.
    ASSERT_TRUE(m_compositor.setRegionRanks(defaultRanks(layers)));
    options.shadeSegmentation = true;
    image = composite(layers, options);
    saveImage(image, "trefoil_segmentation");
    wrong = 0;
    for (std::size_t p = 0; p < stack.pixelCount(); ++p) {
        const std::uint32_t f = stack.fragment(p, 1);
        if (f == kNone)
            continue;
        const std::array<int, 3> flat = toBytes(render::regionColor(layers.segmentation.region[f]));
        for (int c = 0; c < 3; ++c) {
            const int value = image.rgba[p * 4 + std::size_t(c)];
            wrong += value > flat[std::size_t(c)] + 2 || value < flat[std::size_t(c)] * 6 / 10 - 2;
        }
    }
    EXPECT_EQ(wrong, 0u);
}

TEST_F(DepthCompositorGlTest, RegionRanksChangeThePictureWithoutRecapture) {
    const core::Mesh mesh = core::makeTrefoil(120, 40);
    const core::View view = orbitView(mesh, 45.0f, 60.0f, 320, 240, 0.6f);
    const core::DepthLayers layers = build(mesh, view);
    const core::DepthStack& stack = layers.stack;
    const std::vector<core::Region>& regions = layers.segmentation.graph.regions;

    // Pop up the largest layer-2 region and hide the largest layer-1 one.
    std::uint32_t popped = kNone, hidden = kNone;
    for (const core::Region& region : regions) {
        std::uint32_t& pick = region.layer == 2 ? popped : region.layer == 1 ? hidden : popped;
        if (region.layer <= 2 && (pick == kNone || region.pixels > regions[pick].pixels))
            pick = region.id;
    }
    ASSERT_NE(popped, kNone);
    ASSERT_NE(hidden, kNone);
    std::vector<std::uint32_t> rank(regions.size());
    for (std::uint32_t r = 0; r < rank.size(); ++r)
        rank[r] = r == popped ? 0 : r + 1;
    rank[hidden] = kNone;

    render::CompositeOptions options;
    options.display = render::DepthLayerDisplay::Segmentation;
    options.shadeSegmentation = false;
    const core::Image before = composite(layers, options);
    render::CompositeOptions shaded;
    const core::Image shadedBefore = composite(layers, shaded);
    EXPECT_FALSE(m_compositor.setRegionRanks(std::vector<std::uint32_t>(rank.size() + 1, 0)));
    ASSERT_TRUE(m_compositor.setRegionRanks(rank));
    const core::Image after = composite(layers, options);
    const core::Image shadedAfter = composite(layers, shaded);
    saveImage(after, "trefoil_ranks_segmentation");
    saveImage(shadedAfter, "trefoil_ranks_composite");

    std::size_t wrong = 0, changed = 0, expectedChanges = 0, shadedChanged = 0;
    const std::vector<std::uint32_t> initial = defaultRanks(layers);
    for (std::size_t p = 0; p < stack.pixelCount(); ++p) {
        const std::uint32_t f = visibleFragment(layers, rank, p);
        const glm::vec4 expected =
            f == kNone ? options.background : render::regionColor(layers.segmentation.region[f]);
        wrong += !near(after, p, expected, 2);
        changed += channelDifference(before, after, p) > 2;
        expectedChanges += f != visibleFragment(layers, initial, p);
        shadedChanged += channelDifference(shadedBefore, shadedAfter, p) > 2;
    }
    EXPECT_EQ(wrong, 0u);
    EXPECT_GE(changed, std::size_t(regions[popped].pixels));
    EXPECT_LE(changed, expectedChanges);
    EXPECT_GT(shadedChanged, expectedChanges / 2);

    // Highlight touches only the region's own pixels (tinted) and those it lies behind (stripes).
    ASSERT_TRUE(m_compositor.setRegionRanks(initial));
    options.highlightRegion = popped;
    const core::Image highlighted = composite(layers, options);
    saveImage(highlighted, "trefoil_highlight");
    std::size_t outside = 0, tinted = 0;
    for (std::size_t p = 0; p < stack.pixelCount(); ++p) {
        bool inRegion = false;
        for (std::uint32_t f = stack.offsets[p]; f < stack.offsets[p + 1]; ++f)
            inRegion = inRegion || layers.segmentation.region[f] == popped;
        const bool differs = channelDifference(before, highlighted, p) > 2;
        outside += differs && !inRegion;
        tinted += differs;
    }
    EXPECT_EQ(outside, 0u);
    EXPECT_GT(tinted, std::size_t(regions[popped].pixels) / 3);

    // Boundaries darken exactly the visible fragments that end their region towards a
    // neighbour with any fragment, and nothing else.
    options.highlightRegion = kNone;
    options.boundaries = true;
    const core::Image outlined = composite(layers, options);
    saveImage(outlined, "trefoil_boundaries");
    std::size_t wrongLines = 0, lines = 0;
    for (std::size_t p = 0; p < stack.pixelCount(); ++p) {
        const std::uint32_t f = stack.fragment(p, 1);
        const bool expected = f != kNone && onBoundary(layers, p, f);
        const bool darkened = channelDifference(before, outlined, p) > 2;
        lines += expected;
        wrongLines += expected != darkened;
        if (darkened) {
            const int sumBefore =
                before.rgba[p * 4] + before.rgba[p * 4 + 1] + before.rgba[p * 4 + 2];
            const int sumAfter =
                outlined.rgba[p * 4] + outlined.rgba[p * 4 + 1] + outlined.rgba[p * 4 + 2];
            EXPECT_LT(sumAfter, sumBefore);
        }
    }
    EXPECT_EQ(wrongLines, 0u);
    EXPECT_GT(lines, 100u);
    EXPECT_LT(lines, stack.pixelCount() / 5);
}

/**
 * The region order in use (pop-ups, cycling, hiding) through pruned ranks: the drawn visible
 * map equals the CPU lookup with the full ranks, pixel for pixel; with transparency the
 * see-through fragments blend over the next one in the order.
 */
TEST_F(DepthCompositorGlTest, DrawnVisibleMapEqualsTheCpuLookupAfterPopUpsAndHiding) {
    const core::Mesh mesh = core::makeTrefoil(120, 40);
    const core::View view = orbitView(mesh, 45.0f, 60.0f, 320, 240, 0.6f);
    const core::DepthLayers layers = build(mesh, view);
    const core::DepthStack& stack = layers.stack;
    const std::vector<std::uint32_t>& region = layers.segmentation.region;
    core::RegionOrder order(layers.segmentation.graph);

    // Pixels with the most layers, where the order matters most.
    std::vector<std::size_t> deep;
    for (std::size_t p = 0; p < stack.pixelCount(); ++p)
        if (stack.layerCount(p) >= 3)
            deep.push_back(p);
    ASSERT_GT(deep.size(), 20u);

    render::CompositeOptions options;
    options.display = render::DepthLayerDisplay::Segmentation;
    options.shadeSegmentation = false;
    const auto check = [&](const char* step) {
        for (const bool transparency : {false, true}) {
            ASSERT_TRUE(m_compositor.setRegionRanks(order.prunedRanks(transparency)));
            options.popUpOpacity = transparency ? 0.0f : 1.0f;
            const core::Image image = composite(layers, options);
            const std::vector<std::uint32_t> drawn = m_compositor.readVisible();
            ASSERT_EQ(drawn.size(), stack.pixelCount());
            const std::vector<std::uint32_t> rank = order.ranks();
            std::size_t wrong = 0, wrongColour = 0, seeThrough = 0;
            for (std::size_t p = 0; p < stack.pixelCount(); ++p) {
                const std::uint32_t f = core::visibleFragmentByRank(stack, region, rank, p);
                wrong += drawn[p] != f;
                // Opacity 0 shows what lies under a see-through fragment: the next in order.
                std::uint32_t shown = f;
                if (transparency && f != kNone && f != stack.offsets[p]) {
                    std::uint32_t under = kNone;
                    for (std::uint32_t g = stack.offsets[p]; g < stack.offsets[p + 1]; ++g)
                        if (g != f && rank[region[g]] != kNone &&
                            (under == kNone || rank[region[g]] < rank[region[under]]))
                            under = g;
                    if (under != kNone) {
                        shown = under;
                        ++seeThrough;
                    }
                }
                const glm::vec4 expected =
                    shown == kNone ? options.background : render::regionColor(region[shown]);
                wrongColour += !near(image, p, expected, 2);
            }
            EXPECT_EQ(wrong, 0u) << step << (transparency ? " (transparency)" : "");
            EXPECT_EQ(wrongColour, 0u) << step << (transparency ? " (transparency)" : "");
            if (transparency && std::string(step) != "initial") {
                EXPECT_GT(seeThrough, 0u) << step;
            }
        }
    };
    check("initial");
    // Click-to-cycle at one deep pixel twice, a pop-up with neighbours elsewhere, then hiding.
    const std::size_t a = deep[deep.size() / 3], b = deep[2 * deep.size() / 3];
    ASSERT_NE(order.cycleAt(core::regionsAtPixel(stack, region, a)), kNone);
    check("first click");
    ASSERT_NE(order.cycleAt(core::regionsAtPixel(stack, region, a)), kNone);
    check("second click");
    order.popUpWithNeighbours(region[stack.fragment(b, 3)]);
    check("pop-up with neighbours");
    order.hide(region[stack.fragment(b, 1)]);
    order.hide(region[stack.fragment(a, 1)]);
    check("hidden");
}

TEST_F(DepthCompositorGlTest, UpdateSegmentationFollowsNewRegions) {
    const core::Mesh mesh = core::makeTrefoil(120, 40);
    const core::View view = orbitView(mesh, 45.0f, 60.0f, 320, 240, 0.6f);
    core::DepthLayers layers = build(mesh, view);
    render::CompositeOptions options;
    options.display = render::DepthLayerDisplay::Segmentation;
    options.shadeSegmentation = false;
    (void)composite(layers, options);

    // The paper's plain depth test splits the tube into many more regions.
    core::DepthLayerOptions plain;
    plain.test = core::ConnectionTest::Plain;
    const std::size_t before = layers.segmentation.graph.regions.size();
    core::resegmentDepthLayers(layers, mesh, plain);
    ASSERT_NE(layers.segmentation.graph.regions.size(), before);
    const core::Status status = m_compositor.updateSegmentation(layers);
    ASSERT_TRUE(status) << status.error();
    const core::Image image = composite(layers, options);
    saveImage(image, "trefoil_segmentation_plain_test");
    std::size_t wrong = 0;
    for (std::size_t p = 0; p < layers.stack.pixelCount(); ++p) {
        const std::uint32_t f = layers.stack.fragment(p, 1);
        const glm::vec4 expected =
            f == kNone ? options.background : render::regionColor(layers.segmentation.region[f]);
        wrong += !near(image, p, expected, 2);
    }
    EXPECT_EQ(wrong, 0u);

    // Another capture's segmentation is refused.
    core::DepthLayers other = layers;
    other.stack.width += 1;
    EXPECT_FALSE(m_compositor.updateSegmentation(other));
}

TEST_F(DepthCompositorGlTest, TexturedModelShowsItsTexture) {
    const std::string path =
        std::string(LAYERPAINT_ASSIMP_MODELS) + "/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!std::filesystem::exists(path))
        GTEST_SKIP() << path << " is not installed";
    auto mesh = core::loadMesh(path);
    ASSERT_TRUE(mesh) << mesh.error();
    ASSERT_FALSE(mesh->textures.empty());
    const core::View view = orbitView(*mesh, 30.0f, 25.0f, 320, 240);
    const core::DepthLayers layers = build(*mesh, view);
    const render::CompositeOptions options;
    const core::Image composited = composite(layers, options);
    const core::Image rendered = plain(view, options.background);
    saveImage(composited, "box_textured_composite");
    saveImage(rendered, "box_textured_plain");
    expectMatchesPlainRender(composited, rendered, layers.stack);

    // The texture shows: many distinct colours, unlike the flat-shaded box without it.
    core::Mesh untextured = *mesh;
    for (core::Material& material : untextured.materials)
        material.baseColorTexture = -1;
    ASSERT_TRUE(m_compositor.setMesh(untextured));
    const core::Image flat = composite(layers, options);
    std::size_t differing = 0;
    for (std::size_t p = 0; p < layers.stack.pixelCount(); ++p)
        differing += channelDifference(composited, flat, p) > 20;
    EXPECT_GT(differing, layers.stack.pixelCount() / 20);
}

/** Two quads facing the camera with one texture each and one untextured: one pass per texture. */
TEST_F(DepthCompositorGlTest, EachTextureGetsItsPass) {
    core::Mesh mesh;
    const auto quad = [&](float x0, std::uint32_t material) {
        const auto base = std::uint32_t(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), {{x0, -0.5f, 0.0f},
                                                     {x0 + 0.9f, -0.5f, 0.0f},
                                                     {x0 + 0.9f, 0.5f, 0.0f},
                                                     {x0, 0.5f, 0.0f}});
        mesh.uvs.insert(mesh.uvs.end(), {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}});
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
        mesh.triangleMaterial.insert(mesh.triangleMaterial.end(), {material, material});
    };
    quad(-1.5f, 0);
    quad(-0.5f, 1);
    quad(0.5f, 2);
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    const auto solid = [](std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        core::Image image{2, 2, {}};
        for (int i = 0; i < 4; ++i)
            image.rgba.insert(image.rgba.end(), {r, g, b, 255});
        return image;
    };
    mesh.textures = {solid(230, 40, 30), solid(30, 60, 220)};
    mesh.materials = {core::Material{"red", glm::vec4(1.0f), 0},
                      core::Material{"plain", glm::vec4(0.2f, 0.8f, 0.2f, 1.0f), -1},
                      core::Material{"blue", glm::vec4(1.0f), 1}};
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().error();

    core::Camera camera;
    camera.frame(mesh.bounds());
    const core::View view = camera.view(240, 120);
    const core::DepthLayers layers = build(mesh, view);
    const render::CompositeOptions options;
    const core::Image composited = composite(layers, options);
    const core::Image rendered = plain(view, options.background);
    saveImage(composited, "three_quads_composite");
    expectMatchesPlainRender(composited, rendered, layers.stack);

    const auto at = [&](float x) {
        const glm::vec3 pixel = view.project({x, 0.0f, 0.0f});
        const std::size_t p = std::size_t(int(pixel.y)) * std::size_t(view.width) + int(pixel.x);
        return glm::ivec3(composited.rgba[p * 4], composited.rgba[p * 4 + 1],
                          composited.rgba[p * 4 + 2]);
    };
    const glm::ivec3 red = at(-1.05f), green = at(-0.05f), blue = at(0.95f);
    EXPECT_GT(red.r, red.b + 100);
    EXPECT_GT(green.g, green.r + 60);
    EXPECT_GT(blue.b, blue.r + 100);
}

/**
 * At the paper's size (the 144K-vertex trefoil at 1280 × 720, framed and from close up): the
 * default order draws what a plain render shows, and with the largest layer-2 region popped up
 * the drawn fragment of every pixel is the CPU lookup's. How long these draws take is measured by
 * the benchmarks (bench/gl_bench.cpp), not here.
 */
TEST_F(DepthCompositorGlTest, TrefoilAt1280x720MatchesPlainRenderAndTheCpuLookup) {
    const core::Mesh mesh = core::makeTrefoil();
    struct Case {
        const char* name;
        float yaw, pitch, zoom;
    };
    for (const Case& c : {Case{"framed", 0.0f, 0.0f, 1.0f}, Case{"close", 45.0f, 60.0f, 0.6f}}) {
        SCOPED_TRACE(c.name);
        const core::View view = orbitView(mesh, c.yaw, c.pitch, 1280, 720, c.zoom);
        const core::DepthLayers layers = build(mesh, view);
        ASSERT_TRUE(m_compositor.hasDepthLayers());
        const render::CompositeOptions options;
        const core::Image composited = composite(layers, options);
        const core::Image rendered = plain(view, options.background);
        saveImage(composited, std::string("trefoil720_") + c.name + "_composite");
        expectMatchesPlainRender(composited, rendered, layers.stack);

        // Popping up the largest layer-2 region defeats the early exit of the fragment search.
        const std::vector<core::Region>& regions = layers.segmentation.graph.regions;
        std::uint32_t popped = kNone;
        for (const core::Region& region : regions)
            if (region.layer == 2 && (popped == kNone || region.pixels > regions[popped].pixels))
                popped = region.id;
        ASSERT_NE(popped, kNone);
        std::vector<std::uint32_t> rank = defaultRanks(layers);
        for (std::uint32_t& r : rank)
            ++r;
        rank[popped] = 0;
        ASSERT_TRUE(m_compositor.setRegionRanks(rank));
        saveImage(composite(layers, options), std::string("trefoil720_") + c.name + "_popped");
        const std::vector<std::uint32_t> drawn = m_compositor.readVisible();
        ASSERT_EQ(drawn.size(), layers.stack.pixelCount());
        std::size_t wrong = 0, poppedPixels = 0;
        for (std::size_t p = 0; p < drawn.size(); ++p) {
            const std::uint32_t f = visibleFragment(layers, rank, p);
            wrong += drawn[p] != f;
            poppedPixels += f != kNone && layers.segmentation.region[f] == popped;
        }
        EXPECT_EQ(wrong, 0u);
        EXPECT_EQ(poppedPixels, regions[popped].pixels);
    }
}

} // namespace layer_compositor_gltest
