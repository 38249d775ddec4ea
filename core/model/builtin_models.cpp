// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/builtin_models.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace core {

namespace {
constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kUvMargin = 0.01f; // keeps seam padding of neighbouring charts apart

/**
 * Triangles of a (cols + 1) × (rows + 1) row-major vertex grid, counter-clockwise seen from the
 * outside when u runs right and v up on the outer side. poles: rows 0 and `rows` each collapse to
 * one point (a sphere's poles), so the triangles that would be degenerate there are left out.
 */
void addGridTriangles(Mesh& mesh, std::uint32_t base, int cols, int rows, bool poles = false) {
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            const std::uint32_t a = base + r * (cols + 1) + c, b = a + 1;
            const std::uint32_t d = a + (cols + 1), e = d + 1;
            if (!poles || r > 0)
                mesh.indices.insert(mesh.indices.end(), {a, b, e});
            if (!poles || r < rows - 1)
                mesh.indices.insert(mesh.indices.end(), {a, e, d});
        }
    }
}

void finish(Mesh& mesh, const glm::vec4& color, const std::string& name) {
    mesh.materials = {Material{name, color, -1}};
    mesh.triangleMaterial.assign(mesh.triangleCount(), 0);
    if (mesh.normals.size() != mesh.positions.size())
        mesh.computeNormals();
}

} // namespace

glm::vec3 trefoilCurve(float t) {
    return {std::sin(t) + 2.0f * std::sin(2.0f * t), std::cos(t) - 2.0f * std::cos(2.0f * t),
            -std::sin(3.0f * t)};
}

int trefoilSegmentOfTriangle(std::size_t triangle, int radialSegments) {
    // Triangles are emitted strip by strip, segment by segment, two per quad around the tube.
    const std::size_t perSegment = std::size_t(radialSegments) * 2;
    return int(triangle / perSegment);
}

const std::vector<BuiltinModel>& builtinModels() {
    static const std::vector<BuiltinModel> models = {
        {"trefoil", "Trefoil knot tube (144K vertices)"},
        {"hexring", "Hexagonal ring with an inner surface"},
        {"row", "Row of four identical bodies, one behind another"},
        {"knot", "Torus knot tube of any size: knot?triangles=N (default 1,000,000)"},
    };
    return models;
}

namespace {
/** "knot" or "knot?triangles=N": the knot of about N triangles. */
Result<Mesh> makeKnotFromName(const std::string& name) {
    const std::string full = std::string(kBuiltinPrefix) + name;
    std::size_t triangles = kKnotDefaultTriangles;
    if (name.size() > 4) {
        const std::string query = name.substr(5);
        const std::size_t equals = query.find('=');
        const std::string key = query.substr(0, equals);
        if (key != "triangles" || equals == std::string::npos)
            return Error{full + ": unknown parameter \"" + key + "\" (the knot takes triangles=N)",
                         ErrorKind::BadInput};
        const std::string value = query.substr(equals + 1);
        std::uint64_t n = 0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), n);
        if (value.empty() || error != std::errc() || end != value.data() + value.size())
            return Error{full + ": triangles must be a whole number, not \"" + value + "\"",
                         ErrorKind::BadInput};
        if (n < kKnotMinTriangles || n > kKnotMaxTriangles)
            return Error{full + ": triangles must be between " + std::to_string(kKnotMinTriangles) +
                             " and " + std::to_string(kKnotMaxTriangles),
                         ErrorKind::BadInput};
        triangles = std::size_t(n);
    }
    return makeKnot(triangles);
}
} // namespace

Result<Mesh> makeBuiltinModel(const std::string& name) {
    if (name == "knot" || name.rfind("knot?", 0) == 0)
        return makeKnotFromName(name);
    if (name == "trefoil")
        return makeTrefoil();
    if (name == "hexring")
        return makeHexRing();
    if (name == "row")
        return makeRow();
    return Error{std::string(kBuiltinPrefix) + name + ": no such built-in model (try trefoil, " +
                 "hexring, row or knot?triangles=N)"};
}

namespace {
/**
 * A tube of tubeRadius around the closed curve over t in [0, 2π), in `strips` UV strips (one per
 * lobe) so texels are near square: strips × segmentsPerStrip segments along, radialSegments
 * around, two triangles each.
 */
Mesh makeTube(glm::vec3 (*curve)(float), int strips, float tubeRadius, int segmentsPerStrip,
              int radialSegments, const glm::vec4& color, const std::string& name) {
    segmentsPerStrip = std::max(segmentsPerStrip, 3);
    radialSegments = std::max(radialSegments, 3);
    const int segments = strips * segmentsPerStrip;

    // Rotation-minimizing frames along the closed curve (double reflection), then the twist left
    // at the end is spread evenly so the tube closes without a seam in the shading.
    std::vector<glm::vec3> centers(segments + 1), tangents(segments + 1), normals(segments + 1);
    for (int i = 0; i <= segments; ++i) {
        const float t = 2.0f * kPi * float(i) / float(segments);
        centers[i] = curve(t);
        const float h = 1e-3f;
        tangents[i] = glm::normalize(curve(t + h) - curve(t - h));
    }
    normals[0] = glm::normalize(glm::cross(tangents[0], glm::vec3(0.0f, 0.0f, 1.0f)));
    for (int i = 0; i < segments; ++i) {
        const glm::vec3 v1 = centers[i + 1] - centers[i];
        const float c1 = glm::dot(v1, v1);
        const glm::vec3 rL = normals[i] - (2.0f / c1) * glm::dot(v1, normals[i]) * v1;
        const glm::vec3 tL = tangents[i] - (2.0f / c1) * glm::dot(v1, tangents[i]) * v1;
        const glm::vec3 v2 = tangents[i + 1] - tL;
        const float c2 = glm::dot(v2, v2);
        normals[i + 1] = c2 > 0.0f ? rL - (2.0f / c2) * glm::dot(v2, rL) * v2 : rL;
    }
    const glm::vec3 binormal0 = glm::cross(tangents[0], normals[0]);
    const float twist =
        std::atan2(glm::dot(normals[segments], binormal0), glm::dot(normals[segments], normals[0]));

    Mesh mesh;
    const int ring = radialSegments + 1;
    const std::size_t vertexCount = std::size_t(strips) * (segmentsPerStrip + 1) * ring;
    mesh.positions.reserve(vertexCount);
    mesh.normals.reserve(vertexCount);
    mesh.uvs.reserve(vertexCount);
    mesh.indices.reserve(std::size_t(strips) * segmentsPerStrip * radialSegments * 6);
    for (int strip = 0; strip < strips; ++strip) {
        const auto base = std::uint32_t(mesh.positions.size());
        for (int k = 0; k <= segmentsPerStrip; ++k) {
            // The closing ring repeats ring 0 exactly (not just up to rounding), and so does the
            // seam vertex of each ring, so the tube is watertight once positions are welded.
            const int i = (strip * segmentsPerStrip + k) % segments;
            const float correction = -twist * float(i) / float(segments);
            const glm::vec3 b = glm::cross(tangents[i], normals[i]);
            const glm::vec3 n0 = std::cos(correction) * normals[i] + std::sin(correction) * b;
            const glm::vec3 b0 = glm::cross(tangents[i], n0);
            for (int j = 0; j <= radialSegments; ++j) {
                const float a = 2.0f * kPi * float(j % radialSegments) / float(radialSegments);
                const glm::vec3 n = std::cos(a) * n0 + std::sin(a) * b0;
                mesh.positions.push_back(centers[i] + tubeRadius * n);
                mesh.normals.push_back(n);
                const float u = float(k) / float(segmentsPerStrip);
                const float v = float(j) / float(radialSegments);
                const float stripHeight = 1.0f / strips;
                mesh.uvs.push_back(
                    {kUvMargin + u * (1.0f - 2.0f * kUvMargin),
                     strip * stripHeight + kUvMargin + v * (stripHeight - 2.0f * kUvMargin)});
            }
        }
        // j turns counter-clockwise about the tangent: (around, along) faces outward.
        for (int k = 0; k < segmentsPerStrip; ++k) {
            for (int j = 0; j < radialSegments; ++j) {
                const std::uint32_t a = base + k * ring + j, b = a + 1;
                const std::uint32_t d = a + ring, e = d + 1;
                mesh.indices.insert(mesh.indices.end(), {a, b, e, a, e, d});
            }
        }
    }
    finish(mesh, color, name);
    return mesh;
}

/** A (2, 5) torus knot ("cinquefoil") on a torus of radii 2 and 1. */
glm::vec3 knotCurve(float t) {
    const float r = 2.0f + std::cos(5.0f * t);
    return {r * std::cos(2.0f * t), r * std::sin(2.0f * t), -std::sin(5.0f * t)};
}
} // namespace

Mesh makeTrefoil(int segmentsPerStrip, int radialSegments) {
    // Strands pass 1.21 apart at the closest crossing.
    return makeTube(trefoilCurve, 3, 0.45f, segmentsPerStrip, radialSegments,
                    {0.80f, 0.78f, 0.74f, 1.0f}, "trefoil");
}

Mesh makeKnot(std::size_t triangles) {
    // Segments around and along in the tube's proportions (its centre line is about 33 long, its
    // circumference 1.9), so quads are near square: along ≈ 17 × around.
    constexpr int kStrips = 5;
    const double quads = double(std::max<std::size_t>(triangles, kKnotMinTriangles)) / 2.0;
    const int around = std::max(3, int(std::lround(std::sqrt(quads / 17.0))));
    const int perStrip = std::max(3, int(std::lround(quads / (double(around) * kStrips))));
    return makeTube(knotCurve, kStrips, 0.3f, perStrip, around, {0.78f, 0.80f, 0.74f, 1.0f},
                    "knot");
}

Mesh makeHexRing(int subdivisions) {
    constexpr float kOuter = 1.0f, kInner = 0.7f, kHalfHeight = 0.3f;
    const int n = std::max(subdivisions, 1);
    Mesh mesh;
    // 24 planar quads (6 outer walls, 6 inner, 6 top, 6 bottom), each its own grid and UV tile
    // in a 5 × 5 atlas; vertices are not shared across the hard edges.
    const auto corner = [](float radius, int k, float y) {
        const float a = 2.0f * kPi * float(k) / 6.0f;
        return glm::vec3(radius * std::cos(a), y, -radius * std::sin(a));
    };
    int tile = 0;
    const auto addQuad = [&](glm::vec3 p00, glm::vec3 p10, glm::vec3 p01, glm::vec3 p11) {
        const auto base = std::uint32_t(mesh.positions.size());
        const glm::vec3 normal = glm::normalize(glm::cross(p10 - p00, p01 - p00));
        const float tileSize = 1.0f / 5.0f;
        const glm::vec2 origin(float(tile % 5) * tileSize, float(tile / 5) * tileSize);
        for (int r = 0; r <= n; ++r) {
            for (int c = 0; c <= n; ++c) {
                const float u = float(c) / float(n), v = float(r) / float(n);
                const glm::vec3 bottom = glm::mix(p00, p10, u), top = glm::mix(p01, p11, u);
                mesh.positions.push_back(glm::mix(bottom, top, v));
                mesh.normals.push_back(normal);
                mesh.uvs.push_back(origin + kUvMargin +
                                   glm::vec2(u, v) * (tileSize - 2.0f * kUvMargin));
            }
        }
        addGridTriangles(mesh, base, n, n);
        ++tile;
    };
    for (int k = 0; k < 6; ++k) {
        const int k1 = k + 1;
        // Outer wall faces outward, inner wall faces the axis.
        addQuad(corner(kOuter, k, -kHalfHeight), corner(kOuter, k1, -kHalfHeight),
                corner(kOuter, k, kHalfHeight), corner(kOuter, k1, kHalfHeight));
        addQuad(corner(kInner, k1, -kHalfHeight), corner(kInner, k, -kHalfHeight),
                corner(kInner, k1, kHalfHeight), corner(kInner, k, kHalfHeight));
        addQuad(corner(kOuter, k, kHalfHeight), corner(kOuter, k1, kHalfHeight),
                corner(kInner, k, kHalfHeight), corner(kInner, k1, kHalfHeight));
        addQuad(corner(kInner, k, -kHalfHeight), corner(kInner, k1, -kHalfHeight),
                corner(kOuter, k, -kHalfHeight), corner(kOuter, k1, -kHalfHeight));
    }
    finish(mesh, {0.75f, 0.80f, 0.86f, 1.0f}, "hexring");
    return mesh;
}

Mesh makeRow(int subdivisions) {
    constexpr int kCount = 4;
    constexpr float kSpacing = 1.2f;
    const glm::vec3 radii(0.6f, 0.35f, 0.3f);
    const int around = std::max(subdivisions, 4), along = std::max(subdivisions / 2, 2);
    Mesh mesh;
    for (int body = 0; body < kCount; ++body) {
        const auto base = std::uint32_t(mesh.positions.size());
        const glm::vec3 center(0.0f, 0.0f, -kSpacing * float(body));
        const glm::vec2 tileOrigin(float(body % 2) * 0.5f, float(body / 2) * 0.5f);
        for (int r = 0; r <= along; ++r) {
            const float v = float(r) / float(along);
            const float theta = kPi * (v - 0.5f); // -90° (bottom) .. 90° (top)
            const bool pole = r == 0 || r == along;
            const float cosTheta = pole ? 0.0f : std::cos(theta);
            const float sinTheta = pole ? (r == 0 ? -1.0f : 1.0f) : std::sin(theta);
            for (int c = 0; c <= around; ++c) {
                const float u = float(c) / float(around);
                const float phi = 2.0f * kPi * float(c % around) / float(around);
                const glm::vec3 unit(cosTheta * std::cos(phi), sinTheta, -cosTheta * std::sin(phi));
                mesh.positions.push_back(center + unit * radii);
                mesh.normals.push_back(glm::normalize(unit / radii));
                mesh.uvs.push_back(tileOrigin + kUvMargin +
                                   glm::vec2(u, v) * (0.5f - 2.0f * kUvMargin));
            }
        }
        addGridTriangles(mesh, base, around, along, true);
    }
    finish(mesh, {0.82f, 0.72f, 0.60f, 1.0f}, "row");
    return mesh;
}

} // namespace core
