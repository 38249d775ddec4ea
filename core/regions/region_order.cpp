// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/regions/region_order.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/paint/tracking/stroke_tracker.h"

namespace core {

RegionOrder::RegionOrder(const RegionGraph& graph) {
    const std::size_t n = graph.regions.size();
    m_layer.resize(n);
    for (std::size_t r = 0; r < n; ++r)
        m_layer[r] = graph.regions[r].layer;
    m_neighborOffsets.assign(n + 1, 0);
    if (graph.neighborOffsets.size() == n + 1) {
        for (std::size_t r = 0; r < n; ++r) {
            for (const RegionLink& link : graph.neighborsOf(std::uint32_t(r))) {
                if (link.region < n && link.region != r)
                    m_neighbors.push_back(link.region);
            }
            m_neighborOffsets[r + 1] = std::uint32_t(m_neighbors.size());
        }
    }
    m_hidden.assign(n, 0);
    reset();
}

std::vector<std::uint32_t> RegionOrder::ranks() const {
    std::vector<std::uint32_t> rank(m_layer.size(), kNone);
    std::uint32_t next = 0;
    for (std::uint32_t r : m_order) {
        if (!m_hidden[r])
            rank[r] = next++;
    }
    return rank;
}

void RegionOrder::moveToFront(std::span<const std::uint32_t> group) {
    std::vector<std::uint8_t> inGroup(m_layer.size(), 0);
    for (std::uint32_t r : group)
        inGroup[r] = 1;
    std::vector<std::uint32_t> order(group.begin(), group.end());
    order.reserve(m_order.size());
    for (std::uint32_t r : m_order) {
        if (!inGroup[r])
            order.push_back(r);
    }
    m_order = std::move(order);
}

void RegionOrder::popUp(std::uint32_t region) {
    if (region >= m_layer.size())
        return;
    const std::uint32_t group[] = {region};
    moveToFront(group);
}

void RegionOrder::popUpWithNeighbours(std::uint32_t region) {
    if (region >= m_layer.size())
        return;
    std::vector<std::uint8_t> seen(m_layer.size(), 0);
    seen[region] = 1;
    std::vector<std::uint32_t> extra;
    // Level 1: the regions connected to region; level 2: those connected to level 1.
    std::vector<std::uint32_t> frontier{region};
    for (int level = 0; level < 2; ++level) {
        std::vector<std::uint32_t> nextFrontier;
        for (std::uint32_t r : frontier) {
            for (std::uint32_t i = m_neighborOffsets[r]; i < m_neighborOffsets[r + 1]; ++i) {
                const std::uint32_t s = m_neighbors[i];
                if (!seen[s]) {
                    seen[s] = 1;
                    extra.push_back(s);
                    nextFrontier.push_back(s);
                }
            }
        }
        frontier = std::move(nextFrontier);
    }
    std::sort(extra.begin(), extra.end(), [this](std::uint32_t a, std::uint32_t b) {
        return m_layer[a] != m_layer[b] ? m_layer[a] < m_layer[b] : a < b;
    });
    extra.insert(extra.begin(), region);
    moveToFront(extra);
}

std::uint32_t RegionOrder::visibleAt(std::span<const std::uint32_t> pixelRegions) const {
    std::vector<std::uint8_t> atPixel(m_layer.size(), 0);
    for (std::uint32_t r : pixelRegions) {
        if (r < m_layer.size())
            atPixel[r] = 1;
    }
    for (std::uint32_t r : m_order) {
        if (atPixel[r] && !m_hidden[r])
            return r;
    }
    return kNone;
}

std::uint32_t RegionOrder::cycleAt(std::span<const std::uint32_t> pixelRegions,
                                   bool withNeighbours) {
    const auto usable = [this](std::uint32_t r) { return r < m_layer.size() && !m_hidden[r]; };
    const std::uint32_t visible = visibleAt(pixelRegions);
    std::uint32_t target = kNone;
    if (visible != kNone) {
        const auto at = std::find(pixelRegions.begin(), pixelRegions.end(), visible);
        const auto below = std::find_if(at + 1, pixelRegions.end(), usable);
        if (below != pixelRegions.end())
            target = *below;
    }
    if (target == kNone) {
        const auto top = std::find_if(pixelRegions.begin(), pixelRegions.end(), usable);
        if (top == pixelRegions.end())
            return kNone;
        target = *top;
    }
    if (withNeighbours)
        popUpWithNeighbours(target);
    else
        popUp(target);
    return target;
}

std::vector<std::uint32_t> RegionOrder::pruned(bool transparency) const {
    std::uint32_t maxLayer = 0;
    for (std::uint32_t l : m_layer)
        maxLayer = std::max(maxLayer, l);
    // Per layer: regions in it, regions seen so far, whether one of them is hidden.
    std::vector<std::uint32_t> total(maxLayer + 1, 0), seen(maxLayer + 1, 0);
    std::vector<std::uint8_t> hasHidden(maxLayer + 1, 0);
    for (std::uint32_t r = 0; r < m_layer.size(); ++r) {
        ++total[m_layer[r]];
        if (m_hidden[r])
            hasHidden[m_layer[r]] = 1;
    }
    // The nearest layer j >= 1 all of whose regions were seen (and none hidden): it covers every
    // region on a layer below it. kNone while there is none.
    std::uint32_t blocker = kNone;
    std::vector<std::uint32_t> out;
    for (std::uint32_t r : m_order) {
        if (m_hidden[r])
            continue;
        const std::uint32_t layer = m_layer[r];
        if (blocker == 1)
            break; // layer 1 is complete: everything after it is covered
        if (blocker != kNone && layer > blocker)
            continue;
        out.push_back(r);
        if (layer >= 1 && ++seen[layer] == total[layer] && !hasHidden[layer] &&
            (!transparency || layer == 1))
            blocker = std::min(blocker, layer);
    }
    return out;
}

void RegionOrder::hide(std::uint32_t region) {
    if (region < m_hidden.size())
        m_hidden[region] = 1;
}

void RegionOrder::unhide(std::uint32_t region) {
    if (region < m_hidden.size())
        m_hidden[region] = 0;
}

void RegionOrder::unhideAll() {
    std::fill(m_hidden.begin(), m_hidden.end(), 0);
}

std::vector<std::uint32_t> RegionOrder::hiddenRegions() const {
    std::vector<std::uint32_t> out;
    for (std::uint32_t r = 0; r < m_hidden.size(); ++r) {
        if (m_hidden[r])
            out.push_back(r);
    }
    return out;
}

void RegionOrder::reset() {
    m_order.resize(m_layer.size());
    for (std::uint32_t r = 0; r < m_order.size(); ++r)
        m_order[r] = r;
    std::stable_sort(m_order.begin(), m_order.end(),
                     [this](std::uint32_t a, std::uint32_t b) { return m_layer[a] < m_layer[b]; });
}

std::vector<std::uint32_t> RegionOrder::prunedRanks(bool transparency) const {
    std::vector<std::uint32_t> rank(m_layer.size(), kNone);
    const std::vector<std::uint32_t> list = pruned(transparency);
    for (std::size_t i = 0; i < list.size(); ++i)
        rank[list[i]] = std::uint32_t(i);
    return rank;
}

std::vector<std::uint32_t> regionsAtPixel(const DepthStack& stack,
                                          std::span<const std::uint32_t> fragmentRegion,
                                          std::size_t pixel) {
    std::vector<std::uint32_t> out;
    if (pixel + 1 >= stack.offsets.size())
        return out;
    for (std::uint32_t f = stack.offsets[pixel]; f < stack.offsets[pixel + 1]; ++f)
        out.push_back(f < fragmentRegion.size() ? fragmentRegion[f] : kNone);
    return out;
}

std::vector<std::uint32_t> visibleRegionsAlong(const DepthStack& stack,
                                               std::span<const std::uint32_t> fragmentRegion,
                                               std::span<const std::uint32_t> ranks, glm::vec2 a,
                                               glm::vec2 b, float radius) {
    std::vector<std::uint32_t> out;
    const int w = stack.width, h = stack.height;
    if (w <= 0 || h <= 0 || stack.offsets.size() != stack.pixelCount() + 1 || !std::isfinite(a.x) ||
        !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y) ||
        !(radius >= 0.0f && radius < 1e5f))
        return out;
    const auto add = [&](int x, int y) {
        const std::uint32_t f = visibleFragmentByRank(
            stack, fragmentRegion, ranks, std::size_t(y) * std::size_t(w) + std::size_t(x));
        if (f != kNone && f < fragmentRegion.size() && fragmentRegion[f] != kNone)
            out.push_back(fragmentRegion[f]);
    };
    if (a.x >= 0.0f && a.y >= 0.0f && a.x < float(w) && a.y < float(h))
        add(int(a.x), int(a.y));
    const glm::vec2 ab = b - a;
    const float length2 = glm::dot(ab, ab);
    const auto clampTo = [](float v, int size) {
        return std::clamp(int(std::floor(v)), 0, size - 1);
    };
    const int x0 = clampTo(std::min(a.x, b.x) - radius, w),
              x1 = clampTo(std::max(a.x, b.x) + radius, w);
    const int y0 = clampTo(std::min(a.y, b.y) - radius, h),
              y1 = clampTo(std::max(a.y, b.y) + radius, h);
    const float r2 = radius * radius;
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
            const float t =
                length2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
            const glm::vec2 d = p - (a + t * ab);
            if (glm::dot(d, d) <= r2)
                add(x, y);
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

bool RegionOrder::setState(const RegionOrderState& state) {
    if (state.order.size() != m_order.size() || state.hidden.size() != m_hidden.size())
        return false;
    m_order = state.order;
    m_hidden = state.hidden;
    return true;
}

} // namespace core
