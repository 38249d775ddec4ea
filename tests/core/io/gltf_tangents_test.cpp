// SPDX-License-Identifier: GPL-3.0-or-later
// A glTF file's own tangents (TANGENT) reach the mesh through the importer: placed by the node's
// transform (a mirroring one turns w), drawn instead of the computed ones, and ignored where
// glTF says so (no normals, no normal map).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/io/mesh_io.h"
#include "core/model/mesh_tangents.h"
#include "tests/core/io/gltf_files.h"
#include "tests/core/test_files.h"

namespace gltf_tangents_test {

namespace gf = core_test::gltf_files;
using gf::Json;

/** A grid whose TANGENT points along +y (w = -1), unlike the +u (x) direction of its UVs. */
struct TangentFile {
    gf::Grid grid = gf::makeGrid(5);
    Json material = {{"normalTexture", {{"index", 0}}}};
    bool withNormals = true;
    Json node = Json::object();

    bool write(const std::string& path) const {
        gf::Glb glb;
        const auto add = [&glb](const std::vector<float>& values, const char* type,
                                std::size_t count) {
            const std::size_t bytes = values.size() * 4;
            return glb.accessor(glb.view(glb.append(values.data(), bytes), bytes), gf::kFloat,
                                count, type);
        };
        std::vector<float> tangents;
        for (std::size_t v = 0; v < grid.vertices(); ++v)
            tangents.insert(tangents.end(), {0.0f, 1.0f, 0.0f, -1.0f});
        Json attributes = {{"POSITION", add(grid.pos, "VEC3", grid.vertices())},
                           {"TEXCOORD_0", add(grid.uv, "VEC2", grid.vertices())},
                           {"TANGENT", add(tangents, "VEC4", grid.vertices())}};
        if (withNormals)
            attributes["NORMAL"] = add(grid.nrm, "VEC3", grid.vertices());
        const std::size_t indexBytes = grid.idx.size() * 4;
        const int indices =
            glb.accessor(glb.view(glb.append(grid.idx.data(), indexBytes), indexBytes), gf::kUInt,
                         grid.idx.size(), "SCALAR");
        glb.json["materials"] = Json::array({material});
        glb.json["textures"] = Json::array({Json::object()});
        gf::addScene(glb, {{"attributes", attributes}, {"indices", indices}, {"material", 0}},
                     node);
        return glb.write(path);
    }
};

core::Mesh load(const TangentFile& file) {
    core_test::TempDir dir("gltf_tangents");
    const std::string path = (dir.path() / "tangents.glb").string();
    EXPECT_TRUE(file.write(path));
    core::Result<core::Mesh> mesh = core::loadMesh(path);
    EXPECT_TRUE(mesh) << mesh.error();
    return mesh ? std::move(mesh).value() : core::Mesh{};
}

TEST(GltfTangents, TheFilesTangentsAreDrawnInsteadOfComputedOnes) {
    const core::Mesh mesh = load(TangentFile{});
    ASSERT_EQ(mesh.tangents.size(), mesh.vertexCount());
    const std::vector<glm::vec4> drawn = core::vertexTangents(mesh);
    const std::vector<glm::vec4> computed = core::computeTangents(mesh);
    ASSERT_EQ(drawn.size(), mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        EXPECT_NEAR(drawn[v].y, 1.0f, 1e-5f) << v;
        EXPECT_EQ(drawn[v].w, -1.0f) << v;
        EXPECT_LT(std::abs(computed[v].y), 0.1f) << v; // computed: along +u, the grid's x
    }
}

TEST(GltfTangents, AMirroringNodeTurnsTheBitangent) {
    TangentFile file;
    file.node = {{"matrix", {0, 0, 2, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1}}}; // x→2z, z→x
    const core::Mesh mesh = load(file);
    ASSERT_EQ(mesh.tangents.size(), mesh.vertexCount());
    for (const glm::vec4& t : mesh.tangents) {
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
        EXPECT_NEAR(t.y, 1.0f, 1e-5f); // y stays y
        EXPECT_EQ(t.w, 1.0f);          // det < 0: w turned
    }
}

TEST(GltfTangents, IgnoredWithoutNormalsOrWithoutANormalMap) {
    TangentFile noNormals;
    noNormals.withNormals = false;
    EXPECT_TRUE(load(noNormals).tangents.empty());
    TangentFile noNormalMap;
    noNormalMap.material = Json::object();
    EXPECT_TRUE(load(noNormalMap).tangents.empty());
}

} // namespace gltf_tangents_test
