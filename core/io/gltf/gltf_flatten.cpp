// SPDX-License-Identifier: GPL-3.0-or-later
// The glTF scene flattener (see gltf_flatten.h).
#include "core/io/gltf/gltf_flatten.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "core/io/gltf/gltf_accessors.h"
#include "core/io/gltf/gltf_draco.h"
#include "core/io/gltf/gltf_texture_transform.h"
#include "core/io/importer/mesh_io_in_process.h"

static_assert(std::endian::native == std::endian::little,
              "glTF buffers are little-endian and are read with memcpy");

namespace core::detail::gltf {

namespace {

using Json = nlohmann::json;

struct Instance {
    int mesh = -1;
    int node = -1;
    glm::dmat4 transform{1.0};
};

class GltfFlattener : public Flattener {
public:
    GltfFlattener(const tinygltf::Model& model, const Json& json, const FileAccess& access,
                  bool quantized, const ProgressFn& progress, const LoadLimits& limits)
        : m_model(model), m_json(json), m_access(access), m_progress(progress), m_limits(limits),
          m_quantized(quantized) {}

    /** Flattens into out; false with error() on failure. */
    bool run(Mesh& out);

private:
    const tinygltf::Model& m_model;
    const Json& m_json;
    const FileAccess& m_access;
    const ProgressFn& m_progress;
    const LoadLimits& m_limits;
    bool m_quantized;
    std::size_t m_skippedPrimitives = 0;
    std::map<int, int> m_imageToTexture; // glTF image -> Mesh::textures index (-1: failed)
    // Per glTF material: the base colour texture's KHR_texture_transform and coordinate set,
    // applied to the UVs of the primitives using it.
    std::vector<TextureTransform> m_uvTransforms;

    bool collectInstances(std::vector<Instance>& instances);
    bool localTransform(int nodeIndex, glm::dmat4& out);
    bool viewBytes(int viewIndex, const std::string& user, const std::uint8_t*& data,
                   std::uint64_t& length);
    /** Float attributes or uint32 indices; normalized integers are converted (§3.11). */
    template <typename T>
    bool readAccessor(int accessorIndex, Semantic semantic, int& components, std::vector<T>& out);
    bool addPrimitive(const Instance& inst, std::size_t primIndex);
    /** Room in the mesh for every primitive of instances, at most the limits. */
    void reserveForInstances(const std::vector<Instance>& instances);
    /** The primitive's KHR_draco_mesh_compression object in the JSON, or nullptr. */
    const Json* dracoExtension(int mesh, std::size_t primIndex) const;
    bool decodeDracoPrimitive(const Json& ext, const std::string& where, const std::string& uvName,
                              std::vector<float>& pos, std::vector<float>& nrm,
                              std::vector<float>& uv, std::vector<float>& col, int& colComps,
                              std::vector<std::uint32_t>& order);
    bool addMaterials();
    int textureFor(int textureIndex, int texCoord, const std::string& materialName);
};

bool GltfFlattener::localTransform(int nodeIndex, glm::dmat4& out) {
    const tinygltf::Node& node = m_model.nodes[static_cast<std::size_t>(nodeIndex)];
    if (node.matrix.size() == 16) {
        out = glm::make_mat4(node.matrix.data()); // column-major, as glTF stores it
    } else {
        glm::dmat4 t(1.0), r(1.0), s(1.0);
        if (node.translation.size() == 3)
            t = glm::translate(glm::dmat4(1.0), glm::make_vec3(node.translation.data()));
        if (node.rotation.size() == 4) {
            glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
            const double len = glm::length(q);
            if (!(len > 1e-12) || !std::isfinite(len))
                return fail("node " + str(nodeIndex) + " has an invalid rotation");
            r = glm::mat4_cast(q / len);
        }
        if (node.scale.size() == 3)
            s = glm::scale(glm::dmat4(1.0), glm::make_vec3(node.scale.data()));
        out = t * r * s;
    }
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k)
            if (!std::isfinite(out[c][k]))
                return fail("node " + str(nodeIndex) + " has a transform that is not finite");
    return true;
}

bool GltfFlattener::collectInstances(std::vector<Instance>& instances) {
    const std::size_t nodeCount = m_model.nodes.size();
    std::vector<int> roots;
    if (m_model.defaultScene >= 0) {
        if (static_cast<std::size_t>(m_model.defaultScene) >= m_model.scenes.size())
            return fail("the default scene " + str(m_model.defaultScene) + " does not exist");
        roots = m_model.scenes[static_cast<std::size_t>(m_model.defaultScene)].nodes;
    } else if (!m_model.scenes.empty()) {
        roots = m_model.scenes[0].nodes;
    } else if (nodeCount > 0) {
        std::vector<char> isChild(nodeCount, 0);
        for (const tinygltf::Node& n : m_model.nodes)
            for (int c : n.children)
                if (c >= 0 && static_cast<std::size_t>(c) < nodeCount)
                    isChild[static_cast<std::size_t>(c)] = 1;
        for (std::size_t i = 0; i < nodeCount; ++i)
            if (!isChild[i])
                roots.push_back(static_cast<int>(i));
        warnOnce("the file has no scene: all root nodes are shown");
    } else {
        for (std::size_t m = 0; m < m_model.meshes.size(); ++m)
            instances.push_back(Instance{static_cast<int>(m), -1, glm::dmat4(1.0)});
        if (!instances.empty())
            warnOnce("the file has no scene and no nodes: all meshes are shown untransformed");
        return true;
    }

    // Iterative depth-first walk in document order; each node may be reached only once.
    std::vector<char> reached(nodeCount, 0);
    struct Item {
        int node;
        glm::dmat4 parent;
    };
    std::vector<Item> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.push_back(Item{*it, glm::dmat4(1.0)});
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        if (item.node < 0 || static_cast<std::size_t>(item.node) >= nodeCount)
            return fail("node " + str(item.node) + " does not exist");
        const auto idx = static_cast<std::size_t>(item.node);
        if (reached[idx])
            return fail("node " + str(item.node) +
                        " is reached more than once (the node hierarchy has a cycle or a node "
                        "with two parents)");
        reached[idx] = 1;
        glm::dmat4 local;
        if (!localTransform(item.node, local))
            return false;
        const glm::dmat4 global = item.parent * local;
        const tinygltf::Node& node = m_model.nodes[idx];
        if (node.mesh >= 0) {
            if (static_cast<std::size_t>(node.mesh) >= m_model.meshes.size())
                return fail("node " + str(item.node) + " uses mesh " + str(node.mesh) +
                            ", which does not exist");
            if (node.skin >= 0)
                warnOnce("skinning is ignored: skinned meshes are shown in their bind pose");
            instances.push_back(Instance{node.mesh, item.node, global});
        }
        for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
            stack.push_back(Item{*c, global});
    }
    return true;
}

bool GltfFlattener::viewBytes(int viewIndex, const std::string& user, const std::uint8_t*& data,
                              std::uint64_t& length) {
    if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= m_model.bufferViews.size())
        return fail(user + " uses buffer view " + str(viewIndex) + ", which does not exist");
    const tinygltf::BufferView& view = m_model.bufferViews[static_cast<std::size_t>(viewIndex)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= m_model.buffers.size())
        return fail("buffer view " + str(viewIndex) + " uses buffer " + str(view.buffer) +
                    ", which does not exist");
    const tinygltf::Buffer& buffer = m_model.buffers[static_cast<std::size_t>(view.buffer)];
    std::uint64_t end = 0;
    if (addOverflows(view.byteOffset, view.byteLength, end) || end > buffer.data.size())
        return fail("buffer view " + str(viewIndex) + " reaches past the end of buffer " +
                    str(view.buffer) + " (" + str(buffer.data.size()) + " bytes)");
    data = buffer.data.data() + view.byteOffset;
    length = view.byteLength;
    return true;
}

template <typename T>
bool GltfFlattener::readAccessor(int accessorIndex, Semantic semantic, int& components,
                                 std::vector<T>& out) {
    const std::string name = "accessor " + str(accessorIndex);
    if (accessorIndex < 0 || static_cast<std::size_t>(accessorIndex) >= m_model.accessors.size())
        return fail(std::string(semanticName(semantic)) + " uses accessor " + str(accessorIndex) +
                    ", which does not exist");
    const tinygltf::Accessor& acc = m_model.accessors[static_cast<std::size_t>(accessorIndex)];
    if (!typeAllowed(semantic, acc.type))
        return fail(name + " (" + semanticName(semantic) + ") has type " + typeName(acc.type) +
                    ", which glTF does not allow there");
    if (!componentAllowed(semantic, acc.componentType, acc.normalized, m_quantized))
        return fail(name + " (" + semanticName(semantic) + ") has component type " +
                    componentName(acc.componentType, acc.normalized) +
                    ", which glTF does not allow there");
    const std::uint64_t count = acc.count;
    const std::uint64_t cap =
        semantic == Semantic::Indices ? m_limits.maxTriangles * 3 + 2 : m_limits.maxVertices;
    if (count == 0)
        return fail(name + " has no elements");
    if (count > cap)
        return fail(name + " has too many elements (" + str(count) + ")");
    components = componentCount(acc.type);
    const std::uint64_t compSize = static_cast<std::uint64_t>(componentSize(acc.componentType));
    const std::uint64_t elemSize = compSize * static_cast<std::uint64_t>(components);
    const auto nc = static_cast<std::size_t>(components);
    out.assign(static_cast<std::size_t>(count) * nc, T(0));

    if (acc.bufferView >= 0) {
        const std::uint8_t* data = nullptr;
        std::uint64_t length = 0;
        if (!viewBytes(acc.bufferView, name, data, length))
            return false;
        const tinygltf::BufferView& view =
            m_model.bufferViews[static_cast<std::size_t>(acc.bufferView)];
        const std::uint64_t stride = view.byteStride != 0 ? view.byteStride : elemSize;
        if (stride < elemSize)
            return fail("buffer view " + str(acc.bufferView) + " has a byte stride of " +
                        str(stride) + ", smaller than the " + str(elemSize) + "-byte elements of " +
                        name);
        std::uint64_t span = 0, end = 0;
        if (mulOverflows(stride, count - 1, span) || addOverflows(span, elemSize, span) ||
            addOverflows(span, acc.byteOffset, end) || end > length)
            return fail(name + " reads past the end of buffer view " + str(acc.bufferView));
        for (std::size_t i = 0; i < count; ++i) {
            const std::uint8_t* e = data + acc.byteOffset + i * stride;
            for (std::size_t c = 0; c < nc; ++c)
                out[i * nc + c] =
                    readComponent(e + c * compSize, acc.componentType, acc.normalized);
        }
    } else if (semantic == Semantic::Indices && !acc.sparse.isSparse) {
        return fail(name + " (indices) has no buffer view");
    }

    if (acc.sparse.isSparse) {
        const auto& sp = acc.sparse;
        const std::uint64_t n = static_cast<std::uint64_t>(std::max(sp.count, 0));
        if (n == 0 || n > count)
            return fail(name + " has an invalid sparse count " + str(n));
        const int idxType = sp.indices.componentType;
        if (idxType != kUByte && idxType != kUShort && idxType != kUInt)
            return fail(name + " has sparse indices of an invalid component type");
        const std::uint8_t *idxData = nullptr, *valData = nullptr;
        std::uint64_t idxLen = 0, valLen = 0, end = 0;
        const std::string sparseName = name + " (sparse)";
        if (!viewBytes(sp.indices.bufferView, sparseName, idxData, idxLen) ||
            !viewBytes(sp.values.bufferView, sparseName, valData, valLen))
            return false;
        const auto idxSize = static_cast<std::uint64_t>(componentSize(idxType));
        const auto idxOffset = static_cast<std::uint64_t>(std::max(sp.indices.byteOffset, 0));
        const auto valOffset = static_cast<std::uint64_t>(std::max(sp.values.byteOffset, 0));
        if (addOverflows(idxOffset, n * idxSize, end) || end > idxLen)
            return fail(name + " has sparse indices past the end of buffer view " +
                        str(sp.indices.bufferView));
        if (addOverflows(valOffset, n * elemSize, end) || end > valLen)
            return fail(name + " has sparse values past the end of buffer view " +
                        str(sp.values.bufferView));
        for (std::size_t i = 0; i < n; ++i) {
            const auto target = static_cast<std::uint64_t>(
                readComponent(idxData + idxOffset + i * idxSize, idxType, false));
            if (target >= count)
                return fail(name + " has a sparse index " + str(target) + " out of range");
            const std::uint8_t* e = valData + valOffset + i * elemSize;
            for (std::size_t c = 0; c < nc; ++c)
                out[static_cast<std::size_t>(target) * nc + c] = static_cast<T>(
                    readComponent(e + c * compSize, acc.componentType, acc.normalized));
        }
    }

    if (semantic == Semantic::Position)
        for (T v : out)
            if (!std::isfinite(static_cast<double>(v)))
                return fail(name + " (POSITION) holds a value that is not a finite number");
    return true;
}

bool GltfFlattener::addPrimitive(const Instance& inst, std::size_t primIndex) {
    const tinygltf::Mesh& gm = m_model.meshes[static_cast<std::size_t>(inst.mesh)];
    const tinygltf::Primitive& prim = gm.primitives[primIndex];
    const std::string where = "mesh " + str(inst.mesh) + " primitive " + str(primIndex);

    int mode = prim.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE ||
        mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) {
        ++m_skippedPrimitives;
        return true;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN)
        return fail(where + " has an invalid mode " + str(mode));
    const auto posIt = prim.attributes.find("POSITION");
    if (posIt == prim.attributes.end()) {
        warnOnce("primitives without POSITION were skipped");
        return true;
    }
    if (!prim.targets.empty())
        warnOnce("morph targets are ignored: meshes are shown without them");

    const int material = prim.material;
    const TextureTransform* uvTransform =
        material >= 0 && static_cast<std::size_t>(material) < m_uvTransforms.size()
            ? &m_uvTransforms[static_cast<std::size_t>(material)]
            : nullptr;
    const std::string uvName = "TEXCOORD_" + str(uvTransform ? uvTransform->texCoord : 0);

    int nc = 0;
    std::vector<float> pos;
    int nrmComps = 3, uvComps = 2, colComps = 0;
    std::vector<float> nrm, uv, col;
    std::vector<std::uint32_t> order; // the triangles' vertex order before strips and fans
    std::size_t vertexCount = 0;
    int hasNormal = 0, hasUv = 0, hasColor = 0;
    if (const Json* draco = dracoExtension(inst.mesh, primIndex)) {
        if (mode != TINYGLTF_MODE_TRIANGLES)
            return fail(where + " is Draco-compressed but not made of triangles");
        if (!decodeDracoPrimitive(*draco, where, uvName, pos, nrm, uv, col, colComps, order))
            return false;
        vertexCount = pos.size() / 3;
        // The primitive's accessors describe what the Draco data decodes to; a mismatch means
        // the file is damaged (or the attribute map points at other data).
        const auto accessorCount = [&](int index) -> std::uint64_t {
            return index >= 0 && static_cast<std::size_t>(index) < m_model.accessors.size()
                       ? m_model.accessors[static_cast<std::size_t>(index)].count
                       : 0;
        };
        if (accessorCount(posIt->second) != vertexCount)
            return fail(where + ": the Draco data holds " + str(vertexCount) +
                        " vertices, but accessor " + str(posIt->second) + " (POSITION) says " +
                        str(accessorCount(posIt->second)));
        // tinygltf saw no indices (dropDracoIndices); the file's JSON has them.
        const Json& jsonPrim =
            m_json["meshes"][static_cast<std::size_t>(inst.mesh)]["primitives"][primIndex];
        if (const auto it = jsonPrim.find("indices"); it != jsonPrim.end()) {
            const int indices = it->get<int>();
            if (accessorCount(indices) != order.size())
                return fail(where + ": the Draco data holds " + str(order.size()) +
                            " indices, but accessor " + str(indices) + " (indices) says " +
                            str(accessorCount(indices)));
        }
        hasNormal = nrm.empty() ? 0 : 1;
        hasUv = uv.empty() ? 0 : 1;
        hasColor = col.empty() ? 0 : 1;
    } else {
        if (!readAccessor(posIt->second, Semantic::Position, nc, pos))
            return false;
        vertexCount = pos.size() / 3;

        auto readMatching = [&](const char* attr, Semantic sem, int& comps,
                                std::vector<float>& values) -> int {
            const auto it = prim.attributes.find(attr);
            if (it == prim.attributes.end())
                return 0;
            if (!readAccessor(it->second, sem, comps, values))
                return -1;
            if (values.size() / static_cast<std::size_t>(comps) != vertexCount) {
                fail(where + ": " + attr + " has " +
                     str(values.size() / static_cast<std::size_t>(comps)) +
                     " elements but POSITION " + str(vertexCount));
                return -1;
            }
            return 1;
        };
        hasNormal = readMatching("NORMAL", Semantic::Normal, nrmComps, nrm);
        hasUv = readMatching(uvName.c_str(), Semantic::TexCoord, uvComps, uv);
        hasColor = readMatching("COLOR_0", Semantic::Color, colComps, col);
        if (hasNormal < 0 || hasUv < 0 || hasColor < 0)
            return false;

        if (prim.indices >= 0) {
            int one = 0;
            if (!readAccessor(prim.indices, Semantic::Indices, one, order))
                return false;
            for (std::uint32_t i : order)
                if (i >= vertexCount)
                    return fail(where + ": index " + str(i) +
                                " is out of range (the primitive has " + str(vertexCount) +
                                " vertices)");
        } else {
            order.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i)
                order[i] = static_cast<std::uint32_t>(i);
        }
    }

    std::vector<std::uint32_t> tris; // local vertex indices, 3 per triangle
    const std::size_t n = order.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0)
            warnOnce("incomplete triangles at the end of a primitive were dropped");
        tris = std::move(order); // the list itself: a 10M-triangle file holds 120 MB of it
        tris.resize(n - n % 3);
    } else if (n >= 3) {
        tris.reserve((n - 2) * 3);
        for (std::size_t i = 0; i + 2 < n; ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) // glTF 2.0 §3.7.2.1: keeps the winding
                tris.insert(tris.end(), {order[i], order[i + 1 + i % 2], order[i + 2 - i % 2]});
            else
                tris.insert(tris.end(), {order[i + 1], order[i + 2], order[0]});
        }
    }
    if (tris.empty()) {
        warnOnce("primitives with fewer than 3 vertices were skipped");
        return true;
    }

    // Only the vertices the triangles use, in their original order.
    Result<UsedVertices> usedVertices = numberUsedVertices(tris, vertexCount, m_mesh, m_limits);
    if (!usedVertices)
        return fail(usedVertices.error());
    const std::vector<std::uint32_t>& remap = usedVertices->remap;

    const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(inst.transform));
    const bool mirrored = glm::determinant(glm::dmat3(inst.transform)) < 0.0;
    const auto base = static_cast<std::uint32_t>(m_mesh.positions.size());
    // UVs and colours only from the first primitive that has them on (earlier vertices get the
    // defaults then): a file without colours holds no white per vertex while it loads.
    const bool keepUvs = m_anyUv || hasUv, keepColors = m_anyColor || hasColor;
    if (keepUvs)
        m_mesh.uvs.resize(base, glm::vec2(0.0f));
    if (keepColors)
        m_mesh.colors.resize(base, glm::vec4(1.0f));
    for (std::size_t v = 0; v < vertexCount; ++v) {
        if (remap[v] == std::numeric_limits<std::uint32_t>::max())
            continue;
        glm::vec3 pf;
        if (!toFloat(glm::dvec3(inst.transform *
                                glm::dvec4(pos[v * 3], pos[v * 3 + 1], pos[v * 3 + 2], 1.0)),
                     pf))
            return fail(where + ": a vertex position is not finite after the node transform");
        m_mesh.positions.push_back(pf);
        m_mesh.normals.push_back(
            hasNormal
                ? unitNormal(normalMatrix * glm::dvec3(nrm[v * 3], nrm[v * 3 + 1], nrm[v * 3 + 2]))
                : glm::vec3(0.0f));
        m_hasNormal.push_back(hasNormal ? 1 : 0);
        glm::vec2 t(0.0f);
        if (hasUv) {
            t = glm::vec2(uv[v * 2], uv[v * 2 + 1]);
            if (uvTransform && uvTransform->present)
                t = uvTransform->apply(t);
        }
        if (keepUvs)
            m_mesh.uvs.push_back(t);
        glm::vec4 c(1.0f);
        if (hasColor)
            for (int k = 0; k < colComps; ++k)
                c[k] = col[v * static_cast<std::size_t>(colComps) + static_cast<std::size_t>(k)];
        if (keepColors)
            m_mesh.colors.push_back(c);
    }
    m_anyUv = keepUvs;
    m_anyColor = keepColors;
    // The attributes are in the mesh now; the triangles follow.
    for (std::vector<float>* read : {&pos, &nrm, &uv, &col})
        std::vector<float>().swap(*read);

    if (material >= 0 && static_cast<std::size_t>(material) >= m_model.materials.size())
        return fail(where + " uses material " + str(material) + ", which does not exist");
    // Primitives without a material get the default one, appended after the file's.
    const auto matIndex =
        static_cast<std::uint32_t>(material >= 0 ? material : m_model.materials.size());
    for (std::size_t t = 0; t < tris.size(); t += 3) {
        const std::uint32_t a = base + remap[tris[t]];
        const std::uint32_t b = base + remap[tris[t + 1]];
        const std::uint32_t c = base + remap[tris[t + 2]];
        if (mirrored) // a mirroring transform flips the winding (glTF 2.0 §3.5.3)
            m_mesh.indices.insert(m_mesh.indices.end(), {a, c, b});
        else
            m_mesh.indices.insert(m_mesh.indices.end(), {a, b, c});
        m_mesh.triangleMaterial.push_back(matIndex);
    }
    return true;
}

const Json* GltfFlattener::dracoExtension(int mesh, std::size_t primIndex) const {
    const auto meshes = m_json.find("meshes");
    if (meshes == m_json.end() || static_cast<std::size_t>(mesh) >= meshes->size())
        return nullptr;
    const Json& prims = (*meshes)[static_cast<std::size_t>(mesh)]["primitives"];
    if (primIndex >= prims.size())
        return nullptr;
    const auto exts = prims[primIndex].find("extensions");
    if (exts == prims[primIndex].end())
        return nullptr;
    const auto ext = exts->find("KHR_draco_mesh_compression");
    return ext == exts->end() ? nullptr : &*ext;
}

bool GltfFlattener::decodeDracoPrimitive(const Json& ext, const std::string& where,
                                         const std::string& uvName, std::vector<float>& pos,
                                         std::vector<float>& nrm, std::vector<float>& uv,
                                         std::vector<float>& col, int& colComps,
                                         std::vector<std::uint32_t>& order) {
    const std::string at = where + " (KHR_draco_mesh_compression)";
    const auto view = ext.find("bufferView");
    const auto attributes = ext.find("attributes");
    if (view == ext.end() || !view->is_number_unsigned() ||
        view->get<std::uint64_t>() > kMaxIndex || attributes == ext.end() ||
        !attributes->is_object())
        return fail(at + " needs a bufferView and an attributes object");
    std::map<std::string, std::uint32_t> ids;
    for (auto it = attributes->begin(); it != attributes->end(); ++it) {
        if (!it.value().is_number_unsigned() || it.value().get<std::uint64_t>() > kMaxIndex)
            return fail(at + ": attribute " + it.key() + " must be a non-negative integer");
        ids[it.key()] = it.value().get<std::uint32_t>();
    }
    const std::uint8_t* data = nullptr;
    std::uint64_t length = 0;
    if (!viewBytes(view->get<int>(), at, data, length))
        return false;
    Result<DracoPrimitive> decoded =
        decodeDraco(data, static_cast<std::size_t>(length), ids, uvName, m_limits);
    if (!decoded)
        return fail(at + ": " + decoded.error());
    pos = std::move(decoded->positions);
    nrm = std::move(decoded->normals);
    uv = std::move(decoded->uvs);
    col = std::move(decoded->colors);
    colComps = decoded->colorComponents;
    order = std::move(decoded->indices);
    return true;
}

int GltfFlattener::textureFor(int textureIndex, int texCoord, const std::string& materialName) {
    if (textureIndex < 0)
        return -1;
    if (static_cast<std::size_t>(textureIndex) >= m_model.textures.size()) {
        fail("material \"" + materialName + "\" uses texture " + str(textureIndex) +
             ", which does not exist");
        return -1;
    }
    (void)texCoord; // the primitives read the set the material's texture uses
    const int source = m_model.textures[static_cast<std::size_t>(textureIndex)].source;
    if (source < 0) {
        warnOnce("textures without a source image (or only an extension's image) are ignored");
        return -1;
    }
    if (static_cast<std::size_t>(source) >= m_model.images.size()) {
        fail("texture " + str(textureIndex) + " uses image " + str(source) +
             ", which does not exist");
        return -1;
    }
    if (const auto it = m_imageToTexture.find(source); it != m_imageToTexture.end())
        return it->second;

    const tinygltf::Image& img = m_model.images[static_cast<std::size_t>(source)];
    const std::string label = img.uri.empty() || img.uri.rfind("data:", 0) == 0
                                  ? "image " + str(source)
                                  : "image " + str(source) + " (" + img.uri + ")";
    const std::uint8_t* data = nullptr;
    std::uint64_t length = 0;
    if (img.bufferView >= 0) {
        if (!viewBytes(img.bufferView, label, data, length))
            return -1;
    } else if (const auto it = m_access.imageBytes.find(source); it != m_access.imageBytes.end()) {
        data = it->second.data();
        length = it->second.size();
    }
    int result = -1;
    if (data == nullptr || length == 0) {
        if (m_limits.requireTextures) {
            fail(label + " could not be read");
            return -1;
        }
        m_mesh.warnings.push_back(label + " could not be read; the material has no texture");
    } else {
        Result<Image> decoded =
            decodeImage(data, static_cast<std::size_t>(length), label, m_limits);
        if (decoded) {
            result = static_cast<int>(m_mesh.textures.size());
            m_mesh.textures.push_back(std::move(decoded).value());
        } else if (m_limits.requireTextures) {
            fail(decoded.error());
            return -1;
        } else {
            m_mesh.warnings.push_back(decoded.error() + "; the material has no texture");
        }
    }
    m_imageToTexture[source] = result;
    return result;
}

bool GltfFlattener::addMaterials() {
    const Json* jsonMaterials = nullptr;
    if (const auto it = m_json.find("materials"); it != m_json.end())
        jsonMaterials = &*it;
    for (std::size_t i = 0; i < m_model.materials.size(); ++i) {
        const tinygltf::Material& gm = m_model.materials[i];
        Material mat;
        mat.name = gm.name.empty() ? "material " + str(i) : gm.name;
        const auto& pbr = gm.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() == 4)
            for (int k = 0; k < 4; ++k)
                mat.baseColorFactor[k] =
                    static_cast<float>(pbr.baseColorFactor[static_cast<std::size_t>(k)]);
        int texIndex = pbr.baseColorTexture.index;
        int texCoord = pbr.baseColorTexture.texCoord;
        // KHR_materials_pbrSpecularGlossiness: its diffuse is the base color when the
        // metallic-roughness one is absent.
        if (jsonMaterials && i < jsonMaterials->size()) {
            const Json& jm = (*jsonMaterials)[i];
            const Json sg = jm.value("extensions", Json::object())
                                .value("KHR_materials_pbrSpecularGlossiness", Json::object());
            if (!jm.contains("pbrMetallicRoughness") && sg.is_object() && !sg.empty()) {
                const Json factor = sg.value("diffuseFactor", Json());
                if (factor.is_array() && factor.size() == 4)
                    for (int k = 0; k < 4; ++k)
                        if (factor[static_cast<std::size_t>(k)].is_number())
                            mat.baseColorFactor[k] =
                                factor[static_cast<std::size_t>(k)].get<float>();
                const Json tex = sg.value("diffuseTexture", Json());
                if (tex.is_object() && tex.contains("index") && tex["index"].is_number_unsigned() &&
                    tex["index"].get<std::uint64_t>() <= kMaxIndex) {
                    texIndex = tex["index"].get<int>();
                    const Json coord = tex.value("texCoord", Json(0));
                    texCoord = coord.is_number_unsigned() && coord.get<std::uint64_t>() <= kMaxIndex
                                   ? coord.get<int>()
                                   : -1;
                }
            }
        }
        for (int k = 0; k < 4; ++k)
            if (!std::isfinite(mat.baseColorFactor[k]))
                mat.baseColorFactor[k] = 1.0f;
        mat.baseColorTexture = textureFor(texIndex, texCoord, mat.name);
        if (!m_error.message.empty())
            return false;
        m_mesh.materials.push_back(std::move(mat));
    }
    // The default material, for primitives without one.
    m_mesh.materials.push_back(Material{"default", glm::vec4(1.0f), -1});
    return true;
}

void GltfFlattener::reserveForInstances(const std::vector<Instance>& instances) {
    // At most the accessors' counts (primitives use only some vertices; strips and fans give
    // three indices per vertex): the arrays then grow without copies or twice their size in
    // spare room. Reserved room that is never written takes no memory.
    const auto countOf = [&](int accessor) -> std::uint64_t {
        return accessor >= 0 && static_cast<std::size_t>(accessor) < m_model.accessors.size()
                   ? m_model.accessors[static_cast<std::size_t>(accessor)].count
                   : 0;
    };
    std::uint64_t vertices = 0, indices = 0;
    for (const Instance& inst : instances)
        for (const tinygltf::Primitive& prim :
             m_model.meshes[static_cast<std::size_t>(inst.mesh)].primitives) {
            const auto pos = prim.attributes.find("POSITION");
            const std::uint64_t v = pos == prim.attributes.end() ? 0 : countOf(pos->second);
            const std::uint64_t i = prim.indices >= 0 ? countOf(prim.indices) : v;
            vertices += v;
            indices += prim.mode == TINYGLTF_MODE_TRIANGLES || prim.mode < 0 ? i : 3 * i;
        }
    if (vertices > m_limits.maxVertices || indices / 3 > m_limits.maxTriangles)
        return; // refused as it is read
    const auto v = static_cast<std::size_t>(vertices), i = static_cast<std::size_t>(indices);
    m_mesh.positions.reserve(v);
    m_mesh.normals.reserve(v);
    m_mesh.uvs.reserve(v);
    m_hasNormal.reserve(v);
    m_mesh.indices.reserve(i);
    m_mesh.triangleMaterial.reserve(i / 3);
}

bool GltfFlattener::run(Mesh& out) {
    std::vector<Instance> instances;
    if (!collectInstances(instances))
        return false;
    Result<MaterialTransforms> transforms = readMaterialTransforms(m_json);
    if (!transforms)
        return fail(transforms.error());
    m_uvTransforms = std::move(transforms->transforms);
    for (const std::string& w : transforms->warnings)
        warnOnce(w);
    std::size_t primTotal = 0, primDone = 0;
    for (const Instance& inst : instances)
        primTotal += m_model.meshes[static_cast<std::size_t>(inst.mesh)].primitives.size();
    reserveForInstances(instances);
    for (const Instance& inst : instances) {
        const auto& prims = m_model.meshes[static_cast<std::size_t>(inst.mesh)].primitives;
        for (std::size_t p = 0; p < prims.size(); ++p) {
            if (!addPrimitive(inst, p))
                return false;
            ++primDone;
            if (!reportProgress(m_progress, 0.5 + 0.4 * static_cast<double>(primDone) /
                                                      static_cast<double>(primTotal)))
                return fail("cancelled", ErrorKind::Cancelled);
        }
    }
    if (m_skippedPrimitives > 0)
        m_mesh.warnings.push_back(str(m_skippedPrimitives) +
                                  " primitives of points or lines were skipped");
    if (m_mesh.indices.empty())
        return fail("the file contains no triangles");
    if (!addMaterials())
        return false;

    // The default material is only kept if used.
    const auto defaultIndex = static_cast<std::uint32_t>(m_mesh.materials.size() - 1);
    if (m_mesh.materials.size() > 1 &&
        std::find(m_mesh.triangleMaterial.begin(), m_mesh.triangleMaterial.end(), defaultIndex) ==
            m_mesh.triangleMaterial.end())
        m_mesh.materials.pop_back();

    finish(out);
    return true;
}

} // namespace

Result<Mesh> flattenGltf(const tinygltf::Model& model, const Json& json, const FileAccess& access,
                         bool quantized, const ProgressFn& progress, const LoadLimits& limits) {
    Mesh mesh;
    GltfFlattener flattener(model, json, access, quantized, progress, limits);
    if (!flattener.run(mesh))
        return flattener.error();
    return mesh;
}

} // namespace core::detail::gltf
