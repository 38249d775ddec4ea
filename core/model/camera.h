// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/model/mesh.h"

namespace core {

/** The margin around the bounding sphere when the GUI frames a model (a fraction of its radius). */
inline constexpr float kFrameMargin = 0.06f;

/** The matrices and pixel size of one view. Pixel (0,0) is the top-left corner. */
struct View {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    int width = 1;
    int height = 1;

    /** Window pixel (x right, y down, pixel centres at +0.5) to normalized device x, y. */
    glm::vec2 pixelToNdc(glm::vec2 pixel) const;
    /** A world point to window pixel coordinates (y down) and positive view depth. */
    glm::vec3 project(const glm::vec3& world) const;
    /** The world point seen at a pixel at a positive view-space depth. */
    glm::vec3 unproject(glm::vec2 pixel, float viewDepth) const;
    /**
     * Layer-aware rotation of any view: the camera turns about a world pivot by dYaw about the
     * world Y axis and dPitch about its own right axis (positive raises it); the pivot keeps
     * its place on screen exactly.
     */
    View orbitedAbout(const glm::vec3& pivot, float dYawDegrees, float dPitchDegrees) const;
};

/**
 * An orbit camera about a target point: yaw about the world Y axis, pitch above the horizon,
 * distance to the target. yaw = pitch = 0 looks along -Z. Perspective with a 45° vertical field of
 * view, or orthographic with the same framing at the target's distance.
 */
class Camera {
public:
    glm::vec3 target{0.0f};
    float yawDegrees = 0.0f;
    float pitchDegrees = 0.0f;
    float distance = 3.0f;
    float fovYDegrees = 45.0f;
    bool orthographic = false;
    /** Radius of the scene's bounding sphere about its centre, for the clip planes. */
    float sceneRadius = 1.0f;
    glm::vec3 sceneCenter{0.0f};

    glm::vec3 eye() const;
    glm::mat4 viewMatrix() const;
    glm::mat4 projectionMatrix(float aspect) const;
    View view(int width, int height) const;

    /** Rotates about the target; pitch is clamped short of the poles. */
    void orbit(float dYawDegrees, float dPitchDegrees);
    /** Moves the target in the view plane by a pixel delta of a viewport of the given height. */
    void pan(float dxPixels, float dyPixels, int viewportHeight);
    /** Multiplies the distance by factor (> 0), within sane bounds for the scene. */
    void zoom(float factor);
    /**
     * Looks at the bounds' centre from the distance at which their bounding sphere, grown by
     * margin (a fraction of its radius), fits both the vertical and the horizontal field of view
     * of a view aspect = width / height wide, in perspective and orthographic alike. Keeps
     * yaw/pitch.
     */
    void frame(const Bounds& bounds, float aspect = 1.0f, float margin = 0.0f);
    /**
     * Orbits about an arbitrary world pivot: the camera turns about the pivot, which keeps its
     * place on screen.
     */
    void orbitAbout(const glm::vec3& pivot, float dYawDegrees, float dPitchDegrees);

    /**
     * The CLI's "--orbit yaw,pitch,distance": distance in unit-cube units (the bounds' longest
     * side is 1) about the bounds' centre.
     */
    static Camera fromOrbit(const Bounds& bounds, float yawDegrees, float pitchDegrees,
                            float unitCubeDistance);
};

} // namespace core
