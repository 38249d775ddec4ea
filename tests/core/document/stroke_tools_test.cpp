// SPDX-License-Identifier: GPL-3.0-or-later
// The stroke tools in the Document, on CPU-captured layers: the stabilizer's catch-up at release,
// straight lines from the end of the previous stroke (layer-aware behind an occluder, one undo
// step), and both replayed from a recorded session and from script operations.
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/document/document.h"
#include "core/document/project_state.h"
#include "core/document/script.h"
#include "tests/core/script_host.h"
#include "tests/core/test_scenes.h"

namespace stroke_tools_test {

using core_test::pixelView;
using nlohmann::json;

constexpr int kWidth = 96, kHeight = 64;

struct Session : core_test::QuadsScriptSession {
    core::PaintChanges changes;

    Session() : QuadsScriptSession(128) {
        EXPECT_TRUE(host.buildDepthLayers(doc, pixelView(kWidth, kHeight)).ok());
        doc.brush().radius = 3.0f;
        doc.brush().hardness = 1.0f;
    }
    const core::Image& page() const {
        return dynamic_cast<const core::TextureTarget&>(*doc.currentPaintTarget()).page(0);
    }
    std::vector<std::uint8_t> pixels() const { return page().rgba; }
    /** The texels of the front quad's half (u above 0.5, clear of the seam padding). */
    std::vector<std::uint8_t> frontHalf() const { return core_test::frontHalfTexels(page()); }
    void stroke(std::initializer_list<glm::vec2> points) {
        auto it = points.begin();
        ASSERT_TRUE(doc.beginStroke({*it, 1.0f}, changes).ok());
        for (++it; it != points.end(); ++it)
            doc.moveStroke({*it, 1.0f}, changes);
        doc.endStroke(changes);
    }
};

TEST(StrokeTools, WithCatchUpTheLastDabLandsAtTheReleasePoint) {
    for (const bool catchUp : {true, false}) {
        Session s;
        s.doc.brush().stabilizer = true;
        s.doc.brush().stabilizerLength = 20.0f;
        s.doc.brush().stabilizerCatchUp = catchUp;
        s.stroke({{8.0f, 30.0f}, {16.0f, 30.0f}, {24.0f, 30.0f}, {34.0f, 30.0f}});
        ASSERT_TRUE(s.doc.lineStart());
        // Dabs sit every spacing × radius along the path: the last within one step of its end.
        const float step = std::max(s.doc.brush().spacing * s.doc.brush().radius, 0.5f);
        const glm::vec2 end = catchUp ? glm::vec2(34.0f, 30.0f) : glm::vec2(14.0f, 30.0f);
        EXPECT_LE(glm::distance(*s.doc.lineStart(), end), step + 1e-3f)
            << (catchUp ? "catch-up" : "no catch-up") << ": ended at " << s.doc.lineStart()->x;
        EXPECT_EQ(s.doc.history().undoCount(), 1u);
    }
}

TEST(StrokeTools, ALineGoesOnBehindTheOccluderFromAStrokeThatEndedThere) {
    Session s;
    s.doc.setLayerAware(true);
    s.doc.setAutoPopUp(false); // the back quad stays hidden behind the front one
    const std::vector<std::uint8_t> front = s.frontHalf();
    // From the back quad's open part in under the front quad.
    s.stroke({{14.0f, 30.0f}, {30.0f, 30.0f}, {50.0f, 30.0f}});
    ASSERT_EQ(s.frontHalf(), front) << "the stroke stayed on the back quad";
    ASSERT_TRUE(s.doc.lineStart());
    EXPECT_NEAR(s.doc.lineStart()->x, 50.0f, 1.0f);

    const std::vector<std::uint8_t> before = s.pixels();
    ASSERT_TRUE(s.doc.lineTo({{58.0f, 42.0f}, 1.0f}, s.changes).ok());
    EXPECT_FALSE(s.changes.texels.empty());
    EXPECT_NE(s.pixels(), before) << "the line painted";
    EXPECT_EQ(s.frontHalf(), front) << "on the back quad, behind the front one";
    EXPECT_EQ(s.doc.history().undoCount(), 2u) << "a line is one step";
    EXPECT_NEAR(glm::distance(*s.doc.lineStart(), glm::vec2(58.0f, 42.0f)), 0.0f, 1.0f);

    core::PaintChanges undone;
    ASSERT_TRUE(s.doc.undo(undone));
    EXPECT_EQ(s.pixels(), before);

    // The same line started on the surface seen there paints the front quad.
    ASSERT_TRUE(s.doc.line({{50.0f, 30.0f}, 1.0f}, {{58.0f, 42.0f}, 1.0f}, s.changes).ok());
    EXPECT_NE(s.frontHalf(), front);
}

TEST(StrokeTools, ALineWithoutAPreviousStrokeIsADabAndStartsTheNext) {
    Session s;
    EXPECT_FALSE(s.doc.lineStart());
    const std::vector<std::uint8_t> blank = s.pixels();
    ASSERT_TRUE(s.doc.lineTo({{20.0f, 20.0f}, 1.0f}, s.changes).ok());
    EXPECT_NE(s.pixels(), blank);
    ASSERT_TRUE(s.doc.lineStart());
    EXPECT_EQ(*s.doc.lineStart(), glm::vec2(20.0f, 20.0f));
    // A new view forgets it: its pixels are of the old one.
    s.doc.clearDepthLayers();
    EXPECT_FALSE(s.doc.lineStart());
    EXPECT_FALSE(s.doc.lineTo({{20.0f, 20.0f}, 1.0f}, s.changes).ok());
}

TEST(StrokeTools, AStabilizedStrokeAndLinesReplayFromTheSession) {
    Session user;
    user.doc.setLayerAware(true);
    user.doc.brush().stabilizer = true;
    user.doc.brush().stabilizerLength = 12.0f;
    user.doc.brush().stabilizerSmoothing = 0.5f;
    user.stroke({{10.0f, 20.0f},
                 {14.0f, 23.0f},
                 {19.0f, 19.0f},
                 {25.0f, 24.0f},
                 {31.0f, 20.0f},
                 {40.0f, 22.0f}});
    ASSERT_TRUE(user.doc.lineTo({{20.0f, 50.0f}, 1.0f}, user.changes).ok());
    user.doc.brush().stabilizerCatchUp = false;
    user.stroke({{8.0f, 40.0f}, {20.0f, 44.0f}, {30.0f, 40.0f}});
    ASSERT_TRUE(user.doc.line({{60.0f, 12.0f}, 1.0f}, {{80.0f, 40.0f}, 1.0f}, user.changes).ok());

    const std::string text = core::scriptToJson(user.doc.session().script()).dump();
    EXPECT_NE(text.find("\"line-to\""), std::string::npos);
    EXPECT_NE(text.find("\"stabilizer\""), std::string::npos);
    const core::Result<core::Script> parsed = core::parseScript(json::parse(text));
    ASSERT_TRUE(parsed.ok()) << parsed.error();
    Session replay;
    replay.doc.brush() = core::Brush{};
    ASSERT_TRUE(replay.runner.runAll(*parsed).ok());
    EXPECT_EQ(replay.pixels(), user.pixels());
    EXPECT_EQ(replay.doc.brush(), user.doc.brush());
    EXPECT_EQ(replay.doc.history().undoCount(), user.doc.history().undoCount());
}

TEST(StrokeTools, ScriptOperationsSetTheStabilizerAndDrawLines) {
    Session s;
    ASSERT_TRUE(s.runner
                    .run({{"op", "set-brush"},
                          {"stabilizer", {{"on", true}, {"length", 40}, {"catch_up", false}}}})
                    .ok());
    EXPECT_TRUE(s.doc.brush().stabilizer);
    EXPECT_EQ(s.doc.brush().stabilizerLength, 40.0f);
    EXPECT_FALSE(s.doc.brush().stabilizerCatchUp);
    ASSERT_TRUE(s.runner.run({{"op", "set-brush"}, {"stabilizer", false}}).ok());
    EXPECT_FALSE(s.doc.brush().stabilizer);

    const std::vector<std::uint8_t> blank = s.pixels();
    ASSERT_TRUE(s.runner.run({{"op", "line"}, {"from", {10, 12}}, {"to", {30, 12}}}).ok());
    ASSERT_TRUE(s.runner.run({{"op", "line-to"}, {"to", {30, 40, 0.5}}}).ok());
    EXPECT_NE(s.pixels(), blank);
    EXPECT_EQ(s.doc.history().undoCount(), 2u);

    // Bad input: an error naming the operation and the problem; nothing changes.
    const core::Brush brush = s.doc.brush();
    const core::Status badLength =
        s.runner.run({{"op", "set-brush"}, {"stabilizer", {{"length", -1}}}});
    ASSERT_FALSE(badLength.ok());
    EXPECT_NE(badLength.error().find("length"), std::string::npos) << badLength.error();
    EXPECT_FALSE(s.runner.run({{"op", "set-brush"}, {"stabilizer", {{"string", 3}}}}).ok());
    EXPECT_FALSE(s.runner.run({{"op", "set-brush"}, {"stabilizer", "yes"}}).ok());
    EXPECT_EQ(s.doc.brush(), brush);
    const core::Status noTo = s.runner.run({{"op", "line-to"}, {"at", {1, 2}}});
    ASSERT_FALSE(noTo.ok());
    EXPECT_NE(noTo.error().find("\"to\""), std::string::npos) << noTo.error();
    EXPECT_FALSE(s.runner.run({{"op", "line"}, {"to", {1, 2}}}).ok());
    EXPECT_FALSE(s.runner.run({{"op", "line"}, {"from", {1, 2}}, {"to", {1, 2, 7}}}).ok());
    EXPECT_EQ(s.doc.history().undoCount(), 2u);
}

TEST(StrokeTools, AProjectKeepsTheStabilizerSettings) {
    core::ProjectState state;
    state.brush.stabilizer = true;
    state.brush.stabilizerLength = 55.0f;
    state.brush.stabilizerSmoothing = 0.25f;
    state.brush.stabilizerCatchUp = false;
    const core::Result<core::ProjectState> back =
        core::projectStateFromJson(core::projectStateToJson(state));
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_TRUE(back->brush.stabilizer);
    EXPECT_EQ(back->brush.stabilizerLength, 55.0f);
    EXPECT_EQ(back->brush.stabilizerSmoothing, 0.25f);
    EXPECT_FALSE(back->brush.stabilizerCatchUp);

    // A value out of range keeps the default, with a warning.
    nlohmann::json j = core::projectStateToJson(state);
    j["stabilizer"]["length"] = -4;
    std::vector<std::string> warnings;
    const core::Result<core::ProjectState> bad = core::projectStateFromJson(j, &warnings);
    ASSERT_TRUE(bad.ok()) << bad.error();
    EXPECT_EQ(bad->brush.stabilizerLength, core::Brush{}.stabilizerLength);
    EXPECT_FALSE(warnings.empty());
}

} // namespace stroke_tools_test
