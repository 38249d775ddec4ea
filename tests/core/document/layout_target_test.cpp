// SPDX-License-Identifier: GPL-3.0-or-later
// A texture target on a mesh without UVs: the document makes the automatic UV layout (progress,
// cancel, deterministic), paints over it, undoes and redoes the choice, replays it as a script
// operation; and the rule that picks the default target for such a mesh.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "core/depth/cpu_capture.h"
#include "core/document/document.h"
#include "core/document/script.h"
#include "core/model/builtin_models.h"
#include "core/paint/targets/layout_target.h"
#include "tests/core/script_host.h"
#include "tests/core/test_scenes.h"

namespace layout_target_test {

using core_test::pixelView;

/**
 * A box in window pixels (front face toward the camera at depth 4, 40 px deep), eight shared
 * vertices, no UVs: a coarse mesh whose vertex colours cannot hold a stroke.
 */
core::Mesh coarseBox() {
    core::Mesh mesh;
    mesh.materials = {{"grey", glm::vec4(0.5f, 0.5f, 0.5f, 1.0f), -1}};
    const float x0 = 10, x1 = 70, y0 = 10, y1 = 50, z0 = -4, z1 = -44;
    for (int i = 0; i < 8; ++i)
        mesh.positions.push_back({(i & 1) ? x1 : x0, (i & 2) ? y1 : y0, (i & 4) ? z1 : z0});
    // Faces wound clockwise in window coordinates as seen from outside (front-facing here).
    const std::uint32_t faces[6][4] = {{0, 1, 3, 2}, {5, 4, 6, 7}, {4, 0, 2, 6},
                                       {1, 5, 7, 3}, {4, 5, 1, 0}, {2, 3, 7, 6}};
    for (const auto& f : faces) {
        mesh.indices.insert(mesh.indices.end(), {f[0], f[2], f[1], f[0], f[3], f[2]});
        mesh.triangleMaterial.insert(mesh.triangleMaterial.end(), {0u, 0u});
    }
    mesh.computeNormals();
    return mesh;
}

core::PaintTargetOptions textureOptions() {
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::Texture;
    options.resolution = 512;
    return options;
}

TEST(LayoutTarget, TextureOnAMeshWithoutUvsMakesTheLayoutAsAnUndoableStep) {
    core::Document doc;
    doc.setMesh(coarseBox(), "box");
    ASSERT_FALSE(doc.mesh().hasUvs());
    core::PaintTargetOptions colours;
    colours.kind = core::PaintTargetKind::VertexColors;
    ASSERT_TRUE(doc.setPaintTarget(colours).ok());
    ASSERT_EQ(doc.paintTarget()->kind(), core::PaintTargetKind::VertexColors);

    std::vector<double> progress;
    const core::Status status = doc.setPaintTarget(textureOptions(), [&](double f) {
        progress.push_back(f);
        return true;
    });
    ASSERT_TRUE(status.ok()) << status.error();
    ASSERT_GE(progress.size(), 2u);
    for (std::size_t i = 1; i < progress.size(); ++i)
        EXPECT_GE(progress[i], progress[i - 1]);
    EXPECT_DOUBLE_EQ(progress.back(), 1.0);

    // The target's mesh is the box with UVs: seams split vertices, triangles keep their corners.
    const core::PaintTarget* target = doc.paintTarget();
    ASSERT_EQ(target->kind(), core::PaintTargetKind::Texture);
    const core::Mesh& laid = target->mesh();
    const core::Mesh& box = doc.mesh();
    EXPECT_FALSE(box.hasUvs()) << "the document's own mesh is what was loaded";
    ASSERT_TRUE(laid.hasUvs());
    EXPECT_GT(laid.positions.size(), box.positions.size());
    ASSERT_EQ(laid.triangleCount(), box.triangleCount());
    for (std::size_t i = 0; i < box.indices.size(); ++i)
        ASSERT_EQ(laid.positions[laid.indices[i]], box.positions[box.indices[i]]) << i;
    const core::Mesh painted = doc.paintedMesh();
    EXPECT_TRUE(painted.hasUvs());
    ASSERT_EQ(painted.textures.size(), 1u);
    EXPECT_EQ(painted.textures[0].width, 512);

    // A stroke paints the page.
    core::CpuDepthCapturer capturer;
    capturer.setMesh(doc.mesh());
    ASSERT_TRUE(doc.buildDepthLayers(capturer, pixelView(80, 60)).ok());
    doc.brush().color = {1.0f, 0.0f, 0.0f, 1.0f};
    doc.brush().radius = 6.0f;
    core::PaintChanges changes;
    ASSERT_TRUE(doc.beginStroke({{30.0f, 30.0f}, 1.0f}, changes).ok());
    doc.moveStroke({{50.0f, 30.0f}, 1.0f}, changes);
    doc.endStroke();
    const auto* texture = dynamic_cast<const core::TextureTarget*>(doc.paintTarget());
    ASSERT_NE(texture, nullptr);
    std::size_t red = 0;
    const core::Image& page = texture->page(0);
    for (std::size_t i = 0; i < page.rgba.size(); i += 4)
        red += page.rgba[i] == 255 && page.rgba[i + 1] == 0 ? 1 : 0;
    EXPECT_GT(red, 100u);
    EXPECT_EQ(doc.pickColor(30 * 80 + 40).value_or(glm::vec4(0.0f)).r, 1.0f);

    // Undo the stroke, then the choice: vertex colours again, on the mesh as loaded.
    ASSERT_TRUE(doc.undo(changes));
    ASSERT_TRUE(doc.undo(changes));
    EXPECT_EQ(doc.paintTarget()->kind(), core::PaintTargetKind::VertexColors);
    EXPECT_FALSE(doc.paintedMesh().hasUvs());
    ASSERT_TRUE(doc.redo(changes));
    EXPECT_EQ(doc.paintTarget()->kind(), core::PaintTargetKind::Texture);
    EXPECT_EQ(doc.paintedMesh().uvs, laid.uvs);
}

TEST(LayoutTarget, CancelLeavesTheTargetAsItWas) {
    core::Document doc;
    doc.setMesh(coarseBox(), "box");
    ASSERT_NE(doc.paintTarget(), nullptr);
    const std::uint64_t serial = doc.paintTargetSerial();
    int calls = 0;
    const core::Status status =
        doc.setPaintTarget(textureOptions(), [&](double) { return ++calls < 2; });
    EXPECT_TRUE(status.cancelled()) << status.error();
    EXPECT_EQ(doc.paintTargetSerial(), serial);
    EXPECT_EQ(doc.paintTarget()->kind(), core::PaintTargetKind::VertexColors);
    EXPECT_FALSE(doc.history().canUndo());
}

TEST(LayoutTarget, SameLayoutEveryTimeAndAdoptedOnlyForItsMesh) {
    const auto mesh = std::make_shared<const core::Mesh>(coarseBox());
    auto a = core::makePaintTargetWithLayout(mesh, nullptr, textureOptions());
    auto b = core::makePaintTargetWithLayout(mesh, nullptr, textureOptions());
    ASSERT_TRUE(a.ok()) << a.error();
    ASSERT_TRUE(b.ok()) << b.error();
    EXPECT_EQ(a.value()->mesh().uvs, b.value()->mesh().uvs);
    EXPECT_EQ(a.value()->mesh().indices, b.value()->mesh().indices);

    core::Document doc;
    doc.setMesh(coarseBox(), "box");
    const std::uint64_t made = doc.meshSerial();
    doc.setMesh(coarseBox(), "box again");
    EXPECT_FALSE(doc.adoptPaintTarget(std::move(a).value(), textureOptions(), made).ok());
    EXPECT_TRUE(
        doc.adoptPaintTarget(std::move(b).value(), textureOptions(), doc.meshSerial()).ok());
    EXPECT_TRUE(doc.paintedMesh().hasUvs());
}

TEST(LayoutTarget, TheTargetMadeWithTheModelIsReplacedWithoutAnUndoStepUntilUsed) {
    const auto mesh = std::make_shared<const core::Mesh>(core::makeHexRing());
    ASSERT_TRUE(mesh->hasUvs());
    auto made = core::makePaintTargetWithLayout(mesh, nullptr, textureOptions());
    ASSERT_TRUE(made.ok()) << made.error();
    core::Document doc;
    // Only for the document's own mesh, the very object.
    doc.setMesh(core::makeHexRing(), "copy");
    EXPECT_FALSE(doc.adoptModelPaintTarget(std::move(made).value(), textureOptions()).ok());
    EXPECT_FALSE(doc.hasPaintTarget());
    doc.setMesh(mesh, "ring", nullptr);
    made = core::makePaintTargetWithLayout(mesh, nullptr, textureOptions());
    ASSERT_TRUE(doc.adoptModelPaintTarget(std::move(made).value(), textureOptions()).ok());
    ASSERT_TRUE(doc.hasPaintTarget());
    EXPECT_EQ(&doc.paintTarget()->mesh(), mesh.get());
    // Chosen away before anything was done: as if no target had been made.
    core::PaintTargetOptions colours;
    colours.kind = core::PaintTargetKind::VertexColors;
    ASSERT_TRUE(doc.setPaintTarget(colours).ok());
    EXPECT_FALSE(doc.history().canUndo());
    // Any other target is a step when replaced.
    ASSERT_TRUE(doc.setPaintTarget(textureOptions()).ok());
    EXPECT_TRUE(doc.history().canUndo());
}

TEST(LayoutTarget, ScriptOperationSetTargetTextureMakesTheLayout) {
    core::Document doc;
    doc.setMesh(coarseBox(), "box");
    ASSERT_NE(doc.paintTarget(), nullptr); // vertex colours, the target the script replaces
    core_test::CpuScriptHost host;
    core::ScriptRunner runner(doc, host, pixelView(80, 60));
    const core::Status status =
        runner.run(nlohmann::json{{"op", "set-target"}, {"kind", "texture"}, {"resolution", 512}});
    ASSERT_TRUE(status.ok()) << status.error();
    EXPECT_EQ(doc.paintTarget()->kind(), core::PaintTargetKind::Texture);
    EXPECT_TRUE(doc.paintedMesh().hasUvs());
    ASSERT_TRUE(runner.run(nlohmann::json{{"op", "undo"}}).ok());
    EXPECT_FALSE(doc.paintedMesh().hasUvs());
}

TEST(LayoutTarget, DefaultIsATextureWhereVertexColoursWouldBeCoarse) {
    // Eight vertices: a dab covers a sliver of one face.
    const core::Mesh box = coarseBox();
    EXPECT_GT(core::vertexSpacingPixels(box), 100.0);
    EXPECT_EQ(core::defaultTargetKind(box, 32.0f), core::PaintTargetKind::Texture);
    // The trefoil's 144K vertices are a few pixels apart in the default view.
    core::Mesh dense = core::makeTrefoil();
    dense.uvs.clear();
    const double spacing = core::vertexSpacingPixels(dense);
    EXPECT_GT(spacing, 0.5);
    EXPECT_LT(spacing, 8.0);
    EXPECT_EQ(core::defaultTargetKind(dense, 32.0f), core::PaintTargetKind::VertexColors);
    // A tiny brush resolves finer than those vertices.
    EXPECT_EQ(core::defaultTargetKind(dense, 4.0f * float(spacing) - 1.0f),
              core::PaintTargetKind::Texture);
    // With UVs there is nothing to decide.
    EXPECT_EQ(core::defaultTargetKind(core::makeTrefoil(40, 12), 32.0f),
              core::PaintTargetKind::Texture);
    core::Document doc;
    doc.setMesh(std::move(dense), "trefoil");
    EXPECT_EQ(doc.suggestedPaintTargetKind(), core::PaintTargetKind::VertexColors);
}

/** coarseBox() with UVs that put all six faces on the same square (every face painted at once). */
core::Mesh stackedBox() {
    core::Mesh mesh = coarseBox();
    // Unshared corners, so that every face gets the whole square.
    core::Mesh split;
    split.materials = mesh.materials;
    const glm::vec2 corners[6] = {{0, 0}, {1, 1}, {1, 0}, {0, 0}, {0, 1}, {1, 1}};
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        split.positions.push_back(mesh.positions[mesh.indices[i]]);
        split.uvs.push_back(corners[i % 6]);
        split.indices.push_back(std::uint32_t(i));
    }
    split.triangleMaterial = mesh.triangleMaterial;
    split.computeNormals();
    return split;
}

TEST(LayoutTarget, AutomaticUvsOnAMeshWithUvsLayOutAnywayAndOnlyWhenAsked) {
    core::Document doc;
    doc.setMesh(stackedBox(), "stacked box");
    ASSERT_TRUE(doc.mesh().hasUvs());
    // Today's default stays: a mesh with UVs paints its own UVs.
    EXPECT_FALSE(core::needsUvLayout(doc.mesh(), textureOptions()));
    ASSERT_TRUE(doc.setPaintTarget(textureOptions()).ok());
    EXPECT_EQ(doc.paintedMesh().uvs, doc.mesh().uvs);

    core::PaintTargetOptions automatic = textureOptions();
    automatic.automaticUvs = true;
    EXPECT_TRUE(core::needsUvLayout(doc.mesh(), automatic));
    const core::Status status = doc.setPaintTarget(automatic);
    ASSERT_TRUE(status.ok()) << status.error();
    EXPECT_TRUE(doc.paintTargetOptions().automaticUvs);
    const core::Mesh painted = doc.paintedMesh();
    ASSERT_TRUE(painted.hasUvs());
    EXPECT_NE(painted.uvs, doc.mesh().uvs); // the layout's, faces apart
    EXPECT_EQ(painted.triangleCount(), doc.mesh().triangleCount());
    core::PaintChanges changes;
    ASSERT_TRUE(doc.undo(changes));
    EXPECT_EQ(doc.paintedMesh().uvs, doc.mesh().uvs);
}

TEST(LayoutTarget, ScriptTargetsNameAutomaticUvs) {
    core::Document doc;
    doc.setMesh(stackedBox(), "stacked box");
    core_test::CpuScriptHost host;
    core::ScriptRunner runner(doc, host, pixelView(80, 60));
    const core::Status status = runner.run(nlohmann::json{
        {"op", "set-target"}, {"kind", "texture"}, {"resolution", 512}, {"automatic_uvs", true}});
    ASSERT_TRUE(status.ok()) << status.error();
    EXPECT_NE(doc.paintedMesh().uvs, doc.mesh().uvs);
    EXPECT_FALSE(runner
                     .run(nlohmann::json{
                         {"op", "set-target"}, {"kind", "texture"}, {"automatic_uvs", "yes"}})
                     .ok());
    core::Script script;
    script.target = core::PaintTargetOptions{};
    script.target->automaticUvs = true;
    const core::Result<core::Script> back = core::parseScript(core::scriptToJson(script));
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_TRUE(back->target->automaticUvs);
}

TEST(LayoutTarget, TexturePageSizesAreTheTexturesOwnWhereAMaterialHasOne) {
    core::Mesh mesh = stackedBox();
    core::Image small;
    small.width = 256;
    small.height = 128;
    small.rgba.assign(std::size_t(256) * 128 * 4, 255);
    mesh.textures.push_back(small);
    mesh.materials.push_back(core::Material{"textured", glm::vec4(1.0f), 0});
    core::PaintTargetOptions options = textureOptions();
    options.resolution = 1024;
    const std::vector<core::PageSize> sizes = core::texturePageSizes(mesh, options);
    ASSERT_EQ(sizes.size(), 2u);
    EXPECT_EQ(sizes[0], (core::PageSize{1024, 1024})); // no texture: the resolution
    EXPECT_EQ(sizes[1], (core::PageSize{256, 128}));   // its own texture's size
    // The target made paints at those sizes.
    mesh.triangleMaterial[0] = 1;
    auto target =
        core::makePaintTargetWithLayout(std::make_shared<const core::Mesh>(mesh), nullptr, options);
    ASSERT_TRUE(target.ok()) << target.error();
    ASSERT_EQ(target.value()->pageCount(), 2u);
    std::vector<core::PageSize> made;
    for (std::size_t p = 0; p < 2; ++p)
        made.push_back({target.value()->page(p).width, target.value()->page(p).height});
    EXPECT_NE(std::find(made.begin(), made.end(), sizes[0]), made.end());
    EXPECT_NE(std::find(made.begin(), made.end(), sizes[1]), made.end());
    // An automatic layout paints one new page for all.
    options.automaticUvs = true;
    EXPECT_EQ(core::texturePageSizes(mesh, options),
              std::vector<core::PageSize>(2, core::PageSize{1024, 1024}));
    mesh.uvs.clear();
    options.automaticUvs = false;
    EXPECT_EQ(core::texturePageSizes(mesh, options),
              std::vector<core::PageSize>(2, core::PageSize{1024, 1024}));
}

} // namespace layout_target_test
