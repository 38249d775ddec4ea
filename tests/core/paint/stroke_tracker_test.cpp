// SPDX-License-Identifier: GPL-3.0-or-later
// Layer-aware stroke tracking (core/stroke_tracker.h): golden BFS cases on hand-made stacks
// (tests/data/stroke_*/), resampling, the conventional mode, and a stroke on the CPU-captured
// trefoil that follows a strand under a crossing.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/depth/depth_layers.h"
#include "core/model/builtin_models.h"
#include "core/model/camera.h"
#include "core/model/mesh_topology.h"
#include "core/paint/tracking/stroke_tracker.h"
#include "tests/core/golden_cases.h"

namespace stroke_tracker_test {

namespace fs = std::filesystem;
using core::Dab;
using core::kNone;
using core::StrokePoint;
using core::StrokeTracker;
using nlohmann::json;

using core_test::tokens;

/**
 * One golden case, read from tests/data/<case>/stroke.json. layers[k].links are rows of per-pixel
 * tokens for layer k + 1: four digits R, L, U, D (the linked layer of that neighbour, 0 = none)
 * or "." for no fragment. "visible" (optional) gives the visible layer of each pixel, as a region
 * order would; without it layer 1 is visible. Each step is a point with pressure 1 (the first
 * starts the stroke) and what follows it: the dabs painted ([x, y, layer]) and the last painted
 * dab's Mp and complete Mt as rows of layers, "." = none. The expected values were computed by
 * an independent Python BFS and checked by hand against the descriptions.
 */
struct StrokeCase {
    struct Step {
        glm::vec2 point{0.0f};
        std::vector<std::array<float, 3>> dabs;
        std::vector<std::uint32_t> paintable, trackable; // per pixel, 0 = none
    };
    std::string name;
    std::string error;
    core::DepthStack stack;
    core::Connectivity connectivity;
    std::vector<std::uint32_t> visible; // per pixel; empty = layer 1
    core::Brush brush;
    bool layerAware = true;
    bool antiBleeding = true;
    std::vector<Step> steps;
};

std::vector<std::uint32_t> readMap(const json& rows, int w, int h) {
    if (rows.size() != std::size_t(h))
        throw std::runtime_error("a map has a wrong height");
    std::vector<std::uint32_t> map;
    for (const auto& row : rows) {
        const auto t = tokens(row.get<std::string>());
        if (t.size() != std::size_t(w))
            throw std::runtime_error("a map row has a wrong width");
        for (const auto& v : t)
            map.push_back(v == "." ? 0u : std::uint32_t(std::stoul(v)));
    }
    return map;
}

StrokeCase loadCase(const fs::path& file) {
    StrokeCase c;
    c.name = file.parent_path().filename().string();
    try {
        std::ifstream in(file);
        const json j = json::parse(in);
        const int w = j.at("width"), h = j.at("height");
        c.stack.width = c.connectivity.width = w;
        c.stack.height = c.connectivity.height = h;
        const auto& layers = j.at("layers");
        std::vector<std::vector<std::string>> grid; // grid[k][pixel]
        for (const auto& layer : layers) {
            std::vector<std::string> cells;
            for (const auto& row : layer.at("links")) {
                const auto t = tokens(row.get<std::string>());
                if (t.size() != std::size_t(w))
                    throw std::runtime_error("a links row has a wrong width");
                cells.insert(cells.end(), t.begin(), t.end());
            }
            if (cells.size() != std::size_t(w) * std::size_t(h))
                throw std::runtime_error("a links layer has a wrong height");
            grid.push_back(std::move(cells));
        }
        c.stack.offsets.push_back(0);
        for (std::size_t p = 0; p < std::size_t(w) * std::size_t(h); ++p) {
            bool gap = false;
            for (std::size_t k = 0; k < grid.size(); ++k) {
                const std::string& t = grid[k][p];
                if (t == ".") {
                    gap = true;
                    continue;
                }
                if (gap || t.size() != 4)
                    throw std::runtime_error("bad fragment token at pixel " + std::to_string(p));
                c.stack.depth.push_back(float(k + 1));
                c.stack.triangle.push_back(0);
                for (char digit : t)
                    c.connectivity.links.push_back(std::uint8_t(digit - '0'));
            }
            c.stack.offsets.push_back(std::uint32_t(c.stack.depth.size()));
        }
        if (j.contains("visible"))
            c.visible = readMap(j["visible"], w, h);
        const auto& brush = j.at("brush");
        c.brush.radius = brush.at("radius");
        c.brush.trackRadius = brush.at("trackRadius");
        c.brush.spacing = brush.at("spacing");
        c.layerAware = j.value("layerAware", true);
        c.antiBleeding = j.value("antiBleeding", true);
        for (const auto& s : j.at("steps")) {
            StrokeCase::Step step;
            step.point = {s.at("point")[0], s.at("point")[1]};
            for (const auto& d : s.at("dabs"))
                step.dabs.push_back({d[0], d[1], d[2]});
            step.paintable = readMap(s.at("paintable"), w, h);
            step.trackable = readMap(s.at("trackable"), w, h);
            c.steps.push_back(std::move(step));
        }
    } catch (const std::exception& e) {
        c.error = e.what();
    }
    return c;
}

/** A map as rows of layer digits, for readable failures. */
std::string drawMap(const std::vector<std::uint32_t>& map, int w) {
    std::string s;
    for (std::size_t p = 0; p < map.size(); ++p) {
        s += map[p] ? char('0' + std::min(map[p], 9u)) : '.';
        if ((p + 1) % std::size_t(w) == 0)
            s += '\n';
    }
    return s;
}

class StrokeGolden : public testing::TestWithParam<fs::path> {};

TEST_P(StrokeGolden, DabsAndMapsMatch) {
    const StrokeCase c = loadCase(GetParam());
    ASSERT_TRUE(c.error.empty()) << GetParam() << ": " << c.error;
    const std::size_t pixels = c.stack.pixelCount();
    // Lazily grown Mt (as in painting) and Mt completed after every step (as with the overlay on)
    // must give the same dabs: completing only adds what a later lookup would have found.
    for (bool complete : {false, true}) {
        SCOPED_TRACE(complete ? "Mt completed after each step" : "Mt grown lazily");
        StrokeTracker tracker;
        ASSERT_TRUE(tracker.setDepthLayers(c.stack, c.connectivity));
        if (!c.visible.empty())
            tracker.setVisibleFragment([&](std::size_t p) {
                return c.visible[p] ? c.stack.fragment(p, c.visible[p]) : kNone;
            });
        tracker.setLayerAware(c.layerAware);
        tracker.setAntiBleeding(c.antiBleeding);
        for (std::size_t i = 0; i < c.steps.size(); ++i) {
            const StrokeCase::Step& step = c.steps[i];
            SCOPED_TRACE("step " + std::to_string(i) + " to (" + std::to_string(step.point.x) +
                         ", " + std::to_string(step.point.y) + ")");
            std::vector<Dab> dabs;
            const std::size_t added = i == 0
                                          ? tracker.startStroke({step.point, 1.0f}, c.brush, dabs)
                                          : tracker.moveStroke({step.point, 1.0f}, dabs);
            EXPECT_EQ(added, dabs.size());
            ASSERT_EQ(dabs.size(), step.dabs.size());
            for (std::size_t d = 0; d < dabs.size(); ++d) {
                EXPECT_NEAR(dabs[d].center.x, step.dabs[d][0], 1e-4f) << "dab " << d;
                EXPECT_NEAR(dabs[d].center.y, step.dabs[d][1], 1e-4f) << "dab " << d;
                EXPECT_EQ(dabs[d].layer, std::uint32_t(step.dabs[d][2])) << "dab " << d;
                EXPECT_EQ(dabs[d].radius, c.brush.radius);
            }
            std::vector<std::uint32_t> mp(pixels);
            for (std::size_t p = 0; p < pixels; ++p)
                mp[p] = tracker.paintableLayer(p);
            EXPECT_EQ(mp, step.paintable) << "Mp is\n"
                                          << drawMap(mp, c.stack.width) << "expected\n"
                                          << drawMap(step.paintable, c.stack.width);
            if (!dabs.empty()) {
                // The last dab's list is the same Mp, one entry per pixel, with its distances.
                const Dab& dab = dabs.back();
                std::vector<std::uint32_t> fromList(pixels, 0);
                for (const core::MapPixel& m : dab.paintable) {
                    ASSERT_LT(m.pixel, pixels);
                    EXPECT_EQ(fromList[m.pixel], 0u) << "pixel " << m.pixel << " listed twice";
                    ASSERT_GE(m.fragment, c.stack.offsets[m.pixel]);
                    ASSERT_LT(m.fragment, c.stack.offsets[m.pixel + 1]);
                    fromList[m.pixel] = m.fragment - c.stack.offsets[m.pixel] + 1;
                    const glm::vec2 centre(float(m.pixel % std::uint32_t(c.stack.width)) + 0.5f,
                                           float(m.pixel / std::uint32_t(c.stack.width)) + 0.5f);
                    EXPECT_NEAR(m.distance, glm::length(centre - dab.center), 1e-4f);
                    EXPECT_LE(m.distance, dab.radius);
                }
                EXPECT_EQ(fromList, step.paintable);
            }
            if (complete) {
                tracker.completeTrackableMap();
                std::vector<std::uint32_t> mt(pixels);
                for (std::size_t p = 0; p < pixels; ++p)
                    mt[p] = tracker.trackableLayer(p);
                EXPECT_EQ(mt, step.trackable) << "Mt is\n"
                                              << drawMap(mt, c.stack.width) << "expected\n"
                                              << drawMap(step.trackable, c.stack.width);
                EXPECT_EQ(tracker.trackablePixels().size(),
                          std::size_t(std::count_if(mt.begin(), mt.end(),
                                                    [](std::uint32_t l) { return l != 0; })));
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, StrokeGolden,
                         testing::ValuesIn(core_test::goldenFiles("stroke.json")),
                         core_test::goldenTestName);

TEST(StrokeGoldenData, AllExpectedCasesArePresent) {
    const std::vector<std::string> names = core_test::goldenCaseNames("stroke.json");
    for (const char* want :
         {"stroke_flat_disc", "stroke_under_occluder", "stroke_background_start",
          "stroke_popup_start", "stroke_conventional_occluder", "stroke_contour_end_bleeding",
          "stroke_contour_end_no_limit", "stroke_fold_behind"})
        EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
}

// ---------------------------------------------------------------------------------------------
// A larger synthetic scene: a strand S (rows 10-29, all columns) under an occluder O (columns
// 100-139, all rows), S on layer 2 below O; S and O are not connected.

struct Scene {
    core::DepthStack stack;
    core::Connectivity connectivity;
};

Scene strandUnderOccluder(int w = 300, int h = 40) {
    Scene s;
    auto inS = [](int, int y) { return y >= 10 && y < 30; };
    auto inO = [](int x, int) { return x >= 100 && x < 140; };
    auto layersAt = [&](int x, int y) {
        std::vector<char> f;
        if (x >= 0 && y >= 0 && x < w && y < h) {
            if (inO(x, y))
                f.push_back('O');
            if (inS(x, y))
                f.push_back('S');
        }
        return f;
    };
    s.stack.width = s.connectivity.width = w;
    s.stack.height = s.connectivity.height = h;
    s.stack.offsets.push_back(0);
    const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, -1, 1};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const auto here = layersAt(x, y);
            for (std::size_t k = 0; k < here.size(); ++k) {
                s.stack.depth.push_back(float(k + 1));
                s.stack.triangle.push_back(here[k] == 'O' ? 1u : 0u);
                for (int d = 0; d < 4; ++d) {
                    const auto there = layersAt(x + dx[d], y + dy[d]);
                    const auto it = std::find(there.begin(), there.end(), here[k]);
                    s.connectivity.links.push_back(
                        it == there.end() ? 0 : std::uint8_t(it - there.begin() + 1));
                }
            }
            s.stack.offsets.push_back(std::uint32_t(s.stack.depth.size()));
        }
    return s;
}

core::Brush testBrush(float radius) {
    core::Brush b;
    b.radius = radius;
    return b;
}

TEST(StrokeResampling, OneFastJumpGivesTheDabsOfManySmallMoves) {
    const Scene s = strandUnderOccluder();
    core::Brush brush = testBrush(10.0f);
    brush.pressureRadius = true;
    brush.pressureOpacity = true;
    // Along a slanted line through the occluder (layer 1, then 2 under O, then 1 again), with
    // the pressure rising from 0.4 to 1 so the radius and the spacing change along the way.
    const StrokePoint a{{20.3f, 14.7f}, 0.4f}, b{{220.3f, 24.1f}, 1.0f};
    auto run = [&](int moves, bool completeEachTime) {
        StrokeTracker tracker;
        EXPECT_TRUE(tracker.setDepthLayers(s.stack, s.connectivity));
        std::vector<Dab> dabs;
        tracker.startStroke(a, brush, dabs);
        for (int i = 1; i <= moves; ++i) {
            const float t = float(i) / float(moves);
            tracker.moveStroke({a.position + (b.position - a.position) * t,
                                a.pressure + (b.pressure - a.pressure) * t},
                               dabs);
            if (completeEachTime)
                tracker.completeTrackableMap();
        }
        return dabs;
    };
    const std::vector<Dab> jump = run(1, false);
    ASSERT_GT(jump.size(), 40u);
    for (const auto& [moves, complete] :
         {std::pair{40, false}, std::pair{40, true}, std::pair{1000, false}, std::pair{1, true}}) {
        SCOPED_TRACE(std::to_string(moves) + " moves" + (complete ? ", Mt completed" : ""));
        const std::vector<Dab> small = run(moves, complete);
        ASSERT_EQ(small.size(), jump.size());
        for (std::size_t i = 0; i < jump.size(); ++i) {
            EXPECT_NEAR(small[i].center.x, jump[i].center.x, 1e-3f) << "dab " << i;
            EXPECT_NEAR(small[i].center.y, jump[i].center.y, 1e-3f) << "dab " << i;
            EXPECT_NEAR(small[i].radius, jump[i].radius, 1e-3f) << "dab " << i;
            EXPECT_NEAR(small[i].opacity, jump[i].opacity, 1e-4f) << "dab " << i;
            EXPECT_EQ(small[i].layer, jump[i].layer) << "dab " << i;
            EXPECT_EQ(small[i].paintable.size(), jump[i].paintable.size()) << "dab " << i;
        }
    }
    // The dabs follow S under O: layer 2 exactly where the centre is under O.
    for (const Dab& d : jump) {
        const bool underO = d.center.x >= 100.0f && d.center.x < 140.0f;
        EXPECT_EQ(d.layer, underO ? 2u : 1u) << "dab at " << d.center.x;
        for (const core::MapPixel& m : d.paintable)
            EXPECT_EQ(s.stack.triangle[m.fragment], 0u) << "O painted by the dab at " << d.center.x;
    }
    // Spacing: 0.15 × the radius at the previous dab; radius and opacity follow the pressure.
    for (std::size_t i = 1; i < jump.size(); ++i)
        EXPECT_NEAR(glm::length(jump[i].center - jump[i - 1].center),
                    brush.spacing * jump[i - 1].radius, 1e-3f);
    EXPECT_NEAR(jump.front().radius, 4.0f, 1e-5f);
    EXPECT_NEAR(jump.front().opacity, 0.4f, 1e-5f);
    EXPECT_GT(jump.back().radius, 9.5f);
}

TEST(StrokeResampling, DabsAreSpacedAlongThePathNotAtTheEvents) {
    const Scene s = strandUnderOccluder();
    StrokeTracker tracker;
    ASSERT_TRUE(tracker.setDepthLayers(s.stack, s.connectivity));
    core::Brush brush = testBrush(10.0f);
    brush.spacing = 0.5f; // 5 px
    std::vector<Dab> dabs;
    EXPECT_EQ(tracker.startStroke({{10.5f, 20.5f}, 1.0f}, brush, dabs), 1u);
    EXPECT_EQ(tracker.moveStroke({{13.5f, 20.5f}, 1.0f}, dabs), 0u); // 3 px: not yet
    EXPECT_EQ(tracker.moveStroke({{13.5f, 20.5f}, 1.0f}, dabs), 0u); // no motion
    EXPECT_EQ(tracker.moveStroke({{13.5f, 24.5f}, 1.0f}, dabs), 1u); // 7 px of path
    ASSERT_EQ(dabs.size(), 2u);
    EXPECT_NEAR(dabs[1].center.x, 13.5f, 1e-5f);
    EXPECT_NEAR(dabs[1].center.y, 22.5f, 1e-5f);                     // 2 px into the second segment
    EXPECT_EQ(tracker.moveStroke({{13.5f, 34.5f}, 1.0f}, dabs), 1u); // leaves S at y = 30
    // The dab at y = 27.5 is on S; the one at 32.5 is on background and ignored.
    ASSERT_EQ(dabs.size(), 3u);
    EXPECT_NEAR(dabs[2].center.y, 27.5f, 1e-5f);
    tracker.endStroke();
    EXPECT_FALSE(tracker.inStroke());
    EXPECT_EQ(tracker.moveStroke({{50.5f, 20.5f}, 1.0f}, dabs), 0u);
}

TEST(StrokeTracker, NewLayersOfTheSameSizeKeepNothingOfTheLastOnes) {
    // A tracker keeps its mark arrays across views of one size: the marks of a stroke before
    // must neither show in the new layers' maps nor change the next stroke's dabs.
    const Scene s = strandUnderOccluder();
    const core::Brush brush = testBrush(10.0f);
    auto stroke = [&](StrokeTracker& tracker, StrokePoint from, StrokePoint to) {
        std::vector<Dab> dabs;
        tracker.startStroke(from, brush, dabs);
        tracker.moveStroke(to, dabs);
        tracker.completeTrackableMap();
        tracker.endStroke();
        return dabs;
    };
    StrokeTracker used;
    ASSERT_TRUE(used.setDepthLayers(s.stack, s.connectivity));
    ASSERT_GT(stroke(used, {{20.5f, 20.5f}, 1.0f}, {{130.5f, 20.5f}, 1.0f}).size(), 20u);
    ASSERT_NE(used.trackableLayer(125 + 20 * 300), 0u); // the last dab's maps
    ASSERT_TRUE(used.setDepthLayers(s.stack, s.connectivity));
    for (std::size_t p = 0; p < s.stack.pixelCount(); ++p) {
        ASSERT_EQ(used.paintableLayer(p), 0u) << "pixel " << p;
        ASSERT_EQ(used.trackableLayer(p), 0u) << "pixel " << p;
    }
    StrokeTracker fresh;
    ASSERT_TRUE(fresh.setDepthLayers(s.stack, s.connectivity));
    const std::vector<Dab> again = stroke(used, {{120.5f, 22.5f}, 1.0f}, {{40.5f, 18.5f}, 1.0f});
    const std::vector<Dab> first = stroke(fresh, {{120.5f, 22.5f}, 1.0f}, {{40.5f, 18.5f}, 1.0f});
    ASSERT_EQ(again.size(), first.size());
    for (std::size_t i = 0; i < first.size(); ++i) {
        EXPECT_EQ(again[i].layer, first[i].layer) << "dab " << i;
        ASSERT_EQ(again[i].paintable.size(), first[i].paintable.size()) << "dab " << i;
        for (std::size_t k = 0; k < first[i].paintable.size(); ++k)
            EXPECT_EQ(again[i].paintable[k].fragment, first[i].paintable[k].fragment)
                << "dab " << i;
    }
    for (std::size_t p = 0; p < s.stack.pixelCount(); ++p)
        ASSERT_EQ(used.trackableLayer(p), fresh.trackableLayer(p)) << "pixel " << p;
}

TEST(StrokeTracker, ConventionalModePaintsTheVisibleSurfaceOnly) {
    const Scene s = strandUnderOccluder();
    StrokeTracker tracker;
    ASSERT_TRUE(tracker.setDepthLayers(s.stack, s.connectivity));
    tracker.setLayerAware(false);
    std::vector<Dab> dabs;
    tracker.startStroke({{60.5f, 20.5f}, 1.0f}, testBrush(12.0f), dabs);
    tracker.moveStroke({{200.5f, 20.5f}, 1.0f}, dabs);
    ASSERT_GT(dabs.size(), 50u);
    bool paintedO = false;
    for (const Dab& d : dabs) {
        std::set<std::uint32_t> pixels;
        for (const core::MapPixel& m : d.paintable) {
            EXPECT_TRUE(pixels.insert(m.pixel).second);
            // Always the front-most fragment (layer 1): S where it is visible, O over S.
            EXPECT_EQ(m.fragment, s.stack.offsets[m.pixel]) << "dab at " << d.center.x;
            paintedO = paintedO || s.stack.triangle[m.fragment] == 1u;
        }
        EXPECT_EQ(d.layer, 1u);
        // Every visible pixel within the radius: a full disc (S is 20 px tall, O covers it).
        std::size_t inside = 0;
        for (int y = 0; y < s.stack.height; ++y)
            for (int x = 0; x < s.stack.width; ++x) {
                const glm::vec2 c(float(x) + 0.5f, float(y) + 0.5f);
                const bool visible = s.stack.layerCount(std::size_t(y) * 300 + std::size_t(x));
                inside += visible && glm::length(c - d.center) <= d.radius;
            }
        EXPECT_EQ(d.paintable.size(), inside) << "dab at " << d.center.x;
    }
    EXPECT_TRUE(paintedO);
}

TEST(StrokeTracker, ModeSwitchMidStroke) {
    const Scene s = strandUnderOccluder();
    StrokeTracker tracker;
    ASSERT_TRUE(tracker.setDepthLayers(s.stack, s.connectivity));
    std::vector<Dab> dabs;
    tracker.startStroke({{80.5f, 20.5f}, 1.0f}, testBrush(8.0f), dabs);
    tracker.moveStroke({{110.3f, 20.5f}, 1.0f}, dabs);
    ASSERT_EQ(dabs.back().layer, 2u); // tracked under O
    // Conventional from the next dab on: O, the visible surface, is painted.
    tracker.setLayerAware(false);
    dabs.clear();
    tracker.moveStroke({{120.3f, 20.5f}, 1.0f}, dabs);
    ASSERT_FALSE(dabs.empty());
    for (const Dab& d : dabs) {
        EXPECT_EQ(d.layer, 1u);
        for (const core::MapPixel& m : d.paintable)
            EXPECT_EQ(s.stack.triangle[m.fragment], 1u);
    }
    // Layer-aware again: tracking restarts on the visible surface under the next dab (O), as a
    // mouse-down there would; it stays on O and never jumps to S.
    tracker.setLayerAware(true);
    dabs.clear();
    tracker.moveStroke({{135.3f, 20.5f}, 1.0f}, dabs);
    tracker.moveStroke({{160.3f, 20.5f}, 1.0f}, dabs); // off O's right edge: nothing
    ASSERT_FALSE(dabs.empty());
    for (const Dab& d : dabs) {
        EXPECT_LT(d.center.x, 140.0f);
        EXPECT_EQ(d.layer, 1u);
        for (const core::MapPixel& m : d.paintable)
            EXPECT_EQ(s.stack.triangle[m.fragment], 1u);
    }
}

TEST(StrokeTracker, IgnoresPointsOffScreenNotFiniteOrWithoutLayers) {
    const Scene s = strandUnderOccluder();
    StrokeTracker tracker;
    std::vector<Dab> dabs;
    EXPECT_EQ(tracker.startStroke({{20.5f, 20.5f}, 1.0f}, testBrush(5.0f), dabs), 0u);
    EXPECT_EQ(tracker.paintableLayer(0), 0u);
    ASSERT_TRUE(tracker.setDepthLayers(s.stack, s.connectivity));
    EXPECT_EQ(tracker.startStroke({{-3.0f, 20.5f}, 1.0f}, testBrush(5.0f), dabs), 0u);
    EXPECT_EQ(tracker.startStroke({{NAN, 20.5f}, 1.0f}, testBrush(5.0f), dabs), 0u);
    EXPECT_FALSE(tracker.inStroke());
    EXPECT_EQ(tracker.startStroke({{20.5f, 20.5f}, NAN}, testBrush(5.0f), dabs), 1u);
    EXPECT_EQ(dabs.back().radius, 5.0f); // pressure NaN counts as 1
    EXPECT_EQ(tracker.moveStroke({{20.5f, INFINITY}, 1.0f}, dabs), 0u);
    EXPECT_EQ(tracker.moveStroke({{20.5f, 1e30f}, 1.0f}, dabs), 0u); // would never finish
    EXPECT_TRUE(tracker.inStroke());
    // Off screen: the dabs on the way paint S until it ends at y = 10, none beyond.
    dabs.clear();
    EXPECT_GT(tracker.moveStroke({{20.5f, -100.0f}, 1.0f}, dabs), 10u);
    for (const Dab& d : dabs)
        EXPECT_GE(d.center.y, 10.0f);
    EXPECT_EQ(tracker.moveStroke({{30.5f, -100.0f}, 1.0f}, dabs), 0u);
    EXPECT_TRUE(tracker.inStroke());
    // Brush settings out of range: a NaN radius paints nothing, NaN opacity counts as 0.
    core::Brush bad = testBrush(NAN);
    bad.opacity = NAN;
    dabs.clear();
    EXPECT_EQ(tracker.startStroke({{20.3f, 20.5f}, 1.0f}, bad, dabs), 1u);
    EXPECT_EQ(dabs.back().radius, 0.0f);
    EXPECT_EQ(dabs.back().opacity, 0.0f);
    EXPECT_TRUE(dabs.back().paintable.empty());
    EXPECT_EQ(tracker.moveStroke({{40.3f, 20.5f}, 1.0f}, dabs),
              40u); // 0.5 px spacing at least
                    // A connectivity of another stack is refused.
    core::Connectivity wrong = s.connectivity;
    wrong.links.pop_back();
    EXPECT_FALSE(tracker.setDepthLayers(s.stack, wrong));
    EXPECT_FALSE(tracker.inStroke());
    EXPECT_EQ(tracker.startStroke({{20.5f, 20.5f}, 1.0f}, testBrush(5.0f), dabs), 0u);
}

TEST(StrokeTracker, OverlayShowsMpRedAndTheRestOfMtBlue) {
    const Scene s = strandUnderOccluder();
    StrokeTracker tracker;
    ASSERT_TRUE(tracker.setDepthLayers(s.stack, s.connectivity));
    std::vector<Dab> dabs;
    core::Brush brush = testBrush(6.0f);
    brush.trackRadius = 30.0f;
    tracker.startStroke({{95.5f, 20.5f}, 1.0f}, brush, dabs);
    std::vector<std::uint8_t> rgba(4 * s.stack.pixelCount(), 7);
    EXPECT_FALSE(tracker.fillOverlay(std::span(rgba).first(rgba.size() - 4)));
    EXPECT_EQ(rgba[0], 7u);
    ASSERT_TRUE(tracker.fillOverlay(rgba, 100));
    std::size_t red = 0, blue = 0;
    for (std::size_t p = 0; p < s.stack.pixelCount(); ++p) {
        const std::uint8_t* px = &rgba[4 * p];
        const std::uint32_t mp = tracker.paintableLayer(p), mt = tracker.trackableLayer(p);
        if (mp) {
            EXPECT_EQ(mt, mp);
            EXPECT_EQ(std::vector<int>({px[0], px[1], px[2], px[3]}),
                      std::vector<int>({255, 0, 0, 100}));
            ++red;
        } else if (mt) {
            EXPECT_EQ(std::vector<int>({px[0], px[1], px[2], px[3]}),
                      std::vector<int>({0, 0, 255, 100}));
            ++blue;
        } else {
            EXPECT_EQ(px[3], 0u);
        }
    }
    EXPECT_EQ(red, dabs.back().paintable.size());
    EXPECT_EQ(red, tracker.paintablePixels().size());
    EXPECT_EQ(red + blue, tracker.trackablePixels().size());
    EXPECT_GT(blue, red);
    // Mt carries S's layer 2 under O (x >= 100) and never O itself.
    EXPECT_EQ(tracker.trackableLayer(20 * 300 + 110), 2u);
    EXPECT_EQ(tracker.trackableLayer(5 * 300 + 110), 0u);
}

TEST(StrokeTracker, VisibleFragmentByRankSkipsHiddenRegions) {
    core::DepthStack stack;
    stack.width = 2;
    stack.height = 1;
    stack.offsets = {0, 3, 3}; // pixel 0: three layers, pixel 1: background
    stack.depth = {1.0f, 2.0f, 3.0f};
    stack.triangle = {0, 0, 0};
    const std::vector<std::uint32_t> region = {0, 1, 2};
    EXPECT_EQ(core::visibleFragmentByRank(stack, region, std::vector<std::uint32_t>{0, 1, 2}, 0),
              0u);
    EXPECT_EQ(core::visibleFragmentByRank(stack, region, std::vector<std::uint32_t>{1, 2, 0}, 0),
              2u); // region 2 popped up
    EXPECT_EQ(
        core::visibleFragmentByRank(stack, region, std::vector<std::uint32_t>{kNone, 1, 0}, 0), 2u);
    EXPECT_EQ(
        core::visibleFragmentByRank(stack, region, std::vector<std::uint32_t>{kNone, 0, kNone}, 0),
        1u); // region 0 hidden
    EXPECT_EQ(core::visibleFragmentByRank(stack, region,
                                          std::vector<std::uint32_t>{kNone, kNone, kNone}, 0),
              kNone);
    EXPECT_EQ(core::visibleFragmentByRank(stack, region, std::vector<std::uint32_t>{0, 1, 2}, 1),
              kNone);
    EXPECT_EQ(core::visibleFragmentByRank(stack, region, std::vector<std::uint32_t>{0, 1, 2}, 9),
              kNone);
}

// ---------------------------------------------------------------------------------------------
// The CPU-captured trefoil.

glm::vec3 trefoilCentre(float t) { // the tube's centre line (core/builtin_models.cpp)
    return {std::sin(t) + 2.0f * std::sin(2.0f * t), std::cos(t) - 2.0f * std::cos(2.0f * t),
            -std::sin(3.0f * t)};
}

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;

/** The centre-line parameter of a triangle of makeTrefoil(segmentsPerStrip, radialSegments). */
float trefoilParameter(std::uint32_t triangle, int segmentsPerStrip, int radialSegments) {
    const std::uint32_t perStrip = std::uint32_t(segmentsPerStrip * radialSegments * 2);
    const std::uint32_t strip = triangle / perStrip;
    const std::uint32_t along = (triangle % perStrip) / std::uint32_t(radialSegments * 2);
    const float i = float(strip * std::uint32_t(segmentsPerStrip) + along) + 0.5f;
    return kTwoPi * i / float(3 * segmentsPerStrip);
}

float circularDistance(float a, float b) {
    const float d = std::fmod(std::fabs(a - b), kTwoPi);
    return std::min(d, kTwoPi - d);
}

struct TrefoilScene {
    int segmentsPerStrip = 0, radialSegments = 0;
    core::DepthLayers layers;
    float underT = 0.0f; // centre-line parameter of the strand passing under the crossing
    float overT = 0.0f;  // ... and of the strand passing over it
};

/**
 * The trefoil at width × height, and the crossing of the centre line nearest the image centre:
 * two parameters, far apart along the knot, projecting to the same pixel; underT is the deeper.
 */
TrefoilScene trefoilScene(int segmentsPerStrip, int radialSegments, int width, int height) {
    TrefoilScene s;
    s.segmentsPerStrip = segmentsPerStrip;
    s.radialSegments = radialSegments;
    const core::Mesh mesh = core::makeTrefoil(segmentsPerStrip, radialSegments);
    const core::MeshTopology topology = core::buildMeshTopology(mesh);
    const core::View view =
        core::Camera::fromOrbit(mesh.bounds(), 30.0f, 20.0f, 1.6f).view(width, height);
    core::CpuDepthCapturer capturer;
    capturer.setMesh(mesh);
    auto built = core::buildDepthLayers(capturer, mesh, topology, view, core::DepthLayerOptions{});
    EXPECT_TRUE(built.ok()) << built.error();
    if (!built.ok())
        return s;
    s.layers = std::move(built).value();
    constexpr int kSamples = 3000;
    std::vector<glm::vec3> p(kSamples);
    for (int i = 0; i < kSamples; ++i)
        p[std::size_t(i)] = view.project(trefoilCentre(kTwoPi * float(i) / kSamples));
    float best = 1e30f;
    const glm::vec2 middle(float(width) / 2.0f, float(height) / 2.0f);
    for (int i = 0; i < kSamples; ++i)
        for (int j = i + 1; j < kSamples; ++j) {
            const float ti = kTwoPi * float(i) / kSamples, tj = kTwoPi * float(j) / kSamples;
            if (circularDistance(ti, tj) < 1.0f ||
                glm::length(glm::vec2(p[std::size_t(i)]) - glm::vec2(p[std::size_t(j)])) > 1.0f)
                continue;
            const float fromMiddle = glm::length(glm::vec2(p[std::size_t(i)]) - middle);
            if (fromMiddle < best) {
                best = fromMiddle;
                const bool iUnder = p[std::size_t(i)].z > p[std::size_t(j)].z;
                s.underT = iUnder ? ti : tj;
                s.overT = iUnder ? tj : ti;
            }
        }
    EXPECT_LT(best, 1e30f) << "no crossing in view";
    return s;
}

TEST(StrokeTrefoil, LongStrokeFollowsTheStrandUnderACrossing) {
    const TrefoilScene s = trefoilScene(120, 32, 480, 320);
    ASSERT_GT(s.layers.stack.fragmentCount(), 0u);
    const core::DepthStack& stack = s.layers.stack;
    StrokeTracker tracker;
    ASSERT_TRUE(tracker.setDepthLayers(s.layers));
    // The stroke follows the under strand's centre line across the crossing, 1 px a move.
    const core::View& view = s.layers.view;
    std::vector<StrokePoint> path;
    std::vector<float> pathT; // centre-line parameter of each path point
    for (float dt = -0.5f; dt <= 0.5f; dt += 0.002f) {
        const glm::vec3 q = view.project(trefoilCentre(s.underT + dt));
        if (path.empty() || glm::length(glm::vec2(q) - path.back().position) >= 1.0f) {
            path.push_back({glm::vec2(q), 1.0f});
            pathT.push_back(s.underT + dt);
        }
    }
    ASSERT_GT(path.size(), 100u);
    std::vector<Dab> dabs;
    tracker.startStroke(path.front(), testBrush(8.0f), dabs);
    ASSERT_EQ(dabs.size(), 1u);
    EXPECT_EQ(dabs[0].layer, 1u); // the strand is in front before the crossing
    for (std::size_t i = 1; i < path.size(); ++i)
        tracker.moveStroke(path[i], dabs);
    ASSERT_GT(dabs.size(), 100u);

    // Dab layers along the stroke: 1, then 2 under the crossing, then 1 again.
    std::vector<std::uint32_t> runs;
    for (const Dab& d : dabs)
        if (runs.empty() || runs.back() != d.layer)
            runs.push_back(d.layer);
    EXPECT_EQ(runs, (std::vector<std::uint32_t>{1, 2, 1}));

    // Every painted triangle is on the stroked strand, near the dab along it (the visible ring
    // of an obliquely seen tube is some way off the centre line's projection, hence 0.5 rad),
    // and never on the strand passing over it (overT is at least 1 rad away along the knot).
    ASSERT_GT(circularDistance(s.overT, s.underT), 1.0f);
    std::size_t layer2Fragments = 0;
    float worst = 0.0f;
    for (const Dab& d : dabs) {
        std::size_t nearest = 0;
        for (std::size_t i = 1; i < path.size(); ++i)
            if (glm::length(path[i].position - d.center) <
                glm::length(path[nearest].position - d.center))
                nearest = i;
        for (const core::MapPixel& m : d.paintable) {
            const float t =
                trefoilParameter(stack.triangle[m.fragment], s.segmentsPerStrip, s.radialSegments);
            worst = std::max(worst, circularDistance(t, pathT[nearest]));
            EXPECT_LT(circularDistance(t, pathT[nearest]), 0.5f)
                << "dab at " << d.center.x << "," << d.center.y << " painted parameter " << t;
            EXPECT_GT(circularDistance(t, s.overT), 0.4f)
                << "dab at " << d.center.x << "," << d.center.y << " painted the over strand";
            layer2Fragments += m.fragment - stack.offsets[m.pixel] == 1;
        }
        // The dab's layer is that of its own node, the centre pixel's fragment in Mp.
        const std::size_t centre =
            std::size_t(d.center.y) * std::size_t(stack.width) + std::size_t(d.center.x);
        const auto it = std::find_if(d.paintable.begin(), d.paintable.end(),
                                     [&](const core::MapPixel& m) { return m.pixel == centre; });
        ASSERT_NE(it, d.paintable.end());
        EXPECT_EQ(it->fragment, stack.fragment(centre, d.layer));
    }
    EXPECT_GT(layer2Fragments, 0u);

    // The same stroke in the conventional mode paints the over strand at the crossing: what the
    // checks above rule out does happen without layer-aware tracking.
    tracker.setLayerAware(false);
    std::vector<Dab> conventional;
    tracker.startStroke(path.front(), testBrush(8.0f), conventional);
    for (std::size_t i = 1; i < path.size(); ++i)
        tracker.moveStroke(path[i], conventional);
    std::size_t overStrand = 0;
    for (const Dab& d : conventional)
        for (const core::MapPixel& m : d.paintable)
            overStrand += circularDistance(trefoilParameter(stack.triangle[m.fragment],
                                                            s.segmentsPerStrip, s.radialSegments),
                                           s.overT) < 0.4f;
    EXPECT_GT(overStrand, 100u);
    std::printf("[          ] %zu dabs, %zu layer-2 fragments painted, painted parameters within "
                "%.3f rad of the stroke\n",
                dabs.size(), layer2Fragments, worst);
}

} // namespace stroke_tracker_test
