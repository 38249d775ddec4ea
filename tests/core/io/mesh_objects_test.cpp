// SPDX-License-Identifier: GPL-3.0-or-later
// A model's named objects (Mesh::objects: OBJ objects and groups, glTF nodes) are read from the
// file, cross the importer, and come out again in OBJ ("o" lines) and flattened glb exports (a
// node and mesh each) and in projects, so an OBJ asset keeps its parts through a session.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/document/document.h"
#include "core/io/export.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/paint/targets/paint_target.h"
#include "tests/core/test_files.h"

namespace mesh_objects_test {

namespace fs = std::filesystem;
using core_test::TempDir;
using core_test::writeFile;

const fs::path kModels = LAYERPAINT_ASSIMP_MODELS;

core::Mesh load(const std::string& path) {
    core::Result<core::Mesh> mesh = core::loadMesh(path);
    EXPECT_TRUE(mesh.ok()) << mesh.error();
    return mesh.ok() ? std::move(mesh).value() : core::Mesh{};
}

void expectSameObjects(const core::Mesh& a, const core::Mesh& b, const std::string& what) {
    ASSERT_EQ(a.triangleCount(), b.triangleCount()) << what;
    ASSERT_EQ(a.objects.size(), b.objects.size()) << what;
    for (std::size_t o = 0; o < a.objects.size(); ++o) {
        EXPECT_EQ(a.objects[o].name, b.objects[o].name) << what << " object " << o;
        EXPECT_EQ(a.objects[o].firstTriangle, b.objects[o].firstTriangle) << what << " " << o;
    }
}

TEST(MeshObjects, AnObjsGroupsAreItsObjects) {
    const fs::path spider = kModels / "OBJ/spider.obj";
    if (!fs::exists(spider))
        GTEST_SKIP() << spider << " is missing (apt-get install assimp-testmodels)";
    const core::Mesh mesh = load(spider.string());
    ASSERT_EQ(mesh.objects.size(), 19u); // its 19 "g" lines
    EXPECT_EQ(mesh.objects.front().name, "HLeib01");
    EXPECT_EQ(mesh.objects.front().firstTriangle, 0u);
    EXPECT_EQ(mesh.objects[1].name, "OK");
    EXPECT_EQ(mesh.objects[1].firstTriangle, 80u);
    EXPECT_EQ(mesh.objects.back().name, "Duplicate05");
}

TEST(MeshObjects, ObjAndGlbExportsAndProjectsKeepThem) {
    const fs::path spider = kModels / "OBJ/spider.obj";
    if (!fs::exists(spider))
        GTEST_SKIP() << spider << " is missing (apt-get install assimp-testmodels)";
    const core::Mesh mesh = load(spider.string());
    ASSERT_FALSE(mesh.objects.empty());
    TempDir dir;
    for (const auto& [name, format] : {std::pair{"spider.obj", core::ExportFormat::Obj},
                                       std::pair{"spider.glb", core::ExportFormat::Glb}}) {
        const std::string out = dir.file(name);
        const auto written = core::exportMesh(out, format, mesh);
        ASSERT_TRUE(written.ok()) << written.error();
        expectSameObjects(mesh, load(out), name);
    }

    // A painted project of the OBJ reopens with its objects.
    core::Document doc;
    doc.setMesh(mesh, spider.string());
    core::PaintTargetOptions options;
    options.resolution = 512;
    ASSERT_TRUE(doc.setPaintTarget(options).ok());
    const std::string project = dir.file("spider-project.glb");
    ASSERT_TRUE(core::saveProject(project, doc, core::captureProjectState(doc)).ok());
    const core::Result<core::Project> reopened = core::loadProject(project);
    ASSERT_TRUE(reopened.ok()) << reopened.error();
    expectSameObjects(mesh, reopened->mesh, "project");
}

TEST(MeshObjects, UnnamedPartsJoinAndAFileWithoutNamesHasNone) {
    TempDir dir;
    const std::string quads = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
    const std::string named = dir.file("named.obj");
    // Two objects of one name in a row are one; the control character becomes a space.
    writeFile(named, quads + "o Lid\nf 1 2 3\no Lid\nf 1 3 4\no Handle\x01Left\nf 4 3 1\n");
    const core::Mesh mesh = load(named);
    ASSERT_EQ(mesh.objects.size(), 2u);
    EXPECT_EQ(mesh.objects[0].name, "Lid");
    EXPECT_EQ(mesh.objects[1].name, "Handle Left");
    EXPECT_EQ(mesh.objects[1].firstTriangle, 2u);

    const std::string plain = dir.file("plain.obj");
    writeFile(plain, quads + "f 1 2 3\nf 1 3 4\n");
    EXPECT_TRUE(load(plain).objects.empty());
}

} // namespace mesh_objects_test
