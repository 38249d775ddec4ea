// SPDX-License-Identifier: GPL-3.0-or-later
// The checks a glTF file's JSON goes through before tinygltf sees it: the types the glTF 2.0
// schema gives its properties (tinygltf silently ignores properties of the wrong type, so
// "index": -1 or "primitives": {} would otherwise load as something else), the buffer views that
// images use, and the extensions the file requires.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/result.h"

namespace core::detail::gltf {

/** The first property of root whose type is not the schema's, as an Error (BadInput). */
Status checkSchema(const nlohmann::json& root);

/**
 * Buffer views that images use, against the buffers' declared lengths. tinygltf makes every
 * buffer exactly that long (or refuses) but computes image pointers from these views before
 * anything else could check them. Other views are checked when an accessor uses them.
 */
Status checkImageViews(const nlohmann::json& root);

/** What the extensions a file uses mean for loading it. */
struct Extensions {
    bool quantized = false;            // KHR_mesh_quantization: integer attributes allowed
    bool meshopt = false;              // EXT_ or KHR_meshopt_compression is used
    std::vector<std::string> warnings; // required extensions that are ignored
};

/**
 * extensionsRequired: KHR_mesh_quantization, KHR_draco_mesh_compression, EXT_meshopt_compression
 * (and KHR_meshopt_compression) and KHR_texture_transform are supported; shading-only
 * extensions cannot change what is painted on, so they are ignored with a warning; anything else
 * fails the load (Unsupported), as glTF requires.
 */
Result<Extensions> checkExtensions(const nlohmann::json& root);

} // namespace core::detail::gltf
