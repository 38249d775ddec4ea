// SPDX-License-Identifier: GPL-3.0-or-later
// Flood fill (core/flood_fill.h, Document::fill): each mode fills what it should and nothing
// else, on both paint target kinds, and undo restores the target byte for byte.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/base/color.h"
#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/model/mesh_topology.h"
#include "core/paint/targets/flood_fill.h"
#include "core/paint/targets/paint_target.h"
#include "tests/core/test_scenes.h"

namespace flood_fill_test {

using core::FillMode;
using core::kNone;

using core_test::pixelView;
using core_test::Quad;

using ColorFn = std::function<glm::vec4(glm::vec2 pixel)>;

/** Adds q (core_test::addQuad, a white material) with vertex colours: color's, or white. */
void addColoredQuad(core::Mesh& mesh, const Quad& q, const ColorFn& color = {}) {
    if (mesh.materials.empty())
        mesh.materials.push_back({"paint", glm::vec4(1.0f), -1});
    const std::size_t first = mesh.positions.size();
    core_test::addQuad(mesh, q);
    for (std::size_t v = first; v < mesh.positions.size(); ++v)
        mesh.colors.push_back(color ? color(glm::vec2(mesh.positions[v])) : glm::vec4(1.0f));
}

/**
 * A big back quad B (left top quarter of the texture) partly covered by a front quad F (right
 * bottom quarter), a quarter pixel off the pixel borders so no vertex projects onto one. B's
 * pixels around F are one layer-1 region, its part behind F a layer-2 region.
 */
struct TwoQuads {
    core::View view = pixelView(64, 64);
    Quad back{{4.25f, 4.25f}, {60.25f, 60.25f}, 10.0f, {0.0f, 0.0f}, {0.5f, 0.5f}, 14};
    Quad front{{22.25f, 22.25f}, {42.25f, 42.25f}, 5.0f, {0.5f, 0.5f}, {1.0f, 1.0f}, 5};
    core::Document doc;
    core::CpuDepthCapturer capturer;

    explicit TwoQuads(core::PaintTargetKind kind, const ColorFn& backColor = {}) {
        core::Mesh mesh;
        addColoredQuad(mesh, back, backColor);
        addColoredQuad(mesh, front);
        doc.setMesh(std::move(mesh), "two quads");
        core::PaintTargetOptions options;
        options.kind = kind;
        options.resolution = 512;
        EXPECT_TRUE(doc.setPaintTarget(options).ok());
        capturer.setMesh(doc.mesh());
        const core::Status built = doc.buildDepthLayers(capturer, view);
        EXPECT_TRUE(built.ok()) << built.error();
        doc.brush().color = {0.9f, 0.2f, 0.05f, 1.0f};
        doc.brush().opacity = 1.0f;
    }
    /** F covers the centres of pixels 22..41 in x and y. */
    static bool behindFront(glm::vec2 p) {
        return std::floor(p.x) >= 22.0f && std::floor(p.x) <= 41.0f && std::floor(p.y) >= 22.0f &&
               std::floor(p.y) <= 41.0f;
    }
    const core::TextureTarget& texture() {
        return dynamic_cast<const core::TextureTarget&>(*doc.paintTarget());
    }
    const core::VertexColorTarget& vertexColors() {
        return dynamic_cast<const core::VertexColorTarget&>(*doc.paintTarget());
    }
    std::uint32_t regionAt(glm::vec2 p) const {
        const core::DepthLayers& layers = *doc.depthLayers();
        const std::uint32_t f =
            doc.visibleFragment(std::size_t(p.y) * std::size_t(view.width) + std::size_t(p.x));
        return f == kNone ? kNone : layers.segmentation.region[f];
    }
    core::Status fill(glm::vec2 p, FillMode mode, float tolerance = 0.0f) {
        core::PaintChanges changes;
        const core::Status status = doc.fill(p, mode, tolerance, changes);
        lastChanges = changes;
        return status;
    }
    core::PaintChanges lastChanges;
};

const std::uint8_t* texel(const core::Image& image, std::size_t index) {
    return &image.rgba[index * 4];
}

bool sameTexel(const core::Image& a, const core::Image& b, std::size_t index) {
    return std::equal(texel(a, index), texel(a, index) + 4, texel(b, index));
}

std::array<std::uint8_t, 4> brushBytes(const glm::vec4& color) {
    return {core::linearToSrgb(color.r), core::linearToSrgb(color.g), core::linearToSrgb(color.b),
            std::uint8_t(std::lround(color.a * 255.0f))};
}

/** Texel centres of a page as uv, and whether they sit on a pixel border of quad (not judged). */
glm::vec2 texelUv(const core::Image& page, std::size_t index) {
    const auto x = int(index % std::size_t(page.width)), y = int(index / std::size_t(page.width));
    return {(float(x) + 0.5f) / float(page.width), (float(y) + 0.5f) / float(page.height)};
}

bool nearPixelBorder(glm::vec2 p, float margin = 0.02f) {
    const auto near = [&](float v) { return std::fabs(v - std::round(v)) < margin; };
    return near(p.x) || near(p.y);
}

/**
 * Checks every covered texel of page 0: painted with exactly the brush bytes iff expected(uv),
 * otherwise untouched. Texels for which judge(uv) is false are skipped. Returns the count
 * painted.
 */
int expectTexels(const core::TextureTarget& target, const glm::vec4& brush,
                 const std::function<bool(glm::vec2)>& expected,
                 const std::function<bool(glm::vec2)>& judge = {}) {
    const core::Image& page = target.page(0);
    const core::Image& original = target.originalPage(0);
    const auto bytes = brushBytes(brush);
    int painted = 0, missed = 0, stray = 0, partial = 0;
    for (std::size_t i = 0; i < page.rgba.size() / 4; ++i) {
        if (target.coverage(0)[i] != 1)
            continue;
        const glm::vec2 uv = texelUv(page, i);
        if (judge && !judge(uv))
            continue;
        const bool changed = !sameTexel(page, original, i);
        const bool want = expected(uv);
        if (changed) {
            ++painted;
            if (!std::equal(bytes.begin(), bytes.end(), texel(page, i)))
                ++partial;
        }
        if (want && !changed)
            ++missed;
        if (!want && changed)
            ++stray;
    }
    EXPECT_EQ(missed, 0) << "texels left unfilled";
    EXPECT_EQ(stray, 0) << "texels filled that should not be";
    EXPECT_EQ(partial, 0) << "texels filled with another colour";
    return painted;
}

TEST(FloodFill, ModeNamesRoundTrip) {
    for (const FillMode mode : {FillMode::Region, FillMode::Surface, FillMode::Color})
        EXPECT_EQ(core::parseFillMode(core::fillModeName(mode)), mode);
    EXPECT_FALSE(core::parseFillMode("bucket").has_value());
}

TEST(FloodFill, SurfacePointIsTheClickedPointOfTheTriangle) {
    core::Mesh mesh;
    addColoredQuad(mesh, {{10.0f, 10.0f}, {50.0f, 50.0f}, 5.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 1});
    const core::View view = pixelView(64, 64);
    // Triangle 0 is (10,10), (10,50), (50,50): the point (20, 40) is 1/4, 1/2, 1/4 of them.
    const auto b = core::surfacePointAt(mesh, view, 0, {20.0f, 40.0f});
    ASSERT_TRUE(b.has_value());
    EXPECT_NEAR(b->x, 0.25f, 1e-4f);
    EXPECT_NEAR(b->y, 0.5f, 1e-4f);
    EXPECT_NEAR(b->z, 0.25f, 1e-4f);
    EXPECT_FALSE(core::surfacePointAt(mesh, view, 7, {20.0f, 40.0f}).has_value());
}

TEST(FloodFill, NeedsLayersAndFillsNothingOnBackground) {
    core::Document doc;
    core::Mesh mesh;
    addColoredQuad(mesh, {{10.0f, 10.0f}, {50.0f, 50.0f}, 5.0f, {0.0f, 0.0f}, {1.0f, 1.0f}, 1});
    doc.setMesh(std::move(mesh), "quad");
    core::PaintChanges changes;
    EXPECT_FALSE(doc.fill({30.0f, 30.0f}, FillMode::Surface, 0.0f, changes).ok());
    core::CpuDepthCapturer capturer;
    capturer.setMesh(doc.mesh());
    ASSERT_TRUE(doc.buildDepthLayers(capturer, pixelView(64, 64)).ok());
    for (const glm::vec2 p :
         {glm::vec2(2.0f, 2.0f), glm::vec2(-5.0f, 30.0f), glm::vec2(30.0f, 64.0f),
          glm::vec2(NAN, 3.0f), glm::vec2(1e30f, 30.0f)}) {
        for (const FillMode mode : {FillMode::Region, FillMode::Surface, FillMode::Color}) {
            EXPECT_TRUE(doc.fill(p, mode, 0.5f, changes).ok());
            EXPECT_TRUE(changes.empty());
        }
    }
    EXPECT_FALSE(doc.history().canUndo());
}

TEST(FloodFillTexture, RegionFillsTheRegionUnderTheCursorAndItsHiddenPart) {
    TwoQuads s(core::PaintTargetKind::Texture);
    const std::vector<std::uint8_t> original = s.texture().page(0).rgba;
    const glm::vec4 brush = s.doc.brush().color;
    // On B around F: B's layer-1 region, none of B behind F, none of F.
    ASSERT_TRUE(s.fill({10.5f, 10.5f}, FillMode::Region).ok());
    EXPECT_FALSE(s.lastChanges.empty());
    const auto onBack = [&](glm::vec2 uv) { return s.back.hasUv(uv); };
    const auto judge = [&](glm::vec2 uv) {
        return !(s.back.hasUv(uv) && nearPixelBorder(s.back.pixelOfUv(uv)));
    };
    const int ring = expectTexels(
        s.texture(), brush,
        [&](glm::vec2 uv) { return onBack(uv) && !TwoQuads::behindFront(s.back.pixelOfUv(uv)); },
        judge);
    EXPECT_GT(ring, 30000);
    EXPECT_EQ(s.doc.history().undoCount(), 1u);

    // Pop the part of B behind F up: a click there fills it, and still not F.
    const core::DepthLayers& layers = *s.doc.depthLayers();
    const std::size_t centre = 32 * 64 + 32;
    const std::uint32_t hidden = layers.segmentation.region[layers.stack.fragment(centre, 2)];
    core::RegionOrder order = s.doc.regionOrder();
    order.popUp(hidden);
    s.doc.setRegionOrder(order);
    ASSERT_EQ(s.regionAt({32.5f, 32.5f}), hidden);
    ASSERT_TRUE(s.fill({32.5f, 32.5f}, FillMode::Region).ok());
    expectTexels(
        s.texture(), brush, [&](glm::vec2 uv) { return onBack(uv); }, judge);

    // Undo restores byte for byte, redo brings it back.
    const std::vector<std::uint8_t> filled = s.texture().page(0).rgba;
    core::PaintChanges changes;
    ASSERT_TRUE(s.doc.undo(changes));
    ASSERT_TRUE(s.doc.undo(changes));
    EXPECT_TRUE(s.texture().page(0).rgba == original);
    ASSERT_TRUE(s.doc.redo(changes));
    ASSERT_TRUE(s.doc.redo(changes));
    EXPECT_TRUE(s.texture().page(0).rgba == filled);
}

TEST(FloodFillTexture, SurfaceFillsTheWholeConnectedSurfaceAndItsSeamPadding) {
    TwoQuads s(core::PaintTargetKind::Texture);
    const std::vector<std::uint8_t> original = s.texture().page(0).rgba;
    const glm::vec4 brush = s.doc.brush().color;
    // A click on B's visible ring fills all of B, the part behind F too (view-independent).
    ASSERT_TRUE(s.fill({58.5f, 30.5f}, FillMode::Surface).ok());
    const int filled =
        expectTexels(s.texture(), brush, [&](glm::vec2 uv) { return s.back.hasUv(uv); });
    EXPECT_EQ(filled, 256 * 256);
    // Seam padding next to B's chart took the colour too; F's chart kept its colour.
    const core::Image& page = s.texture().page(0);
    const auto bytes = brushBytes(brush);
    const std::size_t padded = 100 * 512 + 257; // right of B's chart (which ends at texel 255)
    EXPECT_EQ(s.texture().coverage(0)[padded], 2);
    EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), texel(page, padded)));

    // F: its own texels only.
    s.doc.brush().color = {0.1f, 0.3f, 0.9f, 1.0f};
    ASSERT_TRUE(s.fill({30.5f, 30.5f}, FillMode::Surface).ok());
    int front = 0;
    for (std::size_t i = 0; i < page.rgba.size() / 4; ++i) {
        if (s.texture().coverage(0)[i] != 1)
            continue;
        if (s.front.hasUv(texelUv(page, i))) {
            ++front;
            EXPECT_TRUE(std::equal(texel(page, i), texel(page, i) + 4,
                                   brushBytes(s.doc.brush().color).begin()));
        } else {
            EXPECT_TRUE(std::equal(bytes.begin(), bytes.end(), texel(page, i)));
        }
    }
    EXPECT_EQ(front, 256 * 256);

    core::PaintChanges changes;
    ASSERT_TRUE(s.doc.undo(changes));
    ASSERT_TRUE(s.doc.undo(changes));
    EXPECT_TRUE(s.texture().page(0).rgba == original);
}

/** A V-shaped grey ramp across B: dark at x = 32, light at both sides. */
glm::vec4 vRamp(glm::vec2 p) {
    const float g = std::min(1.0f, std::fabs(p.x - 32.25f) / 28.0f);
    return {g, g, g, 1.0f};
}

TEST(FloodFillTexture, ColorFillsTheContiguousSimilarTexelsWithinTheTolerance) {
    TwoQuads s(core::PaintTargetKind::Texture, vRamp);
    const core::Image original = s.texture().page(0);
    const glm::vec4 brush = s.doc.brush().color;
    // The seed: B's texel under (8.5, 50.5), light grey on the left arm of the V.
    const glm::vec2 click(8.5f, 50.5f);
    const glm::vec2 seedUv =
        s.back.uv0 + (click - s.back.p0) / (s.back.p1 - s.back.p0) * (s.back.uv1 - s.back.uv0);
    const std::size_t seed = std::size_t(seedUv.y * 512.0f) * 512 + std::size_t(seedUv.x * 512.0f);
    const float seedGrey = float(texel(original, seed)[0]) / 255.0f;
    const float tolerance = 0.2f;
    const auto similar = [&](std::size_t i) {
        return std::fabs(float(texel(original, i)[0]) / 255.0f - seedGrey) <= tolerance + 1e-6f;
    };
    ASSERT_TRUE(s.fill(click, FillMode::Color, tolerance).ok());
    // Expected: the similar texels of B left of the V's dark middle; the right arm has the same
    // greys but lies beyond texels that are too dark.
    const int filled = expectTexels(s.texture(), brush, [&](glm::vec2 uv) {
        if (!s.back.hasUv(uv))
            return false;
        const std::size_t i = std::size_t(uv.y * 512.0f) * 512 + std::size_t(uv.x * 512.0f);
        return similar(i) && s.back.pixelOfUv(uv).x < 32.25f;
    });
    EXPECT_GT(filled, 1000);
    int rightArm = 0;
    for (std::size_t i = 0; i < original.rgba.size() / 4; ++i)
        if (s.texture().coverage(0)[i] == 1 && s.back.hasUv(texelUv(original, i)) &&
            s.back.pixelOfUv(texelUv(original, i)).x > 32.25f && similar(i))
            ++rightArm;
    EXPECT_GT(rightArm, 1000); // there was something to leak into

    // Tolerance 0 takes only the seed's very colour: a column or so of texels.
    core::PaintChanges changes;
    ASSERT_TRUE(s.doc.undo(changes));
    EXPECT_TRUE(s.texture().page(0).rgba == original.rgba);
    ASSERT_TRUE(s.fill(click, FillMode::Color, 0.0f).ok());
    int exact = 0;
    for (std::size_t i = 0; i < original.rgba.size() / 4; ++i) {
        if (s.texture().coverage(0)[i] != 1 || sameTexel(s.texture().page(0), original, i))
            continue;
        ++exact;
        EXPECT_TRUE(std::equal(texel(original, i), texel(original, i) + 4, texel(original, seed)));
        EXPECT_LT(s.back.pixelOfUv(texelUv(original, i)).x, 32.25f);
    }
    EXPECT_GE(exact, 256); // a column of B at least
    ASSERT_TRUE(s.doc.undo(changes));
    EXPECT_TRUE(s.texture().page(0).rgba == original.rgba);
}

/**
 * Three quads in a row on the surface, Q1 | Q2 | Q3, each its own UV chart: Q1 and Q3 touch in
 * UV space (Q3's chart right of Q1's) but not on the surface; Q2's chart is far away, so going
 * from Q1 to Q2 means crossing a UV seam.
 */
struct SeamStrip {
    Quad q1{{4.0f, 4.0f}, {20.0f, 20.0f}, 5.0f, {0.0f, 0.0f}, {0.25f, 0.25f}, 2};
    Quad q2{{20.0f, 4.0f}, {36.0f, 20.0f}, 5.0f, {0.5f, 0.5f}, {0.75f, 0.75f}, 2};
    Quad q3{{36.0f, 4.0f}, {52.0f, 20.0f}, 5.0f, {0.25f, 0.0f}, {0.5f, 0.25f}, 2};
    std::shared_ptr<core::Mesh> mesh = std::make_shared<core::Mesh>();
    std::shared_ptr<core::MeshTopology> topology;

    SeamStrip(const glm::vec4& middle, core::PaintTargetKind kind) {
        addColoredQuad(*mesh, q1);
        addColoredQuad(*mesh, q2, [&](glm::vec2) { return middle; });
        addColoredQuad(*mesh, q3);
        topology = std::make_shared<core::MeshTopology>(core::buildMeshTopology(*mesh));
        core::PaintTargetOptions options;
        options.kind = kind;
        options.resolution = 512;
        auto made = core::makePaintTarget(mesh, topology, options);
        EXPECT_TRUE(made.ok()) << made.error();
        target = std::move(made).value();
    }
    std::unique_ptr<core::PaintTarget> target;
};

TEST(FloodFillTexture, ColorCrossesUvSeamsButNotChartsThatOnlyTouchInUvSpace) {
    const glm::vec3 centre(1.0f / 3.0f);
    {
        SeamStrip strip(glm::vec4(1.0f), core::PaintTargetKind::Texture);
        ASSERT_EQ(strip.topology->componentCount, 1u);
        const auto elements =
            core::similarColorElements(*strip.target, *strip.topology, 0, centre, 0.0f);
        // All three charts: 128 × 128 texels each.
        EXPECT_EQ(elements.size(), 3u * 128u * 128u);
    }
    {
        SeamStrip strip(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), core::PaintTargetKind::Texture);
        const auto& texture = dynamic_cast<const core::TextureTarget&>(*strip.target);
        const auto elements =
            core::similarColorElements(*strip.target, *strip.topology, 0, centre, 0.0f);
        ASSERT_EQ(elements.size(), 128u * 128u);
        for (const core::PaintElement& e : elements)
            EXPECT_TRUE(strip.q1.hasUv(texelUv(texture.page(0), e.index)));
        // paintElements() paints exactly them and undoes exactly.
        const std::vector<std::uint8_t> before = texture.page(0).rgba;
        core::Brush brush;
        brush.color = {0.0f, 1.0f, 0.0f, 1.0f};
        strip.target->beginStroke(brush);
        const core::PaintChanges& changes = strip.target->paintElements(elements);
        EXPECT_FALSE(changes.texels.empty());
        core::TileUndoRecord record = strip.target->endStroke();
        int changed = 0;
        for (std::size_t i = 0; i < before.size() / 4; ++i)
            if (!std::equal(&before[i * 4], &before[i * 4] + 4, texel(texture.page(0), i)))
                ++changed;
        // The chart's texels and its seam padding (Q3's chart borders it on the right).
        EXPECT_GE(changed, 128 * 128);
        EXPECT_LT(changed, 128 * 128 + 4 * 140 * 4);
        ASSERT_TRUE(record.undo(*strip.target));
        EXPECT_TRUE(texture.page(0).rgba == before);
    }
}

TEST(FloodFillVertexColors, EachModeFillsItsVerticesAndUndoRestores) {
    TwoQuads s(core::PaintTargetKind::VertexColors, vRamp);
    const std::vector<glm::vec4> original = s.vertexColors().colors();
    const core::Mesh& mesh = s.doc.mesh();
    const glm::vec4 brush = s.doc.brush().color;
    const std::size_t backVertices = 15 * 15;
    const auto pixelOf = [&](std::size_t v) {
        return glm::vec2(mesh.positions[v].x, mesh.positions[v].y);
    };
    const auto expectVertices = [&](const std::function<bool(std::size_t)>& expected) {
        const std::vector<glm::vec4>& colors = s.vertexColors().colors();
        int filled = 0;
        for (std::size_t v = 0; v < colors.size(); ++v) {
            const bool want = expected(v);
            if (want) {
                ++filled;
                EXPECT_EQ(colors[v], brush) << "vertex " << v;
            } else {
                EXPECT_EQ(colors[v], original[v]) << "vertex " << v;
            }
        }
        return filled;
    };
    core::PaintChanges changes;

    // Region: B's vertices whose pixel shows B's layer-1 region, and its rim (B's last row and
    // column project just beyond its last pixel centres).
    ASSERT_TRUE(s.fill({10.5f, 10.5f}, FillMode::Region).ok());
    EXPECT_FALSE(s.lastChanges.vertices.empty());
    const int region = expectVertices(
        [&](std::size_t v) { return v < backVertices && !TwoQuads::behindFront(pixelOf(v)); });
    EXPECT_EQ(region, 15 * 15 - 5 * 5);
    ASSERT_TRUE(s.doc.undo(changes));
    EXPECT_EQ(s.vertexColors().colors(), original);

    // Surface: every vertex of F, none of B.
    ASSERT_TRUE(s.fill({30.5f, 30.5f}, FillMode::Surface).ok());
    EXPECT_EQ(expectVertices([&](std::size_t v) { return v >= backVertices; }), 6 * 6);
    ASSERT_TRUE(s.doc.undo(changes));
    EXPECT_EQ(s.vertexColors().colors(), original);

    // Colour: from B's left edge, the left arm of the V within the tolerance.
    const float tolerance = 0.3f;
    ASSERT_TRUE(s.fill({5.0f, 30.5f}, FillMode::Color, tolerance).ok());
    // The seed is the clicked triangle's corner nearest the click: on B's left column.
    const float seedGrey = 1.0f; // vRamp at x = 4.25
    const auto encode = [](float c) { return core::encodeSrgb(c); };
    const int colour = expectVertices([&](std::size_t v) {
        return v < backVertices && pixelOf(v).x < 32.25f &&
               std::fabs(encode(original[v].r) - encode(seedGrey)) <= tolerance + 1e-6f;
    });
    EXPECT_GT(colour, 15);
    ASSERT_TRUE(s.doc.undo(changes));
    EXPECT_EQ(s.vertexColors().colors(), original);
    EXPECT_FALSE(s.doc.history().canUndo());
}

TEST(FloodFillVertexColors, ColorCrossesWeldedSeams) {
    const glm::vec3 centre(1.0f / 3.0f);
    SeamStrip white(glm::vec4(1.0f), core::PaintTargetKind::VertexColors);
    EXPECT_EQ(core::similarColorElements(*white.target, *white.topology, 0, centre, 0.0f).size(),
              3u * 9u);
    SeamStrip dark(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f), core::PaintTargetKind::VertexColors);
    // Q1's 9 vertices; Q2's own vertices on the shared edge are dark.
    EXPECT_EQ(core::similarColorElements(*dark.target, *dark.topology, 0, centre, 0.0f).size(), 9u);
}

TEST(FloodFill, OpacityBlendsLikeAStrokeOfThatOpacity) {
    TwoQuads s(core::PaintTargetKind::VertexColors);
    s.doc.brush().opacity = 0.5f;
    ASSERT_TRUE(s.fill({30.5f, 30.5f}, FillMode::Surface).ok());
    // Half way from white on the sRGB-encoded values (as texture targets and paint layers mix).
    const glm::vec4 got = s.vertexColors().colors().back();
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(
            got[k],
            core::srgbToLinear(1.0f + (core::encodeSrgb(s.doc.brush().color[k]) - 1.0f) * 0.5f),
            1e-5f);
    EXPECT_NEAR(got[3], 1.0f, 1e-6f);
}

} // namespace flood_fill_test
