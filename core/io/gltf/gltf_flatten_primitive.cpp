// SPDX-License-Identifier: GPL-3.0-or-later
// One glTF primitive into the flattened mesh (see gltf_flattener.h): screened, read from its
// accessors or its Draco data, its strips and fans made triangles, then only the vertices those
// use appended under the node's transform, and the triangles after them.
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/mat3x3.hpp>

#include "core/io/gltf/gltf_draco.h"
#include "core/io/gltf/gltf_flattener.h"

namespace core::detail::gltf {

using Json = nlohmann::json;

/** The accessor's sparse substitution over out (nc components per element). */
template <typename T>
bool GltfFlattener::applySparse(const tinygltf::Accessor& acc, const std::string& name,
                                std::size_t nc, std::vector<T>& out) {
    const std::uint64_t count = acc.count;
    const std::uint64_t compSize = static_cast<std::uint64_t>(componentSize(acc.componentType));
    const std::uint64_t elemSize = compSize * static_cast<std::uint64_t>(nc);
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
            out[static_cast<std::size_t>(target) * nc + c] =
                static_cast<T>(readComponent(e + c * compSize, acc.componentType, acc.normalized));
    }
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

    if (acc.sparse.isSparse && !applySparse(acc, name, nc, out))
        return false;

    if (semantic == Semantic::Position)
        for (T v : out)
            if (!std::isfinite(static_cast<double>(v)))
                return fail(name + " (POSITION) holds a value that is not a finite number");
    return true;
}

bool GltfFlattener::addPrimitive(const GltfInstance& inst, std::size_t primIndex) {
    const tinygltf::Mesh& gm = m_model.meshes[static_cast<std::size_t>(inst.mesh)];
    PrimitiveRead p(inst, primIndex, gm.primitives[primIndex],
                    "mesh " + str(inst.mesh) + " primitive " + str(primIndex));
    switch (screenPrimitive(p)) {
    case Screening::Skip:
        return true;
    case Screening::Fail:
        return false;
    case Screening::Read:
        break;
    }
    const Json* draco = dracoExtension(inst.mesh, primIndex);
    if (draco) {
        if (!readDracoPrimitive(p, *draco))
            return false;
    } else if (!readAccessorPrimitive(p)) {
        return false;
    }
    triangulate(p);
    if (p.tris.empty()) {
        warnOnce("primitives with fewer than 3 vertices were skipped");
        return true;
    }
    // Only the vertices the triangles use, in their original order.
    Result<UsedVertices> usedVertices = numberUsedVertices(p.tris, p.vertexCount, m_mesh, m_limits);
    if (!usedVertices)
        return fail(usedVertices.error());
    const auto base = static_cast<std::uint32_t>(m_mesh.positions.size());
    const auto firstTriangle = static_cast<std::uint32_t>(m_mesh.indices.size() / 3);
    if (!appendVertices(p, usedVertices->remap) || !appendTriangles(p, usedVertices->remap, base))
        return false;
    recordSource(p, *usedVertices, draco != nullptr, firstTriangle, base);
    return true;
}

void GltfFlattener::recordSource(const PrimitiveRead& p, const UsedVertices& used, bool draco,
                                 std::uint32_t firstTriangle, std::uint32_t firstVertex) {
    const auto end = static_cast<std::uint32_t>(m_mesh.indices.size() / 3);
    if (end == firstTriangle)
        return;
    SourcePrimitive source{static_cast<std::uint32_t>(p.inst.mesh),
                           static_cast<std::uint32_t>(p.primIndex),
                           firstTriangle,
                           end - firstTriangle,
                           firstVertex,
                           static_cast<std::uint32_t>(used.count),
                           static_cast<std::uint32_t>(p.vertexCount),
                           draco ? SourcePrimitive::kDraco : 0u};
    if (used.count != p.vertexCount) {
        source.flags |= SourcePrimitive::kPartial;
        for (std::size_t v = 0; v < used.remap.size(); ++v)
            if (used.remap[v] != std::numeric_limits<std::uint32_t>::max())
                m_usedVertices.push_back(static_cast<std::uint32_t>(v));
    }
    m_sourcePrimitives.push_back(source);
}

GltfFlattener::Screening GltfFlattener::screenPrimitive(PrimitiveRead& p) {
    p.mode = p.prim.mode;
    const int mode = p.mode;
    if (mode == TINYGLTF_MODE_POINTS || mode == TINYGLTF_MODE_LINE ||
        mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) {
        ++m_skippedPrimitives;
        return Screening::Skip;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        fail(p.where + " has an invalid mode " + str(mode));
        return Screening::Fail;
    }
    const auto posIt = p.prim.attributes.find("POSITION");
    if (posIt == p.prim.attributes.end()) {
        warnOnce("primitives without POSITION were skipped");
        return Screening::Skip;
    }
    p.positionAccessor = posIt->second;
    if (!p.prim.targets.empty())
        warnOnce("morph targets are ignored: meshes are shown without them");

    p.material = p.prim.material;
    p.uvTransform = p.material >= 0 && static_cast<std::size_t>(p.material) < m_uvTransforms.size()
                        ? &m_uvTransforms[static_cast<std::size_t>(p.material)]
                        : nullptr;
    p.uvName = "TEXCOORD_" + str(p.uvTransform ? p.uvTransform->texCoord : 0);
    return Screening::Read;
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

bool GltfFlattener::readDracoPrimitive(PrimitiveRead& p, const Json& ext) {
    if (p.mode != TINYGLTF_MODE_TRIANGLES)
        return fail(p.where + " is Draco-compressed but not made of triangles");
    if (!decodeDracoPrimitive(p, ext))
        return false;
    p.vertexCount = p.pos.size() / 3;
    // The primitive's accessors describe what the Draco data decodes to; a mismatch means
    // the file is damaged (or the attribute map points at other data).
    const auto accessorCount = [&](int index) -> std::uint64_t {
        return index >= 0 && static_cast<std::size_t>(index) < m_model.accessors.size()
                   ? m_model.accessors[static_cast<std::size_t>(index)].count
                   : 0;
    };
    if (accessorCount(p.positionAccessor) != p.vertexCount)
        return fail(p.where + ": the Draco data holds " + str(p.vertexCount) +
                    " vertices, but accessor " + str(p.positionAccessor) + " (POSITION) says " +
                    str(accessorCount(p.positionAccessor)));
    // tinygltf saw no indices (dropDracoIndices); the file's JSON has them.
    const Json& jsonPrim =
        m_json["meshes"][static_cast<std::size_t>(p.inst.mesh)]["primitives"][p.primIndex];
    if (const auto it = jsonPrim.find("indices"); it != jsonPrim.end()) {
        const int indices = it->get<int>();
        if (accessorCount(indices) != p.order.size())
            return fail(p.where + ": the Draco data holds " + str(p.order.size()) +
                        " indices, but accessor " + str(indices) + " (indices) says " +
                        str(accessorCount(indices)));
    }
    p.hasNormal = p.nrm.empty() ? 0 : 1;
    p.hasUv = p.uv.empty() ? 0 : 1;
    p.hasColor = p.col.empty() ? 0 : 1;
    return true;
}

bool GltfFlattener::decodeDracoPrimitive(PrimitiveRead& p, const Json& ext) {
    const std::string at = p.where + " (KHR_draco_mesh_compression)";
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
        decodeDraco(data, static_cast<std::size_t>(length), ids, p.uvName, m_limits);
    if (!decoded)
        return fail(at + ": " + decoded.error());
    p.pos = std::move(decoded->positions);
    p.nrm = std::move(decoded->normals);
    p.uv = std::move(decoded->uvs);
    p.col = std::move(decoded->colors);
    p.colComps = decoded->colorComponents;
    p.order = std::move(decoded->indices);
    return true;
}

bool GltfFlattener::readAccessorPrimitive(PrimitiveRead& p) {
    int nc = 0;
    if (!readAccessor(p.positionAccessor, Semantic::Position, nc, p.pos))
        return false;
    p.vertexCount = p.pos.size() / 3;
    p.hasNormal = readMatchingAttribute(p, "NORMAL", Semantic::Normal, p.nrmComps, p.nrm);
    // glTF 2.0 §3.7.2.1: without normals, the tangents are ignored.
    if (p.hasNormal > 0 && wantsTangents(p))
        p.hasTangent = readMatchingAttribute(p, "TANGENT", Semantic::Tangent, p.tanComps, p.tan);
    p.hasUv = readMatchingAttribute(p, p.uvName.c_str(), Semantic::TexCoord, p.uvComps, p.uv);
    p.hasColor = readMatchingAttribute(p, "COLOR_0", Semantic::Color, p.colComps, p.col);
    if (p.hasNormal < 0 || p.hasTangent < 0 || p.hasUv < 0 || p.hasColor < 0)
        return false;
    return readPrimitiveOrder(p);
}

bool GltfFlattener::wantsTangents(const PrimitiveRead& p) const {
    if (p.material < 0 || static_cast<std::size_t>(p.material) >= m_model.materials.size())
        return false;
    const tinygltf::NormalTextureInfo& normal =
        m_model.materials[static_cast<std::size_t>(p.material)].normalTexture;
    return normal.index >= 0 && "TEXCOORD_" + str(normal.texCoord) == p.uvName;
}

int GltfFlattener::readMatchingAttribute(PrimitiveRead& p, const char* attr, Semantic sem,
                                         int& comps, std::vector<float>& values) {
    const auto it = p.prim.attributes.find(attr);
    if (it == p.prim.attributes.end())
        return 0;
    if (!readAccessor(it->second, sem, comps, values))
        return -1;
    if (values.size() / static_cast<std::size_t>(comps) != p.vertexCount) {
        fail(p.where + ": " + attr + " has " +
             str(values.size() / static_cast<std::size_t>(comps)) + " elements but POSITION " +
             str(p.vertexCount));
        return -1;
    }
    return 1;
}

/** The indices, checked against the vertices; without them, the vertices in order. */
bool GltfFlattener::readPrimitiveOrder(PrimitiveRead& p) {
    if (p.prim.indices >= 0) {
        int one = 0;
        if (!readAccessor(p.prim.indices, Semantic::Indices, one, p.order))
            return false;
        for (std::uint32_t i : p.order)
            if (i >= p.vertexCount)
                return fail(p.where + ": index " + str(i) + " is out of range (the primitive has " +
                            str(p.vertexCount) + " vertices)");
    } else {
        p.order.resize(p.vertexCount);
        for (std::size_t i = 0; i < p.vertexCount; ++i)
            p.order[i] = static_cast<std::uint32_t>(i);
    }
    return true;
}

/** p.order as a triangle list in p.tris (strips and fans unrolled); may leave it empty. */
void GltfFlattener::triangulate(PrimitiveRead& p) {
    const std::vector<std::uint32_t>& order = p.order;
    const std::size_t n = order.size();
    if (p.mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3 != 0)
            warnOnce("incomplete triangles at the end of a primitive were dropped");
        p.tris = std::move(p.order); // the list itself: a 10M-triangle file holds 120 MB of it
        p.tris.resize(n - n % 3);
    } else if (n >= 3) {
        p.tris.reserve((n - 2) * 3);
        for (std::size_t i = 0; i + 2 < n; ++i) {
            if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) // glTF 2.0 §3.7.2.1: keeps the winding
                p.tris.insert(p.tris.end(), {order[i], order[i + 1 + i % 2], order[i + 2 - i % 2]});
            else
                p.tris.insert(p.tris.end(), {order[i + 1], order[i + 2], order[0]});
        }
    }
}

namespace {

/**
 * A TANGENT (x, y, z, w) under the node's transform: the direction as positions move, w times
 * handedness; w = 0 (tangent not given) where it is not a usable direction.
 */
glm::vec4 placedTangent(const glm::dmat4& transform, const float* tangent, float handedness) {
    const glm::dvec3 t = glm::dmat3(transform) * glm::dvec3(tangent[0], tangent[1], tangent[2]);
    const double length = glm::length(t);
    if (!(length > 1e-12) || !std::isfinite(length) || tangent[3] == 0.0f)
        return glm::vec4(0.0f);
    return glm::vec4(glm::vec3(t / length), tangent[3] < 0.0f ? -handedness : handedness);
}

} // namespace

/** The used vertices (remap) under the node's transform; the read attributes are freed. */
bool GltfFlattener::appendVertices(PrimitiveRead& p, const std::vector<std::uint32_t>& remap) {
    const glm::dmat4& transform = p.inst.transform;
    const glm::dmat3 normalMatrix = glm::inverseTranspose(glm::dmat3(transform));
    const auto base = static_cast<std::uint32_t>(m_mesh.positions.size());
    const std::vector<float>&pos = p.pos, &nrm = p.nrm, &tan = p.tan, &uv = p.uv, &col = p.col;
    // UVs, tangents and colours only from the first primitive that has them on (earlier vertices
    // get the defaults then): a file without colours holds no white per vertex while it loads.
    const bool keepUvs = m_anyUv || p.hasUv, keepColors = m_anyColor || p.hasColor;
    const bool keepTangents = m_anyTangent || p.hasTangent;
    if (keepUvs)
        m_mesh.uvs.resize(base, glm::vec2(0.0f));
    if (keepTangents)
        m_mesh.tangents.resize(base, glm::vec4(0.0f));
    if (keepColors)
        m_mesh.colors.resize(base, glm::vec4(1.0f));
    // A mirroring transform turns the bitangent the other way (glTF's TANGENT.w).
    const float handedness = glm::determinant(glm::dmat3(transform)) < 0.0 ? -1.0f : 1.0f;
    for (std::size_t v = 0; v < p.vertexCount; ++v) {
        if (remap[v] == std::numeric_limits<std::uint32_t>::max())
            continue;
        glm::vec3 pf;
        if (!toFloat(
                glm::dvec3(transform * glm::dvec4(pos[v * 3], pos[v * 3 + 1], pos[v * 3 + 2], 1.0)),
                pf))
            return fail(p.where + ": a vertex position is not finite after the node transform");
        m_mesh.positions.push_back(pf);
        m_mesh.normals.push_back(
            p.hasNormal
                ? unitNormal(normalMatrix * glm::dvec3(nrm[v * 3], nrm[v * 3 + 1], nrm[v * 3 + 2]))
                : glm::vec3(0.0f));
        m_hasNormal.push_back(p.hasNormal ? 1 : 0);
        if (keepTangents)
            m_mesh.tangents.push_back(
                p.hasTangent ? placedTangent(transform, &tan[v * 4], handedness) : glm::vec4(0.0f));
        glm::vec2 t(0.0f);
        if (p.hasUv) {
            t = glm::vec2(uv[v * 2], uv[v * 2 + 1]);
            if (p.uvTransform && p.uvTransform->present)
                t = p.uvTransform->apply(t);
        }
        if (keepUvs)
            m_mesh.uvs.push_back(t);
        glm::vec4 c(1.0f);
        if (p.hasColor)
            for (int k = 0; k < p.colComps; ++k)
                c[k] = col[v * static_cast<std::size_t>(p.colComps) + static_cast<std::size_t>(k)];
        if (keepColors)
            m_mesh.colors.push_back(c);
    }
    m_anyUv = keepUvs;
    m_anyTangent = keepTangents;
    m_anyColor = keepColors;
    // The attributes are in the mesh now; the triangles follow.
    for (std::vector<float>* read : {&p.pos, &p.nrm, &p.tan, &p.uv, &p.col})
        std::vector<float>().swap(*read);
    return true;
}

/** p's triangles over the vertices appended from base, with their material. */
bool GltfFlattener::appendTriangles(const PrimitiveRead& p, const std::vector<std::uint32_t>& remap,
                                    std::uint32_t base) {
    const int material = p.material;
    if (material >= 0 && static_cast<std::size_t>(material) >= m_model.materials.size())
        return fail(p.where + " uses material " + str(material) + ", which does not exist");
    const bool mirrored = glm::determinant(glm::dmat3(p.inst.transform)) < 0.0;
    // Primitives without a material get the default one, appended after the file's.
    const auto matIndex =
        static_cast<std::uint32_t>(material >= 0 ? material : m_model.materials.size());
    const std::vector<std::uint32_t>& tris = p.tris;
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

} // namespace core::detail::gltf
