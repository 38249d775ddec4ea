// SPDX-License-Identifier: GPL-3.0-or-later
// Tangents for normal maps: per vertex, from the mesh's positions, normals and uvs.
#pragma once

#include <vector>

#include <glm/vec4.hpp>

#include "core/model/mesh.h"

namespace core {

/**
 * A tangent per vertex for mesh.uvs, as glTF's TANGENT: xyz the unit direction of increasing u,
 * perpendicular to the vertex normal; w the sign (+1 or -1) with which cross(normal, xyz) points
 * towards decreasing v (glTF's uvs run down the image). Weighted as MikkTSpace weighs (each
 * triangle's tangent projected onto the vertex normal's plane, weighted by the triangle's angle
 * at the vertex), without MikkTSpace's splitting of a vertex shared by mirrored triangles: the
 * mesh's vertices are already split where their uvs differ. Vertices without a usable triangle
 * get any direction perpendicular to their normal. Empty for a mesh without uvs.
 */
std::vector<glm::vec4> computeTangents(const Mesh& mesh);

/**
 * The tangents a normal map is drawn with: the file's (Mesh::tangents) where it gave them,
 * computeTangents() for the other vertices. Empty for a mesh without uvs.
 */
std::vector<glm::vec4> vertexTangents(const Mesh& mesh);

} // namespace core
