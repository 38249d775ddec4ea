// SPDX-License-Identifier: GPL-3.0-or-later
// KHR_draco_mesh_compression: a primitive's compressed bytes decoded with Google's Draco library
// into plain arrays. Runs only where the other glTF parsers run (the importer process, the fuzz
// targets): the decoder reads untrusted bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/io/mesh_io.h"

namespace core::detail::gltf {

/** A decoded Draco primitive: per-vertex arrays (empty where absent) and triangle indices. */
struct DracoPrimitive {
    std::size_t vertexCount = 0;
    std::vector<float> positions, normals, uvs, colors; // 3, 3, 2 and colorComponents floats
    int colorComponents = 0;
    std::vector<std::uint32_t> indices; // 3 per triangle, each below vertexCount
};

/**
 * Decodes bytes as a Draco mesh and reads the attributes whose glTF names (POSITION, NORMAL,
 * uvName (TEXCOORD_n), COLOR_0) attributeIds maps to Draco unique ids. Values come out as Draco
 * gives them: quantized positions and texture coordinates and octahedral normals are dequantized,
 * normalized integers mapped to [0, 1]. Fails (BadInput) on data Draco cannot decode, point
 * clouds, a missing or mis-shaped attribute, counts beyond limits and values that are not
 * finite; the Error names no file.
 */
/**
 * tinygltf refuses an indices accessor without a buffer view, which is what Draco primitives
 * have. Removes "indices" from the Draco primitives of json (the copy tinygltf parses; the
 * flattener reads them from the file's own JSON). Returns whether json changed.
 */
bool dropDracoIndices(nlohmann::json& json);

Result<DracoPrimitive> decodeDraco(const std::uint8_t* data, std::size_t size,
                                   const std::map<std::string, std::uint32_t>& attributeIds,
                                   const std::string& uvName, const LoadLimits& limits);

} // namespace core::detail::gltf
