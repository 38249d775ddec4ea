// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/paint/brush/symmetry.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace core {

std::string symmetryMirrorName(const BrushSymmetry& symmetry) {
    std::string name;
    if (symmetry.mirrorX)
        name += 'x';
    if (symmetry.mirrorY)
        name += 'y';
    if (symmetry.mirrorZ)
        name += 'z';
    return name;
}

bool symmetryMirrorFromName(std::string_view name, BrushSymmetry& symmetry) {
    bool on[3] = {false, false, false};
    for (const char c : name) {
        const int i = c == 'x' ? 0 : c == 'y' ? 1 : c == 'z' ? 2 : -1;
        if (i < 0 || on[i])
            return false;
        on[i] = true;
    }
    symmetry.mirrorX = on[0];
    symmetry.mirrorY = on[1];
    symmetry.mirrorZ = on[2];
    return true;
}

const char* symmetryCenterName(BrushSymmetry::Center center) {
    return center == BrushSymmetry::Center::Origin ? "origin" : "bbox";
}

bool symmetryCenterFromName(std::string_view name, BrushSymmetry::Center& center) {
    if (name == "bbox")
        center = BrushSymmetry::Center::BoundingBox;
    else if (name == "origin")
        center = BrushSymmetry::Center::Origin;
    else
        return false;
    return true;
}

const char* symmetryAxisName(int axis) {
    return axis == 0 ? "x" : axis == 2 ? "z" : "y";
}

bool symmetryAxisFromName(std::string_view name, int& axis) {
    if (name.size() != 1 || name[0] < 'x' || name[0] > 'z')
        return false;
    axis = name[0] - 'x';
    return true;
}

std::vector<glm::mat4> symmetryTransforms(const BrushSymmetry& symmetry, const glm::vec3& centre) {
    std::vector<glm::mat4> out;
    const int radial = std::clamp(symmetry.radial, 1, BrushSymmetry::kMaxRadial);
    glm::vec3 axis(0.0f);
    axis[std::clamp(symmetry.axis, 0, 2)] = 1.0f;
    const bool mirrors[3] = {symmetry.mirrorX, symmetry.mirrorY, symmetry.mirrorZ};
    const glm::mat4 toCentre = glm::translate(glm::mat4(1.0f), centre);
    const glm::mat4 fromCentre = glm::translate(glm::mat4(1.0f), -centre);
    for (int subset = 0; subset < 8; ++subset) {
        glm::vec3 scale(1.0f);
        bool usable = true;
        for (int i = 0; i < 3; ++i) {
            if (subset & (1 << i)) {
                usable = usable && mirrors[i];
                scale[i] = -1.0f;
            }
        }
        if (!usable)
            continue;
        for (int k = 0; k < radial; ++k) {
            if (subset == 0 && k == 0)
                continue; // the stroke itself
            const float angle = 6.28318530718f * float(k) / float(radial);
            const glm::mat4 turn = glm::rotate(glm::mat4(1.0f), angle, axis);
            out.push_back(toCentre * turn * glm::scale(glm::mat4(1.0f), scale) * fromCentre);
        }
    }
    return out;
}

bool symmetryReflects(const glm::mat4& transform) {
    return glm::determinant(glm::mat3(transform)) < 0.0f;
}

View symmetricView(const View& view, const glm::mat4& transform) {
    View out = view;
    // transform(p) seen through view × inverse(transform) lands where p does in view.
    out.view = view.view * glm::inverse(transform);
    if (symmetryReflects(transform)) {
        glm::mat4 flip(1.0f);
        flip[0][0] = -1.0f; // NDC x
        out.proj = flip * view.proj;
    }
    return out;
}

} // namespace core
