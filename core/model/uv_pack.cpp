// SPDX-License-Identifier: GPL-3.0-or-later
// Packing the charts of the automatic UV layout into texture pages by their shape: each chart is
// rasterized conservatively into a texel mask, grown by half the padding, and dropped onto a
// skyline per page (Tetris-like: the mask's lowest texel of each column rests on the column's
// height), in the quarter turn and place that keep the page lowest.
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

/** The outline of a chart's grown mask: per column and per row, its first and last texel. */
struct Outline {
    int width = 0, height = 0;
    glm::dvec2 origin{0.0};
    std::vector<int> columnLo, columnHi; // rows; lo > hi for an empty column
    std::vector<int> rowLo, rowHi;       // columns; lo > hi for an empty row
};

/** Marks the texels of mask (width w) that triangle a, b, c touches at all. */
void rasterizeConservative(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
                           std::vector<std::uint8_t>& mask, int w, int h) {
    const glm::dvec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    const int x0 = std::max(0, int(std::floor(lo.x))), x1 = std::min(w - 1, int(std::floor(hi.x)));
    const int y0 = std::max(0, int(std::floor(lo.y))), y1 = std::min(h - 1, int(std::floor(hi.y)));
    const double area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    const double sign = area >= 0.0 ? 1.0 : -1.0;
    const glm::dvec2 p[3] = {a, b, c};
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            bool inside = true;
            if (area != 0.0) {
                const glm::dvec2 centre(x + 0.5, y + 0.5);
                // Separating axis test of the texel square against each edge's line.
                for (int k = 0; k < 3 && inside; ++k) {
                    const glm::dvec2 e0 = p[k], e1 = p[(k + 1) % 3];
                    const double dx = e1.x - e0.x, dy = e1.y - e0.y;
                    const double f = sign * (dx * (centre.y - e0.y) - dy * (centre.x - e0.x));
                    inside = f + 0.5 * (std::fabs(dx) + std::fabs(dy)) >= 0.0;
                }
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

Outline outlineChart(const Chart& chart, double density, int r) {
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
    std::vector<std::uint8_t> mask(std::size_t(w) * std::size_t(h), 0u);
    const glm::dvec2 shift = lo - margin;
    for (const auto& c : chart.local)
        rasterizeConservative(chart.uv[c[0]] * density - shift, chart.uv[c[1]] * density - shift,
                              chart.uv[c[2]] * density - shift, mask, w, h);
    if (chart.local.empty() || std::find(mask.begin(), mask.end(), 1u) == mask.end())
        mask[std::size_t(r + 1) * std::size_t(w) + std::size_t(r + 1)] = 1;
    dilate(mask, w, h, r);
    int x0 = w, x1 = -1, y0 = h, y1 = -1;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (mask[std::size_t(y) * std::size_t(w) + std::size_t(x)]) {
                x0 = std::min(x0, x);
                x1 = std::max(x1, x);
                y0 = std::min(y0, y);
                y1 = std::max(y1, y);
            }
    Outline o;
    o.width = x1 - x0 + 1;
    o.height = y1 - y0 + 1;
    o.origin = shift + glm::dvec2(x0, y0);
    o.columnLo.assign(std::size_t(o.width), o.height);
    o.columnHi.assign(std::size_t(o.width), -1);
    o.rowLo.assign(std::size_t(o.height), o.width);
    o.rowHi.assign(std::size_t(o.height), -1);
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
            if (mask[std::size_t(y) * std::size_t(w) + std::size_t(x)]) {
                const int i = x - x0, j = y - y0;
                o.columnLo[std::size_t(i)] = std::min(o.columnLo[std::size_t(i)], j);
                o.columnHi[std::size_t(i)] = std::max(o.columnHi[std::size_t(i)], j);
                o.rowLo[std::size_t(j)] = std::min(o.rowLo[std::size_t(j)], i);
                o.rowHi[std::size_t(j)] = std::max(o.rowHi[std::size_t(j)], i);
            }
    return o;
}

/** A chart's column profile after `rotation` quarter turns (see placeUv). */
struct Profile {
    int width = 0, height = 0;
    std::vector<int> lo, hi;
};

Profile rotatedProfile(const Outline& o, int rotation) {
    Profile p;
    const int w = o.width, h = o.height;
    const bool swapped = rotation % 2 == 1;
    p.width = swapped ? h : w;
    p.height = swapped ? w : h;
    p.lo.resize(std::size_t(p.width));
    p.hi.resize(std::size_t(p.width));
    for (int c = 0; c < p.width; ++c) {
        const std::size_t k = std::size_t(c);
        switch (rotation) {
        case 0:
            p.lo[k] = o.columnLo[k];
            p.hi[k] = o.columnHi[k];
            break;
        case 1: // texel (i, j) goes to (h − 1 − j, i)
            p.lo[k] = o.rowLo[std::size_t(h - 1 - c)];
            p.hi[k] = o.rowHi[std::size_t(h - 1 - c)];
            break;
        case 2: // (i, j) goes to (w − 1 − i, h − 1 − j)
            p.lo[k] = h - 1 - o.columnHi[std::size_t(w - 1 - c)];
            p.hi[k] = h - 1 - o.columnLo[std::size_t(w - 1 - c)];
            break;
        default: // (i, j) goes to (j, w − 1 − i)
            p.lo[k] = w - 1 - o.rowHi[k];
            p.hi[k] = w - 1 - o.rowLo[k];
            break;
        }
    }
    return p;
}

struct Spot {
    long long top = LLONG_MAX;
    long long waste = LLONG_MAX;
    int x = 0, y = 0, rotation = 0;

    bool betterThan(const Spot& o) const {
        return top != o.top ? top < o.top : waste < o.waste;
    }
};

/** The lowest place for profile p on a page's skyline, or top == LLONG_MAX if none fits. */
void bestSpot(const std::vector<int>& sky, int pageSize, const Profile& p, int rotation,
              Spot& best) {
    for (int x = 0; x + p.width <= pageSize; ++x) {
        int y = 0;
        bool skip = false;
        for (int c = 0; c < p.width; ++c) {
            if (p.lo[std::size_t(c)] > p.hi[std::size_t(c)])
                continue;
            y = std::max(y, sky[std::size_t(x + c)] - p.lo[std::size_t(c)]);
            if (static_cast<long long>(y) + p.height > best.top) {
                skip = true;
                break;
            }
        }
        if (skip || y + p.height > pageSize)
            continue;
        long long waste = 0;
        for (int c = 0; c < p.width; ++c)
            if (p.lo[std::size_t(c)] <= p.hi[std::size_t(c)])
                waste += y + p.lo[std::size_t(c)] - sky[std::size_t(x + c)];
        Spot s{y + p.height, waste, x, y, rotation};
        if (s.betterThan(best))
            best = s;
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

Result<Packing> packCharts(const std::vector<Chart>& charts, double density,
                           const UvLayoutOptions& options, std::uint32_t maxPages,
                           const std::atomic<bool>& cancel) {
    const int pageSize = options.resolution;
    const int r = (options.padding + 1) / 2;
    std::vector<Outline> outlines(charts.size());
    std::atomic<std::size_t> next{0};
    parallelRanges(int(resolveThreadCount(options.threads)), options.threads, [&](int, int, int) {
        for (std::size_t i = next++; i < charts.size() && !cancel; i = next++)
            outlines[i] = outlineChart(charts[i], density, r);
    });
    if (cancel)
        return Error{"cancelled", ErrorKind::Cancelled};

    std::vector<std::uint32_t> order(charts.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const Outline &oa = outlines[a], &ob = outlines[b];
        const int ma = std::max(oa.width, oa.height), mb = std::max(ob.width, ob.height);
        if (ma != mb)
            return ma > mb;
        const long long aa = (long long)oa.width * oa.height, ab = (long long)ob.width * ob.height;
        return aa != ab ? aa > ab : a < b;
    });

    Packing packing;
    packing.placements.resize(charts.size());
    std::vector<std::vector<int>> skylines;
    for (std::size_t n = 0; n < order.size(); ++n) {
        if (n % 256 == 0 && cancel)
            return Error{"cancelled", ErrorKind::Cancelled};
        const std::uint32_t i = order[n];
        const Outline& o = outlines[i];
        if (std::max(o.width, o.height) > pageSize)
            return Error{"a chart is larger than a " + std::to_string(pageSize) + " texel page",
                         ErrorKind::BadInput};
        Profile profiles[4];
        for (int rot = 0; rot < 4; ++rot)
            profiles[rot] = rotatedProfile(o, rot);
        bool placed = false;
        for (std::size_t page = 0; !placed; ++page) {
            if (page == skylines.size()) {
                if (skylines.size() >= maxPages)
                    return Error{"the charts do not fit on " + std::to_string(maxPages) +
                                     " page(s)",
                                 ErrorKind::BadInput};
                skylines.emplace_back(std::size_t(pageSize), 0);
            }
            Spot best;
            for (int rot = 0; rot < 4; ++rot)
                bestSpot(skylines[page], pageSize, profiles[rot], rot, best);
            if (best.top == LLONG_MAX)
                continue;
            const Profile& p = profiles[best.rotation];
            for (int c = 0; c < p.width; ++c)
                if (p.lo[std::size_t(c)] <= p.hi[std::size_t(c)])
                    skylines[page][std::size_t(best.x + c)] = best.y + p.hi[std::size_t(c)] + 1;
            Placement& pl = packing.placements[i];
            pl.page = std::uint32_t(page);
            pl.rotation = best.rotation;
            pl.x = best.x;
            pl.y = best.y;
            pl.origin = o.origin;
            pl.width = o.width;
            pl.height = o.height;
            placed = true;
        }
    }
    packing.pageCount = std::uint32_t(std::max<std::size_t>(skylines.size(), 1));
    return packing;
}

} // namespace core::uvl
