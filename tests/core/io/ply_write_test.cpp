// SPDX-License-Identifier: GPL-3.0-or-later
// The one binary PLY writer: the properties asked for, in order, and the bytes where they belong.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "core/io/ply_write.h"

namespace ply_write_test {

core::Mesh oneTriangle() {
    core::Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
    mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    mesh.uvs = {{0.0f, 0.25f}, {1.0f, 0.25f}, {0.0f, 1.0f}};
    mesh.indices = {0, 1, 2};
    mesh.triangleMaterial = {0};
    mesh.materials.push_back(core::Material{"m", glm::vec4(1.0f), -1});
    return mesh;
}

float floatAt(const std::string& bytes, std::size_t at) {
    float v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

TEST(PlyWrite, PositionsAndTrianglesOnly) {
    core::PlyContents contents;
    contents.comment = "flat";
    contents.normals = false;
    contents.uvs = false;
    const std::string ply = core::encodePly(oneTriangle(), contents);
    const std::string header = "ply\nformat binary_little_endian 1.0\ncomment flat\n"
                               "element vertex 3\nproperty float x\nproperty float y\n"
                               "property float z\nelement face 1\n"
                               "property list uchar uint vertex_indices\nend_header\n";
    ASSERT_EQ(ply.substr(0, header.size()), header);
    ASSERT_EQ(ply.size(), header.size() + 3 * 12 + 13);
    EXPECT_EQ(floatAt(ply, header.size() + 2 * 12 + 4), 2.0f); // y of the third vertex
    const std::size_t face = header.size() + 3 * 12;
    EXPECT_EQ(ply[face], 3);
    std::uint32_t indices[3] = {};
    std::memcpy(indices, ply.data() + face + 1, 12);
    EXPECT_EQ(indices[0], 0u);
    EXPECT_EQ(indices[1], 1u);
    EXPECT_EQ(indices[2], 2u);
}

TEST(PlyWrite, NormalsUvsAndColours) {
    const std::vector<glm::vec4> colors = {
        {1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f, 0.5f}, {0.0f, 0.0f, 1.0f, 0.0f}};
    core::PlyContents contents;
    contents.colors = &colors;
    const std::string ply = core::encodePly(oneTriangle(), contents);
    const std::size_t header = ply.find("end_header\n") + 11;
    ASSERT_NE(ply.find("property float nx\nproperty float ny\nproperty float nz\n"
                       "property float s\nproperty float t\nproperty uchar red\n"),
              std::string::npos);
    const std::size_t vertexBytes = 12 + 12 + 8 + 4;
    ASSERT_EQ(ply.size(), header + 3 * vertexBytes + 13);
    EXPECT_EQ(floatAt(ply, header + 12 + 8), 1.0f);  // nz of vertex 0
    EXPECT_EQ(floatAt(ply, header + 24 + 4), 0.75f); // t = 1 - v
    const auto* second = reinterpret_cast<const std::uint8_t*>(ply.data() + header + vertexBytes);
    EXPECT_EQ(second[32], 0);   // red
    EXPECT_EQ(second[33], 255); // green (sRGB of 1)
    EXPECT_EQ(second[35], 128); // alpha 0.5, linear
    // A mesh without UVs leaves s and t out even when asked for.
    core::Mesh noUvs = oneTriangle();
    noUvs.uvs.clear();
    EXPECT_EQ(core::encodePly(noUvs).find("property float s"), std::string::npos);
}

} // namespace ply_write_test
