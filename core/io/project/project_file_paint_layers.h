// SPDX-License-Identifier: GPL-3.0-or-later
// The paint layers' images inside a project file: each plane's written tiles (their bounding
// region per page) as a PNG, and the base where it differs from the saved composite.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/document/project_state.h"
#include "core/io/mesh_io.h"
#include "core/model/mesh.h"

namespace core {

/** Decodes images stored in buffer views of a binary glTF (loadGlbImages() or in process). */
using GlbImageLoader = Result<std::vector<Image>> (*)(const std::string& path,
                                                      const std::vector<GlbImageRequest>& requests,
                                                      const LoadLimits& limits);

/**
 * Adds the planes and the base of saved to paintLayers (extras.layerpaint.paint_layers as
 * paintLayersToJson() wrote it): "pages" (the page sizes), per layer "channels" and "mask"
 * describing each plane with "image" indices into attachments, where the PNG files are
 * appended, and "base". An Error if an image cannot be encoded.
 */
Status addPaintLayerImages(const SavedPaintLayers& saved, const std::vector<PageSize>& pages,
                           nlohmann::json& paintLayers,
                           std::vector<std::vector<std::uint8_t>>& attachments);

/**
 * Reads the planes and the base of the paint layers of the project at path (paintLayers: its
 * extras.layerpaint.paint_layers) into saved, whose layers came from paintLayersFromJson(), and
 * puts the base into mesh's textures (page p is texture p). An Error saying what does not fit.
 * Before any image is decoded, the sizes every plane, base and roughness-metallic base ask of
 * their images and the bytes their tiles take are planned: images nothing uses are not decoded,
 * an image asked for at two sizes or larger than its region is refused, and so is a project
 * whose paint layers would take more than limits.maxPaintLayerBytes. The images are decoded by
 * loadImages (loadGlbImages(): in the importer process), which refuses one whose header
 * disagrees with its size before decoding it.
 */
Status readPaintLayerImages(const std::string& path, const nlohmann::json& paintLayers,
                            const LoadLimits& limits, Mesh& mesh, SavedPaintLayers& saved,
                            GlbImageLoader loadImages);

} // namespace core
