// SPDX-License-Identifier: GPL-3.0-or-later
// Real-world glTF: a small curved grid written as binary glTF uncompressed, with Draco
// (KHR_draco_mesh_compression) and with meshoptimizer (EXT_meshopt_compression over
// KHR_mesh_quantization data, a fallback buffer without data, the octahedral filter), made here
// with the libraries' encoders and loaded through core::loadMesh (the importer process); plus
// KHR_texture_transform on the UVs, damaged compressed data, and glTF 1.0 through Assimp.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <glm/geometric.hpp>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

#include "core/io/mesh_io.h"
#include "tests/core/test_files.h"

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace gltf_compression_test {

/** The reference mesh: an n × n grid bent into a wave, with normals and UVs. */
struct Grid {
    std::vector<float> pos, nrm, uv; // 3, 3, 2 per vertex
    std::vector<std::uint32_t> idx;
    std::size_t vertices() const { return pos.size() / 3; }
    std::size_t triangles() const { return idx.size() / 3; }
};

Grid makeGrid(int n = 9) {
    Grid g;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float u = float(i) / float(n - 1), v = float(j) / float(n - 1);
            const float x = 2.0f * u - 1.0f, y = 2.0f * v - 1.0f;
            const float z = 0.3f * std::sin(3.0f * x);
            g.pos.insert(g.pos.end(), {x + 5.0f, y, z}); // off the origin: quantization offsets
            const glm::vec3 nrm = glm::normalize(glm::vec3(-0.9f * std::cos(3.0f * x), 0, 1));
            g.nrm.insert(g.nrm.end(), {nrm.x, nrm.y, nrm.z});
            g.uv.insert(g.uv.end(), {0.1f + 0.8f * u, 0.05f + 0.9f * v});
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const auto a = std::uint32_t(j * n + i), b = a + 1, c = a + std::uint32_t(n), d = c + 1;
            g.idx.insert(g.idx.end(), {a, b, d, a, d, c});
        }
    return g;
}

/** A GLB builder: JSON plus one BIN chunk that views are appended to. */
struct Glb {
    Json json = Json::object();
    std::vector<std::uint8_t> bin;

    Glb() { json["asset"] = {{"version", "2.0"}}; }
    /** Appends bytes (4-aligned) to the BIN chunk; returns their offset. */
    std::size_t append(const void* data, std::size_t size) {
        while (bin.size() % 4 != 0)
            bin.push_back(0);
        const std::size_t at = bin.size();
        const auto* p = static_cast<const std::uint8_t*>(data);
        bin.insert(bin.end(), p, p + size);
        return at;
    }
    int view(std::size_t offset, std::size_t length, int stride = 0, int buffer = 0) {
        Json v = {{"buffer", buffer}, {"byteOffset", offset}, {"byteLength", length}};
        if (stride)
            v["byteStride"] = stride;
        json["bufferViews"].push_back(v);
        return int(json["bufferViews"].size() - 1);
    }
    int accessor(int view, int componentType, std::size_t count, const char* type,
                 bool normalized = false) {
        Json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
        if (view >= 0)
            a["bufferView"] = view;
        if (normalized)
            a["normalized"] = true;
        json["accessors"].push_back(a);
        return int(json["accessors"].size() - 1);
    }
    void write(const fs::path& file) {
        while (bin.size() % 4 != 0)
            bin.push_back(0);
        if (!json.contains("buffers"))
            json["buffers"] = Json::array();
        json["buffers"].insert(json["buffers"].begin(), Json{{"byteLength", bin.size()}});
        std::string text = json.dump();
        while (text.size() % 4 != 0)
            text.push_back(' ');
        std::vector<std::uint8_t> out;
        auto put = [&out](std::uint32_t v) {
            out.insert(out.end(), {std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16),
                                   std::uint8_t(v >> 24)});
        };
        put(0x46546C67u);
        put(2);
        put(std::uint32_t(12 + 8 + text.size() + 8 + bin.size()));
        put(std::uint32_t(text.size()));
        put(0x4E4F534Au);
        out.insert(out.end(), text.begin(), text.end());
        put(std::uint32_t(bin.size()));
        put(0x004E4942u);
        out.insert(out.end(), bin.begin(), bin.end());
        std::ofstream(file, std::ios::binary)
            .write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
    }
};

constexpr int kByte = 5120, kUShort = 5123, kUInt = 5125, kFloat = 5126;

/** One mesh with one primitive of attrs (and indices), one node (with extra node JSON). */
void addScene(Glb& glb, Json prim, const Json& node = Json::object()) {
    prim["mode"] = 4;
    glb.json["meshes"] = Json::array({Json{{"primitives", Json::array({prim})}}});
    Json n = node;
    n["mesh"] = 0;
    glb.json["nodes"] = Json::array({n});
    glb.json["scenes"] = Json::array({Json{{"nodes", {0}}}});
    glb.json["scene"] = 0;
}

void writePlain(const Grid& g, const fs::path& file, const Json& material = Json()) {
    Glb glb;
    const int p =
        glb.accessor(glb.view(glb.append(g.pos.data(), g.pos.size() * 4), g.pos.size() * 4), kFloat,
                     g.vertices(), "VEC3");
    const int nm =
        glb.accessor(glb.view(glb.append(g.nrm.data(), g.nrm.size() * 4), g.nrm.size() * 4), kFloat,
                     g.vertices(), "VEC3");
    const int t = glb.accessor(glb.view(glb.append(g.uv.data(), g.uv.size() * 4), g.uv.size() * 4),
                               kFloat, g.vertices(), "VEC2");
    const int i =
        glb.accessor(glb.view(glb.append(g.idx.data(), g.idx.size() * 4), g.idx.size() * 4), kUInt,
                     g.idx.size(), "SCALAR");
    Json prim = {{"attributes", {{"POSITION", p}, {"NORMAL", nm}, {"TEXCOORD_0", t}}},
                 {"indices", i}};
    if (!material.is_null()) {
        // TEXCOORD_1: the grid's UVs mirrored, for texCoord overrides.
        std::vector<float> uv1 = g.uv;
        for (float& v : uv1)
            v = 1.0f - v;
        const int t1 =
            glb.accessor(glb.view(glb.append(uv1.data(), uv1.size() * 4), uv1.size() * 4), kFloat,
                         g.vertices(), "VEC2");
        prim["attributes"]["TEXCOORD_1"] = t1;
        prim["material"] = 0;
        glb.json["materials"] = Json::array({material});
        glb.json["textures"] = Json::array({Json::object()}); // no image: only the UVs matter
    }
    addScene(glb, prim);
    glb.write(file);
}

/** The Draco bytes of g, quantized as the bit counts say; ids gets the attributes' ids. */
std::vector<std::uint8_t> dracoBytes(const Grid& g, std::map<std::string, int>& ids) {
    draco::Mesh mesh;
    const auto n = static_cast<std::uint32_t>(g.vertices());
    mesh.set_num_points(n);
    auto add = [&](draco::GeometryAttribute::Type type, int comps, const std::vector<float>& v,
                   const char* name) {
        draco::GeometryAttribute ga;
        ga.Init(type, nullptr, std::uint8_t(comps), draco::DT_FLOAT32, false,
                sizeof(float) * std::size_t(comps), 0);
        const int id = mesh.AddAttribute(ga, true, n);
        for (std::uint32_t k = 0; k < n; ++k)
            mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(k),
                                                  &v[k * std::size_t(comps)]);
        ids[name] = int(mesh.attribute(id)->unique_id());
    };
    add(draco::GeometryAttribute::POSITION, 3, g.pos, "POSITION");
    add(draco::GeometryAttribute::NORMAL, 3, g.nrm, "NORMAL");
    add(draco::GeometryAttribute::TEX_COORD, 2, g.uv, "TEXCOORD_0");
    for (std::size_t t = 0; t < g.idx.size(); t += 3)
        mesh.AddFace({draco::PointIndex(g.idx[t]), draco::PointIndex(g.idx[t + 1]),
                      draco::PointIndex(g.idx[t + 2])});
    draco::Encoder encoder;
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 12);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
    draco::EncoderBuffer out;
    EXPECT_TRUE(encoder.EncodeMeshToBuffer(mesh, &out).ok());
    return {out.data(), out.data() + out.size()};
}

void writeDraco(const Grid& g, const fs::path& file, std::size_t keepBytes = 0,
                std::size_t claimedVertices = 0) {
    std::map<std::string, int> ids;
    std::vector<std::uint8_t> bytes = dracoBytes(g, ids);
    if (keepBytes)
        bytes.resize(keepBytes);
    Glb glb;
    const int view = glb.view(glb.append(bytes.data(), bytes.size()), bytes.size());
    const std::size_t nv = claimedVertices ? claimedVertices : g.vertices();
    const int p = glb.accessor(-1, kFloat, nv, "VEC3");
    const int nm = glb.accessor(-1, kFloat, nv, "VEC3");
    const int t = glb.accessor(-1, kFloat, nv, "VEC2");
    const int i = glb.accessor(-1, kUInt, g.idx.size(), "SCALAR");
    Json attrs;
    for (const auto& [name, id] : ids)
        attrs[name] = id;
    addScene(glb,
             {{"attributes", {{"POSITION", p}, {"NORMAL", nm}, {"TEXCOORD_0", t}}},
              {"indices", i},
              {"extensions",
               {{"KHR_draco_mesh_compression", {{"bufferView", view}, {"attributes", attrs}}}}}});
    glb.json["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    glb.json["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    glb.write(file);
}

/**
 * g with KHR_mesh_quantization (unsigned short positions dequantized by the node's scale and
 * translation, octahedral byte normals, normalized unsigned short UVs) and every view compressed
 * with EXT_meshopt_compression into the BIN chunk; the views themselves point into a fallback
 * buffer without data. countDelta damages the index view's count, keepIndexBytes cuts its data.
 */
void writeMeshopt(const Grid& g, const fs::path& file, long countDelta = 0,
                  std::size_t keepIndexBytes = 0) {
    const std::size_t n = g.vertices();
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (std::size_t v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], g.pos[v * 3 + std::size_t(c)]);
            hi[c] = std::max(hi[c], g.pos[v * 3 + std::size_t(c)]);
        }
    // One step for all axes, as gltfpack does: a non-uniform node scale would bend the normals.
    const float extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    const glm::vec3 step(extent / 65535.0f);
    std::vector<std::uint16_t> qpos(n * 4, 0);
    for (std::size_t v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c)
            qpos[v * 4 + std::size_t(c)] =
                std::uint16_t(std::lround((g.pos[v * 3 + std::size_t(c)] - lo[c]) / step[c]));
    std::vector<float> nrm4(n * 4, 0.0f);
    for (std::size_t v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c)
            nrm4[v * 4 + std::size_t(c)] = g.nrm[v * 3 + std::size_t(c)];
    std::vector<std::int8_t> qnrm(n * 4);
    meshopt_encodeFilterOct(qnrm.data(), n, 4, 8, nrm4.data());
    std::vector<std::uint16_t> quv(n * 2);
    for (std::size_t k = 0; k < quv.size(); ++k)
        quv[k] = std::uint16_t(std::lround(g.uv[k] * 65535.0f));

    Glb glb;
    std::size_t fallbackSize = 0;
    auto compressedView = [&](const std::vector<std::uint8_t>& packed, std::size_t count,
                              std::size_t stride, const char* mode, const char* filter,
                              bool vertexData, long delta = 0) {
        const std::size_t raw = count * stride;
        const int v = glb.view(fallbackSize, raw, vertexData ? int(stride) : 0, 1);
        Json ext = {{"buffer", 0},
                    {"byteOffset", glb.append(packed.data(), packed.size())},
                    {"byteLength", packed.size()},
                    {"byteStride", stride},
                    {"count", std::size_t(long(count) + delta)},
                    {"mode", mode}};
        if (filter)
            ext["filter"] = filter;
        glb.json["bufferViews"][std::size_t(v)]["extensions"]["EXT_meshopt_compression"] = ext;
        fallbackSize += (raw + 3) / 4 * 4;
        return v;
    };
    auto vertexView = [&](const void* data, std::size_t stride, const char* filter) {
        std::vector<std::uint8_t> packed(meshopt_encodeVertexBufferBound(n, stride));
        packed.resize(meshopt_encodeVertexBuffer(packed.data(), packed.size(), data, n, stride));
        return compressedView(packed, n, stride, "ATTRIBUTES", filter, true);
    };
    const int p = glb.accessor(vertexView(qpos.data(), 8, nullptr), kUShort, n, "VEC3");
    const int nm = glb.accessor(vertexView(qnrm.data(), 4, "OCTAHEDRAL"), kByte, n, "VEC3", true);
    const int t = glb.accessor(vertexView(quv.data(), 4, nullptr), kUShort, n, "VEC2", true);
    std::vector<std::uint8_t> packedIdx(meshopt_encodeIndexBufferBound(g.idx.size(), n));
    packedIdx.resize(
        meshopt_encodeIndexBuffer(packedIdx.data(), packedIdx.size(), g.idx.data(), g.idx.size()));
    if (keepIndexBytes)
        packedIdx.resize(keepIndexBytes);
    const int i = glb.accessor(
        compressedView(packedIdx, g.idx.size(), 4, "TRIANGLES", nullptr, false, countDelta), kUInt,
        g.idx.size(), "SCALAR");
    glb.json["buffers"] =
        Json::array({Json{{"byteLength", fallbackSize},
                          {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}});
    addScene(glb,
             {{"attributes", {{"POSITION", p}, {"NORMAL", nm}, {"TEXCOORD_0", t}}}, {"indices", i}},
             {{"translation", {lo.x, lo.y, lo.z}}, {"scale", {step.x, step.y, step.z}}});
    glb.json["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    glb.json["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
    glb.write(file);
}

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
    writePlain(g, dir.path() / "plain.glb");
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "plain.glb").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    expectSameMesh(*mesh, g, 1e-6f, 1e-6f);
}

TEST(GltfCompression, DracoMatchesTheUncompressedMesh) {
    core_test::TempDir dir;
    const Grid g = makeGrid();
    writeDraco(g, dir.path() / "draco.glb");
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "draco.glb").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_TRUE(mesh->warnings.empty()) << mesh->warnings.front();
    // 12 bits over the longest side (2 units): a step of 2/4095, at most half of it per axis.
    expectSameMesh(*mesh, g, 2.0f / 4095.0f, 1.0f / 4095.0f);
}

TEST(GltfCompression, MeshoptQuantizedMatchesTheUncompressedMesh) {
    core_test::TempDir dir;
    const Grid g = makeGrid();
    writeMeshopt(g, dir.path() / "meshopt.glb");
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "meshopt.glb").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_TRUE(mesh->warnings.empty()) << mesh->warnings.front();
    // 16-bit positions through the node transform, 16-bit normalized UVs.
    expectSameMesh(*mesh, g, 2.0f / 65535.0f, 1.0f / 65535.0f);
}

TEST(GltfCompression, TextureTransformMovesTheUvs) {
    core_test::TempDir dir;
    const Grid g = makeGrid(4);
    // The extension's own example: the lower left quarter of the image, turned.
    const Json transform = {
        {"offset", {0.0, 1.0}}, {"rotation", std::numbers::pi / 2}, {"scale", {0.5, 0.5}}};
    writePlain(g, dir.path() / "transform.glb",
               {{"pbrMetallicRoughness",
                 {{"baseColorTexture",
                   {{"index", 0}, {"extensions", {{"KHR_texture_transform", transform}}}}}}}});
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
    writePlain(
        g, dir.path() / "texcoord.glb",
        {{"pbrMetallicRoughness",
          {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", base}}}}},
           {"metallicRoughnessTexture",
            {{"index", 0}, {"extensions", {{"KHR_texture_transform", mr}}}}}}}});
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
    writeDraco(g, dir.path() / "cut.glb", 40);
    expectRefused(dir.path() / "cut.glb", "Draco");
    writeDraco(g, dir.path() / "count.glb", 0, g.vertices() + 7);
    expectRefused(dir.path() / "count.glb", "the Draco data holds 81 vertices");
}

TEST(GltfCompression, DamagedMeshoptIsRefusedNamingTheFile) {
    core_test::TempDir dir;
    const Grid g = makeGrid();
    writeMeshopt(g, dir.path() / "cut.glb", 0, 20);
    expectRefused(dir.path() / "cut.glb", "cannot be decoded");
    writeMeshopt(g, dir.path() / "count.glb", 3);
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
 * The committed files made by DISABLED_WriteDataFiles (fuzz seeds and the crash corpus) are
 * still what the encoders make of the 5 × 5 grid, and load or fail as they should.
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

/** Rewrites those files (run by hand: --gtest_also_run_disabled_tests). */
TEST(GltfCompression, DISABLED_WriteDataFiles) {
    const Grid g = makeGrid(5);
    writeDraco(g, kData / "gltf/grid-draco.glb");
    writeMeshopt(g, kData / "gltf/grid-meshopt.glb");
    writeDraco(g, kData / "crashers/glb-draco-truncated.glb", 30);
    writeMeshopt(g, kData / "crashers/glb-meshopt-wrong-count.glb", 6);
}

} // namespace gltf_compression_test
