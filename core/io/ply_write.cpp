// SPDX-License-Identifier: GPL-3.0-or-later
// The binary PLY writer (see ply_write.h).
#include "core/io/ply_write.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/base/color.h"

static_assert(std::endian::native == std::endian::little,
              "binary_little_endian PLY values are written with memcpy");

namespace core {

std::string encodePly(const Mesh& mesh, const PlyContents& contents) {
    const bool normals = contents.normals;
    const bool uvs = contents.uvs && mesh.hasUvs();
    const std::vector<glm::vec4>* colors = contents.colors;
    std::string out = "ply\nformat binary_little_endian 1.0\ncomment " + contents.comment +
                      "\nelement vertex " + std::to_string(mesh.vertexCount()) +
                      "\nproperty float x\nproperty float y\nproperty float z\n";
    if (normals)
        out += "property float nx\nproperty float ny\nproperty float nz\n";
    // UVs keep the twins of a texture seam apart (importers join identical vertices).
    if (uvs)
        out += "property float s\nproperty float t\n";
    if (colors)
        out += "property uchar red\nproperty uchar green\nproperty uchar blue\n"
               "property uchar alpha\n";
    out += "element face " + std::to_string(mesh.triangleCount()) +
           "\nproperty list uchar uint vertex_indices\nend_header\n";
    const std::size_t header = out.size();
    const std::size_t vertexBytes = 12 + (normals ? 12 : 0) + (uvs ? 8 : 0) + (colors ? 4 : 0);
    out.resize(header + mesh.vertexCount() * vertexBytes + mesh.triangleCount() * 13);
    char* p = out.data() + header;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        std::memcpy(p, &mesh.positions[v], 12);
        std::size_t at = 12;
        if (normals) {
            std::memcpy(p + at, &mesh.normals[v], 12);
            at += 12;
        }
        if (uvs) {
            const float st[2] = {mesh.uvs[v].x, 1.0f - mesh.uvs[v].y};
            std::memcpy(p + at, st, 8);
            at += 8;
        }
        if (colors) {
            const glm::vec4& c = (*colors)[v];
            const std::uint8_t rgba[4] = {
                linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b),
                std::uint8_t(std::lround(std::clamp(c.a, 0.0f, 1.0f) * 255.0f))};
            std::memcpy(p + at, rgba, 4);
        }
        p += vertexBytes;
    }
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        *p++ = 3;
        std::memcpy(p, &mesh.indices[3 * t], 12);
        p += 12;
    }
    return out;
}

} // namespace core
