// SPDX-License-Identifier: GPL-3.0-or-later
// UVs as loading judges them (core/model/uv_coverage.h): UVs that cover no area are dropped with
// a warning naming the file (assimp-testmodels' WusonOBJ.obj gives every corner one "vt"), UVs
// that mostly overlap are kept with a warning, and UVs laid apart load without one.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "core/io/mesh_io.h"
#include "tests/core/test_files.h"

namespace uv_coverage_load_test {

namespace fs = std::filesystem;
using core_test::TempDir;
using core_test::writeFile;

const fs::path kModels = LAYERPAINT_ASSIMP_MODELS;

/** The warning that contains text, or an empty string. */
std::string warningWith(const core::Mesh& mesh, const std::string& text) {
    const auto it =
        std::find_if(mesh.warnings.begin(), mesh.warnings.end(),
                     [&text](const std::string& w) { return w.find(text) != std::string::npos; });
    return it == mesh.warnings.end() ? std::string() : *it;
}

/** Two quads side by side in space; "vt" lines and the faces' UV indices as given. */
std::string twoQuads(const std::string& vts, const std::string& second) {
    return "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n" + vts +
           "f 1/1 2/2 3/3 4/4\nf " + second + "\n";
}

TEST(UvCoverageLoad, WusonObjsOneUvIsDroppedAndNamed) {
    const fs::path file = kModels / "OBJ/WusonOBJ.obj";
    if (!fs::exists(file))
        GTEST_SKIP() << "assimp-testmodels is not installed (" << file
                     << " is missing): scripts/install-deps.sh --test installs it";
    const core::Result<core::Mesh> mesh = core::loadMesh(file.string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_FALSE(mesh->hasUvs());
    const std::string warning = warningWith(*mesh, "cover no area");
    EXPECT_NE(warning.find("WusonOBJ.obj"), std::string::npos) << warning;
    EXPECT_NE(warning.find("automatic UV layout"), std::string::npos) << warning;
}

TEST(UvCoverageLoad, UvsOnALineAreDropped) {
    TempDir dir;
    const std::string model = dir.file("line.obj");
    writeFile(model, twoQuads("vt 0 0\nvt 0.5 0.5\nvt 1 1\nvt 0.25 0.25\n", "2/1 5/2 6/3 3/4"));
    const core::Result<core::Mesh> mesh = core::loadMesh(model);
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_FALSE(mesh->hasUvs());
    EXPECT_NE(warningWith(*mesh, "line.obj cover no area"), "");
}

TEST(UvCoverageLoad, MirroredUvsAreKeptWithAWarning) {
    TempDir dir;
    const std::string model = dir.file("mirrored.obj");
    // The second quad's UVs are the first's, mirrored.
    writeFile(model, twoQuads("vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n", "2/2 5/1 6/4 3/3"));
    const core::Result<core::Mesh> mesh = core::loadMesh(model);
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_TRUE(mesh->hasUvs());
    const std::string warning = warningWith(*mesh, "100% of the UV area of mirrored.obj");
    EXPECT_NE(warning.find("paints every overlapping place at once"), std::string::npos) << warning;
    EXPECT_EQ(warningWith(*mesh, "cover no area"), "");
}

TEST(UvCoverageLoad, UvsApartLoadWithoutAWarning) {
    TempDir dir;
    const std::string model = dir.file("apart.obj");
    writeFile(model,
              twoQuads("vt 0 0\nvt 0.5 0\nvt 0.5 1\nvt 0 1\nvt 1 0\nvt 1 1\n", "2/2 5/5 6/6 3/3"));
    const core::Result<core::Mesh> mesh = core::loadMesh(model);
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_TRUE(mesh->hasUvs());
    EXPECT_TRUE(mesh->warnings.empty()) << mesh->warnings.front();
}

} // namespace uv_coverage_load_test
