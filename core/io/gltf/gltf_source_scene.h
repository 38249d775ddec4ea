// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "core/io/gltf/gltf_file_access.h"
#include "core/model/mesh.h"
#include "core/model/source_scene.h"

namespace core::detail::gltf {

/**
 * Completes scene (its runs as flattenGltf() gave them) with the glTF file as loaded (json the
 * file's own JSON, jsonBytes its length, model its buffers as tinygltf read them, taken from it;
 * access the image files it collected), for writing it back: every buffer merged into one and
 * every image moved into a buffer view of it, and the hashes of mesh's uvs and colours. A scene
 * whose buffers are compressed with EXT_meshopt_compression (meshopt, as gltf::Extensions says;
 * their fallback buffers hold no data), whose JSON text exceeds 16 MiB or that does not fit
 * into one binary glTF is not kept (scene.notKept says why; its runs are dropped).
 */
void keepScene(const nlohmann::json& json, std::uint64_t jsonBytes, bool meshopt,
               tinygltf::Model& model, const FileAccess& access, const Mesh& mesh,
               SourceScene& scene);

} // namespace core::detail::gltf
