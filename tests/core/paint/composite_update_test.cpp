// SPDX-License-Identifier: GPL-3.0-or-later
// A stroke updates the composite of paint layers through a fast path (the layers below the
// stroke's kept per tile, only the dab's rectangle and channels blended): after every dab of
// strokes over a stack of several blend modes, opacities, masks, hidden and locked layers, with
// layer changes, undo and redo in between, every byte of the composite equals a full recompute.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/paint/paint_layers/paint_layers.h"
#include "core/paint/targets/paint_target.h"
#include "tests/core/test_scenes.h"

namespace composite_update_test {

using core::BlendMode;
using core::PaintLayerKind;
using core::PaintLayerSettings;
using core::layer_bytes::toByte;

constexpr int kWidth = 64, kHeight = 64;

core::View pixelView() {
    return core_test::pixelView(kWidth, kHeight);
}

/** A camera-facing quad over most of the view, its uv square on a new page (many tiles). */
core::Mesh quad() {
    core::Mesh mesh;
    mesh.materials = {{"grey", glm::vec4(0.5f, 0.6f, 0.7f, 1.0f), -1}};
    core_test::addQuad(mesh, {glm::vec2(4, 4), glm::vec2(60, 60), 4.0f});
    return mesh;
}

class CompositeUpdateTest : public ::testing::Test {
protected:
    void SetUp() override {
        m_doc.setMesh(quad(), "quad");
        core::PaintTargetOptions options;
        options.resolution = 256; // 4×4 tiles: strokes cross tile edges
        ASSERT_TRUE(m_doc.setPaintTarget(options).ok());
        core::CpuDepthCapturer capturer;
        capturer.setMesh(m_doc.mesh());
        ASSERT_TRUE(m_doc.buildDepthLayers(capturer, pixelView()).ok());
        core::Brush& brush = m_doc.brush();
        brush.radius = 7.0f;
        brush.hardness = 0.3f; // soft: partial coverage at the edges
        brush.flow = 0.6f;
        brush.spacing = 0.3f;
        brush.color = {0.9f, 0.3f, 0.1f, 1.0f};
    }

    core::TextureTarget& target() {
        return *dynamic_cast<core::TextureTarget*>(m_doc.paintTarget());
    }

    /**
     * The composite is what every texel worked out alone gives (compositeTexel()), byte for
     * byte, and so is a full recompute of every tile.
     */
    void expectFullRecompute(const std::string& what) {
        core::PaintLayerStack& stack = target().paintLayerStack();
        expectReferenceBytes(stack, what);
        stack.updateAll();
        expectReferenceBytes(stack, what + ", recomputed");
        ++m_checks;
    }

    static void expectReferenceBytes(const core::PaintLayerStack& stack, const std::string& what) {
        const std::vector<std::uint8_t>& color = stack.compositeBaseColor(0);
        const std::vector<std::uint8_t>& mr = stack.compositeMetallicRoughness(0);
        const int width = stack.pages()[0].width, height = stack.pages()[0].height;
        std::size_t colorDiffs = 0, mrDiffs = 0;
        std::array<float, 5> values{};
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                stack.compositeTexel(0, x, y, stack.size(), values);
                const std::size_t i = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4;
                for (int k = 0; k < 3; ++k)
                    colorDiffs += color[i + std::size_t(k)] != toByte(values[std::size_t(k)]);
                if (!mr.empty())
                    mrDiffs += (mr[i + 1] != toByte(values[3])) + (mr[i + 2] != toByte(values[4]));
            }
        EXPECT_EQ(colorDiffs, 0u) << what << ": base colour bytes differ";
        EXPECT_EQ(mrDiffs, 0u) << what << ": metallic-roughness bytes differ";
    }

    /** A stroke through points, checked against a full recompute after every move. */
    void stroke(const std::string& what, std::vector<glm::vec2> points) {
        const std::vector<std::uint8_t> before = target().page(0).rgba;
        const std::vector<std::uint8_t> beforeMr = target().metallicRoughnessPage(0).rgba;
        core::PaintChanges changes;
        ASSERT_TRUE(m_doc.beginStroke({points[0], 1.0f}, changes).ok()) << what;
        expectFullRecompute(what + " (start)");
        for (std::size_t i = 1; i < points.size(); ++i) {
            m_doc.moveStroke({points[i], 1.0f}, changes);
            expectFullRecompute(what + " (move " + std::to_string(i) + ")");
        }
        m_doc.endStroke();
        expectFullRecompute(what + " (end)");
        m_changed +=
            before != target().page(0).rgba || beforeMr != target().metallicRoughnessPage(0).rgba
                ? 1
                : 0;
    }

    std::uint64_t add(const std::string& name, BlendMode mode, float opacity,
                      PaintLayerKind kind = PaintLayerKind::Paint) {
        PaintLayerSettings s;
        s.name = name;
        s.blend = mode;
        s.opacity = opacity;
        s.kind = kind;
        if (kind == PaintLayerKind::Fill) {
            s.fill.baseColor = glm::vec3(0.2f, 0.7f, 0.4f);
            s.fill.metallic = 0.8f;
        }
        core::PaintChanges changes;
        auto id = m_doc.addPaintLayer(s, changes);
        EXPECT_TRUE(id.ok());
        return id.ok() ? *id : 0;
    }

    void select(std::uint64_t id, bool mask = false) {
        ASSERT_TRUE(m_doc.selectPaint({id, mask}).ok());
    }

    void change(std::uint64_t id, void (*edit)(PaintLayerSettings&)) {
        const std::size_t index = *target().paintLayerStack().indexOf(id);
        PaintLayerSettings s = target().paintLayerStack().layer(index).settings;
        edit(s);
        core::PaintChanges changes;
        ASSERT_TRUE(m_doc.setPaintLayerSettings(id, s, changes).ok());
    }

    void undo(const std::string& what) {
        core::PaintChanges changes;
        ASSERT_TRUE(m_doc.undo(changes)) << what;
        expectFullRecompute(what + " (undo)");
    }
    void redo(const std::string& what) {
        core::PaintChanges changes;
        ASSERT_TRUE(m_doc.redo(changes)) << what;
        expectFullRecompute(what + " (redo)");
    }

    core::Document m_doc;
    int m_checks = 0;
    int m_changed = 0;
};

const std::vector<glm::vec2> kAcross = {{8, 20}, {20, 24}, {34, 30}, {50, 36}, {57, 44}};
const std::vector<glm::vec2> kDown = {{30, 6}, {28, 20}, {33, 36}, {26, 50}, {31, 58}};
const std::vector<glm::vec2> kDiagonal = {{10, 52}, {24, 40}, {38, 26}, {52, 12}};

TEST_F(CompositeUpdateTest, StrokesThroughTheFastPathGiveTheFullRecomputesBytes) {
    core::Brush& brush = m_doc.brush();
    stroke("base, no layers", kAcross);

    const std::uint64_t a = add("A", BlendMode::Normal, 0.7f);
    brush.paintRoughness = brush.paintMetallic = true;
    brush.roughness = 0.2f;
    brush.metallic = 0.9f;
    stroke("A, all channels", kAcross);
    const std::uint64_t fill = add("fill", BlendMode::Multiply, 0.5f, PaintLayerKind::Fill);
    const std::uint64_t b = add("B", BlendMode::Screen, 0.8f);
    brush.color = {0.1f, 0.5f, 0.9f, 1.0f};
    stroke("B over A and a fill layer", kDown);
    change(b, [](PaintLayerSettings& s) { s.blend = BlendMode::SoftLight; });
    stroke("B soft light", kDiagonal);

    // A mask on the fill layer, painted dark in a band: every channel of the composite moves.
    core::PaintChanges changes;
    ASSERT_TRUE(m_doc.addPaintLayerMask(fill, changes).ok());
    brush.color = {0.05f, 0.05f, 0.05f, 1.0f};
    select(fill, true);
    stroke("fill's mask", kDown);

    const std::uint64_t c = add("C", BlendMode::Overlay, 1.0f);
    brush.color = {0.8f, 0.8f, 0.2f, 1.0f};
    brush.paintMetallic = false;
    stroke("C overlay, base colour and roughness", kDiagonal);
    change(c, [](PaintLayerSettings& s) { s.visible = false; });
    const std::uint64_t d = add("D", BlendMode::Difference, 0.6f);
    stroke("D difference over a hidden layer", kAcross);
    change(d, [](PaintLayerSettings& s) { s.lockTransparency = true; });
    brush.color = {0.2f, 0.9f, 0.6f, 1.0f};
    stroke("D locked", kDown);

    // Below layers that are above another stroke's layer: A with B, C, D over it.
    select(a);
    brush.paintMetallic = true;
    brush.metallic = 0.3f;
    stroke("A under five layers", kDiagonal);
    undo("A under five layers");
    stroke("A again after undo", kDown);
    undo("A again");
    redo("A again");

    // On a hidden layer the composite does not change; painting it is still checked.
    select(c);
    stroke("hidden C", kAcross);
    change(c, [](PaintLayerSettings& s) {
        s.visible = true;
        s.blend = BlendMode::Subtract;
    });
    expectFullRecompute("C shown");
    select(d);
    brush.eraser = true;
    stroke("D erased", kAcross);
    brush.eraser = false;

    // Layer changes below the stroke's layer between strokes: the kept lower layers go.
    for (const auto& [mode, name] :
         std::vector<std::pair<BlendMode, std::string>>{{BlendMode::Add, "add"},
                                                        {BlendMode::Darken, "darken"},
                                                        {BlendMode::Lighten, "lighten"}}) {
        const BlendMode m = mode;
        const std::size_t index = *target().paintLayerStack().indexOf(a);
        PaintLayerSettings s = target().paintLayerStack().layer(index).settings;
        s.blend = m;
        s.opacity = 0.45f;
        ASSERT_TRUE(m_doc.setPaintLayerSettings(a, s, changes).ok());
        select(b);
        stroke("B over A " + name, kDiagonal);
    }
    core::PaintChanges moved;
    ASSERT_TRUE(m_doc.movePaintLayer(d, 0, moved).ok());
    select(b);
    stroke("B after D moved to the bottom", kAcross);
    undo("B after the move");
    undo("the move");
    stroke("B with D back on top", kDown);

    // The base under every layer, and a fill (flood fill goes through the same update).
    select(0);
    brush.color = {0.3f, 0.1f, 0.6f, 1.0f};
    stroke("base under the layers", kDown);
    select(b);
    ASSERT_TRUE(m_doc.fill({32, 32}, core::FillMode::Surface, 0.1f, changes).ok());
    expectFullRecompute("fill on B");
    undo("fill on B");

    EXPECT_GT(m_checks, 60);
    EXPECT_GE(m_changed, 15) << "the strokes changed the composite";
}

// Paint layers that all blend in the Normal mode over an untouched base are composed in one pass
// per texel: with a masked fill layer, a hidden layer, partial opacity, locked transparency and the
// material channels one at a time, the bytes are still those of the full recompute.
TEST_F(CompositeUpdateTest, NormalLayersOverTheBaseInOnePassGiveTheFullRecomputesBytes) {
    core::Brush& brush = m_doc.brush();
    stroke("base, no layers", kDown);
    const std::uint64_t a = add("A", BlendMode::Normal, 0.6f);
    const std::uint64_t fill = add("fill", BlendMode::Normal, 0.5f, PaintLayerKind::Fill);
    const std::uint64_t hidden = add("hidden", BlendMode::Normal, 1.0f);
    const std::uint64_t b = add("B", BlendMode::Normal, 0.85f);
    brush.paintRoughness = true;
    brush.roughness = 0.1f;
    select(hidden);
    stroke("hidden, before it is hidden", kDiagonal);
    change(hidden, [](PaintLayerSettings& s) { s.visible = false; });
    expectFullRecompute("hidden");
    core::PaintChanges changes;
    ASSERT_TRUE(m_doc.addPaintLayerMask(fill, changes).ok());
    select(fill, true);
    brush.color = {0.1f, 0.1f, 0.1f, 1.0f};
    stroke("fill's mask", kAcross);
    select(a);
    brush.color = {0.9f, 0.2f, 0.3f, 1.0f};
    stroke("A under a masked fill, a hidden layer and B", kDown);
    select(b);
    brush.paintBaseColor = false;
    stroke("B, roughness only", kAcross);
    brush.paintBaseColor = true;
    brush.paintRoughness = false;
    brush.paintMetallic = true;
    brush.metallic = 0.7f;
    stroke("B, base colour and metallic", kDiagonal);
    change(b, [](PaintLayerSettings& s) { s.lockTransparency = true; });
    brush.color = {0.2f, 0.8f, 0.9f, 1.0f};
    stroke("B locked", kDown);
    undo("B locked");
    redo("B locked");
    EXPECT_GE(m_changed, 6) << "the strokes changed the composite";
}

// More fill layers than one pass per texel takes, in every blend mode, are worked out once per
// base byte and tile: the bytes are still those of every texel worked out alone, with a stroke
// below them, between them and on a mask of one of them.
TEST_F(CompositeUpdateTest, ManyFillLayersGiveTheBytesOfEveryTexelAlone) {
    const BlendMode modes[] = {BlendMode::Normal,    BlendMode::Multiply,  BlendMode::Screen,
                               BlendMode::Overlay,   BlendMode::SoftLight, BlendMode::Add,
                               BlendMode::Subtract,  BlendMode::Darken,    BlendMode::Lighten,
                               BlendMode::Difference};
    const std::uint64_t below = add("below", BlendMode::Normal, 0.8f);
    std::uint64_t masked = 0;
    for (int i = 0; i < 30; ++i) {
        const std::uint64_t id = add("fill " + std::to_string(i), modes[i % 10],
                                     0.3f + 0.02f * float(i), PaintLayerKind::Fill);
        masked = i == 12 ? id : masked;
    }
    expectFullRecompute("30 fill layers");
    select(below);
    stroke("under 30 fill layers", kAcross);
    core::PaintChanges changes;
    ASSERT_TRUE(m_doc.addPaintLayerMask(masked, changes).ok());
    select(masked, true);
    m_doc.brush().color = {0.2f, 0.2f, 0.2f, 1.0f};
    stroke("the mask of a fill layer between the others", kDown);
    select(add("top", BlendMode::Multiply, 0.7f));
    stroke("over 30 fill layers", kDiagonal);
    EXPECT_GE(m_changed, 2) << "the strokes changed the composite";
}

// One paint layer at full opacity over the base, the composite's case in lanes: texels the layer
// covers fully (a hard brush at full flow), partly and not at all, its channels painted three,
// one and two at a time (the others keep their bytes).
TEST_F(CompositeUpdateTest, OneOpaqueLayerOverTheBaseGivesTheFullRecomputesBytes) {
    core::Brush& brush = m_doc.brush();
    select(add("top", BlendMode::Normal, 1.0f));
    brush.paintRoughness = brush.paintMetallic = true;
    brush.roughness = 0.2f;
    brush.metallic = 0.9f;
    brush.hardness = 1.0f;
    brush.flow = 1.0f;
    stroke("all channels, hard", kAcross);
    brush.hardness = 0.3f;
    brush.flow = 0.6f;
    brush.paintBaseColor = brush.paintMetallic = false;
    brush.roughness = 0.7f;
    stroke("roughness only", kDown);
    brush.paintRoughness = false;
    brush.paintMetallic = true;
    brush.metallic = 0.1f;
    stroke("metallic only", kDiagonal);
    brush.paintBaseColor = true;
    brush.paintRoughness = true;
    brush.paintMetallic = false;
    brush.color = {0.1f, 0.5f, 0.9f, 1.0f};
    stroke("base colour and roughness", kDiagonal);
    undo("base colour and roughness");
    EXPECT_GE(m_changed, 4) << "the strokes changed the composite";
}

} // namespace composite_update_test
