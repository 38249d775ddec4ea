// SPDX-License-Identifier: GPL-3.0-or-later
// KHR_texture_transform (see gltf_texture_transform.h).
#include "core/io/gltf/gltf_texture_transform.h"

#include <cmath>
#include <cstdint>

#include "core/io/gltf/gltf_accessors.h"

namespace core::detail::gltf {

namespace {

using Json = nlohmann::json;

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

Result<MaterialTransforms> readMaterialTransforms(const Json& root) {
    MaterialTransforms out;
    const auto materials = root.find("materials");
    if (materials == root.end())
        return out;
    for (std::size_t i = 0; i < materials->size(); ++i) {
        const Json pbr = (*materials)[i].value("pbrMetallicRoughness", Json::object());
        const std::string where = "materials[" + str(i) + "].pbrMetallicRoughness";
        TextureTransform base;
        const auto baseInfo = pbr.find("baseColorTexture");
        if (baseInfo != pbr.end()) {
            Result<TextureTransform> r =
                readTextureTransform(*baseInfo, where + ".baseColorTexture");
            if (!r)
                return r.takeError();
            base = *r;
        }
        if (const auto t = pbr.find("metallicRoughnessTexture"); t != pbr.end()) {
            Result<TextureTransform> r =
                readTextureTransform(*t, where + ".metallicRoughnessTexture");
            if (!r)
                return r.takeError();
            if (baseInfo != pbr.end() && !(*r == base) && out.warnings.empty())
                out.warnings.push_back(
                    "a material's metallic-roughness texture is placed differently from its base "
                    "color texture; the base color texture's placement is used");
        }
        out.transforms.push_back(base);
    }
    return out;
}

} // namespace core::detail::gltf
