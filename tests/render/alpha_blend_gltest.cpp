// SPDX-License-Identifier: GPL-3.0-or-later
// glTF's alphaMode BLEND in the lit Material view (headless EGL, llvmpipe on CI): both shaded
// views (the mesh renderer and the depth layers' composite) draw a blending surface over what
// lies behind it by its alpha (factor × texture), and alike; other channels draw it opaque.
#include <cstdint>

#include <gtest/gtest.h>

#include "tests/render/compositor_test.h"

#include "core/model/camera.h"

namespace alpha_blend_gltest {

using render_test::DepthCompositorGlTest;
using render_test::expectMatchesPlainRender;
using render_test::saveImage;

/**
 * A red quad (material 0) in front of a blue one (material 1) that lies behind its right half
 * only; the red quad is textured white, with texture alpha 128 on its upper half and 255 below.
 */
core::Mesh quadOverHalfAQuad() {
    core::Mesh mesh;
    const auto quad = [&](float x0, float x1, float z) {
        const auto base = std::uint32_t(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(),
                              {{x0, -0.4f, z}, {x1, -0.4f, z}, {x1, 0.4f, z}, {x0, 0.4f, z}});
        mesh.uvs.insert(mesh.uvs.end(), {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}});
        mesh.indices.insert(mesh.indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
    };
    quad(-0.5f, 0.5f, 0.2f);
    quad(0.0f, 0.6f, -0.2f);
    mesh.normals.assign(mesh.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    mesh.triangleMaterial = {0, 0, 1, 1};
    core::Image texture{8, 8, {}};
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            texture.rgba.insert(texture.rgba.end(),
                                {255, 255, 255, std::uint8_t(y < 4 ? 128 : 255)});
    mesh.textures = {texture};
    mesh.materials.resize(2);
    mesh.materials[0].baseColorFactor = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
    mesh.materials[0].baseColorTexture = 0;
    mesh.materials[1].baseColorFactor = glm::vec4(0.0f, 0.0f, 1.0f, 1.0f);
    return mesh;
}

class AlphaBlendGlTest : public DepthCompositorGlTest {
protected:
    core::View view() const {
        core::Camera camera;
        camera.sceneRadius = 1.0f;
        camera.distance = 2.0f;
        return camera.view(64, 48);
    }

    /** The composite and the plain render of mesh, checked to agree; the composite returned. */
    core::Image drawBoth(const core::Mesh& mesh, const char* name,
                         render::MaterialChannel channel = render::MaterialChannel::Material) {
        const core::View v = view();
        const core::DepthLayers layers = build(mesh, v);
        EXPECT_GT(layers.stack.fragmentCount(), 0u);
        render::CompositeOptions options;
        options.background = kBackground;
        options.channel = channel;
        const core::Image composited = composite(layers, options);
        const core::Image rendered = plain(v, kBackground, channel);
        saveImage(composited, std::string(name) + "_composite");
        saveImage(rendered, std::string(name) + "_plain");
        expectMatchesPlainRender(composited, rendered, layers.stack);
        return composited;
    }

    /** The pixel of image where world point (x, y, 0.2) on the red quad shows. */
    glm::ivec3 at(const core::Image& image, float x, float y) const {
        const glm::vec3 p = view().project(glm::vec3(x, y, 0.2f));
        const std::uint8_t* px =
            &image.rgba[(std::size_t(p.y) * std::size_t(image.width) + std::size_t(p.x)) * 4];
        return {px[0], px[1], px[2]};
    }

    static constexpr glm::vec4 kBackground{0.0f, 0.0f, 0.0f, 1.0f};
};

TEST_F(AlphaBlendGlTest, ABlendingSurfaceShowsWhatIsBehindByItsAlphaInBothViews) {
    core::Mesh mesh = quadOverHalfAQuad();
    const core::Image opaque = drawBoth(mesh, "blend_opaque");
    EXPECT_EQ(at(opaque, 0.3f, 0.2f).b, 0) << "opaque: the red quad hides the blue one";

    mesh.materials[0].alphaMode = core::AlphaMode::Blend;
    const core::Image blended = drawBoth(mesh, "blend");
    // Upper half, texture alpha 128: half red, half the blue behind (or the black background).
    const glm::ivec3 overBlue = at(blended, 0.3f, 0.2f);
    EXPECT_NEAR(overBlue.r, 128, 6);
    EXPECT_NEAR(overBlue.b, 127, 6);
    const glm::ivec3 overBackground = at(blended, -0.3f, 0.2f);
    EXPECT_NEAR(overBackground.r, 128, 6);
    EXPECT_EQ(overBackground.b, 0);
    // Lower half, texture alpha 255: opaque.
    const glm::ivec3 opaqueHalf = at(blended, 0.3f, -0.2f);
    EXPECT_GT(opaqueHalf.r, 245); // the headlight is a little off the quad's normal there
    EXPECT_EQ(opaqueHalf.b, 0);

    // The factor's alpha multiplies the texture's: a quarter over the blue.
    mesh.materials[0].baseColorFactor.a = 0.5f;
    const glm::ivec3 quarter = at(drawBoth(mesh, "blend_factor"), 0.3f, 0.2f);
    EXPECT_NEAR(quarter.r, 64, 6);
    EXPECT_NEAR(quarter.b, 191, 6);
}

TEST_F(AlphaBlendGlTest, TheBaseColourChannelShowsABlendingSurfaceOpaque) {
    core::Mesh mesh = quadOverHalfAQuad();
    mesh.materials[0].alphaMode = core::AlphaMode::Blend;
    const core::Image base = drawBoth(mesh, "blend_base", render::MaterialChannel::BaseColor);
    EXPECT_EQ(at(base, 0.3f, 0.2f).b, 0);
}

} // namespace alpha_blend_gltest
