// SPDX-License-Identifier: GPL-3.0-or-later
// A mesh renderer's frame drawn in slices (render::SlicedFrame, headless EGL, llvmpipe on CI):
// the slices give draw()'s pixels, and any change to what the frame shows starts it again.
#include <algorithm>
#include <cstdint>

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "tests/render/gl_test.h"

#include "core/model/builtin_models.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_target.h"
#include "render/sliced_frame.h"

namespace sliced_frame_gltest {

using render_test::GlTest;
using render_test::orbitView;

/**
 * The trefoil in runs of 700 triangles alternating between an opaque textured material and a
 * half-transparent blending one, so slices cut runs, and cross from the opaque triangles into
 * the blended ones drawn after them.
 */
core::Mesh runsOfTwoMaterials() {
    core::Mesh mesh = core::makeTrefoil();
    mesh.materials.resize(2);
    mesh.materials[0].baseColorFactor = glm::vec4(0.9f, 0.5f, 0.2f, 1.0f);
    mesh.materials[0].baseColorTexture = 0;
    mesh.materials[1].baseColorFactor = glm::vec4(0.2f, 0.4f, 0.9f, 0.5f);
    mesh.materials[1].alphaMode = core::AlphaMode::Blend;
    core::Image texture{16, 16, {}};
    for (int i = 0; i < 16 * 16; ++i)
        texture.rgba.insert(texture.rgba.end(), {std::uint8_t(i), std::uint8_t(255 - i), 90, 255});
    mesh.textures = {texture};
    for (std::size_t t = 0; t < mesh.triangleMaterial.size(); ++t)
        mesh.triangleMaterial[t] = std::uint32_t(t / 700 % 2);
    return mesh;
}

class SlicedFrameGlTest : public GlTest {
protected:
    void SetUp() override {
        ASSERT_TRUE(s_context);
        ASSERT_TRUE(m_renderer.initialize());
        m_mesh = runsOfTwoMaterials();
        m_renderer.setMesh(m_mesh);
        m_view = orbitView(m_mesh, 30.0f, 20.0f, 160, 120);
        m_options.cullBackFaces = true;
    }
    void TearDown() override {
        m_frame.release();
        m_renderer.release();
    }

    /** renderer.draw() into a target with a window's depth, read back. */
    core::Image drawnAtOnce(const core::View& view) {
        render::OffscreenTarget target;
        EXPECT_TRUE(target.create(view.width, view.height, true));
        target.bind();
        m_renderer.draw(view, m_options);
        return target.readColor();
    }

    /** The frame as drawn so far, copied into a fresh target and read back. */
    core::Image copied(const core::View& view) {
        render::OffscreenTarget target;
        EXPECT_TRUE(target.create(view.width, view.height, true));
        m_frame.copyTo(target.framebuffer());
        return target.readColor();
    }

    /** advance() until the frame is whole; how many calls it took. */
    int advanceToWhole(const core::View& view, std::size_t slice) {
        for (int calls = 1; calls < 10000; ++calls) {
            const core::Result<bool> whole = m_frame.advance(m_renderer, view, m_options, slice);
            EXPECT_TRUE(whole) << whole.error();
            if (!whole || *whole)
                return calls;
        }
        ADD_FAILURE() << "the frame never became whole";
        return 0;
    }

    render::MeshRenderer m_renderer;
    render::SlicedFrame m_frame;
    core::Mesh m_mesh;
    core::View m_view;
    render::DrawOptions m_options;
};

TEST_F(SlicedFrameGlTest, ItsSlicesGiveTheWholeDrawsPixelsByteForByte) {
    const std::size_t triangles = m_renderer.frameTriangles(m_options);
    ASSERT_EQ(triangles, m_mesh.triangleCount());
    for (const std::size_t slice : {std::size_t(997), std::size_t(5000), triangles}) {
        SCOPED_TRACE(slice);
        m_frame.release();
        EXPECT_EQ(advanceToWhole(m_view, slice), int((triangles + slice - 1) / slice));
        EXPECT_TRUE(m_frame.isWhole());
        EXPECT_EQ(m_frame.drawnTriangles(), triangles);
        EXPECT_EQ(copied(m_view).rgba, drawnAtOnce(m_view).rgba);
    }
    // The bound framebuffer and the viewport are as they were.
    render::OffscreenTarget own;
    ASSERT_TRUE(own.create(40, 30));
    own.bind();
    m_frame.release();
    ASSERT_TRUE(m_frame.advance(m_renderer, m_view, m_options, 1000));
    GLint bound = 0, viewport[4] = {};
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(GLuint(bound), own.framebuffer());
    EXPECT_EQ(viewport[2], 40);
    EXPECT_EQ(viewport[3], 30);
}

TEST_F(SlicedFrameGlTest, AFrameShowsWhatIsDrawnSoFarUntilWhole) {
    const core::Image whole = drawnAtOnce(m_view);
    const core::Result<bool> first = m_frame.advance(m_renderer, m_view, m_options, 1500);
    ASSERT_TRUE(first);
    EXPECT_FALSE(*first);
    EXPECT_FALSE(m_frame.isWhole());
    EXPECT_EQ(m_frame.drawnTriangles(), 1500u);
    // Part of the knot: some of its pixels already, not all of them.
    const core::Image part = copied(m_view);
    render::OffscreenTarget empty;
    ASSERT_TRUE(empty.create(m_view.width, m_view.height, true));
    empty.bind();
    render::MeshRenderer none;
    ASSERT_TRUE(none.initialize());
    none.draw(m_view, m_options); // the background alone
    const core::Image background = empty.readColor();
    none.release();
    EXPECT_NE(part.rgba, whole.rgba);
    EXPECT_NE(part.rgba, background.rgba);
}

TEST_F(SlicedFrameGlTest, AChangeOfViewOptionsColoursOrTexturesStartsTheFrameAgain) {
    const std::size_t slice = m_renderer.frameTriangles(m_options) / 3 + 1;
    ASSERT_EQ(advanceToWhole(m_view, slice), 3);
    // Nothing changed: whole at once, nothing drawn again.
    EXPECT_EQ(advanceToWhole(m_view, slice), 1);

    const core::View turned = orbitView(m_mesh, 60.0f, 20.0f, 160, 120);
    EXPECT_EQ(advanceToWhole(turned, slice), 3);
    EXPECT_EQ(copied(turned).rgba, drawnAtOnce(turned).rgba);

    m_options.channel = render::MaterialChannel::BaseColor;
    EXPECT_EQ(advanceToWhole(turned, slice), 3);
    EXPECT_EQ(copied(turned).rgba, drawnAtOnce(turned).rgba);

    core::Image painted = m_mesh.textures[0];
    std::fill(painted.rgba.begin(), painted.rgba.end(), std::uint8_t(200));
    m_renderer.textures().updateTexels(0, 0, 0, 16, 16, painted);
    EXPECT_EQ(advanceToWhole(turned, slice), 3);
    EXPECT_EQ(copied(turned).rgba, drawnAtOnce(turned).rgba);

    core::Mesh coloured = m_mesh;
    coloured.colors.assign(coloured.vertexCount(), glm::vec4(1.0f, 0.5f, 0.5f, 1.0f));
    m_renderer.setMesh(coloured);
    EXPECT_EQ(advanceToWhole(turned, slice), 3);
    const std::vector<glm::vec4> green(100, glm::vec4(0.0f, 1.0f, 0.0f, 1.0f));
    m_renderer.updateVertexColors(0, green);
    EXPECT_EQ(advanceToWhole(turned, slice), 3);
    EXPECT_EQ(copied(turned).rgba, drawnAtOnce(turned).rgba);

    const core::View larger = orbitView(m_mesh, 60.0f, 20.0f, 200, 100);
    EXPECT_EQ(advanceToWhole(larger, slice), 3);
    EXPECT_EQ(copied(larger).rgba, drawnAtOnce(larger).rgba);
}

TEST_F(SlicedFrameGlTest, AFrameWithoutAMeshIsTheBackground) {
    render::MeshRenderer none;
    ASSERT_TRUE(none.initialize());
    m_options.background = glm::vec4(0.25f, 0.5f, 0.75f, 1.0f);
    const core::Result<bool> whole = m_frame.advance(none, m_view, m_options, 1000);
    ASSERT_TRUE(whole);
    EXPECT_TRUE(*whole);
    const core::Image image = copied(m_view);
    EXPECT_EQ(image.rgba[0], 64);
    EXPECT_EQ(image.rgba[1], 128);
    EXPECT_EQ(image.rgba[2], 191);
    m_frame.release();
    none.release();
}

} // namespace sliced_frame_gltest
