// SPDX-License-Identifier: GPL-3.0-or-later
// glTF's alphaMode MASK in the depth layers: where a material's alpha is below its cutoff there
// is no surface, so the capture's fragments there are dropped and what lies behind shows (and is
// painted), as a glTF viewer draws it and the mesh renderer's ALPHA_MASK does.
#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/vec3.hpp>

#include "core/depth/depth_stack.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"

namespace core {

/** Whether some material of mesh has alphaMode MASK. */
bool hasAlphaMask(const Mesh& mesh);

/**
 * The alpha of triangle t at barycentric point b as glTF tests it: the material's base colour
 * factor times its base colour texture (bilinear, repeating) at the mesh's uvs times the vertex
 * colours'.
 */
float surfaceAlpha(const Mesh& mesh, std::uint32_t t, const glm::vec3& b);

/**
 * Drops the fragments of stack (captured in view) whose material has alphaMode MASK and whose
 * alpha there (at the pixel centre) is below the material's cutoff; returns how many. Nothing to
 * do, and no cost, for a mesh without such a material.
 */
std::size_t dropMaskedFragments(DepthStack& stack, const Mesh& mesh, const View& view);

} // namespace core
