// SPDX-License-Identifier: GPL-3.0-or-later
// Real-world glTF: a small curved grid written as binary glTF uncompressed, with Draco
// (KHR_draco_mesh_compression) and with meshoptimizer (EXT_meshopt_compression over
// KHR_mesh_quantization data, a fallback buffer without data, the octahedral filter), made by
// gltf_files.h with the libraries' encoders and loaded through core::loadMesh (the importer
// process); plus KHR_texture_transform on the UVs, damaged compressed data, and glTF 1.0 through
// Assimp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "core/io/mesh_io.h"
#include "core/model/source_scene.h"
#include "tests/core/io/gltf_files.h"
#include "tests/core/test_files.h"

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace gltf_compression_test {

using core_test::gltf_files::Grid;
using core_test::gltf_files::makeGrid;
using core_test::gltf_files::writeDraco;
using core_test::gltf_files::writeMeshopt;
using core_test::gltf_files::writePlain;

/**
 * Checks that mesh is g up to vertex order: every vertex lies within posTol of one of g's (and
 * carries its UV within uvTol, its normal within 0.02), and the triangles are g's, same winding.
 */
void expectSameMesh(const core::Mesh& mesh, const Grid& g, float posTol, float uvTol) {
    ASSERT_EQ(mesh.triangleCount(), g.triangles());
    std::vector<std::uint32_t> toGrid(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        std::size_t best = 0;
        float bestD = 1e9f;
        for (std::size_t k = 0; k < g.vertices(); ++k) {
            const float d = glm::distance(
                mesh.positions[v], glm::vec3(g.pos[k * 3], g.pos[k * 3 + 1], g.pos[k * 3 + 2]));
            if (d < bestD) {
                bestD = d;
                best = k;
            }
        }
        ASSERT_LE(bestD, posTol) << "vertex " << v;
        toGrid[v] = std::uint32_t(best);
        EXPECT_NEAR(mesh.uvs[v].x, g.uv[best * 2], uvTol);
        EXPECT_NEAR(mesh.uvs[v].y, g.uv[best * 2 + 1], uvTol);
        const glm::vec3 want(g.nrm[best * 3], g.nrm[best * 3 + 1], g.nrm[best * 3 + 2]);
        EXPECT_GT(glm::dot(mesh.normals[v], want), 0.9995f) << "vertex " << v;
    }
    auto canonical = [](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        // the rotation starting at the smallest index keeps the winding
        if (b < a && b < c)
            return std::array<std::uint32_t, 3>{b, c, a};
        if (c < a && c < b)
            return std::array<std::uint32_t, 3>{c, a, b};
        return std::array<std::uint32_t, 3>{a, b, c};
    };
    std::multiset<std::array<std::uint32_t, 3>> want, got;
    for (std::size_t t = 0; t < g.idx.size(); t += 3)
        want.insert(canonical(g.idx[t], g.idx[t + 1], g.idx[t + 2]));
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
        got.insert(canonical(toGrid[mesh.indices[t]], toGrid[mesh.indices[t + 1]],
                             toGrid[mesh.indices[t + 2]]));
    EXPECT_TRUE(want == got);
}

/** The load fails with one line that starts with the file's name and contains what. */
void expectRefused(const fs::path& file, const std::string& what) {
    const core::Result<core::Mesh> mesh = core::loadMesh(file.string());
    ASSERT_FALSE(mesh.ok()) << file;
    EXPECT_EQ(mesh.error().rfind(file.string() + ": ", 0), 0u) << mesh.error();
    EXPECT_EQ(mesh.error().find('\n'), std::string::npos) << mesh.error();
    EXPECT_NE(mesh.error().find(what), std::string::npos) << mesh.error();
}

TEST(GltfCompression, PlainGridLoadsAsMade) {
    core_test::TempDir dir;
    const Grid g = makeGrid();
    ASSERT_TRUE(writePlain(g, dir.path() / "plain.glb"));
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "plain.glb").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    expectSameMesh(*mesh, g, 1e-6f, 1e-6f);
}

TEST(GltfCompression, DracoMatchesTheUncompressedMesh) {
    core_test::TempDir dir;
    const Grid g = makeGrid();
    ASSERT_TRUE(writeDraco(g, dir.path() / "draco.glb"));
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "draco.glb").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_TRUE(mesh->warnings.empty()) << mesh->warnings.front();
    // 12 bits over the longest side (2 units): a step of 2/4095, at most half of it per axis.
    expectSameMesh(*mesh, g, 2.0f / 4095.0f, 1.0f / 4095.0f);
}

TEST(GltfCompression, MeshoptQuantizedMatchesTheUncompressedMesh) {
    core_test::TempDir dir;
    const Grid g = makeGrid();
    ASSERT_TRUE(writeMeshopt(g, dir.path() / "meshopt.glb"));
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "meshopt.glb").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_TRUE(mesh->warnings.empty()) << mesh->warnings.front();
    // 16-bit positions through the node transform, 16-bit normalized UVs.
    expectSameMesh(*mesh, g, 2.0f / 65535.0f, 1.0f / 65535.0f);
    // Its fallback buffers hold no data: saving cannot write the scene back, and says why.
    ASSERT_TRUE(mesh->source);
    EXPECT_NE(mesh->source->notKept.find("EXT_meshopt_compression"), std::string::npos);
}

TEST(GltfCompression, TextureTransformMovesTheUvs) {
    core_test::TempDir dir;
    const Grid g = makeGrid(4);
    // The extension's own example: the lower left quarter of the image, turned.
    const Json transform = {
        {"offset", {0.0, 1.0}}, {"rotation", std::numbers::pi / 2}, {"scale", {0.5, 0.5}}};
    ASSERT_TRUE(
        writePlain(g, dir.path() / "transform.glb",
                   {{"pbrMetallicRoughness",
                     {{"baseColorTexture",
                       {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}}));
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "transform.glb").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    ASSERT_EQ(mesh->uvs.size(), g.vertices());
    for (std::size_t v = 0; v < g.vertices(); ++v) {
        const float u = g.uv[v * 2], w = g.uv[v * 2 + 1];
        EXPECT_NEAR(mesh->uvs[v].x, 0.5f * w, 1e-6f);
        EXPECT_NEAR(mesh->uvs[v].y, 1.0f - 0.5f * u, 1e-6f);
        EXPECT_TRUE(mesh->uvs[v].x >= 0.0f && mesh->uvs[v].x <= 0.5f);
        EXPECT_TRUE(mesh->uvs[v].y >= 0.5f && mesh->uvs[v].y <= 1.0f);
    }
}

TEST(GltfCompression, TextureTransformTexCoordPicksTheSetAndDisagreementWarns) {
    core_test::TempDir dir;
    const Grid g = makeGrid(4);
    const Json base = {{"offset", {0.25, 0.0}}, {"scale", {0.5, 2.0}}, {"texCoord", 1}};
    const Json mr = {{"offset", {0.0, 0.5}}};
    ASSERT_TRUE(writePlain(
        g, dir.path() / "texcoord.glb",
        {{"pbrMetallicRoughness",
          {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", base}}}}},
           {"metallicRoughnessTexture",
            {{"index", 0}, {"extensions", {{"KHR_texture_transform", mr}}}}}}}}));
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "texcoord.glb").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    for (std::size_t v = 0; v < g.vertices(); ++v) {
        // TEXCOORD_1 is the mirrored set.
        EXPECT_NEAR(mesh->uvs[v].x, 0.25f + 0.5f * (1.0f - g.uv[v * 2]), 1e-6f);
        EXPECT_NEAR(mesh->uvs[v].y, 2.0f * (1.0f - g.uv[v * 2 + 1]), 1e-6f);
    }
    const auto warned =
        std::count_if(mesh->warnings.begin(), mesh->warnings.end(), [](const std::string& w) {
            return w.find("metallic-roughness") != std::string::npos;
        });
    EXPECT_EQ(warned, 1);
}

TEST(GltfCompression, DamagedDracoIsRefusedNamingTheFile) {
    core_test::TempDir dir;
    const Grid g = makeGrid();
    ASSERT_TRUE(writeDraco(g, dir.path() / "cut.glb", 40));
    expectRefused(dir.path() / "cut.glb", "Draco");
    ASSERT_TRUE(writeDraco(g, dir.path() / "count.glb", 0, g.vertices() + 7));
    expectRefused(dir.path() / "count.glb", "the Draco data holds 81 vertices");
}

TEST(GltfCompression, DamagedMeshoptIsRefusedNamingTheFile) {
    core_test::TempDir dir;
    const Grid g = makeGrid();
    ASSERT_TRUE(writeMeshopt(g, dir.path() / "cut.glb", 0, 20));
    expectRefused(dir.path() / "cut.glb", "cannot be decoded");
    ASSERT_TRUE(writeMeshopt(g, dir.path() / "count.glb", 3));
    expectRefused(dir.path() / "count.glb", "byteLength");
}

TEST(GltfCompression, Gltf1TextGoesToAssimp) {
    const fs::path models = LAYERPAINT_ASSIMP_MODELS;
    for (const char* rel :
         {"glTF/BoxTextured-glTF/BoxTextured.gltf",
          "glTF/BoxTextured-glTF-Embedded/BoxTextured.gltf",
          "glTF/BoxTextured-glTF-MaterialsCommon/BoxTextured.gltf",
          "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", "glTF/IncorrectVertexArrays/Cube_v1.gltf",
          "glTF/TwoBoxes/TwoBoxes.gltf"}) {
        const core::Result<core::Mesh> mesh = core::loadMesh((models / rel).string());
        ASSERT_TRUE(mesh.ok()) << rel << ": " << mesh.error();
        EXPECT_GT(mesh->triangleCount(), 0u) << rel;
        EXPECT_TRUE(mesh->validate().ok()) << rel;
    }
    const core::Result<core::Mesh> box =
        core::loadMesh((models / "glTF/BoxTextured-glTF/BoxTextured.gltf").string());
    ASSERT_TRUE(box.ok());
    EXPECT_EQ(box->triangleCount(), 12u);
    EXPECT_EQ(box->textures.size(), 1u);
    // Binary glTF 1.0: neither tinygltf nor Assimp 5.2 reads it; one line names the file.
    expectRefused(models / "glTF/BoxTextured-glTF-Binary/BoxTextured.glb", "version 1");
}

TEST(GltfCompression, DracoSampleFromTheCorpusLoads) {
    const fs::path models = LAYERPAINT_ASSIMP_MODELS;
    const core::Result<core::Mesh> draco =
        core::loadMesh((models / "glTF2/draco/2CylinderEngine.gltf").string());
    ASSERT_TRUE(draco.ok()) << draco.error();
    const core::Result<core::Mesh> plain =
        core::loadMesh((models / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb").string());
    ASSERT_TRUE(plain.ok()) << plain.error();
    // Draco's encoder drops degenerate triangles (two corners at one position).
    std::size_t degenerate = 0;
    for (std::size_t t = 0; t < plain->indices.size(); t += 3) {
        const glm::vec3 a = plain->positions[plain->indices[t]];
        const glm::vec3 b = plain->positions[plain->indices[t + 1]];
        const glm::vec3 c = plain->positions[plain->indices[t + 2]];
        degenerate += (a == b || b == c || a == c) ? 1 : 0;
    }
    EXPECT_EQ(draco->triangleCount(), plain->triangleCount() - degenerate);
}

const fs::path kData = LAYERPAINT_TEST_DATA;

/**
 * The committed files (fuzz seeds and the crash corpus) are still what the encoders make of the
 * 5 × 5 grid, and load or fail as they should. tests/tools/make_gltf_compression_data.cpp writes
 * them (scripts/make-gltf-compression-data.sh builds and runs it over tests/data).
 */
TEST(GltfCompression, CommittedFilesLoadOrFail) {
    const Grid g = makeGrid(5);
    for (const char* name : {"grid-draco.glb", "grid-meshopt.glb"}) {
        const core::Result<core::Mesh> mesh = core::loadMesh((kData / "gltf" / name).string());
        ASSERT_TRUE(mesh.ok()) << mesh.error();
        expectSameMesh(*mesh, g, 2.0f / 4095.0f, 1.0f / 4095.0f);
    }
    expectRefused(kData / "crashers/glb-draco-truncated.glb", "Draco");
    expectRefused(kData / "crashers/glb-meshopt-wrong-count.glb", "byteLength");
}

} // namespace gltf_compression_test
