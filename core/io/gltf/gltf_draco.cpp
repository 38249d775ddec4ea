// SPDX-License-Identifier: GPL-3.0-or-later
// KHR_draco_mesh_compression decoding (see gltf_draco.h).
#include "core/io/gltf/gltf_draco.h"

#include <cmath>
#include <memory>

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include "core/io/gltf/gltf_accessors.h"

namespace core::detail::gltf {

namespace {

/** One attribute into out (components per point); false with why on failure. */
bool readAttribute(const draco::Mesh& mesh, const std::string& name, std::uint32_t id,
                   int minComponents, int maxComponents, std::vector<float>& out, int& components,
                   std::string& why) {
    const draco::PointAttribute* att = mesh.GetAttributeByUniqueId(id);
    if (att == nullptr) {
        why = "the Draco data has no attribute " + str(id) + " for " + name;
        return false;
    }
    components = att->num_components();
    if (components < minComponents || components > maxComponents) {
        why = "the Draco attribute for " + name + " has " + str(static_cast<unsigned>(components)) +
              " components";
        return false;
    }
    const std::size_t points = mesh.num_points();
    const auto nc = static_cast<std::size_t>(components);
    out.assign(points * nc, 0.0f);
    for (std::size_t p = 0; p < points; ++p) {
        const draco::AttributeValueIndex v =
            att->mapped_index(draco::PointIndex(static_cast<std::uint32_t>(p)));
        if (v.value() >= att->size() ||
            !att->ConvertValue<float>(v, static_cast<std::int8_t>(components), &out[p * nc])) {
            why = "the Draco attribute for " + name + " cannot be read";
            return false;
        }
        for (std::size_t c = 0; c < nc; ++c)
            if (!std::isfinite(out[p * nc + c])) {
                why = "the Draco attribute for " + name + " holds a value that is not finite";
                return false;
            }
    }
    return true;
}

} // namespace

bool dropDracoIndices(nlohmann::json& json) {
    const auto meshes = json.find("meshes");
    if (meshes == json.end() || !meshes->is_array())
        return false;
    bool changed = false;
    for (auto& mesh : *meshes) {
        const auto prims = mesh.find("primitives");
        if (prims == mesh.end() || !prims->is_array())
            continue;
        for (auto& prim : *prims) {
            const auto exts = prim.find("extensions");
            if (exts != prim.end() && exts->contains("KHR_draco_mesh_compression") &&
                prim.erase("indices") > 0)
                changed = true;
        }
    }
    return changed;
}

Result<DracoPrimitive> decodeDraco(const std::uint8_t* data, std::size_t size,
                                   const std::map<std::string, std::uint32_t>& attributeIds,
                                   const std::string& uvName, const LoadLimits& limits) {
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(data), size);
    const auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
    if (!type.ok())
        return badInput("the Draco data cannot be decoded (" + type.status().error_msg_string() +
                        ")");
    if (type.value() != draco::TRIANGULAR_MESH)
        return badInput("the Draco data is not a triangle mesh");
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok())
        return badInput("the Draco data cannot be decoded (" + decoded.status().error_msg_string() +
                        ")");
    const std::unique_ptr<draco::Mesh> mesh = std::move(decoded).value();
    if (!mesh)
        return badInput("the Draco data cannot be decoded");

    DracoPrimitive out;
    out.vertexCount = mesh->num_points();
    const std::uint64_t faces = mesh->num_faces();
    if (out.vertexCount == 0 || faces == 0)
        return badInput("the Draco data holds no triangles");
    if (out.vertexCount > limits.maxVertices)
        return badInput("the Draco data has too many vertices (" + str(out.vertexCount) + ")");
    if (faces > limits.maxTriangles)
        return badInput("the Draco data has too many triangles (" + str(faces) + ")");

    std::string why;
    int components = 0;
    const auto pos = attributeIds.find("POSITION");
    if (pos == attributeIds.end())
        return badInput("the Draco extension maps no POSITION attribute");
    if (!readAttribute(*mesh, "POSITION", pos->second, 3, 3, out.positions, components, why))
        return badInput(why);
    if (const auto it = attributeIds.find("NORMAL"); it != attributeIds.end())
        if (!readAttribute(*mesh, "NORMAL", it->second, 3, 3, out.normals, components, why))
            return badInput(why);
    if (const auto it = attributeIds.find(uvName); it != attributeIds.end())
        if (!readAttribute(*mesh, uvName, it->second, 2, 2, out.uvs, components, why))
            return badInput(why);
    if (const auto it = attributeIds.find("COLOR_0"); it != attributeIds.end()) {
        if (!readAttribute(*mesh, "COLOR_0", it->second, 3, 4, out.colors, out.colorComponents,
                           why))
            return badInput(why);
    }

    out.indices.reserve(static_cast<std::size_t>(faces) * 3);
    for (std::uint32_t f = 0; f < faces; ++f) {
        const draco::Mesh::Face& face = mesh->face(draco::FaceIndex(f));
        for (const draco::PointIndex& p : face) {
            if (p.value() >= out.vertexCount)
                return badInput("the Draco data has an index out of range");
            out.indices.push_back(p.value());
        }
    }
    return out;
}

} // namespace core::detail::gltf
