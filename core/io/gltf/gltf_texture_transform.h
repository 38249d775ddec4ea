// SPDX-License-Identifier: GPL-3.0-or-later
// KHR_texture_transform on a glTF textureInfo: the affine map of texture coordinates it stands
// for (offset, rotation, scale) and the texture coordinate set it may select instead.
#pragma once

#include <string>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include "core/base/result.h"

namespace core::detail::gltf {

struct TextureTransform {
    /** uv' = (matrix * (u, v, 1)).xy: translation * rotation * scale, as the extension says. */
    glm::dmat3 matrix{1.0};
    bool present = false;
    int texCoord = 0; // the set the texture uses: the extension's override or textureInfo's

    glm::vec2 apply(glm::vec2 uv) const;
    bool operator==(const TextureTransform& o) const {
        return matrix == o.matrix && texCoord == o.texCoord;
    }
};

/**
 * The transform of textureInfo (a JSON object whose types gltf_schema checked; where names it
 * in messages). Offsets, rotation and scale must be finite numbers (BadInput otherwise); no
 * extension gives the identity on textureInfo's texCoord.
 */
Result<TextureTransform> readTextureTransform(const nlohmann::json& textureInfo,
                                              const std::string& where);

/** Per material of a glTF file, the placement of its base color texture. */
struct MaterialTransforms {
    std::vector<TextureTransform> transforms; // one per entry of the file's materials
    std::vector<std::string> warnings;
};

/**
 * The base color textures' transforms of root's materials; a metallic-roughness texture placed
 * otherwise is a warning (its UVs cannot differ: the base color's placement is used).
 */
Result<MaterialTransforms> readMaterialTransforms(const nlohmann::json& root);

} // namespace core::detail::gltf
