// SPDX-License-Identifier: GPL-3.0-or-later
// The automatic UV layout in files: a project keeps the generated UVs (TEXCOORD_0), so
// reopening paints the same texels without laying out again; exports (glb, obj, ply) write them.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/depth/cpu_capture.h"
#include "core/document/document.h"
#include "core/io/export.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/model/builtin_models.h"
#include "tests/core/test_files.h"

namespace layout_project_test {

using core_test::TempDir;

/** A small trefoil without UVs (the built-in one has them). */
core::Mesh trefoilWithoutUvs() {
    core::Mesh mesh = core::makeTrefoil(60, 16);
    mesh.uvs.clear();
    return mesh;
}

/** One stroke across the middle of the model's default view. */
void paintAStroke(core::Document& doc) {
    constexpr int kWidth = 240, kHeight = 180;
    doc.camera() = core::Camera::fromOrbit(doc.mesh().bounds(), 30.0f, 20.0f, 1.6f);
    core::CpuDepthCapturer capturer;
    capturer.setMesh(doc.mesh());
    ASSERT_TRUE(doc.buildDepthLayers(capturer, doc.camera().view(kWidth, kHeight)).ok());
    const core::DepthStack& stack = doc.depthLayers()->stack;
    const int y = kHeight / 2;
    int first = -1, last = -1;
    for (int x = 0; x < kWidth; ++x)
        if (stack.layerCount(std::size_t(y) * kWidth + std::size_t(x)) > 0) {
            first = first < 0 ? x : first;
            last = x;
        }
    ASSERT_GT(last - first, 20);
    doc.brush().color = {0.9f, 0.2f, 0.1f, 1.0f};
    doc.brush().radius = 8.0f;
    core::PaintChanges changes;
    ASSERT_TRUE(doc.beginStroke({{float(first) + 2.5f, float(y) + 0.5f}, 1.0f}, changes).ok());
    for (int x = first + 4; x < last - 2; x += 3)
        doc.moveStroke({{float(x) + 0.5f, float(y) + 0.5f}, 1.0f}, changes);
    doc.endStroke();
}

/** The trefoil without UVs in doc, a 512² texture over its automatic layout, one stroke on it. */
void paintOverAGeneratedLayout(core::Document& doc) {
    doc.setMesh(trefoilWithoutUvs(), "trefoil.obj");
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::Texture;
    options.resolution = 512;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    paintAStroke(doc);
}

const core::TextureTarget* textureOf(core::Document& doc) {
    return dynamic_cast<const core::TextureTarget*>(doc.paintTarget());
}

TEST(LayoutProject, ReopeningKeepsTheGeneratedUvsAndThePaint) {
    TempDir dir;
    core::Document doc;
    ASSERT_NO_FATAL_FAILURE(paintOverAGeneratedLayout(doc));
    const core::TextureTarget* texture = textureOf(doc);
    ASSERT_NE(texture, nullptr);
    const core::Mesh laidOut = texture->mesh();
    ASSERT_TRUE(laidOut.hasUvs());
    const std::vector<std::uint8_t> painted = texture->page(0).rgba;

    const std::string path = dir.file("painted.glb");
    const core::Status saved = core::saveProject(path, doc, core::captureProjectState(doc));
    ASSERT_TRUE(saved.ok()) << saved.error();

    core::Result<core::Project> project = core::loadProject(path);
    ASSERT_TRUE(project.ok()) << project.error();
    ASSERT_TRUE(project->state.has_value());
    // The file holds the layout's vertices and UVs (TEXCOORD_0), triangle for triangle.
    EXPECT_EQ(project->mesh.uvs, laidOut.uvs);
    EXPECT_EQ(project->mesh.indices, laidOut.indices);
    core::Document reopened;
    reopened.setMesh(std::move(project->mesh), path);
    ASSERT_TRUE(core::applyProjectState(reopened, *project->state).ok());
    // No new layout: the target paints the stored UVs and the stored page.
    const core::TextureTarget* again = textureOf(reopened);
    ASSERT_NE(again, nullptr);
    EXPECT_EQ(&again->mesh(), &reopened.mesh()) << "the reopened target is over the file's mesh";
    EXPECT_EQ(again->mesh().uvs, laidOut.uvs);
    ASSERT_EQ(again->pageCount(), 1u);
    EXPECT_EQ(again->page(0).rgba, painted);
}

TEST(LayoutProject, ExportsWriteTheGeneratedUvs) {
    TempDir dir;
    core::Document doc;
    ASSERT_NO_FATAL_FAILURE(paintOverAGeneratedLayout(doc));
    const core::Mesh painted = doc.paintedMesh();
    ASSERT_TRUE(painted.hasUvs());

    for (const core::ExportFormat format :
         {core::ExportFormat::Glb, core::ExportFormat::Obj, core::ExportFormat::Ply}) {
        const std::string path = dir.file(std::string("out") + core::exportExtension(format));
        const auto written = core::exportMesh(path, format, painted);
        ASSERT_TRUE(written.ok()) << written.error();
        core::Result<core::Mesh> back = core::loadMesh(path);
        ASSERT_TRUE(back.ok()) << back.error();
        ASSERT_TRUE(back->hasUvs()) << path;
        ASSERT_EQ(back->triangleCount(), painted.triangleCount()) << path;
        // Each triangle corner keeps its UV (loaders may re-index vertices).
        for (std::size_t i = 0; i < painted.indices.size(); ++i) {
            const glm::vec2 want = painted.uvs[painted.indices[i]];
            const glm::vec2 got = back->uvs[back->indices[i]];
            ASSERT_NEAR(got.x, want.x, 1e-6f) << path << " corner " << i;
            ASSERT_NEAR(got.y, want.y, 1e-6f) << path << " corner " << i;
        }
    }
}

} // namespace layout_project_test
