// SPDX-License-Identifier: GPL-3.0-or-later
// Model loading: the assimp-testmodels corpus (valid and deliberately broken files), hand-made
// hostile files written to a temporary folder, and the glTF flattening rules.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/mesh_io.h"
#include "tests/core/test_files.h"

namespace fs = std::filesystem;

namespace mesh_io_test {

using core_test::readFile;
using core_test::TempDir;
using core_test::writeFile;

const fs::path kModels = LAYERPAINT_ASSIMP_MODELS;

std::string corpus(const std::string& rel) {
    return (kModels / rel).string();
}

std::string base64(const std::string& bytes) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const auto n = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i]) << 16 |
                                                  static_cast<unsigned char>(bytes[i + 1]) << 8 |
                                                  static_cast<unsigned char>(bytes[i + 2]));
        out += {table[n >> 18], table[(n >> 12) & 63], table[(n >> 6) & 63], table[n & 63]};
    }
    if (bytes.size() - i == 1) {
        const auto n = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i]) << 16);
        out += {table[n >> 18], table[(n >> 12) & 63], '=', '='};
    } else if (bytes.size() - i == 2) {
        const auto n = static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i]) << 16 |
                                                  static_cast<unsigned char>(bytes[i + 1]) << 8);
        out += {table[n >> 18], table[(n >> 12) & 63], table[(n >> 6) & 63], '='};
    }
    return out;
}

std::string dataUri(const std::string& bytes) {
    return "data:application/octet-stream;base64," + base64(bytes);
}

template <typename T> void append(std::string& out, std::initializer_list<T> values) {
    for (T v : values) {
        char b[sizeof(T)];
        std::memcpy(b, &v, sizeof(T));
        out.append(b, sizeof(T));
    }
}

/** (0,0,0) (1,0,0) (0,1,0) as floats, then indices 0 1 2 as unsigned shorts, padded: 44 bytes. */
std::string triangleBuffer(float firstX = 0.0f) {
    std::string b;
    append<float>(b, {firstX, 0, 0, 1, 0, 0, 0, 1, 0});
    append<std::uint16_t>(b, {0, 1, 2, 0});
    return b;
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
    for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size()))
        s.replace(p, from.size(), to);
    return s;
}

/**
 * One triangle in a data-URI buffer; @TOKENS@ can be replaced to break one thing at a time.
 * Accessor 0 = POSITION (bufferView 0), accessor 1 = indices (bufferView 1).
 */
std::string triangleGltf(const std::vector<std::pair<std::string, std::string>>& changes = {}) {
    std::string json = R"({@EXTRA@"asset":{"version":"@VERSION@"},"scene":@SCENE@,
"scenes":[{"nodes":@ROOTS@}],
"nodes":@NODES@,
"meshes":[{"primitives":[{"attributes":{@ATTRIBUTES@},"indices":1@PRIMITIVE@}]}],
"buffers":[{"uri":"@URI@","byteLength":44}],
"bufferViews":[{"buffer":0,"byteOffset":@VIEW_OFFSET@,"byteLength":@VIEW_LENGTH@@STRIDE@},
               {"buffer":0,"byteOffset":36,"byteLength":6}],
"accessors":[{"bufferView":0,"byteOffset":@POS_OFFSET@,"componentType":@POS_TYPE@,"count":3,
              "type":"VEC3"@SPARSE@},
             {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}@MORE_ACCESSORS@]})";
    const std::vector<std::pair<std::string, std::string>> defaults = {
        {"@EXTRA@", ""},
        {"@VERSION@", "2.0"},
        {"@SCENE@", "0"},
        {"@ROOTS@", "[0]"},
        {"@NODES@", R"([{"mesh":0}])"},
        {"@ATTRIBUTES@", R"("POSITION":0)"},
        {"@PRIMITIVE@", ""},
        {"@URI@", dataUri(triangleBuffer())},
        {"@VIEW_OFFSET@", "0"},
        {"@VIEW_LENGTH@", "36"},
        {"@STRIDE@", ""},
        {"@POS_OFFSET@", "0"},
        {"@POS_TYPE@", "5126"},
        {"@SPARSE@", ""},
        {"@MORE_ACCESSORS@", ""}};
    for (const auto& [token, value] : changes)
        json = replaceAll(json, token, value);
    for (const auto& [token, value] : defaults)
        json = replaceAll(json, token, value);
    return json;
}

// ---------------------------------------------------------------------------------------------
// The corpus: every model file under the five folders either loads or is listed here with why.

const std::map<std::string, std::string>& expectedFailures() {
    static const std::map<std::string, std::string> list = {
        {"OBJ/box_UTF16BE.obj", "UTF-16BE text: Assimp 5.2 reads no faces from it"},
        {"OBJ/number_formats.obj",
         "a number-parsing test: its one triangle (0,0,0) (1,2,3) (-1,-2,-3) is collinear"},
        {"OBJ/point_cloud.obj", "points only (v lines, no faces)"},
        {"OBJ/testpoints.obj", "points only (p statements)"},
        {"OBJ/testline.obj", "lines only (l statements)"},
        {"OFF/invalid.off", "deliberately broken: faces of 2 and 4 copies of vertex 0, no area"},
        {"PLY/issue623.ply", "no face element (the index list is a vertex property): points"},
        {"PLY/points.ply", "points only (no face element)"},
        {"PLY/pond.0.ply",
         "a point cloud (no face element), and 69 bytes short of its 70051 declared vertices"},
        {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "infinite positions"},
        {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", "indices past the vertex count"},
        {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "an index past the vertex count"},
        {"glTF2/MissingBin/BoxTextured.gltf", "its .bin buffer is missing"},
        {"glTF2/RecursiveNodes/RecursiveNodes.gltf", "a node cycle (and no mesh)"},
        {"glTF2/SchemaFailures/sceneWrongType.gltf", "\"scene\" is a string"},
        {"glTF2/TestNoRootNode/NoScene.gltf", "the default scene 0 does not exist; no geometry"},
        {"glTF2/TestNoRootNode/SceneWithoutNodes.gltf", "an empty scene: no geometry"},
        {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf", "points"},
        {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_01.gltf", "lines"},
        {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_02.gltf", "line loop"},
        {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_03.gltf", "line strip"},
        {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_07.gltf", "points"},
        {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_08.gltf", "lines"},
        {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_09.gltf", "line loop"},
        {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_10.gltf", "line strip"},
        {"glTF2/wrongTypes/badArray.gltf", "\"primitives\" is an object"},
        {"glTF2/wrongTypes/badExtension.gltf", "an extension that is a string"},
        {"glTF2/wrongTypes/badNumber.gltf", "a texture info without index, scale a string"},
        {"glTF2/wrongTypes/badObject.gltf", "\"pbrMetallicRoughness\" is an array"},
        {"glTF2/wrongTypes/badString.gltf", "a scene name that is a number"},
        {"glTF2/wrongTypes/badUint.gltf", "a texture index of -1"},
    };
    return list;
}

bool isModelFile(const fs::path& p) {
    static const std::set<std::string> notModels = {".png", ".jpg", ".bin",  ".mtl",
                                                    ".md",  ".txt", ".vert", ".frag"};
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return !notModels.count(ext) && p.filename() != "LICENSE";
}

/** Every model file under glTF2, OBJ, PLY, STL and OFF, relative to the corpus folder. */
std::vector<std::string> corpusModels() {
    std::vector<std::string> files;
    for (const char* dir : {"glTF2", "OBJ", "PLY", "STL", "OFF"}) {
        std::error_code ec;
        for (auto it = fs::recursive_directory_iterator(kModels / dir, ec);
             !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
            if (it->is_regular_file() && isModelFile(it->path()))
                files.push_back(fs::relative(it->path(), kModels).generic_string());
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::string testName(const std::string& s) {
    std::string out;
    for (char c : s)
        out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return out;
}

class CorpusModel : public ::testing::TestWithParam<std::string> {};

TEST_P(CorpusModel, LoadsOrFailsAsListed) {
    const std::string rel = GetParam();
    const std::string path = corpus(rel);
    const core::Result<core::Mesh> mesh = core::loadMesh(path);
    const auto expected = expectedFailures().find(rel);
    if (expected == expectedFailures().end()) {
        ASSERT_TRUE(mesh.ok()) << mesh.error();
        EXPECT_GT(mesh->triangleCount(), 0u);
        EXPECT_TRUE(mesh->validate().ok());
    } else {
        ASSERT_FALSE(mesh.ok()) << rel << " was expected to fail: " << expected->second;
        EXPECT_EQ(mesh.error().rfind(path + ": ", 0), 0u) << mesh.error();
        EXPECT_EQ(mesh.error().find('\n'), std::string::npos) << mesh.error();
    }
}

INSTANTIATE_TEST_SUITE_P(AssimpTestModels, CorpusModel, ::testing::ValuesIn(corpusModels()),
                         [](const auto& row) { return testName(row.param); });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(CorpusModel);

TEST(CorpusModelList, FindsTheCorpusAndEveryListedFailure) {
    const std::vector<std::string> files = corpusModels();
    ASSERT_GT(files.size(), 80u) << "is assimp-testmodels installed under " << kModels << "?";
    for (const auto& [rel, why] : expectedFailures())
        EXPECT_TRUE(std::binary_search(files.begin(), files.end(), rel))
            << rel << " (" << why << ") is no longer in the corpus";
}

// ---------------------------------------------------------------------------------------------
// Exact counts, verified independently of Assimp and tinygltf with a throwaway script that read
// the files themselves:
// - glTF: walked the default scene's nodes; per mesh instance added the POSITION accessor count
//   (after checking the index buffers reference every vertex) and the index accessor count / 3
//   for TRIANGLES, count - 2 for strips and fans; points and lines skipped. Incomplete trailing
//   triangles dropped (IncorrectVertexArrays: 36+33+36+33 referenced vertices, 12+11+12+11).
// - OBJ/PLY/OFF/ASCII STL: counted the face lines (a polygon of n corners is n - 2 triangles,
//   points and lines none) and the distinct vertices the faces use. Distinct means distinct
//   attribute tuples (OBJ: v/vt/vn values per object and material, i.e. per Assimp mesh; STL:
//   position plus facet normal; PLY: every vertex property), because JoinIdenticalVertices
//   merges exactly those. Binary STL: the same from the 50-byte facet records.
// Files where Assimp's epsilon-based joining merges nearly equal tuples and the exact count
// differs (PLY/Wuson.ply 11184 exact vs 11152, the Spider STLs, 3DSMaxExport.STL, regr01.obj)
// are not listed.

struct VerifiedCounts {
    const char* path;
    std::size_t vertices;
    std::size_t triangles;
};

const VerifiedCounts kVerified[] = {
    {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", 24, 12},
    {"glTF2/BoxTextured-glTF/BoxTextured.gltf", 24, 12},
    {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", 84657, 121496},
    {"glTF2/ClearCoat-glTF/ClearCoatTest.gltf", 20106, 37116},
    {"glTF2/cameras/Cameras.gltf", 4, 2},
    {"glTF2/simple_skin/simple_skin.gltf", 10, 8},
    {"glTF2/issue_3269/texcoord_crash.gltf", 20, 10},
    {"glTF2/IncorrectVertexArrays/Cube.gltf", 138, 46},
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf", 4, 2}, // strip
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_05.gltf", 4, 2}, // fan
    {"glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_06.gltf", 6, 2},
    {"OBJ/box.obj", 8, 12},
    {"OBJ/box_longline.obj", 8, 944},
    {"OBJ/WusonOBJ.obj", 2117, 3732},
    {"OBJ/spider.obj", 946, 1368},
    {"OBJ/concave_polygon.obj", 64, 64},
    {"OBJ/cube_usemtl.obj", 28, 12},
    {"OBJ/empty_mat.obj", 450, 256},
    {"OBJ/testmixed.obj", 8, 12},
    {"OBJ/cube_with_vertexcolors.obj", 24, 12},
    {"PLY/cube.ply", 8, 12},
    {"PLY/cube_uv.ply", 24, 12},
    {"PLY/float-color.ply", 3, 1},
    {"STL/triangle.stl", 3, 1},
    {"STL/triangle_with_two_solids.stl", 6, 2},
    {"STL/sphereWithHole.stl", 855, 285},
    {"STL/Wuson.stl", 2117, 3732}, // binary; all facet normals are 0, so joined by position
    {"OFF/Cube.off", 8, 12},
    {"OFF/Wuson.off", 2117, 3732},
};

class CorpusCounts : public ::testing::TestWithParam<VerifiedCounts> {};

TEST_P(CorpusCounts, MatchTheFile) {
    const VerifiedCounts& c = GetParam();
    const core::Result<core::Mesh> mesh = core::loadMesh(corpus(c.path));
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_EQ(mesh->vertexCount(), c.vertices) << c.path;
    EXPECT_EQ(mesh->triangleCount(), c.triangles) << c.path;
    EXPECT_EQ(mesh->normals.size(), mesh->vertexCount());
    EXPECT_EQ(mesh->triangleMaterial.size(), mesh->triangleCount());
}

INSTANTIATE_TEST_SUITE_P(AssimpTestModels, CorpusCounts, ::testing::ValuesIn(kVerified),
                         [](const auto& row) { return testName(row.param.path); });

// ---------------------------------------------------------------------------------------------
// Broken files: each is refused with a one-line message naming it.

struct BrokenCase {
    std::string name;
    std::function<fs::path(const fs::path& dir)> make; // returns the file to load
    std::string expect;                                // part of the message, if any
};

void PrintTo(const BrokenCase& c, std::ostream* os) {
    *os << c.name;
}

BrokenCase fromCorpus(const std::string& rel, std::string expect = {}) {
    return {rel, [rel](const fs::path&) { return kModels / rel; }, std::move(expect)};
}

BrokenCase written(const std::string& name, std::string content, std::string expect) {
    return {name,
            [name, content](const fs::path& dir) {
                writeFile(dir / name, content);
                return dir / name;
            },
            std::move(expect)};
}

BrokenCase gltf(const std::string& name, std::vector<std::pair<std::string, std::string>> changes,
                std::string expect) {
    return written(name + ".gltf", triangleGltf(changes), std::move(expect));
}

/** A GLB holding `json` and `bin`, with the header fields as given. */
std::string glb(const std::string& json, const std::string& bin) {
    std::string j = json;
    while (j.size() % 4)
        j += ' ';
    std::string b = bin;
    while (b.size() % 4)
        b += '\0';
    std::string out = "glTF";
    append<std::uint32_t>(out, {2, static_cast<std::uint32_t>(12 + 8 + j.size() + 8 + b.size()),
                                static_cast<std::uint32_t>(j.size()), 0x4E4F534Au});
    out += j;
    append<std::uint32_t>(out, {static_cast<std::uint32_t>(b.size()), 0x004E4942u});
    out += b;
    return out;
}

std::string glbTriangleJson() {
    return replaceAll(
        replaceAll(triangleGltf(), R"("uri":")" + dataUri(triangleBuffer()) + "\",", ""), "\n", "");
}

std::vector<BrokenCase> brokenCases() {
    std::vector<BrokenCase> cases;
    // All of invalid/, enumerated so that new files are covered too.
    std::vector<std::string> invalid;
    std::error_code ec;
    for (auto it = fs::directory_iterator(kModels / "invalid", ec);
         !ec && it != fs::directory_iterator(); it.increment(ec))
        if (it->is_regular_file())
            invalid.push_back("invalid/" + it->path().filename().string());
    std::sort(invalid.begin(), invalid.end());
    for (const std::string& rel : invalid)
        cases.push_back(fromCorpus(rel));
    for (const char* rel : {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf",
                            "glTF2/IndexOutOfRange/IndexOutOfRange.gltf"})
        cases.push_back(fromCorpus(rel, "out of range"));
    for (const char* rel : {"glTF2/wrongTypes/badArray.gltf", "glTF2/wrongTypes/badExtension.gltf",
                            "glTF2/wrongTypes/badNumber.gltf", "glTF2/wrongTypes/badObject.gltf",
                            "glTF2/wrongTypes/badString.gltf", "glTF2/wrongTypes/badUint.gltf",
                            "glTF2/SchemaFailures/sceneWrongType.gltf"})
        cases.push_back(fromCorpus(rel));
    cases.push_back(
        fromCorpus("glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "not a finite"));
    cases.push_back(fromCorpus("glTF2/MissingBin/BoxTextured.gltf", "BoxTextured0.bin"));
    cases.push_back(fromCorpus("glTF2/RecursiveNodes/RecursiveNodes.gltf", "more than once"));

    // Files made here.
    cases.push_back(written("empty.gltf", "", "is empty"));
    cases.push_back(written("empty.obj", "", "is empty"));
    cases.push_back({"truncated.glb",
                     [](const fs::path& dir) {
                         const std::string whole =
                             readFile(kModels / "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb");
                         writeFile(dir / "truncated.glb", whole.substr(0, whole.size() / 2));
                         return dir / "truncated.glb";
                     },
                     "truncated"});
    cases.push_back(written("header-only.glb", "glTF\x02\0\0\0", "truncated"));
    {
        // The BIN chunk claims its 8 header bytes as payload too (tinygltf 2.7 would read them).
        std::string bytes = glb(glbTriangleJson(), triangleBuffer());
        const auto binAt = bytes.size() - 44 - 8;
        const std::uint32_t tooLong = 44 + 8;
        std::memcpy(&bytes[binAt], &tooLong, 4);
        cases.push_back(written("bin-past-end.glb", bytes, "BIN chunk"));
    }
    cases.push_back(written("not-json.gltf", "this is not JSON at all", "is not a glTF file"));
    cases.push_back(written("garbage.glb", std::string("\x9c\x01\xff\x00 data", 9),
                            "is not a glTF binary file"));
    cases.push_back(written("broken.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"meshes\": [ }",
                            "malformed at line 2, column 14"));
    // Other files under a model's name: what is wrong in words, never the reader's jargon.
    cases.push_back(written("notes.obj", "just notes\n", "too short to be a Wavefront OBJ model"));
    cases.push_back(written("noise.ply", std::string(300, '\xa7'), "is not a Stanford PLY model"));
    cases.push_back(written("noise.stl", std::string(100, '\xa7'), "is not an STL model"));
    cases.push_back(written("model.xyz", "hello\n", "not in a 3D model format"));
    cases.push_back(written("deep.gltf",
                            "{\"a\": " + std::string(100000, '[') + std::string(100000, ']') + "}",
                            "nested too deeply"));
    cases.push_back(gltf("version1", {{"@VERSION@", "1.0"}}, "version"));
    cases.push_back({"dotdot-buffer.gltf",
                     [](const fs::path& dir) {
                         writeFile(dir / "outside.bin", triangleBuffer());
                         writeFile(dir / "model/dotdot-buffer.gltf",
                                   triangleGltf({{"@URI@", "../outside.bin"}}));
                         return dir / "model/dotdot-buffer.gltf";
                     },
                     "outside the model's folder"});
    cases.push_back({"dotdot-encoded.gltf",
                     [](const fs::path& dir) {
                         writeFile(dir / "outside.bin", triangleBuffer());
                         writeFile(dir / "model/dotdot-encoded.gltf",
                                   triangleGltf({{"@URI@", "%2E%2E/outside.bin"}}));
                         return dir / "model/dotdot-encoded.gltf";
                     },
                     "outside the model's folder"});
    cases.push_back({"absolute-buffer.gltf",
                     [](const fs::path& dir) {
                         writeFile(dir / "outside.bin", triangleBuffer());
                         writeFile(dir / "model/absolute-buffer.gltf",
                                   triangleGltf({{"@URI@", (dir / "outside.bin").string()}}));
                         return dir / "model/absolute-buffer.gltf";
                     },
                     "absolute path"});
    cases.push_back(
        {"symlink-buffer.gltf",
         [](const fs::path& dir) {
             writeFile(dir / "outside.bin", triangleBuffer());
             writeFile(dir / "model/symlink-buffer.gltf", triangleGltf({{"@URI@", "link.bin"}}));
             fs::create_symlink(dir / "outside.bin", dir / "model/link.bin");
             return dir / "model/symlink-buffer.gltf";
         },
         "symbolic link"});
    cases.push_back(
        {"dotdot-image.gltf",
         [](const fs::path& dir) {
             writeFile(dir / "outside.png",
                       readFile(kModels / "glTF2/BoxTextured-glTF/CesiumLogoFlat.png"));
             writeFile(
                 dir / "model/dotdot-image.gltf",
                 triangleGltf(
                     {{"@PRIMITIVE@", R"(,"material":0)"},
                      {"@EXTRA@",
                       R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],
"textures":[{"source":0}],"images":[{"uri":"../outside.png"}],)"}}));
             return dir / "model/dotdot-image.gltf";
         },
         "outside the model's folder"});
    // Offsets: one beyond the schema's range, one whose sum runs past the view, one past the
    // buffer, one so large that a 32-bit sum would wrap.
    cases.push_back(gltf("offset-huge", {{"@POS_OFFSET@", "18446744073709551615"}}, "byteOffset"));
    cases.push_back(gltf("offset-wraps", {{"@POS_OFFSET@", "4294967292"}},
                         "reads past the end of buffer view 0"));
    cases.push_back(gltf("offset-past-view", {{"@POS_OFFSET@", "4"}},
                         "accessor 0 reads past the end of buffer view 0"));
    cases.push_back(gltf("view-past-buffer",
                         {{"@VIEW_OFFSET@", "4294967295"}, {"@VIEW_LENGTH@", "4294967295"}},
                         "buffer view 0 reaches past the end of buffer 0"));
    cases.push_back(gltf("stride-too-small", {{"@STRIDE@", R"(,"byteStride":4)"}}, "stride"));
    cases.push_back(gltf("position-ubyte", {{"@POS_TYPE@", "5121"}}, "component type"));
    cases.push_back(gltf("index-out-of-range",
                         {{"@URI@", dataUri(replaceAll(triangleBuffer(), std::string("\2\0", 2),
                                                       std::string("\7\0", 2)))}},
                         "out of range"));
    cases.push_back(
        gltf("nan-position",
             {{"@URI@", dataUri(triangleBuffer(std::numeric_limits<float>::quiet_NaN()))}},
             "not a finite number"));
    cases.push_back(gltf(
        "normal-count",
        {{"@ATTRIBUTES@", R"("POSITION":0,"NORMAL":2)"},
         {"@MORE_ACCESSORS@", R"(,{"bufferView":0,"componentType":5126,"count":2,"type":"VEC3"})"}},
        "NORMAL has 2 elements"));
    cases.push_back(gltf(
        "normal-as-vec2",
        {{"@ATTRIBUTES@", R"("POSITION":0,"NORMAL":2)"},
         {"@MORE_ACCESSORS@", R"(,{"bufferView":0,"componentType":5126,"count":3,"type":"VEC2"})"}},
        "has type VEC2"));
    cases.push_back(
        gltf("missing-accessor", {{"@ATTRIBUTES@", R"("POSITION":9)"}}, "does not exist"));
    cases.push_back(gltf("missing-mesh", {{"@NODES@", R"([{"mesh":3}])"}}, "does not exist"));
    cases.push_back(gltf("missing-scene", {{"@SCENE@", "4"}}, "default scene 4 does not exist"));
    cases.push_back(gltf("cycle", {{"@NODES@", R"([{"mesh":0,"children":[1]},{"children":[0]}])"}},
                         "more than once"));
    cases.push_back(gltf(
        "shared-child",
        {{"@ROOTS@", "[0,1]"}, {"@NODES@", R"([{"children":[2]},{"children":[2]},{"mesh":0}])"}},
        "more than once"));
    cases.push_back(gltf("root-twice", {{"@ROOTS@", "[0,0]"}}, "more than once"));
    cases.push_back(
        gltf("bad-rotation", {{"@NODES@", R"([{"mesh":0,"rotation":[0,0,0,0]}])"}}, "rotation"));
    cases.push_back(gltf("scale-overflow", {{"@NODES@", R"([{"mesh":0,"scale":[1e300,1,1]}])"}},
                         "not finite after the node transform"));
    cases.push_back(
        gltf("short-matrix", {{"@NODES@", R"([{"mesh":0,"matrix":[1,0,0]}])"}}, "matrix"));
    cases.push_back(gltf("unsupported-extension",
                         {{"@EXTRA@", R"("extensionsRequired":["EXT_mesh_gpu_instancing"],)"}},
                         "EXT_mesh_gpu_instancing"));
    cases.push_back(gltf("sparse-index-out-of-range",
                         {{"@SPARSE@",
                           R"(,"sparse":{"count":1,"indices":{"bufferView":1,"componentType":5123},
                                         "values":{"bufferView":0}})"},
                          {"@URI@", dataUri(replaceAll(triangleBuffer(), std::string("\0\0\1\0", 4),
                                                       std::string("\5\0\1\0", 4)))}},
                         "sparse index"));
    cases.push_back(gltf("invalid-mode", {{"@PRIMITIVE@", R"(,"mode":9)"}}, "mode"));
    cases.push_back(gltf("negative-index", {{"@NODES@", R"([{"mesh":-1}])"}}, "mesh"));
    // Header counts a small file cannot hold (Assimp would allocate and loop over them).
    cases.push_back(written("many-vertices.ply",
                            "ply\nformat ascii 1.0\nelement vertex 1000000\nproperty float x\n"
                            "property float y\nproperty float z\nelement face 1\n"
                            "property list uchar int vertex_indices\nend_header\n"
                            "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                            "more than the"));
    cases.push_back(written("many-faces.ply",
                            "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                            "property float x\nproperty float y\nproperty float z\n"
                            "element face 50000\nproperty list uchar int vertex_indices\n"
                            "end_header\n" +
                                std::string(36, '\0'),
                            "more than the"));
    cases.push_back(written("many-faces.off", "OFF\n3 1000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                            "more than the"));
    // Assimp reads a count by its leading digits: 10^17 faces (found by fuzzing).
    cases.push_back(written("many-faces-then-letters.off",
                            "OFF\n3 100000000000000000storage 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                            "more than the"));
    cases.push_back(written("empty-face.obj", "mtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf\n",
                            "face without vertices"));
    // Found by fuzzing (tests/fuzz): Assimp hangs or reads past its buffer on these.
    cases.push_back(written("no-end-header.ply",
                            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                            "0\n1\n2\n",
                            "does not end"));
    cases.push_back(written("broken-element.ply",
                            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                            "element f00.0 0.0 0 0 1 1\nend_header\n3 0 1 2\n",
                            "is not followed by what it needs"));
    cases.push_back(written("fraction-count.ply",
                            "ply\nformat ascii 1.0\nelement vertex 0.0\nproperty float x\n"
                            "end_header\n",
                            "not a whole number"));
    cases.push_back(written("no-properties.ply",
                            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                            "property float y\nproperty float z\nelement face 1\nend_header\n"
                            "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                            "without properties"));
    cases.push_back(
        written("short-face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 4\n", "says it has 4"));
    cases.push_back(written("bad-index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
                            "not one of the file's 3 vertices"));
    return cases;
}

/** Whether text is valid UTF-8 without control characters: fit to show to a user. */
bool showable(const std::string& text) {
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        const int follow = c < 0x80             ? 0
                           : (c & 0xE0) == 0xC0 ? 1
                           : (c & 0xF0) == 0xE0 ? 2
                           : (c & 0xF8) == 0xF0 ? 3
                                                : -1;
        if (follow < 0 || c < 0x20 || c == 0x7F || i + follow >= text.size() + (follow ? 0 : 1))
            return false;
        for (int k = 1; k <= follow; ++k)
            if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80)
                return false;
        i += std::size_t(follow) + 1;
    }
    return true;
}

class BrokenFile : public ::testing::TestWithParam<BrokenCase> {};

TEST_P(BrokenFile, IsRefusedWithAOneLineMessageNamingIt) {
    TempDir dir;
    ASSERT_FALSE(dir.path().empty());
    const fs::path file = GetParam().make(dir.path());
    const core::Result<core::Mesh> mesh = core::loadMesh(file.string());
    ASSERT_FALSE(mesh.ok()) << file << " loaded";
    EXPECT_NE(mesh.error().find(file.filename().string()), std::string::npos) << mesh.error();
    EXPECT_EQ(mesh.error().rfind(file.string() + ": ", 0), 0u) << mesh.error();
    EXPECT_EQ(mesh.error().find('\n'), std::string::npos) << mesh.error();
    EXPECT_TRUE(showable(mesh.error())) << "raw bytes in: " << mesh.error();
    if (!GetParam().expect.empty()) {
        EXPECT_NE(mesh.error().find(GetParam().expect), std::string::npos) << mesh.error();
    }
}

INSTANTIATE_TEST_SUITE_P(All, BrokenFile, ::testing::ValuesIn(brokenCases()),
                         [](const auto& row) { return testName(row.param.name); });

// ---------------------------------------------------------------------------------------------
// Materials and textures

TEST(MeshIo, BoxTexturedHasUvsTextureAndBaseColor) {
    const core::Result<core::Mesh> gltf =
        core::loadMesh(corpus("glTF2/BoxTextured-glTF/BoxTextured.gltf"));
    const core::Result<core::Mesh> glb =
        core::loadMesh(corpus("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"));
    for (const auto* result : {&gltf, &glb}) {
        ASSERT_TRUE(result->ok()) << result->error();
        const core::Mesh& mesh = result->value();
        EXPECT_TRUE(mesh.hasUvs());
        EXPECT_EQ(mesh.uvs.size(), mesh.vertexCount());
        // The box repeats the logo: its UVs run from 0 to 6 (the sampler wraps).
        const auto [lo, hi] =
            std::minmax_element(mesh.uvs.begin(), mesh.uvs.end(),
                                [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x; });
        EXPECT_EQ(lo->x, 0.0f);
        EXPECT_EQ(hi->x, 6.0f);
        ASSERT_EQ(mesh.textures.size(), 1u);
        // CesiumLogoFlat.png: a 211 x 211 palette PNG (its IHDR read with a script).
        EXPECT_EQ(mesh.textures[0].width, 211);
        EXPECT_EQ(mesh.textures[0].height, 211);
        EXPECT_EQ(mesh.textures[0].rgba.size(), 211u * 211u * 4u);
        ASSERT_EQ(mesh.materials.size(), 1u);
        EXPECT_EQ(mesh.materials[0].name, "Texture");
        EXPECT_EQ(mesh.materials[0].baseColorTexture, 0);
        EXPECT_EQ(mesh.materials[0].baseColorFactor, glm::vec4(1.0f)); // the glTF default
        // Six faces on the one repeating logo: the UVs are kept, and the warning says so.
        ASSERT_EQ(mesh.warnings.size(), 1u);
        EXPECT_EQ(mesh.warnings[0].rfind("100% of the UV area of BoxTextured.gl", 0), 0u)
            << mesh.warnings[0];
    }
    // The external PNG and the one in the GLB's buffer view decode to the same pixels.
    ASSERT_TRUE(gltf.ok() && glb.ok());
    EXPECT_EQ(gltf->textures[0].rgba, glb->textures[0].rgba);
    EXPECT_EQ(gltf->positions, glb->positions);
    EXPECT_EQ(gltf->uvs, glb->uvs);
}

TEST(MeshIo, BaseColorFactorsAndSharedImages) {
    // issue_3269: five materials, four of them on the same image (512 x 512), one without.
    const core::Result<core::Mesh> mesh =
        core::loadMesh(corpus("glTF2/issue_3269/texcoord_crash.gltf"));
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    ASSERT_EQ(mesh->materials.size(), 5u);
    EXPECT_EQ(mesh->textures.size(), 1u);
    EXPECT_EQ(mesh->materials[0].name, "BackPlaneMat");
    EXPECT_EQ(mesh->materials[0].baseColorTexture, -1);
    EXPECT_NEAR(mesh->materials[0].baseColorFactor.r, 0.16f, 1e-6f);
    EXPECT_EQ(mesh->materials[1].baseColorTexture, 0);
    EXPECT_NEAR(mesh->materials[1].baseColorFactor.b, 0.8f, 1e-6f);
    EXPECT_EQ(mesh->materials[4].baseColorTexture, 0);
}

TEST(MeshIo, ObjTexturesAreReadFromTheModelFolder) {
    // spider.mtl names its textures ".\SpiderTex.jpg" etc. (Windows separators).
    const core::Result<core::Mesh> mesh = core::loadMesh(corpus("OBJ/spider.obj"));
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    EXPECT_TRUE(mesh->hasUvs());
    EXPECT_EQ(mesh->textures.size(), 5u);
    int textured = 0;
    for (const core::Material& m : mesh->materials)
        if (m.baseColorTexture >= 0) {
            ++textured;
            // A texture is shown as is: the legacy diffuse color does not tint it.
            EXPECT_EQ(glm::vec3(m.baseColorFactor), glm::vec3(1.0f)) << m.name;
        }
    EXPECT_EQ(textured, 5);
    for (const core::Image& img : mesh->textures) {
        EXPECT_FALSE(img.empty());
        EXPECT_EQ(img.rgba.size(), static_cast<std::size_t>(img.width) * img.height * 4);
    }
}

TEST(MeshIo, VertexColorsAreConvertedToLinear) {
    // float-color.ply: three vertices, each with the float color (0, 0, 1, 1): pure blue stays
    // pure blue in linear.
    const core::Result<core::Mesh> mesh = core::loadMesh(corpus("PLY/float-color.ply"));
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    ASSERT_TRUE(mesh->hasColors());
    for (const glm::vec4& c : mesh->colors)
        EXPECT_EQ(c, glm::vec4(0, 0, 1, 1));

    // Byte colors: sRGB 128/255 becomes 0.2158 linear.
    TempDir dir;
    writeFile(dir.path() / "grey.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"
                                       "property float x\nproperty float y\nproperty float z\n"
                                       "property uchar red\nproperty uchar green\n"
                                       "property uchar blue\nelement face 1\n"
                                       "property list uchar int vertex_indices\nend_header\n"
                                       "0 0 0 128 128 128\n1 0 0 255 255 255\n0 1 0 0 0 0\n"
                                       "3 0 1 2\n");
    const core::Result<core::Mesh> grey = core::loadMesh((dir.path() / "grey.ply").string());
    ASSERT_TRUE(grey.ok()) << grey.error();
    ASSERT_EQ(grey->colors.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        const glm::vec3 p = grey->positions[i];
        const float expected = p == glm::vec3(0, 0, 0)   ? 0.2158f // sRGB 128/255 in linear
                               : p == glm::vec3(1, 0, 0) ? 1.0f
                                                         : 0.0f;
        EXPECT_NEAR(grey->colors[i].r, expected, 1e-3f);
        EXPECT_NEAR(grey->colors[i].b, expected, 1e-3f);
        EXPECT_EQ(grey->colors[i].a, 1.0f);
    }
}

TEST(MeshIo, ObjUvsUseTheGltfConvention) {
    // OBJ's v axis points up; Mesh::uvs (like glTF) has v pointing down from the top row.
    TempDir dir;
    writeFile(dir.path() / "uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                     "f 1/1 2/2 3/3\n");
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "uv.obj").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    ASSERT_EQ(mesh->uvs.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        if (mesh->positions[i] == glm::vec3(0, 0, 0)) {
            EXPECT_EQ(mesh->uvs[i], glm::vec2(0, 1));
        } else if (mesh->positions[i] == glm::vec3(0, 1, 0)) {
            EXPECT_EQ(mesh->uvs[i], glm::vec2(0, 0));
        }
    }
}

TEST(MeshIo, ObjReferencesOutsideTheFolderAreNotRead) {
    TempDir dir;
    writeFile(dir.path() / "secret.mtl", "newmtl leaked\nKd 1 0 0\nmap_Kd secret.png\n");
    writeFile(dir.path() / "secret.png",
              readFile(kModels / "glTF2/BoxTextured-glTF/CesiumLogoFlat.png"));
    writeFile(dir.path() / "model/local.mtl", "newmtl local\nKd 0 1 0\nmap_Kd ../secret.png\n");
    writeFile(dir.path() / "model/m.obj",
              "mtllib ../secret.mtl\nmtllib local.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n"
              "usemtl local\nf 1/1 2/1 3/1\n");
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "model/m.obj").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    for (const core::Material& m : mesh->materials)
        EXPECT_NE(m.name, "leaked");
    EXPECT_TRUE(mesh->textures.empty());
    std::string all;
    for (const std::string& w : mesh->warnings)
        all += w + "\n";
    EXPECT_NE(all.find("outside the model's folder"), std::string::npos) << all;
}

// ---------------------------------------------------------------------------------------------
// Flattening

TEST(MeshIo, NodeTransformsMovePositionsAndNormals) {
    TempDir dir;
    std::string bin = triangleBuffer();
    append<float>(bin, {0, 0, 1, 0, 0, 1, 0, 0, 1}); // normals at byte 44
    // Node 0 translates by (10,0,0); its child node 1 rotates 90 degrees about z and scales by 2.
    // Node 2 (a second root) places the same mesh with a matrix translating by (0,0,5).
    const std::string json = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0,2]}],
"nodes":[{"translation":[10,0,0],"children":[1]},
         {"rotation":[0,0,0.7071067811865476,0.7071067811865476],"scale":[2,2,2],"mesh":0},
         {"matrix":[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,5,1],"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":2},"indices":1}]}],
"buffers":[{"uri":")" + dataUri(bin) +
                             R"(","byteLength":80}],
"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6},
               {"buffer":0,"byteOffset":44,"byteLength":36}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},
             {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"},
             {"bufferView":2,"componentType":5126,"count":3,"type":"VEC3"}]})";
    writeFile(dir.path() / "nodes.gltf", json);
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "nodes.gltf").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    ASSERT_EQ(mesh->vertexCount(), 6u);
    ASSERT_EQ(mesh->triangleCount(), 2u);
    auto near = [](const glm::vec3& a, const glm::vec3& b) { return glm::length(a - b) < 1e-5f; };
    // Triangle 0 is node 1's instance (depth-first), triangle 1 node 2's.
    const glm::vec3 expected0[3] = {{10, 0, 0}, {10, 2, 0}, {8, 0, 0}};
    const glm::vec3 expected1[3] = {{0, 0, 5}, {1, 0, 5}, {0, 1, 5}};
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(near(mesh->positions[mesh->indices[k]], expected0[k]))
            << k << ": " << mesh->positions[mesh->indices[k]].x << " "
            << mesh->positions[mesh->indices[k]].y;
        EXPECT_TRUE(near(mesh->positions[mesh->indices[3 + k]], expected1[k])) << k;
    }
    for (const glm::vec3& n : mesh->normals)
        EXPECT_TRUE(near(n, glm::vec3(0, 0, 1)));
}

TEST(MeshIo, AssimpNodeTransformsApply) {
    // Collada: a parent node translating by (10,20,30) over a child scaling by 2.
    TempDir dir;
    writeFile(dir.path() / "nodes.dae", R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Y_UP</up_axis></asset>
  <library_geometries><geometry id="tri"><mesh>
    <source id="pos"><float_array id="pos-array" count="9">0 0 0 1 0 0 0 1 0</float_array>
      <technique_common><accessor source="#pos-array" count="3" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <vertices id="vtx"><input semantic="POSITION" source="#pos"/></vertices>
    <triangles count="1"><input semantic="VERTEX" source="#vtx" offset="0"/><p>0 1 2</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="scene">
    <node id="parent"><matrix>1 0 0 10  0 1 0 20  0 0 1 30  0 0 0 1</matrix>
      <node id="child"><matrix>2 0 0 0  0 2 0 0  0 0 2 0  0 0 0 1</matrix>
        <instance_geometry url="#tri"/></node></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)");
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "nodes.dae").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    ASSERT_EQ(mesh->triangleCount(), 1u);
    EXPECT_EQ(mesh->positions[mesh->indices[0]], glm::vec3(10, 20, 30));
    EXPECT_EQ(mesh->positions[mesh->indices[1]], glm::vec3(12, 20, 30));
    EXPECT_EQ(mesh->positions[mesh->indices[2]], glm::vec3(10, 22, 30));
    EXPECT_NEAR(mesh->normals[0].z, 1.0f, 1e-6f); // computed: the file has no normals
}

TEST(MeshIo, MirroringNodesKeepTrianglesFrontFacing) {
    TempDir dir;
    writeFile(dir.path() / "mirror.gltf",
              triangleGltf({{"@NODES@", R"([{"mesh":0,"scale":[-1,1,1]}])"}}));
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "mirror.gltf").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    ASSERT_EQ(mesh->triangleCount(), 1u);
    const glm::vec3 a = mesh->positions[mesh->indices[0]];
    const glm::vec3 b = mesh->positions[mesh->indices[1]];
    const glm::vec3 c = mesh->positions[mesh->indices[2]];
    // Unmirrored the triangle faces +z; mirrored in x its front must still face +z.
    EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f);
}

TEST(MeshIo, StripsFansMixedAttributesAndSkippedPoints) {
    TempDir dir;
    std::string bin;
    append<float>(bin, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}); // 4 positions, byte 0
    append<float>(bin, {0, 0, 1, 0, 0, 1, 1, 1});             // 4 uvs, byte 48
    append<std::uint8_t>(
        bin, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 51, 51, 51, 0}); // 4 colors, byte 80
    const std::string json = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0}],
"meshes":[{"primitives":[
  {"attributes":{"POSITION":0,"TEXCOORD_0":1},"mode":5},
  {"attributes":{"POSITION":0,"COLOR_0":2},"mode":6},
  {"attributes":{"POSITION":0},"mode":0}]}],
"buffers":[{"uri":")" + dataUri(bin) +
                             R"(","byteLength":96}],
"bufferViews":[{"buffer":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":32},
               {"buffer":0,"byteOffset":80,"byteLength":16}],
"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},
             {"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"},
             {"bufferView":2,"componentType":5121,"normalized":true,"count":4,"type":"VEC4"}]})";
    writeFile(dir.path() / "modes.gltf", json);
    const core::Result<core::Mesh> mesh = core::loadMesh((dir.path() / "modes.gltf").string());
    ASSERT_TRUE(mesh.ok()) << mesh.error();
    ASSERT_EQ(mesh->vertexCount(), 8u);
    ASSERT_EQ(mesh->triangleCount(), 4u);
    // Strip (glTF 2.0 §3.7.2.1): {v0 v1 v2}, {v1 v3 v2}. Fan: {v1 v2 v0}, {v2 v3 v0}.
    const std::vector<std::uint32_t> expected = {0, 1, 2, 1, 3, 2, 5, 6, 4, 6, 7, 4};
    EXPECT_EQ(mesh->indices, expected);
    ASSERT_TRUE(mesh->hasUvs());
    EXPECT_EQ(mesh->uvs[3], glm::vec2(1, 1));
    EXPECT_EQ(mesh->uvs[5], glm::vec2(0, 0)); // the fan has no UVs: filled with 0
    ASSERT_TRUE(mesh->hasColors());
    EXPECT_EQ(mesh->colors[0], glm::vec4(1)); // the strip has no colors: filled with 1
    EXPECT_EQ(mesh->colors[4], glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(mesh->colors[7].r, 0.2f, 1e-6f); // normalized unsigned byte 51
    EXPECT_EQ(mesh->colors[7].a, 0.0f);
    bool warned = false;
    for (const std::string& w : mesh->warnings)
        warned = warned || w.find("points or lines") != std::string::npos;
    EXPECT_TRUE(warned);
    for (std::size_t v = 0; v < 4; ++v) // computed from the strip, which faces +z
        EXPECT_NEAR(mesh->normals[v].z, 1.0f, 1e-5f);
}

TEST(MeshIo, SparseAccessorsQuantizationAndNoScene) {
    TempDir dir;
    // Sparse: position 1 replaced by (3,0,0). The values live in an extra 12 bytes.
    std::string bin = triangleBuffer();
    append<std::uint16_t>(bin, {1, 0});
    append<float>(bin, {3, 0, 0});
    const std::string sparse =
        R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],
"buffers":[{"uri":")" +
        dataUri(bin) + R"(","byteLength":60}],
"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6},
               {"buffer":0,"byteOffset":44,"byteLength":2},
               {"buffer":0,"byteOffset":48,"byteLength":12}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",
              "sparse":{"count":1,"indices":{"bufferView":2,"componentType":5123},
                        "values":{"bufferView":3}}},
             {"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]})";
    writeFile(dir.path() / "sparse.gltf", sparse);
    const core::Result<core::Mesh> s = core::loadMesh((dir.path() / "sparse.gltf").string());
    ASSERT_TRUE(s.ok()) << s.error();
    EXPECT_EQ(s->positions[1], glm::vec3(3, 0, 0));

    // KHR_mesh_quantization: unsigned short positions (not normalized) are plain numbers.
    std::string qbin;
    append<std::uint16_t>(qbin, {0, 0, 0, 0, 0, 7, 0, 0, 0, 0, 7, 0}); // stride 8
    const std::string quantized = R"({"asset":{"version":"2.0"},
"extensionsUsed":["KHR_mesh_quantization"],"extensionsRequired":["KHR_mesh_quantization"],
"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
"buffers":[{"uri":")" + dataUri(qbin) +
                                  R"(","byteLength":24}],
"bufferViews":[{"buffer":0,"byteLength":24,"byteStride":8}],
"accessors":[{"bufferView":0,"componentType":5123,"count":3,"type":"VEC3"}]})";
    writeFile(dir.path() / "quantized.gltf", quantized);
    const core::Result<core::Mesh> q = core::loadMesh((dir.path() / "quantized.gltf").string());
    ASSERT_TRUE(q.ok()) << q.error();
    EXPECT_EQ(q->positions[1], glm::vec3(0, 7, 0));
    EXPECT_EQ(q->positions[2], glm::vec3(0, 0, 7));
    // No scene at all: the root nodes are shown, with a warning.
    EXPECT_FALSE(q->warnings.empty());
}

TEST(MeshIo, RecursiveNodesFailsCleanly) {
    const std::string path = corpus("glTF2/RecursiveNodes/RecursiveNodes.gltf");
    const core::Result<core::Mesh> mesh = core::loadMesh(path);
    ASSERT_FALSE(mesh.ok());
    EXPECT_NE(mesh.error().find("RecursiveNodes.gltf"), std::string::npos);
    EXPECT_NE(mesh.error().find("node 0"), std::string::npos) << mesh.error();
}

// ---------------------------------------------------------------------------------------------
// The file checks, limits and progress

TEST(MeshIo, FileProblemsAreNamed) {
    TempDir dir;
    const std::string missing = (dir.path() / "missing.glb").string();
    core::Result<core::Mesh> r = core::loadMesh(missing);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error(), missing + ": does not exist");

    r = core::loadMesh(dir.path().string());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error(), dir.path().string() + ": is a directory, not a file");

    writeFile(dir.path() / "empty.ply", "");
    r = core::loadMesh((dir.path() / "empty.ply").string());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error(), (dir.path() / "empty.ply").string() + ": is empty");

    r = core::loadMesh("");
    EXPECT_FALSE(r.ok());
}

TEST(MeshIo, LimitsAreEnforced) {
    const std::string box = corpus("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb");
    core::LoadLimits small;
    small.maxFileBytes = 100;
    core::Result<core::Mesh> r = core::loadMesh(box, {}, small);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find("too large"), std::string::npos) << r.error();

    core::LoadLimits fewVertices;
    fewVertices.maxVertices = 10;
    r = core::loadMesh(box, {}, fewVertices);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find("too many"), std::string::npos) << r.error();
    r = core::loadMesh(corpus("OBJ/WusonOBJ.obj"), {}, fewVertices);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().find("too many"), std::string::npos) << r.error();

    core::LoadLimits fewTriangles;
    fewTriangles.maxTriangles = 11;
    r = core::loadMesh(box, {}, fewTriangles);
    EXPECT_FALSE(r.ok());

    // An image over the pixel cap is dropped with a warning; the geometry still loads.
    core::LoadLimits tinyImages;
    tinyImages.maxImagePixels = 100;
    r = core::loadMesh(box, {}, tinyImages);
    ASSERT_TRUE(r.ok()) << r.error();
    EXPECT_TRUE(r->textures.empty());
    EXPECT_EQ(r->materials[0].baseColorTexture, -1);
    EXPECT_TRUE(std::any_of(r->warnings.begin(), r->warnings.end(), [](const std::string& w) {
        return w.find("too large") != std::string::npos;
    })) << r->warnings.size();
}

TEST(MeshIo, ProgressIsReportedAndCancels) {
    for (const char* rel :
         {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "OBJ/WusonOBJ.obj"}) {
        std::vector<double> seen;
        const core::Result<core::Mesh> ok = core::loadMesh(corpus(rel), [&](double f) {
            seen.push_back(f);
            return true;
        });
        ASSERT_TRUE(ok.ok()) << ok.error();
        ASSERT_FALSE(seen.empty());
        EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end())) << rel;
        EXPECT_EQ(seen.back(), 1.0);

        int calls = 0;
        const core::Result<core::Mesh> cancelled =
            core::loadMesh(corpus(rel), [&](double) { return ++calls < 3; });
        ASSERT_FALSE(cancelled.ok());
        EXPECT_EQ(cancelled.error(), corpus(rel) + ": cancelled");
        EXPECT_TRUE(cancelled.cancelled()) << rel;

        // The loaders themselves (in the importer process) stop with the same kind of error.
        int inProcessCalls = 0;
        const core::Result<core::Mesh> stopped =
            core::loadMeshInProcess(corpus(rel), [&](double) { return ++inProcessCalls < 3; });
        ASSERT_FALSE(stopped.ok());
        EXPECT_EQ(stopped.error(), corpus(rel) + ": cancelled");
        EXPECT_EQ(stopped.errorKind(), core::ErrorKind::Cancelled) << rel;
    }
}

/** Whether two loads gave the same mesh: every array, material and texture byte. */
::testing::AssertionResult sameMesh(const core::Mesh& a, const core::Mesh& b) {
    if (a.positions != b.positions || a.normals != b.normals || a.uvs != b.uvs ||
        a.colors != b.colors)
        return ::testing::AssertionFailure() << "vertex arrays differ";
    if (a.indices != b.indices || a.triangleMaterial != b.triangleMaterial)
        return ::testing::AssertionFailure() << "indices or triangle materials differ";
    if (a.materials.size() != b.materials.size())
        return ::testing::AssertionFailure() << "material counts differ";
    for (std::size_t m = 0; m < a.materials.size(); ++m)
        if (a.materials[m].name != b.materials[m].name ||
            a.materials[m].baseColorFactor != b.materials[m].baseColorFactor ||
            a.materials[m].baseColorTexture != b.materials[m].baseColorTexture)
            return ::testing::AssertionFailure() << "material " << m << " differs";
    if (a.textures.size() != b.textures.size())
        return ::testing::AssertionFailure() << "texture counts differ";
    for (std::size_t t = 0; t < a.textures.size(); ++t)
        if (a.textures[t].width != b.textures[t].width ||
            a.textures[t].height != b.textures[t].height ||
            a.textures[t].rgba != b.textures[t].rgba)
            return ::testing::AssertionFailure() << "texture " << t << " differs";
    if (a.warnings != b.warnings)
        return ::testing::AssertionFailure() << "warnings differ";
    return ::testing::AssertionSuccess();
}

TEST(MeshIo, ConcurrentLoadsAgree) {
    // Each file loaded alone is the reference; four threads then load both files three times
    // each at once, and every load must give the reference mesh byte for byte.
    const std::string files[2] = {corpus("OBJ/spider.obj"),
                                  corpus("glTF2/BoxTextured-glTF-Binary/BoxTextured.glb")};
    std::vector<core::Mesh> reference;
    for (const std::string& file : files) {
        core::Result<core::Mesh> m = core::loadMesh(file);
        ASSERT_TRUE(m.ok()) << m.error();
        ASSERT_FALSE(m->textures.empty()) << file; // so that texture bytes are compared too
        reference.push_back(std::move(m).value());
    }
    constexpr int kThreads = 4, kLoads = 3;
    std::vector<core::Mesh> meshes(kThreads * kLoads);
    std::vector<std::string> errors(kThreads * kLoads);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            for (int i = 0; i < kLoads; ++i) {
                core::Result<core::Mesh> m = core::loadMesh(files[t % 2]);
                const std::size_t slot = std::size_t(t * kLoads + i);
                if (m.ok())
                    meshes[slot] = std::move(m).value();
                else
                    errors[slot] = m.error();
            }
        });
    for (std::thread& t : threads)
        t.join();
    for (int t = 0; t < kThreads; ++t)
        for (int i = 0; i < kLoads; ++i) {
            const std::size_t slot = std::size_t(t * kLoads + i);
            SCOPED_TRACE(files[t % 2] + ", thread " + std::to_string(t));
            ASSERT_EQ(errors[slot], "");
            EXPECT_TRUE(sameMesh(meshes[slot], reference[std::size_t(t % 2)]));
        }
}

TEST(MeshIo, ExtensionsAreReadInAnyCase) {
    // The loader is chosen by the extension, whatever its case: BOX.GLB through the glTF reader
    // (a GLB read as anything else fails), BOX.OBJ through Assimp.
    const TempDir dir;
    ASSERT_FALSE(dir.path().empty());
    const std::pair<const char*, const char*> files[] = {
        {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", "BOX.GLB"},
        {"OBJ/box.obj", "Box.Obj"},
    };
    for (const auto& [from, to] : files) {
        const fs::path copy = dir.path() / to;
        fs::copy_file(corpus(from), copy);
        const core::Result<core::Mesh> upper = core::loadMesh(copy.string());
        const core::Result<core::Mesh> lower = core::loadMesh(corpus(from));
        ASSERT_TRUE(upper.ok()) << upper.error();
        ASSERT_TRUE(lower.ok()) << lower.error();
        EXPECT_EQ(upper->positions, lower->positions) << to;
        EXPECT_EQ(upper->triangleCount(), lower->triangleCount()) << to;
    }
}

TEST(MeshIo, BuiltinModelsAreDispatched) {
    const core::Result<core::Mesh> unknown = core::loadMesh("builtin:no-such-model");
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().rfind("builtin:no-such-model: ", 0), 0u) << unknown.error();
    const core::Result<core::Mesh> ring = core::loadMesh("builtin:hexring");
    ASSERT_TRUE(ring.ok()) << ring.error();
    EXPECT_GT(ring->triangleCount(), 0u);
}

// ---------------------------------------------------------------------------------------------
// decodeImage

TEST(DecodeImage, ConvertsToRgba8) {
    // A palette PNG and a grey PNG (colour types 3 and 0, read from their IHDR chunks).
    const std::string palette = readFile(kModels / "glTF2/BoxTextured-glTF/CesiumLogoFlat.png");
    core::Result<core::Image> img = core::decodeImage(
        reinterpret_cast<const std::uint8_t*>(palette.data()), palette.size(), "logo.png");
    ASSERT_TRUE(img.ok()) << img.error();
    EXPECT_EQ(img->width, 211);
    EXPECT_EQ(img->rgba.size(), 211u * 211u * 4u);

    const std::string grey = readFile(kModels / "SIB/UV Mapping.png");
    img = core::decodeImage(reinterpret_cast<const std::uint8_t*>(grey.data()), grey.size(),
                            "grey.png");
    ASSERT_TRUE(img.ok()) << img.error();
    for (std::size_t i = 0; i < img->rgba.size(); i += 4) {
        ASSERT_EQ(img->rgba[i], img->rgba[i + 1]);
        ASSERT_EQ(img->rgba[i], img->rgba[i + 2]);
        ASSERT_EQ(img->rgba[i + 3], 255);
    }

    core::LoadLimits limits;
    limits.maxImagePixels = 1000;
    img = core::decodeImage(reinterpret_cast<const std::uint8_t*>(palette.data()), palette.size(),
                            "logo.png", limits);
    ASSERT_FALSE(img.ok());
    EXPECT_NE(img.error().find("too large"), std::string::npos) << img.error();
}

TEST(DecodeImage, RefusesGarbage) {
    const std::string junk = "\x89PNG\r\n\x1a\nthis is not really a PNG";
    core::Result<core::Image> img = core::decodeImage(
        reinterpret_cast<const std::uint8_t*>(junk.data()), junk.size(), "junk.png");
    ASSERT_FALSE(img.ok());
    EXPECT_EQ(img.error().rfind("junk.png: ", 0), 0u) << img.error();
    EXPECT_EQ(img.error().find('\n'), std::string::npos) << img.error();

    const std::string text = "plain text";
    img = core::decodeImage(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(),
                            "notes.txt");
    EXPECT_FALSE(img.ok());
    img = core::decodeImage(nullptr, 0, "nothing.png");
    EXPECT_FALSE(img.ok());

    // Truncated halfway: an error, never a crash.
    const std::string logo = readFile(kModels / "glTF2/BoxTextured-glTF/CesiumLogoFlat.png");
    img = core::decodeImage(reinterpret_cast<const std::uint8_t*>(logo.data()), logo.size() / 2,
                            "half.png");
    EXPECT_FALSE(img.ok());
}

} // namespace mesh_io_test
