// SPDX-License-Identifier: GPL-3.0-or-later
// The texel loop of a dab on a texture target (TextureTarget::paint), in two passes. The first
// only reads: for each triangle the dab looks at, the texels the dab reaches on its surface and
// their falloff weight (on both cores for a large dab, the triangles in chunks). Between them
// each texel gets the stroke's slot of its tile. The second raises the texels' stroke coverage
// and writes them, each tile on one core in the triangles' order, so the bytes are those of one
// pass over the triangles in order, whatever the number of threads.
#include <algorithm>
#include <atomic>
#include <limits>
#include <mutex>
#include <utility>

#include <glm/common.hpp>

#include "core/base/helper_threads.h"
#include "core/paint/paint_context.h"
#include "core/paint/texture_tile_layout.h"
#include "core/paint/uv_raster.h"

namespace core {

using uv::scanUv;
using uv::setUpUv;
using uv::UvTriangle;
using uv::wrapIndex;

namespace {

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

const PaintChanges& TextureTarget::paint(const Layers& layers, const Dab& dab) {
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
        const float toleranceScale = c.toleranceScale, toleranceOffset = c.toleranceOffset;
        const LayerStack& stack = layers.stack;

        // Triangle si: its texels the dab reaches go to texels, counted per slot of their tile
        // in slotCounts (those of tiles without a slot get theirs between the passes); what the
        // second pass needs of it.
        const auto scan = [&](std::size_t si, std::vector<DabTexel>& texels,
                              std::uint32_t* slotCounts) {
            DabTriangle out;
            out.begin = out.end = std::uint32_t(texels.size());
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

            scanUv(
                r, x0, x1, y0, y1,
                [&](int x, int y, std::int64_t e0, std::int64_t e1, std::int64_t e2) {
                    const int tx = wrap ? wrapIndex(x, width) : x;
                    const int ty = wrap ? wrapIndex(y, height) : y;
                    const std::uint32_t tile = std::uint32_t(ty / kTextureTile) * tilesX +
                                               std::uint32_t(tx / kTextureTile);
                    if (tile != seenTile) {
                        seenTile = tile;
                        seenSlot = tileSlots[tile];
                        seenAlpha =
                            seenSlot >= 0 ? c.slots[std::size_t(seenSlot)].alpha.data() : nullptr;
                        seenWidth =
                            std::min(kTextureTile, width - (tx / kTextureTile) * kTextureTile);
                    }
                    const std::size_t local =
                        std::size_t(ty % kTextureTile) * std::size_t(seenWidth) +
                        std::size_t(tx % kTextureTile);
                    const float old = seenAlpha ? seenAlpha[local] : 0.0f;
                    const auto rejected = [&] { least = std::min(least, old); };
                    // The coverage never falls in a stroke and a dab raises it to its
                    // opacity at most: a texel there already takes nothing from this dab.
                    if (old >= dabOpacity)
                        return rejected();
                    const float l0 = float(e0) * invArea, l1 = float(e1) * invArea,
                                l2 = float(e2) * invArea;
                    const float w = l0 * p[0].w + l1 * p[1].w + l2 * p[2].w;
                    if (!(w > kMinW))
                        return rejected();
                    const float px = (l0 * p[0].sx + l1 * p[1].sx + l2 * p[2].sx) / w;
                    const float py = (l0 * p[0].sy + l1 * p[1].sy + l2 * p[2].sy) / w;
                    // The map's fragment at the texel's pixel (as Context::mapAt()). Texels
                    // up to a pixel outside the map's box can be at its surface's outline.
                    const float fx = px - windowX, fy = py - windowY;
                    if (!(fx >= -1.0f && fx < windowW + 1.0f && fy >= -1.0f && fy < windowH + 1.0f))
                        return rejected();
                    const std::uint32_t mapped =
                        fx >= 0.0f && fx < windowW && fy >= 0.0f && fy < windowH
                            ? window[std::size_t(fy) * windowStride + std::size_t(fx)]
                            : kNone;
                    // On its surface (as Context::onMapSurface()).
                    bool onMap = mapped == own;
                    if (!onMap && mapped != kNone) {
                        const glm::vec3 point = l0 * p[0].view + l1 * p[1].view + l2 * p[2].view;
                        const glm::vec4& plane = setups[mapped].plane;
                        onMap = plane != glm::vec4(0.0f) &&
                                std::fabs(glm::dot(glm::vec3(plane), point) + plane.w) <=
                                    -point.z * toleranceScale + toleranceOffset;
                    }
                    const float distance = glm::length(glm::vec2(px, py) - center);
                    if (!(distance < radius))
                        return rejected();
                    if (!onMap &&
                        !c.coveredAtEdge(stack, own,
                                         l0 * p[0].view + l1 * p[1].view + l2 * p[2].view, px, py))
                        return rejected();
                    const float weight = tip.weight(glm::vec2(px, py) - center, distance);
                    if (!(weight > 0.0f))
                        return rejected();
                    texels.push_back({std::uint16_t(tx), std::uint16_t(ty), weight, seenSlot});
                    if (seenSlot >= 0)
                        ++slotCounts[seenSlot];
                    else
                        out.newTiles = true;
                });
            out.scanned = true;
            out.whole = x0 == r.minX && x1 == r.maxX && y0 == r.minY && y1 == r.maxY;
            out.page = pageIndex;
            out.least = least;
            out.end = std::uint32_t(texels.size());
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
                std::vector<DabTexel>& texels = c.dabTexels[k];
                texels.clear();
                for (std::size_t si = k * kDabChunk, end = std::min(count, si + kDabChunk);
                     si < end; ++si)
                    c.dabTriangles[si] = scan(si, texels, slotCounts.data());
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
        for (std::size_t si = 0; si < count; ++si) {
            const DabTriangle& found = c.dabTriangles[si];
            if (!found.scanned)
                continue;
            float least = std::numeric_limits<float>::infinity();
            const std::uint32_t pageIndex = found.page;
            Page& page = m_pages[pageIndex];
            const int width = page.image.width, height = page.image.height;
            std::uint8_t* pixels = m_stack->baseColor(pageIndex).data();
            const DabTexel* texels = c.dabTexels[si / kDabChunk].data();
            for (std::uint32_t h = found.begin; h < found.end; ++h) {
                const DabTexel& texel = texels[h];
                if (c.slotPart[std::size_t(texel.slot)] != part)
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
                                st->layerTiles[ch] =
                                    m_planes[ch] != nullptr
                                        ? m_planes[ch]->writableTile(pageIndex, tile)
                                        : nullptr;
                        }
                    }
                    channelTiles = st->layerTiles;
                }
                Context::wrote(*st, tx % kTextureTile, ty % kTextureTile);
                if (onBase) {
                    // lerp(stroke start, target, coverage): the brush colour, or the original
                    // for the eraser.
                    const std::size_t at = std::size_t(ty) * std::size_t(width) + std::size_t(tx);
                    blendTexel(srgb, pixels + at * 4, before + local * 4,
                               eraser ? &page.original.rgba[at * 4] : c.colorBytes.data(),
                               eraser ? nullptr : &c.colorLinear[0], cover);
                } else if (onChannels) {
                    // As writeTexel(), with the tiles at hand.
                    for (std::size_t ch = 0; ch < kPaintChannels; ++ch) {
                        if (channelTiles[ch] == nullptr)
                            continue;
                        const int n = ch == 0 ? 3 : 1;
                        const std::size_t at = local * std::size_t(n + 1);
                        const std::uint8_t* start = before + channelOffset(ch, tileTexels) + at;
                        if (eraser)
                            eraseTexel(channelTiles[ch] + at, start, n, cover);
                        else
                            paintTexel(channelTiles[ch] + at, start, n,
                                       &m_values[ch == 0 ? 0 : ch + 2], cover, m_lock,
                                       &m_emptyBytes[ch == 0 ? 0 : ch + 2]);
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
