// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace render {

/**
 * Which material channel the shaded views show (the compositor's Composite and SingleLayer,
 * the mesh renderer). Material lights base colour with the
 * metallic-roughness textures of MaterialTextures::setMetallicRoughness() (GGX specular from a key,
 * fill and rim light and a sky-and-ground environment that metal reflects); fragments without one
 * shade as roughness 1, metal 0, which is the plain headlight shading. The others show one channel
 * unlit: the base colour, or roughness or metallic as grey (the texel's byte as the grey level).
 */
enum class MaterialChannel { Material, BaseColor, Roughness, Metallic };

} // namespace render
