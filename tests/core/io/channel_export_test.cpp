// SPDX-License-Identifier: GPL-3.0-or-later
// Exports of the material channels: glb with both textures, OBJ + MTL with map_Pr and map_Pm,
// and the texture formats with roughness and metallic images beside the base colour.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/base/color.h"
#include "core/io/export.h"
#include "core/io/mesh_io.h"
#include "core/model/builtin_models.h"
#include "tests/core/test_files.h"

namespace channel_export_test {

using core_test::readFile;
using core_test::TempDir;

core::Image gradient(int width, int height, int seed) {
    core::Image image{width, height, {}};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.rgba.insert(image.rgba.end(),
                              {std::uint8_t(x * 3 + seed), std::uint8_t(y * 5 + seed),
                               std::uint8_t((x ^ y) + seed), 255});
    return image;
}

struct Painted {
    core::Mesh mesh;
    core::MaterialChannels channels;
};

Painted painted() {
    Painted p;
    p.mesh = core::makeTrefoil(40, 8);
    EXPECT_TRUE(p.mesh.hasUvs());
    p.mesh.textures = {gradient(64, 48, 7)};
    p.mesh.materials[0].baseColorTexture = 0;
    p.channels.metallicRoughness = {gradient(64, 48, 90)};
    return p;
}

/** The decoded image at path (through the importer, as the app reads images). */
core::Image image(const std::string& path) {
    core::Result<core::Image> image = core::loadImageFile(path);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? *image : core::Image{};
}

void expectChannel(const core::Image& grey, const core::Image& mr, int component,
                   int tolerance = 0) {
    ASSERT_EQ(grey.width, mr.width);
    ASSERT_EQ(grey.height, mr.height);
    int worst = 0;
    for (std::size_t i = 0; i < grey.rgba.size(); i += 4)
        worst = std::max(worst, std::abs(int(grey.rgba[i]) - int(mr.rgba[i + component])));
    EXPECT_LE(worst, tolerance);
}

TEST(ChannelExport, GlbHasBothTextures) {
    TempDir dir;
    const Painted p = painted();
    const std::string path = dir.file("knot.glb");
    auto files = core::exportMaterial(path, core::ExportFormat::Glb, p.mesh, p.channels);
    ASSERT_TRUE(files.ok()) << files.error();
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, path)) << err;
    const auto& pbr = model.materials.at(0).pbrMetallicRoughness;
    ASSERT_GE(pbr.metallicRoughnessTexture.index, 0);
    const auto& mr = model.images.at(
        std::size_t(model.textures.at(std::size_t(pbr.metallicRoughnessTexture.index)).source));
    EXPECT_TRUE(mr.image == p.channels.metallicRoughness[0].rgba);
    const auto& color = model.images.at(
        std::size_t(model.textures.at(std::size_t(pbr.baseColorTexture.index)).source));
    EXPECT_TRUE(color.image == p.mesh.textures[0].rgba);
    // Without channels the material stays as before: no metallic-roughness texture.
    ASSERT_TRUE(core::exportMesh(path, core::ExportFormat::Glb, p.mesh).ok());
    tinygltf::Model plain;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&plain, &err, &warn, path)) << err;
    EXPECT_LT(plain.materials.at(0).pbrMetallicRoughness.metallicRoughnessTexture.index, 0);
}

TEST(ChannelExport, ObjNamesRoughnessAndMetallicInTheMtl) {
    TempDir dir;
    const Painted p = painted();
    const std::string path = dir.file("knot.obj");
    auto files = core::exportMaterial(path, core::ExportFormat::Obj, p.mesh, p.channels);
    ASSERT_TRUE(files.ok()) << files.error();
    EXPECT_EQ(*files, (std::vector<std::string>{
                          dir.file("knot_1.png"), dir.file("knot_1_roughness.png"),
                          dir.file("knot_1_metallic.png"), dir.file("knot.mtl"), path}));
    const std::string mtl = readFile(dir.file("knot.mtl"));
    EXPECT_NE(mtl.find("map_Kd knot_1.png\n"), std::string::npos) << mtl;
    EXPECT_NE(mtl.find("map_Pr knot_1_roughness.png\n"), std::string::npos) << mtl;
    EXPECT_NE(mtl.find("map_Pm knot_1_metallic.png\n"), std::string::npos) << mtl;
    expectChannel(image(dir.file("knot_1_roughness.png")), p.channels.metallicRoughness[0], 1);
    expectChannel(image(dir.file("knot_1_metallic.png")), p.channels.metallicRoughness[0], 2);
    // The model still loads, with the same base colour texture as without the channels.
    core::Result<core::Mesh> back = core::loadMesh(path);
    ASSERT_TRUE(back.ok()) << back.error();
    const std::string plainPath = dir.file("plain.obj");
    ASSERT_TRUE(core::exportMesh(plainPath, core::ExportFormat::Obj, p.mesh).ok());
    core::Result<core::Mesh> plain = core::loadMesh(plainPath);
    ASSERT_TRUE(plain.ok()) << plain.error();
    // The base colour first, then the roughness and metallic read back as one texture.
    ASSERT_EQ(back->textures.size(), 2u);
    ASSERT_EQ(plain->textures.size(), 1u);
    EXPECT_TRUE(
        std::any_of(back->materials.begin(), back->materials.end(),
                    [](const core::Material& m) { return m.metallicRoughness.texture == 1; }));
    EXPECT_TRUE(back->textures[0].rgba == plain->textures[0].rgba);
}

TEST(ChannelExport, TextureFormatsWriteAnImagePerChannel) {
    TempDir dir;
    const Painted p = painted();
    for (const auto& [format, ext, tolerance] :
         {std::tuple{core::ExportFormat::Png8, ".png", 0}, {core::ExportFormat::Tiff, ".tif", 0}}) {
        const std::string path = dir.file(std::string("paint") + ext);
        auto files = core::exportChannelTextures(path, format, p.mesh.textures,
                                                 p.channels.metallicRoughness);
        ASSERT_TRUE(files.ok()) << files.error();
        const std::string rough = dir.file(std::string("paint_roughness") + ext);
        const std::string metal = dir.file(std::string("paint_metallic") + ext);
        EXPECT_EQ(*files, (std::vector<std::string>{path, rough, metal}));
        EXPECT_EQ(image(path).width, p.mesh.textures[0].width);
        expectChannel(image(rough), p.channels.metallicRoughness[0], 1, tolerance);
        expectChannel(image(metal), p.channels.metallicRoughness[0], 2, tolerance);
    }
    // EXR holds the linear values: read back (as sRGB bytes) they are the values re-encoded.
    const std::string exr = dir.file("paint.exr");
    auto files = core::exportChannelTextures(exr, core::ExportFormat::Exr, p.mesh.textures,
                                             p.channels.metallicRoughness);
    ASSERT_TRUE(files.ok()) << files.error();
    ASSERT_EQ(files->size(), 3u);
    EXPECT_EQ((*files)[1], dir.file("paint_roughness.exr"));
    // A model without channels writes the base colour only.
    auto plain = core::exportChannelTextures(dir.file("plain.png"), core::ExportFormat::Png8,
                                             p.mesh.textures, {});
    ASSERT_TRUE(plain.ok());
    EXPECT_EQ(plain->size(), 1u);
}

} // namespace channel_export_test
