// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/model/mesh.h"

namespace core {

/** Size caps that keep a hostile file from exhausting memory, and how strict loading is. */
struct LoadLimits {
    std::uint64_t maxFileBytes = 2ull << 30; // 2 GiB
    std::uint64_t maxVertices = 50'000'000;
    std::uint64_t maxTriangles = 50'000'000;
    std::uint64_t maxImagePixels = 16384ull * 16384ull;
    /**
     * A glTF base colour texture that cannot be read fails the load instead of being dropped
     * with a warning (a project's textures hold the painting).
     */
    bool requireTextures = false;
};

/**
 * Loads a mesh: "builtin:NAME" (see builtin_models.h), glTF 2.0 (.gltf/.glb) through tinygltf,
 * or any format Assimp reads (OBJ, PLY, STL, OFF, ...). The default scene is flattened with node
 * transforms; points and lines are skipped with a warning.
 *
 * Returns the mesh, or an Error whose message names the file and the problem. Never throws.
 * A cancelled load (progress returned false) returns an Error "…: cancelled".
 */
Result<Mesh> loadMesh(const std::string& path, const ProgressFn& progress = {},
                      const LoadLimits& limits = {});

/** Decodes an image file held in memory (PNG, JPEG, ...) to RGBA8 through OpenImageIO. */
Result<Image> decodeImage(const std::uint8_t* data, std::size_t size, const std::string& name,
                          const LoadLimits& limits = {});

} // namespace core
