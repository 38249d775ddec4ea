// SPDX-License-Identifier: GPL-3.0-or-later
// The whole glTF material through load, painting, project and export: every factor and map of
// tests/data/material/materials.glb (scripts/make-material-test-data.py) is loaded, the roughness
// and metallic channels start from the metallic-roughness map, and after a stroke, a save, a
// reopen and a glb export every map is still there, the unpainted ones as the source's very
// files, with the factors unchanged. A real file of Debian's assimp-testmodels (normal maps in
// PNG and JPEG, an emissive map) loads with its maps. The Khronos validator, when installed,
// checks the written files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/depth/cpu_capture.h"
#include "core/document/document.h"
#include "core/document/project_state.h"
#include "core/io/export.h"
#include "core/io/gltf/gltf_texture_transform.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/paint/targets/paint_target.h"
#include "tests/core/test_files.h"

namespace material_test {

using core_test::readFile;
using core_test::TempDir;
using Bytes = std::vector<std::uint8_t>;

const std::string kMaterials = std::string(LAYERPAINT_TEST_DATA) + "/material/materials.glb";
const std::string kClearCoat =
    std::string(LAYERPAINT_ASSIMP_MODELS) + "/glTF2/ClearCoat-glTF/ClearCoatTest.gltf";

constexpr int kWidth = 320, kHeight = 240;

/** A binary glTF as tinygltf reads it, and each image's file bytes. */
struct Glb {
    tinygltf::Model model;
    std::vector<Bytes> files; // per image

    /** The file of texture t's image. */
    const Bytes& textureFile(int t) const {
        return files.at(std::size_t(model.textures.at(std::size_t(t)).source));
    }
};

Glb readGlb(const std::string& path) {
    Glb glb;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&glb.model, &err, &warn, path)) << err;
    for (const tinygltf::Image& image : glb.model.images) {
        const tinygltf::BufferView& view = glb.model.bufferViews.at(std::size_t(image.bufferView));
        const auto* data = glb.model.buffers.at(0).data.data() + view.byteOffset;
        glb.files.emplace_back(data, data + view.byteLength);
    }
    return glb;
}

/** Runs the Khronos validator on path; skipped when it is not installed. */
void expectValidGltf(const std::string& path) {
    const std::string script = std::string(LAYERPAINT_TEST_DATA) + "/../tools/validate-gltf.cjs";
    const std::string command = "NODE_PATH=\"$(npm root -g 2>/dev/null)\" node '" + script + "' '" +
                                path + "' > /dev/null 2>&1";
    const int status = std::system(command.c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (code == 3 || code == 127) {
        std::cout << "[  SKIPPED ] the glTF validator is not installed (npm install -g "
                     "gltf-validator); "
                  << path << " not validated\n";
        return;
    }
    EXPECT_EQ(code, 0) << path << " fails the Khronos glTF validator: run node " << script << " "
                       << path;
}

void expectMap(const core::Mesh& mesh, const core::MaterialMap& map, int width, int height) {
    ASSERT_GE(map.texture, 0);
    const core::Image& image = mesh.textures.at(std::size_t(map.texture));
    EXPECT_EQ(image.width, width);
    EXPECT_EQ(image.height, height);
}

/** Material 0's normal map placement: KHR_texture_transform offset (0.5, 0.25), scale 2. */
glm::mat3 normalPlacement() {
    glm::mat3 m(2.0f);
    m[2] = glm::vec3(0.5f, 0.25f, 1.0f);
    return m;
}

TEST(Material, GltfLoadGivesEveryFieldOfBothMaterials) {
    core::Result<core::Mesh> loaded = core::loadMesh(kMaterials);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    const core::Mesh& mesh = *loaded;
    EXPECT_TRUE(mesh.warnings.empty()) << mesh.warnings.front();
    ASSERT_EQ(mesh.materials.size(), 2u);
    ASSERT_EQ(mesh.textures.size(), 10u);
    ASSERT_EQ(mesh.textureSources.size(), 10u);

    const core::Material& a = mesh.materials[0];
    EXPECT_EQ(a.name, "painted");
    EXPECT_EQ(a.baseColorTexture, 0); // the base colour textures come first
    EXPECT_FLOAT_EQ(a.metallicFactor, 0.25f);
    EXPECT_FLOAT_EQ(a.roughnessFactor, 0.75f);
    EXPECT_FLOAT_EQ(a.normalScale, 0.8f);
    EXPECT_FLOAT_EQ(a.occlusionStrength, 0.6f);
    EXPECT_EQ(a.emissiveFactor, glm::vec3(0.5f, 0.25f, 1.0f));
    EXPECT_FLOAT_EQ(a.emissiveStrength, 2.5f);
    EXPECT_EQ(a.alphaMode, core::AlphaMode::Opaque);
    EXPECT_TRUE(a.doubleSided);
    expectMap(mesh, a.metallicRoughness, 8, 8);
    expectMap(mesh, a.normal, 4, 4);
    expectMap(mesh, a.occlusion, 4, 8);
    expectMap(mesh, a.emissive, 8, 4);
    EXPECT_EQ(a.normal.uvTransform, normalPlacement());
    EXPECT_EQ(a.occlusion.uvTransform, glm::mat3(1.0f));

    const core::Material& b = mesh.materials[1];
    EXPECT_EQ(b.name, "masked");
    EXPECT_EQ(b.baseColorTexture, 1);
    EXPECT_FLOAT_EQ(b.metallicFactor, 0.9f);
    EXPECT_FLOAT_EQ(b.roughnessFactor, 0.2f);
    EXPECT_FLOAT_EQ(b.normalScale, 1.0f);
    EXPECT_FLOAT_EQ(b.occlusionStrength, 1.0f);
    EXPECT_EQ(b.emissiveFactor, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_FLOAT_EQ(b.emissiveStrength, 1.0f);
    EXPECT_EQ(b.alphaMode, core::AlphaMode::Mask);
    EXPECT_FLOAT_EQ(b.alphaCutoff, 0.3f);
    EXPECT_FALSE(b.doubleSided);
    for (const core::MaterialMap* map :
         {&b.metallicRoughness, &b.normal, &b.occlusion, &b.emissive})
        EXPECT_EQ(map->uvTransform, glm::mat3(1.0f));

    // Ten different images, each kept as its file and decoded as stored (no colour conversion:
    // tinygltf's decoder gives the same bytes).
    const Glb source = readGlb(kMaterials);
    const int sourceTexture[2][5] = {{0, 1, 2, 3, 4}, {5, 6, 7, 8, 9}};
    for (int m = 0; m < 2; ++m) {
        const core::Material& mat = mesh.materials[std::size_t(m)];
        const int ours[5] = {mat.baseColorTexture, mat.metallicRoughness.texture,
                             mat.normal.texture, mat.occlusion.texture, mat.emissive.texture};
        for (int k = 0; k < 5; ++k) {
            const auto t = std::size_t(ours[k]);
            const int theirs = sourceTexture[m][k];
            EXPECT_EQ(mesh.textureSources[t].mimeType, "image/png");
            EXPECT_TRUE(mesh.textureSources[t].bytes == source.textureFile(theirs))
                << "material " << m << " map " << k;
            const tinygltf::Image& decoded = source.model.images.at(std::size_t(theirs));
            EXPECT_TRUE(mesh.textures[t].rgba == decoded.image) << "material " << m << " map " << k;
        }
    }
}

TEST(Material, MapsArePlacedRelativeToTheBaseColourAndOtherSetsWarn) {
    using core::detail::gltf::MapSlot;
    const nlohmann::json root = nlohmann::json::parse(R"({"materials": [
        {"name": "rock",
         "pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions":
             {"KHR_texture_transform": {"scale": [2, 2]}}}},
         "normalTexture": {"index": 1, "extensions":
             {"KHR_texture_transform": {"scale": [4, 4], "offset": [1, 0]}}},
         "occlusionTexture": {"index": 2, "texCoord": 1}},
        {"emissiveTexture": {"index": 3, "texCoord": 1, "extensions":
             {"KHR_texture_transform": {"offset": [0.5, 0.5]}}}}]})");
    core::Result<core::detail::gltf::MaterialTransforms> read =
        core::detail::gltf::readMaterialTransforms(root);
    ASSERT_TRUE(read.ok()) << read.error();
    // The mesh's UVs take the base colour's placement; the normal map's is relative to it.
    EXPECT_EQ(read->transforms[0].matrix, glm::dmat3(2, 0, 0, 0, 2, 0, 0, 0, 1));
    EXPECT_EQ(read->maps[0][std::size_t(MapSlot::Normal)], glm::mat3(2, 0, 0, 0, 2, 0, 1, 0, 1));
    EXPECT_EQ(read->maps[0][std::size_t(MapSlot::Occlusion)],
              glm::mat3(0.5f, 0, 0, 0, 0.5f, 0, 0, 0, 1));
    ASSERT_EQ(read->warnings.size(), 1u);
    EXPECT_EQ(read->warnings[0],
              "material \"rock\": its occlusion map uses TEXCOORD_1, which is not "
              "loaded; it is placed on TEXCOORD_0 instead");
    // Without a base colour the first map gives the UVs, set and placement.
    EXPECT_EQ(read->transforms[1].texCoord, 1);
    EXPECT_EQ(read->transforms[1].matrix, glm::dmat3(1, 0, 0, 0, 1, 0, 0.5, 0.5, 1));
    EXPECT_EQ(read->maps[1][std::size_t(MapSlot::Emissive)], glm::mat3(1.0f));
}

TEST(Material, RoughnessAndMetallicStartFromTheMapTimesTheFactors) {
    core::Result<core::Mesh> loaded = core::loadMesh(kMaterials);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    auto mesh = std::make_shared<const core::Mesh>(std::move(loaded).value());
    auto target = core::TextureTarget::create(mesh, nullptr);
    ASSERT_TRUE(target.ok()) << target.error();
    ASSERT_EQ((*target)->pageCount(), 2u);
    for (std::size_t m = 0; m < 2; ++m) {
        const core::Material& mat = mesh->materials[m];
        const core::Image& page = (*target)->metallicRoughnessPage(m);
        const core::Image& map = mesh->textures[std::size_t(mat.metallicRoughness.texture)];
        ASSERT_EQ(page.width, map.width); // the 8×8 base colour texture is the page
        ASSERT_EQ(page.rgba.size(), map.rgba.size());
        for (std::size_t i = 0; i < page.rgba.size(); i += 4) {
            const auto scaled = [](std::uint8_t v, float f) {
                return int(std::lround(float(v) / 255.0f * f * 255.0f));
            };
            EXPECT_NEAR(page.rgba[i + 1], scaled(map.rgba[i + 1], mat.roughnessFactor), 1) << i;
            EXPECT_NEAR(page.rgba[i + 2], scaled(map.rgba[i + 2], mat.metallicFactor), 1) << i;
        }
        EXPECT_FALSE((*target)->metallicRoughnessPainted(m));
    }
}

/** One horizontal stroke across the middle of the view (base colour only). */
void paintStroke(core::Document& doc) {
    doc.camera() = core::Camera::fromOrbit(doc.mesh().bounds(), 0.0f, 0.0f, 1.6f);
    core::CpuDepthCapturer capturer;
    capturer.setMesh(doc.mesh());
    ASSERT_TRUE(doc.buildDepthLayers(capturer, doc.camera().view(kWidth, kHeight)).ok());
    doc.brush().radius = 20.0f;
    doc.brush().color = glm::vec4(0.9f, 0.1f, 0.1f, 1.0f);
    const core::DepthStack& stack = doc.depthLayers()->stack;
    const int y = kHeight / 2;
    int first = -1, last = -1;
    for (int x = 0; x < kWidth; ++x)
        if (stack.layerCount(std::size_t(y) * kWidth + std::size_t(x)) > 0) {
            first = first < 0 ? x : first;
            last = x;
        }
    ASSERT_GT(last - first, 20) << "the quads are not in view";
    core::PaintChanges changes;
    ASSERT_TRUE(doc.beginStroke({{float(first) + 2.5f, float(y) + 0.5f}, 1.0f}, changes).ok());
    for (int x = first + 4; x < last - 2; x += 3)
        doc.moveStroke({{float(x) + 0.5f, float(y) + 0.5f}, 1.0f}, changes);
    doc.endStroke();
}

void expectSameMaterial(const tinygltf::Material& out, const tinygltf::Material& in) {
    const auto& po = out.pbrMetallicRoughness;
    const auto& pi = in.pbrMetallicRoughness;
    EXPECT_EQ(out.name, in.name);
    EXPECT_NEAR(po.metallicFactor, pi.metallicFactor, 1e-6);
    EXPECT_NEAR(po.roughnessFactor, pi.roughnessFactor, 1e-6);
    EXPECT_NEAR(out.normalTexture.scale, in.normalTexture.scale, 1e-6);
    EXPECT_NEAR(out.occlusionTexture.strength, in.occlusionTexture.strength, 1e-6);
    ASSERT_EQ(out.emissiveFactor.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_NEAR(out.emissiveFactor[k], in.emissiveFactor[k], 1e-6);
    EXPECT_EQ(out.alphaMode, in.alphaMode);
    EXPECT_NEAR(out.alphaCutoff, in.alphaCutoff, 1e-6);
    EXPECT_EQ(out.doubleSided, in.doubleSided);
    EXPECT_EQ(out.extensions.count("KHR_materials_emissive_strength"),
              in.extensions.count("KHR_materials_emissive_strength"));
    EXPECT_EQ(out.normalTexture.extensions.count("KHR_texture_transform"),
              in.normalTexture.extensions.count("KHR_texture_transform"));
}

TEST(Material, PaintSaveReopenAndExportKeepEveryMap) {
    core::Result<core::Mesh> loaded = core::loadMesh(kMaterials);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    core::Document doc;
    doc.setMesh(std::move(loaded).value(), kMaterials);
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::Texture;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    paintStroke(doc);

    TempDir dir;
    const std::string project = dir.file("project.glb");
    const core::ProjectState state = core::captureProjectState(doc);
    ASSERT_TRUE(core::saveProject(project, doc, state).ok());
    core::Result<core::Project> reopened = core::loadProject(project);
    ASSERT_TRUE(reopened.ok()) << reopened.error();
    ASSERT_TRUE(reopened->state.has_value());
    core::Document again;
    again.setMesh(std::move(reopened->mesh), project);
    const core::Status applied = core::applyProjectState(again, *reopened->state);
    ASSERT_TRUE(applied.ok()) << applied.error();
    const std::string exported = dir.file("exported.glb");
    auto files = core::exportMesh(exported, core::ExportFormat::Glb, again.paintedMesh());
    ASSERT_TRUE(files.ok()) << files.error();

    const Glb source = readGlb(kMaterials);
    const Glb saved = readGlb(project);
    const Glb out = readGlb(exported);
    bool painted = false;
    for (const Glb* written : {&saved, &out}) {
        ASSERT_EQ(written->model.materials.size(), 2u);
        for (std::size_t m = 0; m < 2; ++m) {
            SCOPED_TRACE("material " + std::to_string(m));
            const tinygltf::Material& in = source.model.materials[m];
            const tinygltf::Material& mat = written->model.materials[m];
            expectSameMaterial(mat, in);
            const auto& pbr = mat.pbrMetallicRoughness;
            ASSERT_GE(pbr.baseColorTexture.index, 0);
            ASSERT_GE(pbr.metallicRoughnessTexture.index, 0);
            ASSERT_GE(mat.normalTexture.index, 0);
            ASSERT_GE(mat.occlusionTexture.index, 0);
            ASSERT_GE(mat.emissiveTexture.index, 0);
            // Not painted: the source's very files.
            const auto same = [&](int ours, int theirs) {
                return written->textureFile(ours) == source.textureFile(theirs);
            };
            EXPECT_TRUE(same(pbr.metallicRoughnessTexture.index,
                             in.pbrMetallicRoughness.metallicRoughnessTexture.index));
            EXPECT_TRUE(same(mat.normalTexture.index, in.normalTexture.index));
            EXPECT_TRUE(same(mat.occlusionTexture.index, in.occlusionTexture.index));
            EXPECT_TRUE(same(mat.emissiveTexture.index, in.emissiveTexture.index));
            const auto& base = written->model.images.at(std::size_t(
                written->model.textures.at(std::size_t(pbr.baseColorTexture.index)).source));
            const auto& sourceBase = source.model.images.at(
                std::size_t(source.model.textures
                                .at(std::size_t(in.pbrMetallicRoughness.baseColorTexture.index))
                                .source));
            painted = painted || base.image != sourceBase.image;
        }
    }
    EXPECT_TRUE(painted) << "the stroke changed no base colour texture";
    expectValidGltf(project);
    expectValidGltf(exported);
}

TEST(Material, PaintedRoughnessIsSavedAsTheMapWithFactorsOne) {
    core::Result<core::Mesh> loaded = core::loadMesh(kMaterials);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    core::Document doc;
    doc.setMesh(std::move(loaded).value(), kMaterials);
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::Texture;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    // Roughness is painted into a paint layer (the base has the base colour only).
    core::PaintLayerSettings layer;
    layer.name = "rough";
    core::PaintChanges changes;
    ASSERT_TRUE(doc.addPaintLayer(layer, changes).ok());
    doc.brush().paintRoughness = true;
    doc.brush().roughness = 0.0f;
    paintStroke(doc);
    const core::Mesh painted = doc.paintedMesh();
    bool any = false;
    for (std::size_t m = 0; m < 2; ++m) {
        if (!doc.paintTarget()->metallicRoughnessPainted(m))
            continue;
        any = true;
        const core::Material& mat = painted.materials[m];
        EXPECT_EQ(mat.roughnessFactor, 1.0f);
        EXPECT_EQ(mat.metallicFactor, 1.0f);
        ASSERT_GE(mat.metallicRoughness.texture, 2); // after the two pages
        EXPECT_TRUE(painted.textures[std::size_t(mat.metallicRoughness.texture)].rgba ==
                    doc.paintTarget()->metallicRoughnessPage(m).rgba);
        EXPECT_EQ(painted.textureSource(mat.metallicRoughness.texture), nullptr);
    }
    EXPECT_TRUE(any) << "the stroke painted no roughness";

    // The view draws the same look beside the target's geometry, which it does not copy.
    const core::Mesh look = doc.paintTarget()->paintedLook();
    EXPECT_TRUE(look.positions.empty() && look.normals.empty() && look.indices.empty());
    ASSERT_EQ(look.materials.size(), painted.materials.size());
    for (std::size_t m = 0; m < look.materials.size(); ++m) {
        EXPECT_EQ(look.materials[m].baseColorTexture, painted.materials[m].baseColorTexture);
        EXPECT_EQ(look.materials[m].metallicRoughness.texture,
                  painted.materials[m].metallicRoughness.texture);
        EXPECT_EQ(look.materials[m].roughnessFactor, painted.materials[m].roughnessFactor);
    }
    ASSERT_EQ(look.textures.size(), painted.textures.size());
    for (std::size_t t = 0; t < look.textures.size(); ++t)
        EXPECT_TRUE(look.textures[t].rgba == painted.textures[t].rgba) << t;
    EXPECT_EQ(look.textureSources.size(), painted.textureSources.size());
    EXPECT_EQ(look.colors, painted.colors);
}

TEST(Material, ObjExportKeepsTheMapsAssimpReadsBack) {
    core::Result<core::Mesh> loaded = core::loadMesh(kMaterials);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    TempDir dir;
    const std::string path = dir.file("materials.obj");
    auto files = core::exportMesh(path, core::ExportFormat::Obj, *loaded);
    ASSERT_TRUE(files.ok()) << files.error();
    core::Result<core::Mesh> back = core::loadMesh(path);
    ASSERT_TRUE(back.ok()) << back.error();
    for (std::size_t m = 0; m < 2; ++m) {
        const core::Material& in = loaded->materials[m];
        const core::Material* out = nullptr;
        for (const core::Material& candidate : back->materials)
            if (candidate.name.ends_with("_" + in.name))
                out = &candidate;
        ASSERT_NE(out, nullptr) << in.name;
        EXPECT_FLOAT_EQ(out->metallicFactor, in.metallicFactor);
        EXPECT_FLOAT_EQ(out->roughnessFactor, in.roughnessFactor);
        EXPECT_EQ(out->emissiveFactor, in.emissiveFactor * in.emissiveStrength);
        expectMap(*back, out->metallicRoughness, 8, 8);
        expectMap(*back, out->normal, 4, 4);
        expectMap(*back, out->occlusion, 4, 8);
        expectMap(*back, out->emissive, 8, 4);
        // The kept files are written as they are; roughness and metallic come back combined.
        for (const core::MaterialMap* map : {&in.normal, &in.occlusion, &in.emissive}) {
            const core::MaterialMap& same = map == &in.normal      ? out->normal
                                            : map == &in.occlusion ? out->occlusion
                                                                   : out->emissive;
            EXPECT_TRUE(back->textures[std::size_t(same.texture)].rgba ==
                        loaded->textures[std::size_t(map->texture)].rgba);
        }
        const core::Image& mr = back->textures[std::size_t(out->metallicRoughness.texture)];
        const core::Image& source = loaded->textures[std::size_t(in.metallicRoughness.texture)];
        for (std::size_t i = 0; i < mr.rgba.size(); i += 4) {
            EXPECT_EQ(mr.rgba[i + 1], source.rgba[i + 1]) << i;
            EXPECT_EQ(mr.rgba[i + 2], source.rgba[i + 2]) << i;
        }
    }
}

TEST(Material, EmissionBeyondGltfsFactorGoesIntoTheStrength) {
    // OBJ's Ke and Assimp's emissive colour know no limit of 1; glTF's factor does.
    core::Result<core::Mesh> loaded = core::loadMesh(kMaterials);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    core::Mesh mesh = std::move(loaded).value();
    mesh.source.reset(); // as a model Assimp read: no glTF scene to write back into
    mesh.materials[1].emissiveFactor = glm::vec3(2.0f, 1.0f, 0.0f);
    TempDir dir;
    const std::string path = dir.file("bright.glb");
    ASSERT_TRUE(core::exportMesh(path, core::ExportFormat::Glb, mesh).ok());
    core::Result<core::Mesh> back = core::loadMesh(path);
    ASSERT_TRUE(back.ok()) << back.error();
    const core::Material& m = back->materials[1];
    EXPECT_EQ(m.emissiveFactor, glm::vec3(1.0f, 0.5f, 0.0f));
    EXPECT_FLOAT_EQ(m.emissiveStrength, 2.0f);
    expectValidGltf(path);
}

TEST(Material, RealFileKeepsItsNormalAndEmissiveMaps) {
    if (!std::filesystem::exists(kClearCoat))
        GTEST_SKIP() << kClearCoat << " is missing (apt-get install assimp-testmodels)";
    core::Result<core::Mesh> loaded = core::loadMesh(kClearCoat);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    const core::Mesh& mesh = *loaded;
    const auto material = [&](const std::string& name) -> const core::Material& {
        for (const core::Material& m : mesh.materials)
            if (m.name == name)
                return m;
        ADD_FAILURE() << "no material " << name;
        return mesh.materials.front();
    };
    const std::filesystem::path folder = std::filesystem::path(kClearCoat).parent_path();
    const auto fileOf = [&](int texture) {
        const core::EncodedImage* kept = mesh.textureSource(texture);
        return kept ? std::string(kept->bytes.begin(), kept->bytes.end()) : std::string();
    };
    const core::Material& ribs = material("BaseNorm_Base");
    expectMap(mesh, ribs.normal, 512, 512);
    EXPECT_EQ(fileOf(ribs.normal.texture), readFile(folder / "RibsNormal.png"));
    // One image under several textures stays one texture.
    EXPECT_EQ(material("SharedNorm_Base").normal.texture, ribs.normal.texture);
    EXPECT_EQ(material("SharedNorm_Coating").normal.texture, ribs.normal.texture);
    const core::Material& wrap = material("CoatNorm_Coating");
    expectMap(mesh, wrap.normal, 1024, 1024);
    ASSERT_NE(mesh.textureSource(wrap.normal.texture), nullptr);
    EXPECT_EQ(mesh.textureSource(wrap.normal.texture)->mimeType, "image/jpeg");
    EXPECT_EQ(fileOf(wrap.normal.texture), readFile(folder / "PlasticWrap_normals.jpg"));
    const core::Material& label = material("LabelMaterial");
    expectMap(mesh, label.emissive, 256, 256);
    EXPECT_EQ(label.emissiveFactor, glm::vec3(1.0f));
    EXPECT_FLOAT_EQ(label.roughnessFactor, 0.9f);
    EXPECT_FLOAT_EQ(label.metallicFactor, 0.0f);
    const core::Material& stripes = material("RoughVariations_Coating");
    expectMap(mesh, stripes.metallicRoughness, 512, 512);
    EXPECT_FLOAT_EQ(stripes.roughnessFactor, 1.0f);
    EXPECT_EQ(material("Partial_Coating").alphaMode, core::AlphaMode::Blend);
    // The one base colour texture comes first.
    EXPECT_EQ(material("Partial_Coating").baseColorTexture, 0);
}

} // namespace material_test
