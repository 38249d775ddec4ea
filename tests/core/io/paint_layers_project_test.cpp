// SPDX-License-Identifier: GPL-3.0-or-later
// Projects with paint layers: five layers (paint and fill, masks, multiply/screen/overlay, a
// hidden and a locked one) saved and reopened give the same stack, the same bytes per layer and
// the same composite; the file is plain glTF to tinygltf and Assimp, and its material's two
// textures are the composite. Older projects open with no paint layers.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/depth/cpu_capture.h"
#include "core/document/document.h"
#include "core/io/gltf/glb_container.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/project/project_file.h"
#include "core/model/builtin_models.h"
#include "tests/core/paint_layers_snapshot.h"
#include "tests/core/test_files.h"

namespace paint_layers_project_test {

using core_test::TempDir;
using Json = nlohmann::json;

using core_test::paintLayersSnapshot;
using Snapshot = core_test::PaintLayersSnapshot;

class PaintLayersProjectTest : public ::testing::Test {
protected:
    void SetUp() override {
        m_doc.setMesh(core::makeTrefoil(60, 16), "builtin:trefoil");
        core::PaintTargetOptions options;
        options.resolution = 512;
        ASSERT_TRUE(m_doc.setPaintTarget(options).ok());
        m_doc.camera() = core::Camera::fromOrbit(m_doc.mesh().bounds(), 30.0f, 20.0f, 1.6f);
        core::CpuDepthCapturer capturer;
        capturer.setMesh(m_doc.mesh());
        ASSERT_TRUE(m_doc.buildDepthLayers(capturer, m_doc.camera().view(kWidth, kHeight)).ok());
        m_doc.brush().radius = 9.0f;
        m_doc.brush().hardness = 0.7f;
    }

    /** A horizontal stroke across the model at row y. */
    void stroke(int y, glm::vec4 color) {
        m_doc.brush().color = color;
        const core::DepthStack& stack = m_doc.depthLayers()->stack;
        int first = -1, last = -1;
        for (int x = 0; x < kWidth; ++x)
            if (stack.layerCount(std::size_t(y) * kWidth + std::size_t(x)) > 0) {
                if (first < 0)
                    first = x;
                last = x;
            }
        ASSERT_GT(last - first, 20) << "row " << y;
        core::PaintChanges changes;
        ASSERT_TRUE(
            m_doc.beginStroke({{float(first) + 2.5f, float(y) + 0.5f}, 1.0f}, changes).ok());
        for (int x = first + 4; x < last - 2; x += 3)
            m_doc.moveStroke({{float(x) + 0.5f, float(y) + 0.5f}, 1.0f}, changes);
        m_doc.endStroke();
    }

    std::uint64_t add(std::string name, core::PaintLayerKind kind, core::BlendMode blend) {
        core::PaintLayerSettings s;
        s.name = std::move(name);
        s.kind = kind;
        s.blend = blend;
        if (kind == core::PaintLayerKind::Fill) {
            s.fill.baseColor = glm::vec3(0.2f, 0.6f, 0.9f);
            s.fill.roughness = 0.3f;
        }
        core::PaintChanges changes;
        core::Result<std::uint64_t> id = m_doc.addPaintLayer(s, changes);
        EXPECT_TRUE(id.ok()) << id.error();
        return id.ok() ? *id : 0;
    }

    void set(std::uint64_t id, void (*change)(core::PaintLayerSettings&)) {
        const auto& target = dynamic_cast<const core::TextureTarget&>(*m_doc.currentPaintTarget());
        core::PaintLayerSettings s =
            target.paintLayerStack().layer(*target.paintLayerStack().indexOf(id)).settings;
        change(s);
        core::PaintChanges changes;
        ASSERT_TRUE(m_doc.setPaintLayerSettings(id, s, changes).ok());
    }

    /** Five layers: paint, fill with a mask, multiply, screen (hidden), overlay (locked). */
    void buildStack() {
        stroke(100, {0.9f, 0.9f, 0.2f, 1.0f}); // the base
        const std::uint64_t paint =
            add("Paint", core::PaintLayerKind::Paint, core::BlendMode::Normal);
        m_doc.brush().paintRoughness = true;
        m_doc.brush().roughness = 0.2f;
        m_doc.brush().paintMetallic = true;
        m_doc.brush().metallic = 1.0f;
        stroke(110, {0.8f, 0.1f, 0.1f, 1.0f});
        m_doc.brush().paintRoughness = m_doc.brush().paintMetallic = false;
        const std::uint64_t fill = add("Fill", core::PaintLayerKind::Fill, core::BlendMode::Normal);
        core::PaintChanges changes;
        ASSERT_TRUE(m_doc.addPaintLayerMask(fill, changes).ok());
        stroke(130, {0.0f, 0.0f, 0.0f, 1.0f}); // black hides the fill there
        const std::uint64_t multiply =
            add("Multiply", core::PaintLayerKind::Paint, core::BlendMode::Multiply);
        stroke(120, {0.3f, 0.9f, 0.4f, 1.0f});
        set(multiply, [](core::PaintLayerSettings& s) { s.opacity = 0.75f; });
        const std::uint64_t screen =
            add("Screen", core::PaintLayerKind::Paint, core::BlendMode::Screen);
        stroke(140, {0.2f, 0.3f, 0.9f, 1.0f});
        set(screen, [](core::PaintLayerSettings& s) { s.visible = false; });
        const std::uint64_t overlay =
            add("Overlay", core::PaintLayerKind::Paint, core::BlendMode::Overlay);
        stroke(125, {0.7f, 0.5f, 0.9f, 1.0f});
        set(overlay, [](core::PaintLayerSettings& s) { s.lockTransparency = true; });
        ASSERT_TRUE(m_doc.addPaintLayerMask(multiply, changes).ok());
        stroke(115, {0.4f, 0.4f, 0.4f, 1.0f}); // a grey mask on the multiply layer
        ASSERT_TRUE(m_doc.selectPaint({paint, false}).ok());
        (void)paint;
    }

    static constexpr int kWidth = 320, kHeight = 240;
    core::Document m_doc;
};

TEST_F(PaintLayersProjectTest, SaveAndReopenRestoresEveryLayerByteForByte) {
    buildStack();
    const Snapshot before = paintLayersSnapshot(m_doc);
    ASSERT_EQ(before.ids.size(), 5u);
    EXPECT_NE(before.base, before.color) << "the layers change the look";

    TempDir dir;
    const std::string path = dir.file("layers.glb");
    const core::ProjectState state = core::captureProjectState(m_doc);
    ASSERT_TRUE(state.paintLayers);
    ASSERT_TRUE(core::saveProject(path, m_doc, state).ok());

    core::Result<core::Project> project = core::loadProject(path);
    ASSERT_TRUE(project.ok()) << project.error();
    ASSERT_TRUE(project->state.has_value());
    EXPECT_EQ(project->state->formatVersion, core::kProjectFormatVersion);
    core::Document reopened;
    reopened.setMesh(std::move(project->mesh), path);
    const core::Status applied = core::applyProjectState(reopened, *project->state);
    ASSERT_TRUE(applied.ok()) << applied.error();
    const Snapshot after = paintLayersSnapshot(reopened);
    EXPECT_EQ(after.ids, before.ids);
    EXPECT_TRUE(after.settings == before.settings);
    EXPECT_EQ(after.selection, before.selection);
    ASSERT_EQ(after.planes.size(), before.planes.size());
    for (std::size_t i = 0; i < after.planes.size(); ++i)
        EXPECT_TRUE(after.planes[i] == before.planes[i])
            << "plane " << i << ": " << after.planes[i].size() << " bytes, was "
            << before.planes[i].size() << [&] {
                   for (std::size_t k = 0; k < after.planes[i].size(); ++k)
                       if (after.planes[i][k] != before.planes[i][k])
                           return " at " + std::to_string(k) + ": " +
                                  std::to_string(after.planes[i][k]) + " was " +
                                  std::to_string(before.planes[i][k]);
                   return std::string();
               }();
    EXPECT_TRUE(after.base == before.base);
    EXPECT_TRUE(after.color == before.color);
    EXPECT_TRUE(after.mr == before.mr);
    // What the reopened stack does next is as before: a new layer gets a fresh id.
    core::PaintChanges changes;
    core::Result<std::uint64_t> next = reopened.addPaintLayer({}, changes);
    ASSERT_TRUE(next.ok());
    for (std::uint64_t id : before.ids)
        EXPECT_NE(*next, id);

    // Other tools: tinygltf reads the file, the material's two textures are the composite.
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &err, &warn, path)) << err;
    EXPECT_TRUE(err.empty()) << err;
    ASSERT_EQ(model.materials.size(), 1u);
    const auto& pbr = model.materials[0].pbrMetallicRoughness;
    ASSERT_GE(pbr.baseColorTexture.index, 0);
    ASSERT_GE(pbr.metallicRoughnessTexture.index, 0);
    const auto& color =
        model.images[std::size_t(model.textures[std::size_t(pbr.baseColorTexture.index)].source)];
    const auto& mr = model.images[std::size_t(
        model.textures[std::size_t(pbr.metallicRoughnessTexture.index)].source)];
    ASSERT_EQ(color.component, 4);
    EXPECT_TRUE(color.image == before.color);
    // An opaque image is stored as RGB; tinygltf gives it back as RGBA with A 255.
    ASSERT_EQ(mr.component, 4);
    EXPECT_TRUE(mr.image == before.mr);
    EXPECT_EQ(pbr.metallicFactor, 1.0);
    EXPECT_EQ(pbr.roughnessFactor, 1.0);

    // Assimp validates and reads it, with both textures on the material.
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_GE(scene->mNumMaterials, 1u);
    EXPECT_GE(scene->mMaterials[0]->GetTextureCount(aiTextureType_BASE_COLOR) +
                  scene->mMaterials[0]->GetTextureCount(aiTextureType_DIFFUSE),
              1u);
    EXPECT_GE(scene->mMaterials[0]->GetTextureCount(aiTextureType_METALNESS) +
                  scene->mMaterials[0]->GetTextureCount(aiTextureType_DIFFUSE_ROUGHNESS) +
                  scene->mMaterials[0]->GetTextureCount(aiTextureType_UNKNOWN),
              1u);
}

TEST_F(PaintLayersProjectTest, OlderProjectsOpenWithNoPaintLayers) {
    // Version 2 as written before paint layers: the painted texture and the state, nothing else.
    stroke(100, {0.9f, 0.2f, 0.2f, 1.0f});
    core::ProjectState state = core::captureProjectState(m_doc);
    EXPECT_FALSE(state.paintLayers) << "no paint layer yet";
    Json v2 = core::projectStateToJson(state);
    v2["version"] = 2;
    TempDir dir;
    const std::string path = dir.file("v2.glb");
    ASSERT_TRUE(core::saveGlb(path, m_doc.paintedMesh(), {{"layerpaint", v2}}).ok());
    const std::vector<std::uint8_t> painted = m_doc.paintedMesh().textures[0].rgba;
    for (const Json& old : {v2, Json{{"script", Json::array()}, {"model", "builtin:trefoil"}}}) {
        ASSERT_TRUE(core::saveGlb(path, m_doc.paintedMesh(), {{"layerpaint", old}}).ok());
        core::Result<core::Project> project = core::loadProject(path);
        ASSERT_TRUE(project.ok()) << project.error();
        ASSERT_TRUE(project->state.has_value());
        EXPECT_FALSE(project->state->paintLayers);
        core::Document reopened;
        reopened.setMesh(std::move(project->mesh), path);
        ASSERT_TRUE(core::applyProjectState(reopened, *project->state).ok());
        const auto& target =
            dynamic_cast<const core::TextureTarget&>(*reopened.currentPaintTarget());
        EXPECT_EQ(target.paintLayerStack().size(), 0u);
        EXPECT_TRUE(target.page(0).rgba == painted);
    }
}

TEST_F(PaintLayersProjectTest, DamagedLayerDataIsAClearErrorNamingTheFile) {
    buildStack();
    TempDir dir;
    const std::string path = dir.file("layers.glb");
    const core::ProjectState state = core::captureProjectState(m_doc);
    // The structure without the images behind it: the planes cannot be found.
    ASSERT_TRUE(
        core::saveGlb(path, m_doc.paintedMesh(), {{"layerpaint", core::projectStateToJson(state)}})
            .ok());
    core::Result<core::Project> project = core::loadProject(path);
    ASSERT_FALSE(project.ok());
    EXPECT_EQ(project.error().rfind(path + ": ", 0), 0u) << project.error();
    // Duplicate ids.
    Json bad = core::projectStateToJson(state);
    bad["paint_layers"]["layers"][1]["id"] = bad["paint_layers"]["layers"][0]["id"];
    ASSERT_TRUE(core::saveGlb(path, m_doc.paintedMesh(), {{"layerpaint", bad}}).ok());
    project = core::loadProject(path);
    ASSERT_FALSE(project.ok());
    EXPECT_NE(project.error().find("id"), std::string::npos) << project.error();
}

// The layers' PNG images are untrusted bytes like any file's: the importer process decodes them
// (loadGlbImages), with the same result as decoding here, and a damaged one is an error naming
// the file, never a crash of the application.
TEST_F(PaintLayersProjectTest, LayerImagesAreDecodedByTheImporter) {
    buildStack();
    TempDir dir;
    const std::string path = dir.file("layers.glb");
    ASSERT_TRUE(core::saveProject(path, m_doc, core::captureProjectState(m_doc)).ok());
    core::Result<Json> extras = core::readGlbExtras(path);
    ASSERT_TRUE(extras.ok()) << extras.error();
    std::vector<core::GlbImageRequest> views;
    for (int view : (*extras)["layerpaint"]["paint_layers"]["images"].get<std::vector<int>>())
        views.push_back({view});
    ASSERT_FALSE(views.empty());

    const core::Result<std::vector<core::Image>> outside = core::loadGlbImages(path, views);
    ASSERT_TRUE(outside.ok()) << outside.error();
    const core::Result<std::vector<core::Image>> inside = core::loadGlbImagesInProcess(path, views);
    ASSERT_TRUE(inside.ok()) << inside.error();
    ASSERT_EQ(outside->size(), views.size());
    ASSERT_EQ(inside->size(), views.size());
    for (std::size_t k = 0; k < views.size(); ++k) {
        EXPECT_EQ((*outside)[k].width, (*inside)[k].width) << k;
        EXPECT_TRUE((*outside)[k].rgba == (*inside)[k].rgba) << k;
    }

    // A view that is not an image.
    const core::Result<std::vector<core::Image>> notImage =
        core::loadGlbImages(path, {views.front(), {0}});
    ASSERT_FALSE(notImage.ok());
    EXPECT_EQ(notImage.error().rfind(path + ": ", 0), 0u) << notImage.error();
    // A view that does not exist.
    const core::Result<std::vector<core::Image>> missing = core::loadGlbImages(path, {{100000}});
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().rfind(path + ": ", 0), 0u) << missing.error();
}

} // namespace paint_layers_project_test

namespace paint_layers_project_test {

/** The project at path with its glTF JSON changed by edit (its BIN chunk kept). */
void editProject(const std::string& path, const std::function<void(Json&)>& edit) {
    const std::string bytes = core_test::readFile(path);
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    const core::Result<core::glb::Layout> layout = core::glb::readContainer({data, bytes.size()});
    ASSERT_TRUE(layout) << layout.error();
    Json json = Json::parse(bytes.substr(layout->jsonOffset, layout->jsonLength));
    edit(json);
    const std::vector<std::uint8_t> out =
        core::glb::replaceJson({data, bytes.size()}, *layout, json.dump());
    core_test::writeFile(path, std::string(out.begin(), out.end()));
}

/** How often text occurs in message. */
std::size_t occurrences(const std::string& message, const std::string& text) {
    std::size_t count = 0;
    for (std::size_t at = message.find(text); at != std::string::npos;
         at = message.find(text, at + 1))
        ++count;
    return count;
}

class HostileProjectTest : public PaintLayersProjectTest {
protected:
    /**
     * A saved project of buildStack() with its layerpaint extras edited; the error loading it
     * gives (none: "").
     */
    std::string loadEdited(const std::function<void(Json&)>& edit,
                           const core::LoadLimits& limits = {}) {
        return loadEditedRoot([&](Json& root) { edit(root["asset"]["extras"]["layerpaint"]); },
                              limits);
    }

    /** As loadEdited(), editing the whole glTF JSON. */
    std::string loadEditedRoot(const std::function<void(Json&)>& edit,
                               const core::LoadLimits& limits = {}) {
        const std::string path = m_dir.file("hostile.glb");
        EXPECT_TRUE(core::saveProject(path, m_doc, core::captureProjectState(m_doc)).ok());
        editProject(path, edit);
        const core::Result<core::Project> project = core::loadProject(path, {}, limits);
        if (project)
            return "";
        // One file name per message, at its start.
        EXPECT_EQ(project.error().rfind(path + ": ", 0), 0u) << project.error();
        EXPECT_EQ(occurrences(project.error(), path), 1u) << project.error();
        return project.error();
    }

    void SetUp() override {
        ASSERT_NO_FATAL_FAILURE(PaintLayersProjectTest::SetUp());
        ASSERT_NO_FATAL_FAILURE(buildStack());
    }

    TempDir m_dir;
};

/** The first plane page entry of the paint layers (a layer's base colour region). */
Json& firstRegion(Json& layerpaint) {
    for (Json& layer : layerpaint["paint_layers"]["layers"])
        if (layer.contains("channels") && layer["channels"].contains("base_color") &&
            !layer["channels"]["base_color"]["pages"].empty())
            return layer["channels"]["base_color"]["pages"][0];
    ADD_FAILURE() << "no region";
    static Json none;
    return none;
}

TEST_F(HostileProjectTest, TooManyPaintLayersAreRefusedBeforeAnyIsRead) {
    const std::string error = loadEdited([](Json& layerpaint) {
        Json& layers = layerpaint["paint_layers"]["layers"];
        const Json copy = layers[0];
        for (std::uint64_t id = 1000; layers.size() <= core::kMaxPaintLayers; ++id) {
            layers.push_back(copy);
            layers.back()["id"] = id;
        }
    });
    EXPECT_NE(error.find("1001 paint layers; at most 1000"), std::string::npos) << error;
}

TEST_F(HostileProjectTest, PaintLayersBeyondTheMemoryBudgetAreRefusedBeforeDecoding) {
    core::LoadLimits limits;
    limits.maxPaintLayerBytes = 64 * 1024; // less than the five layers' tiles
    const std::string error = loadEdited([](Json&) {}, limits);
    EXPECT_NE(error.find("too large for this machine's memory"), std::string::npos) << error;
    // The same project within the default budget opens.
    EXPECT_EQ(loadEdited([](Json&) {}), "");
}

TEST_F(HostileProjectTest, AnImageLargerThanItsRegionIsRefusedBeforeDecoding) {
    const std::string error = loadEdited([](Json& layerpaint) {
        Json& region = firstRegion(layerpaint);
        region["width"] = 1;
        region["height"] = 1;
    });
    // The decoder's check of the header against the size asked for: nothing was decoded.
    EXPECT_NE(error.find("paint layer image"), std::string::npos) << error;
    EXPECT_NE(error.find("too large"), std::string::npos) << error;
}

TEST_F(HostileProjectTest, AnImageUsedAtTwoSizesIsRefused) {
    const std::string error = loadEdited([](Json& layerpaint) {
        Json& base = layerpaint["paint_layers"]["base"];
        ASSERT_FALSE(base.empty());
        firstRegion(layerpaint)["image"] = base[0]["image"]; // a page-sized image
    });
    EXPECT_NE(error.find("used at two sizes"), std::string::npos) << error;
}

TEST_F(HostileProjectTest, NumbersBeyondTheirTypeAreRefusedNotWrapped) {
    // 2^32 + an index: read as 32 bits it would name a real image.
    std::string error = loadEdited([](Json& layerpaint) {
        Json& images = layerpaint["paint_layers"]["images"];
        images[0] = (std::uint64_t(1) << 32) + images[0].get<std::uint64_t>();
    });
    EXPECT_NE(error.find("buffer view number"), std::string::npos) << error;
    // A fill byte of 2^32 + 7.
    error = loadEdited([](Json& layerpaint) {
        for (Json& layer : layerpaint["paint_layers"]["layers"])
            if (layer.contains("channels") && layer["channels"].contains("base_color"))
                layer["channels"]["base_color"]["fill"][0] = (std::uint64_t(1) << 32) + 7;
    });
    EXPECT_NE(error.find("fill value that is not bytes"), std::string::npos) << error;
}

TEST_F(HostileProjectTest, ImagesNothingUsesAreNotDecoded) {
    // An extra image entry pointing at a buffer view that holds no image: never decoded, so the
    // project opens as before.
    EXPECT_EQ(
        loadEdited([](Json& layerpaint) { layerpaint["paint_layers"]["images"].push_back(0); }),
        "");
}

TEST_F(HostileProjectTest, JsonLayerPaintDoesNotReadIsSkippedAndItsOwnIsBounded) {
    // A member LayerPaint's state reading has no use for is skipped as it is parsed (the model
    // loader reads the whole file, in the sandboxed importer).
    const Json some = Json(std::vector<int>(200'000, 0));
    EXPECT_EQ(loadEditedRoot([&](Json& root) { root["extras"] = {{"junk", some}}; }), "");
    // More values under the state than it ever needs: refused instead of held.
    const Json many = Json(std::vector<int>(4'300'000, 0));
    const std::string error = loadEdited([&](Json& layerpaint) { layerpaint["junk"] = many; });
    EXPECT_NE(error.find("JSON values"), std::string::npos) << error;
}

TEST_F(PaintLayersProjectTest, ADocumentMakesNoMorePaintLayersThanAProjectHolds) {
    // Empty paint layers: adding one composites nothing (a fill layer would cover every texel).
    core::PaintChanges changes;
    for (std::size_t i = 0; i < core::kMaxPaintLayers; ++i)
        ASSERT_TRUE(m_doc.addPaintLayer({}, changes).ok()) << i;
    const core::Result<std::uint64_t> more = m_doc.addPaintLayer({}, changes);
    ASSERT_FALSE(more.ok());
    EXPECT_NE(more.error().find("the most a project can hold"), std::string::npos) << more.error();
}

} // namespace paint_layers_project_test
