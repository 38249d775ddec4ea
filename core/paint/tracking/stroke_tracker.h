// SPDX-License-Identifier: GPL-3.0-or-later
// core/paint/tracking/: from pointer input to dabs: the paintable and trackable maps (Mp,
// Mt) a stroke follows across depth layers, and the stroke stabilizer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

#include "core/depth/connectivity.h"
#include "core/depth/depth_stack.h"
#include "core/paint/brush/dab.h"

namespace core {

struct DepthLayers;

/**
 * The visible fragment of a pixel (docs/architecture.md §3 step 3): the index of the fragment whose
 * region comes first in the region order, skipping hidden regions; kNone when none is visible.
 */
using VisibleFragmentFn = std::function<std::uint32_t(std::size_t pixel)>;

/**
 * The visible fragment of pixel for a region order given as ranks: regionRank[r] is region r's
 * place in the front-to-back list (lower is nearer the front), kNone for a hidden region;
 * fragmentRegion is Segmentation::region. kNone when every fragment there is hidden or unknown.
 */
std::uint32_t visibleFragmentByRank(const DepthStack& stack,
                                    std::span<const std::uint32_t> fragmentRegion,
                                    std::span<const std::uint32_t> regionRank, std::size_t pixel);

/** One input sample of a stroke. */
struct StrokePoint {
    /** Pixels, y down; pixel (x, y) covers [x, x + 1) × [y, y + 1). Beyond ±10^5: ignored. */
    glm::vec2 position{0.0f};
    float pressure = 1.0f; // 0..1; 1 for a mouse
};

/**
 * The stroke logic of layer-aware painting (the paper's On-Mouse-Down / On-Mouse-Drag,
 * docs/architecture.md §3 step 5): resamples the input at the brush spacing and turns every sample
 * into a Dab whose paintable map Mp was found by a breadth-first search over (pixel, layer) nodes
 * along the pixel connectivity, the dab's layer looked up in the trackable map Mt of the previous
 * dab. In the conventional mode a dab paints the visible fragment of every pixel under its
 * footprint instead, like a standard screen-space painter (even when its centre is on background:
 * Dab::layer 0), and tracks nothing (Mt = Mp).
 *
 * Mp: nodes within the dab radius R (pixel centres), reached by a search that stays inside that
 * disc and takes at most ⌊√2·R⌋ 4-steps (anti-bleeding); one layer per pixel, the first reached.
 * Mt: Mp, and elsewhere the first layer reached by the same search from the same node out to
 * R_max (Brush::effectiveTrackRadius()) with at most ⌊√2·R_max⌋ steps. Mt is grown lazily, only
 * as far as a lookup needs (see trackedFragment in the .cpp).
 *
 * Not thread-safe. The stack and connectivity passed to setDepthLayers() are referenced, not
 * copied.
 */
class StrokeTracker {
public:
    StrokeTracker() = default;

    /**
     * Uses stack and connectivity from now on; they must stay alive and unchanged until the next
     * call. Ends any stroke. Returns false (and paints nothing until the next call) when the
     * connectivity does not belong to the stack.
     */
    bool setDepthLayers(const DepthStack& stack, const Connectivity& connectivity);
    /** setDepthLayers(layers.stack, layers.connectivity). */
    bool setDepthLayers(const DepthLayers& layers);
    /** Forgets the layers (e.g. when the view changes) and ends any stroke. */
    void clearDepthLayers();

    /** The region order's visible fragment; an empty function means layer 1 (the default order). */
    void setVisibleFragment(VisibleFragmentFn visible) { m_visible = std::move(visible); }
    /**
     * Fragments no dab may paint or track through (hidden regions, paint-to-hide): non-zero
     * entries, per fragment of the stack; empty for none. Referenced, not copied: it must stay
     * alive and unchanged while in use.
     */
    void setHiddenFragments(std::span<const std::uint8_t> hidden) { m_hidden = hidden; }

    /**
     * Layer-aware (true, the default) or conventional WYSIWYG painting. Safe mid-stroke: the
     * next dab uses the new mode; a layer-aware dab after conventional ones starts tracking on the
     * surface visible under it.
     */
    void setLayerAware(bool on) { m_layerAware = on; }
    bool layerAware() const { return m_layerAware; }
    /** The path-length limit against colour bleeding (on by default; off for comparisons). */
    void setAntiBleeding(bool on) { m_antiBleeding = on; }
    bool antiBleeding() const { return m_antiBleeding; }

    /**
     * On-Mouse-Down: starts a stroke with brush at point and appends its first dab to out unless
     * the point is ignored (background, or nothing visible there). Until a layer-aware dab has
     * been painted, later dabs start the tracking the same way. A layer (1-based, layer-aware
     * mode) starts on that depth layer's fragment of the pixel instead of the visible one (where
     * the pixel has one that is not hidden), as a straight line from the end of a stroke behind
     * an occluder does. Returns the dabs appended (0, 1).
     */
    std::size_t startStroke(const StrokePoint& point, const Brush& brush, std::vector<Dab>& out,
                            std::uint32_t layer = 0);
    /**
     * On-Mouse-Drag: continues the stroke to point. The path is resampled every Brush::spacing ×
     * radius (radius after pressure, pressure interpolated along the path) and each sample is
     * tracked from the previous painted dab, so one long jump gives the same dabs as many small
     * moves. Samples on background or outside Mt are ignored. Returns the dabs appended.
     */
    std::size_t moveStroke(const StrokePoint& point, std::vector<Dab>& out);
    /**
     * A copy of a dab of another stroke (a symmetric copy, painted through its own view): a dab
     * at like's centre with its radius, opacity and angle, no jitter of its own. The first one
     * after startCopy() starts on depth layer startLayer (or the visible surface), later ones are
     * tracked from the previous copy. like becomes the dab (its paintable map's storage is reused,
     * so a caller that hands the previous one back allocates nothing). Returns the dabs appended
     * (0, 1).
     */
    std::size_t followDab(Dab like, std::vector<Dab>& out);
    /** Starts a stroke of copies (followDab()) with brush, the first on depth layer layer. */
    void startCopy(const Brush& brush, std::uint32_t layer);
    /** Ends the stroke; the maps of its last dab stay readable. */
    void endStroke() { m_inStroke = false; }
    bool inStroke() const { return m_inStroke; }

    /** Layer (1-based) of pixel in the last dab's paintable map Mp; 0 = none. */
    std::uint32_t paintableLayer(std::size_t pixel) const;
    /**
     * Layer of pixel in the last dab's trackable map Mt as far as it has been built (call
     * completeTrackableMap() first for all of it); 0 = none. Mt includes Mp.
     */
    std::uint32_t trackableLayer(std::size_t pixel) const;
    /** The pixels of Mp (the last dab's), in search order. */
    std::span<const std::uint32_t> paintablePixels() const { return m_mpPixels; }
    /** The pixels of Mt built so far, Mp's first. */
    std::span<const std::uint32_t> trackablePixels() const { return m_mtPixels; }
    /** Builds the rest of the last dab's Mt out to R_max (tracking builds only what it needs). */
    void completeTrackableMap();
    /**
     * The paper's Figure 4 overlay: fills rgba (4 bytes a pixel, row-major, top row first) with
     * Mp red, the rest of Mt blue (straight alpha), transparent elsewhere; completes Mt first.
     * Returns false and leaves rgba alone if its size is not 4 × the pixel count.
     */
    bool fillOverlay(std::span<std::uint8_t> rgba, std::uint8_t alpha = 128);

private:
    struct Node {
        std::int32_t x, y;
        std::uint32_t fragment;
        std::uint32_t depth; // 4-steps from the dab's node
    };
    struct FragmentMarks {
        std::uint32_t mp = 0, mt = 0; // generation of the search that reached the fragment
    };
    struct PixelSlot {
        std::uint32_t mpGen = 0, mpFragment = 0; // Mp claim, valid when mpGen == m_gen
        std::uint32_t mtGen = 0, mtFragment = 0; // the R_max search's claim
    };
    /** Where one step of a search leads. */
    struct SearchStep {
        Node node;
        std::uint32_t pixel = 0;
        float distance2 = 0.0f; // squared, from the dab's centre to the pixel's centre
    };
    /**
     * One step of the Mp (Mark = &FragmentMarks::mp) or Mt search from n along its link d
     * (nodeLinks: n's four links): false where there is no link or neighbour, the fragment was
     * reached already in this search (else it is marked now) or is hidden, or its pixel centre
     * lies outside radius2 of centre (the search stays inside the disc: no detour outside it).
     */
    template <std::uint32_t FragmentMarks::*Mark>
    bool searchStep(const Node& n, int d, const std::uint8_t* nodeLinks,
                    const std::uint32_t* offsets, glm::vec2 centre, float radius2, SearchStep& out);

    std::size_t placeDab(glm::vec2 center, float pressure, std::vector<Dab>& out);
    /** Tracks dab (its brush state drawn) at center and appends it; returns 0 or 1. */
    std::size_t trackDab(glm::vec2 center, Dab& dab, std::vector<Dab>& out);
    void beginMaps();
    void searchPaintable(std::uint32_t pixel, std::uint32_t fragment, Dab& dab);
    void paintVisible(Dab& dab);
    bool growTrackable();
    std::uint32_t trackedFragment(std::uint32_t pixel);
    std::uint32_t visibleFragment(std::size_t pixel) const;
    std::uint32_t layerOf(std::size_t pixel, std::uint32_t fragment) const {
        return fragment - m_stack->offsets[pixel] + 1;
    }
    float stepFor(float pressure) const;
    /** Draws the dab's jitter and angle; moves center by the scatter. */
    void jitterDab(glm::vec2& center, Dab& dab);

    const DepthStack* m_stack = nullptr;
    const Connectivity* m_connectivity = nullptr;
    VisibleFragmentFn m_visible;
    std::span<const std::uint8_t> m_hidden;
    bool isHidden(std::uint32_t fragment) const {
        return fragment < m_hidden.size() && m_hidden[fragment] != 0;
    }
    bool m_layerAware = true;
    bool m_antiBleeding = true;

    // The stroke and its resampling.
    bool m_inStroke = false;
    Brush m_brush;
    StrokePoint m_last;             // the end of the input path so far
    double m_carry = 0.0;           // path length from the last dab to m_last
    float m_dabPressure = 1.0f;     // pressure at the last dab (sets the spacing)
    std::uint32_t m_startLayer = 0; // the layer the tracking starts on, 0 = the visible one
    // The tip's turn and jitter: a PRNG seeded per stroke, the path's direction (radians) and
    // the last dab's size jitter (the spacing follows the jittered size).
    SplitMix64 m_rng;
    float m_pathAngle = 0.0f;
    float m_sizeFactor = 1.0f;

    // The maps of the last painted dab (generation m_gen).
    bool m_tracking = false;     // the last painted dab was layer-aware: its Mt answers lookups
    std::uint32_t m_gen = 0;     // 0 while no dab of these layers has been painted
    std::uint32_t m_lastGen = 0; // the last generation begun, in any view: no mark is later
    glm::vec2 m_center{0.0f};
    float m_trackRadius2 = 0.0f;
    std::uint32_t m_trackLimit = 0;
    std::vector<FragmentMarks> m_fragments;
    std::vector<PixelSlot> m_pixels;
    std::vector<std::uint32_t> m_mpPixels, m_mtPixels;
    std::vector<Node> m_mpQueue, m_mtQueue;
    std::size_t m_mtHead = 0;
};

} // namespace core
