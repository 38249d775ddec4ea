// SPDX-License-Identifier: GPL-3.0-or-later
// Binary glTF 2.0 writer. The GLB container is written here with nlohmann::json rather than
// through tinygltf's writer: the layout (one buffer, 4-byte aligned views, strides, PNG images in
// views) is then exactly what mesh_io_gltf.cpp reads back, and no image is re-encoded behind our
// back. Images are encoded to PNG in memory by encodeImage() (image_encode.h).
#include "core/io/gltf/gltf_export.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <glm/common.hpp>

#include "core/io/atomic_write.h"
#include "core/io/gltf/glb_container.h"
#include "core/io/gltf/gltf_write_back.h"
#include "core/io/image/image_encode.h"
#include "core/io/json_nesting.h"

static_assert(std::endian::native == std::endian::little,
              "glTF buffers are little-endian and are written with memcpy");

namespace core {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using Bytes = std::vector<std::uint8_t>;

constexpr std::uint64_t kMaxGlbBytes = 0xFFFFFFFFu; // the header's length is 32 bits
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

std::size_t padded4(std::size_t n) {
    return (n + 3) & ~std::size_t{3};
}

void putU32(Bytes& out, std::uint32_t v) {
    const auto at = out.size();
    out.resize(at + 4);
    std::memcpy(out.data() + at, &v, 4);
}

// ---------------------------------------------------------------------------------------------
// Geometry

/** Consecutive triangles [first, first + count) with one material, of one named object. */
struct Run {
    std::size_t firstTriangle = 0;
    std::size_t triangleCount = 0;
    std::uint32_t material = 0;
    std::size_t object = 0; // index into Mesh::objects (0 without)
};

std::vector<Run> materialRuns(const Mesh& mesh) {
    std::vector<Run> runs;
    std::size_t object = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const bool objectBegins =
            object + 1 < mesh.objects.size() && mesh.objects[object + 1].firstTriangle == t;
        object += objectBegins ? 1 : 0;
        if (runs.empty() || runs.back().material != mesh.triangleMaterial[t] || objectBegins)
            runs.push_back(Run{t, 0, mesh.triangleMaterial[t], object});
        ++runs.back().triangleCount;
    }
    return runs;
}

/** The binary chunk under construction and the buffer views into it. */
class BinBuilder {
public:
    /** Appends size bytes as a new buffer view (4-byte aligned); returns its index. */
    int addView(const void* data, std::size_t size, int target, int stride) {
        const std::size_t offset = m_bytes.size();
        m_bytes.resize(offset + padded4(size), 0);
        std::memcpy(m_bytes.data() + offset, data, size);
        Json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}};
        if (stride > 0)
            view["byteStride"] = stride;
        if (target > 0)
            view["target"] = target;
        m_views.push_back(std::move(view));
        return static_cast<int>(m_views.size() - 1);
    }
    Bytes& bytes() { return m_bytes; }
    Json& views() { return m_views; }

private:
    Bytes m_bytes;
    Json m_views = Json::array();
};

/** Vertex data of all runs, one run after the other; each run's vertices in original order. */
struct RunGeometry {
    std::vector<float> positions, normals, uvs, colors;
    std::vector<std::uint32_t> indices; // local to each run
    struct Range {
        std::size_t firstVertex = 0, vertexCount = 0, firstIndex = 0, indexCount = 0;
        glm::vec3 min{0.0f}, max{0.0f};
    };
    std::vector<Range> ranges; // per run
};

RunGeometry gatherRuns(const Mesh& mesh, const std::vector<Run>& runs) {
    RunGeometry g;
    const std::size_t n = mesh.vertexCount();
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> local(n, kNone);
    std::vector<std::uint32_t> used;
    g.positions.reserve(n * 3);
    g.normals.reserve(n * 3);
    g.uvs.reserve(mesh.hasUvs() ? n * 2 : 0);
    g.colors.reserve(mesh.hasColors() ? n * 4 : 0);
    g.indices.reserve(mesh.indices.size());
    for (const Run& run : runs) {
        const std::size_t begin = run.firstTriangle * 3, end = begin + run.triangleCount * 3;
        used.clear();
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t v = mesh.indices[i];
            if (local[v] == kNone) {
                local[v] = 0;
                used.push_back(v);
            }
        }
        // Original order: the loader keeps a primitive's vertices in accessor order.
        std::sort(used.begin(), used.end());
        for (std::size_t k = 0; k < used.size(); ++k)
            local[used[k]] = static_cast<std::uint32_t>(k);

        RunGeometry::Range r;
        r.firstVertex = g.positions.size() / 3;
        r.vertexCount = used.size();
        r.firstIndex = g.indices.size();
        r.indexCount = end - begin;
        r.min = r.max = mesh.positions[used.front()];
        for (std::uint32_t v : used) {
            const glm::vec3& p = mesh.positions[v];
            r.min = glm::min(r.min, p);
            r.max = glm::max(r.max, p);
            g.positions.insert(g.positions.end(), {p.x, p.y, p.z});
            const glm::vec3& nv = mesh.normals[v];
            g.normals.insert(g.normals.end(), {nv.x, nv.y, nv.z});
            if (mesh.hasUvs())
                g.uvs.insert(g.uvs.end(), {mesh.uvs[v].x, mesh.uvs[v].y});
            if (mesh.hasColors()) {
                const glm::vec4& c = mesh.colors[v];
                g.colors.insert(g.colors.end(), {c.r, c.g, c.b, c.a});
            }
        }
        for (std::size_t i = begin; i < end; ++i)
            g.indices.push_back(local[mesh.indices[i]]);
        for (std::uint32_t v : used)
            local[v] = kNone;
        g.ranges.push_back(r);
    }
    return g;
}

Json vec(const glm::vec3& v) {
    return Json::array({v.x, v.y, v.z});
}

/** A finite factor component, as the loader would read it (non-finite ones become 1). */
double factor(float v) {
    return std::isfinite(v) ? static_cast<double>(v) : 1.0;
}

struct GlbParts {
    Bytes head; // GLB header, JSON chunk, BIN chunk header
    Bytes bin;  // BIN chunk data, 4-byte aligned
};

/** A GLB under construction: the BIN chunk and the JSON arrays that index into it. */
struct GlbDraft {
    const Mesh& mesh;
    const GlbAdditions& additions;
    const ProgressFn& progress;
    Json extras;
    BinBuilder bin;
    Json accessors = Json::array(), primitives = Json::array();
    std::vector<std::size_t> primitiveObject; // per primitive, its run's object
    Json images = Json::array(), textures = Json::array(), materials = Json::array();
    std::vector<int> textureIndex; // glTF texture per mesh texture (-1: not written)
    std::vector<int> mrTexture;    // glTF texture per metallic-roughness image (-1: not written)
    std::set<std::string> extensionsUsed;
};

/** The buffer views of the vertex attributes and indices (-1: the mesh has none). */
struct GeometryViews {
    int pos = -1, nrm = -1, uv = -1, col = -1, idx = -1;
};

int addAccessor(Json& accessors, int view, std::size_t element, std::size_t first,
                std::size_t count, int componentType, const char* type) {
    accessors.push_back({{"bufferView", view},
                         {"byteOffset", first * element},
                         {"componentType", componentType},
                         {"count", count},
                         {"type", type}});
    return static_cast<int>(accessors.size() - 1);
}

/** One primitive per material run, its accessors into the views. */
void addPrimitives(GlbDraft& d, const std::vector<Run>& runs, const RunGeometry& g,
                   const GeometryViews& views) {
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const RunGeometry::Range& range = g.ranges[r];
        const std::size_t first = range.firstVertex, count = range.vertexCount;
        Json attributes;
        const int pos = addAccessor(d.accessors, views.pos, 12, first, count, kFloat, "VEC3");
        d.accessors[static_cast<std::size_t>(pos)]["min"] = vec(range.min);
        d.accessors[static_cast<std::size_t>(pos)]["max"] = vec(range.max);
        attributes["POSITION"] = pos;
        attributes["NORMAL"] =
            addAccessor(d.accessors, views.nrm, 12, first, count, kFloat, "VEC3");
        if (views.uv >= 0)
            attributes["TEXCOORD_0"] =
                addAccessor(d.accessors, views.uv, 8, first, count, kFloat, "VEC2");
        if (views.col >= 0)
            attributes["COLOR_0"] =
                addAccessor(d.accessors, views.col, 16, first, count, kFloat, "VEC4");
        const int idx = addAccessor(d.accessors, views.idx, 4, range.firstIndex, range.indexCount,
                                    kUnsignedInt, "SCALAR");
        d.primitives.push_back({{"attributes", std::move(attributes)},
                                {"indices", idx},
                                {"material", runs[r].material},
                                {"mode", 4}});
        d.primitiveObject.push_back(runs[r].object);
    }
}

/** The vertices and indices, per material run, as the first views and the primitives. */
Status writeGeometry(GlbDraft& d) {
    const Mesh& mesh = d.mesh;
    const std::vector<Run> runs = materialRuns(mesh);
    const RunGeometry g = gatherRuns(mesh, runs);
    BinBuilder& bin = d.bin;
    GeometryViews views;
    views.pos = bin.addView(g.positions.data(), g.positions.size() * 4, kArrayBuffer, 12);
    views.nrm = bin.addView(g.normals.data(), g.normals.size() * 4, kArrayBuffer, 12);
    views.uv = mesh.hasUvs() ? bin.addView(g.uvs.data(), g.uvs.size() * 4, kArrayBuffer, 8) : -1;
    views.col =
        mesh.hasColors() ? bin.addView(g.colors.data(), g.colors.size() * 4, kArrayBuffer, 16) : -1;
    views.idx = bin.addView(g.indices.data(), g.indices.size() * 4, kElementArrayBuffer, 0);
    if (!reportProgress(d.progress, 0.2))
        return cancelledError();
    addPrimitives(d, runs, g, views);
    return {};
}

/** A material's textures: the base colour, then its other maps in Material's order. */
std::array<int, 5> texturesOf(const Material& m) {
    return {m.baseColorTexture, m.metallicRoughness.texture, m.normal.texture, m.occlusion.texture,
            m.emissive.texture};
}

/** Texture t as a glTF image: its kept file as it was, else encoded as PNG. */
Status writeImage(GlbDraft& d, std::size_t t) {
    const Mesh& mesh = d.mesh;
    std::string mimeType = "image/png";
    Bytes encoded;
    const Bytes* bytes = &encoded;
    if (const EncodedImage* kept = mesh.textureSource(int(t))) {
        bytes = &kept->bytes;
        mimeType = kept->mimeType;
    } else {
        Result<Bytes> png = encodeImage(mesh.textures[t], ExportFormat::Png8);
        if (!png)
            return Error{"texture " + std::to_string(t) + " cannot be encoded as PNG (" +
                             png.error() + ")",
                         png.errorKind()};
        encoded = std::move(png).value();
    }
    const int view = d.bin.addView(bytes->data(), bytes->size(), 0, 0);
    d.images.push_back(
        {{"bufferView", view}, {"mimeType", mimeType}, {"name", "texture " + std::to_string(t)}});
    d.textures.push_back({{"source", d.images.size() - 1}, {"sampler", 0}});
    return {};
}

/**
 * The textures the materials use: the base colour textures first, in order of first use (the
 * order the loader gives them back, so a project's pages stay first), then the other maps'.
 */
Status writeTextures(GlbDraft& d) {
    const Mesh& mesh = d.mesh;
    d.textureIndex.assign(mesh.textures.size(), -1);
    std::vector<std::size_t> written; // mesh texture per glTF texture
    const auto use = [&](int t) {
        if (t >= 0 && d.textureIndex[std::size_t(t)] < 0 &&
            !mesh.textures[std::size_t(t)].empty()) {
            d.textureIndex[std::size_t(t)] = static_cast<int>(written.size());
            written.push_back(std::size_t(t));
        }
    };
    for (const Material& m : mesh.materials)
        use(m.baseColorTexture);
    for (const Material& m : mesh.materials)
        for (std::size_t k = 1; k < 5; ++k)
            use(texturesOf(m)[k]);
    for (std::size_t k = 0; k < written.size(); ++k) {
        if (Status s = writeImage(d, written[k]); !s)
            return s;
        if (!reportProgress(d.progress, 0.2 + 0.7 * static_cast<double>(k + 1) /
                                                  static_cast<double>(written.size())))
            return cancelledError();
    }
    return {};
}

/** Metallic-roughness images the materials without a map of their own take from additions. */
Status writeMetallicRoughness(GlbDraft& d) {
    const GlbAdditions& additions = d.additions;
    d.mrTexture.assign(additions.metallicRoughness.size(), -1);
    for (std::size_t mi = 0; mi < d.mesh.materials.size(); ++mi) {
        const int source = mi < additions.materialMetallicRoughness.size()
                               ? additions.materialMetallicRoughness[mi]
                               : -1;
        if (source < 0 || std::size_t(source) >= d.mrTexture.size() ||
            d.mrTexture[std::size_t(source)] >= 0 ||
            additions.metallicRoughness[std::size_t(source)].empty() ||
            d.mesh.materials[mi].metallicRoughness.texture >= 0)
            continue;
        const Result<Bytes> png =
            encodeImage(additions.metallicRoughness[std::size_t(source)], ExportFormat::Png8);
        if (!png)
            return Error{"metallic-roughness texture " + std::to_string(source) +
                             " cannot be encoded as PNG (" + png.error() + ")",
                         png.errorKind()};
        const int view = d.bin.addView(png->data(), png->size(), 0, 0);
        d.images.push_back({{"bufferView", view},
                            {"mimeType", "image/png"},
                            {"name", "metallic-roughness " + std::to_string(source)}});
        d.mrTexture[std::size_t(source)] = static_cast<int>(d.textures.size());
        d.textures.push_back({{"source", d.images.size() - 1}, {"sampler", 0}});
    }
    return {};
}

/** The attachments as views, listed in the extras under additions.attachmentsAt. */
void writeAttachments(GlbDraft& d) {
    if (d.additions.attachments.empty() || !d.extras.is_object())
        return;
    Json views = Json::array();
    for (const Bytes& blob : d.additions.attachments)
        views.push_back(d.bin.addView(blob.data(), blob.size(), 0, 0));
    d.extras[d.additions.attachmentsAt] = std::move(views);
}

/**
 * map's placement as KHR_texture_transform (offset, rotation, scale), or nothing for none. A
 * placement with shear has no such form: its nearest one is written.
 */
Json textureTransform(const glm::mat3& m) {
    if (m == glm::mat3(1.0f))
        return nullptr;
    // m = T · R · S with R's columns (c, −s), (s, c) (gltf_texture_transform.cpp).
    const double sx = std::hypot(double(m[0][0]), double(m[0][1]));
    const double rotation = std::atan2(-double(m[0][1]), double(m[0][0]));
    const double c = std::cos(rotation), s = std::sin(rotation);
    const double sy = s * double(m[1][0]) + c * double(m[1][1]);
    return {{"offset", Json::array({factor(m[2][0]), factor(m[2][1])})},
            {"rotation", std::isfinite(rotation) ? rotation + 0.0 : 0.0}, // no -0
            {"scale", Json::array({std::isfinite(sx) ? sx : 1.0, std::isfinite(sy) ? sy : 1.0})}};
}

/** The textureInfo of map (its glTF texture and placement), or null when it was not written. */
Json textureInfo(GlbDraft& d, const MaterialMap& map) {
    if (map.texture < 0 || d.textureIndex[std::size_t(map.texture)] < 0)
        return nullptr;
    Json info = {{"index", d.textureIndex[std::size_t(map.texture)]}};
    if (Json transform = textureTransform(map.uvTransform); !transform.is_null()) {
        info["extensions"] = {{"KHR_texture_transform", std::move(transform)}};
        d.extensionsUsed.insert("KHR_texture_transform");
    }
    return info;
}

const char* alphaModeName(AlphaMode mode) {
    switch (mode) {
    case AlphaMode::Mask:
        return "MASK";
    case AlphaMode::Blend:
        return "BLEND";
    case AlphaMode::Opaque:
        break;
    }
    return "OPAQUE";
}

/** The maps besides the base colour and metallic-roughness, the alpha and the sides. */
void writeSurface(GlbDraft& d, const Material& m, Json& material) {
    if (Json info = textureInfo(d, m.normal); !info.is_null()) {
        if (m.normalScale != 1.0f)
            info["scale"] = factor(m.normalScale);
        material["normalTexture"] = std::move(info);
    }
    if (Json info = textureInfo(d, m.occlusion); !info.is_null()) {
        if (m.occlusionStrength != 1.0f)
            info["strength"] = std::clamp(factor(m.occlusionStrength), 0.0, 1.0);
        material["occlusionTexture"] = std::move(info);
    }
    if (Json info = textureInfo(d, m.emissive); !info.is_null())
        material["emissiveTexture"] = std::move(info);
    // glTF's emissive factor stops at 1: beyond, the strength carries the rest.
    glm::dvec3 emissive(std::max(0.0, factor(m.emissiveFactor.r)),
                        std::max(0.0, factor(m.emissiveFactor.g)),
                        std::max(0.0, factor(m.emissiveFactor.b)));
    double strength =
        std::isfinite(m.emissiveStrength) ? std::max(0.0, double(m.emissiveStrength)) : 1.0;
    if (const double top = std::max({emissive.r, emissive.g, emissive.b}); top > 1.0) {
        emissive /= top;
        strength *= top;
    }
    if (emissive != glm::dvec3(0.0))
        material["emissiveFactor"] = Json::array({emissive.r, emissive.g, emissive.b});
    if (strength != 1.0) {
        material["extensions"]["KHR_materials_emissive_strength"] = {
            {"emissiveStrength", strength}};
        d.extensionsUsed.insert("KHR_materials_emissive_strength");
    }
    if (m.alphaMode != AlphaMode::Opaque)
        material["alphaMode"] = alphaModeName(m.alphaMode);
    if (m.alphaMode == AlphaMode::Mask && m.alphaCutoff != 0.5f)
        material["alphaCutoff"] = std::max(0.0, factor(m.alphaCutoff));
    if (m.doubleSided)
        material["doubleSided"] = true;
}

void writeMaterials(GlbDraft& d) {
    const GlbAdditions& additions = d.additions;
    for (std::size_t mi = 0; mi < d.mesh.materials.size(); ++mi) {
        const Material& m = d.mesh.materials[mi];
        const int mrSource = mi < additions.materialMetallicRoughness.size()
                                 ? additions.materialMetallicRoughness[mi]
                                 : -1;
        const int mr = mrSource >= 0 && std::size_t(mrSource) < d.mrTexture.size()
                           ? d.mrTexture[std::size_t(mrSource)]
                           : -1;
        Json pbr = {
            {"baseColorFactor",
             Json::array({factor(m.baseColorFactor.r), factor(m.baseColorFactor.g),
                          factor(m.baseColorFactor.b), factor(m.baseColorFactor.a)})},
            {"metallicFactor", mr >= 0 ? 1.0 : std::clamp(factor(m.metallicFactor), 0.0, 1.0)},
            {"roughnessFactor", mr >= 0 ? 1.0 : std::clamp(factor(m.roughnessFactor), 0.0, 1.0)}};
        if (Json info = textureInfo(d, m.metallicRoughness); !info.is_null())
            pbr["metallicRoughnessTexture"] = std::move(info);
        else if (mr >= 0)
            pbr["metallicRoughnessTexture"] = {{"index", mr}};
        if (m.baseColorTexture >= 0 &&
            d.textureIndex[static_cast<std::size_t>(m.baseColorTexture)] >= 0)
            pbr["baseColorTexture"] = {
                {"index", d.textureIndex[static_cast<std::size_t>(m.baseColorTexture)]}};
        Json material = {{"pbrMetallicRoughness", std::move(pbr)}};
        writeSurface(d, m, material);
        if (!m.name.empty())
            material["name"] = m.name;
        d.materials.push_back(std::move(material));
    }
}

/**
 * The scene's nodes and meshes: one node and mesh (unnamed), or with named objects
 * (Mesh::objects) a node and mesh of each object's name; the draft's primitives moved in.
 */
std::pair<Json, Json> nodesAndMeshes(GlbDraft& d) {
    const std::vector<MeshObject>& objects = d.mesh.objects;
    if (objects.empty())
        return {Json::array({{{"mesh", 0}}}),
                Json::array({{{"primitives", std::move(d.primitives)}}})};
    Json nodes = Json::array(), meshes = Json::array();
    for (std::size_t p = 0; p < d.primitives.size(); ++p) {
        const std::size_t object = d.primitiveObject[p];
        if (p == 0 || object != d.primitiveObject[p - 1]) {
            Json mesh = {{"primitives", Json::array()}};
            Json node = {{"mesh", meshes.size()}};
            if (!objects[object].name.empty())
                mesh["name"] = node["name"] = objects[object].name;
            meshes.push_back(std::move(mesh));
            nodes.push_back(std::move(node));
        }
        meshes.back()["primitives"].push_back(std::move(d.primitives[p]));
    }
    return {std::move(nodes), std::move(meshes)};
}

/** The glTF JSON: one scene of the nodes; the draft's arrays moved in. */
Json assembleRoot(GlbDraft& d) {
    Json asset = {{"version", "2.0"}, {"generator", "LayerPaint"}};
    if (d.extras.is_object())
        asset["extras"] = d.extras;
    auto [nodes, meshes] = nodesAndMeshes(d);
    Json sceneNodes = Json::array();
    for (std::size_t n = 0; n < nodes.size(); ++n)
        sceneNodes.push_back(n);
    Json root = {{"asset", std::move(asset)},
                 {"scene", 0},
                 {"scenes", Json::array({{{"nodes", std::move(sceneNodes)}}})},
                 {"nodes", std::move(nodes)},
                 {"meshes", std::move(meshes)},
                 {"materials", std::move(d.materials)},
                 {"accessors", std::move(d.accessors)},
                 {"bufferViews", std::move(d.bin.views())},
                 {"buffers", Json::array({{{"byteLength", d.bin.bytes().size()}}})}};
    if (!d.extensionsUsed.empty())
        root["extensionsUsed"] = d.extensionsUsed;
    if (!d.textures.empty()) {
        // Painting wraps UVs outside 0..1 (paint_target.h), so do viewers.
        root["samplers"] = Json::array(
            {{{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}}});
        root["images"] = std::move(d.images);
        root["textures"] = std::move(d.textures);
    }
    return root;
}

/** The GLB header, the JSON chunk and the BIN chunk's header before bin. */
Result<GlbParts> packGlb(const Json& root, Bytes&& bin) {
    // Invalid UTF-8 (material names from other formats, extras) is replaced, not thrown on.
    std::string json = root.dump(-1, ' ', false, Json::error_handler_t::replace);
    json.resize(padded4(json.size()), ' ');
    const std::uint64_t total = 12 + 8 + json.size() + 8 + bin.size();
    if (total > kMaxGlbBytes)
        return Error{"the mesh and its textures are too large for a binary glTF file (" +
                     std::to_string(total) + " bytes, at most 4 GiB)"};

    GlbParts parts;
    parts.head.reserve(28 + json.size());
    putU32(parts.head, glb::kMagic);
    putU32(parts.head, 2);
    putU32(parts.head, static_cast<std::uint32_t>(total));
    putU32(parts.head, static_cast<std::uint32_t>(json.size()));
    putU32(parts.head, glb::kChunkJson);
    parts.head.insert(parts.head.end(), json.begin(), json.end());
    putU32(parts.head, static_cast<std::uint32_t>(bin.size()));
    putU32(parts.head, glb::kChunkBin);
    parts.bin = std::move(bin);
    return parts;
}

/**
 * mesh written back into its scene; nullopt (after a warning saying why) when the scene cannot
 * be kept and the mesh is to be written flattened.
 */
std::optional<Result<GlbParts>> encodeWrittenBack(const Mesh& mesh, const GlbAdditions& additions,
                                                  const ProgressFn& progress) {
    std::vector<std::string> warnings;
    std::string blocker = detail::gltf::writeBackBlocker(mesh);
    if (blocker.empty()) {
        Result<detail::gltf::GlbContent> content =
            detail::gltf::writeBack(mesh, additions, progress, warnings);
        if (content) {
            if (additions.warnings)
                additions.warnings->insert(additions.warnings->end(), warnings.begin(),
                                           warnings.end());
            return packGlb(content->root, std::move(content->bin));
        }
        if (content.cancelled())
            return Result<GlbParts>(content.takeError());
        blocker = content.error();
    }
    if (additions.warnings)
        additions.warnings->push_back("the file's scene is not kept (" + blocker +
                                      "): the model is written as one mesh");
    return std::nullopt;
}

Result<GlbParts> encodeParts(const Mesh& mesh, const GlbAdditions& additions,
                             const ProgressFn& progress) {
    GlbDraft d{.mesh = mesh, .additions = additions, .progress = progress};
    d.extras = additions.extras;
    if (const Status valid = mesh.validate(); !valid)
        return Error{"the mesh cannot be saved (" + valid.error() + ")", ErrorKind::BadInput};
    if (!d.extras.is_null() && !d.extras.is_object())
        return Error{"the extras to save are not a JSON object"};
    if (!reportProgress(progress, 0.0))
        return cancelledError();
    if (mesh.source)
        if (std::optional<Result<GlbParts>> parts = encodeWrittenBack(mesh, additions, progress))
            return std::move(*parts);

    if (Status s = writeGeometry(d); !s)
        return s.takeError();
    if (Status s = writeTextures(d); !s)
        return s.takeError();
    if (Status s = writeMetallicRoughness(d); !s)
        return s.takeError();
    writeAttachments(d);
    writeMaterials(d);
    Result<GlbParts> parts = packGlb(assembleRoot(d), std::move(d.bin.bytes()));
    if (parts && !reportProgress(progress, 0.95))
        return cancelledError();
    return parts;
}

} // namespace

Result<std::vector<std::uint8_t>> encodeGlb(const Mesh& mesh, const nlohmann::json& extras,
                                            const ProgressFn& progress) {
    GlbAdditions additions;
    additions.extras = extras;
    return encodeGlbWith(mesh, additions, progress);
}

Result<std::vector<std::uint8_t>> encodeGlbWith(const Mesh& mesh, const GlbAdditions& additions,
                                                const ProgressFn& progress) {
    try {
        Result<GlbParts> parts = encodeParts(mesh, additions, progress);
        if (!parts)
            return parts.takeError();
        Bytes out = std::move(parts->head);
        out.insert(out.end(), parts->bin.begin(), parts->bin.end());
        return out;
    } catch (const std::bad_alloc&) {
        return Error{"not enough memory to encode the file"};
    } catch (const std::exception& e) {
        return Error{std::string("cannot be encoded (") + e.what() + ")"};
    }
}

Status saveGlb(const std::string& path, const Mesh& mesh, const nlohmann::json& extras,
               const ProgressFn& progress, bool keepBackup) {
    GlbAdditions additions;
    additions.extras = extras;
    return saveGlbWith(path, mesh, additions, progress, keepBackup);
}

Status saveGlbWith(const std::string& path, const Mesh& mesh, const GlbAdditions& additions,
                   const ProgressFn& progress, bool keepBackup) {
    try {
        Result<GlbParts> parts = encodeParts(mesh, additions, progress);
        if (!parts)
            return Status(Error{path + ": " + parts.error(), parts.errorKind()});
        const std::span<const std::uint8_t> spans[] = {parts->head, parts->bin};
        Status status = writePartsAtomically(path, spans, keepBackup);
        if (status)
            reportProgress(progress, 1.0); // too late to cancel: the file is saved
        return status;
    } catch (const std::bad_alloc&) {
        return Status(Error{path + ": not enough memory to save the file"});
    } catch (const std::exception& e) {
        return Status(Error{path + ": cannot be saved (" + std::string(e.what()) + ")"});
    }
}

} // namespace core
