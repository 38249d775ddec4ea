// SPDX-License-Identifier: GPL-3.0-or-later
// core::computeTangents(): glTF's convention on a flat quad (u along the tangent, the bitangent's
// sign turning v over), mirrored uvs, tangents perpendicular to bent normals, and meshes without
// uvs or with degenerate ones.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/model/mesh_tangents.h"

namespace mesh_tangents_test {

/** A quad in the xy plane facing +z, with the uv of each corner (bottom left first, ccw). */
core::Mesh quad(std::vector<glm::vec2> uvs) {
    core::Mesh mesh;
    mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    mesh.normals.assign(4, glm::vec3(0, 0, 1));
    mesh.uvs = std::move(uvs);
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.triangleMaterial = {0, 0};
    mesh.materials.resize(1);
    return mesh;
}

void expectTangent(const glm::vec4& tangent, glm::vec3 direction, float sign) {
    EXPECT_NEAR(tangent.x, direction.x, 1e-5f);
    EXPECT_NEAR(tangent.y, direction.y, 1e-5f);
    EXPECT_NEAR(tangent.z, direction.z, 1e-5f);
    EXPECT_EQ(tangent.w, sign);
}

TEST(MeshTangents, FollowIncreasingUWithTheBitangentUpTheImage) {
    // glTF: uv (0, 0) is the image's top left, so v grows downwards on the quad.
    const auto tangents = core::computeTangents(quad({{0, 1}, {1, 1}, {1, 0}, {0, 0}}));
    ASSERT_EQ(tangents.size(), 4u);
    for (const glm::vec4& t : tangents)
        expectTangent(t, {1, 0, 0}, 1.0f); // cross(+z, +x) = +y: up the image
}

TEST(MeshTangents, MirroredUvsTurnTheSign) {
    // v grows upwards: the image is mirrored top to bottom on the quad.
    for (const glm::vec4& t : core::computeTangents(quad({{0, 0}, {1, 0}, {1, 1}, {0, 1}})))
        expectTangent(t, {1, 0, 0}, -1.0f);
    // u grows leftwards: the tangent points left, the image mirrored left to right.
    for (const glm::vec4& t : core::computeTangents(quad({{1, 1}, {0, 1}, {0, 0}, {1, 0}})))
        expectTangent(t, {-1, 0, 0}, -1.0f);
}

TEST(MeshTangents, AreUnitAndPerpendicularToTheVertexNormal) {
    core::Mesh mesh = quad({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    mesh.normals = {{0.4f, 0, 1}, {-0.3f, 0.2f, 1}, {0, -0.5f, 1}, {0.1f, 0.1f, 1}}; // not unit
    const auto tangents = core::computeTangents(mesh);
    ASSERT_EQ(tangents.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        const glm::vec3 t(tangents[i]);
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f);
        EXPECT_NEAR(glm::dot(t, glm::normalize(mesh.normals[i])), 0.0f, 1e-5f);
        EXPECT_GT(t.x, 0.9f); // still along u
        EXPECT_EQ(tangents[i].w, 1.0f);
    }
}

TEST(MeshTangents, NoUvsGiveNoneAndDegenerateUvsGiveSomePerpendicular) {
    core::Mesh withoutUvs = quad({});
    EXPECT_TRUE(core::computeTangents(withoutUvs).empty());
    core::Mesh flat = quad(std::vector<glm::vec2>(4, glm::vec2(0.5f)));
    const auto tangents = core::computeTangents(flat);
    ASSERT_EQ(tangents.size(), 4u);
    for (const glm::vec4& t : tangents) {
        EXPECT_NEAR(glm::length(glm::vec3(t)), 1.0f, 1e-5f);
        EXPECT_NEAR(t.z, 0.0f, 1e-5f);
    }
}

} // namespace mesh_tangents_test
