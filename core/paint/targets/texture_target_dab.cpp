// SPDX-License-Identifier: GPL-3.0-or-later
// The texel loop of a dab on a texture target (TextureTarget::paint), in two passes. The first
// only reads: for each triangle the dab looks at, the texels the dab reaches on its surface and
// their falloff weight (on both cores for a large dab, the triangles in chunks). Between them
// each texel gets the stroke's slot of its tile. The second raises the texels' stroke coverage
// and writes them, each tile on one core in the triangles' order, so the bytes are those of one
// pass over the triangles in order, whatever the number of threads.
#include <algorithm>
#include <atomic>
#include <bit>
#include <limits>
#include <mutex>
#include <utility>

#include <glm/common.hpp>

#include "core/base/helper_threads.h"
#include "core/paint/targets/paint_context.h"
#include "core/paint/targets/texture_tile_layout.h"
#include "core/paint/targets/uv_raster.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace core {

using uv::scanUv;
using uv::setUpUv;
using uv::UvTriangle;
using uv::wrapIndex;

namespace {

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

/** Triangles a worker of the first pass takes at a time. */
constexpr std::size_t kDabChunk = 32;
/**
 * A dab looking at fewer triangles runs its first pass on the calling thread alone: a small
 * brush's dab costs less than starting a thread.
 */
constexpr std::size_t kDabParallelFrom = 256;
/** The second pass shares its tiles among the helpers from this many texels that take paint. */
constexpr std::size_t kSecondPassParallelFrom = 2048;

} // namespace

const PaintChanges& TextureTarget::paint(const DepthLayers& layers, const Dab& dab) {
    Context& c = *m_context;
    c.changes.clear();
    if (!c.inStroke || m_mode == StrokeMode::Nothing || !c.beginDab(layers, dab))
        return c.changes;
    const Mesh& m = *c.mesh;
    const std::size_t count = c.setups.size();
    const float dabOpacity = c.dabOpacity, flowOpacity = c.flowOpacity;
    float* triangleCover = c.triangleCover.data();

    // First pass: reads the mesh, the view, the map and the stroke's coverage before this dab.
    {
        // The dab's constants as locals, which the compiler can keep in registers across the
        // texel loop (members would be reloaded after every store).
        const std::uint32_t* window = c.window.data();
        const float windowX = float(c.windowX), windowY = float(c.windowY);
        const float windowW = float(c.windowW), windowH = float(c.windowH);
        const std::size_t windowStride = std::size_t(c.windowW);
        const TriangleSetup* setups = c.setups.data();
        const glm::vec2 center = c.center;
        const TipSampler& tip = c.tip;
        const float radius = c.radius;
        const bool roundTip = !tip.textured();
        const float tipRadius = tip.radius(), hardness = tip.hardness();
        const float toleranceScale = c.toleranceScale, toleranceOffset = c.toleranceOffset;
        const DepthStack& stack = layers.stack;

        // Triangle si: its texels the dab reaches go to texels from used on (used counts them),
        // counted per slot of their tile in slotCounts (those of tiles without a slot get theirs
        // between the passes); what the second pass needs of it.
        const auto scan = [&](std::size_t si, std::vector<DabTexel>& texels, std::size_t& used,
                              std::uint32_t* slotCounts) {
            DabTriangle out;
            out.begin = out.end = std::uint32_t(used);
            const TriangleSetup& s = setups[si];
            // Every texel of the triangle is at this dab's opacity already: none can take paint.
            if (triangleCover[s.triangle] >= dabOpacity)
                return out;
            const auto own = std::uint32_t(si);
            const std::uint32_t pageIndex = m_materialPage[m.triangleMaterial[s.triangle]];
            const Page& page = m_pages[pageIndex];
            const int width = page.image.width, height = page.image.height;
            const auto tilesX = std::uint32_t(page.tilesX);
            glm::vec2 uv[3];
            for (int k = 0; k < 3; ++k)
                uv[k] = m.uvs[s.vertex[std::size_t(k)]];
            UvTriangle r;
            if (!setUpUv(uv, width, height, r))
                return out;
            int x0 = r.minX, x1 = r.maxX, y0 = r.minY, y1 = r.maxY;
            // A triangle larger than the dab: visit only the texels that can land in the map.
            const float sMinX = std::min({s.screen[0].x, s.screen[1].x, s.screen[2].x});
            const float sMaxX = std::max({s.screen[0].x, s.screen[1].x, s.screen[2].x});
            const float sMinY = std::min({s.screen[0].y, s.screen[1].y, s.screen[2].y});
            const float sMaxY = std::max({s.screen[0].y, s.screen[1].y, s.screen[2].y});
            const bool inside =
                sMinX >= float(c.windowX - 2) && sMaxX <= float(c.windowX + c.windowW + 2) &&
                sMinY >= float(c.windowY - 2) && sMaxY <= float(c.windowY + c.windowH + 2);
            if (!inside && double(x1 - x0 + 1) * double(y1 - y0 + 1) > 64.0) {
                glm::dvec2 texel[3];
                for (int k = 0; k < 3; ++k)
                    texel[k] = glm::dvec2(double(uv[k].x) * width, double(uv[k].y) * height);
                double minX, maxX, minY, maxY;
                if (c.windowPreimage(s, texel, minX, maxX, minY, maxY)) {
                    x0 = std::max(x0, int(std::floor(minX)) - 1);
                    x1 = std::min(x1, int(std::floor(maxX)) + 1);
                    y0 = std::max(y0, int(std::floor(minY)) - 1);
                    y1 = std::min(y1, int(std::floor(maxY)) + 1);
                }
            }
            if (x0 > x1 || y0 > y1)
                return out;
            if (double(x1 - x0 + 1) * double(y1 - y0 + 1) > 4.0 * double(width) * double(height))
                return out; // spread over many repeats of the texture (see create())
            const bool wrap = x0 < 0 || y0 < 0 || x1 >= width || y1 >= height;

            ProjectedVertex p[3];
            for (int k = 0; k < 3; ++k)
                p[k] = c.vertices[s.vertex[std::size_t(r.corner[k])]];
            const float invArea = float(1.0 / double(r.area));
            const std::int32_t* tileSlots = c.tileSlot[pageIndex].data();
            // The tile of the texel looked at: its slot and stroke coverage (nullptr: no slot
            // yet, all 0).
            std::uint32_t seenTile = kNone;
            std::int32_t seenSlot = -1;
            const float* seenAlpha = nullptr;
            int seenWidth = 0;
            // The least coverage of the texels that take nothing from this dab (the second pass
            // adds the others): at most what it is after the dab, as triangleCover needs.
            float least = std::numeric_limits<float>::infinity();
            // The slot of the texels found so far while they share one (kNoSlotYet: none found).
            constexpr std::int32_t kNoSlotYet = -2;
            std::int32_t sharedSlot = kNoSlotYet;

            // Texels holds room for n more from used on after room(n) (written through
            // outTexels). It keeps its size from dab to dab, so that its texels are not set
            // to their defaults before every dab.
            DabTexel* outTexels = texels.data();
            const auto room = [&](std::size_t n) {
                if (texels.size() < used + n) {
                    texels.resize(std::max(used + n, 2 * texels.size()));
                    outTexels = texels.data();
                }
            };
            // A texel inside the triangle, at barycentric weights l and window position (px,
            // py); near: in front of the eye, within a pixel of the map's box and inside the
            // dab's disc; round: the round tip's weight there (if the tip is round). Rejected
            // texels give their coverage to least. Inlined in both paths below.
            const auto visit = [&](int x, int y, float l0, float l1, float l2, float px, float py,
                                   float distance, bool near, float round)
                __attribute__((always_inline)) {
                const int tx = wrap ? wrapIndex(x, width) : x;
                const int ty = wrap ? wrapIndex(y, height) : y;
                const std::uint32_t tile =
                    std::uint32_t(ty / kTextureTile) * tilesX + std::uint32_t(tx / kTextureTile);
                if (tile != seenTile) {
                    seenTile = tile;
                    seenSlot = tileSlots[tile];
                    seenAlpha =
                        seenSlot >= 0 ? c.slots[std::size_t(seenSlot)].alpha.data() : nullptr;
                    seenWidth = std::min(kTextureTile, width - (tx / kTextureTile) * kTextureTile);
                }
                const std::size_t local = std::size_t(ty % kTextureTile) * std::size_t(seenWidth) +
                                          std::size_t(tx % kTextureTile);
                const float old = seenAlpha ? seenAlpha[local] : 0.0f;
                // The coverage never falls in a stroke and a dab raises it to its opacity at
                // most: a texel there already takes nothing from this dab.
                if (old >= dabOpacity || !near) {
                    least = std::min(least, old);
                    return;
                }
                // The map's fragment at the texel's pixel (as Context::mapAt()).
                const float fx = px - windowX, fy = py - windowY;
                const std::uint32_t mapped =
                    fx >= 0.0f && fx < windowW && fy >= 0.0f && fy < windowH
                        ? window[std::size_t(fy) * windowStride + std::size_t(fx)]
                        : kNone;
                // On its surface (as Context::onMapSurface()), or covered at its edge.
                if (mapped != own) {
                    const glm::vec3 point = l0 * p[0].view + l1 * p[1].view + l2 * p[2].view;
                    bool onMap = false;
                    if (mapped != kNone) {
                        const glm::vec4& plane = setups[mapped].plane;
                        onMap = plane != glm::vec4(0.0f) &&
                                std::fabs(glm::dot(glm::vec3(plane), point) + plane.w) <=
                                    -point.z * toleranceScale + toleranceOffset;
                    }
                    if (!onMap && !c.coveredAtEdge(stack, own, point, px, py)) {
                        least = std::min(least, old);
                        return;
                    }
                }
                const float weight =
                    roundTip ? round : tip.weight(glm::vec2(px, py) - center, distance);
                if (!(weight > 0.0f)) {
                    least = std::min(least, old);
                    return;
                }
                outTexels[used++] = {std::uint16_t(tx), std::uint16_t(ty), weight, seenSlot};
                if (sharedSlot != seenSlot)
                    sharedSlot = sharedSlot == kNoSlotYet ? seenSlot : -1;
                if (seenSlot >= 0)
                    ++slotCounts[seenSlot];
                else
                    out.newTiles = true;
            };
            // Texels up to a pixel outside the map's box can be at its surface's outline.
            const float nearW = windowW + 1.0f, nearH = windowH + 1.0f;
#if defined(__SSE2__)
            if (x1 - x0 >= 3 && uv::edgesFitInt32(r)) {
                // Four texels of a row at a time (rows of four or more): the same operations in
                // the same order as the one-texel path below, lane by lane, so the same floats.
                const __m128 invA = _mm_set1_ps(invArea);
                const __m128 w0 = _mm_set1_ps(p[0].w), w1 = _mm_set1_ps(p[1].w),
                             w2 = _mm_set1_ps(p[2].w);
                const __m128 sx0 = _mm_set1_ps(p[0].sx), sx1 = _mm_set1_ps(p[1].sx),
                             sx2 = _mm_set1_ps(p[2].sx);
                const __m128 sy0 = _mm_set1_ps(p[0].sy), sy1 = _mm_set1_ps(p[1].sy),
                             sy2 = _mm_set1_ps(p[2].sy);
                const __m128 minW = _mm_set1_ps(kMinW), minusOne = _mm_set1_ps(-1.0f);
                const __m128 winX = _mm_set1_ps(windowX), winY = _mm_set1_ps(windowY);
                const __m128 limX = _mm_set1_ps(nearW), limY = _mm_set1_ps(nearH);
                const __m128 cx = _mm_set1_ps(center.x), cy = _mm_set1_ps(center.y);
                const __m128 rad = _mm_set1_ps(radius);
                __m128i step4[3], bias[3];
                std::int32_t step[3];
                for (int k = 0; k < 3; ++k) {
                    step[k] = std::int32_t(uv::edgeStepX(r, k));
                    step4[k] = _mm_set1_epi32(std::int32_t(4u * std::uint32_t(step[k])));
                    bias[k] = _mm_set1_epi32(std::int32_t(r.bias[k]));
                }
                const __m128i minusOneI = _mm_set1_epi32(-1);
                // The groups of four texels with a covered one, computed ahead of their visits
                // (so the divisions and square roots of several groups overlap), then visited
                // in the same order.
                struct Group {
                    alignas(16) float l[3][4];
                    alignas(16) float px[4], py[4], d[4], round[4];
                    int x, y, covered, near;
                };
                constexpr int kGroups = 16;
                Group groups[kGroups];
                int pending = 0;
                const auto visitGroups = [&] {
                    room(std::size_t(pending) * 4);
                    for (int g = 0; g < pending; ++g) {
                        const Group& q = groups[g];
                        for (unsigned bits = unsigned(q.covered); bits != 0; bits &= bits - 1) {
                            const int i = std::countr_zero(bits);
                            visit(q.x + i, q.y, q.l[0][i], q.l[1][i], q.l[2][i], q.px[i], q.py[i],
                                  q.d[i], (q.near >> i) & 1, q.round[i]);
                        }
                    }
                    pending = 0;
                };
                uv::forRowsOf(r, x0, y0, y1, [&](int y, const std::int64_t e[3]) {
                    // Lane i: texel x + i. Past x1 the values may wrap; those lanes are unused.
                    __m128i ek[3];
                    for (int k = 0; k < 3; ++k) {
                        const auto at = [&](int i) {
                            return std::int32_t(std::uint32_t(e[k]) +
                                                std::uint32_t(i) * std::uint32_t(step[k]));
                        };
                        ek[k] = _mm_set_epi32(at(3), at(2), at(1), at(0));
                    }
                    for (int x = x0; x <= x1; x += 4) {
                        const __m128i in = _mm_and_si128(
                            _mm_and_si128(
                                _mm_cmpgt_epi32(_mm_add_epi32(ek[0], bias[0]), minusOneI),
                                _mm_cmpgt_epi32(_mm_add_epi32(ek[1], bias[1]), minusOneI)),
                            _mm_cmpgt_epi32(_mm_add_epi32(ek[2], bias[2]), minusOneI));
                        int covered = _mm_movemask_ps(_mm_castsi128_ps(in));
                        if (x1 - x < 3)
                            covered &= (1 << (x1 - x + 1)) - 1;
                        if (covered != 0) {
                            Group& q = groups[pending];
                            const __m128 l0 = _mm_mul_ps(_mm_cvtepi32_ps(ek[0]), invA);
                            const __m128 l1 = _mm_mul_ps(_mm_cvtepi32_ps(ek[1]), invA);
                            const __m128 l2 = _mm_mul_ps(_mm_cvtepi32_ps(ek[2]), invA);
                            const __m128 w =
                                _mm_add_ps(_mm_add_ps(_mm_mul_ps(l0, w0), _mm_mul_ps(l1, w1)),
                                           _mm_mul_ps(l2, w2));
                            const __m128 px = _mm_div_ps(
                                _mm_add_ps(_mm_add_ps(_mm_mul_ps(l0, sx0), _mm_mul_ps(l1, sx1)),
                                           _mm_mul_ps(l2, sx2)),
                                w);
                            const __m128 py = _mm_div_ps(
                                _mm_add_ps(_mm_add_ps(_mm_mul_ps(l0, sy0), _mm_mul_ps(l1, sy1)),
                                           _mm_mul_ps(l2, sy2)),
                                w);
                            const __m128 fx = _mm_sub_ps(px, winX), fy = _mm_sub_ps(py, winY);
                            const __m128 dx = _mm_sub_ps(px, cx), dy = _mm_sub_ps(py, cy);
                            const __m128 d =
                                _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)));
                            const __m128 near = _mm_and_ps(
                                _mm_and_ps(
                                    _mm_and_ps(_mm_cmpgt_ps(w, minW), _mm_cmplt_ps(d, rad)),
                                    _mm_and_ps(_mm_cmpge_ps(fx, minusOne), _mm_cmplt_ps(fx, limX))),
                                _mm_and_ps(_mm_cmpge_ps(fy, minusOne), _mm_cmplt_ps(fy, limY)));
                            q.near = _mm_movemask_ps(near);
                            q.covered = covered;
                            q.x = x;
                            q.y = y;
                            _mm_store_ps(q.l[0], l0);
                            _mm_store_ps(q.l[1], l1);
                            _mm_store_ps(q.l[2], l2);
                            _mm_store_ps(q.px, px);
                            _mm_store_ps(q.py, py);
                            _mm_store_ps(q.d, d);
                            _mm_store_ps(q.round, roundTip && q.near != 0
                                                      ? roundFalloff4(d, tipRadius, hardness)
                                                      : _mm_setzero_ps());
                            if (++pending == kGroups)
                                visitGroups();
                        }
                        for (int k = 0; k < 3; ++k)
                            ek[k] = _mm_add_epi32(ek[k], step4[k]);
                    }
                });
                visitGroups();
            } else
#endif
            {
                scanUv(r, x0, x1, y0, y1,
                       [&](int x, int y, std::int64_t e0, std::int64_t e1, std::int64_t e2) {
                           room(1);
                           const float l0 = float(e0) * invArea, l1 = float(e1) * invArea,
                                       l2 = float(e2) * invArea;
                           const float w = l0 * p[0].w + l1 * p[1].w + l2 * p[2].w;
                           const float px = (l0 * p[0].sx + l1 * p[1].sx + l2 * p[2].sx) / w;
                           const float py = (l0 * p[0].sy + l1 * p[1].sy + l2 * p[2].sy) / w;
                           const float fx = px - windowX, fy = py - windowY;
                           const float distance = glm::length(glm::vec2(px, py) - center);
                           const bool near = w > kMinW && distance < radius && fx >= -1.0f &&
                                             fx < nearW && fy >= -1.0f && fy < nearH;
                           visit(x, y, l0, l1, l2, px, py, distance, near,
                                 roundTip && near ? roundFalloff(distance, tipRadius, hardness)
                                                  : 0.0f);
                       });
            }
            out.scanned = true;
            out.whole = x0 == r.minX && x1 == r.maxX && y0 == r.minY && y1 == r.maxY;
            out.page = pageIndex;
            out.least = least;
            out.slot = std::max(sharedSlot, -1);
            out.end = std::uint32_t(used);
            return out;
        };

        const std::size_t chunks = (count + kDabChunk - 1) / kDabChunk;
        c.dabTriangles.resize(count);
        if (c.dabTexels.size() < chunks)
            c.dabTexels.resize(chunks);
        std::atomic<std::size_t> next{0};
        HelperThreads& helpers = HelperThreads::shared();
        const int parts = count >= kDabParallelFrom ? helpers.width() : 1;
        if (c.partSlotTexels.size() < std::size_t(parts))
            c.partSlotTexels.resize(std::size_t(parts));
        helpers.run(parts, [&](int part) {
            std::vector<std::uint32_t>& slotCounts = c.partSlotTexels[std::size_t(part)];
            slotCounts.assign(c.slotsUsed, 0u);
            for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < chunks;) {
                std::size_t used = 0;
                for (std::size_t si = k * kDabChunk, end = std::min(count, si + kDabChunk);
                     si < end; ++si)
                    c.dabTriangles[si] = scan(si, c.dabTexels[k], used, slotCounts.data());
            }
        });
        c.slotTexels.assign(c.slotsUsed, 0u);
        for (int part = 0; part < parts; ++part)
            for (std::size_t k = 0; k < c.slotsUsed; ++k)
                c.slotTexels[k] += c.partSlotTexels[std::size_t(part)][k];
    }

    // Between the passes, on this thread in the triangles' order: the texels of tiles that had
    // no slot get the stroke's slot of their tile, made where the one loop would make it (at
    // the first texel of the tile that takes paint). A new slot's coverage is all 0, as the
    // first pass took it to be.
    std::size_t reaching = 0;
    for (std::size_t si = 0; si < count; ++si) {
        const DabTriangle& found = c.dabTriangles[si];
        if (!found.scanned)
            continue;
        reaching += found.end - found.begin;
        if (!found.newTiles)
            continue;
        const auto tilesX = std::uint32_t(m_pages[found.page].tilesX);
        DabTexel* texels = c.dabTexels[si / kDabChunk].data();
        for (std::uint32_t h = found.begin; h < found.end; ++h) {
            DabTexel& texel = texels[h];
            if (texel.slot >= 0)
                continue;
            const std::uint32_t tile = std::uint32_t(texel.y / kTextureTile) * tilesX +
                                       std::uint32_t(texel.x / kTextureTile);
            texel.slot = c.slotFor(*this, found.page, tile);
            if (c.slotTexels.size() <= std::size_t(texel.slot))
                c.slotTexels.resize(std::size_t(texel.slot) + 1, 0u);
            ++c.slotTexels[std::size_t(texel.slot)];
        }
    }

    // Each tile's texels go to one part, the largest tiles first to the least loaded part.
    // The base and the paint layers' channels are written per tile; the other modes on this
    // thread alone.
    HelperThreads& helpers = HelperThreads::shared();
    const bool perTile = m_mode == StrokeMode::Base || m_mode == StrokeMode::Channels;
    const int parts = perTile && reaching >= kSecondPassParallelFrom ? helpers.width() : 1;
    c.slotPart.assign(c.slotTexels.size(), 0u);
    if (parts > 1) {
        std::vector<std::uint32_t> order;
        for (std::uint32_t k = 0; k < c.slotTexels.size(); ++k)
            if (c.slotTexels[k] > 0)
                order.push_back(k);
        std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
            return c.slotTexels[a] != c.slotTexels[b] ? c.slotTexels[a] > c.slotTexels[b] : a < b;
        });
        std::vector<std::size_t> load(std::size_t(parts), 0u);
        for (const std::uint32_t k : order) {
            const auto least =
                std::size_t(std::min_element(load.begin(), load.end()) - load.begin());
            c.slotPart[k] = std::uint8_t(least);
            load[least] += c.slotTexels[k];
        }
    }
    std::fill(c.slotTexels.begin(), c.slotTexels.end(), 0u);
    if (c.partLeast.size() < std::size_t(parts)) {
        c.partLeast.resize(std::size_t(parts));
        c.partTouched.resize(std::size_t(parts));
    }

    // Second pass: each part its tiles' texels, triangle by triangle in order, so every tile
    // sees the writes of the one loop in its order.
    const SrgbTables& srgb = SrgbTables::get();
    const bool eraser = c.brush.eraser;
    const bool onBase = m_mode == StrokeMode::Base;
    const bool onChannels = m_mode == StrokeMode::Channels;
    std::mutex allocating; // a paint layer's tile made by one part at a time
    helpers.run(parts, [&](int part) {
        std::vector<float>& partLeast = c.partLeast[std::size_t(part)];
        partLeast.assign(count, std::numeric_limits<float>::infinity());
        std::vector<std::pair<std::uint64_t, std::uint32_t>>& firsts =
            c.partTouched[std::size_t(part)];
        firsts.clear();
        std::array<std::uint8_t*, kPaintChannels> channelTiles{};
        std::int32_t lastSlot = -1;
        StrokeTile* st = nullptr;
        float* alpha = nullptr;
        const float* base = nullptr;
        const std::uint8_t* before = nullptr;
        bool tileTouched = false;
        std::size_t tileWidth = 0, tileTexels = 0;
        const std::uint8_t* slotPart = c.slotPart.data();
        // The page of the triangle at hand.
        std::uint32_t pageIndex = kNone;
        Page* page = nullptr;
        int width = 0, height = 0;
        std::uint8_t* pixels = nullptr;
        for (std::size_t si = 0; si < count; ++si) {
            const DabTriangle& found = c.dabTriangles[si];
            // A triangle whose texels all are in another part's tile.
            if (!found.scanned || (found.slot >= 0 && slotPart[found.slot] != part))
                continue;
            const bool shared = found.slot >= 0;
            float least = std::numeric_limits<float>::infinity();
            if (found.page != pageIndex) {
                pageIndex = found.page;
                page = &m_pages[pageIndex];
                width = page->image.width;
                height = page->image.height;
                pixels = m_stack->baseColor(pageIndex).data();
            }
            const DabTexel* texels = c.dabTexels[si / kDabChunk].data();
            for (std::uint32_t h = found.begin; h < found.end; ++h) {
                const DabTexel& texel = texels[h];
                if (!shared && slotPart[std::size_t(texel.slot)] != part)
                    continue;
                const int tx = int(texel.x), ty = int(texel.y);
                if (texel.slot != lastSlot) {
                    lastSlot = texel.slot;
                    st = &c.slots[std::size_t(lastSlot)];
                    alpha = st->alpha.data();
                    base = c.coverBase(lastSlot);
                    before = st->before.data();
                    tileTouched = false;
                    tileWidth = std::size_t(
                        std::min(kTextureTile, width - (tx / kTextureTile) * kTextureTile));
                    tileTexels = tileWidth *
                                 std::size_t(std::min(kTextureTile,
                                                      height - (ty / kTextureTile) * kTextureTile));
                }
                const std::size_t local =
                    std::size_t(ty % kTextureTile) * tileWidth + std::size_t(tx % kTextureTile);
                // An earlier triangle of this dab may have raised it since the first pass.
                const float old = alpha[local];
                if (old >= dabOpacity) {
                    least = std::min(least, old);
                    continue;
                }
                const float cover =
                    std::max(old, std::min(dabOpacity, base[local] + flowOpacity * texel.weight));
                if (!(cover > old)) {
                    least = std::min(least, old);
                    continue;
                }
                least = std::min(least, cover);
                alpha[local] = cover;
                if (!tileTouched) {
                    tileTouched = true;
                    if (c.claim(*st)) {
                        firsts.emplace_back((std::uint64_t(si) << 32) | h, std::uint32_t(lastSlot));
                        // The paint layer's tiles of the channels painted, found (and made) once
                        // a dab.
                        if (onChannels) {
                            const std::uint32_t tile = st->key.tile;
                            const std::lock_guard lock(allocating);
                            for (std::size_t ch = 0; ch < kPaintChannels; ++ch)
                                st->paintLayerTiles[ch] =
                                    m_planes[ch] != nullptr
                                        ? m_planes[ch]->writableTile(pageIndex, tile)
                                        : nullptr;
                        }
                    }
                    channelTiles = st->paintLayerTiles;
                }
                Context::wrote(*st, tx % kTextureTile, ty % kTextureTile);
                if (onBase) {
                    // lerp(stroke start, target, coverage): the brush colour, or the original
                    // for the eraser.
                    const std::size_t at = std::size_t(ty) * std::size_t(width) + std::size_t(tx);
                    blendTexel(srgb, pixels + at * 4, before + local * 4,
                               eraser ? &page->original.rgba[at * 4] : c.colorBytes.data(),
                               eraser ? nullptr : &c.colorLinear[0], cover);
                } else if (onChannels) {
                    // As writeTexel(), with the tiles at hand: colour, then the channels of
                    // one component.
                    if (std::uint8_t* colour = channelTiles[0]; colour != nullptr) {
                        const std::size_t at = local * 4;
                        if (eraser)
                            eraseTexel(colour + at, before + at, 3, cover);
                        else
                            paintTexelOf<3>(colour + at, before + at, &m_values[0], cover, m_lock,
                                            &m_emptyBytes[0]);
                    }
                    std::uint8_t* const rough = channelTiles[1];
                    std::uint8_t* const metal = channelTiles[2];
                    if (rough != nullptr || metal != nullptr) {
                        const std::size_t at = local * 2;
                        const std::uint8_t* roughStart = before + channelOffset(1, tileTexels) + at;
                        const std::uint8_t* metalStart = before + channelOffset(2, tileTexels) + at;
                        if (eraser) {
                            if (rough != nullptr)
                                eraseTexel(rough + at, roughStart, 1, cover);
                            if (metal != nullptr)
                                eraseTexel(metal + at, metalStart, 1, cover);
                        } else {
                            paintTexelPair(rough != nullptr ? rough + at : nullptr,
                                           metal != nullptr ? metal + at : nullptr, roughStart,
                                           metalStart, &m_values[3], cover, m_lock);
                        }
                    }
                } else {
                    writeTexel(pageIndex, tx, ty, before, local, tileTexels, cover);
                }
            }
            partLeast[si] = least;
        }
    });

    // The tiles in the order the one loop touched them first; the triangles' least coverage.
    std::vector<std::pair<std::uint64_t, std::uint32_t>>& firsts = c.partTouched[0];
    for (int part = 1; part < parts; ++part)
        firsts.insert(firsts.end(), c.partTouched[std::size_t(part)].begin(),
                      c.partTouched[std::size_t(part)].end());
    std::sort(firsts.begin(), firsts.end());
    for (const auto& [at, slot] : firsts)
        c.touched.push_back(slot);
    for (std::size_t si = 0; si < count; ++si) {
        const DabTriangle& found = c.dabTriangles[si];
        if (!found.scanned || !found.whole)
            continue;
        float least = found.least;
        for (int part = 0; part < parts; ++part)
            least = std::min(least, c.partLeast[std::size_t(part)][si]);
        c.setTriangleCover(c.setups[si].triangle, least);
    }
    padTouched();
    refreshTouched();
    return touchedChanges();
}

} // namespace core
