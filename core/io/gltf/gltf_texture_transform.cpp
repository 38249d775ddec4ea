// SPDX-License-Identifier: GPL-3.0-or-later
// KHR_texture_transform (see gltf_texture_transform.h).
#include "core/io/gltf/gltf_texture_transform.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include <glm/matrix.hpp>

#include "core/io/gltf/gltf_accessors.h"

namespace core::detail::gltf {

using Json = nlohmann::json;

namespace {

bool finiteNumber(const Json& v, double& out) {
    if (!v.is_number())
        return false;
    out = v.get<double>();
    return std::isfinite(out);
}

bool pair(const Json& ext, const char* key, double& a, double& b) {
    const auto it = ext.find(key);
    if (it == ext.end())
        return true;
    return it->is_array() && it->size() == 2 && finiteNumber((*it)[0], a) &&
           finiteNumber((*it)[1], b);
}

bool index(const Json& v, int& out) {
    if (!v.is_number_unsigned() || v.get<std::uint64_t>() > kMaxIndex)
        return false;
    out = v.get<int>();
    return true;
}

} // namespace

glm::vec2 TextureTransform::apply(glm::vec2 uv) const {
    const glm::dvec3 t = matrix * glm::dvec3(uv.x, uv.y, 1.0);
    return {static_cast<float>(t.x), static_cast<float>(t.y)};
}

Result<TextureTransform> readTextureTransform(const Json& textureInfo, const std::string& where) {
    TextureTransform out;
    if (const auto tc = textureInfo.find("texCoord"); tc != textureInfo.end())
        if (!index(*tc, out.texCoord))
            return Error{where + ".texCoord must be a non-negative integer", ErrorKind::BadInput};
    const auto exts = textureInfo.find("extensions");
    if (exts == textureInfo.end() || !exts->is_object())
        return out;
    const auto ext = exts->find("KHR_texture_transform");
    if (ext == exts->end() || !ext->is_object())
        return out;
    const std::string at = where + ".extensions.KHR_texture_transform";
    double ox = 0.0, oy = 0.0, sx = 1.0, sy = 1.0, r = 0.0;
    if (!pair(*ext, "offset", ox, oy))
        return Error{at + ".offset must be two finite numbers", ErrorKind::BadInput};
    if (!pair(*ext, "scale", sx, sy))
        return Error{at + ".scale must be two finite numbers", ErrorKind::BadInput};
    if (const auto it = ext->find("rotation"); it != ext->end() && !finiteNumber(*it, r))
        return Error{at + ".rotation must be a finite number", ErrorKind::BadInput};
    if (const auto it = ext->find("texCoord"); it != ext->end() && !index(*it, out.texCoord))
        return Error{at + ".texCoord must be a non-negative integer", ErrorKind::BadInput};
    // translation * rotation * scale with u' = cos·u + sin·v, v' = −sin·u + cos·v: the matrix
    // the extension's own example needs (offset [0, 1], rotation π/2, scale 0.5 maps [0,1]² onto
    // the lower left quarter of the image, v down) and the one common viewers use; the GLSL
    // listing beside it reads as its transpose.
    const double c = std::cos(r), s = std::sin(r);
    const glm::dmat3 translation(1, 0, 0, 0, 1, 0, ox, oy, 1);
    const glm::dmat3 rotation(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::dmat3 scale(sx, 0, 0, 0, sy, 0, 0, 0, 1);
    out.matrix = translation * rotation * scale;
    out.present = true;
    return out;
}

namespace {

struct MapInfo {
    const char* key;  // the textureInfo's key
    bool inPbr;       // under pbrMetallicRoughness, else on the material
    const char* name; // for messages
};
constexpr std::array<MapInfo, kMapSlots> kMaps = {{
    {"metallicRoughnessTexture", true, "metallic-roughness"},
    {"normalTexture", false, "normal"},
    {"occlusionTexture", false, "occlusion"},
    {"emissiveTexture", false, "emissive"},
}};

/** One material's textures: the transform of each that is there (else nothing). */
struct MaterialTextures {
    std::optional<TextureTransform> base;
    std::array<std::optional<TextureTransform>, kMapSlots> maps;
};

Result<MaterialTextures> readTextures(const Json& material, std::size_t index) {
    MaterialTextures out;
    const std::string where = "materials[" + str(index) + "]";
    const auto read = [&](const Json& owner, const char* key, const std::string& at,
                          std::optional<TextureTransform>& into) -> Status {
        const auto info = owner.find(key);
        if (info == owner.end())
            return {};
        Result<TextureTransform> r = readTextureTransform(*info, at + "." + key);
        if (!r)
            return r.takeError();
        into = *r;
        return {};
    };
    const Json pbr = material.value("pbrMetallicRoughness", Json::object());
    const std::string pbrAt = where + ".pbrMetallicRoughness";
    if (Status s = read(pbr, "baseColorTexture", pbrAt, out.base); !s)
        return s.takeError();
    for (std::size_t m = 0; m < kMapSlots; ++m)
        if (Status s = read(kMaps[m].inPbr ? pbr : material, kMaps[m].key,
                            kMaps[m].inPbr ? pbrAt : where, out.maps[m]);
            !s)
            return s.takeError();
    return out;
}

glm::mat3 relativeTo(const glm::dmat3& map, const glm::dmat3& uvs) {
    // A placement that collapses the texture has no inverse: the map keeps its own.
    if (std::abs(glm::determinant(uvs)) < 1e-12)
        return glm::mat3(map);
    return glm::mat3(map * glm::inverse(uvs));
}

} // namespace

Result<MaterialTransforms> readMaterialTransforms(const Json& root) {
    MaterialTransforms out;
    const auto materials = root.find("materials");
    if (materials == root.end())
        return out;
    for (std::size_t i = 0; i < materials->size(); ++i) {
        const Json& material = (*materials)[i];
        Result<MaterialTextures> textures = readTextures(material, i);
        if (!textures)
            return textures.takeError();
        // The mesh's UVs carry the base colour's placement, else the first map's.
        TextureTransform uvs = textures->base.value_or(TextureTransform{});
        if (!textures->base)
            for (const std::optional<TextureTransform>& map : textures->maps)
                if (map) {
                    uvs = *map;
                    break;
                }
        const Json name = material.value("name", Json());
        const std::string label = name.is_string() && !name.get<std::string>().empty()
                                      ? name.get<std::string>()
                                      : "material " + str(i);
        std::array<glm::mat3, kMapSlots> maps;
        maps.fill(glm::mat3(1.0f));
        for (std::size_t m = 0; m < kMapSlots; ++m) {
            const std::optional<TextureTransform>& map = textures->maps[m];
            if (!map)
                continue;
            maps[m] = relativeTo(map->matrix, uvs.matrix);
            if (map->texCoord != uvs.texCoord)
                out.warnings.push_back("material \"" + label + "\": its " + kMaps[m].name +
                                       " map uses TEXCOORD_" + str(map->texCoord) +
                                       ", which is not loaded; it is placed on TEXCOORD_" +
                                       str(uvs.texCoord) + " instead");
        }
        out.transforms.push_back(uvs);
        out.maps.push_back(maps);
    }
    return out;
}

} // namespace core::detail::gltf
