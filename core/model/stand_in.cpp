// SPDX-License-Identifier: GPL-3.0-or-later
// The simplified stand-in drawn while the camera moves: meshoptimizer's simplifiers per material.
#include "core/model/stand_in.h"

#include <algorithm>
#include <limits>

#include <meshoptimizer.h>

namespace core {

namespace {
constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
// The edge-collapse simplifier stops at this error (relative to the mesh's extent) even above
// the target; the grid clustering then takes it the rest of the way.
constexpr float kTargetError = 0.02f;
// A group of more than this many times its target is first clustered down to that many times
// (a grid far finer than the stand-in's detail): the edge collapses then start from there. On a
// 10M-triangle knot: 7.6 s → 3.4 s for the 250K stand-in.
constexpr std::size_t kClusterFirstAbove = 8;

/**
 * Simplifies the triangles corners (source vertex ids) to at most target triangles, appending
 * them to out. local and positions are scratch; local is all kUnused again on return.
 */
void simplifyGroup(const Mesh& mesh, const std::vector<std::uint32_t>& corners, std::size_t target,
                   std::vector<std::uint32_t>& local, std::vector<std::uint32_t>& out) {
    // Compact the group's vertices, so the simplifier's per-vertex memory is the group's.
    std::vector<std::uint32_t> source;
    std::vector<std::uint32_t> indices(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const std::uint32_t v = corners[i];
        if (local[v] == kUnused) {
            local[v] = std::uint32_t(source.size());
            source.push_back(v);
        }
        indices[i] = local[v];
    }
    for (const std::uint32_t v : source)
        local[v] = kUnused;
    std::vector<glm::vec3> positions(source.size());
    for (std::size_t i = 0; i < source.size(); ++i)
        positions[i] = mesh.positions[source[i]];

    const std::size_t targetIndices = target * 3;
    if (indices.size() > kClusterFirstAbove * targetIndices) {
        std::vector<std::uint32_t> clustered(indices.size());
        const std::size_t made = meshopt_simplifySloppy(
            clustered.data(), indices.data(), indices.size(), &positions[0].x, positions.size(),
            sizeof(glm::vec3), kClusterFirstAbove * targetIndices, 1.0f, nullptr);
        if (made >= targetIndices) { // else too coarse a grid: the collapses alone
            clustered.resize(made);
            indices = std::move(clustered);
        }
    }
    std::vector<std::uint32_t> simplified(indices.size());
    std::size_t count = meshopt_simplify(simplified.data(), indices.data(), indices.size(),
                                         &positions[0].x, positions.size(), sizeof(glm::vec3),
                                         targetIndices, kTargetError, 0, nullptr);
    // Seams, borders and unwelded triangles can keep it above the target: cluster the rest.
    for (std::size_t aim = targetIndices; count > targetIndices && aim >= 3; aim = aim * 3 / 4) {
        std::vector<std::uint32_t> coarser(count);
        const std::size_t made =
            meshopt_simplifySloppy(coarser.data(), simplified.data(), count, &positions[0].x,
                                   positions.size(), sizeof(glm::vec3), aim, 1.0f, nullptr);
        if (made <= targetIndices) {
            coarser.resize(made);
            simplified = std::move(coarser);
            count = made;
        }
    }
    if (count > targetIndices)
        count = 0; // nothing small enough: the material is left out
    for (std::size_t i = 0; i < count; ++i)
        out.push_back(source[simplified[i]]);
}
} // namespace

Result<StandIn> simplifyForDisplay(const Mesh& mesh, std::size_t targetTriangles,
                                   const ProgressFn& progress) {
    StandIn standIn;
    const std::size_t triangles = mesh.triangleCount();
    if (triangles <= targetTriangles)
        return standIn;
    if (!reportProgress(progress, 0.0))
        return cancelledError();

    // Triangles by material, each material's in their order.
    std::size_t materials = 0;
    for (const std::uint32_t m : mesh.triangleMaterial)
        materials = std::max<std::size_t>(materials, std::size_t(m) + 1);
    std::vector<std::size_t> perMaterial(materials, 0);
    for (const std::uint32_t m : mesh.triangleMaterial)
        ++perMaterial[m];

    std::vector<std::uint32_t> local(mesh.vertexCount(), kUnused);
    std::size_t done = 0;
    for (std::uint32_t m = 0; m < materials; ++m) {
        const std::size_t count = perMaterial[m];
        if (count == 0)
            continue;
        // Its share of the target, rounded down: the sum stays under the target.
        const std::size_t target =
            std::size_t(double(targetTriangles) * double(count) / double(triangles));
        if (target > 0) {
            std::vector<std::uint32_t> corners;
            corners.reserve(count * 3);
            for (std::size_t t = 0; t < triangles; ++t)
                if (mesh.triangleMaterial[t] == m)
                    corners.insert(corners.end(), mesh.indices.begin() + std::ptrdiff_t(3 * t),
                                   mesh.indices.begin() + std::ptrdiff_t(3 * t + 3));
            const std::size_t before = standIn.indices.size();
            simplifyGroup(mesh, corners, target, local, standIn.indices);
            standIn.triangleMaterial.resize(
                standIn.triangleMaterial.size() + (standIn.indices.size() - before) / 3, m);
        }
        done += count;
        if (!reportProgress(progress, double(done) / double(triangles)))
            return cancelledError();
    }
    return standIn;
}

StandIn standInFor(const StandIn& standIn, const Mesh& source, const Mesh& drawn) {
    if (drawn.triangleCount() != source.triangleCount())
        return {};
    if (drawn.vertexCount() == source.vertexCount() && drawn.indices == source.indices &&
        drawn.triangleMaterial == source.triangleMaterial)
        return standIn;
    StandIn result;
    // One corner per source vertex the stand-in uses, and the drawn vertex there.
    std::vector<std::uint32_t> drawnVertex(source.vertexCount(), kUnused);
    for (const std::uint32_t v : standIn.indices)
        drawnVertex[v] = kUnused - 1; // wanted
    for (std::size_t i = 0; i < source.indices.size(); ++i)
        if (drawnVertex[source.indices[i]] == kUnused - 1)
            drawnVertex[source.indices[i]] = drawn.indices[i];
    std::vector<std::uint32_t> drawnMaterial;
    for (std::size_t t = 0; t < source.triangleCount(); ++t) {
        const std::uint32_t m = source.triangleMaterial[t];
        if (m >= drawnMaterial.size())
            drawnMaterial.resize(std::size_t(m) + 1, kUnused);
        if (drawnMaterial[m] == kUnused)
            drawnMaterial[m] = drawn.triangleMaterial[t];
    }
    result.indices.reserve(standIn.indices.size());
    for (const std::uint32_t v : standIn.indices)
        result.indices.push_back(drawnVertex[v]);
    result.triangleMaterial.reserve(standIn.triangleMaterial.size());
    for (const std::uint32_t m : standIn.triangleMaterial)
        result.triangleMaterial.push_back(m < drawnMaterial.size() ? drawnMaterial[m] : 0);
    return result;
}

} // namespace core
