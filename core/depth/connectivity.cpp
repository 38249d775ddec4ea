// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/depth/connectivity.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#if defined(__SSE__)
#include <immintrin.h>
#endif

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "core/base/parallel.h"

namespace core {

namespace {

constexpr float kFail = std::numeric_limits<float>::infinity();
/** |cos| of the angle between a pixel ray and a plane's normal below which the plane is grazing
 * (about 0.6° from edge-on): predictions there amplify depth noise by more than 100×. */
constexpr float kMinRayCosine = 0.01f;
/** Allowed distance of a sample from the other sample's plane, relative to a circular arc's:
 * a true arc gives 1, a sheet seen edge-on against an unrelated one about 2 or more. */
constexpr float kArcSlack = 1.5f;
/** The same for facets sharing a corner, within kFacetCosine (30°) of each other. */
constexpr float kFacetSlack = 2.5f;
constexpr float kFacetCosine = 0.8660254f;

/** The ray through one window position, with |direction|² for the grazing check. */
struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;
    float length2;
};

/** Depth at which ray meets plane; NaN when grazing or degenerate (so any test with it fails). */
inline float planeDepth(const glm::vec4& plane, const Ray& ray) {
    const float denom =
        plane.x * ray.direction.x + plane.y * ray.direction.y + plane.z * ray.direction.z;
    if (!(denom * denom >= kMinRayCosine * kMinRayCosine * ray.length2))
        return std::numeric_limits<float>::quiet_NaN();
    return -(plane.w + plane.x * ray.origin.x + plane.y * ray.origin.y + plane.z * ray.origin.z) /
           denom;
}

/** Four floats in one SIMD register (GCC's and Clang's vectors). */
using Floats4 = float __attribute__((vector_size(16)));

/** PixelRays with each vector in one register (the fourth lane unused). */
struct PixelRays4 {
    Floats4 origin0, originDx, originDy, direction0, directionDx, directionDy;

    explicit PixelRays4(const PixelRays& rays)
        : origin0(of(rays.origin0)), originDx(of(rays.originDx)), originDy(of(rays.originDy)),
          direction0(of(rays.direction0)), directionDx(of(rays.directionDx)),
          directionDy(of(rays.directionDy)) {}

private:
    static Floats4 of(const glm::vec3& v) { return Floats4{v.x, v.y, v.z, 0.0f}; }
};

/**
 * Sets out to the ray through (px, py) in place (a Ray returned and copied was stored in pieces
 * and loaded whole, which stalled the loads): PixelRays::origin() and direction() and their
 * dot product, with the same operations lane by lane.
 */
inline void setRay(const PixelRays4& rays, float px, float py, Ray& out) {
    const Floats4 origin = rays.origin0 + px * rays.originDx + py * rays.originDy;
    const Floats4 direction = rays.direction0 + px * rays.directionDx + py * rays.directionDy;
    const Floats4 squares = direction * direction;
    out.origin = glm::vec3(origin[0], origin[1], origin[2]);
    out.direction = glm::vec3(direction[0], direction[1], direction[2]);
    out.length2 = squares[0] + squares[1] + squares[2];
}

/** Rows to a work item: small enough to balance two loaded cores, large enough to stream. */
constexpr int kRowsPerChunk = 8;

// The linker twice: in four lanes for any processor, in eight for those with AVX2.
namespace lanes4 {
#define LAYERPAINT_LINKER_LANES 4
#include "core/depth/connectivity_linker.inl"
#undef LAYERPAINT_LINKER_LANES
} // namespace lanes4

#if defined(__x86_64__) || defined(__i386__)
#define LAYERPAINT_LINKER_AVX2 1
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace lanes8 {
#define LAYERPAINT_LINKER_LANES 8
#include "core/depth/connectivity_linker.inl"
#undef LAYERPAINT_LINKER_LANES
} // namespace lanes8
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#endif

/** The linker for this processor: eight lanes where it (and its operating system) runs AVX2. */
using LinkBands = bool (*)(const DepthStack&, const ConnectivityOptions&, const SurfaceGeometry*,
                           Connectivity&, std::atomic<int>&, int);
LinkBands linkBandsFor(const ConnectivityOptions& options) {
#if defined(LAYERPAINT_LINKER_AVX2)
    if (options.wideLanes && __builtin_cpu_supports("avx2"))
        return lanes8::linkBands;
#endif
    return lanes4::linkBands;
}

} // namespace

float unitScale(const Mesh& mesh) {
    const float side = mesh.positions.empty() ? 0.0f : mesh.bounds().longestSide();
    return side > 0.0f && std::isfinite(side) ? 1.0f / side : 1.0f;
}

Connectivity computeConnectivity(const DepthStack& stack, const ConnectivityOptions& options,
                                 const SurfaceGeometry* geometry) {
    Connectivity out;
    out.width = stack.width;
    out.height = stack.height;
    out.links.assign(4 * stack.fragmentCount(), 0);
    if (stack.width <= 0 || stack.height <= 0 || stack.offsets.size() != stack.pixelCount() + 1)
        return out;
    // Each part writes the right/left links of its rows and the down links of its rows plus the
    // up links of the row below: every byte has one writer, whatever the split.
    // Bands of kRowsPerChunk rows go to whichever thread is free next.
    const int chunks = (stack.height + kRowsPerChunk - 1) / kRowsPerChunk;
    std::atomic<int> nextChunk{0};
    std::atomic<bool> truncated{false};
    const LinkBands linkBands = linkBandsFor(options);
    parallelRanges(chunks, options.threads, [&](int, int, int) {
        if (linkBands(stack, options, geometry, out, nextChunk, chunks))
            truncated = true;
    });
    out.truncated = truncated;
    return out;
}

ConnectivityQuality measureConnectivity(const DepthStack& stack, const Connectivity& connectivity,
                                        const MeshTopology& topology) {
    ConnectivityQuality quality;
    if (connectivity.links.size() != 4 * stack.fragmentCount() ||
        stack.offsets.size() != stack.pixelCount() + 1)
        return quality;
    const std::size_t triangles = topology.triangleCount();
    const int w = stack.width, h = stack.height;
    auto linked = [&](std::uint32_t from, std::uint32_t fromLayer, int direction,
                      std::uint32_t toLayer) {
        return fromLayer <= kMaxLinkedLayers && connectivity.link(from, direction) == toLayer;
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
            for (int dir = 0; dir < 2; ++dir) {
                if ((dir == 0 && x + 1 >= w) || (dir == 1 && y + 1 >= h))
                    continue;
                const std::size_t q = dir == 0 ? p + 1 : p + std::size_t(w);
                const int forward = dir == 0 ? kRight : kDown, backward = dir == 0 ? kLeft : kUp;
                for (std::uint32_t i = 1; i <= stack.layerCount(p); ++i) {
                    const std::uint32_t a = stack.offsets[p] + i - 1;
                    const std::uint32_t ta = stack.triangle[a];
                    if (ta >= triangles)
                        continue;
                    for (std::uint32_t j = 1; j <= stack.layerCount(q); ++j) {
                        const std::uint32_t b = stack.offsets[q] + j - 1;
                        const std::uint32_t tb = stack.triangle[b];
                        if (tb >= triangles)
                            continue;
                        const bool ab = linked(a, i, forward, j), ba = linked(b, j, backward, i);
                        if (ta == tb) {
                            ++quality.sameTrianglePairs;
                            quality.sameTriangleDisconnected += (ab && ba) ? 0 : 1;
                        } else if (topology.sharedCorners(ta, tb) > 0) {
                            ++quality.adjacentTrianglePairs;
                            quality.adjacentTriangleDisconnected += (ab || ba) ? 0 : 1;
                        }
                        if (ab || ba) {
                            ++quality.connectedPairs;
                            quality.crossComponentConnected +=
                                topology.component[ta] != topology.component[tb] ? 1 : 0;
                        }
                    }
                }
            }
        }
    return quality;
}

} // namespace core
