// SPDX-License-Identifier: GPL-3.0-or-later
// core/paint/brush/: what a brush is: its settings and dabs, tips, previews, symmetry.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/paint/brush/brush_tips.h"
#include "core/paint/brush/symmetry.h"

namespace core {

/** One pixel of a paintable map Mp: the fragment (of the view's DepthStack) painted there. */
struct MapPixel {
    std::uint32_t pixel = 0;    // y * width + x
    std::uint32_t fragment = 0; // index into DepthStack arrays; its layer is the Mp layer
    float distance = 0.0f;      // screen distance from the dab centre to the pixel centre, px
};

/**
 * One brush footprint ready to paint (the paper's paint_object(object, Mp)): the paintable map of
 * a dab centre reached by the stroke tracking, and the brush state at that point.
 */
struct Dab {
    glm::vec2 center{0.0f};  // pixels, y down
    float radius = 0.0f;     // screen radius R in pixels (after pressure)
    float opacity = 1.0f;    // after pressure
    float angle = 0.0f;      // the tip's turn, radians, clockwise on screen
    std::uint32_t layer = 0; // 1-based layer of the centre's fragment
    std::vector<MapPixel> paintable;
};

/** Brush settings an artist sets (docs/architecture.md §3 step 6). Colours are linear RGBA. */
struct Brush {
    glm::vec4 color{0.8f, 0.1f, 0.1f, 1.0f};
    float radius = 32.0f;  // pixels
    float hardness = 0.5f; // 0 soft (falloff from the centre) .. 1 hard edge
    float opacity = 1.0f;  // the most a stroke can reach
    float flow = 1.0f;     // how much one dab adds towards it
    float spacing = 0.15f; // dab distance as a fraction of the radius
    // The tip (brush_tips.h): a built-in name, or kUserTip for userTip; its turn and the jitter
    // per dab, drawn from seed (mixed with the stroke's first point, so strokes differ but a
    // replayed script repeats them exactly).
    std::string tip{kRoundTip};
    TipAngleMode angleMode = TipAngleMode::Fixed;
    float angle = 0.0f; // degrees, clockwise on screen
    BrushJitter jitter;
    std::uint32_t seed = 0;
    std::shared_ptr<const TipImage> userTip; // a loaded image (kUserTip), shared between copies
    std::string userTipName;                 // its file name, for display
    bool eraser = false;                     // restores the original surface colour
    bool pressureRadius = true;
    bool pressureOpacity = false;
    float trackRadius = 0.0f; // R_max in pixels; 0 = max(4R, 64)
    // The material channels a stroke paints into a paint layer and their values (0..1);
    // the base colour is color. Vertex colours and the base have the base colour only.
    bool paintBaseColor = true;
    bool paintRoughness = false;
    bool paintMetallic = false;
    float roughness = 0.5f;
    float metallic = 0.0f;
    // The stroke stabilizer (core/paint/tracking/stroke_stabilizer.h): a lazy-mouse string of
    // stabilizerLength pixels, the input averaged by stabilizerSmoothing (0 none .. 1 most)
    // first; with stabilizerCatchUp the stroke reaches the release point.
    bool stabilizer = false;
    float stabilizerLength = 30.0f;
    float stabilizerSmoothing = 0.0f;
    bool stabilizerCatchUp = true;
    // Mirror and radial copies of every dab (core/paint/brush/symmetry.h).
    BrushSymmetry symmetry;

    friend bool operator==(const Brush&, const Brush&) = default;

    float effectiveTrackRadius() const {
        return trackRadius > 0.0f ? trackRadius : (4.0f * radius > 64.0f ? 4.0f * radius : 64.0f);
    }
    /** Falloff weight in [0, 1] at distance d (pixels) from a dab of radius r. */
    float falloff(float d, float r) const;
    /** The hardness of the round falloff the tip uses (round-soft 0, round-hard 1). */
    float tipHardness() const;
    /** The tip's image; nullptr for a round tip (or kUserTip with none loaded). */
    const TipImage* tipImage() const;
    /** Takes built-in tip name with its spacing, turn and jitter (tipCharacter()). */
    void chooseTip(std::string_view name);
};

/**
 * How pen pressure maps to the pressure a stroke uses (StrokePoint::pressure): p^gamma. Below 1 a
 * light touch already gives much, above 1 it takes a firm press; 1 is the identity, so a mouse
 * (pressure 1) is unaffected by any curve. Out-of-range gamma is clamped, pressure to 0..1.
 */
struct PressureCurve {
    static constexpr float kMinGamma = 0.2f;
    static constexpr float kMaxGamma = 5.0f;
    float gamma = 1.0f;

    float apply(float pressure) const;
};

} // namespace core
