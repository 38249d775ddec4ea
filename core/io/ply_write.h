// SPDX-License-Identifier: GPL-3.0-or-later
// Binary little-endian PLY, written in memory: the one writer behind Export ▸ PLY and the headless
// tool's mesh.ply.
#pragma once

#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "core/model/mesh.h"

namespace core {

/** What a PLY file holds besides the positions and the triangles. */
struct PlyContents {
    std::string comment = "LayerPaint export";
    bool normals = true; // nx, ny, nz
    bool uvs = true;     // s, t (t up, as in OBJ), when the mesh has UVs
    /** Per vertex, linear RGBA; written as sRGB red, green, blue and linear alpha (uchar). */
    const std::vector<glm::vec4>* colors = nullptr;
};

/**
 * mesh (Mesh::validate() holds) as a binary little-endian PLY: one vertex element with the
 * properties contents asks for, in that order, and the triangles in triangle order as lists of
 * three uint indices.
 */
std::string encodePly(const Mesh& mesh, const PlyContents& contents = {});

} // namespace core
