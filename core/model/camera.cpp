// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/model/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

namespace core {

namespace {
constexpr float kMaxPitch = 89.0f;

glm::vec3 direction(float yawDegrees, float pitchDegrees) {
    const float yaw = glm::radians(yawDegrees), pitch = glm::radians(pitchDegrees);
    return {std::cos(pitch) * std::sin(yaw), std::sin(pitch), std::cos(pitch) * std::cos(yaw)};
}
} // namespace

glm::vec2 View::pixelToNdc(glm::vec2 pixel) const {
    return {pixel.x / float(width) * 2.0f - 1.0f, 1.0f - pixel.y / float(height) * 2.0f};
}

glm::vec3 View::project(const glm::vec3& world) const {
    const glm::vec4 v = view * glm::vec4(world, 1.0f);
    const glm::vec4 clip = proj * v;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x + 1.0f) * 0.5f * float(width), (1.0f - ndc.y) * 0.5f * float(height), -v.z};
}

glm::vec3 View::unproject(glm::vec2 pixel, float viewDepth) const {
    const glm::vec2 ndc = pixelToNdc(pixel);
    const glm::mat4 invProj = glm::inverse(proj);
    // The view-space ray through the pixel: points at NDC z = -1 and z = 1.
    glm::vec4 a = invProj * glm::vec4(ndc, -1.0f, 1.0f);
    glm::vec4 b = invProj * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 pa = glm::vec3(a) / a.w, pb = glm::vec3(b) / b.w;
    const float t = (-viewDepth - pa.z) / (pb.z - pa.z);
    const glm::vec3 viewPoint = pa + (pb - pa) * t;
    return glm::vec3(glm::inverse(view) * glm::vec4(viewPoint, 1.0f));
}

glm::vec3 Camera::eye() const {
    return target + direction(yawDegrees, pitchDegrees) * distance;
}

glm::mat4 Camera::viewMatrix() const {
    return glm::lookAt(eye(), target, glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 Camera::projectionMatrix(float aspect) const {
    // Clip planes hug the scene's bounding sphere so depth precision is spent on the model.
    const float centerDistance = glm::length(sceneCenter - eye());
    const float farPlane = centerDistance + sceneRadius * 1.05f;
    const float nearPlane = std::max(centerDistance - sceneRadius * 1.05f, farPlane * 1e-4f);
    if (orthographic) {
        const float halfHeight = distance * std::tan(glm::radians(fovYDegrees) * 0.5f);
        const float halfWidth = halfHeight * aspect;
        return glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight,
                          std::max(centerDistance - sceneRadius * 1.05f, -farPlane), farPlane);
    }
    return glm::perspective(glm::radians(fovYDegrees), aspect, nearPlane, farPlane);
}

View Camera::view(int width, int height) const {
    View v;
    v.width = std::max(width, 1);
    v.height = std::max(height, 1);
    v.view = viewMatrix();
    v.proj = projectionMatrix(float(v.width) / float(v.height));
    return v;
}

void Camera::orbit(float dYawDegrees, float dPitchDegrees) {
    yawDegrees = std::fmod(yawDegrees + dYawDegrees, 360.0f);
    pitchDegrees = std::clamp(pitchDegrees + dPitchDegrees, -kMaxPitch, kMaxPitch);
}

void Camera::pan(float dxPixels, float dyPixels, int viewportHeight) {
    const float worldPerPixel = 2.0f * distance * std::tan(glm::radians(fovYDegrees) * 0.5f) /
                                float(std::max(viewportHeight, 1));
    const glm::mat4 v = viewMatrix();
    const glm::vec3 right(v[0][0], v[1][0], v[2][0]);
    const glm::vec3 up(v[0][1], v[1][1], v[2][1]);
    target += (-dxPixels * right + dyPixels * up) * worldPerPixel;
}

void Camera::zoom(float factor) {
    if (!(factor > 0.0f))
        return;
    distance = std::clamp(distance * factor, sceneRadius * 1e-3f, sceneRadius * 1e3f);
}

void Camera::frame(const Bounds& bounds, float aspect, float margin) {
    sceneCenter = bounds.center();
    sceneRadius = std::max(glm::length(bounds.size()) * 0.5f, 1e-6f);
    target = sceneCenter;
    if (!(aspect > 0.0f) || !std::isfinite(aspect))
        aspect = 1.0f;
    if (!(margin >= 0.0f) || !std::isfinite(margin))
        margin = 0.0f;
    // The narrower of the two half-angles decides: a sphere seen at distance d fills a half-angle
    // of asin(r / d). Orthographic shows d * tan(half-angle) on each side, which is more than r.
    const float tanHalfY = std::tan(glm::radians(fovYDegrees) * 0.5f);
    const float halfAngle = std::atan(tanHalfY * std::min(aspect, 1.0f));
    distance = sceneRadius * (1.0f + margin) / std::sin(halfAngle);
}

View View::orbitedAbout(const glm::vec3& pivot, float dYawDegrees, float dPitchDegrees) const {
    const glm::mat4 identity(1.0f);
    const glm::vec3 right = glm::normalize(glm::vec3(glm::inverse(view)[0]));
    // The camera-to-world transform turns about the pivot; the view is its inverse.
    const glm::mat4 turn = glm::translate(identity, pivot) *
                           glm::rotate(identity, glm::radians(dYawDegrees), {0.0f, 1.0f, 0.0f}) *
                           glm::rotate(identity, glm::radians(-dPitchDegrees), right) *
                           glm::translate(identity, -pivot);
    View turned = *this;
    turned.view = view * glm::inverse(turn);
    return turned;
}

void Camera::orbitAbout(const glm::vec3& pivot, float dYawDegrees, float dPitchDegrees) {
    const float oldYaw = yawDegrees, oldPitch = pitchDegrees;
    orbit(dYawDegrees, dPitchDegrees);
    // Rotate the eye and target about the pivot by the same rotation the view direction made,
    // so the pivot stays fixed in camera space (and therefore on screen).
    const glm::quat before = glm::quatLookAt(-direction(oldYaw, oldPitch), glm::vec3(0, 1, 0));
    const glm::quat after =
        glm::quatLookAt(-direction(yawDegrees, pitchDegrees), glm::vec3(0, 1, 0));
    const glm::quat delta = after * glm::inverse(before);
    target = pivot + delta * (target - pivot);
}

Camera Camera::fromOrbit(const Bounds& bounds, float yaw, float pitch, float unitCubeDistance) {
    Camera c;
    c.frame(bounds);
    c.yawDegrees = yaw;
    c.pitchDegrees = std::clamp(pitch, -kMaxPitch, kMaxPitch);
    c.distance = unitCubeDistance * std::max(bounds.longestSide(), 1e-6f);
    return c;
}

} // namespace core
