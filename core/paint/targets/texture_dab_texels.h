// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to texture_target_dab.cpp: the first pass's walk over a triangle's texels in its UV
// raster (TextureTarget::paint()), with each texel's window position, its distance from the
// dab's centre and the round tip's weight there, one texel or four lanes at a time.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "core/paint/brush/brush_tips.h"
#include "core/paint/targets/paint_context.h"
#include "core/paint/targets/uv_raster.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace core::dab_texels {

#if defined(__SSE2__)
/** roundFalloff() at four distances: the same operations, lane by lane. */
inline __m128 roundFalloff4(__m128 d, float r, float hardness) {
    if (!(r > 0.0f))
        return _mm_setzero_ps();
    const float h = std::clamp(hardness, 0.0f, 1.0f);
    const __m128 one = _mm_set1_ps(1.0f);
    const __m128 t = _mm_div_ps(d, _mm_set1_ps(r));
    const __m128 s = _mm_div_ps(_mm_sub_ps(t, _mm_set1_ps(h)), _mm_set1_ps(1.0f - h));
    const __m128 rim =
        _mm_sub_ps(one, _mm_mul_ps(_mm_mul_ps(s, s), _mm_sub_ps(_mm_set1_ps(3.0f),
                                                                _mm_mul_ps(_mm_set1_ps(2.0f), s))));
    const __m128 core = _mm_cmple_ps(t, _mm_set1_ps(h));
    const __m128 weight = _mm_or_ps(_mm_and_ps(core, one), _mm_andnot_ps(core, rim));
    return _mm_andnot_ps(_mm_cmpge_ps(d, _mm_set1_ps(r)), weight);
}
#endif

/**
 * The dab's constants the first pass reads per texel. The texel loop holds a copy, which the
 * compiler can keep in registers across the loop (the context's members would be reloaded after
 * every store).
 */
struct DabConstants {
    const std::uint32_t* window = nullptr;
    float windowX = 0.0f, windowY = 0.0f, windowW = 0.0f, windowH = 0.0f;
    std::size_t windowStride = 0;
    // Texels up to a pixel outside the map's box can be at its surface's outline.
    float nearW = 0.0f, nearH = 0.0f;
    const TriangleSetup* setups = nullptr;
    glm::vec2 center{0.0f};
    const TipSampler* tip = nullptr;
    float radius = 0.0f;
    bool roundTip = true;
    float tipRadius = 0.0f, hardness = 0.0f;
    float toleranceScale = 0.0f, toleranceOffset = 0.0f;
    float dabOpacity = 0.0f;
};

/**
 * What the first pass visits of a triangle: its raster on its page, the texels [x0, x1] ×
 * [y0, y1] to look at (unwrapped; wrap: some lie outside the page), and its corners in the view
 * in the raster's order.
 */
struct TriangleTexels {
    uv::UvTriangle r;
    int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    bool wrap = false;
    std::uint32_t page = 0;
    int width = 0, height = 0;
    ProjectedVertex p[3];
    float invArea = 0.0f;
};

// The walks in an unnamed namespace: their instantiations, like those of the uv raster's loops
// they call, keep internal linkage, so the compiler inlines them into the one file's texel loop
// as it would its own functions (shared ones it keeps apart, the visit's state then in memory).
namespace {

/**
 * Calls visit(x, y, l0, l1, l2, px, py, distance, near, round) for every covered texel of t
 * (see TextureDab::TexelVisit), one at a time; visit.room(n) readies room for n texels.
 */
template <typename Visit>
[[gnu::always_inline]] inline void visitOneByOne(const TriangleTexels& t, const DabConstants& k,
                                                 Visit& visit) {
    const ProjectedVertex* p = t.p;
    const float invArea = t.invArea;
    uv::scanUv(t.r, t.x0, t.x1, t.y0, t.y1,
               [&](int x, int y, std::int64_t e0, std::int64_t e1, std::int64_t e2) {
                   visit.room(1);
                   const float l0 = float(e0) * invArea, l1 = float(e1) * invArea,
                               l2 = float(e2) * invArea;
                   const float w = l0 * p[0].w + l1 * p[1].w + l2 * p[2].w;
                   const float px = (l0 * p[0].sx + l1 * p[1].sx + l2 * p[2].sx) / w;
                   const float py = (l0 * p[0].sy + l1 * p[1].sy + l2 * p[2].sy) / w;
                   const float fx = px - k.windowX, fy = py - k.windowY;
                   const float distance = glm::length(glm::vec2(px, py) - k.center);
                   const bool near = w > kMinW && distance < k.radius && fx >= -1.0f &&
                                     fx < k.nearW && fy >= -1.0f && fy < k.nearH;
                   visit(x, y, l0, l1, l2, px, py, distance, near,
                         k.roundTip && near ? roundFalloff(distance, k.tipRadius, k.hardness)
                                            : 0.0f);
               });
}

#if defined(__SSE2__)
/** The constants of visitInFours(), in four lanes. */
struct LaneConstants {
    __m128 invA, w0, w1, w2, sx0, sx1, sx2, sy0, sy1, sy2;
    __m128 minW, minusOne, winX, winY, limX, limY, cx, cy, rad;
    bool roundTip;
    float tipRadius, hardness;

    LaneConstants(const TriangleTexels& t, const DabConstants& k)
        : invA(_mm_set1_ps(t.invArea)), w0(_mm_set1_ps(t.p[0].w)), w1(_mm_set1_ps(t.p[1].w)),
          w2(_mm_set1_ps(t.p[2].w)), sx0(_mm_set1_ps(t.p[0].sx)), sx1(_mm_set1_ps(t.p[1].sx)),
          sx2(_mm_set1_ps(t.p[2].sx)), sy0(_mm_set1_ps(t.p[0].sy)), sy1(_mm_set1_ps(t.p[1].sy)),
          sy2(_mm_set1_ps(t.p[2].sy)), minW(_mm_set1_ps(kMinW)), minusOne(_mm_set1_ps(-1.0f)),
          winX(_mm_set1_ps(k.windowX)), winY(_mm_set1_ps(k.windowY)), limX(_mm_set1_ps(k.nearW)),
          limY(_mm_set1_ps(k.nearH)), cx(_mm_set1_ps(k.center.x)), cy(_mm_set1_ps(k.center.y)),
          rad(_mm_set1_ps(k.radius)), roundTip(k.roundTip), tipRadius(k.tipRadius),
          hardness(k.hardness) {}
};

/** Four texels of a row with a covered one: what the visit takes of each lane. */
struct TexelGroup {
    alignas(16) float l[3][4];
    alignas(16) float px[4], py[4], d[4], round[4];
    int x, y, covered, near;
};

/**
 * Group q's lanes from the edge functions ek at its texels (q.x, q.y and q.covered are the
 * caller's): the operations of visitOneByOne(), lane by lane.
 */
[[gnu::always_inline]] inline void computeGroup(const LaneConstants& c, const __m128i ek[3],
                                                TexelGroup& q) {
    const __m128 l0 = _mm_mul_ps(_mm_cvtepi32_ps(ek[0]), c.invA);
    const __m128 l1 = _mm_mul_ps(_mm_cvtepi32_ps(ek[1]), c.invA);
    const __m128 l2 = _mm_mul_ps(_mm_cvtepi32_ps(ek[2]), c.invA);
    const __m128 w =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(l0, c.w0), _mm_mul_ps(l1, c.w1)), _mm_mul_ps(l2, c.w2));
    const __m128 px = _mm_div_ps(
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(l0, c.sx0), _mm_mul_ps(l1, c.sx1)), _mm_mul_ps(l2, c.sx2)),
        w);
    const __m128 py = _mm_div_ps(
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(l0, c.sy0), _mm_mul_ps(l1, c.sy1)), _mm_mul_ps(l2, c.sy2)),
        w);
    const __m128 fx = _mm_sub_ps(px, c.winX), fy = _mm_sub_ps(py, c.winY);
    const __m128 dx = _mm_sub_ps(px, c.cx), dy = _mm_sub_ps(py, c.cy);
    const __m128 d = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)));
    const __m128 near =
        _mm_and_ps(_mm_and_ps(_mm_and_ps(_mm_cmpgt_ps(w, c.minW), _mm_cmplt_ps(d, c.rad)),
                              _mm_and_ps(_mm_cmpge_ps(fx, c.minusOne), _mm_cmplt_ps(fx, c.limX))),
                   _mm_and_ps(_mm_cmpge_ps(fy, c.minusOne), _mm_cmplt_ps(fy, c.limY)));
    q.near = _mm_movemask_ps(near);
    _mm_store_ps(q.l[0], l0);
    _mm_store_ps(q.l[1], l1);
    _mm_store_ps(q.l[2], l2);
    _mm_store_ps(q.px, px);
    _mm_store_ps(q.py, py);
    _mm_store_ps(q.d, d);
    _mm_store_ps(q.round, c.roundTip && q.near != 0 ? roundFalloff4(d, c.tipRadius, c.hardness)
                                                    : _mm_setzero_ps());
}

/**
 * visitOneByOne() four texels of a row at a time (t's rows are four or more texels long, its
 * edge functions fit 32 bits): the same operations in the same order, lane by lane, so the same
 * floats.
 */
template <typename Visit>
[[gnu::always_inline]] inline void visitInFours(const TriangleTexels& t, const DabConstants& k,
                                                Visit& visit) {
    const LaneConstants lanes(t, k);
    const int x0 = t.x0, x1 = t.x1;
    __m128i step4[3], bias[3];
    std::int32_t step[3];
    for (int i = 0; i < 3; ++i) {
        step[i] = std::int32_t(uv::edgeStepX(t.r, i));
        step4[i] = _mm_set1_epi32(std::int32_t(4u * std::uint32_t(step[i])));
        bias[i] = _mm_set1_epi32(std::int32_t(t.r.bias[i]));
    }
    const __m128i minusOneI = _mm_set1_epi32(-1);
    // The groups of four texels with a covered one, computed ahead of their visits (so the
    // divisions and square roots of several groups overlap), then visited in the same order.
    constexpr int kGroups = 16;
    TexelGroup groups[kGroups];
    int pending = 0;
    const auto visitGroups = [&] {
        visit.room(std::size_t(pending) * 4);
        for (int g = 0; g < pending; ++g) {
            const TexelGroup& q = groups[g];
            for (unsigned bits = unsigned(q.covered); bits != 0; bits &= bits - 1) {
                const int i = std::countr_zero(bits);
                visit(q.x + i, q.y, q.l[0][i], q.l[1][i], q.l[2][i], q.px[i], q.py[i], q.d[i],
                      (q.near >> i) & 1, q.round[i]);
            }
        }
        pending = 0;
    };
    uv::forRowsOf(t.r, x0, t.y0, t.y1, [&](int y, const std::int64_t e[3]) {
        // Lane i: texel x + i. Past x1 the values may wrap; those lanes are unused.
        __m128i ek[3];
        for (int i = 0; i < 3; ++i) {
            const auto at = [&](int lane) {
                return std::int32_t(std::uint32_t(e[i]) +
                                    std::uint32_t(lane) * std::uint32_t(step[i]));
            };
            ek[i] = _mm_set_epi32(at(3), at(2), at(1), at(0));
        }
        for (int x = x0; x <= x1; x += 4) {
            const __m128i in = _mm_and_si128(
                _mm_and_si128(_mm_cmpgt_epi32(_mm_add_epi32(ek[0], bias[0]), minusOneI),
                              _mm_cmpgt_epi32(_mm_add_epi32(ek[1], bias[1]), minusOneI)),
                _mm_cmpgt_epi32(_mm_add_epi32(ek[2], bias[2]), minusOneI));
            int covered = _mm_movemask_ps(_mm_castsi128_ps(in));
            if (x1 - x < 3)
                covered &= (1 << (x1 - x + 1)) - 1;
            if (covered != 0) {
                TexelGroup& q = groups[pending];
                computeGroup(lanes, ek, q);
                q.covered = covered;
                q.x = x;
                q.y = y;
                if (++pending == kGroups)
                    visitGroups();
            }
            for (int i = 0; i < 3; ++i)
                ek[i] = _mm_add_epi32(ek[i], step4[i]);
        }
    });
    visitGroups();
}
#endif

} // namespace

} // namespace core::dab_texels
