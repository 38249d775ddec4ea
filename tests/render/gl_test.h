// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include <gtest/gtest.h>

#include "core/depth/depth_layers.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"
#include "render/depth_compositor.h"
#include "render/gl_context.h"
#include "render/gl_depth_capturer.h"
#include "render/offscreen_target.h"

namespace render_test {

/** Base of the *_gltest fixtures: one headless EGL context (llvmpipe on CI) per test suite. */
class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        auto context = render::HeadlessContext::create();
        ASSERT_TRUE(context) << context.error();
        s_context = std::move(context).value();
    }
    static void TearDownTestSuite() { s_context.reset(); }

    inline static std::unique_ptr<render::HeadlessContext> s_context;
};

/** A GlTest that captures depth layers on the GPU: m_capturer is ready in each test. */
class GlCaptureTest : public GlTest {
protected:
    void SetUp() override {
        ASSERT_TRUE(s_context);
        const core::Status status = m_capturer.initialize();
        ASSERT_TRUE(status) << status.error();
    }
    void TearDown() override { m_capturer.depthCapture().release(); }

    /** build_layers of mesh in view through the GL capture; empty (and a failure) on error. */
    core::DepthLayers captureDepthLayers(const core::Mesh& mesh, const core::View& view) {
        m_capturer.setMesh(mesh);
        auto layers =
            core::buildDepthLayers(m_capturer, mesh, core::buildMeshTopology(mesh), view, {});
        EXPECT_TRUE(layers) << layers.error();
        return layers ? std::move(layers).value() : core::DepthLayers{};
    }

    render::GlDepthCapturer m_capturer;
};

/** What compositor draws with options into a fresh width × height target, read back. */
inline core::Image drawComposite(render::DepthCompositor& compositor, int width, int height,
                                 const render::CompositeOptions& options) {
    render::OffscreenTarget target;
    EXPECT_TRUE(target.create(width, height));
    target.bind();
    compositor.draw(options);
    return target.readColor();
}

/** The mesh framed, orbited by yaw and pitch; zoom < 1 moves closer than framed. */
inline core::View orbitView(const core::Mesh& mesh, float yaw, float pitch, int width, int height,
                            float zoom = 1.0f) {
    core::Camera camera;
    camera.frame(mesh.bounds());
    camera.orbit(yaw, pitch);
    camera.zoom(zoom);
    return camera.view(width, height);
}

} // namespace render_test
