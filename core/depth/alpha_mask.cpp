// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/depth/alpha_mask.h"

#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

#include "core/model/surface_point.h"

namespace core {

namespace {

/** Texel (x, y) of image, repeating, as alpha in 0..1. */
float alphaAt(const Image& image, int x, int y) {
    x = ((x % image.width) + image.width) % image.width;
    y = ((y % image.height) + image.height) % image.height;
    return float(image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4 + 3]) /
           255.0f;
}

/** The texture's alpha at uv, bilinear between texel centres, repeating. */
float sampleAlpha(const Image& image, glm::vec2 uv) {
    const float fx = uv.x * float(image.width) - 0.5f, fy = uv.y * float(image.height) - 0.5f;
    if (!std::isfinite(fx) || !std::isfinite(fy))
        return 1.0f;
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float tx = fx - x0, ty = fy - y0;
    const auto x = int(std::fmod(x0, float(image.width))),
               y = int(std::fmod(y0, float(image.height)));
    const float top = alphaAt(image, x, y) * (1 - tx) + alphaAt(image, x + 1, y) * tx;
    const float bottom = alphaAt(image, x, y + 1) * (1 - tx) + alphaAt(image, x + 1, y + 1) * tx;
    return top * (1 - ty) + bottom * ty;
}

} // namespace

bool hasAlphaMask(const Mesh& mesh) {
    return std::any_of(mesh.materials.begin(), mesh.materials.end(),
                       [](const Material& m) { return m.alphaMode == AlphaMode::Mask; });
}

float surfaceAlpha(const Mesh& mesh, std::uint32_t t, const glm::vec3& b) {
    const Material& material = mesh.materials[mesh.triangleMaterial[t]];
    float alpha = material.baseColorFactor.a;
    const std::uint32_t* v = &mesh.indices[3 * std::size_t(t)];
    if (mesh.hasColors())
        alpha *= b.x * mesh.colors[v[0]].a + b.y * mesh.colors[v[1]].a + b.z * mesh.colors[v[2]].a;
    const int texture = material.baseColorTexture;
    if (texture >= 0 && std::size_t(texture) < mesh.textures.size() && mesh.hasUvs() &&
        !mesh.textures[std::size_t(texture)].empty()) {
        const glm::vec2 uv = b.x * mesh.uvs[v[0]] + b.y * mesh.uvs[v[1]] + b.z * mesh.uvs[v[2]];
        alpha *= sampleAlpha(mesh.textures[std::size_t(texture)], uv);
    }
    return alpha;
}

std::size_t dropMaskedFragments(DepthStack& stack, const Mesh& mesh, const View& view) {
    if (!hasAlphaMask(mesh) || stack.offsets.size() != stack.pixelCount() + 1)
        return 0;
    const SurfacePoints points(mesh, view);
    const auto masked = [&](std::uint32_t t, std::size_t pixel) {
        if (t >= mesh.triangleCount())
            return false;
        const Material& material = mesh.materials[mesh.triangleMaterial[t]];
        if (material.alphaMode != AlphaMode::Mask)
            return false;
        const glm::vec2 centre(float(pixel % std::size_t(stack.width)) + 0.5f,
                               float(pixel / std::size_t(stack.width)) + 0.5f);
        const auto b = points.at(t, centre);
        return b && surfaceAlpha(mesh, t, *b) < material.alphaCutoff;
    };
    std::size_t kept = 0;
    std::uint32_t begin = stack.offsets[0];
    for (std::size_t pixel = 0; pixel < stack.pixelCount(); ++pixel) {
        const std::uint32_t end = stack.offsets[pixel + 1];
        stack.offsets[pixel] = std::uint32_t(kept);
        for (std::uint32_t f = begin; f < end; ++f) {
            if (masked(stack.triangle[f], pixel))
                continue;
            stack.depth[kept] = stack.depth[f];
            stack.triangle[kept] = stack.triangle[f];
            ++kept;
        }
        begin = end;
    }
    const std::size_t dropped = stack.depth.size() - kept;
    stack.offsets[stack.pixelCount()] = std::uint32_t(kept);
    stack.depth.resize(kept);
    stack.triangle.resize(kept);
    return dropped;
}

} // namespace core
