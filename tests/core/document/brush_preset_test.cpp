// SPDX-License-Identifier: GPL-3.0-or-later
// Brush presets: JSON round trip of every starter preset, bad files named in the error, previews.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "core/document/brush_preset.h"
#include "core/paint/brush/brush_preview.h"

namespace brush_preset_test {

using nlohmann::json;

TEST(BrushPresetTest, StarterPresetsRoundTripThroughJson) {
    const std::vector<core::BrushPreset> presets = core::starterBrushPresets();
    ASSERT_GE(presets.size(), 8u);
    for (const core::BrushPreset& preset : presets) {
        const std::string text = core::brushPresetToJson(preset).dump();
        core::Result<core::BrushPreset> back = core::parseBrushPresetFile(text, "p.lpbrush", {});
        ASSERT_TRUE(back) << back.error();
        EXPECT_EQ(*back, preset) << preset.name;
    }
}

TEST(BrushPresetTest, StarterPresetsAreDistinctAndUseful) {
    const std::vector<core::BrushPreset> presets = core::starterBrushPresets();
    const auto find = [&](const std::string& name) {
        return std::find_if(presets.begin(), presets.end(),
                            [&](const core::BrushPreset& p) { return p.name == name; });
    };
    const auto metal = find("Metal Paint");
    ASSERT_NE(metal, presets.end());
    EXPECT_TRUE(metal->brush.paintMetallic);
    EXPECT_FLOAT_EQ(metal->brush.metallic, 1.0f);
    EXPECT_FLOAT_EQ(metal->brush.roughness, 0.3f);
    const auto matte = find("Rough Matte");
    ASSERT_NE(matte, presets.end());
    EXPECT_FLOAT_EQ(matte->brush.roughness, 0.9f);
    ASSERT_NE(find("Eraser Soft"), presets.end());
    EXPECT_TRUE(find("Eraser Soft")->brush.eraser);
    ASSERT_NE(find("Stabilized Liner"), presets.end());
    EXPECT_TRUE(find("Stabilized Liner")->brush.stabilizer);
    for (std::size_t i = 0; i < presets.size(); ++i)
        for (std::size_t k = i + 1; k < presets.size(); ++k)
            EXPECT_NE(presets[i].brush, presets[k].brush) << presets[i].name;
}

TEST(BrushPresetTest, BadFilesGiveOneErrorNamingTheFile) {
    const json good = core::brushPresetToJson(core::starterBrushPresets().front());
    json wrongFormat = good;
    wrongFormat["format"] = "something-else";
    json noName = good;
    noName.erase("name");
    json badRadius = good;
    badRadius["brush"]["radius"] = -3;
    json badTip = good;
    badTip["brush"]["tip"] = "/nonexistent/tip.png";
    for (const std::string& text :
         {std::string("{ not json"), std::string("[1, 2]"), wrongFormat.dump(), noName.dump(),
          badRadius.dump(), badTip.dump()}) {
        core::Result<core::BrushPreset> r = core::parseBrushPresetFile(text, "bad.lpbrush", {});
        ASSERT_FALSE(r) << text;
        EXPECT_EQ(r.error().rfind("bad.lpbrush: ", 0), 0u) << r.error();
        EXPECT_EQ(r.error().find('\n'), std::string::npos) << r.error();
    }
    json radius = good;
    radius["brush"]["radius"] = -3;
    core::Result<core::BrushPreset> r = core::parseBrushPresetFile(radius.dump(), "x.lpbrush", {});
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().find("radius"), std::string::npos) << r.error();
}

TEST(BrushPresetTest, MissingKeysKeepTheDefaultBrush) {
    const json minimal = {
        {"format", "layerpaint-brush"}, {"name", "Tiny"}, {"brush", {{"radius", 3}}}};
    core::Result<core::BrushPreset> r = core::brushPresetFromJson(minimal, {});
    ASSERT_TRUE(r) << r.error();
    core::Brush expected;
    expected.radius = 3.0f;
    EXPECT_EQ(r->brush, expected);
    EXPECT_EQ(r->name, "Tiny");
}

TEST(BrushPresetTest, PreviewsShowTheBrushShape) {
    const std::vector<core::BrushPreset> presets = core::starterBrushPresets();
    std::vector<std::vector<std::uint8_t>> previews;
    for (const core::BrushPreset& preset : presets) {
        std::vector<std::uint8_t> image = core::renderBrushPreview(preset.brush, 96, 48);
        ASSERT_EQ(image.size(), 96u * 48u);
        const auto painted =
            std::count_if(image.begin(), image.end(), [](auto v) { return v > 0; });
        // A stroke, not a blank and not a filled box.
        EXPECT_GT(painted, 96 * 48 / 20) << preset.name;
        EXPECT_LT(painted, 96 * 48 * 9 / 10) << preset.name;
        previews.push_back(std::move(image));
    }
    // The hard ink is sharper than the soft round: more of its painted pixels are full.
    const auto full = [](const std::vector<std::uint8_t>& image) {
        const auto painted =
            std::count_if(image.begin(), image.end(), [](auto v) { return v > 0; });
        const auto solid =
            std::count_if(image.begin(), image.end(), [](auto v) { return v > 240; });
        return double(solid) / double(painted);
    };
    EXPECT_GT(full(previews[1]), full(previews[0]) + 0.2);
    // The same brush draws the same preview (the jitter comes from its seed).
    EXPECT_EQ(core::renderBrushPreview(presets[3].brush, 96, 48), previews[3]);
}

} // namespace brush_preset_test
