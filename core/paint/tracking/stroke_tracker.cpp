// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/tracking/stroke_tracker.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

#include "core/depth/depth_layers.h"

namespace core {

namespace {

// Neighbour offsets in Direction order: right, left, up (y - 1), down (y + 1).
constexpr int kDx[4] = {1, -1, 0, 0};
constexpr int kDy[4] = {0, 0, -1, 1};

constexpr std::uint32_t kNoLimit = std::numeric_limits<std::uint32_t>::max();

/**
 * The most 4-steps a search of radius r may take when the anti-bleeding limit is on. A 4-step
 * path to a pixel at offset (dx, dy) on an unbroken surface is |dx| + |dy| long, at most √2
 * times the Euclidean distance (on the diagonal), so ⌊√2·r⌋ never clips the brush disc on a
 * surface without gaps; it only cuts pixels that are reachable by a detour alone, like the far
 * side of a contour that the search would have to go around (the paper's Figure 6).
 */
std::uint32_t pathLimit(bool antiBleeding, double radius) {
    if (!antiBleeding)
        return kNoLimit;
    const double steps = std::floor(std::sqrt(2.0) * radius);
    return steps < double(kNoLimit) ? std::uint32_t(steps) : kNoLimit;
}

float sanitizePressure(float pressure) {
    return std::isfinite(pressure) ? std::clamp(pressure, 0.0f, 1.0f) : 1.0f;
}

/**
 * Input positions a pointer can produce. Anything else (NaN, or a jump of 10^30 px that would
 * take forever to resample) is dropped like a bad event.
 */
bool sane(glm::vec2 v) {
    constexpr float kMax = 1.0e5f;
    return std::fabs(v.x) <= kMax && std::fabs(v.y) <= kMax; // false for NaN
}

} // namespace

std::uint32_t visibleFragmentByRank(const DepthStack& stack,
                                    std::span<const std::uint32_t> fragmentRegion,
                                    std::span<const std::uint32_t> regionRank, std::size_t pixel) {
    if (pixel + 1 >= stack.offsets.size())
        return kNone;
    std::uint32_t best = kNone, bestRank = kNone;
    for (std::uint32_t f = stack.offsets[pixel]; f < stack.offsets[pixel + 1]; ++f) {
        if (f >= fragmentRegion.size() || fragmentRegion[f] >= regionRank.size())
            continue;
        const std::uint32_t rank = regionRank[fragmentRegion[f]];
        if (rank < bestRank) {
            best = f;
            bestRank = rank;
        }
    }
    return best;
}

bool StrokeTracker::setDepthLayers(const DepthStack& stack, const Connectivity& connectivity) {
    clearDepthLayers();
    const std::size_t pixels = stack.pixelCount();
    const std::size_t fragments = stack.fragmentCount();
    if (stack.width <= 0 || stack.height <= 0 || stack.offsets.size() != pixels + 1 ||
        stack.offsets.back() != fragments || fragments >= kNone ||
        connectivity.width != stack.width || connectivity.height != stack.height ||
        connectivity.links.size() != 4 * fragments)
        return false;
    m_stack = &stack;
    m_connectivity = &connectivity;
    // Every dab only touches what it reaches (generations). The marks of earlier views are
    // older than any generation to come, so arrays of the same size are kept as they are:
    // clearing them took 1.3 ms of each build of a 1280×720 view.
    if (m_fragments.size() != fragments)
        m_fragments.assign(fragments, {});
    if (m_pixels.size() != pixels)
        m_pixels.assign(pixels, {});
    return true;
}

bool StrokeTracker::setDepthLayers(const DepthLayers& layers) {
    return setDepthLayers(layers.stack, layers.connectivity);
}

void StrokeTracker::clearDepthLayers() {
    m_stack = nullptr;
    m_connectivity = nullptr;
    m_inStroke = false;
    m_tracking = false;
    m_gen = 0;
    m_mpPixels.clear();
    m_mtPixels.clear();
    m_mtQueue.clear();
    m_mtHead = 0;
}

std::size_t StrokeTracker::startStroke(const StrokePoint& point, const Brush& brush,
                                       std::vector<Dab>& out, std::uint32_t layer) {
    m_inStroke = false;
    m_tracking = false;
    m_startLayer = layer;
    if (!sane(point.position))
        return 0;
    m_brush = brush;
    // Settings from a file or a slider: keep NaN and negative values out of the maps' arithmetic.
    if (!(m_brush.radius >= 0.0f))
        m_brush.radius = 0.0f;
    if (!(m_brush.opacity >= 0.0f))
        m_brush.opacity = 0.0f;
    m_inStroke = true;
    const float pressure = sanitizePressure(point.pressure);
    m_last = {point.position, pressure};
    m_carry = 0.0;
    m_dabPressure = pressure;
    // The stroke's seed: the brush's, mixed with the first point's exact position.
    std::uint32_t xBits = 0, yBits = 0;
    std::memcpy(&xBits, &point.position.x, sizeof xBits);
    std::memcpy(&yBits, &point.position.y, sizeof yBits);
    m_rng = SplitMix64{std::uint64_t(m_brush.seed) << 32 ^ (std::uint64_t(xBits) << 16) ^ yBits};
    m_pathAngle = 0.0f;
    m_sizeFactor = 1.0f;
    return placeDab(point.position, pressure, out);
}

std::size_t StrokeTracker::moveStroke(const StrokePoint& point, std::vector<Dab>& out) {
    if (!m_inStroke || !sane(point.position))
        return 0;
    const float p1 = sanitizePressure(point.pressure);
    const glm::dvec2 a(m_last.position), b(point.position);
    const double p0 = m_last.pressure;
    const double length = glm::length(b - a);
    std::size_t added = 0;
    if (length > 0.0) {
        m_pathAngle = float(std::atan2(b.y - a.y, b.x - a.x));
        // Dabs sit at fixed path lengths from the previous one, wherever the input events fall,
        // so the dabs of a path do not depend on how finely it was sampled.
        double t = 0.0;
        for (;;) {
            const double step = stepFor(m_dabPressure);
            const double need = std::max(step - m_carry, 0.0);
            if (t + need > length + 1e-6 * step)
                break;
            t = std::min(t + need, length);
            const double s = t / length;
            const float pressure = float(p0 + (double(p1) - p0) * s);
            m_carry = 0.0;
            m_dabPressure = pressure;
            added += placeDab(glm::vec2(a + (b - a) * s), pressure, out);
        }
        m_carry += length - t;
    }
    m_last = {point.position, p1};
    return added;
}

float StrokeTracker::stepFor(float pressure) const {
    const float radius = m_brush.radius * (m_brush.pressureRadius ? pressure : 1.0f) * m_sizeFactor;
    const float step = m_brush.spacing * radius;
    // Below half a pixel more dabs change nothing on a pixel map; the floor also keeps a zero
    // radius or spacing from looping forever.
    return step >= 0.5f ? step : 0.5f;
}

void StrokeTracker::beginMaps() {
    m_gen = ++m_lastGen;
    if (m_gen == 0) {
        // 2^32 dabs later: clear the marks once instead of comparing wider generations.
        std::fill(m_fragments.begin(), m_fragments.end(), FragmentMarks{});
        std::fill(m_pixels.begin(), m_pixels.end(), PixelSlot{});
        m_gen = m_lastGen = 1;
    }
    m_mpPixels.clear();
    m_mtPixels.clear();
    m_mtQueue.clear();
    m_mtHead = 0;
}

std::size_t StrokeTracker::placeDab(glm::vec2 center, float pressure, std::vector<Dab>& out) {
    if (!m_stack)
        return 0;
    Dab dab;
    dab.center = center;
    dab.radius = m_brush.radius * (m_brush.pressureRadius ? pressure : 1.0f);
    dab.opacity =
        std::clamp(m_brush.opacity, 0.0f, 1.0f) * (m_brush.pressureOpacity ? pressure : 1.0f);
    jitterDab(center, dab);
    return trackDab(center, dab, out);
}

void StrokeTracker::startCopy(const Brush& brush, std::uint32_t layer) {
    m_brush = brush;
    m_inStroke = true;
    m_tracking = false;
    m_startLayer = layer;
}

std::size_t StrokeTracker::followDab(Dab like, std::vector<Dab>& out) {
    if (!m_inStroke || !m_stack || !sane(like.center))
        return 0;
    like.layer = 0;
    like.paintable.clear();
    const glm::vec2 center = like.center;
    return trackDab(center, like, out);
}

std::size_t StrokeTracker::trackDab(glm::vec2 center, Dab& dab, std::vector<Dab>& out) {
    if (!m_layerAware) {
        // Conventional: no tracking across layers; a later layer-aware dab starts afresh.
        m_tracking = false;
        beginMaps();
        m_center = center;
        paintVisible(dab);
        if (dab.paintable.empty())
            return 0;
        out.push_back(std::move(dab));
        return 1;
    }

    const int w = m_stack->width, h = m_stack->height;
    if (!(center.x >= 0.0f && center.x < float(w) && center.y >= 0.0f && center.y < float(h)))
        return 0; // off screen: like background
    const auto pixel =
        std::uint32_t(std::size_t(center.y) * std::size_t(w) + std::size_t(center.x));
    if (m_stack->layerCount(pixel) == 0)
        return 0; // background
    // On-Mouse-Down takes the visible layer, On-Mouse-Drag the previous dab's Mt. A sample on
    // background or outside Mt leaves the tracking state at the last painted dab.
    std::uint32_t fragment = kNone;
    if (m_tracking) {
        fragment = trackedFragment(pixel);
    } else if (m_startLayer > 0) {
        fragment = m_stack->fragment(pixel, m_startLayer);
        if (fragment == kNone || isHidden(fragment))
            fragment = visibleFragment(pixel);
    } else {
        fragment = visibleFragment(pixel);
    }
    if (fragment == kNone)
        return 0;
    m_startLayer = 0;

    beginMaps();
    m_center = center;
    dab.layer = layerOf(pixel, fragment);
    searchPaintable(pixel, fragment, dab);

    // Seed the R_max search; it runs only when a lookup misses Mp (see trackedFragment()).
    const double trackRadius =
        std::max({double(m_brush.effectiveTrackRadius()), double(dab.radius), 1.0});
    m_trackRadius2 = float(trackRadius * trackRadius);
    m_trackLimit = pathLimit(m_antiBleeding, trackRadius);
    m_fragments[fragment].mt = m_gen;
    m_mtQueue.push_back({std::int32_t(pixel % std::uint32_t(w)),
                         std::int32_t(pixel / std::uint32_t(w)), fragment, 0});
    m_pixels[pixel].mtGen = m_gen;
    m_pixels[pixel].mtFragment = fragment;
    if (m_pixels[pixel].mpGen != m_gen)
        m_mtPixels.push_back(pixel);
    m_tracking = true;

    out.push_back(std::move(dab));
    return 1;
}

void StrokeTracker::jitterDab(glm::vec2& center, Dab& dab) {
    // Every sample draws the same numbers, painted or not, so a dab's jitter depends only on the
    // seed and its place in the stroke.
    const float uSize = m_rng.unit(), uOpacity = m_rng.unit(), uAngle = m_rng.unit();
    const float uTurn = m_rng.unit(), uScatter = m_rng.unit(), uDirection = m_rng.unit();
    const BrushJitter& j = m_brush.jitter;
    constexpr float kPi = 3.14159265358979f;
    if (j.size > 0.0f) {
        m_sizeFactor = 1.0f - std::clamp(j.size, 0.0f, 1.0f) * uSize;
        dab.radius *= m_sizeFactor;
    }
    if (j.opacity > 0.0f)
        dab.opacity *= 1.0f - std::clamp(j.opacity, 0.0f, 1.0f) * uOpacity;
    float degrees = std::isfinite(m_brush.angle) ? m_brush.angle : 0.0f;
    if (m_brush.angleMode == TipAngleMode::Random)
        degrees += 360.0f * uTurn;
    if (j.angle > 0.0f)
        degrees += std::clamp(j.angle, 0.0f, 180.0f) * (2.0f * uAngle - 1.0f);
    dab.angle =
        degrees * (kPi / 180.0f) + (m_brush.angleMode == TipAngleMode::Stroke ? m_pathAngle : 0.0f);
    if (j.scatter > 0.0f) {
        // Uniform over the disc of scatter radii around the path point.
        const float r = std::clamp(j.scatter, 0.0f, 4.0f) * dab.radius * std::sqrt(uScatter);
        const float a = 2.0f * kPi * uDirection;
        center += glm::vec2(r * std::cos(a), r * std::sin(a));
        dab.center = center;
    }
}

template <std::uint32_t StrokeTracker::FragmentMarks::*Mark>
bool StrokeTracker::searchStep(const Node& n, int d, const std::uint8_t* nodeLinks,
                               const std::uint32_t* offsets, glm::vec2 centre, float radius2,
                               SearchStep& out) {
    const std::uint32_t l = nodeLinks[d];
    if (l == 0)
        return false;
    const int w = m_stack->width, h = m_stack->height;
    const int nx = n.x + kDx[d], ny = n.y + kDy[d];
    if (nx < 0 || ny < 0 || nx >= w || ny >= h)
        return false;
    const auto q = std::uint32_t(ny * w + nx);
    const std::uint32_t begin = offsets[q];
    if (l > offsets[q + 1] - begin)
        return false; // a link past the neighbour's fragments: ignored, as segmentDepthLayers does
    const std::uint32_t g = begin + l - 1;
    std::uint32_t& mark = m_fragments[g].*Mark;
    if (mark == m_gen || isHidden(g))
        return false;
    mark = m_gen;
    const float dx = float(nx) + 0.5f - centre.x, dy = float(ny) + 0.5f - centre.y;
    out.distance2 = dx * dx + dy * dy;
    if (out.distance2 > radius2)
        return false;
    out.node = {nx, ny, g, n.depth + 1};
    out.pixel = q;
    return true;
}

void StrokeTracker::searchPaintable(std::uint32_t pixel, std::uint32_t fragment, Dab& dab) {
    const int w = m_stack->width;
    const std::uint32_t* offsets = m_stack->offsets.data();
    const std::uint8_t* links = m_connectivity->links.data();
    const float r2 = dab.radius * dab.radius;
    const std::uint32_t limit = pathLimit(m_antiBleeding, dab.radius);
    const glm::vec2 c = m_center;
    const std::uint32_t gen = m_gen;

    // Mp is also the inner part of Mt: a pixel claimed here is Mt's too, with this layer.
    auto claim = [&](std::uint32_t q, std::uint32_t g, float d2) {
        PixelSlot& slot = m_pixels[q];
        if (slot.mpGen == gen)
            return; // one layer per pixel: the nearest, reached first
        slot.mpGen = gen;
        slot.mpFragment = g;
        m_mpPixels.push_back(q);
        m_mtPixels.push_back(q);
        dab.paintable.push_back({q, g, std::sqrt(d2)});
    };

    const int x0 = int(pixel % std::uint32_t(w)), y0 = int(pixel / std::uint32_t(w));
    m_mpQueue.clear();
    m_fragments[fragment].mp = gen;
    m_mpQueue.push_back({x0, y0, fragment, 0});
    // The dab's own node seeds the search even when a tiny radius leaves its pixel centre out.
    {
        const float dx = float(x0) + 0.5f - c.x, dy = float(y0) + 0.5f - c.y;
        if (dx * dx + dy * dy <= r2)
            claim(pixel, fragment, dx * dx + dy * dy);
    }
    dab.paintable.reserve(
        std::size_t(std::min(3.2 * double(r2) + 8.0, double(m_stack->pixelCount()))));
    for (std::size_t head = 0; head < m_mpQueue.size(); ++head) {
        const Node n = m_mpQueue[head];
        if (n.depth >= limit)
            continue;
        const std::uint8_t* nodeLinks = links + 4 * std::size_t(n.fragment);
        for (int d = 0; d < 4; ++d) {
            SearchStep next;
            if (!searchStep<&FragmentMarks::mp>(n, d, nodeLinks, offsets, c, r2, next))
                continue;
            m_mpQueue.push_back(next.node);
            claim(next.pixel, next.node.fragment, next.distance2);
        }
    }
}

bool StrokeTracker::growTrackable() {
    if (m_mtHead >= m_mtQueue.size())
        return false;
    const Node n = m_mtQueue[m_mtHead++];
    if (n.depth >= m_trackLimit)
        return true;
    const std::uint32_t* offsets = m_stack->offsets.data();
    const std::uint8_t* nodeLinks = m_connectivity->links.data() + 4 * std::size_t(n.fragment);
    const std::uint32_t gen = m_gen;
    for (int d = 0; d < 4; ++d) {
        SearchStep next;
        if (!searchStep<&FragmentMarks::mt>(n, d, nodeLinks, offsets, m_center, m_trackRadius2,
                                            next))
            continue;
        m_mtQueue.push_back(next.node);
        const std::uint32_t q = next.pixel, g = next.node.fragment;
        PixelSlot& slot = m_pixels[q];
        if (slot.mtGen != gen) {
            slot.mtGen = gen;
            slot.mtFragment = g;
            if (slot.mpGen != gen)
                m_mtPixels.push_back(q); // Mp's pixels are listed already
        }
    }
    return true;
}

/**
 * The layer lookup of On-Mouse-Drag in the last painted dab's Mt. Successive dabs lie a spacing
 * (≤ R) apart, so the answer is nearly always in that dab's Mp, which was built anyway (layer
 * coherence). Otherwise the R_max search from the same node grows, breadth-first, only until it
 * reaches the pixel (the first layer reached there is Mt's answer) or runs out: a miss costs one
 * full Mt, a hit at distance d about d² nodes, and no dab ever rebuilds Mt in full.
 */
std::uint32_t StrokeTracker::trackedFragment(std::uint32_t pixel) {
    const PixelSlot& slot = m_pixels[pixel];
    if (slot.mpGen == m_gen)
        return slot.mpFragment;
    while (slot.mtGen != m_gen && growTrackable()) {
    }
    return slot.mtGen == m_gen ? slot.mtFragment : kNone;
}

void StrokeTracker::paintVisible(Dab& dab) {
    const int w = m_stack->width, h = m_stack->height;
    const glm::vec2 c = dab.center;
    if (!std::isfinite(c.x) || !std::isfinite(c.y))
        return;
    const float r = dab.radius, r2 = r * r;
    if (c.x >= 0.0f && c.x < float(w) && c.y >= 0.0f && c.y < float(h)) {
        const std::size_t centre = std::size_t(c.y) * std::size_t(w) + std::size_t(c.x);
        const std::uint32_t f = visibleFragment(centre);
        dab.layer = f == kNone ? 0 : layerOf(centre, f);
    }
    // Pixel centres within r: a standard screen-space brush paints whatever is visible there.
    auto lo = [](float v, int size) {
        return int(std::clamp(std::ceil(v - 0.5f), 0.0f, float(size)));
    };
    auto hi = [](float v, int size) {
        return int(std::clamp(std::floor(v - 0.5f), -1.0f, float(size - 1)));
    };
    const int x0 = lo(c.x - r, w), x1 = hi(c.x + r, w);
    const int y0 = lo(c.y - r, h), y1 = hi(c.y + r, h);
    for (int y = y0; y <= y1; ++y) {
        const float dy = float(y) + 0.5f - c.y;
        for (int x = x0; x <= x1; ++x) {
            const float dx = float(x) + 0.5f - c.x;
            const float d2 = dx * dx + dy * dy;
            if (d2 > r2)
                continue;
            const auto q = std::uint32_t(y * w + x);
            const std::uint32_t f = visibleFragment(q);
            if (f == kNone)
                continue;
            m_pixels[q].mpGen = m_gen;
            m_pixels[q].mpFragment = f;
            m_mpPixels.push_back(q);
            m_mtPixels.push_back(q);
            dab.paintable.push_back({q, f, std::sqrt(d2)});
        }
    }
}

std::uint32_t StrokeTracker::visibleFragment(std::size_t pixel) const {
    const std::uint32_t begin = m_stack->offsets[pixel], end = m_stack->offsets[pixel + 1];
    if (!m_visible)
        return begin < end ? begin : kNone; // the default order: layer 1 in front
    const std::uint32_t f = m_visible(pixel);
    return f >= begin && f < end ? f : kNone; // anything else is not this pixel's fragment
}

std::uint32_t StrokeTracker::paintableLayer(std::size_t pixel) const {
    if (!m_stack || m_gen == 0 || pixel >= m_pixels.size() || m_pixels[pixel].mpGen != m_gen)
        return 0;
    return layerOf(pixel, m_pixels[pixel].mpFragment);
}

std::uint32_t StrokeTracker::trackableLayer(std::size_t pixel) const {
    if (!m_stack || m_gen == 0 || pixel >= m_pixels.size())
        return 0;
    const PixelSlot& slot = m_pixels[pixel];
    if (slot.mpGen == m_gen)
        return layerOf(pixel, slot.mpFragment);
    return slot.mtGen == m_gen ? layerOf(pixel, slot.mtFragment) : 0;
}

void StrokeTracker::completeTrackableMap() {
    if (!m_stack)
        return;
    while (growTrackable()) {
    }
}

bool StrokeTracker::fillOverlay(std::span<std::uint8_t> rgba, std::uint8_t alpha) {
    if (!m_stack || rgba.size() != 4 * m_stack->pixelCount())
        return false;
    completeTrackableMap();
    std::fill(rgba.begin(), rgba.end(), std::uint8_t(0));
    for (const std::uint32_t p : m_mtPixels) {
        const bool paintable = m_pixels[p].mpGen == m_gen;
        std::uint8_t* px = rgba.data() + 4 * std::size_t(p);
        px[0] = paintable ? 255 : 0; // Mp red, the rest of Mt blue (the paper's Figure 4)
        px[1] = 0;
        px[2] = paintable ? 0 : 255;
        px[3] = alpha;
    }
    return true;
}

} // namespace core
