// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/depth/alpha_mask.h"

#include <algorithm>

#include <glm/vec2.hpp>

#include "core/model/image_sample.h"
#include "core/model/surface_point.h"

namespace core {

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
        alpha *= sampleChannel(mesh.textures[std::size_t(texture)], uv, 3);
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
