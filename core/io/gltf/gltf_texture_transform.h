// SPDX-License-Identifier: GPL-3.0-or-later
// KHR_texture_transform on a glTF textureInfo: the affine map of texture coordinates it stands
// for (offset, rotation, scale) and the texture coordinate set it may select instead.
#pragma once

#include <array>
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

/** The maps of a material besides the base colour, in the order of Material's fields. */
enum class MapSlot { MetallicRoughness, Normal, Occlusion, Emissive };
inline constexpr std::size_t kMapSlots = 4;

/** Per material of a glTF file, where its textures lie. */
struct MaterialTransforms {
    /**
     * Per entry of the file's materials: the placement the mesh's UVs take (the base colour
     * texture's, or for a material without one its first map's) and its texture coordinate set.
     */
    std::vector<TextureTransform> transforms;
    /** Per material and MapSlot: the map's placement relative to the mesh's UVs. */
    std::vector<std::array<glm::mat3, kMapSlots>> maps;
    std::vector<std::string> warnings;
};

/**
 * The placements of root's materials' textures. A map's transform is T_map · T_uvs⁻¹; a map on
 * another texture coordinate set than the one the mesh's UVs come from keeps that relation on
 * the mesh's UVs, with a warning naming the material and the map.
 */
Result<MaterialTransforms> readMaterialTransforms(const nlohmann::json& root);

} // namespace core::detail::gltf
