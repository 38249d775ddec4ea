// SPDX-License-Identifier: GPL-3.0-or-later
// The point of a triangle seen at a window position: the picking of the fill, the eyedropper and
// the alpha test of the depth-layer capture.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/model/camera.h"
#include "core/model/mesh.h"

namespace core {

/** surfacePointAt() for many points of one view: the view's inverse made once. */
class SurfacePoints {
public:
    SurfacePoints(const Mesh& mesh, const View& view);

    /**
     * The barycentric coordinates (clamped into the triangle) of the point of triangle seen at
     * window position (pixels, y down); nullopt for a degenerate triangle, an index out of range,
     * or a ray parallel to it.
     */
    std::optional<glm::vec3> at(std::uint32_t triangle, glm::vec2 position) const;

private:
    const Mesh& m_mesh;
    const View& m_view;
    glm::dmat4 m_inverseProjection;
    glm::dmat4 m_toView;
};

/** SurfacePoints(mesh, view).at(triangle, position). */
std::optional<glm::vec3> surfacePointAt(const Mesh& mesh, const View& view, std::uint32_t triangle,
                                        glm::vec2 position);

} // namespace core
