// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/depth/cpu_capture.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "core/base/parallel.h"

namespace core {

namespace {

constexpr int kSubpixelBits = 8;
constexpr std::int64_t kSubpixel = std::int64_t(1) << kSubpixelBits;
constexpr double kGuardBand = double(1 << 20); // pixels; keeps edge products inside int64

/** One triangle ready to rasterize, vertices ordered so the edge functions are positive. */
struct Setup {
    std::int64_t x[3], y[3]; // window position in 1/256 pixel (y down)
    float invW[3];           // 1 / clip w
    float depthOverW[3];     // positive view depth / clip w
    float ndcZ[3];
    int minX, minY, maxX, maxY; // pixel bounding box, clamped to the view
    std::int64_t area2;
    bool valid;
};

/** Edge function of a→b at p: positive on the inner side of a positive-area triangle. */
inline std::int64_t edge(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by,
                         std::int64_t px, std::int64_t py) {
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

/** Fill rule tie-break for a point exactly on edge a→b: exactly one of a→b and b→a owns it. */
inline bool ownsEdge(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by) {
    return by < ay || (by == ay && bx > ax);
}

/** Whether triangle t's back face is captured although back faces are culled. */
bool shown(const CpuCaptureOptions& options, int t) {
    return !options.shownBackFaces.empty() &&
           std::binary_search(options.shownBackFaces.begin(), options.shownBackFaces.end(),
                              std::uint32_t(t));
}

Setup setUp(const Mesh& mesh, std::size_t t, const View& view, const glm::mat4& viewProj,
            const glm::mat4& viewMatrix, bool cullBackFaces) {
    Setup s{};
    s.valid = false;
    double wx[3], wy[3];
    for (int c = 0; c < 3; ++c) {
        const std::uint32_t index = mesh.indices[3 * t + std::size_t(c)];
        if (index >= mesh.positions.size())
            return s;
        const glm::vec4 p(mesh.positions[index], 1.0f);
        const glm::vec4 clip = viewProj * p;
        if (!(clip.w > 0.0f))
            return s;
        const float depth = -(viewMatrix * p).z;
        const double nx = double(clip.x) / clip.w, ny = double(clip.y) / clip.w;
        wx[c] = (nx + 1.0) * 0.5 * view.width;
        wy[c] = (1.0 - ny) * 0.5 * view.height;
        if (!(std::abs(wx[c]) < kGuardBand && std::abs(wy[c]) < kGuardBand))
            return s;
        s.x[c] = std::llround(wx[c] * double(kSubpixel));
        s.y[c] = std::llround(wy[c] * double(kSubpixel));
        s.invW[c] = 1.0f / clip.w;
        s.depthOverW[c] = depth / clip.w;
        s.ndcZ[c] = clip.z / clip.w;
    }
    s.area2 = edge(s.x[0], s.y[0], s.x[1], s.y[1], s.x[2], s.y[2]);
    // Counter-clockwise in NDC (y up) is clockwise in window coordinates (y down): area2 < 0.
    if (s.area2 == 0 || (cullBackFaces && s.area2 > 0))
        return s;
    if (s.area2 < 0) {
        std::swap(s.x[1], s.x[2]);
        std::swap(s.y[1], s.y[2]);
        std::swap(s.invW[1], s.invW[2]);
        std::swap(s.depthOverW[1], s.depthOverW[2]);
        std::swap(s.ndcZ[1], s.ndcZ[2]);
        s.area2 = -s.area2;
    }
    const double minX = std::min({wx[0], wx[1], wx[2]}), maxX = std::max({wx[0], wx[1], wx[2]});
    const double minY = std::min({wy[0], wy[1], wy[2]}), maxY = std::max({wy[0], wy[1], wy[2]});
    // Pixels whose centre (x + 0.5) can lie inside, with a little slack for the snapping.
    s.minX = std::max(0, int(std::floor(minX - 0.5)));
    s.maxX = std::min(view.width - 1, int(std::ceil(maxX - 0.5)));
    s.minY = std::max(0, int(std::floor(minY - 0.5)));
    s.maxY = std::min(view.height - 1, int(std::ceil(maxY - 0.5)));
    s.valid = s.minX <= s.maxX && s.minY <= s.maxY;
    return s;
}

/** Calls emit(pixel, weights of the ordered vertices) for each covered pixel centre in rows
 * [y0, y1). */
template <typename Emit> void rasterize(const Setup& s, int width, int y0, int y1, Emit&& emit) {
    const int rowBegin = std::max(s.minY, y0), rowEnd = std::min(s.maxY + 1, y1);
    // Edge k is opposite vertex k: e0 = v1→v2, e1 = v2→v0, e2 = v0→v1.
    const int a[3] = {1, 2, 0}, b[3] = {2, 0, 1};
    std::int64_t bias[3];
    for (int k = 0; k < 3; ++k)
        bias[k] = ownsEdge(s.x[a[k]], s.y[a[k]], s.x[b[k]], s.y[b[k]]) ? 0 : -1;
    for (int py = rowBegin; py < rowEnd; ++py) {
        const std::int64_t cy = std::int64_t(py) * kSubpixel + kSubpixel / 2;
        for (int px = s.minX; px <= s.maxX; ++px) {
            const std::int64_t cx = std::int64_t(px) * kSubpixel + kSubpixel / 2;
            std::int64_t e[3];
            bool inside = true;
            for (int k = 0; k < 3 && inside; ++k) {
                e[k] = edge(s.x[a[k]], s.y[a[k]], s.x[b[k]], s.y[b[k]], cx, cy);
                inside = e[k] + bias[k] >= 0;
            }
            if (inside)
                emit(std::size_t(py) * std::size_t(width) + std::size_t(px), e);
        }
    }
}

} // namespace

DepthStack captureDepthLayersCpu(const Mesh& mesh, const View& view,
                                 const CpuCaptureOptions& options) {
    DepthStack stack;
    if (view.width <= 0 || view.height <= 0)
        return stack;
    stack.width = view.width;
    stack.height = view.height;
    const std::size_t pixels = stack.pixelCount();
    stack.offsets.assign(pixels + 1, 0);

    const std::size_t triangles = mesh.triangleCount();
    std::vector<Setup> setups(triangles);
    const glm::mat4 viewProj = view.proj * view.view;
    parallelRanges(int(triangles), options.threads, [&](int, int t0, int t1) {
        for (int t = t0; t < t1; ++t)
            setups[std::size_t(t)] = setUp(mesh, std::size_t(t), view, viewProj, view.view,
                                           options.cullBackFaces && !shown(options, t));
    });

    // The view depth of one covered pixel; false when outside the near/far planes.
    auto sample = [](const Setup& s, const std::int64_t* e, float& depth) {
        const double l0 = double(e[0]) / double(s.area2), l1 = double(e[1]) / double(s.area2),
                     l2 = double(e[2]) / double(s.area2);
        const double ndcZ = l0 * s.ndcZ[0] + l1 * s.ndcZ[1] + l2 * s.ndcZ[2];
        if (!(ndcZ >= -1.0 && ndcZ <= 1.0))
            return false;
        // Perspective-correct: depth / w and 1 / w are affine on screen.
        const double iw = l0 * s.invW[0] + l1 * s.invW[1] + l2 * s.invW[2];
        depth = float((l0 * s.depthOverW[0] + l1 * s.depthOverW[1] + l2 * s.depthOverW[2]) / iw);
        return true;
    };

    // Pass 1: count fragments per pixel, each band of rows on its own thread.
    std::vector<std::uint32_t> counts(pixels, 0);
    parallelRanges(view.height, options.threads, [&](int, int y0, int y1) {
        for (const Setup& s : setups) {
            if (!s.valid || s.maxY < y0 || s.minY >= y1)
                continue;
            rasterize(s, view.width, y0, y1, [&](std::size_t p, const std::int64_t* e) {
                float unused;
                if (sample(s, e, unused))
                    ++counts[p];
            });
        }
    });
    std::uint64_t total = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        stack.offsets[p] = std::uint32_t(std::min<std::uint64_t>(total, 0xffffffffu));
        total += counts[p];
    }
    if (total >= 0xffffffffu) { // cannot be indexed by uint32: give up rather than wrap
        stack.offsets.assign(pixels + 1, 0);
        return stack;
    }
    stack.offsets[pixels] = std::uint32_t(total);
    stack.depth.resize(total);
    stack.triangle.resize(total);

    // Pass 2: write the fragments in triangle order, then sort each pixel front to back.
    parallelRanges(view.height, options.threads, [&](int, int y0, int y1) {
        std::vector<std::uint32_t> cursor(stack.offsets.begin() + std::ptrdiff_t(y0) * view.width,
                                          stack.offsets.begin() + std::ptrdiff_t(y1) * view.width);
        const std::size_t firstPixel = std::size_t(y0) * std::size_t(view.width);
        for (std::size_t t = 0; t < setups.size(); ++t) {
            const Setup& s = setups[t];
            if (!s.valid || s.maxY < y0 || s.minY >= y1)
                continue;
            rasterize(s, view.width, y0, y1, [&](std::size_t p, const std::int64_t* e) {
                float depth;
                if (!sample(s, e, depth))
                    return;
                const std::uint32_t f = cursor[p - firstPixel]++;
                stack.depth[f] = depth;
                stack.triangle[f] = std::uint32_t(t);
            });
        }
        std::vector<std::uint32_t> order;
        std::vector<float> depth;
        std::vector<std::uint32_t> tri;
        for (std::size_t p = firstPixel; p < std::size_t(y1) * std::size_t(view.width); ++p) {
            const std::uint32_t f0 = stack.offsets[p], n = stack.offsets[p + 1] - f0;
            if (n < 2)
                continue;
            order.resize(n);
            for (std::uint32_t i = 0; i < n; ++i)
                order[i] = i;
            std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) {
                const float di = stack.depth[f0 + i], dj = stack.depth[f0 + j];
                return di != dj ? di < dj : stack.triangle[f0 + i] < stack.triangle[f0 + j];
            });
            depth.assign(stack.depth.begin() + f0, stack.depth.begin() + f0 + n);
            tri.assign(stack.triangle.begin() + f0, stack.triangle.begin() + f0 + n);
            for (std::uint32_t i = 0; i < n; ++i) {
                stack.depth[f0 + i] = depth[order[i]];
                stack.triangle[f0 + i] = tri[order[i]];
            }
        }
    });
    return stack;
}

} // namespace core
