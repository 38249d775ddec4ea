// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to core: exact texel-space rasterization of UV triangles, shared by the paint targets,
// the flood fill and the texture-set export so all visit the same texels of a triangle.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include <glm/vec2.hpp>

namespace core::uv {

constexpr int kSubBits = 8; // texel positions snapped to 1/256 texel, as the capture does
constexpr std::int64_t kSub = std::int64_t(1) << kSubBits;
constexpr double kMaxTexelCoord = double(1 << 20); // keeps edge products inside int64

inline std::int64_t edgeFunction(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by,
                                 std::int64_t px, std::int64_t py) {
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/** Fill rule tie-break for a point exactly on edge a→b: exactly one of a→b and b→a owns it. */
inline bool ownsEdge(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by) {
    return by < ay || (by == ay && bx > ax);
}

inline std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/**
 * One triangle in a page's texel space, ordered to positive area. A texel (x, y) is covered when
 * its centre (x + 0.5, y + 0.5) is inside, with a fill rule that covers a centre on an edge
 * shared by two triangles exactly once: the texels of a UV chart are all visited, none twice.
 */
struct UvTriangle {
    std::int64_t x[3], y[3];
    int corner[3]; // the triangle's corner (0..2) in each slot
    std::int64_t area;
    std::int64_t bias[3];       // per edge k (opposite slot k): 0 if it owns its points, else -1
    int minX, maxX, minY, maxY; // texels whose centres may be inside (not wrapped)
};

inline bool setUpUv(const glm::vec2 uv[3], int width, int height, UvTriangle& r) {
    for (int c = 0; c < 3; ++c) {
        const double tx = double(uv[c].x) * width, ty = double(uv[c].y) * height;
        if (!(std::fabs(tx) < kMaxTexelCoord) || !(std::fabs(ty) < kMaxTexelCoord))
            return false;
        // Rounded half away from zero, as llround would (without the library call).
        r.x[c] = std::int64_t(tx * double(kSub) + (tx < 0.0 ? -0.5 : 0.5));
        r.y[c] = std::int64_t(ty * double(kSub) + (ty < 0.0 ? -0.5 : 0.5));
        r.corner[c] = c;
    }
    r.area = edgeFunction(r.x[0], r.y[0], r.x[1], r.y[1], r.x[2], r.y[2]);
    if (r.area == 0)
        return false;
    if (r.area < 0) {
        // A mirrored chart: order the corners so the edge functions are positive inside.
        std::swap(r.x[1], r.x[2]);
        std::swap(r.y[1], r.y[2]);
        std::swap(r.corner[1], r.corner[2]);
        r.area = -r.area;
    }
    for (int k = 0; k < 3; ++k) {
        const int a = (k + 1) % 3, b = (k + 2) % 3;
        r.bias[k] = ownsEdge(r.x[a], r.y[a], r.x[b], r.y[b]) ? 0 : -1;
    }
    const std::int64_t minX = std::min({r.x[0], r.x[1], r.x[2]});
    const std::int64_t maxX = std::max({r.x[0], r.x[1], r.x[2]});
    const std::int64_t minY = std::min({r.y[0], r.y[1], r.y[2]});
    const std::int64_t maxY = std::max({r.y[0], r.y[1], r.y[2]});
    // Texel x has its centre at x * kSub + kSub / 2.
    r.minX = int(-floorDiv(-(minX - kSub / 2), kSub));
    r.maxX = int(floorDiv(maxX - kSub / 2, kSub));
    r.minY = int(-floorDiv(-(minY - kSub / 2), kSub));
    r.maxY = int(floorDiv(maxY - kSub / 2, kSub));
    return r.minX <= r.maxX && r.minY <= r.maxY;
}

/** How edge k's function changes from a texel to the next one to its right. */
inline std::int64_t edgeStepX(const UvTriangle& r, int k) {
    const int a = (k + 1) % 3, b = (k + 2) % 3;
    return -(r.y[b] - r.y[a]) * kSub;
}

/**
 * Calls fn(y, e) for every row y in [y0, y1], e[k] the edge function k at the centre of texel
 * (x0, y); the texel (x, y) is covered when e[k] + (x - x0) * edgeStepX(r, k) + r.bias[k] >= 0
 * for every k.
 */
template <typename Fn> inline void forRowsOf(const UvTriangle& r, int x0, int y0, int y1, Fn&& fn) {
    const std::int64_t px = std::int64_t(x0) * kSub + kSub / 2;
    for (int y = y0; y <= y1; ++y) {
        const std::int64_t py = std::int64_t(y) * kSub + kSub / 2;
        std::int64_t e[3];
        for (int k = 0; k < 3; ++k) {
            const int a = (k + 1) % 3, b = (k + 2) % 3;
            e[k] = edgeFunction(r.x[a], r.y[a], r.x[b], r.y[b], px, py);
        }
        fn(y, static_cast<const std::int64_t*>(e));
    }
}

/**
 * Whether the edge functions at every texel centre of the triangle's box fit in 31 bits, so that
 * they (taken modulo 2^32 in 32-bit lanes) and their float conversions are exact. A centre lies
 * within half a texel of the triangle's extent W × H, so |e| <= 2·W·H + kSub·(W + H).
 */
inline bool edgesFitInt32(const UvTriangle& r) {
    const std::int64_t w = std::max({r.x[0], r.x[1], r.x[2]}) - std::min({r.x[0], r.x[1], r.x[2]});
    const std::int64_t h = std::max({r.y[0], r.y[1], r.y[2]}) - std::min({r.y[0], r.y[1], r.y[2]});
    constexpr std::int64_t kLimit = std::int64_t(1) << 30;
    return w < kLimit && h < kLimit && 2 * w * h + kSub * (w + h) < kLimit;
}

/**
 * Calls fn(x, y, e0, e1, e2) for every covered texel (x, y) of r in [x0, x1] × [y0, y1]
 * (unwrapped indices); e_k / r.area is the barycentric weight of slot k.
 */
template <typename Fn>
inline void scanUv(const UvTriangle& r, int x0, int x1, int y0, int y1, Fn&& fn) {
    const std::int64_t stepX[3] = {edgeStepX(r, 0), edgeStepX(r, 1), edgeStepX(r, 2)};
    forRowsOf(r, x0, y0, y1, [&](int y, const std::int64_t* start) {
        std::int64_t e[3] = {start[0], start[1], start[2]};
        for (int x = x0; x <= x1; ++x) {
            if (e[0] + r.bias[0] >= 0 && e[1] + r.bias[1] >= 0 && e[2] + r.bias[2] >= 0)
                fn(x, y, e[0], e[1], e[2]);
            e[0] += stepX[0];
            e[1] += stepX[1];
            e[2] += stepX[2];
        }
    });
}

inline int wrapIndex(int i, int size) {
    const int m = i % size;
    return m < 0 ? m + size : m;
}

} // namespace core::uv
