// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"
#include "core/paint/targets/paint_target.h"

namespace core {

/**
 * A texture target over an automatic UV layout of mesh (makeUvLayout at options.resolution and
 * options.padding): the target's mesh() is mesh with TEXCOORD_0, its vertices split where the
 * layout cuts seams, triangles in the same order; it paints one new page. Deterministic.
 * progress runs on the calling thread; its false cancels (ErrorKind::Cancelled). An Error as
 * makeUvLayout() or TextureTarget::create() give.
 */
Result<std::unique_ptr<TextureTarget>> makeLayoutTarget(const Mesh& mesh,
                                                        const PaintTargetOptions& options,
                                                        const ProgressFn& progress = {});

/**
 * makePaintTarget(), except that a texture asked for (options.kind) on a mesh without UVs, or
 * with options.automaticUvs, gets an automatic layout (makeLayoutTarget()).
 */
Result<std::unique_ptr<PaintTarget>>
makePaintTargetWithLayout(std::shared_ptr<const Mesh> mesh,
                          std::shared_ptr<const MeshTopology> topology,
                          const PaintTargetOptions& options, const ProgressFn& progress = {});

/**
 * Whether a paint target made with options for mesh needs an automatic UV layout: a texture on a
 * mesh without UVs, or with options.automaticUvs.
 */
bool needsUvLayout(const Mesh& mesh, const PaintTargetOptions& options);

/**
 * Per material of mesh, the size of the texture it is painted into by a texture target made with
 * options (options.kind aside): TextureTarget::materialPageSizes(), or with an automatic layout
 * (needsUvLayout()) one new page of options.resolution² (clamped to 512..8192) for all.
 */
std::vector<PageSize> texturePageSizes(const Mesh& mesh, const PaintTargetOptions& options);

/**
 * How finely vertex colours resolve on mesh, in pixels: the length of triangle edges in the
 * model's default view (the whole model framed in a kReferenceViewHeight-pixel-high view, as
 * Camera::frame() with kFrameMargin does), taken as the median over the surface (triangles
 * weighted by their area, each with its longest edge). 0 for a mesh without surface area.
 */
double vertexSpacingPixels(const Mesh& mesh);
inline constexpr int kReferenceViewHeight = 720;

/**
 * The paint target a mesh without UVs gets by default: a texture with an automatic layout where
 * vertex colours would be coarse (vertexSpacingPixels() above a quarter of brushRadius, so a dab
 * of that radius spans fewer than about eight vertices across), else vertex colours. A mesh with
 * UVs always gets a texture.
 */
PaintTargetKind defaultTargetKind(const Mesh& mesh, float brushRadius);

} // namespace core
