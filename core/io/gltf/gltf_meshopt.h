// SPDX-License-Identifier: GPL-3.0-or-later
// EXT_meshopt_compression (and KHR_meshopt_compression, the same layout): buffer views whose
// bytes are compressed with meshoptimizer's codecs, decoded before the scene is flattened. Runs
// only where the other glTF parsers run (the importer process, the fuzz targets).
#pragma once

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/base/result.h"
#include "core/io/mesh_io.h"

namespace core::detail::gltf {

/**
 * The extension's fallback buffers may have no data at all (no uri, or a GLB's BIN chunk shorter
 * than they claim); tinygltf would refuse them. Each such buffer becomes a one-byte placeholder
 * in json, since only compressed views point into it. Returns whether json changed.
 */
bool replaceFallbackBuffers(nlohmann::json& json);

/**
 * Decodes every buffer view of json (the file's JSON, matching model) that carries the
 * extension: the compressed bytes (mode ATTRIBUTES, TRIANGLES or INDICES, filter NONE,
 * OCTAHEDRAL, QUATERNION or EXPONENTIAL) become a new buffer of model the view then points at.
 * Fails (BadInput) on malformed extension objects, ranges outside the source buffer, a decoded
 * size other than the view's byteLength, and data the decoder refuses; the Error names no file.
 */
Status decodeMeshoptViews(tinygltf::Model& model, const nlohmann::json& json,
                          const LoadLimits& limits);

} // namespace core::detail::gltf
