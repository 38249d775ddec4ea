// SPDX-License-Identifier: GPL-3.0-or-later
// core/io/gltf/: glTF read (accessors, Draco, meshopt, texture transforms, flattening) and
// written (GLB container, export).
//
// Flattening a parsed glTF scene into one Mesh: the default scene (else scene 0; without any, the
// root nodes or the meshes in order, with a warning) depth-first in document order, each node
// reached once (a cycle or a node with two parents is an error: sharing would let a small file
// instance geometry exponentially); each primitive contributes the vertices its indices
// reference, in their original order; materials and their base colour textures.
#pragma once

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/io/gltf/gltf_file_access.h"
#include "core/io/mesh_io.h"
#include "core/model/mesh.h"
#include "core/model/source_scene.h"

namespace core::detail::gltf {

/**
 * model (as tinygltf parsed it from json) as a Mesh without normals repaired (finishMesh() does
 * that); quantized allows KHR_mesh_quantization's attribute types. Progress goes from 0.5 to 0.9.
 * The Error names no file. Where each run of triangles and vertices came from goes to runs'
 * primitives and usedVertices, if given; Mesh::textureOrigins names each texture's image.
 */
Result<Mesh> flattenGltf(const tinygltf::Model& model, const nlohmann::json& json,
                         const FileAccess& access, bool quantized, const ProgressFn& progress,
                         const LoadLimits& limits, SourceScene* runs = nullptr);

} // namespace core::detail::gltf
