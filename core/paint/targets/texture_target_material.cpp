// SPDX-License-Identifier: GPL-3.0-or-later
// Where a texture target's roughness and metallic start: the materials' metallic-roughness maps
// times their factors, resampled onto the pages (see startingMetallicRoughness()).
#include <algorithm>
#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "core/model/image_sample.h"
#include "core/paint/targets/paint_context.h"
#include "core/paint/targets/uv_raster.h"

namespace core {

// A namespace of its own: the unity build compiles this file with others.
namespace starting_mr {

std::uint8_t unitByte(float v) {
    return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

/** How a material starts: its map (or nullptr), the map's placement and its factors. */
struct StartingMr {
    const Image* map = nullptr;
    glm::mat3 uvTransform{1.0f};
    float roughness = 1.0f, metallic = 0.0f;

    static StartingMr of(const Mesh& mesh, const Material& m) {
        StartingMr s;
        const int t = m.metallicRoughness.texture;
        if (t >= 0 && std::size_t(t) < mesh.textures.size() &&
            !mesh.textures[std::size_t(t)].empty()) {
            s.map = &mesh.textures[std::size_t(t)];
            s.uvTransform = m.metallicRoughness.uvTransform;
        }
        s.roughness = std::isfinite(m.roughnessFactor) ? m.roughnessFactor : 1.0f;
        s.metallic = std::isfinite(m.metallicFactor) ? m.metallicFactor : 0.0f;
        return s;
    }
    bool operator==(const StartingMr&) const = default;

    /** The texel (R unused, G roughness, B metallic, A 1) at the mesh's uv. */
    void write(glm::vec2 uv, std::uint8_t* px) const {
        float g = roughness, b = metallic;
        if (map) {
            const glm::vec3 t = uvTransform * glm::vec3(uv, 1.0f);
            g *= sampleChannel(*map, glm::vec2(t), 1);
            b *= sampleChannel(*map, glm::vec2(t), 2);
        }
        px[0] = 0;
        px[1] = unitByte(g);
        px[2] = unitByte(b);
        px[3] = 255;
    }
};

} // namespace starting_mr

using starting_mr::StartingMr;

Image startingMetallicRoughness(const Mesh& mesh, const std::vector<std::uint32_t>& materialPage,
                                std::uint32_t page, int width, int height) {
    Image out{width, height, {}};
    out.rgba.resize(std::size_t(width) * std::size_t(height) * 4);
    std::vector<StartingMr> starts(mesh.materials.size());
    const StartingMr* owner = nullptr;
    bool mixed = false;
    for (std::size_t m = 0; m < mesh.materials.size(); ++m) {
        starts[m] = StartingMr::of(mesh, mesh.materials[m]);
        if (m >= materialPage.size() || materialPage[m] != page)
            continue;
        mixed = mixed || (owner && !(*owner == starts[m]));
        owner = owner ? owner : &starts[m];
    }
    // The whole page from its first material (padding and texels between charts too)...
    const StartingMr flat;
    const StartingMr& first = owner ? *owner : flat;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            first.write(
                glm::vec2((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)),
                &out.rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4]);
    if (!mixed)
        return out;
    // ...then, where materials sharing the page differ, each triangle's texels from its own.
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t m = mesh.triangleMaterial[t];
        if (m >= materialPage.size() || materialPage[m] != page || starts[m] == first)
            continue;
        glm::vec2 uv[3];
        for (int c = 0; c < 3; ++c)
            uv[c] = mesh.uvs[mesh.indices[3 * t + std::size_t(c)]];
        uv::UvTriangle r;
        if (!uv::setUpUv(uv, width, height, r) ||
            double(r.maxX - r.minX + 1) * double(r.maxY - r.minY + 1) >
                4.0 * double(width) * double(height))
            continue;
        uv::scanUv(r, r.minX, r.maxX, r.minY, r.maxY,
                   [&](int x, int y, std::int64_t, std::int64_t, std::int64_t) {
                       const std::size_t texel =
                           std::size_t(uv::wrapIndex(y, height)) * std::size_t(width) +
                           std::size_t(uv::wrapIndex(x, width));
                       starts[m].write(glm::vec2((float(x) + 0.5f) / float(width),
                                                 (float(y) + 0.5f) / float(height)),
                                       &out.rgba[texel * 4]);
                   });
    }
    return out;
}

} // namespace core
