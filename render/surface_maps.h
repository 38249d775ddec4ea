// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <span>
#include <string>
#include <vector>

#include <glm/mat2x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/model/mesh.h"
#include "render/material_textures.h"
#include "render/shader_library.h"

namespace render {

/** What a material's maps add to the lit Material view, as glTF defines them. */
enum SurfaceFeature : unsigned {
    kSurfaceNormalMap = 1u << 0,    // NORMAL_MAP: tangent-space normals (needs uvs and tangents)
    kSurfaceOcclusionMap = 1u << 1, // OCCLUSION_MAP: darkens the ambient light and environment
    kSurfaceEmissive = 1u << 2,     // EMISSIVE: emitted light added after lighting
    kSurfaceEmissiveMap = 1u << 3,  // EMISSIVE_MAP: the emission times an sRGB map
};

/** One map: a mesh texture, placed relative to the mesh's uvs. */
struct SurfaceMap {
    int texture = -1;
    glm::mat3 uvTransform{1.0f};
    bool operator==(const SurfaceMap&) const = default;
};

/**
 * The normal, occlusion and emissive maps of a material with a base colour texture, which both
 * shaded views (mesh.frag and composite.frag, through material_shading.frag) draw in the
 * Material channel. Maps whose texture the mesh lacks (or that is empty) are left out, and so is
 * a normal map on a mesh without uvs.
 */
struct SurfaceMaps {
    SurfaceMap normal, occlusion, emissive;
    float normalScale = 1.0f;
    float occlusionStrength = 1.0f;
    glm::vec3 emission{0.0f}; // emissiveFactor × emissiveStrength, linear

    /** The maps of material among textures, on a mesh with or without uvs. */
    static SurfaceMaps of(std::span<const core::Image> textures, bool hasUvs,
                          const core::Material& material);
    /** SurfaceFeature bits. */
    unsigned features() const;
    bool operator==(const SurfaceMaps&) const = default;
};

/** The shader defines of SurfaceFeature bits. */
std::vector<std::string> surfaceDefines(unsigned features);

/**
 * Sets the current program's uniforms of the maps' features (SurfaceFeature bits, those its
 * variant was built with) and binds those maps to texture units 2-4. baseWidth and baseHeight,
 * the base colour texture's size, give composite.frag the maps' LOD offsets from the base
 * colour's LOD (mesh.frag lets GL choose).
 */
void bindSurfaceMaps(const ShaderProgram& program, const SurfaceMaps& maps, unsigned features,
                     const MaterialTextures& textures, int baseWidth, int baseHeight);

/** Unbinds texture units 2-4. */
void unbindSurfaceMaps();

} // namespace render
