// SPDX-License-Identifier: GPL-3.0-or-later
// Packing the charts of the automatic UV layout into texture pages by their shape: each chart is
// rasterized into a mask of the texels it fills, grown by half the padding, and put at the lowest
// free place of a page (first fit, row by row) in the quarter turn that keeps its top lowest, so
// small charts fill the gaps and holes that big ones leave.
#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>
#include <string>

#include <glm/common.hpp>

#include "core/base/parallel.h"
#include "core/model/uv_layout_internal.h"

namespace core::uvl {

namespace {

/** A chart's mask: the texels it fills, grown by half the padding (or its own, when small). */
struct Mask {
    int width = 0, height = 0;
    glm::dvec2 origin{0.0}; // texel position (uv × density) of the mask's corner
    std::vector<std::uint8_t> bits;
    bool small = false; // fills at most smallChartTexels texels: grown by the small radius
};

/**
 * Marks the texels of mask (width w) whose centre triangle a, b, c covers, or lies within kSlack
 * texels of: the texels painting fills (its fill rule takes texel centres), with room for the
 * rounding of the float UVs. A triangle covering no centre marks none.
 */
constexpr double kSlack = 0.05;
void rasterizeCentres(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
                      std::vector<std::uint8_t>& mask, int w, int h) {
    const glm::dvec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    const int x0 = std::max(0, int(std::floor(lo.x))), x1 = std::min(w - 1, int(std::floor(hi.x)));
    const int y0 = std::max(0, int(std::floor(lo.y))), y1 = std::min(h - 1, int(std::floor(hi.y)));
    const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    const double sign = area >= 0.0 ? 1.0 : -1.0;
    const glm::dvec2 p[3] = {a, b, c};
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            bool inside = area != 0.0;
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            // The centre's distance to each edge's line, positive inside.
            for (int k = 0; k < 3 && inside; ++k) {
                const glm::dvec2 e0 = p[k], e1 = p[(k + 1) % 3];
                const double dx = e1.x - e0.x, dy = e1.y - e0.y;
                const double f = sign * (dx * (centre.y - e0.y) - dy * (centre.x - e0.x));
                inside = f + kSlack * std::sqrt(dx * dx + dy * dy) >= 0.0;
            }
            if (inside)
                mask[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 1;
        }
}

/** Grows a mask by r texels in every direction (a square brush). */
void dilate(std::vector<std::uint8_t>& mask, int w, int h, int r) {
    if (r <= 0)
        return;
    std::vector<std::uint8_t> tmp(mask.size(), 0u);
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* in = &mask[std::size_t(y) * std::size_t(w)];
        std::uint8_t* out = &tmp[std::size_t(y) * std::size_t(w)];
        for (int x = 0; x < w; ++x)
            if (in[x])
                for (int k = std::max(0, x - r); k <= std::min(w - 1, x + r); ++k)
                    out[k] = 1;
    }
    std::fill(mask.begin(), mask.end(), 0u);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (tmp[std::size_t(y) * std::size_t(w) + std::size_t(x)])
                for (int k = std::max(0, y - r); k <= std::min(h - 1, y + r); ++k)
                    mask[std::size_t(k) * std::size_t(w) + std::size_t(x)] = 1;
}

/** Grows charts: r for all, rSmall for those filling at most smallTexels texels. */
struct Growth {
    int r = 0, rSmall = 0;
    int smallTexels = 0;
};

Mask maskChart(const Chart& chart, double density, const Growth& growth) {
    const int r = growth.r;
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const glm::dvec2& p : chart.uv) {
        lo = glm::min(lo, p * density);
        hi = glm::max(hi, p * density);
    }
    if (chart.uv.empty())
        lo = hi = glm::dvec2(0.0);
    const double margin = double(r + 1);
    const int w = int(std::floor(hi.x - lo.x + margin)) + r + 2;
    const int h = int(std::floor(hi.y - lo.y + margin)) + r + 2;
    std::vector<std::uint8_t> bits(std::size_t(w) * std::size_t(h), 0u);
    const glm::dvec2 shift = lo - margin;
    for (const auto& c : chart.local)
        rasterizeCentres(chart.uv[c[0]] * density - shift, chart.uv[c[1]] * density - shift,
                         chart.uv[c[2]] * density - shift, bits, w, h);
    // The texels of the corners too, so the chart's UVs stay inside its mask's bounds (and the
    // page) even where a sliver covers no texel centre.
    for (const glm::dvec2& uv : chart.uv) {
        const glm::dvec2 q = uv * density - shift;
        const int x = std::clamp(int(std::floor(q.x)), 0, w - 1);
        const int y = std::clamp(int(std::floor(q.y)), 0, h - 1);
        bits[std::size_t(y) * std::size_t(w) + std::size_t(x)] = 1;
    }
    const bool small =
        std::count(bits.begin(), bits.end(), 1u) <= std::ptrdiff_t(growth.smallTexels);
    dilate(bits, w, h, small ? growth.rSmall : r);
    int x0 = w, x1 = -1, y0 = h, y1 = -1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (bits[std::size_t(y) * std::size_t(w) + std::size_t(x)]) {
                x0 = std::min(x0, x);
                x1 = std::max(x1, x);
                y0 = std::min(y0, y);
                y1 = std::max(y1, y);
            }
    Mask m;
    m.width = x1 - x0 + 1;
    m.height = y1 - y0 + 1;
    m.origin = shift + glm::dvec2(x0, y0);
    m.small = small;
    m.bits.resize(std::size_t(m.width) * std::size_t(m.height));
    for (int y = 0; y < m.height; ++y)
        std::copy_n(&bits[std::size_t(y + y0) * std::size_t(w) + std::size_t(x0)], m.width,
                    &m.bits[std::size_t(y) * std::size_t(m.width)]);
    return m;
}

/** A mask after `rotation` quarter turns (see placeUv) as runs of texels per row. */
struct Shape {
    int width = 0, height = 0;
    std::vector<int> rowBegin;             // per row: its first run; height + 1 entries
    std::vector<std::pair<int, int>> runs; // first and last column, inclusive
    std::vector<int> widestRun;            // per row
};

Shape rotatedShape(const Mask& m, int rotation) {
    Shape s;
    const int w = m.width, h = m.height;
    const bool swapped = rotation % 2 == 1;
    s.width = swapped ? h : w;
    s.height = swapped ? w : h;
    const auto bit = [&](int x, int y) {
        int i, j;
        switch (rotation) {
        case 0:
            i = x, j = y;
            break;
        case 1:
            i = y, j = h - 1 - x;
            break; // texel (i, j) goes to (h − 1 − j, i)
        case 2:
            i = w - 1 - x, j = h - 1 - y;
            break;
        default:
            i = w - 1 - y, j = x;
            break; // (i, j) goes to (j, w − 1 − i)
        }
        return m.bits[std::size_t(j) * std::size_t(w) + std::size_t(i)] != 0;
    };
    s.rowBegin.reserve(std::size_t(s.height) + 1);
    s.widestRun.assign(std::size_t(s.height), 0);
    for (int y = 0; y < s.height; ++y) {
        s.rowBegin.push_back(int(s.runs.size()));
        for (int x = 0; x < s.width;) {
            if (!bit(x, y)) {
                ++x;
                continue;
            }
            int e = x;
            while (e + 1 < s.width && bit(e + 1, y))
                ++e;
            s.runs.emplace_back(x, e);
            s.widestRun[std::size_t(y)] = std::max(s.widestRun[std::size_t(y)], e - x + 1);
            x = e + 1;
        }
    }
    s.rowBegin.push_back(int(s.runs.size()));
    return s;
}

/**
 * One page's occupancy: per texel, the length of the free (> 0) or taken (< 0) stretch that
 * starts there and runs right, so a chart's row of texels is tested with one look-up and a
 * failed test says how far to move on.
 */
class Page {
public:
    explicit Page(int size) : m_size(size), m_run(std::size_t(size) * std::size_t(size)) {
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x)
                m_run[index(x, y)] = std::int16_t(size - x);
        m_widest.assign(std::size_t(size), size);
        m_dirty.assign(std::size_t(size), 0u);
    }

    /** The lowest row, then column, where s fits with its top below topLimit; false if none. */
    bool firstFit(const Shape& s, long long topLimit, int& outX, int& outY) {
        m_lastFailed = 0;
        while (m_open < m_size && widest(m_open) == 0)
            ++m_open;
        // Tall charts try every step-th row, then slide down from where they fit: far fewer
        // tests, and at most a step higher than the lowest place.
        const int step = std::max(1, s.height / 16);
        const int from = std::max(m_open, searchFrom(s));
        for (int y = from; y + s.height <= m_size && y + s.height < topLimit; y += step) {
            bool rowsFit = true;
            for (int j = 0; j < s.height && rowsFit; ++j)
                rowsFit = widest(y + j) >= s.widestRun[std::size_t(j)];
            if (!rowsFit)
                continue;
            // Rows are tested round the shape from the one that failed last; a failing row moves
            // x past what blocked it and is tested again; s fits when every row passed in turn.
            int j = m_lastFailed, passed = 0;
            for (int x = 0; x + s.width <= m_size;) {
                const int next = testRow(s, j, x, y);
                if (next >= 0) {
                    x = next;
                    passed = 0;
                    continue;
                }
                if (++passed == s.height) {
                    while (y > m_open && fitsAt(s, x, y - 1))
                        --y;
                    outX = x;
                    outY = y;
                    return true;
                }
                j = j + 1 == s.height ? 0 : j + 1;
            }
        }
        return false;
    }

    /**
     * Grows what is taken by d texels, and takes a frame of d texels round the page: charts
     * grown by d less then keep the same distance to what is placed and to the border.
     */
    void grow(int d) {
        if (d <= 0)
            return;
        std::vector<std::uint8_t> taken(m_run.size());
        for (std::size_t i = 0; i < m_run.size(); ++i)
            taken[i] = m_run[i] < 0 ? 1u : 0u;
        dilate(taken, m_size, m_size, d);
        for (int y = 0; y < m_size; ++y) {
            std::int16_t* row = &m_run[index(0, y)];
            const std::uint8_t* t = &taken[index(0, y)];
            const bool frame = y < d || y >= m_size - d;
            for (int x = m_size - 1; x >= 0; --x) {
                const bool isTaken = frame || x < d || x >= m_size - d || t[x] != 0;
                const int right = x + 1 < m_size ? row[x + 1] : 0;
                row[x] = isTaken ? std::int16_t(right < 0 ? right - 1 : -1)
                                 : std::int16_t(right > 0 ? right + 1 : 1);
            }
            m_dirty[std::size_t(y)] = 1;
        }
        m_placed.clear();
        m_open = 0;
    }

    void place(const Shape& s, int x, int y) {
        // Charts come largest first and many are alike: one at least as large both ways as
        // this one (its sides, whichever way turned) starts its search this one's shorter side
        // above the row where this one went, not at the first row again. (With sizes by powers
        // of two instead of the sides themselves, a chart sent larger ones of its size class
        // past gaps they fitted.)
        remember({std::min(s.width, s.height), std::max(s.width, s.height),
                  std::max(0, y - std::min({s.width, s.height, m_size}))});
        for (int j = 0; j < s.height; ++j) {
            std::int16_t* row = &m_run[index(0, y + j)];
            for (int k = s.rowBegin[std::size_t(j)]; k < s.rowBegin[std::size_t(j) + 1]; ++k) {
                const auto [a, b] = s.runs[std::size_t(k)];
                const int begin = x + a, end = x + b; // inclusive
                for (int i = begin; i <= end; ++i)
                    row[i] = -1; // fixed up below
                // The taken stretch now reaches from its left end to the right end of what
                // was taken after it.
                int right = end + 1;
                while (right < m_size && row[right] < 0)
                    right += -row[right];
                int left = begin;
                while (left > 0 && row[left - 1] < 0)
                    --left;
                for (int i = right - 1; i >= left; --i)
                    row[i] = std::int16_t(-(right - i));
                for (int i = left - 1; i >= 0 && row[i] > 0; --i)
                    row[i] = std::int16_t(left - i);
            }
            m_dirty[std::size_t(y + j)] = 1;
        }
    }

private:
    /** A placed chart's sides (shorter, longer) and where a chart no smaller both ways starts. */
    struct Placed {
        int shorter, longer, from;
        bool covers(const Placed& o) const { // o's searches start no lower than this gives
            return shorter <= o.shorter && longer <= o.longer && from >= o.from;
        }
    };

    int searchFrom(const Shape& s) const {
        const int shorter = std::min(s.width, s.height), longer = std::max(s.width, s.height);
        int from = 0;
        for (const Placed& p : m_placed)
            if (p.shorter <= shorter && p.longer <= longer)
                from = std::max(from, p.from);
        return from;
    }

    /** Keeps only the placed charts that no other one covers. */
    void remember(const Placed& p) {
        for (const Placed& q : m_placed)
            if (q.covers(p))
                return;
        std::erase_if(m_placed, [&](const Placed& q) { return p.covers(q); });
        m_placed.push_back(p);
    }

    bool fitsAt(const Shape& s, int x, int y) {
        for (int j = 0; j < s.height; ++j)
            if (testRow(s, j, x, y) >= 0)
                return false;
        return true;
    }

    /**
     * -1 if row j of s fits at (x, y); else the next x worth testing (the row's run moved past
     * the taken stretch it met), and j becomes the last failed row.
     */
    int testRow(const Shape& s, int j, int x, int y) {
        const std::int16_t* row = &m_run[index(0, y + j)];
        for (int k = s.rowBegin[std::size_t(j)]; k < s.rowBegin[std::size_t(j) + 1]; ++k) {
            const auto [a, b] = s.runs[std::size_t(k)];
            const int v = row[x + a];
            if (v > b - a)
                continue;
            // Taken at x + a + max(v, 0): move the run past that taken stretch.
            const int taken = x + a + std::max(v, 0);
            m_lastFailed = j;
            return taken - row[taken] - a;
        }
        return -1;
    }

    std::size_t index(int x, int y) const {
        return std::size_t(y) * std::size_t(m_size) + std::size_t(x);
    }
    int widest(int y) {
        if (m_dirty[std::size_t(y)]) {
            int w = 0;
            const std::int16_t* row = &m_run[index(0, y)];
            for (int x = 0; x < m_size; ++x)
                w = std::max(w, int(row[x]));
            m_widest[std::size_t(y)] = w;
            m_dirty[std::size_t(y)] = 0;
        }
        return m_widest[std::size_t(y)];
    }

    int m_size;
    std::vector<std::int16_t> m_run;
    std::vector<int> m_widest;
    std::vector<std::uint8_t> m_dirty;
    std::vector<Placed> m_placed; // no one covering another
    int m_open = 0;
    int m_lastFailed = 0;
};

Error chartTooLargeError(int pageSize) {
    return Error{"a chart is larger than a " + std::to_string(pageSize) + " texel page",
                 ErrorKind::BadInput};
}

Error chartsDoNotFitError(std::uint32_t maxPages) {
    return Error{"the charts do not fit on " + std::to_string(maxPages) + " page(s)",
                 ErrorKind::BadInput};
}

/** Every chart's mask, made in parallel; stops when cancelled or at a chart that is larger than a
 *  page both ways. */
Status maskCharts(const std::vector<Chart>& charts, double density, const UvLayoutOptions& options,
                  const Growth& growth, const std::atomic<bool>& cancel, std::vector<Mask>& masks) {
    const int pageSize = options.resolution;
    masks.resize(charts.size());
    std::atomic<std::size_t> next{0};
    std::atomic<bool> tooLarge{false};
    const unsigned threads = resolveThreadCount(options.threads);
    parallelRanges(int(threads), threads, [&](int, int, int) {
        for (std::size_t i = next++; i < charts.size() && !cancel && !tooLarge; i = next++) {
            glm::dvec2 lo(1e300), hi(-1e300);
            for (const glm::dvec2& p : charts[i].uv) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            if (!charts[i].uv.empty() &&
                std::min(hi.x - lo.x, hi.y - lo.y) * density > double(pageSize)) {
                tooLarge = true;
                break;
            }
            if (charts[i].area > 0.0) // charts without area are points that need no room
                masks[i] = maskChart(charts[i], density, growth);
        }
    });
    if (cancel)
        return Error{"cancelled", ErrorKind::Cancelled};
    if (tooLarge)
        return chartTooLargeError(pageSize);
    return {};
}

/** Each mask's texel count in texels; returns their sum. */
double countMaskTexels(const std::vector<Mask>& masks, std::vector<std::size_t>& texels) {
    texels.resize(masks.size());
    double allTexels = 0.0;
    for (std::size_t i = 0; i < masks.size(); ++i) {
        texels[i] = std::size_t(std::count(masks[i].bits.begin(), masks[i].bits.end(), 1u));
        allTexels += double(texels[i]);
    }
    return allTexels;
}

/**
 * The order the charts are placed in: the most texels first. Small charts go last: before them,
 * what is placed grows so that their smaller rings keep the full padding to it.
 */
std::vector<std::uint32_t> packingOrder(const std::vector<Mask>& masks,
                                        const std::vector<std::size_t>& texels) {
    std::vector<std::uint32_t> order(masks.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        if (masks[a].small != masks[b].small)
            return masks[b].small;
        return texels[a] != texels[b] ? texels[a] > texels[b] : a < b;
    });
    return order;
}

/** The pages being filled, and whether the small charts' turn has come. */
struct PageFill {
    int pageSize = 0;
    std::uint32_t maxPages = 0;
    int smallGrowth = 0; // how much placed charts grow when the small ones start
    bool smallPhase = false;
    std::vector<Page> pages;
};

/**
 * Puts m on the first page with room for it (a new one when none has, at most maxPages), in the
 * quarter turn that keeps its top lowest.
 */
Status placeMask(PageFill& fill, const Mask& m, Placement& pl) {
    std::vector<Page>& pages = fill.pages;
    if (std::min(m.width, m.height) > fill.pageSize)
        return chartTooLargeError(fill.pageSize);
    if (m.small && !fill.smallPhase) {
        fill.smallPhase = true;
        for (Page& page : pages)
            page.grow(fill.smallGrowth);
    }
    Shape shapes[4];
    for (int rot = 0; rot < 4; ++rot)
        shapes[rot] = rotatedShape(m, rot);
    for (std::size_t page = 0;; ++page) {
        if (page == pages.size()) {
            if (pages.size() >= fill.maxPages)
                return chartsDoNotFitError(fill.maxPages);
            pages.emplace_back(fill.pageSize);
            if (fill.smallPhase)
                pages.back().grow(fill.smallGrowth);
        }
        long long bestTop = LLONG_MAX;
        int bestX = 0, bestY = 0, bestRotation = -1;
        for (int rot = 0; rot < 4; ++rot) {
            int x, y;
            if (pages[page].firstFit(shapes[rot], bestTop, x, y)) {
                bestTop = y + shapes[rot].height;
                bestX = x;
                bestY = y;
                bestRotation = rot;
            }
        }
        if (bestRotation < 0)
            continue;
        pages[page].place(shapes[bestRotation], bestX, bestY);
        pl.page = std::uint32_t(page);
        pl.rotation = bestRotation;
        pl.x = bestX;
        pl.y = bestY;
        pl.origin = m.origin;
        pl.width = m.width;
        pl.height = m.height;
        return {};
    }
}

} // namespace

glm::dvec2 placeUv(const Placement& placement, const glm::dvec2& uv, double density) {
    const glm::dvec2 q = uv * density - placement.origin;
    const double w = placement.width, h = placement.height;
    glm::dvec2 r;
    switch (placement.rotation) {
    case 0:
        r = q;
        break;
    case 1:
        r = {h - q.y, q.x};
        break;
    case 2:
        r = {w - q.x, h - q.y};
        break;
    default:
        r = {q.y, w - q.x};
        break;
    }
    return r + glm::dvec2(placement.x, placement.y);
}

int smallChartRadius(int padding) {
    return ((padding + 1) / 2 + 1) / 2;
}

Result<Packing> packCharts(const std::vector<Chart>& charts, double density,
                           const UvLayoutOptions& options, std::uint32_t maxPages,
                           const std::atomic<bool>& cancel) {
    const int pageSize = options.resolution;
    Growth growth;
    growth.r = (options.padding + 1) / 2;
    growth.rSmall = smallChartRadius(options.padding);
    growth.smallTexels = options.smallChartTexels;
    std::vector<Mask> masks;
    if (Status masked = maskCharts(charts, density, options, growth, cancel, masks); !masked)
        return masked.takeError();
    std::vector<std::size_t> texels;
    if (countMaskTexels(masks, texels) > double(maxPages) * double(pageSize) * double(pageSize))
        return chartsDoNotFitError(maxPages);
    const std::vector<std::uint32_t> order = packingOrder(masks, texels);

    PageFill fill;
    fill.pageSize = pageSize;
    fill.maxPages = maxPages;
    fill.smallGrowth = growth.r - growth.rSmall;
    Packing packing;
    packing.placements.resize(charts.size());
    for (std::size_t n = 0; n < order.size(); ++n) {
        if (n % 64 == 0 && cancel)
            return Error{"cancelled", ErrorKind::Cancelled};
        const std::uint32_t i = order[n];
        if (masks[i].bits.empty())
            continue; // a point: at the first page's corner, where it covers nothing
        if (Status placed = placeMask(fill, masks[i], packing.placements[i]); !placed)
            return placed.takeError();
        masks[i] = {};
    }
    packing.pageCount = std::uint32_t(std::max<std::size_t>(fill.pages.size(), 1));
    return packing;
}

} // namespace core::uvl
