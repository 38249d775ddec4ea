// SPDX-License-Identifier: GPL-3.0-or-later
// The compositor's render tests' fixture: a mesh's depth layers built through the GL capture and
// uploaded to a compositor, the composite drawn beside a plain render of the same view, and the
// comparison of the two. Set LAYERPAINT_TEST_IMAGES=DIR to write the pictures as PNGs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/render/gl_test.h"

#include "core/depth/depth_layers.h"
#include "core/io/image/image_write.h"
#include "render/depth_compositor.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"

namespace render_test {

class DepthCompositorGlTest : public GlCaptureTest {
protected:
    void SetUp() override {
        ASSERT_NO_FATAL_FAILURE(GlCaptureTest::SetUp());
        core::Status status = m_compositor.initialize();
        ASSERT_TRUE(status) << status.error();
        status = m_renderer.initialize();
        ASSERT_TRUE(status) << status.error();
    }
    void TearDown() override {
        m_compositor.release();
        m_renderer.release();
        GlCaptureTest::TearDown();
    }

    /** build_layers through the GL capture, then uploads mesh and layers to the compositor. */
    core::DepthLayers build(const core::Mesh& mesh, const core::View& view) {
        core::DepthLayers layers = captureDepthLayers(mesh, view);
        if (layers.stack.width == 0)
            return layers;
        core::Status status = m_compositor.setMesh(mesh);
        EXPECT_TRUE(status) << status.error();
        status = m_compositor.setDepthLayers(layers);
        EXPECT_TRUE(status) << status.error();
        m_renderer.setMesh(mesh);
        return layers;
    }

    core::Image composite(const core::DepthLayers& layers,
                          const render::CompositeOptions& options) {
        return drawComposite(m_compositor, layers.stack.width, layers.stack.height, options);
    }

    core::Image plain(const core::View& view, const glm::vec4& background,
                      render::MaterialChannel channel = render::MaterialChannel::Material) {
        render::OffscreenTarget target;
        EXPECT_TRUE(target.create(view.width, view.height));
        target.bind();
        render::DrawOptions options;
        options.background = background;
        options.channel = channel;
        m_renderer.draw(view, options);
        return target.readColor();
    }

    render::DepthCompositor m_compositor;
    render::MeshRenderer m_renderer;
};

inline void saveImage(const core::Image& image, const std::string& name) {
    const char* dir = std::getenv("LAYERPAINT_TEST_IMAGES");
    if (!dir || !*dir)
        return;
    std::filesystem::create_directories(dir);
    const std::string path = std::string(dir) + "/" + name + ".png";
    const core::Status status = core::writeImage(path, image.width, image.height, 4,
                                                 core::PixelType::UInt8, image.rgba.data());
    EXPECT_TRUE(status) << status.error();
}

inline int channelDifference(const core::Image& a, const core::Image& b, std::size_t pixel) {
    int difference = 0;
    for (int c = 0; c < 3; ++c)
        difference =
            std::max(difference, std::abs(int(a.rgba[pixel * 4 + c]) - int(b.rgba[pixel * 4 + c])));
    return difference;
}

/** Counts pixels differing by more than tolerance, among pixels where either image has content. */
struct Comparison {
    std::size_t covered = 0;
    std::size_t differing = 0;
    double meanDifference = 0.0;
};
inline Comparison compare(const core::Image& a, const core::Image& b, const core::DepthStack& stack,
                          int tolerance) {
    Comparison result;
    double sum = 0.0;
    for (std::size_t p = 0; p < stack.pixelCount(); ++p) {
        const int difference = channelDifference(a, b, p);
        if (stack.layerCount(p) == 0 && difference == 0)
            continue;
        ++result.covered;
        sum += difference;
        result.differing += difference > tolerance;
    }
    result.meanDifference = result.covered ? sum / double(result.covered) : 0.0;
    return result;
}

inline void expectMatchesPlainRender(const core::Image& composited, const core::Image& rendered,
                                     const core::DepthStack& stack) {
    const Comparison c = compare(composited, rendered, stack, 6);
    ::testing::Test::RecordProperty("differing_pixels", std::to_string(c.differing) + " of " +
                                                            std::to_string(c.covered));
    ::testing::Test::RecordProperty("mean_difference", std::to_string(c.meanDifference));
    EXPECT_GT(c.covered, stack.pixelCount() / 10);
    // Only edge pixels may differ: where capture (back faces culled) and the plain render
    // (two-sided) disagree about the front-most triangle at a silhouette.
    EXPECT_LT(double(c.differing), 0.01 * double(c.covered))
        << c.differing << " of " << c.covered << " pixels differ";
    EXPECT_LT(c.meanDifference, 1.0);
}

} // namespace render_test
