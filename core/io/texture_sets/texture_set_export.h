// SPDX-License-Identifier: GPL-3.0-or-later
// Texture sets written through an export preset: per set, each map of the preset packed from the
// set's channels, padded around the charts, resampled to a chosen size and written as a file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/io/texture_sets/export_preset.h"
#include "core/model/mesh.h"

namespace core {

/**
 * A texture set of a painted mesh (PaintTarget::paintedMesh()): one base colour texture and the
 * materials painted into it, whose other maps and factors give its remaining channels.
 */
struct TextureSet {
    std::string name; // its first material's name (unique among the sets)
    int texture = -1; // the base colour texture in the mesh
    int width = 0, height = 0;
    std::vector<std::size_t> materials;
};

/** The texture sets of mesh in texture order; none when no material has a base colour texture. */
std::vector<TextureSet> textureSets(const Mesh& mesh);

struct TextureExportOptions {
    ExportPreset preset;
    std::string meshName; // $mesh
    int size = 0;         // the longer side of every map (0: each set's own resolution)
};

/** A map as packed: components × width × height values from 0 to 1, interleaved. */
struct PackedMap {
    int width = 0, height = 0, components = 0;
    std::vector<std::uint16_t> values; // 0 .. 65535
};

/**
 * The file names (no folder) exporting mesh with options writes, per set then per map; an Error
 * if two would be the same or the preset is not valid.
 */
Result<std::vector<std::string>> textureExportFileNames(const Mesh& mesh,
                                                        const TextureExportOptions& options);

/**
 * Map map of preset for set (at the set's resolution, padded as the preset says, not resampled).
 * Texels whose centres no triangle of the set covers are 0 until padding reaches them.
 */
PackedMap packMap(const Mesh& mesh, const TextureSet& set, const PresetMap& map,
                  const ExportPreset& preset);

/**
 * Grows the values of the texels where covered is non-zero into the others, ring by ring (each
 * new texel the mean of its already filled 8-neighbours), padding rings or until all are filled
 * (kPadToFill). Texels with covered set are unchanged.
 */
void padMap(PackedMap& map, const std::vector<std::uint8_t>& covered, int padding);

/** map resampled to width × height: a box filter where it shrinks, bilinear where it grows. */
PackedMap resampleMap(const PackedMap& map, int width, int height);

/**
 * Writes every texture set of mesh through options.preset into folder (which must exist), the
 * files named by textureExportFileNames(). Returns the paths written, or an Error naming the file
 * and the problem (files already written stay; cancelling gives ErrorKind::Cancelled). What the
 * maps cannot hold (an emissive strength over 1 in integer formats) is named in warnings.
 */
Result<std::vector<std::string>> exportTextureSets(const std::string& folder, const Mesh& mesh,
                                                   const TextureExportOptions& options,
                                                   const ProgressFn& progress = {},
                                                   std::vector<std::string>* warnings = nullptr);

} // namespace core
