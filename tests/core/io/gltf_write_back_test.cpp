// SPDX-License-Identifier: GPL-3.0-or-later
// Saving writes the glTF scene a model was read from back, copy-on-write: the node tree, names,
// transforms, instancing, accessors and extensions of the 2CylinderEngine sample (Debian's
// assimp-testmodels, binary and Draco) come out as they went in; after a stroke on
// tests/data/material/materials.glb only the painted image differs (the others are the source's
// very bytes); a project reopens as painted and saving it again does not grow it; a mesh that no
// longer matches its scene is written flattened with a warning saying why.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/gtc/epsilon.hpp>
#include <nlohmann/json.hpp>

#include "core/depth/cpu_capture.h"
#include "core/document/document.h"
#include "core/document/project_state.h"
#include "core/io/export.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/model/source_scene.h"
#include "tests/core/test_files.h"

namespace material_test {
void paintStroke(core::Document& doc);
void expectValidGltf(const std::string& path);
} // namespace material_test

namespace {

using core_test::readFile;
using core_test::TempDir;
using Json = nlohmann::json;
using Bytes = std::vector<std::uint8_t>;

const std::string kMaterials = std::string(LAYERPAINT_TEST_DATA) + "/material/materials.glb";
const std::string kEngine = std::string(LAYERPAINT_ASSIMP_MODELS) +
                            "/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
const std::string kDracoEngine =
    std::string(LAYERPAINT_ASSIMP_MODELS) + "/glTF2/draco/2CylinderEngine.gltf";

/** A binary glTF's JSON and BIN chunk. */
struct Glb {
    Json json;
    Bytes bin;

    /** The bytes of image i. */
    Bytes image(std::size_t i) const {
        const Json& view = json["bufferViews"][json["images"][i]["bufferView"].get<std::size_t>()];
        const auto at = view.value("byteOffset", std::size_t{0});
        return Bytes(bin.begin() + std::ptrdiff_t(at),
                     bin.begin() + std::ptrdiff_t(at + view["byteLength"].get<std::size_t>()));
    }
};

Glb readGlb(const std::string& path) {
    const std::string text = readFile(path);
    const Bytes bytes(text.begin(), text.end());
    Glb glb;
    std::uint32_t jsonLength = 0, binLength = 0;
    EXPECT_GE(bytes.size(), 20u);
    std::memcpy(&jsonLength, bytes.data() + 12, 4);
    glb.json = Json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLength);
    const std::size_t binAt = 20 + jsonLength;
    if (binAt + 8 <= bytes.size()) {
        std::memcpy(&binLength, bytes.data() + binAt, 4);
        glb.bin.assign(bytes.begin() + std::ptrdiff_t(binAt + 8),
                       bytes.begin() + std::ptrdiff_t(binAt + 8 + binLength));
    }
    return glb;
}

/** The parts of a scene that saving must not change. */
void expectSameScene(const Json& out, const Json& in) {
    for (const char* key :
         {"scene", "scenes", "nodes", "meshes", "accessors", "materials", "cameras", "animations",
          "skins", "extensionsUsed", "extensionsRequired"}) {
        SCOPED_TRACE(key);
        EXPECT_EQ(out.value(key, Json()), in.value(key, Json()));
    }
}

core::Mesh load(const std::string& path) {
    core::Result<core::Mesh> loaded = core::loadMesh(path);
    EXPECT_TRUE(loaded.ok()) << loaded.error();
    return loaded.ok() ? std::move(loaded).value() : core::Mesh{};
}

TEST(WriteBack, UnpaintedEngineComesOutAsItWentIn) {
    if (!std::filesystem::exists(kEngine))
        GTEST_SKIP() << kEngine << " is missing (apt-get install assimp-testmodels)";
    const core::Mesh mesh = load(kEngine);
    ASSERT_TRUE(mesh.source);
    EXPECT_EQ(mesh.source->notKept, "");
    TempDir dir;
    const std::string out = dir.file("engine.glb");
    std::vector<std::string> warnings;
    auto files = core::exportMesh(out, core::ExportFormat::Glb, mesh, {}, &warnings);
    ASSERT_TRUE(files.ok()) << files.error();
    EXPECT_TRUE(warnings.empty()) << warnings.front();

    const Glb source = readGlb(kEngine), written = readGlb(out);
    expectSameScene(written.json, source.json);
    ASSERT_EQ(written.json["nodes"].size(), 82u);
    ASSERT_EQ(written.json["bufferViews"].size(), source.json["bufferViews"].size());
    for (std::size_t v = 0; v < source.json["bufferViews"].size(); ++v) {
        const Json& a = source.json["bufferViews"][v];
        const Json& b = written.json["bufferViews"][v];
        const auto from = a.value("byteOffset", std::size_t{0});
        const auto to = b.value("byteOffset", std::size_t{0});
        ASSERT_EQ(a["byteLength"], b["byteLength"]);
        EXPECT_TRUE(std::equal(source.bin.begin() + std::ptrdiff_t(from),
                               source.bin.begin() +
                                   std::ptrdiff_t(from + a["byteLength"].get<std::size_t>()),
                               written.bin.begin() + std::ptrdiff_t(to)))
            << "view " << v << " changed";
    }
    material_test::expectValidGltf(out);

    // Reopened, it flattens into the very same triangles.
    const core::Mesh again = load(out);
    EXPECT_EQ(again.positions, mesh.positions);
    EXPECT_EQ(again.indices, mesh.indices);
}

/**
 * Sample files of Debian's assimp-testmodels with cameras, animations, skins, morph targets,
 * texture transforms, specular-glossiness and every primitive mode: written back unpainted, each
 * keeps its scene and reopens as the same triangles.
 */
TEST(WriteBack, SampleFilesKeepTheirScenes) {
    const std::string root = std::string(LAYERPAINT_ASSIMP_MODELS) + "/glTF2/";
    const std::vector<std::string> files = {
        "cameras/Cameras.gltf",
        "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf",
        "simple_skin/simple_skin.gltf",
        "textureTransform/TextureTransformTest.gltf",
        "BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf",
        "BoxTextured-glTF-Embedded/BoxTextured.gltf",
        "glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf",
        "glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_05.gltf",
        "glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_06.gltf",
        "glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_13.gltf",
    };
    TempDir dir;
    for (const std::string& name : files) {
        SCOPED_TRACE(name);
        const std::string path = root + name;
        if (!std::filesystem::exists(path))
            GTEST_SKIP() << path << " is missing (apt-get install assimp-testmodels)";
        const core::Mesh mesh = load(path);
        const std::string out = dir.file("out.glb");
        std::vector<std::string> warnings;
        ASSERT_TRUE(core::exportMesh(out, core::ExportFormat::Glb, mesh, {}, &warnings).ok());
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        const Json source = Json::parse(readFile(path));
        const Glb written = readGlb(out);
        expectSameScene(written.json, source);
        EXPECT_EQ(written.json.value("images", Json::array()).size(),
                  source.value("images", Json::array()).size());
        const core::Mesh again = load(out);
        EXPECT_EQ(again.indices, mesh.indices);
        EXPECT_EQ(again.positions, mesh.positions);
        EXPECT_EQ(again.uvs, mesh.uvs);
    }
}

/**
 * The painted engine exported to out: its scene kept (no warning says otherwise, the node tree
 * as it was), every primitive with attribute, and valid.
 */
void exportEngineWithAttribute(const core::Mesh& painted, const std::string& out,
                               const char* attribute) {
    std::vector<std::string> warnings;
    ASSERT_TRUE(core::exportMesh(out, core::ExportFormat::Glb, painted, {}, &warnings).ok());
    std::size_t factorsBaked = 0;
    for (const std::string& w : warnings) {
        EXPECT_EQ(w.find("not kept"), std::string::npos) << w;
        factorsBaked += w.find("base colour factor is multiplied into") != std::string::npos;
    }
    const Glb source = readGlb(kEngine), written = readGlb(out);
    // The engine's materials are coloured by their factors alone: each such factor is named.
    std::size_t coloured = 0;
    for (const Json& m : source.json["materials"])
        coloured += m["pbrMetallicRoughness"].value("baseColorFactor", Json::array({1, 1, 1, 1})) !=
                    Json::array({1, 1, 1, 1});
    EXPECT_GT(coloured, 0u);
    EXPECT_EQ(factorsBaked, coloured);
    for (const char* key : {"scene", "scenes", "nodes"})
        EXPECT_EQ(written.json[key], source.json[key]) << key;
    ASSERT_EQ(written.json["meshes"].size(), source.json["meshes"].size());
    for (const Json& mesh : written.json["meshes"])
        for (const Json& primitive : mesh["primitives"])
            EXPECT_TRUE(primitive["attributes"].contains(attribute));
    material_test::expectValidGltf(out);
}

TEST(WriteBack, PaintedVertexColoursBecomeEachPrimitivesColour) {
    if (!std::filesystem::exists(kEngine))
        GTEST_SKIP() << kEngine << " is missing (apt-get install assimp-testmodels)";
    core::Document doc;
    doc.setMesh(load(kEngine), kEngine);
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::VertexColors;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    material_test::paintStroke(doc);
    const core::Mesh painted = doc.paintedMesh();

    TempDir dir;
    const std::string out = dir.file("engine.glb");
    exportEngineWithAttribute(painted, out, "COLOR_0");

    // Reopened: the same triangles, and the stroke's colours where it painted.
    const core::Mesh again = load(out);
    EXPECT_EQ(again.indices, painted.indices);
    ASSERT_TRUE(again.hasColors());
    std::size_t same = 0, stroke = 0;
    for (std::size_t v = 0; v < painted.vertexCount(); ++v) {
        const bool red = painted.colors[v].r > 0.5f && painted.colors[v].g < 0.4f;
        stroke += red ? 1 : 0;
        same += red && glm::all(glm::epsilonEqual(again.colors[v], painted.colors[v], 1e-6f));
    }
    EXPECT_GT(stroke, 0u) << "the stroke painted nothing";
    EXPECT_GT(same, stroke / 2) << "the painted colours did not come back";
}

TEST(WriteBack, AnAutomaticUvLayoutGivesEachPrimitiveItsTexture) {
    if (!std::filesystem::exists(kEngine))
        GTEST_SKIP() << kEngine << " is missing (apt-get install assimp-testmodels)";
    core::Document doc;
    doc.setMesh(load(kEngine), kEngine);
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::Texture; // the engine has no UVs: a layout
    options.resolution = 512;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    material_test::paintStroke(doc);
    const core::Mesh painted = doc.paintedMesh();
    ASSERT_TRUE(painted.hasUvs());

    TempDir dir;
    const std::string out = dir.file("engine.glb");
    exportEngineWithAttribute(painted, out, "TEXCOORD_0");
    const Glb written = readGlb(out);
    std::size_t textured = 0;
    for (const Json& material : written.json["materials"])
        textured += material["pbrMetallicRoughness"].contains("baseColorTexture") ? 1 : 0;
    EXPECT_EQ(textured, written.json["materials"].size()) << "the painted page is not shown";

    // Reopened: the same triangles, with UVs (no second layout).
    const core::Mesh again = load(out);
    EXPECT_EQ(again.indices.size(), painted.indices.size());
    EXPECT_EQ(again.triangleMaterial, painted.triangleMaterial);
    EXPECT_TRUE(again.hasUvs());

    // As a project: it reopens with the page as painted.
    const std::string project = dir.file("engine-project.glb");
    ASSERT_TRUE(core::saveProject(project, doc, core::captureProjectState(doc)).ok());
    core::Result<core::Project> reopened = core::loadProject(project);
    ASSERT_TRUE(reopened.ok()) << reopened.error();
    core::Document second;
    second.setMesh(std::move(reopened->mesh), project);
    ASSERT_TRUE(core::applyProjectState(second, *reopened->state).ok());
    ASSERT_EQ(second.paintTarget()->pageCount(), doc.paintTarget()->pageCount());
    EXPECT_TRUE(second.paintTarget()->page(0).rgba == doc.paintTarget()->page(0).rgba);
}

TEST(WriteBack, DracoEngineKeepsItsCompressionAndTakesItsBufferIn) {
    if (!std::filesystem::exists(kDracoEngine))
        GTEST_SKIP() << kDracoEngine << " is missing (apt-get install assimp-testmodels)";
    const core::Mesh mesh = load(kDracoEngine);
    TempDir dir;
    const std::string out = dir.file("engine.glb");
    std::vector<std::string> warnings;
    ASSERT_TRUE(core::exportMesh(out, core::ExportFormat::Glb, mesh, {}, &warnings).ok());
    EXPECT_TRUE(warnings.empty());
    const Json source = Json::parse(readFile(kDracoEngine));
    const Glb written = readGlb(out);
    expectSameScene(written.json, source);
    EXPECT_FALSE(written.json["buffers"][0].contains("uri")) << "the .bin was not taken in";
    material_test::expectValidGltf(out);
    const core::Mesh again = load(out);
    EXPECT_EQ(again.indices, mesh.indices);
}

TEST(WriteBack, AStrokeChangesOnlyThePaintedImage) {
    core::Document doc;
    doc.setMesh(load(kMaterials), kMaterials);
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::Texture;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    material_test::paintStroke(doc);

    TempDir dir;
    const std::string out = dir.file("painted.glb");
    std::vector<std::string> warnings;
    ASSERT_TRUE(
        core::exportMesh(out, core::ExportFormat::Glb, doc.paintedMesh(), {}, &warnings).ok());
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    const Glb source = readGlb(kMaterials), written = readGlb(out);
    expectSameScene(written.json, source.json);
    ASSERT_EQ(written.json["images"].size(), source.json["images"].size());
    std::size_t changed = 0;
    for (std::size_t i = 0; i < source.json["images"].size(); ++i) {
        const bool baseColour = i == 0 || i == 5; // materials.glb's base colour images
        if (written.image(i) == source.image(i))
            continue;
        ++changed;
        EXPECT_TRUE(baseColour) << "image " << i << " changed without being painted";
    }
    EXPECT_GE(changed, 1u) << "the stroke changed no image";
    material_test::expectValidGltf(out);
}

TEST(WriteBack, ProjectReopensAsPaintedAndDoesNotGrowWhenSavedAgain) {
    core::Document doc;
    doc.setMesh(load(kMaterials), kMaterials);
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::Texture;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    core::PaintChanges changes;
    ASSERT_TRUE(doc.addPaintLayer(core::PaintLayerSettings{}, changes).ok());
    material_test::paintStroke(doc);

    TempDir dir;
    const std::string first = dir.file("first.glb"), second = dir.file("second.glb");
    ASSERT_TRUE(core::saveProject(first, doc, core::captureProjectState(doc)).ok());
    core::Result<core::Project> reopened = core::loadProject(first);
    ASSERT_TRUE(reopened.ok()) << reopened.error();
    core::Document again;
    again.setMesh(std::move(reopened->mesh), first);
    ASSERT_TRUE(core::applyProjectState(again, *reopened->state).ok());
    ASSERT_EQ(again.paintTarget()->pageCount(), doc.paintTarget()->pageCount());
    for (std::size_t p = 0; p < doc.paintTarget()->pageCount(); ++p)
        EXPECT_TRUE(again.paintTarget()->page(p).rgba == doc.paintTarget()->page(p).rgba)
            << "page " << p << " differs after reopening";
    ASSERT_TRUE(core::saveProject(second, again, core::captureProjectState(again)).ok());

    const Glb a = readGlb(first), b = readGlb(second);
    expectSameScene(b.json, a.json);
    EXPECT_EQ(b.json["images"].size(), a.json["images"].size());
    EXPECT_EQ(b.json["bufferViews"].size(), a.json["bufferViews"].size());
    EXPECT_EQ(b.bin.size(), a.bin.size());
    material_test::expectValidGltf(second);
}

TEST(WriteBack, AMeshThatNoLongerMatchesItsSceneIsWrittenFlattenedWithAWarning) {
    core::Mesh mesh = load(kMaterials);
    ASSERT_TRUE(mesh.hasUvs());
    mesh.uvs[0].x += 0.25f; // as an automatic layout would
    core::GlbAdditions additions;
    std::vector<std::string> warnings;
    additions.warnings = &warnings;
    core::Result<Bytes> bytes = core::encodeGlbWith(mesh, additions);
    ASSERT_TRUE(bytes.ok()) << bytes.error();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("texture coordinates"), std::string::npos) << warnings[0];
}

} // namespace
