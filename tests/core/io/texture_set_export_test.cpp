// SPDX-License-Identifier: GPL-3.0-or-later
// Texture export presets: each packed component read back from the written files and compared
// with the channel it came from, the names from the template, padding and resampling, and preset
// files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "core/io/mesh_io.h"
#include "core/io/texture_sets/texture_set_export.h"
#include "tests/core/test_files.h"

namespace texture_set_export_test {

using core::MapFileFormat;
using core::SetChannel;
using core_test::TempDir;

constexpr int kSize = 32;

core::Image pattern(int width, int height, int seed) {
    core::Image image{width, height, {}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.rgba.insert(image.rgba.end(),
                              {std::uint8_t(x * 7 + seed), std::uint8_t(y * 5 + 2 * seed),
                               std::uint8_t((x * y + seed) & 255), std::uint8_t(200 + (x & 7))});
    return image;
}

/** One quad per material over the left half of its texture (the right half is empty). */
void addQuad(core::Mesh& mesh, float x0, std::uint32_t material) {
    const auto base = std::uint32_t(mesh.positions.size());
    const glm::vec2 uv[4] = {{0.0f, 0.0f}, {0.5f, 0.0f}, {0.5f, 1.0f}, {0.0f, 1.0f}};
    for (int k = 0; k < 4; ++k) {
        mesh.positions.push_back({x0 + uv[k].x * 2.0f, uv[k].y, 0.0f});
        mesh.normals.push_back({0.0f, 0.0f, 1.0f});
        mesh.uvs.push_back(uv[k]);
    }
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    mesh.triangleMaterial.insert(mesh.triangleMaterial.end(), {material, material});
}

/**
 * Two texture sets: "Metal" with every map (metallic-roughness, normal at scale 1, occlusion at
 * strength 0.5, emissive) and factors, "Plain" with factors only.
 */
core::Mesh twoSets() {
    core::Mesh mesh;
    addQuad(mesh, 0.0f, 0);
    addQuad(mesh, 2.0f, 1);
    mesh.textures = {pattern(kSize, kSize, 3),  pattern(kSize, kSize, 40),
                     pattern(kSize, kSize, 90), pattern(kSize, kSize, 11),
                     pattern(kSize, kSize, 60), pattern(kSize / 2, kSize / 2, 5)};
    core::Material metal;
    metal.name = "Metal";
    metal.baseColorTexture = 0;
    metal.metallicFactor = 0.8f;
    metal.roughnessFactor = 0.5f;
    metal.metallicRoughness.texture = 1;
    metal.normal.texture = 2;
    metal.occlusion.texture = 3;
    metal.occlusionStrength = 0.5f;
    metal.emissive.texture = 4;
    metal.emissiveFactor = glm::vec3(1.0f);
    core::Material plain;
    plain.name = "Plain";
    plain.baseColorTexture = 5;
    plain.metallicFactor = 0.25f;
    plain.roughnessFactor = 0.75f;
    mesh.materials = {metal, plain};
    return mesh;
}

core::Image read(const std::string& path) {
    core::Result<core::Image> image = core::loadImageFile(path);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? *image : core::Image{};
}

std::uint8_t byteOf(double v) {
    return std::uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

const std::uint8_t* texel(const core::Image& image, int x, int y) {
    return &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
}

/** Exports mesh through the built-in preset id (padding as given) into dir; the files. */
std::vector<std::string> exportAs(const core::Mesh& mesh, const std::string& id, const TempDir& dir,
                                  int padding = 0) {
    core::TextureExportOptions options{*core::builtinPreset(id), "model", 0};
    options.preset.padding = padding;
    core::Result<std::vector<std::string>> files =
        core::exportTextureSets(dir.path().string(), mesh, options);
    EXPECT_TRUE(files.ok()) << files.error();
    return files.ok() ? *files : std::vector<std::string>{};
}

// Texels (x, y) with x < kSize / 2 - 1 lie under the Metal quad (left half of the texture).
constexpr int kCoveredColumns = kSize / 2 - 1;

TEST(TextureSetExport, EveryBuiltInPresetWritesTheNamesOfItsTemplate) {
    const core::Mesh mesh = twoSets();
    for (const core::ExportPreset& preset : core::builtinPresets()) {
        TempDir dir;
        const std::vector<std::string> files = exportAs(mesh, preset.id, dir);
        ASSERT_EQ(files.size(), 2 * preset.maps.size()) << preset.id;
        std::size_t k = 0;
        for (const char* set : {"Metal", "Plain"})
            for (const core::PresetMap& map : preset.maps) {
                const std::string expected = std::string("model_") + set + "_" + map.name + ".png";
                EXPECT_EQ(std::filesystem::path(files[k++]).filename().string(), expected);
                EXPECT_TRUE(std::filesystem::exists(dir.file(expected))) << expected;
            }
    }
}

TEST(TextureSetExport, OcclusionRoughnessMetallicHoldsEachChannel) {
    const core::Mesh mesh = twoSets();
    TempDir dir;
    exportAs(mesh, "gltf", dir);
    const core::Image orm = read(dir.file("model_Metal_OcclusionRoughnessMetallic.png"));
    const core::Image base = read(dir.file("model_Metal_BaseColor.png"));
    const core::Image& mr = mesh.textures[1];
    const core::Image& occlusion = mesh.textures[3];
    ASSERT_EQ(orm.width, kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kCoveredColumns; ++x) {
            const std::uint8_t* o = texel(orm, x, y);
            EXPECT_EQ(o[0], byteOf(1.0 + 0.5 * (texel(occlusion, x, y)[0] / 255.0 - 1.0)));
            EXPECT_EQ(o[1], byteOf(0.5 * texel(mr, x, y)[1] / 255.0));
            EXPECT_EQ(o[2], byteOf(0.8 * texel(mr, x, y)[2] / 255.0));
            // Base colour and its alpha byte for byte.
            for (int k = 0; k < 4; ++k)
                ASSERT_EQ(texel(base, x, y)[k], texel(mesh.textures[0], x, y)[k]) << x << "," << y;
        }
    // The set without maps: its factors everywhere under its quad, occlusion white.
    const core::Image plain = read(dir.file("model_Plain_OcclusionRoughnessMetallic.png"));
    EXPECT_EQ(texel(plain, 2, 3)[0], 255);
    EXPECT_EQ(texel(plain, 2, 3)[1], byteOf(0.75));
    EXPECT_EQ(texel(plain, 2, 3)[2], byteOf(0.25));
}

TEST(TextureSetExport, UnityMaskMapHoldsSmoothnessAndUnrealNormalsAreDirectX) {
    const core::Mesh mesh = twoSets();
    TempDir unity, unreal, gltf;
    exportAs(mesh, "unity", unity);
    exportAs(mesh, "unreal", unreal);
    exportAs(mesh, "gltf", gltf);
    const core::Image mask = read(unity.file("model_Metal_MaskMap.png"));
    const core::Image orm = read(gltf.file("model_Metal_OcclusionRoughnessMetallic.png"));
    const core::Image directX = read(unreal.file("model_Metal_Normal.png"));
    const core::Image openGl = read(gltf.file("model_Metal_Normal.png"));
    const core::Image& normal = mesh.textures[2];
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kCoveredColumns; ++x) {
            const std::uint8_t* m = texel(mask, x, y);
            const std::uint8_t* o = texel(orm, x, y);
            EXPECT_EQ(m[0], o[2]);                                       // metallic
            EXPECT_EQ(m[1], o[0]);                                       // occlusion
            EXPECT_EQ(m[2], 255);                                        // detail mask
            EXPECT_NEAR(int(m[3]), 255 - int(o[1]), 1) << x << "," << y; // smoothness
            EXPECT_EQ(texel(openGl, x, y)[1], texel(normal, x, y)[1]);
            EXPECT_EQ(texel(directX, x, y)[1], 255 - texel(normal, x, y)[1]);
            EXPECT_EQ(texel(directX, x, y)[0], texel(normal, x, y)[0]);
            EXPECT_EQ(texel(directX, x, y)[2], texel(normal, x, y)[2]);
        }
}

TEST(TextureSetExport, PaddingFillsItsDistanceAndLeavesTheChartsAlone) {
    const core::Mesh mesh = twoSets();
    TempDir none, four, fill;
    exportAs(mesh, "orm", none, 0);
    exportAs(mesh, "orm", four, 4);
    exportAs(mesh, "orm", fill, core::kPadToFill);
    const core::Image bare = read(none.file("model_Plain_ORM.png"));
    const core::Image padded = read(four.file("model_Plain_ORM.png"));
    const core::Image filled = read(fill.file("model_Plain_ORM.png"));
    // The Plain quad covers the texels of x < 8 of its 16 × 16 texture.
    const int w = kSize / 2, covered = w / 2;
    for (int y = 0; y < w; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* b = texel(bare, x, y);
            const std::uint8_t* p = texel(padded, x, y);
            const std::uint8_t* f = texel(filled, x, y);
            if (x < covered) {
                for (int k = 0; k < 3; ++k) {
                    ASSERT_EQ(p[k], b[k]);
                    ASSERT_EQ(f[k], b[k]);
                }
                continue;
            }
            EXPECT_EQ(b[0], 0) << "no padding leaves the background";
            EXPECT_EQ(f[0], 255) << "fill reaches every texel";
            if (x < covered + 4)
                EXPECT_EQ(p[1], byteOf(0.75)) << x << "," << y << " is within the padding";
            else
                EXPECT_EQ(p[1], 0) << x << "," << y << " is beyond the padding";
        }
}

TEST(TextureSetExport, ResamplingToAChosenSizeAveragesTheTexels) {
    core::PackedMap map{4, 2, 1, {0, 65535, 1000, 3000, 10, 20, 30, 40}};
    const core::PackedMap half = core::resampleMap(map, 2, 1);
    ASSERT_EQ(half.values.size(), 2u);
    EXPECT_EQ(half.values[0], (0 + 65535 + 10 + 20 + 2) / 4);
    EXPECT_EQ(half.values[1], 1018); // (1000 + 3000 + 30 + 40) / 4, rounded
    const core::PackedMap twice = core::resampleMap(map, 8, 4);
    EXPECT_EQ(twice.width, 8);
    EXPECT_EQ(twice.values[0], 0) << "the corner keeps its texel";
    // Through the export: the longer side becomes the size asked for.
    TempDir dir;
    core::TextureExportOptions options{*core::builtinPreset("orm"), "model", 8};
    ASSERT_TRUE(core::exportTextureSets(dir.path().string(), twoSets(), options).ok());
    EXPECT_EQ(read(dir.file("model_Metal_ORM.png")).width, 8);
    EXPECT_EQ(read(dir.file("model_Plain_ORM.png")).height, 8);
}

TEST(TextureSetExport, APresetFileMapsChannelsToComponents) {
    const std::string json = R"({
      "name": "Mine", "fileName": "$textureSet-$channel", "normal": "directx",
      "format": "tga", "padding": 8,
      "maps": [
        {"name": "Color", "rgb": "baseColor", "a": "opacity"},
        {"name": "RMA", "r": "roughness", "g": "metallic", "b": "occlusion", "a": 0.5},
        {"name": "Gloss", "grey": "smoothness"},
        {"name": "NormalY", "grey": "normal.g"}
      ]})";
    core::Result<core::ExportPreset> preset = core::parsePreset(json, "mine.json");
    ASSERT_TRUE(preset.ok()) << preset.error();
    EXPECT_EQ(preset->format, MapFileFormat::Tga);
    EXPECT_EQ(preset->padding, 8);
    ASSERT_EQ(preset->maps.size(), 4u);
    EXPECT_EQ(preset->maps[1].components.size(), 4u);
    EXPECT_EQ(preset->maps[1].components[3].constant, 0.5f);
    EXPECT_TRUE(preset->maps[2].components[0].inverted);
    EXPECT_EQ(preset->maps[3].components[0].component, 1);
    // Written and read again, it is the same preset.
    core::Result<core::ExportPreset> again = core::parsePreset(core::presetJson(*preset), "again");
    ASSERT_TRUE(again.ok()) << again.error();
    EXPECT_EQ(*again, *preset);
    for (const core::ExportPreset& builtin : core::builtinPresets()) {
        core::Result<core::ExportPreset> copy = core::parsePreset(core::presetJson(builtin), "b");
        ASSERT_TRUE(copy.ok()) << copy.error();
        copy->id = builtin.id;
        EXPECT_EQ(*copy, builtin);
    }
    TempDir dir;
    core::TextureExportOptions options{*preset, "model", 0};
    core::Result<std::vector<std::string>> files =
        core::exportTextureSets(dir.path().string(), twoSets(), options);
    ASSERT_TRUE(files.ok()) << files.error();
    const core::Image y = read(dir.file("Metal-NormalY.tga"));
    const core::Mesh mesh = twoSets();
    EXPECT_EQ(texel(y, 3, 4)[0], 255 - texel(mesh.textures[2], 3, 4)[1]);
}

TEST(TextureSetExport, BadPresetsAreRefusedWithTheReason) {
    const auto error = [](const std::string& json) {
        core::Result<core::ExportPreset> p = core::parsePreset(json, "bad.json");
        return p.ok() ? std::string() : p.error();
    };
    EXPECT_NE(error(R"({"maps": [{"name": "A", "grey": "shininess"}]})").find("unknown channel"),
              std::string::npos);
    EXPECT_NE(error(R"({"maps": [{"name": "A", "r": "roughness", "rgb": "normal"}]})")
                  .find("given twice"),
              std::string::npos);
    EXPECT_NE(error(R"({"fileName": "$mesh", "maps": [{"name": "A", "grey": "roughness"},
                       {"name": "B", "grey": "metallic"}]})")
                  .find("$channel"),
              std::string::npos);
    EXPECT_NE(error(R"({"format": "tga", "bitDepth": 16, "maps": [{"name": "A", "grey": 1}]})")
                  .find("cannot hold"),
              std::string::npos);
    EXPECT_NE(error(R"({"fileName": "../$channel", "maps": [{"name": "A", "grey": 1}]})")
                  .find("path separators"),
              std::string::npos);
    EXPECT_NE(error(R"({"maps": [{"name": "A", "grey": "baseColor"}]})").find("baseColor.r"),
              std::string::npos);
    EXPECT_NE(error("[1, 2]").find("bad.json: not a JSON object"), std::string::npos);
    EXPECT_NE(core::expandFileName("$mesh_$what", "m", "s", "c").error().find("$what"),
              std::string::npos);
    core::Result<core::ExportPreset> missing = core::findPreset("no-such-preset");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().find("gltf, unreal, unity, orm"), std::string::npos);
}

TEST(TextureSetExport, AModelWithoutATextureSetSaysSo) {
    core::Mesh mesh = twoSets();
    for (core::Material& m : mesh.materials)
        m.baseColorTexture = -1;
    TempDir dir;
    core::TextureExportOptions options{*core::builtinPreset("gltf"), "model", 0};
    core::Result<std::vector<std::string>> files =
        core::exportTextureSets(dir.path().string(), mesh, options);
    ASSERT_FALSE(files.ok());
    EXPECT_NE(files.error().find("vertex colours"), std::string::npos);
}

} // namespace texture_set_export_test
