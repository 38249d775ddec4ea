// SPDX-License-Identifier: GPL-3.0-or-later
// Scripts in the core: the runner replays operations through the Document, every change is one
// step of the one history, and a recorded session replays to the same picture.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "core/document/document.h"
#include "core/document/script.h"
#include "tests/core/script_host.h"
#include "tests/core/test_scenes.h"

namespace script_test {

using core_test::pixelView;
using nlohmann::json;

constexpr int kWidth = 96, kHeight = 64;

struct Session : core_test::QuadsScriptSession {
    Session() : QuadsScriptSession(256) {}
    core::Status run(const json& operations) {
        for (const json& op : operations)
            if (core::Status s = runner.run(op); !s)
                return s;
        return {};
    }
    std::vector<std::uint8_t> pixels() const { return doc.paintedMesh().textures.at(0).rgba; }
};

const json kBrush = {{"op", "set-brush"}, {"color", "#20c040"}, {"radius", 5}, {"hardness", 1}};
// From the back quad's uncovered part into the part the front quad covers.
const json kBehind = {{"op", "stroke"}, {"points", {{14, 30}, {24, 30}, {34, 30}, {50, 30}}}};

TEST(Script, AStrokeAndThePopUpsItCausedAreOneUndoStep) {
    Session s;
    const std::vector<std::uint8_t> blank = s.pixels();
    ASSERT_TRUE(s.run({{{"op", "set-mode"}, {"layer_aware", true}}, kBrush, kBehind}).ok());
    const core::RegionOrderState initial = [&] {
        core::RegionOrder order = s.doc.regionOrder();
        order.reset();
        return order.state();
    }();
    ASSERT_NE(s.doc.regionOrder().state(), initial) << "the stroke went behind: pop-up";
    ASSERT_NE(s.pixels(), blank);
    EXPECT_EQ(s.doc.history().undoCount(), 1u);
    EXPECT_EQ(s.doc.history().undoKind(), core::StepKind::Stroke);

    ASSERT_TRUE(s.run({{{"op", "undo"}}}).ok());
    EXPECT_EQ(s.pixels(), blank);
    EXPECT_EQ(s.doc.regionOrder().state(), initial);
    ASSERT_TRUE(s.run({{{"op", "redo"}}}).ok());
    EXPECT_NE(s.pixels(), blank);
    EXPECT_NE(s.doc.regionOrder().state(), initial);
}

TEST(Script, UndoAfterAPopUpTakesBackThePopUpNotTheStroke) {
    Session s;
    ASSERT_TRUE(s.run({{{"op", "set-mode"}, {"layer_aware", false}},
                       kBrush,
                       {{"op", "stroke"}, {"points", {{10, 12}, {20, 12}}}}})
                    .ok());
    const std::vector<std::uint8_t> painted = s.pixels();
    const core::RegionOrderState before = s.doc.regionOrder().state();
    ASSERT_TRUE(s.run({{{"op", "popup"}, {"at", {50, 30}}}}).ok());
    ASSERT_NE(s.doc.regionOrder().state(), before);
    ASSERT_TRUE(s.run({{{"op", "undo"}}}).ok());
    EXPECT_EQ(s.doc.regionOrder().state(), before);
    EXPECT_EQ(s.pixels(), painted);
    // Hiding and unhiding are steps too.
    ASSERT_TRUE(s.run({{{"op", "hide"}, {"path", {{70, 30}, {80, 30}}}, {"radius", 3}}}).ok());
    EXPECT_FALSE(s.doc.regionOrder().hiddenRegions().empty());
    ASSERT_TRUE(s.run({{{"op", "unhide-all"}}, {{"op", "undo"}}}).ok());
    EXPECT_FALSE(s.doc.regionOrder().hiddenRegions().empty());
    ASSERT_TRUE(s.run({{{"op", "undo"}}}).ok());
    EXPECT_TRUE(s.doc.regionOrder().hiddenRegions().empty());
    EXPECT_EQ(s.pixels(), painted);
}

TEST(Script, APaintTargetChangeIsUndoable) {
    Session s;
    ASSERT_TRUE(s.run({kBrush, {{"op", "stroke"}, {"points", {{10, 12}, {20, 12}}}}}).ok());
    const std::vector<std::uint8_t> painted = s.pixels();
    ASSERT_TRUE(s.run({{{"op", "set-target"}, {"kind", "vertex-colors"}}}).ok());
    EXPECT_EQ(s.doc.paintTargetKind(), core::PaintTargetKind::VertexColors);
    ASSERT_TRUE(s.run({{{"op", "undo"}}}).ok());
    ASSERT_EQ(s.doc.paintTargetKind(), core::PaintTargetKind::Texture);
    EXPECT_EQ(s.pixels(), painted);
    ASSERT_TRUE(s.run({{{"op", "undo"}}}).ok()); // and the stroke before it
    EXPECT_NE(s.pixels(), painted);
}

TEST(Script, ErrorsNameTheOperation) {
    Session s;
    const core::Status status =
        s.run({kBrush, {{"op", "stroke"}, {"points", {{10, 12}}}}, {{"op", "fly"}}});
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().find("operation 3"), std::string::npos) << status.error();
    EXPECT_NE(status.error().find("fly"), std::string::npos) << status.error();
    EXPECT_EQ(status.errorKind(), core::ErrorKind::BadInput);
    EXPECT_FALSE(core::parseScript(json::object()).ok());
    EXPECT_FALSE(s.runner.run({{"op", "set-brush"}, {"radius", "big"}}).ok());
}

TEST(Script, ARecordedSessionReplaysToTheSamePicture) {
    // What a user does, through the Document's own operations (as the GUI calls them).
    Session user;
    ASSERT_TRUE(user.host.buildDepthLayers(user.doc, pixelView(kWidth, kHeight)).ok());
    core::PaintChanges changes;
    user.doc.setLayerAware(true);
    user.doc.brush().color = {0.2f, 0.4f, 0.9f, 1.0f};
    user.doc.brush().radius = 6.0f;
    user.doc.setPressureCurve({2.0f});
    ASSERT_TRUE(user.doc.beginStroke({{14.0f, 30.0f}, 0.7f}, changes).ok());
    user.doc.moveStroke({{30.0f, 31.0f}, 0.9f}, changes);
    user.doc.moveStroke({{50.0f, 33.0f}, 0.5f}, changes);
    user.doc.endStroke();
    user.doc.beginHide();
    user.doc.hideAlong({70.0f, 30.0f}, {70.0f, 30.0f}, 3.0f);
    user.doc.hideAlong({70.0f, 30.0f}, {80.0f, 32.0f}, 3.0f);
    user.doc.endHide();
    user.doc.brush().color = {0.9f, 0.1f, 0.1f, 0.5f};
    ASSERT_TRUE(user.doc.fill({50.0f, 30.0f}, core::FillMode::Region, 0.1f, changes).ok());
    ASSERT_TRUE(user.doc.undo(changes));
    ASSERT_TRUE(user.doc.popUpAt({50.0f, 30.0f}) != core::kNone);
    user.doc.setShownLayer(2); // the Single Layer view of the covered part
    user.doc.brush().color = {0.1f, 0.9f, 0.9f, 1.0f};
    ASSERT_TRUE(user.doc.beginStroke({{44.0f, 24.0f}, 1.0f}, changes).ok());
    user.doc.moveStroke({{56.0f, 24.0f}, 1.0f}, changes);
    user.doc.endStroke();
    user.doc.setShownLayer(0);
    user.doc.brush().eraser = true;
    ASSERT_TRUE(user.doc.beginStroke({{20.0f, 30.0f}, 1.0f}, changes).ok());
    user.doc.moveStroke({{26.0f, 30.0f}, 1.0f}, changes);
    user.doc.endStroke();

    const core::Script script = user.doc.session().script();
    ASSERT_GT(script.operations.size(), 5u);
    // Through text, as a saved script would be.
    const core::Result<core::Script> parsed =
        core::parseScript(json::parse(core::scriptToJson(script).dump()));
    ASSERT_TRUE(parsed.ok()) << parsed.error();

    Session replay;
    ASSERT_TRUE(replay.runner.runAll(*parsed).ok());
    EXPECT_EQ(replay.pixels(), user.pixels());
    EXPECT_EQ(replay.doc.regionOrder().state(), user.doc.regionOrder().state());
    EXPECT_EQ(replay.doc.brush(), user.doc.brush());
    EXPECT_EQ(replay.doc.history().undoCount(), user.doc.history().undoCount());
}

TEST(Script, AGroupedScriptIsOneUndoStep) {
    Session s;
    const std::vector<std::uint8_t> blank = s.pixels();
    core::Script script;
    script.operations = {kBrush,
                         {{"op", "stroke"}, {"points", {{10, 12}, {20, 12}}}},
                         {{"op", "popup"}, {"at", {50, 30}}},
                         {{"op", "stroke"}, {"points", {{10, 40}, {20, 40}}}},
                         {{"op", "undo"}}, // the script's own undo works step by step
                         {{"op", "stroke"}, {"points", {{10, 44}, {20, 44}}}}};
    Session stepByStep;
    ASSERT_TRUE(stepByStep.runner.runAll(script).ok());
    EXPECT_EQ(stepByStep.doc.history().undoCount(), 3u);

    const std::uint64_t mark = s.doc.history().mark();
    ASSERT_TRUE(s.runner.runAll(script).ok());
    ASSERT_TRUE(s.doc.history().squash(mark, core::StepKind::Script));
    EXPECT_EQ(s.doc.history().undoCount(), 1u);
    EXPECT_FALSE(s.doc.history().canRedo());
    EXPECT_EQ(s.pixels(), stepByStep.pixels());
    core::PaintChanges changes;
    ASSERT_TRUE(s.doc.undo(changes));
    EXPECT_EQ(s.pixels(), blank);
    EXPECT_FALSE(s.doc.history().canUndo());
}

TEST(Script, RunAllCanBeCancelled) {
    Session s;
    core::Script script;
    script.operations = {kBrush, kBrush, kBrush};
    int calls = 0;
    const core::Status status = s.runner.runAll(script, [&](double) { return ++calls < 2; });
    EXPECT_TRUE(status.cancelled());
    EXPECT_EQ(s.runner.count(), 1u);
}

/** Every byte of every paint layer of a session's texture target, with the shown pages. */
std::vector<std::uint8_t> layerBytes(core::Document& doc) {
    const auto& target = *dynamic_cast<const core::TextureTarget*>(doc.paintTarget());
    std::vector<std::uint8_t> out = target.page(0).rgba;
    const auto& mr = target.metallicRoughnessPage(0).rgba;
    out.insert(out.end(), mr.begin(), mr.end());
    const core::PaintLayerStack& stack = target.paintLayerStack();
    for (std::size_t i = 0; i < stack.size(); ++i) {
        const core::PaintLayer& layer = stack.layer(i);
        out.insert(out.end(), layer.settings.name.begin(), layer.settings.name.end());
        out.push_back(std::uint8_t(layer.settings.blend));
        out.push_back(std::uint8_t(layer.settings.visible));
        out.push_back(std::uint8_t(layer.settings.opacity * 255.0f));
        for (const core::TiledPlane* plane : {layer.channels[0].get(), layer.channels[1].get(),
                                              layer.channels[2].get(), layer.mask.get()}) {
            if (!plane)
                continue;
            for (const core::TileKey key : plane->writtenTiles()) {
                const std::uint8_t* t = plane->tile(key.page, key.tile);
                out.insert(out.end(), t, t + plane->tileBytes(key));
            }
        }
    }
    return out;
}

TEST(Script, PaintLayerOperations) {
    Session s;
    const json ops = json::parse(R"json([
        {"op": "layer-add", "name": "Colour"},
        {"op": "set-brush", "color": "#20c040", "radius": 5, "hardness": 1},
        {"op": "stroke", "points": [[14, 30], [30, 30]]},
        {"op": "layer-add", "name": "Metal", "kind": "paint"},
        {"op": "set-brush", "channels": {"roughness": 0.3, "metallic": 1.0}},
        {"op": "stroke", "points": [[14, 20], [30, 20]]},
        {"op": "layer-add", "name": "Tint", "kind": "fill",
         "values": {"base_color": "#ff8000"}},
        {"op": "layer-set", "layer": "Tint", "opacity": 0.5, "blend": "multiply"},
        {"op": "mask-add", "layer": "Tint"},
        {"op": "set-brush", "channels": {"base_color": "#000000"}},
        {"op": "stroke", "points": [[14, 40], [30, 40]]},
        {"op": "layer-select", "layer": "Colour"},
        {"op": "layer-move", "index": 2},
        {"op": "layer-set", "layer": 0, "visible": false, "name": "Metal (hidden)"},
        {"op": "mask-select", "layer": "Tint"},
        {"op": "layer-merge-down", "layer": "Colour"}
    ])json");
    ASSERT_TRUE(s.run(ops).ok());
    const auto& target = *dynamic_cast<const core::TextureTarget*>(s.doc.paintTarget());
    const core::PaintLayerStack& stack = target.paintLayerStack();
    ASSERT_EQ(stack.size(), 2u);
    EXPECT_EQ(stack.layer(0).settings.name, "Metal (hidden)");
    EXPECT_FALSE(stack.layer(0).settings.visible);
    EXPECT_EQ(stack.layer(1).settings.name, "Tint");
    EXPECT_EQ(stack.layer(1).settings.kind, core::PaintLayerKind::Paint) << "merged";
    EXPECT_EQ(target.selection().layer, stack.layer(1).id);
    EXPECT_EQ(s.doc.brush().paintBaseColor, true);
    EXPECT_EQ(s.doc.brush().paintRoughness, false);

    // Errors name the operation and what is wrong.
    core::Status bad = s.run(json::array({{{"op", "layer-set"}, {"blend", "sideways"}}}));
    EXPECT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("blend"), std::string::npos) << bad.error();
    bad = s.run(json::array({{{"op", "layer-select"}, {"layer", "Nope"}}}));
    EXPECT_NE(bad.error().find("Nope"), std::string::npos) << bad.error();
    bad = s.run(json::array({{{"op", "set-brush"}, {"channels", {{"gloss", 1}}}}}));
    EXPECT_NE(bad.error().find("gloss"), std::string::npos) << bad.error();
    bad = s.run(json::array({{{"op", "layer-merge-down"}, {"layer", 0}}}));
    EXPECT_FALSE(bad.ok());
}

TEST(Script, ARecordedSessionWithPaintLayersReplaysToTheSameLayers) {
    Session user;
    ASSERT_TRUE(user.host.buildDepthLayers(user.doc, pixelView(kWidth, kHeight)).ok());
    core::PaintChanges changes;
    core::PaintLayerSettings settings;
    settings.name = "One";
    auto one = user.doc.addPaintLayer(settings, changes);
    ASSERT_TRUE(one.ok());
    user.doc.brush().radius = 6.0f;
    user.doc.brush().paintRoughness = true;
    user.doc.brush().roughness = 0.1f;
    ASSERT_TRUE(user.doc.beginStroke({{14.0f, 30.0f}, 1.0f}, changes).ok());
    user.doc.moveStroke({{50.0f, 33.0f}, 1.0f}, changes);
    user.doc.endStroke();
    auto two = user.doc.duplicatePaintLayer(*one, changes);
    ASSERT_TRUE(two.ok());
    settings = user.doc.paintLayerTarget().value()->paintLayerStack().layer(1).settings;
    settings.blend = core::BlendMode::Screen;
    settings.opacity = 0.5f;
    ASSERT_TRUE(user.doc.setPaintLayerSettings(*two, settings, changes).ok());
    ASSERT_TRUE(user.doc.addPaintLayerMask(*two, changes).ok());
    user.doc.brush().color = {0.0f, 0.0f, 0.0f, 1.0f};
    ASSERT_TRUE(user.doc.beginStroke({{20.0f, 30.0f}, 1.0f}, changes).ok());
    user.doc.moveStroke({{26.0f, 30.0f}, 1.0f}, changes);
    user.doc.endStroke();
    ASSERT_TRUE(user.doc.selectPaint({0, false}).ok());
    ASSERT_TRUE(user.doc.movePaintLayer(*one, 1, changes).ok());
    ASSERT_TRUE(user.doc.undo(changes));
    ASSERT_TRUE(user.doc.mergePaintLayerDown(*two, changes).ok());

    const core::Result<core::Script> parsed =
        core::parseScript(json::parse(core::scriptToJson(user.doc.session().script()).dump()));
    ASSERT_TRUE(parsed.ok()) << parsed.error();
    Session replay;
    ASSERT_TRUE(replay.runner.runAll(*parsed).ok());
    EXPECT_EQ(layerBytes(replay.doc), layerBytes(user.doc));
    EXPECT_EQ(replay.doc.brush(), user.doc.brush());
    EXPECT_EQ(replay.doc.history().undoCount(), user.doc.history().undoCount());
}

TEST(Script, FillLayerValuesChangeAfterCreationAsOneUndoStep) {
    Session s;
    ASSERT_TRUE(s.run(json::parse(R"json([
        {"op": "layer-add", "name": "Gloss", "kind": "fill", "values": {"roughness": 0.3}}
    ])json"))
                    .ok());
    const auto& target = *dynamic_cast<const core::TextureTarget*>(s.doc.paintTarget());
    const std::vector<std::uint8_t> before = target.metallicRoughnessPage(0).rgba;
    ASSERT_EQ(before[1], 77); // roughness 0.3 everywhere
    const std::size_t steps = s.doc.history().undoCount();

    ASSERT_TRUE(s.run(json::parse(R"json([
        {"op": "layer-set", "layer": "Gloss", "values": {"roughness": 0.8, "metallic": 1}}
    ])json"))
                    .ok());
    const core::PaintLayerStack& stack = target.paintLayerStack();
    EXPECT_EQ(stack.layer(0).settings.fill.roughness, 0.8f);
    EXPECT_EQ(stack.layer(0).settings.fill.metallic, 1.0f);
    EXPECT_FALSE(stack.layer(0).settings.fill.baseColor.has_value());
    const std::vector<std::uint8_t>& after = target.metallicRoughnessPage(0).rgba;
    EXPECT_EQ(after[1], 204);
    EXPECT_EQ(after[2], 255);
    EXPECT_EQ(s.doc.history().undoCount(), steps + 1);
    // The session records it so that a replay gives the same values.
    EXPECT_NE(s.doc.session().script().operations.dump().find("\"values\""), std::string::npos);

    // null leaves a channel alone again; values on a paint layer are an error.
    ASSERT_TRUE(
        s.run(json::parse(
                  R"json([{"op": "layer-set", "layer": 0, "values": {"metallic": null}}])json"))
            .ok());
    EXPECT_FALSE(stack.layer(0).settings.fill.metallic.has_value());
    EXPECT_EQ(target.metallicRoughnessPage(0).rgba[2], 0);
    ASSERT_TRUE(s.run(json::parse(R"json([{"op": "undo"}, {"op": "undo"}])json")).ok());
    EXPECT_EQ(target.metallicRoughnessPage(0).rgba, before);
    ASSERT_TRUE(s.run(json::parse(R"json([{"op": "layer-add", "name": "Paint"}])json")).ok());
    const core::Status bad = s.run(json::parse(
        R"json([{"op": "layer-set", "layer": "Paint", "values": {"roughness": 1}}])json"));
    EXPECT_FALSE(bad.ok());
    EXPECT_NE(bad.error().find("fill layer"), std::string::npos) << bad.error();
}

} // namespace script_test
