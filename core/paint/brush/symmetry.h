// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/model/camera.h"

namespace core {

/**
 * Symmetric painting: every dab of a stroke is repeated mirrored across the model's X, Y and/or Z
 * planes and turned into radial copies about an axis, through the bounding-box centre or the
 * origin. All off: an ordinary stroke.
 */
struct BrushSymmetry {
    enum class Center : std::uint8_t { BoundingBox, Origin };
    static constexpr int kMaxRadial = 16;

    bool mirrorX = false, mirrorY = false, mirrorZ = false;
    Center center = Center::BoundingBox;
    int radial = 1; // copies about axis, the stroke included; 1 = none
    int axis = 1;   // 0 x, 1 y, 2 z

    bool active() const { return mirrorX || mirrorY || mirrorZ || radial > 1; }
    friend bool operator==(const BrushSymmetry&, const BrushSymmetry&) = default;
};

/** "x", "xy", "xyz", ... for the mirrors on, "" for none. */
std::string symmetryMirrorName(const BrushSymmetry& symmetry);
/** Sets the mirrors from such a name (letters x, y, z, each at most once); false otherwise. */
bool symmetryMirrorFromName(std::string_view name, BrushSymmetry& symmetry);
const char* symmetryCenterName(BrushSymmetry::Center center); // "bbox", "origin"
bool symmetryCenterFromName(std::string_view name, BrushSymmetry::Center& center);
const char* symmetryAxisName(int axis); // "x", "y", "z"
bool symmetryAxisFromName(std::string_view name, int& axis);

/**
 * The world transforms of the copies (the identity, the stroke itself, left out): each subset of
 * the mirrors times each radial turn, about centre. Radial counts are clamped to 1..kMaxRadial.
 */
std::vector<glm::mat4> symmetryTransforms(const BrushSymmetry& symmetry, const glm::vec3& centre);

/**
 * The view in which the copy of the surface under a pixel of view appears at a pixel that mirrors
 * it: a world point p at window position (x, y) in view puts transform(p) at (x, y) in the result,
 * or at (width - x, y) when transform reflects (the image is flipped back so that front faces stay
 * front faces). A stroke painted through this view paints the copy of what it paints in view.
 */
View symmetricView(const View& view, const glm::mat4& transform);
/** Whether transform reflects (its symmetricView() flips the image left to right). */
bool symmetryReflects(const glm::mat4& transform);

} // namespace core
