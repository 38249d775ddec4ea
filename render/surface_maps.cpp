// SPDX-License-Identifier: GPL-3.0-or-later
#include "render/surface_maps.h"

#include <algorithm>
#include <cmath>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

namespace render {

namespace {

constexpr GLuint kNormalUnit = 2, kOcclusionUnit = 3, kEmissiveUnit = 4;

/** The map of a mesh texture, or none where the mesh lacks it. */
SurfaceMap mapOf(std::span<const core::Image> textures, const core::MaterialMap& map) {
    if (map.texture < 0 || std::size_t(map.texture) >= textures.size() ||
        textures[std::size_t(map.texture)].empty())
        return {};
    return {map.texture, map.uvTransform};
}

/**
 * How the map's u and v axes lie in the mesh uvs' tangent frame (tangent, bitangent), the
 * bitangent pointing up the image as glTF's normal maps have it: the inverse of the placement's
 * linear part, with v turned over on both sides.
 */
glm::mat2 mapAxes(const glm::mat3& uvTransform) {
    const glm::mat2 linear(uvTransform);
    if (!(std::abs(glm::determinant(linear)) > 1e-12f))
        return glm::mat2(1.0f);
    glm::mat2 axes = glm::inverse(linear);
    axes[0][1] = -axes[0][1];
    axes[1][0] = -axes[1][0];
    return axes;
}

/**
 * How many mip levels finer or coarser than the base colour texture the map is sampled, from
 * its size and the placement's scale (composite.frag adds it to the base colour's LOD).
 */
float lodBias(const SurfaceMap& map, const MaterialTextures& textures, int baseWidth,
              int baseHeight) {
    const PaintTexture* texture = textures.baseColor(std::size_t(map.texture));
    if (!texture || baseWidth <= 0 || baseHeight <= 0)
        return 0.0f;
    const glm::mat2 linear(map.uvTransform);
    const float scale = std::max(glm::length(linear[0]), glm::length(linear[1]));
    const float ratio = std::max(float(texture->width()) / float(baseWidth),
                                 float(texture->height()) / float(baseHeight)) *
                        scale;
    return ratio > 0.0f && std::isfinite(ratio) ? std::log2(ratio) : 0.0f;
}

/** Binds a map to its unit and sets its placement and LOD bias uniforms. */
void bindMap(const ShaderProgram& program, const SurfaceMap& map, GLuint unit, unsigned texture,
             const char* sampler, const char* transform, const char* bias, float lod) {
    glBindTextureUnit(unit, texture);
    glUniform1i(program.uniform(sampler), GLint(unit));
    glUniformMatrix3fv(program.uniform(transform), 1, GL_FALSE, glm::value_ptr(map.uvTransform));
    glUniform1f(program.uniform(bias), lod);
}

} // namespace

SurfaceMaps SurfaceMaps::of(std::span<const core::Image> textures, bool hasUvs,
                            const core::Material& material) {
    SurfaceMaps maps;
    if (material.baseColorTexture < 0)
        return maps;
    if (hasUvs)
        maps.normal = mapOf(textures, material.normal);
    maps.occlusion = mapOf(textures, material.occlusion);
    maps.emissive = mapOf(textures, material.emissive);
    maps.normalScale = std::isfinite(material.normalScale) ? material.normalScale : 1.0f;
    maps.occlusionStrength = std::isfinite(material.occlusionStrength)
                                 ? std::clamp(material.occlusionStrength, 0.0f, 1.0f)
                                 : 1.0f;
    const glm::vec3 emission = material.emissiveFactor * material.emissiveStrength;
    if (std::isfinite(emission.x) && std::isfinite(emission.y) && std::isfinite(emission.z))
        maps.emission = glm::max(emission, glm::vec3(0.0f));
    if (maps.emission == glm::vec3(0.0f))
        maps.emissive = {}; // a map times zero emits nothing
    return maps;
}

unsigned SurfaceMaps::features() const {
    unsigned bits = 0;
    if (normal.texture >= 0)
        bits |= kSurfaceNormalMap;
    if (occlusion.texture >= 0)
        bits |= kSurfaceOcclusionMap;
    if (emission != glm::vec3(0.0f))
        bits |= kSurfaceEmissive;
    if (emissive.texture >= 0)
        bits |= kSurfaceEmissiveMap;
    return bits;
}

std::vector<std::string> surfaceDefines(unsigned features) {
    std::vector<std::string> defines;
    if (features & kSurfaceNormalMap)
        defines.emplace_back("NORMAL_MAP");
    if (features & kSurfaceOcclusionMap)
        defines.emplace_back("OCCLUSION_MAP");
    if (features & kSurfaceEmissive)
        defines.emplace_back("EMISSIVE");
    if (features & kSurfaceEmissiveMap)
        defines.emplace_back("EMISSIVE_MAP");
    return defines;
}

void bindSurfaceMaps(const ShaderProgram& program, const SurfaceMaps& maps, unsigned features,
                     const MaterialTextures& textures, int baseWidth, int baseHeight) {
    if (features & kSurfaceNormalMap) {
        bindMap(program, maps.normal, kNormalUnit,
                textures.linearView(std::size_t(maps.normal.texture)), "uNormalMap",
                "uNormalTransform", "uNormalLodBias",
                lodBias(maps.normal, textures, baseWidth, baseHeight));
        const glm::mat2 axes = mapAxes(maps.normal.uvTransform);
        glUniformMatrix2fv(program.uniform("uNormalAxes"), 1, GL_FALSE, glm::value_ptr(axes));
        glUniform1f(program.uniform("uNormalScale"), maps.normalScale);
    }
    if (features & kSurfaceOcclusionMap) {
        bindMap(program, maps.occlusion, kOcclusionUnit,
                textures.linearView(std::size_t(maps.occlusion.texture)), "uOcclusionMap",
                "uOcclusionTransform", "uOcclusionLodBias",
                lodBias(maps.occlusion, textures, baseWidth, baseHeight));
        glUniform1f(program.uniform("uOcclusionStrength"), maps.occlusionStrength);
    }
    if (features & kSurfaceEmissive)
        glUniform3fv(program.uniform("uEmission"), 1, glm::value_ptr(maps.emission));
    if (features & kSurfaceEmissiveMap) {
        const PaintTexture* texture = textures.baseColor(std::size_t(maps.emissive.texture));
        bindMap(program, maps.emissive, kEmissiveUnit, texture ? texture->id() : 0u, "uEmissiveMap",
                "uEmissiveTransform", "uEmissiveLodBias",
                lodBias(maps.emissive, textures, baseWidth, baseHeight));
    }
}

void unbindSurfaceMaps() {
    for (GLuint unit : {kNormalUnit, kOcclusionUnit, kEmissiveUnit})
        glBindTextureUnit(unit, 0);
}

} // namespace render
