// SPDX-License-Identifier: GPL-3.0-or-later
// Binary glTF export: round trips through loadMesh (built-in, corpus and hand-made meshes), the
// GLB layout the spec asks for, app-state extras, and atomic saving with a backup.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "core/io/gltf/gltf_export.h"
#include "core/io/mesh_io.h"
#include "core/model/builtin_models.h"
#include "tests/core/test_files.h"

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace gltf_export_test {

using core_test::readFile;
using core_test::TempDir;
using core_test::writeFile;

const fs::path kModels = LAYERPAINT_ASSIMP_MODELS;

std::vector<std::string> folderNames(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

/** A gradient image with an alpha that varies (or is opaque). */
core::Image makeImage(int width, int height, bool opaque, int seed) {
    core::Image img;
    img.width = width;
    img.height = height;
    img.rgba.resize(static_cast<std::size_t>(width) * height * 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            std::uint8_t* p = &img.rgba[(static_cast<std::size_t>(y) * width + x) * 4];
            p[0] = static_cast<std::uint8_t>(x * 7 + seed);
            p[1] = static_cast<std::uint8_t>(y * 13 + seed * 3);
            p[2] = static_cast<std::uint8_t>((x ^ y) + seed);
            p[3] = opaque ? 255 : static_cast<std::uint8_t>((x * y + seed) % 256);
        }
    return img;
}

/** A quad (two triangles, four vertices of its own) at height z. */
void addQuad(core::Mesh& mesh, float z, std::uint32_t material, const glm::vec4& color) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const glm::vec2& c : corners) {
        mesh.positions.push_back({c.x + z * 0.25f, c.y - z, z});
        mesh.normals.push_back({0, 0, 1});
        mesh.uvs.push_back({c.x * 0.5f + 0.125f, 1.0f - c.y * 0.75f});
        mesh.colors.push_back(color * glm::vec4(c.x, c.y, 1.0f - z, 1.0f));
    }
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    mesh.triangleMaterial.insert(mesh.triangleMaterial.end(), {material, material});
}

/**
 * Vertex colours, UVs, three materials in five runs (0, 1, 0, 2, 1), two textures (one with a
 * varying alpha, one opaque, used in the other order), a material no triangle uses.
 */
core::Mesh makeColoredMesh() {
    core::Mesh mesh;
    addQuad(mesh, 0.0f, 0, {1.0f, 0.5f, 0.25f, 1.0f});
    addQuad(mesh, 0.1f, 1, {0.2f, 0.4f, 0.6f, 0.5f});
    addQuad(mesh, 0.2f, 1, {0.9f, 0.8f, 0.7f, 0.25f});
    addQuad(mesh, 0.3f, 0, {0.1f, 0.2f, 0.3f, 1.0f});
    addQuad(mesh, 0.4f, 2, {0.5f, 0.5f, 0.5f, 1.0f});
    addQuad(mesh, 0.5f, 1, {1.0f, 1.0f, 1.0f, 0.0f});
    mesh.materials = {core::Material{"first", {0.8f, 0.6f, 0.4f, 1.0f}, 0},
                      core::Material{"second", {1.0f, 1.0f, 1.0f, 0.5f}, 1},
                      core::Material{"plain", {0.1f, 0.2f, 0.3f, 1.0f}, -1},
                      core::Material{"unused", {0.3f, 0.3f, 0.3f, 1.0f}, 0}};
    mesh.textures = {makeImage(17, 9, false, 3), makeImage(8, 12, true, 40)};
    return mesh;
}

void expectSameMesh(const core::Mesh& a, const core::Mesh& b) {
    ASSERT_EQ(a.vertexCount(), b.vertexCount());
    ASSERT_EQ(a.triangleCount(), b.triangleCount());
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.triangleMaterial, b.triangleMaterial);
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t o = 0; o < a.objects.size(); ++o) {
        EXPECT_EQ(a.objects[o].name, b.objects[o].name);
        EXPECT_EQ(a.objects[o].firstTriangle, b.objects[o].firstTriangle);
    }
    ASSERT_EQ(a.normals.size(), b.normals.size());
    ASSERT_EQ(a.uvs.size(), b.uvs.size());
    ASSERT_EQ(a.colors.size(), b.colors.size());
    std::size_t bad = 0;
    for (std::size_t v = 0; v < a.vertexCount(); ++v) {
        for (int k = 0; k < 3; ++k) {
            bad += std::abs(a.positions[v][k] - b.positions[v][k]) > 1e-6f;
            bad += std::abs(a.normals[v][k] - b.normals[v][k]) > 1e-6f;
        }
        if (a.hasUvs())
            for (int k = 0; k < 2; ++k)
                bad += std::abs(a.uvs[v][k] - b.uvs[v][k]) > 1e-6f;
        if (a.hasColors())
            bad += a.colors[v] != b.colors[v];
    }
    EXPECT_EQ(bad, 0u) << "vertex components differ";
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t m = 0; m < a.materials.size(); ++m) {
        EXPECT_EQ(a.materials[m].name, b.materials[m].name);
        EXPECT_EQ(a.materials[m].baseColorFactor, b.materials[m].baseColorFactor) << m;
        EXPECT_EQ(a.materials[m].baseColorTexture, b.materials[m].baseColorTexture) << m;
    }
    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (std::size_t t = 0; t < a.textures.size(); ++t) {
        EXPECT_EQ(a.textures[t].width, b.textures[t].width);
        EXPECT_EQ(a.textures[t].height, b.textures[t].height);
        EXPECT_TRUE(a.textures[t].rgba == b.textures[t].rgba) << "texture " << t << " differs";
    }
}

core::Mesh roundTrip(const core::Mesh& mesh, const TempDir& dir, const std::string& name) {
    const std::string path = dir.file(name);
    const core::Status saved = core::saveGlb(path, mesh);
    EXPECT_TRUE(saved.ok()) << saved.error();
    core::Result<core::Mesh> loaded = core::loadMesh(path);
    EXPECT_TRUE(loaded.ok()) << loaded.error();
    if (!loaded)
        return {};
    // Only UVs that overlap (the box's faces share its logo) are named at load.
    for (const std::string& warning : loaded->warnings)
        EXPECT_NE(warning.find("covered by two or more triangles"), std::string::npos) << warning;
    return std::move(loaded).value();
}

std::uint32_t u32(const std::string& b, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, b.data() + at, 4);
    return v;
}

/**
 * Checks the GLB container and the JSON against the glTF 2.0 rules a validator applies to what
 * we write; returns the JSON.
 */
Json checkGlbLayout(const std::string& b) {
    EXPECT_GE(b.size(), 28u);
    if (b.size() < 28)
        return {};
    EXPECT_EQ(b.compare(0, 4, "glTF"), 0);
    EXPECT_EQ(u32(b, 4), 2u);
    EXPECT_EQ(u32(b, 8), b.size());
    EXPECT_EQ(b.size() % 4, 0u);
    const std::uint32_t jsonLength = u32(b, 12);
    EXPECT_EQ(u32(b, 16), 0x4E4F534Au); // JSON
    EXPECT_EQ(jsonLength % 4, 0u);
    const std::size_t binHeader = 20 + jsonLength;
    EXPECT_LE(binHeader + 8, b.size());
    const std::uint32_t binLength = u32(b, binHeader);
    EXPECT_EQ(u32(b, binHeader + 4), 0x004E4942u); // BIN
    EXPECT_EQ(binLength % 4, 0u);
    EXPECT_EQ(binHeader + 8 + binLength, b.size());
    const std::string jsonText = b.substr(20, jsonLength);
    // JSON padding is spaces.
    EXPECT_EQ(jsonText.find('\0'), std::string::npos);
    const Json json = Json::parse(jsonText);
    const std::string_view bin(b.data() + binHeader + 8, binLength);

    EXPECT_EQ(json["asset"]["version"], "2.0");
    EXPECT_EQ(json["buffers"].size(), 1u);
    EXPECT_FALSE(json["buffers"][0].contains("uri"));
    const std::uint64_t bufferLength = json["buffers"][0]["byteLength"];
    EXPECT_LE(bufferLength, binLength);
    EXPECT_GE(bufferLength + 3, binLength);
    for (const Json& view : json["bufferViews"]) {
        const std::uint64_t offset = view.value("byteOffset", 0), length = view["byteLength"];
        EXPECT_EQ(offset % 4, 0u);
        EXPECT_GE(length, 1u);
        EXPECT_LE(offset + length, bufferLength);
        if (view.contains("byteStride")) {
            EXPECT_EQ(view["target"], 34962); // only vertex attributes have a stride
            EXPECT_EQ(view["byteStride"].get<int>() % 4, 0);
        }
    }
    std::vector<int> viewUsers(json["bufferViews"].size(), 0);
    for (const Json& acc : json["accessors"]) {
        const Json& view = json["bufferViews"][acc["bufferView"].get<std::size_t>()];
        ++viewUsers[acc["bufferView"].get<std::size_t>()];
        const std::uint64_t comps = acc["type"] == "SCALAR" ? 1
                                    : acc["type"] == "VEC2" ? 2
                                    : acc["type"] == "VEC3" ? 3
                                                            : 4;
        EXPECT_TRUE(acc["componentType"] == 5126 || acc["componentType"] == 5125);
        const std::uint64_t element = comps * 4;
        const std::uint64_t stride = view.value("byteStride", element);
        const std::uint64_t offset = acc.value("byteOffset", 0);
        const std::uint64_t count = acc["count"];
        EXPECT_GE(count, 1u);
        EXPECT_EQ(offset % 4, 0u);
        EXPECT_LE(offset + stride * (count - 1) + element, view["byteLength"].get<std::uint64_t>());
    }
    for (std::size_t v = 0; v < viewUsers.size(); ++v) {
        if (viewUsers[v] > 1 && json["bufferViews"][v].value("target", 0) == 34962) {
            EXPECT_TRUE(json["bufferViews"][v].contains("byteStride"))
                << "a vertex view shared by accessors needs a byteStride";
        }
    }
    std::vector<Json> primitives;
    for (const Json& mesh : json["meshes"])
        primitives.insert(primitives.end(), mesh["primitives"].begin(), mesh["primitives"].end());
    for (const Json& prim : primitives) {
        const Json& pos = json["accessors"][prim["attributes"]["POSITION"].get<std::size_t>()];
        EXPECT_TRUE(pos.contains("min") && pos.contains("max")) << "POSITION needs min and max";
        // min and max are exactly the extremes of the data.
        const Json& view = json["bufferViews"][pos["bufferView"].get<std::size_t>()];
        const std::size_t start =
            view.value("byteOffset", std::size_t{0}) + pos.value("byteOffset", std::size_t{0});
        const std::size_t stride = view.value("byteStride", std::size_t{12});
        std::vector<float> lo(3, INFINITY), hi(3, -INFINITY);
        for (std::size_t i = 0; i < pos["count"].get<std::size_t>(); ++i)
            for (std::size_t k = 0; k < 3; ++k) {
                float f = 0;
                std::memcpy(&f, bin.data() + start + i * stride + k * 4, 4);
                lo[k] = std::min(lo[k], f);
                hi[k] = std::max(hi[k], f);
            }
        for (std::size_t k = 0; k < 3; ++k) {
            EXPECT_EQ(pos["min"][k].get<float>(), lo[k]);
            EXPECT_EQ(pos["max"][k].get<float>(), hi[k]);
        }
        const Json& idx = json["accessors"][prim["indices"].get<std::size_t>()];
        EXPECT_EQ(idx["componentType"], 5125);
        EXPECT_EQ(json["bufferViews"][idx["bufferView"].get<std::size_t>()]["target"], 34963);
        EXPECT_FALSE(
            json["bufferViews"][idx["bufferView"].get<std::size_t>()].contains("byteStride"));
    }
    for (const Json& img : json.value("images", Json::array())) {
        EXPECT_EQ(img["mimeType"], "image/png");
        const Json& view = json["bufferViews"][img["bufferView"].get<std::size_t>()];
        EXPECT_FALSE(view.contains("byteStride"));
        EXPECT_EQ(bin.substr(view.value("byteOffset", std::size_t{0}), 8), "\x89PNG\r\n\x1a\n");
    }
    EXPECT_EQ(json["scene"], 0);
    EXPECT_EQ(json["scenes"].size(), 1u);
    // A node and a mesh per named object (one without), each node in the scene.
    EXPECT_GE(json["nodes"].size(), 1u);
    EXPECT_EQ(json["meshes"].size(), json["nodes"].size());
    EXPECT_EQ(json["scenes"][0]["nodes"].size(), json["nodes"].size());
    for (std::size_t n = 0; n < json["nodes"].size(); ++n)
        EXPECT_EQ(json["nodes"][n]["mesh"], n);
    return json;
}

TEST(GltfExportTest, TrefoilRoundTrip) {
    TempDir dir;
    const core::Mesh mesh = core::makeTrefoil();
    const core::Mesh back = roundTrip(mesh, dir, "trefoil.glb");
    expectSameMesh(mesh, back);
    const Json json = checkGlbLayout(readFile(dir.path() / "trefoil.glb"));
    EXPECT_EQ(json["meshes"][0]["primitives"].size(), 1u);
    EXPECT_FALSE(json["meshes"][0]["primitives"][0]["attributes"].contains("COLOR_0"));
}

TEST(GltfExportTest, TexturedModelRoundTrip) {
    const fs::path model = kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!fs::exists(model))
        GTEST_SKIP() << model << " is not installed";
    core::Result<core::Mesh> original = core::loadMesh(model.string());
    ASSERT_TRUE(original.ok()) << original.error();
    ASSERT_EQ(original->textures.size(), 1u);
    original->source.reset(); // the flattened writer (gltf_write_back_test.cpp: the scene's)
    TempDir dir;
    const core::Mesh back = roundTrip(*original, dir, "box.glb");
    expectSameMesh(*original, back);
    checkGlbLayout(readFile(dir.path() / "box.glb"));
}

TEST(GltfExportTest, ManyNodesAndMaterialsRoundTrip) {
    const fs::path model = kModels / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
    if (!fs::exists(model))
        GTEST_SKIP() << model << " is not installed";
    core::Result<core::Mesh> original = core::loadMesh(model.string());
    ASSERT_TRUE(original.ok()) << original.error();
    original->source.reset(); // the flattened writer (gltf_write_back_test.cpp: the scene's)
    EXPECT_GT(original->objects.size(), 10u) << "the engine's named nodes";
    TempDir dir;
    const core::Mesh back = roundTrip(*original, dir, "engine.glb");
    expectSameMesh(*original, back);
    checkGlbLayout(readFile(dir.path() / "engine.glb"));
}

TEST(GltfExportTest, VertexColorsMaterialRunsAndTexturesRoundTrip) {
    TempDir dir;
    const core::Mesh mesh = makeColoredMesh();
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().error();
    const core::Mesh back = roundTrip(mesh, dir, "colored.glb");
    expectSameMesh(mesh, back);
    const Json json = checkGlbLayout(readFile(dir.path() / "colored.glb"));
    // One primitive per run of consecutive triangles with one material.
    const Json& prims = json["meshes"][0]["primitives"];
    ASSERT_EQ(prims.size(), 5u);
    const int expected[] = {0, 1, 0, 2, 1};
    for (std::size_t p = 0; p < prims.size(); ++p) {
        EXPECT_EQ(prims[p]["material"], expected[p]);
        const Json& color = json["accessors"][prims[p]["attributes"]["COLOR_0"].get<std::size_t>()];
        EXPECT_EQ(color["componentType"], 5126);
        EXPECT_EQ(color["type"], "VEC4");
    }
    EXPECT_EQ(json["images"].size(), 2u);
}

TEST(GltfExportTest, OnlyUsedTexturesInOrderOfFirstUse) {
    TempDir dir;
    core::Mesh mesh = makeColoredMesh();
    // Texture 2 is unused; material 0 uses texture 1 first.
    mesh.textures.push_back(makeImage(4, 4, true, 9));
    mesh.materials[0].baseColorTexture = 1;
    mesh.materials[1].baseColorTexture = 0;
    mesh.materials[3].baseColorTexture = 1;
    const core::Mesh back = roundTrip(mesh, dir, "order.glb");
    ASSERT_EQ(back.textures.size(), 2u);
    EXPECT_EQ(back.materials[0].baseColorTexture, 0);
    EXPECT_EQ(back.materials[1].baseColorTexture, 1);
    EXPECT_EQ(back.materials[3].baseColorTexture, 0);
    EXPECT_TRUE(back.textures[0].rgba == mesh.textures[1].rgba);
    EXPECT_TRUE(back.textures[1].rgba == mesh.textures[0].rgba);
}

TEST(GltfExportTest, VerticesSharedBetweenRunsKeepTriangleOrder) {
    // Two materials alternate over triangles that share vertices: the vertices are duplicated
    // per primitive, but triangles keep their order, corners and materials.
    core::Mesh mesh;
    for (int i = 0; i < 6; ++i) {
        const float x = static_cast<float>(i);
        mesh.positions.insert(mesh.positions.end(), {{x, 0, 0}, {x, 1, 0}});
        mesh.normals.insert(mesh.normals.end(), {{0, 0, 1}, {0, 0, 1}});
    }
    mesh.positions.push_back({9, 9, 9}); // no triangle uses it
    mesh.normals.push_back({1, 0, 0});
    for (std::uint32_t i = 0; i < 5; ++i) {
        mesh.indices.insert(mesh.indices.end(), {2 * i, 2 * i + 2, 2 * i + 1});
        mesh.indices.insert(mesh.indices.end(), {2 * i + 1, 2 * i + 2, 2 * i + 3});
        mesh.triangleMaterial.insert(mesh.triangleMaterial.end(), {i % 2, i % 2});
    }
    mesh.materials = {core::Material{"a", glm::vec4(1.0f), -1},
                      core::Material{"b", glm::vec4(0.5f), -1}};
    ASSERT_TRUE(mesh.validate().ok()) << mesh.validate().error();
    TempDir dir;
    const core::Mesh back = roundTrip(mesh, dir, "shared.glb");
    ASSERT_EQ(back.triangleCount(), mesh.triangleCount());
    EXPECT_EQ(back.triangleMaterial, mesh.triangleMaterial);
    for (std::size_t i = 0; i < mesh.indices.size(); ++i)
        EXPECT_EQ(back.positions[back.indices[i]], mesh.positions[mesh.indices[i]]) << i;
    EXPECT_EQ(back.vertexCount(), 5u * 4u); // 4 per run, the unused vertex dropped
}

TEST(GltfExportTest, ExtrasRoundTrip) {
    TempDir dir;
    const Json extras = {{"layerpaint",
                          {{"version", 1},
                           {"camera", {{"yaw", 30.5}, {"pitch", -10}}},
                           {"hidden", {1, 5, 9}},
                           {"name", "\xc3\xa9t\xc3\xa9 \"quoted\""}}}};
    const std::string path = dir.file("project.glb");
    const core::Status saved = core::saveGlb(path, core::makeTrefoil(20, 8), extras);
    ASSERT_TRUE(saved.ok()) << saved.error();
    core::Result<Json> read = core::readGlbExtras(path);
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(*read, extras);
    EXPECT_EQ(checkGlbLayout(readFile(path))["asset"]["extras"], extras);
    EXPECT_TRUE(core::loadMesh(path).ok());

    // No extras: an empty object.
    ASSERT_TRUE(core::saveGlb(path, core::makeTrefoil(20, 8)).ok());
    read = core::readGlbExtras(path);
    ASSERT_TRUE(read.ok()) << read.error();
    EXPECT_EQ(*read, Json::object());

    // A corpus file, binary and JSON.
    const fs::path box = kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (fs::exists(box)) {
        read = core::readGlbExtras(box.string());
        EXPECT_TRUE(read.ok()) << read.error();
    }
    const fs::path boxJson = kModels / "glTF2/BoxTextured-glTF/BoxTextured.gltf";
    if (fs::exists(boxJson)) {
        read = core::readGlbExtras(boxJson.string());
        EXPECT_TRUE(read.ok()) << read.error();
    }
}

TEST(GltfExportTest, ReadExtrasRejectsBadFiles) {
    TempDir dir;
    auto expectError = [](const std::string& path, const std::string& what) {
        core::Result<Json> read = core::readGlbExtras(path);
        ASSERT_FALSE(read.ok()) << path;
        EXPECT_NE(read.error().find(path), std::string::npos) << read.error();
        EXPECT_NE(read.error().find(what), std::string::npos) << read.error();
    };
    expectError(dir.file("missing.glb"), "does not exist");
    expectError(dir.path().string(), "not a regular file");
    writeFile(dir.path() / "text.glb", "hello");
    expectError(dir.file("text.glb"), "not valid glTF JSON");
    writeFile(dir.path() / "noasset.gltf", "{\"extras\": 1}");
    expectError(dir.file("noasset.gltf"), "no asset");
    writeFile(dir.path() / "badextras.gltf", "{\"asset\": {\"version\": \"2.0\", \"extras\": 3}}");
    expectError(dir.file("badextras.gltf"), "not a JSON object");
    writeFile(dir.path() / "deep.gltf", std::string(100000, '['));
    expectError(dir.file("deep.gltf"), "nested too deeply");

    // A GLB whose JSON chunk runs past the end.
    const std::string path = dir.file("cut.glb");
    ASSERT_TRUE(core::saveGlb(path, core::makeTrefoil(20, 8)).ok());
    std::string bytes = readFile(path);
    const std::uint32_t jsonLength = u32(bytes, 12);
    bytes.resize(20 + jsonLength / 2);
    writeFile(path, bytes);
    expectError(path, "truncated");
    writeFile(path, bytes.substr(0, 10));
    expectError(path, "truncated");
}

TEST(GltfExportTest, SaveKeepsOneBackup) {
    TempDir dir;
    const std::string path = dir.file("model.glb");
    ASSERT_TRUE(core::saveGlb(path, core::makeTrefoil(20, 8)).ok());
    const std::string first = readFile(path);
    EXPECT_FALSE(fs::exists(path + ".bak")); // nothing to back up the first time
    ASSERT_TRUE(core::saveGlb(path, makeColoredMesh()).ok());
    const std::string second = readFile(path);
    EXPECT_NE(first, second);
    EXPECT_EQ(readFile(path + ".bak"), first);
    ASSERT_TRUE(core::saveGlb(path, core::makeTrefoil(30, 8)).ok());
    EXPECT_EQ(readFile(path + ".bak"), second);
    // The backup is a complete file (loadMesh picks the format by extension).
    fs::copy_file(path + ".bak", dir.path() / "restored.glb");
    EXPECT_TRUE(core::loadMesh(dir.file("restored.glb")).ok());
    fs::remove(dir.path() / "restored.glb");
    // No temporary files are left behind.
    EXPECT_EQ(folderNames(dir.path()), (std::vector<std::string>{"model.glb", "model.glb.bak"}));
}

TEST(GltfExportTest, SaveAfterACrashBetweenBackupAndReplaceLeavesNoTemporary) {
    // A save killed after making the backup (a hard link to the file) and before replacing the
    // file leaves the backup and the file as one inode; the next save must still clean up.
    TempDir dir;
    const std::string path = dir.file("model.glb");
    ASSERT_TRUE(core::saveGlb(path, core::makeTrefoil(20, 8)).ok());
    const std::string first = readFile(path);
    ASSERT_EQ(::link(path.c_str(), (path + ".bak").c_str()), 0);
    ASSERT_TRUE(core::saveGlb(path, makeColoredMesh()).ok());
    EXPECT_EQ(readFile(path + ".bak"), first);
    EXPECT_NE(readFile(path), first);
    EXPECT_EQ(folderNames(dir.path()), (std::vector<std::string>{"model.glb", "model.glb.bak"}));
}

TEST(GltfExportTest, SaveKeepsPermissionsAndFollowsLinks) {
    TempDir dir;
    const std::string path = dir.file("model.glb");
    ASSERT_TRUE(core::saveGlb(path, core::makeTrefoil(20, 8)).ok());
    fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    ASSERT_TRUE(core::saveGlb(path, makeColoredMesh()).ok());
    EXPECT_EQ(fs::status(path).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);

    const std::string link = dir.file("link.glb");
    fs::create_symlink("model.glb", link);
    ASSERT_TRUE(core::saveGlb(link, core::makeTrefoil(20, 8)).ok());
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(readFile(path), readFile(link));
    EXPECT_FALSE(fs::exists(link + ".bak"));
    EXPECT_TRUE(fs::exists(path + ".bak"));
}

TEST(GltfExportTest, SaveFailuresNameTheFileAndLeaveItIntact) {
    TempDir dir;
    auto expectFailure = [](const std::string& path, const core::Status& status) {
        ASSERT_FALSE(status.ok()) << path;
        EXPECT_NE(status.error().find(path), std::string::npos) << status.error();
    };
    const core::Mesh mesh = core::makeTrefoil(20, 8);
    // A missing folder.
    const std::string missing = dir.file("no/such/folder/model.glb");
    expectFailure(missing, core::saveGlb(missing, mesh));
    EXPECT_FALSE(fs::exists(dir.path() / "no"));
    // A parent that is a file.
    writeFile(dir.path() / "plain", "not a folder");
    const std::string underFile = dir.file("plain/model.glb");
    expectFailure(underFile, core::saveGlb(underFile, mesh));
    EXPECT_EQ(readFile(dir.path() / "plain"), "not a folder");
    // A folder where the file should be.
    fs::create_directory(dir.path() / "folder.glb");
    expectFailure(dir.file("folder.glb"), core::saveGlb(dir.file("folder.glb"), mesh));
    EXPECT_TRUE(fs::is_directory(dir.path() / "folder.glb"));

    const std::string path = dir.file("model.glb");
    writeFile(path, "old content");
    // An invalid mesh or extras: nothing is written.
    expectFailure(path, core::saveGlb(path, core::Mesh{}));
    expectFailure(path, core::saveGlb(path, mesh, Json::array({1, 2})));
    // Cancelled.
    const core::Status cancelled =
        core::saveGlb(path, makeColoredMesh(), {}, [](double f) { return f < 0.5; });
    expectFailure(path, cancelled);
    EXPECT_NE(cancelled.error().find("cancelled"), std::string::npos);
    EXPECT_TRUE(cancelled.cancelled());
    EXPECT_EQ(readFile(path), "old content");
    EXPECT_FALSE(fs::exists(path + ".bak"));

    // The disk fills up while writing: a file size limit makes write() fail (EFBIG).
    rlimit old{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = old;
    small.rlim_cur = 1000;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
    const core::Status full = core::saveGlb(path, mesh);
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);
    expectFailure(path, full);
    EXPECT_NE(full.error().find("large"), std::string::npos) << full.error(); // "File too large"
    EXPECT_EQ(readFile(path), "old content");
    EXPECT_FALSE(fs::exists(path + ".bak"));

    // Nothing but the files made here is left.
    EXPECT_EQ(folderNames(dir.path()),
              (std::vector<std::string>{"folder.glb", "model.glb", "plain"}));
}

TEST(GltfExportTest, WriteFileAtomically) {
    TempDir dir;
    const std::string path = dir.file("state.json");
    ASSERT_TRUE(core::writeFileAtomically(path, "one", 3).ok());
    ASSERT_TRUE(core::writeFileAtomically(path, "two", 3, false).ok());
    EXPECT_EQ(readFile(path), "two");
    EXPECT_FALSE(fs::exists(path + ".bak"));
    ASSERT_TRUE(core::writeFileAtomically(path, "three", 5).ok());
    EXPECT_EQ(readFile(path + ".bak"), "two");
    EXPECT_EQ(readFile(path), "three");
    // An empty file is a valid result.
    ASSERT_TRUE(core::writeFileAtomically(path, nullptr, 0).ok());
    EXPECT_EQ(readFile(path), "");
}

TEST(GltfExportTest, EncodeGlbMatchesSavedFile) {
    TempDir dir;
    const core::Mesh mesh = makeColoredMesh();
    core::Result<std::vector<std::uint8_t>> bytes = core::encodeGlb(mesh, {{"k", "v"}});
    ASSERT_TRUE(bytes.ok()) << bytes.error();
    ASSERT_TRUE(core::saveGlb(dir.file("a.glb"), mesh, {{"k", "v"}}).ok());
    EXPECT_EQ(readFile(dir.path() / "a.glb"), std::string(bytes->begin(), bytes->end()));
    // Invalid UTF-8 in a name does not throw.
    core::Mesh bad = mesh;
    bad.materials[0].name = "bad \xff\xfe name";
    EXPECT_TRUE(core::encodeGlb(bad).ok());
}

} // namespace gltf_export_test
