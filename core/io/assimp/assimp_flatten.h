// SPDX-License-Identifier: GPL-3.0-or-later
// core/io/assimp/: the other model formats, through Assimp: prechecks, file access and
// flattening.
//
// From Assimp's scene to one Mesh. Assimp reads with no post-processing first; checkRawScene()
// then checks every face index, bone weight and morph mesh that the post-processing steps read
// (instead of aiProcess_ValidateDataStructure, which rejects whole files for harmless defects).
// flattenAssimp() applies node transforms, nodes depth-first and meshes in node order, and
// converts UVs (to glTF's: origin top-left, v down), vertex colours (sRGB-encoded, to linear),
// materials and their textures (a legacy diffuse colour does not tint a diffuse texture).
#pragma once

#include <filesystem>

#include <assimp/scene.h>

#include "core/base/result.h"
#include "core/io/mesh_io.h"
#include "core/model/mesh.h"

namespace core::detail::assimp {

/**
 * What the post-processing steps read, checked before they run. Also sets each mesh's primitive
 * types from its faces: Triangulate asserts (and Debian's Assimp aborts) when an importer
 * declared them wrongly.
 */
Status checkRawScene(const aiScene& scene, const LoadLimits& limits);

/** scene (post-processed) as a Mesh; textures are read inside folder. No file named. */
Result<Mesh> flattenAssimp(const aiScene& scene, const std::filesystem::path& folder,
                           const LoadLimits& limits);

} // namespace core::detail::assimp
