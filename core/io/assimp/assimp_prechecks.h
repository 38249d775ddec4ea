// SPDX-License-Identifier: GPL-3.0-or-later
// The checks made before Assimp reads a file. OFF and PLY header counts must fit the file
// (Assimp allocates and loops over them first: a 309-byte OFF file can cost 16 GB and 20 s), and
// an OBJ face statement without vertices is refused (Assimp drops it silently). Each returns the
// problem as an Error (BadInput) naming no file.
#pragma once

#include <cstdint>
#include <filesystem>

#include "core/base/result.h"
#include "core/io/mesh_io.h"

namespace core::detail::assimp {

/** An OBJ face statement without vertices (a truncated or hand-broken file). */
Status checkObjFaces(const std::filesystem::path& file);

/** An OFF file's faces: as many as its header declares, each with its vertex count. */
Status checkOffFaces(const std::filesystem::path& file);

/**
 * OFF and PLY header counts against the file's size: an ASCII value takes at least 2 bytes
 * ("0 "), a binary one its size; a PLY header must end.
 */
Status checkDeclaredCounts(const std::filesystem::path& file, std::uint64_t fileSize,
                           const LoadLimits& limits);

} // namespace core::detail::assimp
