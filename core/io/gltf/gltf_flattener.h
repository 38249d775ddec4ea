// SPDX-License-Identifier: GPL-3.0-or-later
// The glTF flattener's class, shared by its files: gltf_flatten.cpp walks the scene and reads the
// materials, gltf_flatten_primitive.cpp reads each primitive's accessors (or Draco data) and
// appends its vertices and triangles. Internal to flattenGltf() (gltf_flatten.h).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/base/progress.h"
#include "core/io/gltf/gltf_accessors.h"
#include "core/io/gltf/gltf_file_access.h"
#include "core/io/gltf/gltf_texture_transform.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/mesh_io.h"
#include "core/model/source_scene.h"

namespace core::detail::gltf {

/** A mesh placed by a node (node -1: a file without nodes). */
struct GltfInstance {
    int mesh = -1;
    int node = -1;
    glm::dmat4 transform{1.0};
};

/** One primitive while it is read: what it is, then its attributes as the file holds them. */
struct PrimitiveRead {
    PrimitiveRead(const GltfInstance& instance, std::size_t index,
                  const tinygltf::Primitive& primitive, std::string whereText)
        : inst(instance), primIndex(index), prim(primitive), where(std::move(whereText)) {}

    const GltfInstance& inst;
    std::size_t primIndex = 0;
    const tinygltf::Primitive& prim;
    std::string where; // "mesh M primitive P", for messages
    int mode = 0;
    int positionAccessor = -1;
    int material = -1;
    const TextureTransform* uvTransform = nullptr; // the material's, if it has one
    std::string uvName;                            // the TEXCOORD_n the material's texture uses

    std::vector<float> pos, nrm, tan, uv, col;
    int nrmComps = 3, tanComps = 4, uvComps = 2, colComps = 0;
    std::vector<std::uint32_t> order; // the triangles' vertex order before strips and fans
    std::size_t vertexCount = 0;
    int hasNormal = 0, hasTangent = 0, hasUv = 0, hasColor = 0;
    std::vector<std::uint32_t> tris; // local vertex indices, 3 per triangle
};

class GltfFlattener : public Flattener {
public:
    GltfFlattener(const tinygltf::Model& model, const nlohmann::json& json,
                  const FileAccess& access, bool quantized, const ProgressFn& progress,
                  const LoadLimits& limits)
        : m_model(model), m_json(json), m_access(access), m_progress(progress), m_limits(limits),
          m_quantized(quantized) {}

    /** Flattens into out; false with error() on failure. */
    bool run(Mesh& out);
    /** Where each run of the flattened triangles came from (see SourceScene). */
    std::vector<SourcePrimitive>& sourcePrimitives() { return m_sourcePrimitives; }
    std::vector<std::uint32_t>& usedVertices() { return m_usedVertices; }

private:
    const tinygltf::Model& m_model;
    const nlohmann::json& m_json;
    const FileAccess& m_access;
    const ProgressFn& m_progress;
    const LoadLimits& m_limits;
    bool m_quantized;
    std::size_t m_skippedPrimitives = 0;
    std::map<int, int> m_imageToTexture; // glTF image -> Mesh::textures index (-1: failed)
    std::vector<SourcePrimitive> m_sourcePrimitives;
    std::vector<std::uint32_t> m_usedVertices;
    // Per glTF material: the placement of the mesh's UVs (its base colour texture's
    // KHR_texture_transform and coordinate set), applied to the UVs of the primitives using it,
    // and its other maps' placements relative to them.
    std::vector<TextureTransform> m_uvTransforms;
    std::vector<std::array<glm::mat3, kMapSlots>> m_mapTransforms;

    // The scene (gltf_flatten.cpp).
    bool collectInstances(std::vector<GltfInstance>& instances);
    bool localTransform(int nodeIndex, glm::dmat4& out);
    bool viewBytes(int viewIndex, const std::string& user, const std::uint8_t*& data,
                   std::uint64_t& length);
    /** Room in the mesh for every primitive of instances, at most the limits. */
    void reserveForInstances(const std::vector<GltfInstance>& instances);
    bool addMaterials();
    /** Material i's factors, alpha and base colour (its texture through textureFor). */
    bool readMaterial(std::size_t i, Material& mat);
    /** Material i's maps other than the base colour, after every base colour texture. */
    bool readMaterialMaps(std::size_t i, Material& mat);
    int textureFor(int textureIndex, int texCoord, const std::string& materialName);

    // One primitive (gltf_flatten_primitive.cpp).
    /** Float attributes or uint32 indices; normalized integers are converted (§3.11). */
    template <typename T>
    bool readAccessor(int accessorIndex, Semantic semantic, int& components, std::vector<T>& out);
    template <typename T>
    bool applySparse(const tinygltf::Accessor& acc, const std::string& name, std::size_t nc,
                     std::vector<T>& out);
    bool addPrimitive(const GltfInstance& inst, std::size_t primIndex);
    /** What becomes of a primitive before anything of it is read. */
    enum class Screening { Read, Skip, Fail };
    Screening screenPrimitive(PrimitiveRead& p);
    /** The primitive's KHR_draco_mesh_compression object in the JSON, or nullptr. */
    const nlohmann::json* dracoExtension(int mesh, std::size_t primIndex) const;
    bool readDracoPrimitive(PrimitiveRead& p, const nlohmann::json& ext);
    bool decodeDracoPrimitive(PrimitiveRead& p, const nlohmann::json& ext);
    bool readAccessorPrimitive(PrimitiveRead& p);
    /** Whether p's TANGENT is read: its material draws a normal map over p's uvs. */
    bool wantsTangents(const PrimitiveRead& p) const;
    /** 1 if the attribute is there and matches POSITION, 0 if absent, -1 on failure. */
    int readMatchingAttribute(PrimitiveRead& p, const char* attr, Semantic sem, int& comps,
                              std::vector<float>& values);
    bool readPrimitiveOrder(PrimitiveRead& p);
    void triangulate(PrimitiveRead& p);
    bool appendVertices(PrimitiveRead& p, const std::vector<std::uint32_t>& remap);
    bool appendTriangles(const PrimitiveRead& p, const std::vector<std::uint32_t>& remap,
                         std::uint32_t base);
    /** Records where the run just appended came from. */
    void recordSource(const PrimitiveRead& p, const UsedVertices& used, bool draco,
                      std::uint32_t firstTriangle, std::uint32_t firstVertex);
};

} // namespace core::detail::gltf
