// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "core/model/camera.h"

namespace camera_test {

core::Bounds unitBox() {
    return {glm::vec3(-0.5f), glm::vec3(0.5f)};
}

TEST(Camera, ProjectAndUnprojectRoundTrip) {
    core::Camera camera;
    camera.frame(unitBox());
    camera.orbit(30.0f, 20.0f);
    const core::View view = camera.view(640, 480);
    const glm::vec3 world(0.2f, -0.1f, 0.3f);
    const glm::vec3 pixel = view.project(world);
    const glm::vec3 back = view.unproject({pixel.x, pixel.y}, pixel.z);
    EXPECT_NEAR(glm::distance(world, back), 0.0f, 1e-4f);
}

TEST(Camera, DefaultViewLooksDownMinusZWithYUp) {
    core::Camera camera;
    camera.frame(unitBox());
    const core::View view = camera.view(200, 100);
    const glm::vec3 center = view.project({0, 0, 0});
    EXPECT_NEAR(center.x, 100.0f, 1e-3f);
    EXPECT_NEAR(center.y, 50.0f, 1e-3f);
    // +Y is up on screen (smaller pixel y); the nearer point along +Z has a smaller depth.
    EXPECT_LT(view.project({0, 0.3f, 0}).y, center.y);
    EXPECT_LT(view.project({0, 0, 0.3f}).z, center.z);
}

TEST(Camera, FrameFitsTheBoundsInsideTheView) {
    core::Camera camera;
    const core::Bounds box{glm::vec3(10, 20, 30), glm::vec3(14, 21, 31)};
    camera.frame(box);
    camera.orbit(45.0f, 30.0f);
    const core::View view = camera.view(800, 600);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                               (i & 4) ? box.max.z : box.min.z);
        const glm::vec3 p = view.project(corner);
        EXPECT_GE(p.x, 0.0f);
        EXPECT_LE(p.x, 800.0f);
        EXPECT_GE(p.y, 0.0f);
        EXPECT_LE(p.y, 600.0f);
        EXPECT_GT(p.z, 0.0f);
    }
}

TEST(Camera, FrameFitsWideAndTallViewsWithAMargin) {
    const core::Bounds box{glm::vec3(-3, -0.5f, -1), glm::vec3(5, 1, 0.5f)};
    const glm::vec2 sizes[] = {{1600, 400}, {300, 1000}, {500, 500}};
    for (const glm::vec2 size : sizes) {
        for (const bool orthographic : {false, true}) {
            core::Camera camera;
            camera.orthographic = orthographic;
            camera.frame(box, size.x / size.y, 0.1f);
            for (const glm::vec2 turn : {glm::vec2(0, 0), glm::vec2(90, 0), glm::vec2(35, 60)}) {
                core::Camera turned = camera;
                turned.orbit(turn.x, turn.y);
                const core::View view = turned.view(int(size.x), int(size.y));
                // The sphere with its margin is in view, so the corners are well inside.
                const float margin = 0.02f * std::min(size.x, size.y);
                for (int i = 0; i < 8; ++i) {
                    const glm::vec3 corner((i & 1) ? box.max.x : box.min.x,
                                           (i & 2) ? box.max.y : box.min.y,
                                           (i & 4) ? box.max.z : box.min.z);
                    const glm::vec3 p = view.project(corner);
                    EXPECT_GT(p.x, margin) << size.x << "x" << size.y << " " << orthographic;
                    EXPECT_LT(p.x, size.x - margin) << size.x << "x" << size.y;
                    EXPECT_GT(p.y, margin) << size.x << "x" << size.y;
                    EXPECT_LT(p.y, size.y - margin) << size.x << "x" << size.y;
                }
            }
        }
    }
    // Not needlessly far: in a square view the sphere with its margin just fits.
    core::Camera camera;
    camera.frame(box, 1.0f, 0.1f);
    const float radius = glm::length(box.size()) * 0.5f;
    EXPECT_NEAR(camera.distance * std::sin(glm::radians(22.5f)), radius * 1.1f, 1e-3f * radius);
    // Bad input keeps a usable camera.
    camera.frame(box, std::nanf(""), -1.0f);
    EXPECT_TRUE(std::isfinite(camera.distance));
    EXPECT_GT(camera.distance, radius);
}

TEST(Camera, OrbitAboutKeepsThePivotOnScreen) {
    core::Camera camera;
    camera.frame(unitBox());
    const glm::vec3 pivot(0.4f, -0.3f, 0.2f);
    const glm::vec3 before = camera.view(640, 480).project(pivot);
    camera.orbitAbout(pivot, 35.0f, -20.0f);
    const glm::vec3 after = camera.view(640, 480).project(pivot);
    EXPECT_NEAR(before.x, after.x, 1e-2f);
    EXPECT_NEAR(before.y, after.y, 1e-2f);
    EXPECT_NEAR(before.z, after.z, 1e-3f);
    EXPECT_NEAR(camera.yawDegrees, 35.0f, 1e-4f);
}

TEST(Camera, ViewOrbitedAboutAPivotKeepsItOnScreenAndMovesTheEye) {
    core::Camera camera;
    camera.frame(unitBox());
    camera.orbit(20.0f, 10.0f);
    const core::View view = camera.view(640, 480);
    const glm::vec3 pivot(0.3f, 0.1f, -0.2f);
    const core::View turned = view.orbitedAbout(pivot, 40.0f, 15.0f);
    const glm::vec3 before = view.project(pivot), after = turned.project(pivot);
    EXPECT_NEAR(before.x, after.x, 1e-3f);
    EXPECT_NEAR(before.y, after.y, 1e-3f);
    EXPECT_NEAR(before.z, after.z, 1e-4f);
    // The eye keeps its distance to the pivot and goes up for a positive pitch.
    const glm::vec3 eye = glm::vec3(glm::inverse(view.view)[3]);
    const glm::vec3 turnedEye = glm::vec3(glm::inverse(turned.view)[3]);
    EXPECT_NEAR(glm::distance(eye, pivot), glm::distance(turnedEye, pivot), 1e-4f);
    EXPECT_GT(glm::distance(eye, turnedEye), 0.5f);
    EXPECT_GT(turnedEye.y, eye.y);
    // The centre of the box moved on screen: the view did turn.
    EXPECT_GT(
        glm::distance(glm::vec2(view.project({0, 0, 0})), glm::vec2(turned.project({0, 0, 0}))),
        5.0f);
}

TEST(Camera, FromOrbitUsesUnitCubeDistance) {
    const core::Bounds box{glm::vec3(0), glm::vec3(4, 2, 1)}; // longest side 4
    const core::Camera camera = core::Camera::fromOrbit(box, 90.0f, 0.0f, 2.0f);
    EXPECT_NEAR(glm::distance(camera.eye(), box.center()), 8.0f, 1e-4f);
    // yaw 90° puts the eye on +X of the centre.
    EXPECT_GT(camera.eye().x, box.center().x + 7.9f);
}

TEST(Camera, PitchIsClampedShortOfThePoles) {
    core::Camera camera;
    camera.orbit(0.0f, 500.0f);
    EXPECT_LT(camera.pitchDegrees, 90.0f);
    const glm::mat4 m = camera.viewMatrix();
    EXPECT_FALSE(std::isnan(m[0][0]));
}

} // namespace camera_test
