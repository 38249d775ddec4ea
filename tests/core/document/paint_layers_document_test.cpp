// SPDX-License-Identifier: GPL-3.0-or-later
// Paint layers wired into the controller: strokes and fills go into the selected paint layer (or
// its mask, or the base), the shown texture is the composite, every layer operation is one undo
// step undone and redone to the byte, and memory grows with what is painted.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include "core/base/color.h"
#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/paint/paint_layers/paint_layers.h"
#include "core/paint/targets/paint_target.h"
#include "tests/core/paint_layers_snapshot.h"
#include "tests/core/test_scenes.h"

namespace paint_layers_document_test {

constexpr int kWidth = 64, kHeight = 64;

using core_test::pixelView;

/** One camera-facing quad over the middle of the view, its uv square on a new 512² page. */
core::Mesh quad() {
    core::Mesh mesh;
    mesh.materials = {{"grey", glm::vec4(0.5f, 0.5f, 0.5f, 1.0f), -1}};
    core_test::addQuad(mesh, {glm::vec2(4, 4), glm::vec2(60, 60), 4.0f});
    return mesh;
}

using core_test::paintLayersSnapshot;
using Snapshot = core_test::PaintLayersSnapshot;

class PaintLayersDocumentTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_NO_FATAL_FAILURE(openQuad(512));
        m_doc.history().clear();
        core::Brush& brush = m_doc.brush();
        brush.radius = 6.0f;
        brush.hardness = 1.0f;
        brush.color = {0.9f, 0.2f, 0.1f, 1.0f};
    }

    /** The quad in the document, a texture target of resolution², its depth layers built. */
    void openQuad(int resolution) {
        m_doc.setMesh(quad(), "quad");
        core::PaintTargetOptions options;
        options.resolution = resolution;
        ASSERT_TRUE(m_doc.setPaintTarget(options).ok());
        core::CpuDepthCapturer capturer;
        capturer.setMesh(m_doc.mesh());
        ASSERT_TRUE(m_doc.buildDepthLayers(capturer, pixelView(kWidth, kHeight)).ok());
    }

    core::TextureTarget& target() {
        return *dynamic_cast<core::TextureTarget*>(m_doc.paintTarget());
    }

    void stroke(glm::vec2 from, glm::vec2 to) {
        core::PaintChanges changes;
        ASSERT_TRUE(m_doc.beginStroke({from, 1.0f}, changes).ok());
        m_doc.moveStroke({to, 1.0f}, changes);
        m_doc.endStroke();
    }

    /** Undoes and redoes the newest step, checking both states byte for byte. */
    void expectUndoRedo(const Snapshot& before, const char* what) {
        const Snapshot after = paintLayersSnapshot(target());
        EXPECT_NE(before, after) << what << " changed nothing";
        core::PaintChanges changes;
        ASSERT_TRUE(m_doc.undo(changes)) << what;
        EXPECT_TRUE(paintLayersSnapshot(target()) == before) << what << ": undo";
        ASSERT_TRUE(m_doc.redo(changes)) << what;
        EXPECT_TRUE(paintLayersSnapshot(target()) == after) << what << ": redo";
    }

    std::uint64_t addLayer(const std::string& name,
                           core::PaintLayerKind kind = core::PaintLayerKind::Paint) {
        core::PaintLayerSettings settings;
        settings.name = name;
        settings.kind = kind;
        if (kind == core::PaintLayerKind::Fill)
            settings.fill.roughness = 0.25f;
        core::PaintChanges changes;
        auto id = m_doc.addPaintLayer(settings, changes);
        EXPECT_TRUE(id.ok());
        return id.ok() ? *id : 0;
    }

    core::Document m_doc;
};

TEST_F(PaintLayersDocumentTest, PaintingTheBaseIsPaintingAsBefore) {
    // With no paint layer the base is selected and takes the paint, as the target always did:
    // the shown page is the base byte for byte, the eraser brings the original back.
    EXPECT_EQ(target().selection().layer, 0u);
    const std::vector<std::uint8_t> original = target().page(0).rgba;
    stroke({20, 30}, {44, 30});
    EXPECT_NE(target().page(0).rgba, original);
    EXPECT_EQ(target().page(0).rgba, target().basePixels(0));
    m_doc.brush().eraser = true;
    m_doc.brush().radius = 20.0f;
    stroke({20, 30}, {44, 30});
    EXPECT_EQ(target().page(0).rgba, original);
}

TEST_F(PaintLayersDocumentTest, AStrokeOnALayerLeavesTheBaseAndShowsInTheComposite) {
    const std::vector<std::uint8_t> base = target().basePixels(0);
    // The base painted with a hard full-opacity brush is the reference: a normal layer at full
    // opacity shows the same bytes where the brush covered fully.
    stroke({20, 30}, {44, 30});
    const std::vector<std::uint8_t> onBase = target().page(0).rgba;
    core::PaintChanges changes;
    ASSERT_TRUE(m_doc.undo(changes));
    ASSERT_EQ(target().page(0).rgba, base);

    addLayer("Paint 1");
    stroke({20, 30}, {44, 30});
    EXPECT_EQ(target().basePixels(0), base) << "the base is not painted";
    const core::TiledPlane* color = target().paintLayerStack().layer(0).channels[0].get();
    ASSERT_NE(color, nullptr);
    std::size_t full = 0, same = 0;
    for (std::size_t i = 0; i < base.size() / 4; ++i) {
        const int x = int(i % 512), y = int(i / 512);
        if (color->texel(0, x, y)[3] != 255)
            continue;
        ++full;
        same += std::equal(&onBase[i * 4], &onBase[i * 4] + 4, &target().page(0).rgba[i * 4]);
    }
    EXPECT_GT(full, 1000u);
    EXPECT_EQ(same, full);
    // The stroke is one step: undone, the composite is the base again.
    const Snapshot painted = paintLayersSnapshot(target());
    ASSERT_TRUE(m_doc.undo(changes));
    EXPECT_EQ(target().page(0).rgba, base);
    EXPECT_FALSE(changes.texels.empty());
    ASSERT_TRUE(m_doc.redo(changes));
    EXPECT_TRUE(paintLayersSnapshot(target()) == painted);

    // The eraser takes the layer's paint away (to transparent): the base shows again.
    m_doc.brush().eraser = true;
    m_doc.brush().radius = 30.0f;
    stroke({20, 30}, {44, 30});
    EXPECT_EQ(target().page(0).rgba, base);
}

TEST_F(PaintLayersDocumentTest, ASoftStrokeGivesTheSameColourOnTheBaseAsThroughANormalLayer) {
    // #3399e6 at half opacity with a soft edge: every coverage from 0 to 0.5. Moved from the
    // base onto a Normal paint layer, the stroke keeps its colour (one mixing arithmetic; the
    // layer keeps its coverage in a byte, hence one unit).
    core::Brush& brush = m_doc.brush();
    brush.color = {core::srgbToLinear(std::uint8_t(0x33)), core::srgbToLinear(std::uint8_t(0x99)),
                   core::srgbToLinear(std::uint8_t(0xe6)), 1.0f};
    brush.opacity = 0.5f;
    brush.hardness = 0.2f;
    brush.radius = 10.0f;
    const std::vector<std::uint8_t> base = target().page(0).rgba;
    stroke({20, 30}, {44, 30});
    const std::vector<std::uint8_t> onBase = target().page(0).rgba;
    core::PaintChanges changes;
    ASSERT_TRUE(m_doc.undo(changes));
    addLayer("Paint 1");
    stroke({20, 30}, {44, 30});
    const std::vector<std::uint8_t>& throughLayer = target().page(0).rgba;
    std::size_t painted = 0, worst = 0;
    for (std::size_t i = 0; i < base.size(); ++i) {
        if (i % 4 == 3)
            continue;
        painted += onBase[i] != base[i];
        worst = std::max<std::size_t>(worst,
                                      std::size_t(std::abs(int(onBase[i]) - int(throughLayer[i]))));
    }
    EXPECT_GT(painted, 1000u);
    EXPECT_LE(worst, 1u);
}

TEST_F(PaintLayersDocumentTest, TheBrushPaintsTheChannelsItHasOn) {
    addLayer("Rough");
    core::Brush& brush = m_doc.brush();
    brush.paintBaseColor = false;
    brush.paintRoughness = true;
    brush.roughness = 0.2f;
    brush.paintMetallic = true;
    brush.metallic = 1.0f;
    const std::vector<std::uint8_t> color = target().page(0).rgba;
    stroke({32, 32}, {33, 32});
    EXPECT_EQ(target().page(0).rgba, color) << "base colour is off";
    const core::Image& mr = target().metallicRoughnessPage(0);
    const std::uint8_t* centre = &mr.rgba[(256u * 512u + 256u) * 4];
    EXPECT_EQ(centre[1], 51);  // roughness 0.2
    EXPECT_EQ(centre[2], 255); // metallic 1
    EXPECT_EQ(mr.rgba[2], 0u) << "not metallic where nothing was painted";
    EXPECT_EQ(mr.rgba[1], 255u) << "rough where nothing was painted";
}

TEST_F(PaintLayersDocumentTest, AMaskHidesWhereItIsPaintedBlack) {
    const std::vector<std::uint8_t> base = target().basePixels(0);
    const std::uint64_t id = addLayer("Masked");
    m_doc.brush().radius = 25.0f;
    stroke({32, 32}, {33, 32});
    const std::vector<std::uint8_t> painted = target().page(0).rgba;
    core::PaintChanges changes;
    ASSERT_TRUE(m_doc.addPaintLayerMask(id, changes).ok());
    EXPECT_EQ(target().selection(), (core::PaintSelection{id, true}));
    EXPECT_EQ(target().page(0).rgba, painted) << "a new mask shows everything";
    m_doc.brush().color = {0.0f, 0.0f, 0.0f, 1.0f};
    m_doc.brush().radius = 40.0f;
    stroke({32, 32}, {33, 32});
    EXPECT_EQ(target().page(0).rgba, base) << "black hides the layer";
    EXPECT_TRUE(target().paintLayerStack().layer(0).channels[0]->anyTile(0)) << "the paint stays";
}

TEST_F(PaintLayersDocumentTest, EveryOperationUndoesAndRedoesToTheByte) {
    core::PaintChanges changes;
    Snapshot before = paintLayersSnapshot(target());
    const std::uint64_t a = addLayer("A");
    expectUndoRedo(before, "add");
    stroke({20, 20}, {40, 40});

    before = paintLayersSnapshot(target());
    const std::uint64_t fill = addLayer("Fill", core::PaintLayerKind::Fill);
    expectUndoRedo(before, "add fill");

    before = paintLayersSnapshot(target());
    auto copy = m_doc.duplicatePaintLayer(a, changes);
    ASSERT_TRUE(copy.ok());
    expectUndoRedo(before, "duplicate");

    before = paintLayersSnapshot(target());
    m_doc.brush().color = {0.1f, 0.8f, 0.2f, 1.0f};
    stroke({40, 20}, {20, 40});
    expectUndoRedo(before, "stroke on the copy");

    before = paintLayersSnapshot(target());
    core::PaintLayerSettings s = target().paintLayerStack().layer(1).settings;
    s.name = "Renamed";
    ASSERT_TRUE(m_doc.setPaintLayerSettings(*copy, s, changes).ok());
    expectUndoRedo(before, "rename");

    for (const auto& change : std::vector<std::function<void(core::PaintLayerSettings&)>>{
             [](core::PaintLayerSettings& x) { x.opacity = 0.4f; },
             [](core::PaintLayerSettings& x) { x.blend = core::BlendMode::Multiply; },
             [](core::PaintLayerSettings& x) { x.visible = false; },
             [](core::PaintLayerSettings& x) { x.lockTransparency = true; }}) {
        before = paintLayersSnapshot(target());
        s = target().paintLayerStack().layer(*target().paintLayerStack().indexOf(*copy)).settings;
        change(s);
        ASSERT_TRUE(m_doc.setPaintLayerSettings(*copy, s, changes).ok());
        expectUndoRedo(before, "set");
    }

    before = paintLayersSnapshot(target());
    ASSERT_TRUE(m_doc.movePaintLayer(fill, 0, changes).ok());
    expectUndoRedo(before, "move");

    before = paintLayersSnapshot(target());
    ASSERT_TRUE(m_doc.addPaintLayerMask(a, changes).ok());
    expectUndoRedo(before, "add mask");
    before = paintLayersSnapshot(target());
    m_doc.brush().color = {0.0f, 0.0f, 0.0f, 1.0f};
    stroke({25, 25}, {30, 30});
    expectUndoRedo(before, "stroke on the mask");

    // Selecting is no undo step; the undo of the next operation brings the selection back.
    const std::size_t steps = m_doc.history().undoCount();
    ASSERT_TRUE(m_doc.selectPaint({fill, false}).ok());
    EXPECT_EQ(target().selection(), (core::PaintSelection{fill, false}));
    ASSERT_TRUE(m_doc.selectPaint({a, true}).ok());
    EXPECT_EQ(target().selection(), (core::PaintSelection{a, true}));
    EXPECT_EQ(m_doc.history().undoCount(), steps) << "selecting made an undo step";

    before = paintLayersSnapshot(target());
    ASSERT_TRUE(m_doc.mergePaintLayerDown(a, changes).ok());
    EXPECT_NE(target().selection(), (core::PaintSelection{a, true}));
    expectUndoRedo(before, "merge down");
    EXPECT_EQ(m_doc.history().undoCount(), steps + 1);

    before = paintLayersSnapshot(target());
    ASSERT_TRUE(m_doc.deletePaintLayer(*copy, changes).ok());
    expectUndoRedo(before, "delete");

    before = paintLayersSnapshot(target());
    ASSERT_TRUE(m_doc.flattenPaintLayers("Flat", changes).ok());
    expectUndoRedo(before, "flatten");
    EXPECT_EQ(target().paintLayerStack().size(), 1u);

    // All the way back: the document as it was before the first layer.
    while (m_doc.undo(changes)) {
    }
    EXPECT_EQ(target().paintLayerStack().size(), 0u);
    EXPECT_EQ(target().page(0).rgba, target().originalPage(0).rgba);
}

TEST_F(PaintLayersDocumentTest, OperationsThatDoNotApplyAreErrorsAndChangeNothing) {
    core::PaintChanges changes;
    const std::uint64_t a = addLayer("A");
    const std::size_t steps = m_doc.history().undoCount();
    EXPECT_FALSE(m_doc.mergePaintLayerDown(a, changes).ok()) << "nothing below";
    EXPECT_FALSE(m_doc.deletePaintLayer(999, changes).ok());
    EXPECT_FALSE(m_doc.selectPaint({a, true}).ok()) << "no mask yet";
    ASSERT_TRUE(m_doc.addPaintLayerMask(a, changes).ok());
    EXPECT_FALSE(m_doc.addPaintLayerMask(a, changes).ok()) << "already has one";
    EXPECT_EQ(m_doc.history().undoCount(), steps + 1);
}

TEST_F(PaintLayersDocumentTest, EightLayersWithAFewStrokesCostLessThanOneFullLayer) {
    // Eight 4096² layers with a few strokes each against one full 4096² RGBA8 layer.
    ASSERT_NO_FATAL_FAILURE(openQuad(4096));
    m_doc.brush().radius = 1.5f;
    m_doc.brush().paintRoughness = true;
    for (int l = 0; l < 8; ++l) {
        addLayer("Layer " + std::to_string(l + 1));
        for (int s = 0; s < 3; ++s)
            stroke({float(10 + 5 * l), float(10 + 12 * s)},
                   {float(20 + 5 * l), float(14 + 12 * s)});
    }
    const std::size_t full = std::size_t(4096) * 4096 * 4;
    const std::size_t layers = target().paintLayerStack().layerBytes();
    EXPECT_GT(layers, 0u);
    EXPECT_LT(double(layers) / double(full), 1.5);
    std::printf("8 layers at 4096² with 3 strokes each: %zu bytes, %.3f of one full layer\n",
                layers, double(layers) / double(full));
}

} // namespace paint_layers_document_test
