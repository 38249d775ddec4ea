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
#include "core/paint/targets/paint_context.h"
#include "core/paint/targets/texture_dab_texels.h"
#include "core/paint/targets/texture_tile_layout.h"
#include "core/paint/targets/uv_raster.h"

namespace core {

using dab_texels::DabConstants;
using dab_texels::TriangleTexels;
using uv::setUpUv;
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

/**
 * What a dab's passes read and write of the texture target: its own members, which paint()
 * hands them.
 */
struct DabTarget {
    std::vector<TextureTarget::Page>& pages;
    const std::vector<std::uint32_t>& materialPage;
    TileStore& store;             // the target, where a new slot reads its tile
    PaintLayerStack& paintLayers; // the base's texels
    // The stroke's mode: the base, a paint layer's channels, or another (written by the
    // target's writeTexel()).
    bool onBase = false, onChannels = false;
    // A paint layer's planes the stroke paints, their values (sRGB base colour, roughness,
    // metallic), their emptyTexelByte() and the layer's lockTransparency.
    const std::array<TiledPlane*, kPaintChannels>& planes;
    const float* values = nullptr;
    const std::int16_t* emptyBytes = nullptr;
    bool lock = false;
};

/** What the second pass writes texels with, as locals of its loop. */
struct TexelWrites {
    bool eraser = false, onBase = false, onChannels = false;
    const std::uint8_t* colorBytes = nullptr;
    const float* values = nullptr;
    const std::int16_t* emptyBytes = nullptr;
    bool lock = false;
};

/** The page of the triangle at hand in the second pass. */
struct PageAtHand {
    std::uint32_t index = kNone;
    TextureTarget::Page* page = nullptr;
    int width = 0, height = 0;
    std::uint8_t* pixels = nullptr; // the base's texels
};

/** The stroke tile of the texels at hand in the second pass: its slot's coverage and bytes. */
struct TileAtHand {
    std::int32_t slot = -1;
    StrokeTile* st = nullptr;
    float* alpha = nullptr;
    const float* base = nullptr; // the coverage the dab builds on (Context::coverBase())
    const std::uint8_t* before = nullptr;
    bool touched = false; // a texel of it written by this part in this dab
    std::size_t width = 0, texels = 0;
    std::array<std::uint8_t*, kPaintChannels> channelTiles{}; // its paint layer's tiles
};

/**
 * Writes texel (tx, ty), index local in its tile, at coverage cover: on the base, a paint
 * layer's channels, or through writeOther (the target's writeTexel()) in the other modes.
 */
template <typename WriteOther>
[[gnu::always_inline]] inline void
writeTexelAt(const TexelWrites& w, const TileAtHand& tile, const PageAtHand& page, int tx, int ty,
             std::size_t local, float cover, WriteOther& writeOther) {
    const std::uint8_t* before = tile.before;
    if (w.onBase) {
        // lerp(stroke start, target, coverage): the brush colour, or the original for the
        // eraser.
        const std::size_t at = std::size_t(ty) * std::size_t(page.width) + std::size_t(tx);
        blendTexel(page.pixels + at * 4, before + local * 4,
                   w.eraser ? &page.page->original.rgba[at * 4] : w.colorBytes, cover);
    } else if (w.onChannels) {
        // As writeTexel(), with the tiles at hand: colour, then the channels of one component.
        if (std::uint8_t* colour = tile.channelTiles[0]; colour != nullptr) {
            const std::size_t at = local * 4;
            if (w.eraser)
                eraseTexel(colour + at, before + at, 3, cover);
            else
                paintTexelOf<3>(colour + at, before + at, &w.values[0], cover, w.lock,
                                &w.emptyBytes[0]);
        }
        std::uint8_t* const rough = tile.channelTiles[1];
        std::uint8_t* const metal = tile.channelTiles[2];
        if (rough != nullptr || metal != nullptr) {
            const std::size_t at = local * 2;
            const std::uint8_t* roughStart = before + channelOffset(1, tile.texels) + at;
            const std::uint8_t* metalStart = before + channelOffset(2, tile.texels) + at;
            if (w.eraser) {
                if (rough != nullptr)
                    eraseTexel(rough + at, roughStart, 1, cover);
                if (metal != nullptr)
                    eraseTexel(metal + at, metalStart, 1, cover);
            } else {
                paintTexelPair(rough != nullptr ? rough + at : nullptr,
                               metal != nullptr ? metal + at : nullptr, roughStart, metalStart,
                               &w.values[3], cover, w.lock);
            }
        }
    } else {
        writeOther(page.index, tx, ty, before, local, tile.texels, cover);
    }
}

} // namespace

/**
 * A texture dab (TextureTarget::paint()) as passes over the context: first collectTexels(), then
 * giveSlots() and shareTiles() between the passes, writeTexels(), and listTouched() and
 * coverTriangles() to finish.
 */
struct PaintTarget::Context::TextureDab {
    struct TexelVisit;
    /** Per part of the second pass: the tiles it touched first, at (triangle << 32) | texel. */
    using Firsts = std::vector<std::pair<std::uint64_t, std::uint32_t>>;

    Context& c;
    const Mesh& mesh;
    const DepthStack& stack;
    const DabTarget target;
    const std::size_t count; // the triangles the dab looks at (c.setups)
    const DabConstants constants;
    int parts = 1; // the second pass's

    TextureDab(Context& context, const DepthStack& depthStack, const DabTarget& dabTarget);
    /** The dab's constants the first pass reads per texel, as c holds them. */
    static DabConstants constantsOf(const Context& c);

    // The first pass.
    bool findTexels(std::size_t si, TriangleTexels& t) const;
    void clipToMap(const TriangleSetup& s, const glm::vec2 uv[3], TriangleTexels& t) const;
    DabTriangle scanTriangle(std::size_t si, std::vector<DabTexel>& texels, std::size_t& used,
                             std::uint32_t* slotCounts) const;
    void collectTexels();
    // Between the passes.
    std::size_t giveSlots();
    void shareTiles(int secondPassParts);
    // The second pass.
    template <typename WriteOther> void writeTexels(WriteOther&& writeOther);
    template <typename WriteOther>
    void writePart(int part, std::mutex& allocating, WriteOther& writeOther);
    [[gnu::always_inline]] inline void enterTile(TileAtHand& tile, std::int32_t slot, int tx,
                                                 int ty, const PageAtHand& page);
    void claimTile(StrokeTile& st, std::int32_t slot, std::uint64_t at, std::uint32_t page,
                   Firsts& firsts, std::mutex& allocating);
    // The end.
    void listTouched();
    void coverTriangles();
};

/**
 * The first pass's look at a texel of a triangle (operator()): whether it takes paint from the
 * dab, and if so its weight and its tile's slot. A local of the triangle's texel loop, with a
 * copy of the dab's constants.
 */
struct PaintTarget::Context::TextureDab::TexelVisit {
    const DabConstants k;
    const Context& c;
    const DepthStack& stack;
    const TriangleTexels& t;
    const std::uint32_t own; // the triangle's setup
    const std::uint32_t tilesX;
    const std::int32_t* const tileSlots;
    // The tile of the texel looked at: its slot and stroke coverage (nullptr: no slot yet, all
    // 0).
    std::uint32_t seenTile = kNone;
    std::int32_t seenSlot = -1;
    const float* seenAlpha = nullptr;
    int seenWidth = 0;
    // The least coverage of the texels that take nothing from this dab (the second pass adds
    // the others): at most what it is after the dab, as triangleCover needs.
    float least = std::numeric_limits<float>::infinity();
    // The slot of the texels found so far while they share one (kNoSlotYet: none found).
    static constexpr std::int32_t kNoSlotYet = -2;
    std::int32_t sharedSlot = kNoSlotYet;
    bool newTiles = false; // some are in tiles without a slot
    // The texels found go to texels from used on (used counts them), counted per slot of
    // their tile in slotCounts (those of tiles without a slot get theirs between the passes).
    std::vector<DabTexel>& texels;
    std::size_t& used;
    std::uint32_t* const slotCounts;
    DabTexel* outTexels;

    TexelVisit(const TextureDab& d, const TriangleTexels& triangle, std::uint32_t setup,
               std::vector<DabTexel>& found, std::size_t& foundUsed, std::uint32_t* counts)
        : k(d.constants), c(d.c), stack(d.stack), t(triangle), own(setup),
          tilesX(std::uint32_t(d.target.pages[triangle.page].tilesX)),
          tileSlots(d.c.tileSlot[triangle.page].data()), texels(found), used(foundUsed),
          slotCounts(counts), outTexels(found.data()) {}

    /**
     * Room for n more texels from used on (written through outTexels). Texels keeps its size
     * from dab to dab, so that its texels are not set to their defaults before every dab.
     */
    void room(std::size_t n) {
        if (texels.size() < used + n) {
            texels.resize(std::max(used + n, 2 * texels.size()));
            outTexels = texels.data();
        }
    }

    /**
     * A texel inside the triangle, at barycentric weights l and window position (px, py); near:
     * in front of the eye, within a pixel of the map's box and inside the dab's disc; round: the
     * round tip's weight there (if the tip is round). Rejected texels give their coverage to
     * least.
     */
    [[gnu::always_inline]] void operator()(int x, int y, float l0, float l1, float l2, float px,
                                           float py, float distance, bool near, float round) {
        const int tx = t.wrap ? wrapIndex(x, t.width) : x;
        const int ty = t.wrap ? wrapIndex(y, t.height) : y;
        const std::uint32_t tile =
            std::uint32_t(ty / kTextureTile) * tilesX + std::uint32_t(tx / kTextureTile);
        if (tile != seenTile) {
            seenTile = tile;
            seenSlot = tileSlots[tile];
            seenAlpha = seenSlot >= 0 ? c.slots[std::size_t(seenSlot)].alpha.data() : nullptr;
            seenWidth = std::min(kTextureTile, t.width - (tx / kTextureTile) * kTextureTile);
        }
        const std::size_t local = std::size_t(ty % kTextureTile) * std::size_t(seenWidth) +
                                  std::size_t(tx % kTextureTile);
        const float old = seenAlpha ? seenAlpha[local] : 0.0f;
        // The coverage never falls in a stroke and a dab raises it to its opacity at most: a
        // texel there already takes nothing from this dab.
        if (old >= k.dabOpacity || !near || !onMap(l0, l1, l2, px, py)) {
            least = std::min(least, old);
            return;
        }
        const float weight =
            k.roundTip ? round : k.tip->weight(glm::vec2(px, py) - k.center, distance);
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
            newTiles = true;
    }

    /**
     * Whether the triangle's point at weights l, seen at window position (px, py), is on the
     * map's surface: the map's fragment at its pixel is on it (as Context::mapAt() and
     * Context::onMapSurface()), or it is covered at the map's edge.
     */
    [[gnu::always_inline]] bool onMap(float l0, float l1, float l2, float px, float py) const {
        const float fx = px - k.windowX, fy = py - k.windowY;
        const std::uint32_t mapped =
            fx >= 0.0f && fx < k.windowW && fy >= 0.0f && fy < k.windowH
                ? k.window[std::size_t(fy) * k.windowStride + std::size_t(fx)]
                : kNone;
        if (mapped == own)
            return true;
        const ProjectedVertex* p = t.p;
        const glm::vec3 point = l0 * p[0].view + l1 * p[1].view + l2 * p[2].view;
        if (mapped != kNone) {
            const glm::vec4& plane = k.setups[mapped].plane;
            if (plane != glm::vec4(0.0f) &&
                std::fabs(glm::dot(glm::vec3(plane), point) + plane.w) <=
                    -point.z * k.toleranceScale + k.toleranceOffset)
                return true;
        }
        return c.coveredAtEdge(stack, own, point, px, py);
    }
};

PaintTarget::Context::TextureDab::TextureDab(Context& context, const DepthStack& depthStack,
                                             const DabTarget& dabTarget)
    : c(context), mesh(*context.mesh), stack(depthStack), target(dabTarget),
      count(context.setups.size()), constants(constantsOf(context)) {}

DabConstants PaintTarget::Context::TextureDab::constantsOf(const Context& c) {
    DabConstants k;
    k.window = c.window.data();
    k.windowX = float(c.windowX);
    k.windowY = float(c.windowY);
    k.windowW = float(c.windowW);
    k.windowH = float(c.windowH);
    k.windowStride = std::size_t(c.windowW);
    k.nearW = k.windowW + 1.0f;
    k.nearH = k.windowH + 1.0f;
    k.setups = c.setups.data();
    k.center = c.center;
    k.tip = &c.tip;
    k.radius = c.radius;
    k.roundTip = !c.tip.textured();
    k.tipRadius = c.tip.radius();
    k.hardness = c.tip.hardness();
    k.toleranceScale = c.toleranceScale;
    k.toleranceOffset = c.toleranceOffset;
    k.dabOpacity = c.dabOpacity;
    return k;
}

/**
 * Triangle si's texels the first pass is to look at; false when none can take paint from the
 * dab.
 */
bool PaintTarget::Context::TextureDab::findTexels(std::size_t si, TriangleTexels& t) const {
    const TriangleSetup& s = c.setups[si];
    // Every texel of the triangle is at this dab's opacity already: none can take paint.
    if (c.triangleCover[s.triangle] >= c.dabOpacity)
        return false;
    t.page = target.materialPage[mesh.triangleMaterial[s.triangle]];
    const TextureTarget::Page& page = target.pages[t.page];
    t.width = page.image.width;
    t.height = page.image.height;
    glm::vec2 uv[3];
    for (int k = 0; k < 3; ++k)
        uv[k] = mesh.uvs[s.vertex[std::size_t(k)]];
    if (!setUpUv(uv, t.width, t.height, t.r))
        return false;
    t.x0 = t.r.minX;
    t.x1 = t.r.maxX;
    t.y0 = t.r.minY;
    t.y1 = t.r.maxY;
    clipToMap(s, uv, t);
    if (t.x0 > t.x1 || t.y0 > t.y1)
        return false;
    if (double(t.x1 - t.x0 + 1) * double(t.y1 - t.y0 + 1) >
        4.0 * double(t.width) * double(t.height))
        return false; // spread over many repeats of the texture (see create())
    t.wrap = t.x0 < 0 || t.y0 < 0 || t.x1 >= t.width || t.y1 >= t.height;
    for (int k = 0; k < 3; ++k)
        t.p[k] = c.vertices[s.vertex[std::size_t(t.r.corner[k])]];
    t.invArea = float(1.0 / double(t.r.area));
    return true;
}

/**
 * A triangle larger than the dab (reaching past the map's box, over more than 64 texels): visit
 * only the texels of t that can land in the map.
 */
void PaintTarget::Context::TextureDab::clipToMap(const TriangleSetup& s, const glm::vec2 uv[3],
                                                 TriangleTexels& t) const {
    const float sMinX = std::min({s.screen[0].x, s.screen[1].x, s.screen[2].x});
    const float sMaxX = std::max({s.screen[0].x, s.screen[1].x, s.screen[2].x});
    const float sMinY = std::min({s.screen[0].y, s.screen[1].y, s.screen[2].y});
    const float sMaxY = std::max({s.screen[0].y, s.screen[1].y, s.screen[2].y});
    const bool inside = sMinX >= float(c.windowX - 2) &&
                        sMaxX <= float(c.windowX + c.windowW + 2) &&
                        sMinY >= float(c.windowY - 2) && sMaxY <= float(c.windowY + c.windowH + 2);
    if (inside || double(t.x1 - t.x0 + 1) * double(t.y1 - t.y0 + 1) <= 64.0)
        return;
    glm::dvec2 texel[3];
    for (int k = 0; k < 3; ++k)
        texel[k] = glm::dvec2(double(uv[k].x) * t.width, double(uv[k].y) * t.height);
    double minX, maxX, minY, maxY;
    if (c.windowPreimage(s, texel, minX, maxX, minY, maxY)) {
        t.x0 = std::max(t.x0, int(std::floor(minX)) - 1);
        t.x1 = std::min(t.x1, int(std::floor(maxX)) + 1);
        t.y0 = std::max(t.y0, int(std::floor(minY)) - 1);
        t.y1 = std::min(t.y1, int(std::floor(maxY)) + 1);
    }
}

/**
 * Triangle si: its texels the dab reaches go to texels from used on (used counts them), counted
 * per slot of their tile in slotCounts; what the second pass needs of it.
 */
DabTriangle PaintTarget::Context::TextureDab::scanTriangle(std::size_t si,
                                                           std::vector<DabTexel>& texels,
                                                           std::size_t& used,
                                                           std::uint32_t* slotCounts) const {
    DabTriangle out;
    out.begin = out.end = std::uint32_t(used);
    TriangleTexels t;
    if (!findTexels(si, t))
        return out;
    TexelVisit visit(*this, t, std::uint32_t(si), texels, used, slotCounts);
#if defined(__SSE2__)
    if (t.x1 - t.x0 >= 3 && uv::edgesFitInt32(t.r))
        dab_texels::visitInFours(t, visit.k, visit);
    else
#endif
        dab_texels::visitOneByOne(t, visit.k, visit);
    out.scanned = true;
    out.whole = t.x0 == t.r.minX && t.x1 == t.r.maxX && t.y0 == t.r.minY && t.y1 == t.r.maxY;
    out.page = t.page;
    out.least = visit.least;
    out.slot = std::max(visit.sharedSlot, -1);
    out.newTiles = visit.newTiles;
    out.end = std::uint32_t(used);
    return out;
}

/**
 * The first pass: reads the mesh, the view, the map and the stroke's coverage before this dab,
 * and counts the texels found per slot (c.slotTexels).
 */
void PaintTarget::Context::TextureDab::collectTexels() {
    const std::size_t chunks = (count + kDabChunk - 1) / kDabChunk;
    c.dabTriangles.resize(count);
    if (c.dabTexels.size() < chunks)
        c.dabTexels.resize(chunks);
    std::atomic<std::size_t> next{0};
    HelperThreads& helpers = HelperThreads::shared();
    const int firstParts = count >= kDabParallelFrom ? helpers.width() : 1;
    if (c.partSlotTexels.size() < std::size_t(firstParts))
        c.partSlotTexels.resize(std::size_t(firstParts));
    helpers.run(firstParts, [&](int part) {
        std::vector<std::uint32_t>& slotCounts = c.partSlotTexels[std::size_t(part)];
        slotCounts.assign(c.slotsUsed, 0u);
        for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < chunks;) {
            std::size_t used = 0;
            for (std::size_t si = k * kDabChunk, end = std::min(count, si + kDabChunk); si < end;
                 ++si)
                c.dabTriangles[si] = scanTriangle(si, c.dabTexels[k], used, slotCounts.data());
        }
    });
    c.slotTexels.assign(c.slotsUsed, 0u);
    for (int part = 0; part < firstParts; ++part)
        for (std::size_t k = 0; k < c.slotsUsed; ++k)
            c.slotTexels[k] += c.partSlotTexels[std::size_t(part)][k];
}

/**
 * Between the passes, on this thread in the triangles' order: the texels of tiles that had no
 * slot get the stroke's slot of their tile, made where the one loop would make it (at the first
 * texel of the tile that takes paint). A new slot's coverage is all 0, as the first pass took it
 * to be. Returns how many texels take paint.
 */
std::size_t PaintTarget::Context::TextureDab::giveSlots() {
    std::size_t reaching = 0;
    for (std::size_t si = 0; si < count; ++si) {
        const DabTriangle& found = c.dabTriangles[si];
        if (!found.scanned)
            continue;
        reaching += found.end - found.begin;
        if (!found.newTiles)
            continue;
        const auto tilesX = std::uint32_t(target.pages[found.page].tilesX);
        DabTexel* texels = c.dabTexels[si / kDabChunk].data();
        for (std::uint32_t h = found.begin; h < found.end; ++h) {
            DabTexel& texel = texels[h];
            if (texel.slot >= 0)
                continue;
            const std::uint32_t tile = std::uint32_t(texel.y / kTextureTile) * tilesX +
                                       std::uint32_t(texel.x / kTextureTile);
            texel.slot = c.slotFor(target.store, found.page, tile);
            if (c.slotTexels.size() <= std::size_t(texel.slot))
                c.slotTexels.resize(std::size_t(texel.slot) + 1, 0u);
            ++c.slotTexels[std::size_t(texel.slot)];
        }
    }
    return reaching;
}

/**
 * Each tile's texels go to one of the second pass's parts, the largest tiles first to the least
 * loaded part.
 */
void PaintTarget::Context::TextureDab::shareTiles(int secondPassParts) {
    parts = secondPassParts;
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
}

/**
 * The second pass: each part its tiles' texels, triangle by triangle in order, so every tile
 * sees the writes of the one loop in its order.
 */
template <typename WriteOther>
void PaintTarget::Context::TextureDab::writeTexels(WriteOther&& writeOther) {
    std::mutex allocating; // a paint layer's tile made by one part at a time
    HelperThreads::shared().run(parts, [&](int part) { writePart(part, allocating, writeOther); });
}

/** The second pass's part: raises the coverage of its tiles' texels and writes them. */
template <typename WriteOther>
void PaintTarget::Context::TextureDab::writePart(int part, std::mutex& allocating,
                                                 WriteOther& writeOther) {
    std::vector<float>& partLeast = c.partLeast[std::size_t(part)];
    partLeast.assign(count, std::numeric_limits<float>::infinity());
    Firsts& firsts = c.partTouched[std::size_t(part)];
    firsts.clear();
    const float dabOpacity = c.dabOpacity, flowOpacity = c.flowOpacity;
    const TexelWrites writes{.eraser = c.brush.eraser,
                             .onBase = target.onBase,
                             .onChannels = target.onChannels,
                             .colorBytes = c.colorBytes.data(),
                             .values = target.values,
                             .emptyBytes = target.emptyBytes,
                             .lock = target.lock};
    const std::uint8_t* slotPart = c.slotPart.data();
    PageAtHand page;
    TileAtHand tile;
    for (std::size_t si = 0; si < count; ++si) {
        const DabTriangle& found = c.dabTriangles[si];
        // A triangle whose texels all are in another part's tile.
        if (!found.scanned || (found.slot >= 0 && slotPart[found.slot] != part))
            continue;
        const bool shared = found.slot >= 0;
        float least = std::numeric_limits<float>::infinity();
        if (found.page != page.index) {
            page.index = found.page;
            page.page = &target.pages[page.index];
            page.width = page.page->image.width;
            page.height = page.page->image.height;
            page.pixels = target.paintLayers.baseColor(page.index).data();
        }
        const DabTexel* texels = c.dabTexels[si / kDabChunk].data();
        for (std::uint32_t h = found.begin; h < found.end; ++h) {
            const DabTexel& texel = texels[h];
            if (!shared && slotPart[std::size_t(texel.slot)] != part)
                continue;
            const int tx = int(texel.x), ty = int(texel.y);
            if (texel.slot != tile.slot)
                enterTile(tile, texel.slot, tx, ty, page);
            const std::size_t local =
                std::size_t(ty % kTextureTile) * tile.width + std::size_t(tx % kTextureTile);
            // An earlier triangle of this dab may have raised it since the first pass.
            const float old = tile.alpha[local];
            if (old >= dabOpacity) {
                least = std::min(least, old);
                continue;
            }
            const float cover =
                std::max(old, std::min(dabOpacity, tile.base[local] + flowOpacity * texel.weight));
            if (!(cover > old)) {
                least = std::min(least, old);
                continue;
            }
            least = std::min(least, cover);
            tile.alpha[local] = cover;
            if (!tile.touched) {
                tile.touched = true;
                claimTile(*tile.st, tile.slot, (std::uint64_t(si) << 32) | h, page.index, firsts,
                          allocating);
                tile.channelTiles = tile.st->paintLayerTiles;
            }
            Context::wrote(*tile.st, tx % kTextureTile, ty % kTextureTile);
            writeTexelAt(writes, tile, page, tx, ty, local, cover, writeOther);
        }
        partLeast[si] = least;
    }
}

/** The tile of slot, where texel (tx, ty) of the page at hand is, becomes the tile at hand. */
inline void PaintTarget::Context::TextureDab::enterTile(TileAtHand& tile, std::int32_t slot, int tx,
                                                        int ty, const PageAtHand& page) {
    tile.slot = slot;
    tile.st = &c.slots[std::size_t(slot)];
    tile.alpha = tile.st->alpha.data();
    tile.base = c.coverBase(slot);
    tile.before = tile.st->before.data();
    tile.touched = false;
    tile.width =
        std::size_t(std::min(kTextureTile, page.width - (tx / kTextureTile) * kTextureTile));
    tile.texels =
        tile.width *
        std::size_t(std::min(kTextureTile, page.height - (ty / kTextureTile) * kTextureTile));
}

/**
 * The first write of a part to tile st (of slot) in this dab, at position at ((triangle << 32) |
 * texel) in the one loop's order: readies the tile the first time in the dab and lists it in
 * firsts.
 */
void PaintTarget::Context::TextureDab::claimTile(StrokeTile& st, std::int32_t slot,
                                                 std::uint64_t at, std::uint32_t page,
                                                 Firsts& firsts, std::mutex& allocating) {
    if (!c.claim(st))
        return;
    firsts.emplace_back(at, std::uint32_t(slot));
    // The paint layer's tiles of the channels painted, found (and made) once a dab.
    if (target.onChannels) {
        const std::uint32_t tile = st.key.tile;
        const std::lock_guard lock(allocating);
        for (std::size_t ch = 0; ch < kPaintChannels; ++ch)
            st.paintLayerTiles[ch] = target.planes[ch] != nullptr
                                         ? target.planes[ch]->writableTile(page, tile)
                                         : nullptr;
    }
}

/** The tiles the dab touched (c.touched) in the order the one loop touched them first. */
void PaintTarget::Context::TextureDab::listTouched() {
    Firsts& firsts = c.partTouched[0];
    for (int part = 1; part < parts; ++part)
        firsts.insert(firsts.end(), c.partTouched[std::size_t(part)].begin(),
                      c.partTouched[std::size_t(part)].end());
    std::sort(firsts.begin(), firsts.end());
    for (const auto& [at, slot] : firsts)
        c.touched.push_back(slot);
}

/** Each triangle whose texels were all looked at: the least coverage they have after the dab. */
void PaintTarget::Context::TextureDab::coverTriangles() {
    for (std::size_t si = 0; si < count; ++si) {
        const DabTriangle& found = c.dabTriangles[si];
        if (!found.scanned || !found.whole)
            continue;
        float least = found.least;
        for (int part = 0; part < parts; ++part)
            least = std::min(least, c.partLeast[std::size_t(part)][si]);
        c.setTriangleCover(c.setups[si].triangle, least);
    }
}

const PaintChanges& TextureTarget::paint(const DepthLayers& layers, const Dab& dab) {
    Context& c = *m_context;
    c.changes.clear();
    if (!c.inStroke || m_mode == StrokeMode::Nothing || !c.beginDab(layers, dab))
        return c.changes;
    const bool onBase = m_mode == StrokeMode::Base, onChannels = m_mode == StrokeMode::Channels;
    Context::TextureDab d(c, layers.stack,
                          {.pages = m_pages,
                           .materialPage = m_materialPage,
                           .store = *this,
                           .paintLayers = *m_stack,
                           .onBase = onBase,
                           .onChannels = onChannels,
                           .planes = m_planes,
                           .values = m_values.data(),
                           .emptyBytes = m_emptyBytes.data(),
                           .lock = m_lock});
    // First pass: the texels the dab reaches; between the passes, their tiles' slots.
    d.collectTexels();
    const std::size_t reaching = d.giveSlots();
    // The base and the paint layers' channels are written per tile, on all parts once enough
    // texels take paint; the other modes on this thread alone.
    const bool perTile = onBase || onChannels;
    d.shareTiles(perTile && reaching >= kSecondPassParallelFrom ? HelperThreads::shared().width()
                                                                : 1);
    // Second pass: the texels' coverage raised and written.
    d.writeTexels([this](std::uint32_t page, int x, int y, const std::uint8_t* before,
                         std::size_t local, std::size_t tileTexels, float cover) {
        writeTexel(page, x, y, before, local, tileTexels, cover);
    });
    // The end: the tiles touched in order, the triangles' least coverage, seam padding and the
    // composite.
    d.listTouched();
    d.coverTriangles();
    padTouched();
    refreshTouched();
    return touchedChanges();
}

} // namespace core
