// SPDX-License-Identifier: GPL-3.0-or-later
// Projection painting on layers of a real capture (headless EGL, llvmpipe on CI): where a stroke
// meets the outline of the surface, and painting a piece hidden under another strand.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "tests/render/gl_test.h"

#include "core/builtin_models.h"
#include "core/camera.h"
#include "core/document.h"
#include "core/layers.h"
#include "core/paint_target.h"
#include "render/gl_layer_capturer.h"

namespace {

using core::kNone;

class PaintProjectionGlTest : public render_test::GlTest {
protected:
    void SetUp() override {
        ASSERT_TRUE(s_context);
        const core::Status status = m_capturer.initialize();
        ASSERT_TRUE(status) << status.error();
        s_trefoil = s_trefoil ? s_trefoil : std::make_shared<core::Mesh>(core::makeTrefoil());
    }
    void TearDown() override { m_capturer.layerCapture().release(); }

    /** The trefoil, as the headless tool shows it by default, its layers built at size × scale. */
    std::unique_ptr<core::Document> open(int width, int height, int scale) {
        auto doc = std::make_unique<core::Document>();
        doc->setMesh(*s_trefoil, "trefoil");
        core::Camera camera;
        camera.frame(s_trefoil->bounds());
        camera.orbit(30.0f, 20.0f);
        doc->camera() = camera;
        m_capturer.setMesh(doc->mesh());
        const core::Status status =
            doc->buildLayers(m_capturer, camera.view(width * scale, height * scale));
        EXPECT_TRUE(status) << status.error();
        return doc;
    }

    /** Per texel of page 0: whether the brush colour (pure red) is there. */
    static std::vector<std::uint8_t> redTexels(core::Document& doc) {
        const auto* target = dynamic_cast<const core::TextureTarget*>(doc.paintTarget());
        std::vector<std::uint8_t> red;
        if (!target)
            return red;
        const core::Image& page = target->page(0);
        red.resize(std::size_t(page.width) * std::size_t(page.height));
        for (std::size_t i = 0; i < red.size(); ++i)
            red[i] = page.rgba[4 * i] > 200 && page.rgba[4 * i + 1] < 60 ? 1 : 0;
        return red;
    }

    render::GlLayerCapturer m_capturer;
    inline static std::shared_ptr<core::Mesh> s_trefoil;
};

/** Pixels of a layer stack with exactly one fragment (the surface seen alone). */
bool single(const core::LayerStack& stack, int x, int y) {
    if (x < 0 || y < 0 || x >= stack.width || y >= stack.height)
        return false;
    const std::size_t i = std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
    return stack.offsets[i + 1] - stack.offsets[i] == 1;
}
bool empty(const core::LayerStack& stack, int x, int y) {
    if (x < 0 || y < 0 || x >= stack.width || y >= stack.height)
        return true;
    const std::size_t i = std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
    return stack.offsets[i + 1] == stack.offsets[i];
}

/**
 * A stretch of tube seen alone: a pixel whose horizontal run of single-layer pixels is
 * narrower than 2 × radius - 8 (so a dab there covers the tube from outline to outline), with
 * nothing but background or that tube within radius + 4. nullopt if the view has none.
 */
std::optional<glm::ivec2> crossableTube(const core::LayerStack& stack, int radius) {
    for (int y = radius + 4; y < stack.height - radius - 4; y += 3) {
        for (int left = radius + 4; left < stack.width - radius - 4; ++left) {
            if (!single(stack, left, y) || !empty(stack, left - 1, y))
                continue;
            int right = left;
            while (single(stack, right + 1, y))
                ++right;
            const int width = right - left + 1;
            const int x = (left + right) / 2;
            if (!empty(stack, right + 1, y) || width > 2 * radius - 8 || width < radius / 2) {
                left = right;
                continue;
            }
            bool alone = true;
            for (int dy = -radius - 4; alone && dy <= radius + 4; ++dy)
                for (int dx = -radius - 4; alone && dx <= radius + 4; ++dx)
                    alone = empty(stack, x + dx, y + dy) || single(stack, x + dx, y + dy);
            // The tube runs up and down here: the pixels above and below are on it too.
            if (alone && single(stack, x, y - 8) && single(stack, x, y + 8))
                return glm::ivec2(x, y);
            left = right;
        }
    }
    return std::nullopt;
}

TEST_F(PaintProjectionGlTest, StrokeEdgeAtTheOutlineFollowsTheSurfaceNotThePixels) {
    // A hard stroke across the tube, wider than it, so it ends at the tube's outline on both
    // sides; painted at 640x480 and, as the reference, at 4 × 4 the pixels (the outline then
    // falls on quarter pixels). Without anti-aliasing at the outline the 1× paint ends in a
    // saw-tooth of whole pixels, which on a surface seen this steeply spans many texels.
    constexpr int kWidth = 640, kHeight = 480, kRadius = 30, kScale = 4;
    const auto paint = [&](int scale) {
        auto doc = open(kWidth, kHeight, scale);
        const auto at = crossableTube(open(kWidth, kHeight, 1)->layers()->stack, kRadius);
        EXPECT_TRUE(at.has_value());
        doc->setLayerAware(false);
        core::Brush& brush = doc->brush();
        brush.color = {1.0f, 0.0f, 0.0f, 1.0f};
        brush.radius = float(kRadius * scale);
        brush.hardness = 1.0f;
        brush.opacity = 1.0f;
        brush.pressureRadius = false;
        core::PaintChanges changes;
        const glm::vec2 centre = (glm::vec2(at.value_or(glm::ivec2(0))) + 0.5f) * float(scale);
        EXPECT_TRUE(doc->beginStroke({centre - glm::vec2(0, 6 * scale), 1.0f}, changes));
        doc->moveStroke({centre + glm::vec2(0, 6 * scale), 1.0f}, changes);
        doc->endStroke();
        return redTexels(*doc);
    };
    const std::vector<std::uint8_t> painted = paint(1);
    const std::vector<std::uint8_t> reference = paint(kScale);
    ASSERT_EQ(painted.size(), reference.size());
    std::size_t referenceCount = 0, missing = 0, extra = 0;
    for (std::size_t i = 0; i < painted.size(); ++i) {
        referenceCount += reference[i];
        missing += reference[i] && !painted[i];
        extra += painted[i] && !reference[i];
    }
    std::printf("[ outline ] reference %zu texels; at 1x %zu missing, %zu extra\n", referenceCount,
                missing, extra);
    ASSERT_GT(referenceCount, 2000u);
    // The paint ends where the surface and the circle end, at any pixel size: the two agree
    // but for rounding (before, 3.3 % of the texels were missing at 1×, in saw-teeth along the
    // outline and around the circle).
    EXPECT_LT(double(missing), 0.005 * double(referenceCount));
    EXPECT_LT(double(extra), 0.005 * double(referenceCount));
}

} // namespace
