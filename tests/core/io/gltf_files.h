// SPDX-License-Identifier: GPL-3.0-or-later
// Binary glTF files of a small curved grid, written with the libraries' own encoders:
// uncompressed, with Draco (KHR_draco_mesh_compression) and with meshoptimizer
// (EXT_meshopt_compression over KHR_mesh_quantization data), whole or damaged on purpose. Used by
// io/gltf_compression_test.cpp and by tests/tools/make_gltf_compression_data.cpp, which writes
// the committed copies under tests/data.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

namespace core_test::gltf_files {

namespace fs = std::filesystem;
using Json = nlohmann::json;

/** The reference mesh: an n × n grid bent into a wave, with normals and UVs. */
struct Grid {
    std::vector<float> pos, nrm, uv; // 3, 3, 2 per vertex
    std::vector<std::uint32_t> idx;
    std::size_t vertices() const { return pos.size() / 3; }
    std::size_t triangles() const { return idx.size() / 3; }
};

inline Grid makeGrid(int n = 9) {
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
    /** Writes the file; false if it could not be written. */
    bool write(const fs::path& file) {
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
        std::ofstream stream(file, std::ios::binary | std::ios::trunc);
        stream.write(reinterpret_cast<const char*>(out.data()), std::streamsize(out.size()));
        return bool(stream);
    }
};

inline constexpr int kByte = 5120, kUShort = 5123, kUInt = 5125, kFloat = 5126;

/** One mesh with one primitive of attrs (and indices), one node (with extra node JSON). */
inline void addScene(Glb& glb, Json prim, const Json& node = Json::object()) {
    prim["mode"] = 4;
    glb.json["meshes"] = Json::array({Json{{"primitives", Json::array({prim})}}});
    Json n = node;
    n["mesh"] = 0;
    glb.json["nodes"] = Json::array({n});
    glb.json["scenes"] = Json::array({Json{{"nodes", {0}}}});
    glb.json["scene"] = 0;
}

inline bool writePlain(const Grid& g, const fs::path& file, const Json& material = Json()) {
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
    return glb.write(file);
}

/**
 * The Draco bytes of g (12-bit positions and UVs, 10-bit normals); ids gets the attributes'
 * ids. Empty if the encoder fails.
 */
inline std::vector<std::uint8_t> dracoBytes(const Grid& g, std::map<std::string, int>& ids) {
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
    if (!encoder.EncodeMeshToBuffer(mesh, &out).ok())
        return {};
    return {out.data(), out.data() + out.size()};
}

inline bool writeDraco(const Grid& g, const fs::path& file, std::size_t keepBytes = 0,
                       std::size_t claimedVertices = 0) {
    std::map<std::string, int> ids;
    std::vector<std::uint8_t> bytes = dracoBytes(g, ids);
    if (bytes.empty())
        return false;
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
    return glb.write(file);
}

/**
 * g with KHR_mesh_quantization (unsigned short positions dequantized by the node's scale and
 * translation, octahedral byte normals, normalized unsigned short UVs) and every view compressed
 * with EXT_meshopt_compression into the BIN chunk; the views themselves point into a fallback
 * buffer without data. countDelta damages the index view's count, keepIndexBytes cuts its data.
 */
inline bool writeMeshopt(const Grid& g, const fs::path& file, long countDelta = 0,
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
    return glb.write(file);
}

} // namespace core_test::gltf_files
