// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/model/builtin_models.h"

namespace builtin_models_test {

using core::Mesh;

/** Sum over triangles of sign(geometric normal · vertex normals): outward winding gives +1 each. */
double outwardShare(const Mesh& mesh) {
    std::size_t outward = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const auto a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1],
                   c = mesh.indices[3 * t + 2];
        const glm::vec3 g = glm::cross(mesh.positions[b] - mesh.positions[a],
                                       mesh.positions[c] - mesh.positions[a]);
        if (glm::dot(g, mesh.normals[a] + mesh.normals[b] + mesh.normals[c]) > 0.0f)
            ++outward;
    }
    return double(outward) / double(mesh.triangleCount());
}

/** Every edge (with positions welded) is used by exactly two triangles, in opposite directions. */
bool closedAndOriented(const Mesh& mesh) {
    std::map<std::tuple<float, float, float>, std::uint32_t> weld;
    std::vector<std::uint32_t> id(mesh.vertexCount());
    for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
        const glm::vec3 p = mesh.positions[i];
        // Quantize so seam copies computed along different paths weld together.
        const auto key =
            std::make_tuple(std::round(p.x * 1e4f), std::round(p.y * 1e4f), std::round(p.z * 1e4f));
        id[i] = weld.emplace(key, std::uint32_t(weld.size())).first->second;
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int e = 0; e < 3; ++e) {
            const auto u = id[mesh.indices[3 * t + e]], v = id[mesh.indices[3 * t + (e + 1) % 3]];
            if (u == v)
                return false;
            ++directed[{u, v}];
        }
    for (const auto& [edge, count] : directed) {
        const auto back = directed.find({edge.second, edge.first});
        if (count != 1 || back == directed.end() || back->second != 1)
            return false;
    }
    return true;
}

/** Texel centres of a size × size grid covered by the interiors of two or more UV triangles. */
int overlappingTexels(const Mesh& mesh, int size) {
    std::vector<std::uint8_t> cover(std::size_t(size) * size, 0);
    int overlaps = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        glm::vec2 p[3];
        for (int k = 0; k < 3; ++k)
            p[k] = mesh.uvs[mesh.indices[3 * t + k]] * float(size);
        const float area =
            (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
        const int x0 = std::max(0, int(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
        const int x1 = std::min(size - 1, int(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
        const int y0 = std::max(0, int(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
        const int y1 = std::min(size - 1, int(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 c(float(x) + 0.5f, float(y) + 0.5f);
                bool inside = true;
                for (int k = 0; k < 3 && inside; ++k) {
                    const glm::vec2 a = p[k], b = p[(k + 1) % 3];
                    const float e = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
                    inside = (area > 0 ? e : -e) > 1e-4f;
                }
                if (inside && cover[std::size_t(y) * size + x]++ == 1)
                    ++overlaps;
            }
    }
    return overlaps;
}

TEST(BuiltinModels, TrefoilHasThePapersVertexCount) {
    const Mesh mesh = core::makeTrefoil();
    EXPECT_EQ(mesh.vertexCount(), 144000u);
    EXPECT_EQ(mesh.triangleCount(), 3u * 399 * 119 * 2);
    EXPECT_TRUE(mesh.hasUvs());
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().error();
}

class BuiltinModelTest : public ::testing::TestWithParam<std::string> {};

TEST_P(BuiltinModelTest, IsValidClosedOutwardAndUvMappedWithoutOverlap) {
    auto loaded = core::makeBuiltinModel(GetParam());
    ASSERT_TRUE(loaded) << loaded.error();
    const Mesh& mesh = *loaded;
    EXPECT_TRUE(mesh.validate().ok()) << mesh.validate().error();
    EXPECT_DOUBLE_EQ(outwardShare(mesh), 1.0);
    EXPECT_TRUE(closedAndOriented(mesh));
    ASSERT_TRUE(mesh.hasUvs());
    for (const glm::vec2& uv : mesh.uvs) {
        ASSERT_GE(uv.x, 0.0f);
        ASSERT_LE(uv.x, 1.0f);
        ASSERT_GE(uv.y, 0.0f);
        ASSERT_LE(uv.y, 1.0f);
    }
    EXPECT_EQ(overlappingTexels(mesh, 1024), 0);
}

INSTANTIATE_TEST_SUITE_P(All, BuiltinModelTest, ::testing::Values("trefoil", "hexring", "row"));

TEST(BuiltinModels, RowIsFourCopiesOneBehindAnother) {
    const Mesh mesh = core::makeRow();
    const std::size_t perBody = mesh.vertexCount() / 4;
    ASSERT_EQ(perBody * 4, mesh.vertexCount());
    for (std::size_t body = 1; body < 4; ++body)
        for (std::size_t i = 0; i < perBody; i += 97) {
            const glm::vec3 a = mesh.positions[i], b = mesh.positions[body * perBody + i];
            EXPECT_NEAR(a.x, b.x, 1e-6f);
            EXPECT_NEAR(a.y, b.y, 1e-6f);
            EXPECT_LT(b.z, a.z - 1.0f); // strictly behind along -Z
        }
}

TEST(BuiltinModels, UnknownNameIsAnError) {
    auto mesh = core::makeBuiltinModel("teapot");
    ASSERT_FALSE(mesh);
    EXPECT_NE(mesh.error().find("builtin:teapot"), std::string::npos);
}

TEST(BuiltinModels, KnotHasAboutTheTrianglesAskedForAndIsAClosedTube) {
    for (const std::size_t asked : {std::size_t(1000), std::size_t(20000), std::size_t(123457)}) {
        const core::Result<Mesh> knot =
            core::makeBuiltinModel("knot?triangles=" + std::to_string(asked));
        ASSERT_TRUE(knot) << knot.error();
        const double ratio = double(knot->triangleCount()) / double(asked);
        EXPECT_GT(ratio, 0.9) << asked;
        EXPECT_LT(ratio, 1.1) << asked;
        EXPECT_EQ(knot->uvs.size(), knot->vertexCount());
        EXPECT_EQ(knot->normals.size(), knot->vertexCount());
        EXPECT_EQ(knot->triangleMaterial.size(), knot->triangleCount());
        for (const glm::vec2& uv : knot->uvs) {
            ASSERT_GE(uv.x, 0.0f);
            ASSERT_LE(uv.x, 1.0f);
            ASSERT_GE(uv.y, 0.0f);
            ASSERT_LE(uv.y, 1.0f);
        }
        EXPECT_GT(outwardShare(*knot), 0.99);
    }
    const core::Result<Mesh> small = core::makeBuiltinModel("knot?triangles=4000");
    ASSERT_TRUE(small);
    EXPECT_TRUE(closedAndOriented(*small));
    EXPECT_EQ(overlappingTexels(*small, 256), 0);
    // Without a parameter: the default size.
    const core::Result<Mesh> plain = core::makeBuiltinModel("knot");
    ASSERT_TRUE(plain);
    EXPECT_NEAR(double(plain->triangleCount()), double(core::kKnotDefaultTriangles),
                0.1 * double(core::kKnotDefaultTriangles));
    const auto& models = core::builtinModels();
    EXPECT_TRUE(std::any_of(models.begin(), models.end(),
                            [](const core::BuiltinModel& m) { return m.name == "knot"; }));
}

TEST(BuiltinModels, KnotRejectsBadParametersNamingThem) {
    const auto error = [](const std::string& name) {
        const core::Result<Mesh> mesh = core::makeBuiltinModel(name);
        EXPECT_FALSE(mesh) << name;
        return mesh ? std::string() : mesh.error();
    };
    EXPECT_EQ(error("knot?size=5000"),
              "builtin:knot?size=5000: unknown parameter \"size\" (the knot takes triangles=N)");
    EXPECT_EQ(error("knot?triangles"),
              "builtin:knot?triangles: unknown parameter \"triangles\" (the knot takes "
              "triangles=N)");
    EXPECT_EQ(error("knot?triangles=lots"),
              "builtin:knot?triangles=lots: triangles must be a whole number, not \"lots\"");
    EXPECT_EQ(error("knot?triangles=-5"),
              "builtin:knot?triangles=-5: triangles must be a whole number, not \"-5\"");
    EXPECT_EQ(error("knot?triangles=12x"),
              "builtin:knot?triangles=12x: triangles must be a whole number, not \"12x\"");
    EXPECT_EQ(error("knot?triangles=999"),
              "builtin:knot?triangles=999: triangles must be between 1000 and 50000000");
    EXPECT_EQ(error("knot?triangles=50000001"),
              "builtin:knot?triangles=50000001: triangles must be between 1000 and 50000000");
    EXPECT_EQ(error("knot?triangles=99999999999999999999999"),
              "builtin:knot?triangles=99999999999999999999999: triangles must be a whole number, "
              "not \"99999999999999999999999\"");
    EXPECT_NE(error("knots").find("no such built-in model"), std::string::npos);
}

} // namespace builtin_models_test
