// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"
#include "core/model/surface_point.h"
#include "core/paint/brush/dab.h"
#include "core/paint/targets/paint_target.h"

namespace core {

struct DepthLayers;

/** What a flood fill covers: a segmented region, a connected surface, or similar colour. */
enum class FillMode : std::uint8_t {
    /** The segmented region under the cursor in this view, its hidden part included. */
    Region,
    /** The whole connected surface (mesh topology) of the clicked triangle, any view. */
    Surface,
    /** Texels or vertices of similar colour connected to the clicked point across the surface. */
    Color,
};

/** "region", "surface" or "color" to a mode; nullopt for other names. */
std::optional<FillMode> parseFillMode(std::string_view name);
/** The mode's name as parseFillMode() reads it. */
const char* fillModeName(FillMode mode);

/**
 * Region fill: a dab whose paintable map is every fragment of region (all of it, hidden part
 * included, one layer), plus the pixels just beyond where its surface ends mapped to the
 * fragment next to them (the surface's rim between the last pixel centres and its edge),
 * centred on the region with a radius that covers it, so a hard brush paints it all at full
 * weight through PaintTarget::paint(). No pixels for an unknown region.
 */
Dab regionFillDab(const DepthLayers& layers, std::uint32_t region, float opacity);

/**
 * The triangles of triangle's connected component (MeshTopology::component), ascending; just
 * {triangle} when the topology does not match, empty when triangle is out of range.
 */
std::vector<std::uint32_t> componentTriangles(const MeshTopology& topology, std::uint32_t triangle);

/**
 * Surface fill: every element of triangles, each once: the texels their UVs cover on their
 * pages (the texels a stroke could paint on them) or their vertices. Empty for a target of
 * another mesh.
 */
std::vector<PaintElement> triangleElements(const PaintTarget& target,
                                           std::span<const std::uint32_t> triangles);

/**
 * Colour fill: the elements connected to the point (triangle, barycentric) whose colour is
 * within tolerance of the colour there: the largest difference of a channel (sRGB-encoded red,
 * green, blue and alpha, 0..1) at most tolerance, so 0 takes only the very same colour.
 * Texels spread to the 4 neighbours of their page, between texels of triangles that share a
 * corner, and across UV seams to the texels along the same mesh edge on the other side;
 * vertices spread along triangle edges and to their welded duplicates. Stays within the
 * triangle's component. Empty when nothing matches (a bad triangle, another mesh).
 */
std::vector<PaintElement> similarColorElements(const PaintTarget& target,
                                               const MeshTopology& topology, std::uint32_t triangle,
                                               glm::vec3 barycentric, float tolerance);

} // namespace core
