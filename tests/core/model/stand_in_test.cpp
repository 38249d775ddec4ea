// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include <set>

#include <glm/common.hpp>

#include "core/model/builtin_models.h"
#include "core/model/stand_in.h"

namespace stand_in_test {

using core::Mesh;
using core::StandIn;

/** A small trefoil with a colour per vertex that varies over the surface. */
Mesh colouredTrefoil() {
    Mesh mesh = core::makeTrefoil(80, 24);
    mesh.colors.resize(mesh.vertexCount());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        mesh.colors[v] = glm::vec4(glm::fract(mesh.positions[v] * 0.7f), 1.0f);
    return mesh;
}

/** The same triangles with a vertex per corner (as a per-triangle UV layout splits them). */
Mesh splitPerCorner(const Mesh& mesh) {
    Mesh split = mesh;
    split.positions.clear();
    split.normals.clear();
    split.uvs.clear();
    split.colors.clear();
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        const std::uint32_t v = mesh.indices[i];
        split.positions.push_back(mesh.positions[v]);
        split.normals.push_back(mesh.normals[v]);
        if (mesh.hasUvs())
            split.uvs.push_back(mesh.uvs[v]);
        if (mesh.hasColors())
            split.colors.push_back(mesh.colors[v]);
        split.indices[i] = std::uint32_t(i);
    }
    return split;
}

void expectValid(const StandIn& standIn, const Mesh& mesh, std::size_t target) {
    EXPECT_LE(standIn.triangleCount(), target);
    EXPECT_EQ(standIn.indices.size(), standIn.triangleCount() * 3);
    ASSERT_EQ(standIn.triangleMaterial.size(), standIn.triangleCount());
    for (const std::uint32_t v : standIn.indices)
        ASSERT_LT(v, mesh.vertexCount());
    for (const std::uint32_t m : standIn.triangleMaterial)
        ASSERT_LT(m, mesh.materials.size());
}

TEST(StandInTest, SimplifiesUnderTheTargetDeterministically) {
    const Mesh mesh = colouredTrefoil();
    ASSERT_GT(mesh.triangleCount(), 8000u);
    constexpr std::size_t target = 1500;
    auto first = core::simplifyForDisplay(mesh, target);
    ASSERT_TRUE(first) << first.error();
    expectValid(*first, mesh, target);
    // Near the target, not a few triangles: the tube still looks like one.
    EXPECT_GT(first->triangleCount(), target / 2);
    auto second = core::simplifyForDisplay(mesh, target);
    ASSERT_TRUE(second);
    EXPECT_EQ(first->indices, second->indices);
    EXPECT_EQ(first->triangleMaterial, second->triangleMaterial);
}

TEST(StandInTest, NoStandInForASmallMesh) {
    const Mesh mesh = colouredTrefoil();
    auto standIn = core::simplifyForDisplay(mesh, mesh.triangleCount());
    ASSERT_TRUE(standIn);
    EXPECT_TRUE(standIn->empty());
}

TEST(StandInTest, EachMaterialKeepsItsShare) {
    Mesh mesh = colouredTrefoil();
    mesh.materials.push_back(core::Material{"second", glm::vec4(1.0f, 0.0f, 0.0f, 1.0f), -1});
    // The second half of the triangles (whole segments of the tube) gets the second material.
    for (std::size_t t = mesh.triangleCount() / 2; t < mesh.triangleCount(); ++t)
        mesh.triangleMaterial[t] = 1;
    constexpr std::size_t target = 2000;
    auto standIn = core::simplifyForDisplay(mesh, target);
    ASSERT_TRUE(standIn) << standIn.error();
    expectValid(*standIn, mesh, target);
    std::size_t second = 0;
    for (std::size_t t = 0; t < standIn->triangleCount(); ++t) {
        const std::uint32_t m = standIn->triangleMaterial[t];
        second += m;
    }
    EXPECT_GT(second, standIn->triangleCount() / 4);
    EXPECT_LT(second, standIn->triangleCount() * 3 / 4);
    // Its vertices are those of triangles with its material.
    std::set<std::uint32_t> materialVertices[2];
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int c = 0; c < 3; ++c)
            materialVertices[mesh.triangleMaterial[t]].insert(mesh.indices[3 * t + std::size_t(c)]);
    for (std::size_t t = 0; t < standIn->triangleCount(); ++t)
        for (int c = 0; c < 3; ++c)
            EXPECT_TRUE(materialVertices[standIn->triangleMaterial[t]].count(
                standIn->indices[3 * t + std::size_t(c)]));
}

TEST(StandInTest, UnweldedTrianglesStillSimplify) {
    // Every corner its own vertex: the edge-collapse simplifier sees seams everywhere.
    const Mesh mesh = splitPerCorner(colouredTrefoil());
    constexpr std::size_t target = 1500;
    auto standIn = core::simplifyForDisplay(mesh, target);
    ASSERT_TRUE(standIn) << standIn.error();
    expectValid(*standIn, mesh, target);
    EXPECT_GT(standIn->triangleCount(), target / 8);
}

TEST(StandInTest, AttributesCarriedToASplitDrawnMesh) {
    const Mesh mesh = colouredTrefoil();
    auto standIn = core::simplifyForDisplay(mesh, 1500);
    ASSERT_TRUE(standIn);
    ASSERT_FALSE(standIn->empty());
    // Drawn as the source: the same stand-in.
    const StandIn same = core::standInFor(*standIn, mesh, mesh);
    EXPECT_EQ(same.indices, standIn->indices);
    // Drawn through split vertices: every corner has the source vertex's position, UV, colour.
    Mesh drawn = splitPerCorner(mesh);
    drawn.materials.push_back(drawn.materials.front());
    drawn.triangleMaterial.assign(drawn.triangleCount(), 1);
    const StandIn split = core::standInFor(*standIn, mesh, drawn);
    ASSERT_EQ(split.indices.size(), standIn->indices.size());
    for (std::size_t i = 0; i < split.indices.size(); ++i) {
        const std::uint32_t s = standIn->indices[i], d = split.indices[i];
        ASSERT_LT(d, drawn.vertexCount());
        EXPECT_EQ(drawn.positions[d], mesh.positions[s]);
        EXPECT_EQ(drawn.uvs[d], mesh.uvs[s]);
        EXPECT_EQ(drawn.colors[d], mesh.colors[s]);
    }
    for (const std::uint32_t m : split.triangleMaterial)
        EXPECT_EQ(m, 1u);
    // Another mesh's triangles: nothing.
    Mesh other = mesh;
    other.indices.resize(other.indices.size() - 3);
    other.triangleMaterial.pop_back();
    EXPECT_TRUE(core::standInFor(*standIn, mesh, other).empty());
}

TEST(StandInTest, ProgressCancels) {
    const Mesh mesh = colouredTrefoil();
    auto standIn = core::simplifyForDisplay(mesh, 1500, [](double) { return false; });
    EXPECT_TRUE(standIn.cancelled());
}

} // namespace stand_in_test
