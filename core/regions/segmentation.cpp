// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/regions/segmentation.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <climits>
#include <cstdint>
#include <memory>
#include <numeric>

#include "core/base/parallel.h"

namespace core {

namespace {

// Union-find on a flat parent array whose root is always the smallest fragment index of its set.
// Fragments are stored in scan order, so a root is its region's first pixel, and parent[i] <= i
// holds throughout, which lets a single ascending pass flatten a range.

inline std::uint32_t findRoot(std::uint32_t* parent, std::uint32_t x) {
    while (parent[x] != x) {
        parent[x] = parent[parent[x]]; // path halving
        x = parent[x];
    }
    return x;
}

inline std::uint32_t findRootReadOnly(const std::uint32_t* parent, std::uint32_t x) {
    while (parent[x] != x)
        x = parent[x];
    return x;
}

inline void unite(std::uint32_t* parent, std::uint32_t a, std::uint32_t b) {
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a < b)
        parent[b] = a;
    else if (b < a)
        parent[a] = b;
}

/**
 * The high bit of byte d set where a fragment's link byte d (Direction order) joins another
 * layer than its own, `layer`: neither 0 (no link) nor `layer`.
 */
inline std::uint32_t crossLayerLinks(const std::uint8_t* links, std::uint32_t layer) {
    const std::uint32_t word = std::uint32_t(links[0]) | std::uint32_t(links[1]) << 8 |
                               std::uint32_t(links[2]) << 16 | std::uint32_t(links[3]) << 24;
    // The high bit of each byte that is not zero, exactly (no carries between bytes).
    const auto nonZero = [](std::uint32_t v) {
        return (((v & 0x7f7f7f7fu) + 0x7f7f7f7fu) | v) & 0x80808080u;
    };
    return nonZero(word) & nonZero(word ^ (layer * 0x01010101u));
}

/** The fragment that link value `layer` of a fragment at pixel p points to at pixel q, or kNone. */
inline std::uint32_t target(const DepthStack& stack, std::size_t q, std::uint32_t layer) {
    return layer != 0 && layer <= stack.layerCount(q) ? stack.offsets[q] + layer - 1 : kNone;
}

/**
 * Joins the same-layer links of rows [y0, y1) that stay inside those rows. In scan order, each
 * fragment joins the sets of its left and upper neighbours on its layer (already labelled) if
 * either end of the pair links to the other: every pair is met once, at its later fragment.
 */
void labelRows(const DepthStack& stack, const Connectivity& conn, std::uint32_t* parent, int y0,
               int y1) {
    const int w = stack.width;
    const std::uint8_t* links = conn.links.data();
    // The root each layer's fragment took at the pixel before: still its set's root, as only
    // sets of the same layer are joined.
    std::uint32_t leftRoot[kMaxLinkedLayers];
    for (int y = y0; y < y1; ++y)
        for (auto [x, end] = stack.rowSpan(y); x < end; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const std::uint32_t n = std::min(stack.layerCount(p), kMaxLinkedLayers);
            const std::uint32_t first = stack.offsets[p];
            for (std::uint32_t k = 1; k <= n; ++k) {
                const std::uint32_t f = first + k - 1;
                const std::uint8_t* l = links + 4 * std::size_t(f);
                std::uint32_t root = f;
                // A fragment on the left exists only within the row's span, taken just before.
                if (x > 0)
                    if (const std::uint32_t g = target(stack, p - 1, k);
                        g != kNone && (l[kLeft] == k || links[4 * std::size_t(g) + kRight] == k))
                        root = leftRoot[k - 1];
                if (y > y0)
                    if (const std::uint32_t g = target(stack, p - std::size_t(w), k);
                        g != kNone && (l[kUp] == k || links[4 * std::size_t(g) + kDown] == k)) {
                        const std::uint32_t above = findRoot(parent, g);
                        if (root == f)
                            root = above;
                        else if (above < root)
                            root = parent[root] = above;
                        else if (root < above)
                            parent[above] = root;
                    }
                parent[f] = root;
                leftRoot[k - 1] = root;
            }
        }
}

/** Joins the same-layer links between row y - 1 and row y. */
void stitchRows(const DepthStack& stack, const Connectivity& conn, std::uint32_t* parent, int y) {
    const int w = stack.width;
    // Every link between the rows has a fragment at both ends: the columns both rows span.
    const auto [above, aboveEnd] = stack.rowSpan(y - 1);
    const auto [below, belowEnd] = stack.rowSpan(y);
    for (int x = std::max(above, below), end = std::min(aboveEnd, belowEnd); x < end; ++x) {
        const std::size_t q = std::size_t(y) * std::size_t(w) + std::size_t(x);
        const std::size_t p = q - std::size_t(w);
        for (std::uint32_t k = 1; k <= std::min(stack.layerCount(p), kMaxLinkedLayers); ++k)
            if (conn.link(stack.offsets[p] + k - 1, kDown) == k)
                if (const std::uint32_t g = target(stack, q, k); g != kNone)
                    unite(parent, stack.offsets[p] + k - 1, g);
        for (std::uint32_t k = 1; k <= std::min(stack.layerCount(q), kMaxLinkedLayers); ++k)
            if (conn.link(stack.offsets[q] + k - 1, kUp) == k)
                if (const std::uint32_t g = target(stack, p, k); g != kNone)
                    unite(parent, stack.offsets[q] + k - 1, g);
    }
}

/** The recent pairs a band counts in place: 2^kRecentPairBits slots. */
constexpr unsigned kRecentPairBits = 12;

/**
 * A band's share of the work, kept until the bands are merged: its union-find roots, then its
 * partial region nodes and cross-layer links.
 */
struct SegmentBand {
    std::vector<std::uint32_t> roots;      // local roots in scan order
    std::vector<std::uint32_t> rootLayers; // their 1-based layers
    std::vector<Region> regions;           // partial nodes, by region id
    // Cross-layer links as (smaller, larger) ids with their count; neighbouring pixels
    // mostly repeat a pair, which a small direct-mapped table of recent pairs counts in
    // place, so far fewer entries are sorted.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> pairs;
    std::vector<std::uint32_t> recent; // an index into pairs, or kNone
    void addPair(std::uint64_t key) {
        const std::size_t slot =
            std::size_t((key * 0x9e3779b97f4a7c15ull) >> (64 - kRecentPairBits));
        std::uint32_t& index = recent[slot];
        if (index != kNone && pairs[index].first == key) {
            ++pairs[index].second;
            return;
        }
        index = std::uint32_t(pairs.size());
        pairs.emplace_back(key, 1u);
    }
};

/** The scratch of one segmentDepthLayers() call, which its passes fill in turn. */
struct Segmenter {
    const DepthStack& stack;
    const Connectivity& conn;
    int width = 0, height = 0;
    int parts = 0;
    // Band i is rows [bandRow[i], bandRow[i + 1]), perhaps empty.
    std::vector<int> bandRow;
    std::vector<SegmentBand> bands;
    // Union-find parents, one per fragment: every entry is set (per band) before it is read.
    std::unique_ptr<std::uint32_t[]> parent;
    std::uint32_t deepestLayer = 0; // of any root
    // [band * deepestLayer + k - 1]: the band's roots on layer k, then the next id it gives
    // one; after numbering, the last band's counter of a layer is the layer's end.
    std::vector<std::uint32_t> base;
    std::uint32_t regionCount = 0;

    std::uint32_t rowFragment(int y) const {
        return stack.offsets[std::size_t(y) * std::size_t(width)];
    }
    /** Calls fn(band, y0, y1) for every band, each on its own thread. */
    template <typename Fn> void forBands(Fn&& fn) const {
        parallelRanges(parts, unsigned(parts), [&](int, int begin, int end) {
            for (int index = begin; index < end; ++index)
                fn(index, bandRow[std::size_t(index)], bandRow[std::size_t(index) + 1]);
        });
    }
};

/**
 * Bands of rows with about as many fragments each (a model seldom fills the view evenly), one
 * per thread.
 */
void planBands(Segmenter& s, unsigned threads) {
    const std::size_t fragments = s.stack.fragmentCount();
    const int h = s.height;
    s.parts = partCount(h, threads);
    s.bandRow.assign(std::size_t(s.parts) + 1, h);
    for (int index = 0; index < s.parts; ++index) {
        const std::uint64_t wanted =
            std::uint64_t(fragments) * std::uint64_t(index) / std::uint64_t(s.parts);
        int lo = 0, hi = h; // the first row starting at or after the wanted fragment
        while (lo < hi) {
            const int mid = lo + (hi - lo) / 2;
            if (s.rowFragment(mid) < wanted)
                lo = mid + 1;
            else
                hi = mid;
        }
        s.bandRow[std::size_t(index)] = index == 0 ? 0 : lo;
    }
    s.bands.resize(std::size_t(s.parts));
}

/**
 * Labels rows [y0, y1) on their own, flattens them (parent[i] <= i, so one ascending pass) and
 * notes their roots.
 */
void labelBand(const Segmenter& s, SegmentBand& own, int y0, int y1) {
    const DepthStack& stack = s.stack;
    const int w = s.width;
    std::uint32_t* parent = s.parent.get();
    const std::uint32_t f0 = s.rowFragment(y0), f1 = s.rowFragment(y1);
    std::iota(parent + f0, parent + f1, f0);
    labelRows(stack, s.conn, parent, y0, y1);
    for (int y = y0; y < y1; ++y)
        for (auto [x, end] = stack.rowSpan(y); x < end; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
            for (std::uint32_t f = stack.offsets[p], k = 1; f < stack.offsets[p + 1]; ++f, ++k) {
                parent[f] = parent[parent[f]];
                if (parent[f] == f) {
                    own.roots.push_back(f);
                    own.rootLayers.push_back(k);
                }
            }
        }
}

/** Joins the bands' sets across their seams, in order; this only touches roots and short paths. */
void stitchBands(Segmenter& s) {
    for (int index = 1; index < s.parts; ++index)
        if (const int y = s.bandRow[std::size_t(index)]; y > 0 && y < s.height)
            stitchRows(s.stack, s.conn, s.parent.get(), y);
}

/**
 * Counts the surviving roots per band and layer and turns the counts into each band's first id
 * on each layer: ids run by layer, then scan order (bands are in scan order).
 */
void planRegionIds(Segmenter& s) {
    const std::uint32_t* parent = s.parent.get();
    s.deepestLayer = 0;
    for (const SegmentBand& own : s.bands)
        for (std::uint32_t k : own.rootLayers)
            s.deepestLayer = std::max(s.deepestLayer, k);
    const std::uint32_t layerSpan = s.deepestLayer;
    s.base.assign(std::size_t(s.parts) * layerSpan, 0);
    for (int index = 0; index < s.parts; ++index) {
        const SegmentBand& own = s.bands[std::size_t(index)];
        for (std::size_t i = 0; i < own.roots.size(); ++i)
            if (parent[own.roots[i]] == own.roots[i])
                ++s.base[std::size_t(index) * layerSpan + own.rootLayers[i] - 1];
    }
    s.regionCount = 0;
    for (std::uint32_t k = 0; k < layerSpan; ++k)
        for (int index = 0; index < s.parts; ++index) {
            std::uint32_t& slot = s.base[std::size_t(index) * layerSpan + k];
            const std::uint32_t count = slot;
            slot = s.regionCount;
            s.regionCount += count;
        }
}

/**
 * Numbers the surviving roots. The band roots the stitching joined to others take their final
 * root's id and become roots again (a root reached on the way already has its final id).
 */
void numberBandRoots(Segmenter& s, std::uint32_t* region) {
    std::uint32_t* parent = s.parent.get();
    for (int index = 0; index < s.parts; ++index) {
        const SegmentBand& own = s.bands[std::size_t(index)];
        std::uint32_t* nextId = s.base.data() + std::size_t(index) * s.deepestLayer;
        for (std::size_t i = 0; i < own.roots.size(); ++i)
            if (parent[own.roots[i]] == own.roots[i])
                region[own.roots[i]] = nextId[own.rootLayers[i] - 1]++;
    }
    for (const SegmentBand& own : s.bands)
        for (const std::uint32_t root : own.roots)
            if (parent[root] != root) {
                region[root] = region[findRootReadOnly(parent, root)];
                parent[root] = root;
            }
}

/**
 * Every other fragment's id: its parent is a band root (flattened per band, and the stitching's
 * path halving links only to band roots), whose id is final; only the ids of band roots are
 * read across bands.
 */
void spreadRegionIds(const Segmenter& s, std::uint32_t* region) {
    const std::uint32_t* parent = s.parent.get();
    s.forBands([&](int, int y0, int y1) {
        for (std::uint32_t f = s.rowFragment(y0), f1 = s.rowFragment(y1); f < f1; ++f)
            if (parent[f] != f)
                region[f] = region[parent[f]];
    });
}

/** The pixel a fragment at p = (x, y) links to in direction d, or SIZE_MAX outside the view. */
inline std::size_t linkedPixel(int d, std::size_t p, int x, int y, int w, int h) {
    const bool inside = d == kRight ? x + 1 < w : d == kLeft ? x > 0 : d == kUp ? y > 0 : y + 1 < h;
    if (!inside)
        return SIZE_MAX;
    return d == kRight  ? p + 1
           : d == kLeft ? p - 1
           : d == kUp   ? p - std::size_t(w)
                        : p + std::size_t(w);
}

/** Rows [y0, y1)'s partial region nodes and their cross-layer links, sorted. */
void collectBand(const Segmenter& s, const std::uint32_t* region, SegmentBand& own, int y0,
                 int y1) {
    const DepthStack& stack = s.stack;
    const int w = s.width, h = s.height;
    own.regions.assign(s.regionCount, Region{0, 0, 0, INT_MAX, INT_MAX, INT_MIN, INT_MIN});
    own.recent.assign(std::size_t(1) << kRecentPairBits, kNone);
    // Per layer, the run of the row's fragments in one region so far (layer k's at k - 1):
    // a region's node takes a run at once, not each of its fragments.
    struct Run {
        std::uint32_t region = kNone;
        std::uint32_t pixels = 0;
        int minX = 0, maxX = 0;
    };
    std::vector<Run> runs;
    const auto close = [&](Run& run, int y) {
        if (run.region == kNone)
            return;
        Region& node = own.regions[run.region];
        node.pixels += run.pixels;
        node.minX = std::min(node.minX, run.minX);
        node.maxX = std::max(node.maxX, run.maxX);
        node.minY = std::min(node.minY, y);
        node.maxY = std::max(node.maxY, y);
        run.region = kNone;
    };
    for (int y = y0; y < y1; ++y) {
        for (auto [x, end] = stack.rowSpan(y); x < end; ++x) {
            const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const std::uint32_t n = stack.layerCount(p);
            if (runs.size() < n)
                runs.resize(n);
            for (std::uint32_t k = 1; k <= n; ++k) {
                const std::uint32_t f = stack.offsets[p] + k - 1;
                const std::uint32_t r = region[f];
                if (Run& run = runs[k - 1]; run.region == r) {
                    ++run.pixels;
                    run.maxX = x;
                } else {
                    close(run, y);
                    run = {r, 1, x, x};
                }
                if (k > kMaxLinkedLayers)
                    continue;
                const std::uint8_t* l = s.conn.links.data() + 4 * std::size_t(f);
                for (unsigned cross = crossLayerLinks(l, k); cross != 0; cross &= cross - 1) {
                    const int d = std::countr_zero(cross) / 8;
                    const std::size_t q = linkedPixel(d, p, x, y, w, h);
                    if (q == SIZE_MAX)
                        continue;
                    const std::uint32_t g = target(stack, q, l[d]);
                    if (g == kNone)
                        continue;
                    const std::uint64_t a = r, b = region[g];
                    own.addPair(a < b ? (a << 32) | b : (b << 32) | a);
                }
            }
        }
        for (Run& run : runs)
            close(run, y);
    }
    std::sort(own.pairs.begin(), own.pairs.end());
}

/** The graph's region nodes: the bands' partial nodes merged, with their ids and layers. */
void mergeRegionNodes(Segmenter& s, RegionGraph& graph) {
    graph.regions = std::move(s.bands[0].regions);
    for (int index = 1; index < s.parts; ++index)
        for (std::uint32_t r = 0; r < s.regionCount; ++r) {
            Region& node = graph.regions[r];
            const Region& more = s.bands[std::size_t(index)].regions[r];
            node.pixels += more.pixels;
            node.minX = std::min(node.minX, more.minX);
            node.maxX = std::max(node.maxX, more.maxX);
            node.minY = std::min(node.minY, more.minY);
            node.maxY = std::max(node.maxY, more.maxY);
        }
    // Ids run layer by layer; after numbering, the last band's counter of a layer is the
    // layer's end.
    const std::uint32_t layerSpan = s.deepestLayer;
    for (std::uint32_t k = 0, id = 0; k < layerSpan; ++k)
        for (const std::uint32_t end = s.base[std::size_t(s.parts - 1) * layerSpan + k]; id < end;
             ++id) {
            graph.regions[id].id = id;
            graph.regions[id].layer = k + 1;
        }
}

/**
 * The unordered region pairs of the cross-layer links with their link counts, by pair: each
 * band sorted its own; merged here.
 */
std::vector<std::pair<std::uint64_t, std::uint32_t>> countRegionPairs(const Segmenter& s) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> pairs;
    for (const SegmentBand& own : s.bands) {
        const std::ptrdiff_t sorted = std::ptrdiff_t(pairs.size());
        pairs.insert(pairs.end(), own.pairs.begin(), own.pairs.end());
        std::inplace_merge(pairs.begin(), pairs.begin() + sorted, pairs.end());
    }
    std::vector<std::pair<std::uint64_t, std::uint32_t>> edges; // unique pair, link count
    for (std::size_t i = 0; i < pairs.size();) {
        std::uint32_t count = 0;
        std::size_t j = i;
        for (; j < pairs.size() && pairs[j].first == pairs[i].first; ++j)
            count += pairs[j].second;
        edges.emplace_back(pairs[i].first, count);
        i = j;
    }
    return edges;
}

/** The graph's region edges: each region's neighbour list, from the counted pairs. */
void fillNeighborLists(const std::vector<std::pair<std::uint64_t, std::uint32_t>>& edges,
                       std::uint32_t regionCount, RegionGraph& graph) {
    graph.neighborOffsets.assign(std::size_t(regionCount) + 1, 0);
    for (const auto& [key, count] : edges) {
        ++graph.neighborOffsets[(key >> 32) + 1];
        ++graph.neighborOffsets[(key & 0xffffffffu) + 1];
    }
    std::partial_sum(graph.neighborOffsets.begin(), graph.neighborOffsets.end(),
                     graph.neighborOffsets.begin());
    graph.neighbors.resize(graph.neighborOffsets.back());
    // Edges are sorted by (smaller, larger) id, so appending to both ends fills every list in
    // ascending neighbour order: first the smaller neighbours, then the larger ones.
    std::vector<std::uint32_t> fill(graph.neighborOffsets.begin(), graph.neighborOffsets.end() - 1);
    for (const auto& [key, count] : edges) {
        const std::uint32_t r = std::uint32_t(key >> 32), s = std::uint32_t(key & 0xffffffffu);
        graph.neighbors[fill[r]++] = {s, count};
        graph.neighbors[fill[s]++] = {r, count};
    }
}

} // namespace

Segmentation segmentDepthLayers(const DepthStack& stack, const Connectivity& conn, unsigned threads,
                                SegmentationTimings* timings) {
    const auto start = std::chrono::steady_clock::now();
    Segmentation out;
    const std::size_t fragments = stack.fragmentCount();
    if (stack.width <= 0 || stack.height <= 0 || stack.offsets.size() != stack.pixelCount() + 1 ||
        conn.width != stack.width || conn.height != stack.height ||
        conn.links.size() != 4 * fragments || stack.offsets.back() != fragments) {
        out.graph.neighborOffsets.assign(1, 0);
        return out;
    }
    Segmenter s{stack, conn, stack.width, stack.height};
    planBands(s, threads);
    // 1. Label each band of rows on its own; 2. stitch the bands in order.
    s.parent = std::make_unique_for_overwrite<std::uint32_t[]>(fragments);
    s.forBands(
        [&](int index, int y0, int y1) { labelBand(s, s.bands[std::size_t(index)], y0, y1); });
    stitchBands(s);
    // 3. Number the surviving roots by layer, then scan order; 4. every other fragment's id.
    planRegionIds(s);
    out.region.resize(fragments);
    std::uint32_t* region = out.region.data();
    numberBandRoots(s, region);
    spreadRegionIds(s, region);
    // 5. The partial region nodes and the cross-layer links, per band.
    s.forBands([&](int index, int y0, int y1) {
        collectBand(s, region, s.bands[std::size_t(index)], y0, y1);
    });

    const auto graphStart = std::chrono::steady_clock::now();
    // 6. Region nodes: merge the bands' partial nodes; 7. region edges from the link pairs.
    mergeRegionNodes(s, out.graph);
    fillNeighborLists(countRegionPairs(s), s.regionCount, out.graph);
    if (timings) {
        const auto ms = [](auto a, auto b) {
            return std::chrono::duration<double, std::milli>(b - a).count();
        };
        const auto end = std::chrono::steady_clock::now();
        *timings = {ms(start, graphStart), ms(graphStart, end)};
    }
    return out;
}

} // namespace core
