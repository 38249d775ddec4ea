// SPDX-License-Identifier: GPL-3.0-or-later
// The glTF scene flattener (see gltf_flatten.h): the scene walk, the materials and their
// textures, and the run over every primitive (gltf_flatten_primitive.cpp reads one).
#include "core/io/gltf/gltf_flatten.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "core/io/gltf/gltf_flattener.h"

static_assert(std::endian::native == std::endian::little,
              "glTF buffers are little-endian and are read with memcpy");

namespace core::detail::gltf {

using Json = nlohmann::json;

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

bool GltfFlattener::collectInstances(std::vector<GltfInstance>& instances) {
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
            instances.push_back(GltfInstance{static_cast<int>(m), -1, glm::dmat4(1.0)});
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
            instances.push_back(GltfInstance{node.mesh, item.node, global});
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

int GltfFlattener::textureFor(int textureIndex, int texCoord, const std::string& materialName) {
    if (textureIndex < 0)
        return -1;
    if (static_cast<std::size_t>(textureIndex) >= m_model.textures.size()) {
        fail("material \"" + materialName + "\" uses texture " + str(textureIndex) +
             ", which does not exist");
        return -1;
    }
    (void)texCoord; // the primitives read the set the material's textures use
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
        // The decoder hands over the stored values as they are (no gamma or colour profile is
        // applied): base colour and emissive stay sRGB-encoded, the other maps linear.
        Result<Image> decoded =
            decodeImage(data, static_cast<std::size_t>(length), label, m_limits);
        if (decoded) {
            result = addTexture(std::move(decoded).value(), data, static_cast<std::size_t>(length));
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

namespace {

/** A finite number, else fallback. */
float finiteOr(double v, float fallback) {
    return std::isfinite(v) ? static_cast<float>(v) : fallback;
}

AlphaMode alphaModeOf(const std::string& mode) {
    if (mode == "MASK")
        return AlphaMode::Mask;
    if (mode == "BLEND")
        return AlphaMode::Blend;
    return AlphaMode::Opaque;
}

} // namespace

bool GltfFlattener::readMaterial(std::size_t i, Material& mat) {
    const tinygltf::Material& gm = m_model.materials[i];
    mat.name = gm.name.empty() ? "material " + str(i) : gm.name;
    const auto& pbr = gm.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4)
        for (int k = 0; k < 4; ++k)
            mat.baseColorFactor[k] =
                static_cast<float>(pbr.baseColorFactor[static_cast<std::size_t>(k)]);
    mat.metallicFactor = finiteOr(pbr.metallicFactor, 1.0f);
    mat.roughnessFactor = finiteOr(pbr.roughnessFactor, 1.0f);
    mat.normalScale = finiteOr(gm.normalTexture.scale, 1.0f);
    mat.occlusionStrength = finiteOr(gm.occlusionTexture.strength, 1.0f);
    if (gm.emissiveFactor.size() == 3)
        for (int k = 0; k < 3; ++k)
            mat.emissiveFactor[k] = finiteOr(gm.emissiveFactor[static_cast<std::size_t>(k)], 0.0f);
    mat.alphaMode = alphaModeOf(gm.alphaMode);
    mat.alphaCutoff = finiteOr(gm.alphaCutoff, 0.5f);
    mat.doubleSided = gm.doubleSided;
    int texIndex = pbr.baseColorTexture.index;
    int texCoord = pbr.baseColorTexture.texCoord;
    if (m_json.contains("materials") && i < m_json["materials"].size()) {
        const Json& jm = m_json["materials"][i];
        const Json exts = jm.value("extensions", Json::object());
        const Json strength = exts.value("KHR_materials_emissive_strength", Json::object())
                                  .value("emissiveStrength", Json(1.0));
        if (strength.is_number())
            mat.emissiveStrength = finiteOr(strength.get<double>(), 1.0f);
        // KHR_materials_pbrSpecularGlossiness: its diffuse is the base color when the
        // metallic-roughness one is absent.
        const Json sg = exts.value("KHR_materials_pbrSpecularGlossiness", Json::object());
        if (!jm.contains("pbrMetallicRoughness") && sg.is_object() && !sg.empty()) {
            // Specular-glossiness has no metal; its glossiness is the roughness turned round.
            mat.metallicFactor = 0.0f;
            const Json gloss = sg.value("glossinessFactor", Json(1.0));
            if (gloss.is_number())
                mat.roughnessFactor =
                    std::clamp(1.0f - finiteOr(gloss.get<double>(), 1.0f), 0.0f, 1.0f);
            const Json factor = sg.value("diffuseFactor", Json());
            if (factor.is_array() && factor.size() == 4)
                for (int k = 0; k < 4; ++k)
                    if (factor[static_cast<std::size_t>(k)].is_number())
                        mat.baseColorFactor[k] = factor[static_cast<std::size_t>(k)].get<float>();
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
    return m_error.message.empty();
}

bool GltfFlattener::readMaterialMaps(std::size_t i, Material& mat) {
    const tinygltf::Material& gm = m_model.materials[i];
    const auto& mr = gm.pbrMetallicRoughness.metallicRoughnessTexture;
    const std::pair<int, int> textures[kMapSlots] = {
        {mr.index, mr.texCoord},
        {gm.normalTexture.index, gm.normalTexture.texCoord},
        {gm.occlusionTexture.index, gm.occlusionTexture.texCoord},
        {gm.emissiveTexture.index, gm.emissiveTexture.texCoord}};
    MaterialMap* maps[kMapSlots] = {&mat.metallicRoughness, &mat.normal, &mat.occlusion,
                                    &mat.emissive};
    for (std::size_t m = 0; m < kMapSlots; ++m) {
        maps[m]->texture = textureFor(textures[m].first, textures[m].second, mat.name);
        if (!m_error.message.empty())
            return false;
        if (maps[m]->texture >= 0 && i < m_mapTransforms.size())
            maps[m]->uvTransform = m_mapTransforms[i][m];
    }
    return true;
}

bool GltfFlattener::addMaterials() {
    // Every base colour texture first, in the order of first use, then the other maps: a saved
    // project's base colour textures are its paint target's pages, in that order.
    for (std::size_t i = 0; i < m_model.materials.size(); ++i) {
        Material mat;
        if (!readMaterial(i, mat))
            return false;
        m_mesh.materials.push_back(std::move(mat));
    }
    for (std::size_t i = 0; i < m_model.materials.size(); ++i)
        if (!readMaterialMaps(i, m_mesh.materials[i]))
            return false;
    // The default material, for primitives without one.
    Material fallback{"default", glm::vec4(1.0f), -1};
    fallback.metallicFactor = 1.0f; // glTF's default material
    m_mesh.materials.push_back(std::move(fallback));
    return true;
}

void GltfFlattener::reserveForInstances(const std::vector<GltfInstance>& instances) {
    // At most the accessors' counts (primitives use only some vertices; strips and fans give
    // three indices per vertex): the arrays then grow without copies or twice their size in
    // spare room. Reserved room that is never written takes no memory.
    const auto countOf = [&](int accessor) -> std::uint64_t {
        return accessor >= 0 && static_cast<std::size_t>(accessor) < m_model.accessors.size()
                   ? m_model.accessors[static_cast<std::size_t>(accessor)].count
                   : 0;
    };
    std::uint64_t vertices = 0, indices = 0;
    for (const GltfInstance& inst : instances)
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
    std::vector<GltfInstance> instances;
    if (!collectInstances(instances))
        return false;
    Result<MaterialTransforms> transforms = readMaterialTransforms(m_json);
    if (!transforms)
        return fail(transforms.error());
    m_uvTransforms = std::move(transforms->transforms);
    m_mapTransforms = std::move(transforms->maps);
    for (const std::string& w : transforms->warnings)
        warnOnce(w);
    std::size_t primTotal = 0, primDone = 0;
    for (const GltfInstance& inst : instances)
        primTotal += m_model.meshes[static_cast<std::size_t>(inst.mesh)].primitives.size();
    reserveForInstances(instances);
    for (const GltfInstance& inst : instances) {
        const tinygltf::Mesh& mesh = m_model.meshes[static_cast<std::size_t>(inst.mesh)];
        const std::string& nodeName = m_model.nodes[static_cast<std::size_t>(inst.node)].name;
        beginObject(nodeName.empty() ? mesh.name : nodeName);
        const auto& prims = mesh.primitives;
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

    m_mesh.textureOrigins.assign(m_mesh.textures.size(), TextureOrigin{});
    for (const auto& [image, texture] : m_imageToTexture)
        if (texture >= 0)
            m_mesh.textureOrigins[std::size_t(texture)] = TextureOrigin{image, true};
    finish(out);
    return true;
}

Result<Mesh> flattenGltf(const tinygltf::Model& model, const Json& json, const FileAccess& access,
                         bool quantized, const ProgressFn& progress, const LoadLimits& limits,
                         SourceScene* runs) {
    Mesh mesh;
    GltfFlattener flattener(model, json, access, quantized, progress, limits);
    if (!flattener.run(mesh))
        return flattener.error();
    if (runs) {
        runs->primitives = std::move(flattener.sourcePrimitives());
        runs->usedVertices = std::move(flattener.usedVertices());
    }
    return mesh;
}

} // namespace core::detail::gltf
