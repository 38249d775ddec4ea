// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/surface_point.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

namespace core {

SurfacePoints::SurfacePoints(const Mesh& mesh, const View& view)
    : m_mesh(mesh), m_view(view), m_inverseProjection(glm::inverse(glm::dmat4(view.proj))),
      m_toView(view.view) {}

std::optional<glm::vec3> SurfacePoints::at(std::uint32_t triangle, glm::vec2 position) const {
    if (triangle >= m_mesh.triangleCount())
        return std::nullopt;
    // The ray through position in view space, and the triangle there (in double: a far or
    // grazing triangle would lose its barycentrics in float).
    const glm::dvec2 ndc(double(position.x) / m_view.width * 2.0 - 1.0,
                         1.0 - double(position.y) / m_view.height * 2.0);
    const glm::dvec4 a4 = m_inverseProjection * glm::dvec4(ndc, -1.0, 1.0);
    const glm::dvec4 b4 = m_inverseProjection * glm::dvec4(ndc, 1.0, 1.0);
    const glm::dvec3 origin = glm::dvec3(a4) / a4.w;
    const glm::dvec3 direction = glm::dvec3(b4) / b4.w - origin;
    glm::dvec3 p[3];
    for (int c = 0; c < 3; ++c) {
        const std::uint32_t v = m_mesh.indices[3 * std::size_t(triangle) + std::size_t(c)];
        if (v >= m_mesh.positions.size())
            return std::nullopt;
        p[c] = glm::dvec3(m_toView * glm::dvec4(glm::dvec3(m_mesh.positions[v]), 1.0));
    }
    const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
    const glm::dvec3 normal = glm::cross(e1, e2);
    const double along = glm::dot(normal, direction);
    if (!(std::fabs(along) > 0.0) || !std::isfinite(along))
        return std::nullopt;
    const glm::dvec3 q = origin + direction * (glm::dot(normal, p[0] - origin) / along) - p[0];
    const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
    const double denom = d00 * d11 - d01 * d01;
    if (!(denom > 0.0))
        return std::nullopt;
    const double d20 = glm::dot(q, e1), d21 = glm::dot(q, e2);
    double b1 = (d11 * d20 - d01 * d21) / denom;
    double b2 = (d00 * d21 - d01 * d20) / denom;
    double b0 = 1.0 - b1 - b2;
    if (!std::isfinite(b0) || !std::isfinite(b1) || !std::isfinite(b2))
        return std::nullopt;
    // A pixel centre just outside the triangle (its fragment covers the centre, the position
    // may not): the nearest point inside, near enough.
    b0 = std::max(b0, 0.0);
    b1 = std::max(b1, 0.0);
    b2 = std::max(b2, 0.0);
    const double sum = b0 + b1 + b2;
    return glm::vec3(float(b0 / sum), float(b1 / sum), float(b2 / sum));
}

std::optional<glm::vec3> surfacePointAt(const Mesh& mesh, const View& view, std::uint32_t triangle,
                                        glm::vec2 position) {
    return SurfacePoints(mesh, view).at(triangle, position);
}

} // namespace core
