// SPDX-License-Identifier: GPL-3.0-or-later
// A material's normal, occlusion and emissive maps in the lit Material view (headless EGL,
// llvmpipe on CI): both shaded views (the mesh renderer and the depth layers' composite) draw
// them alike, each map changes the picture the way it should, and the other channels ignore them.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "tests/render/compositor_test.h"

#include "core/io/mesh_io.h"
#include "core/model/camera.h"
#include "render/material_textures.h"

namespace surface_maps_gltest {

using render_test::channelDifference;
using render_test::DepthCompositorGlTest;
using render_test::expectMatchesPlainRender;
using render_test::orbitView;
using render_test::saveImage;

/** A size² image whose texel (x, y) is pixel(x, y). */
template <typename F> core::Image pattern(int size, F&& pixel) {
    core::Image image{size, size, std::vector<std::uint8_t>(std::size_t(size) * size * 4)};
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const glm::u8vec4 p = pixel(x, y);
            std::uint8_t* out = &image.rgba[(std::size_t(y) * size + x) * 4];
            out[0] = p.r;
            out[1] = p.g;
            out[2] = p.b;
            out[3] = p.a;
        }
    return image;
}

/** A normal map of round bumps, 8 across the texture. */
core::Image bumps() {
    return pattern(128, [](int x, int y) {
        const float u = std::sin(float(x) / 128.0f * 16.0f * 3.14159265f);
        const float v = std::sin(float(y) / 128.0f * 16.0f * 3.14159265f);
        const glm::vec3 n = glm::normalize(glm::vec3(0.7f * u, 0.7f * v, 1.0f));
        return glm::u8vec4(glm::round((n * 0.5f + 0.5f) * 255.0f), 255);
    });
}

/** The textured box of glTF-Sample-Models with every map added to its material. */
core::Mesh boxWithMaps(const core::Mesh& box) {
    core::Mesh mesh = box;
    const int normal = int(mesh.textures.size());
    mesh.textures.push_back(bumps());
    mesh.textures.push_back(pattern(64, [](int x, int) {
        return glm::u8vec4(x < 32 ? 40 : 255, 0, 0, 255); // occluded on the left half
    }));
    mesh.textures.push_back(pattern(64, [](int, int y) {
        return glm::u8vec4(y < 16 ? 255 : 0, y < 16 ? 255 : 0, y < 16 ? 255 : 0, 255);
    }));
    for (core::Material& m : mesh.materials) {
        m.normal = {normal, glm::mat3(1.0f)};
        m.occlusion = {normal + 1, glm::mat3(1.0f)};
        m.emissive = {normal + 2, glm::mat3(1.0f)};
        m.emissiveFactor = glm::vec3(0.0f, 0.6f, 0.0f);
    }
    return mesh;
}

class SurfaceMapsGlTest : public DepthCompositorGlTest {
protected:
    /** Both views of mesh, sharing their textures as the viewport's do. */
    void show(const core::Mesh& mesh, const core::DepthLayers& layers) {
        auto textures = std::make_shared<render::MaterialTextures>();
        textures->create(mesh.textures);
        ASSERT_TRUE(m_compositor.setMesh(mesh, textures));
        ASSERT_TRUE(m_compositor.setDepthLayers(layers));
        m_renderer.setMesh(mesh, textures);
    }

    /** The Material view drawn both ways, and checked alike. */
    core::Image drawBoth(const core::DepthLayers& layers, const core::View& view,
                         const std::string& name) {
        render::CompositeOptions options;
        const core::Image composited = composite(layers, options);
        const core::Image rendered = plain(view, options.background);
        saveImage(composited, name + "_composite");
        saveImage(rendered, name + "_plain");
        expectMatchesPlainRender(composited, rendered, layers.stack);
        return rendered;
    }

    /** How many covered pixels of a and b differ by more than tolerance. */
    static std::size_t differing(const core::Image& a, const core::Image& b,
                                 const core::DepthLayers& layers, int tolerance) {
        std::size_t count = 0;
        for (std::size_t p = 0; p < layers.stack.pixelCount(); ++p)
            count += layers.stack.layerCount(p) > 0 && channelDifference(a, b, p) > tolerance;
        return count;
    }
};

TEST_F(SurfaceMapsGlTest, BothViewsDrawTheMapsAlikeAndEachMapShows) {
    const std::string path =
        std::string(LAYERPAINT_ASSIMP_MODELS) + "/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!std::filesystem::exists(path))
        GTEST_SKIP() << path << " is not installed";
    auto box = core::loadMesh(path);
    ASSERT_TRUE(box) << box.error();
    const core::Mesh mapped = boxWithMaps(*box);
    const core::View view = orbitView(mapped, 30.0f, 25.0f, 320, 240);
    const core::DepthLayers layers = build(mapped, view);
    ASSERT_GT(layers.stack.fragmentCount(), 0u);
    std::size_t covered = 0;
    for (std::size_t p = 0; p < layers.stack.pixelCount(); ++p)
        covered += layers.stack.layerCount(p) > 0;

    show(*box, layers);
    const core::Image without = drawBoth(layers, view, "box_without_maps");
    show(mapped, layers);
    const core::Image with = drawBoth(layers, view, "box_with_maps");
    EXPECT_GT(differing(with, without, layers, 12), covered / 4);

    // Each map alone: bumps change the shading, occlusion only darkens, emission only brightens
    // (green, where its map is white).
    const auto only = [&](auto keep) {
        core::Mesh one = mapped;
        for (core::Material& m : one.materials)
            keep(m);
        return one;
    };
    struct Case {
        const char* name;
        core::Mesh mesh;
        int sign; // +1 brighter, -1 darker, 0 either
    };
    const Case cases[] = {
        {"normal", only([](core::Material& m) {
             m.occlusion = {};
             m.emissiveFactor = glm::vec3(0.0f);
         }),
         0},
        {"occlusion", only([](core::Material& m) {
             m.normal = {};
             m.emissiveFactor = glm::vec3(0.0f);
         }),
         -1},
        {"emissive", only([](core::Material& m) {
             m.normal = {};
             m.occlusion = {};
         }),
         +1},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        show(c.mesh, layers);
        const core::Image image = drawBoth(layers, view, std::string("box_") + c.name);
        EXPECT_GT(differing(image, without, layers, 6), covered / 20);
        std::size_t wrongWay = 0;
        for (std::size_t p = 0; c.sign != 0 && p < layers.stack.pixelCount(); ++p) {
            int change = 0;
            for (int ch = 0; ch < 3; ++ch)
                change += int(image.rgba[p * 4 + ch]) - int(without.rgba[p * 4 + ch]);
            wrongWay += change * c.sign < -6;
        }
        EXPECT_EQ(wrongWay, 0u);
    }

    // The unlit channels show the base colour as before.
    show(mapped, layers);
    render::CompositeOptions base;
    base.channel = render::MaterialChannel::BaseColor;
    const core::Image baseWith = composite(layers, base);
    show(*box, layers);
    EXPECT_EQ(differing(composite(layers, base), baseWith, layers, 0), 0u);
}

TEST_F(SurfaceMapsGlTest, AGltfMaterialsMapsShowInBothViews) {
    auto mesh = core::loadMesh(std::string(LAYERPAINT_TEST_DATA) + "/material/materials.glb");
    ASSERT_TRUE(mesh) << mesh.error();
    const core::View view = orbitView(*mesh, 20.0f, 15.0f, 320, 240, 0.9f);
    const core::DepthLayers layers = build(*mesh, view);
    ASSERT_GT(layers.stack.fragmentCount(), 0u);
    show(*mesh, layers);
    const core::Image with = drawBoth(layers, view, "materials_glb");

    core::Mesh bare = *mesh;
    for (core::Material& m : bare.materials) {
        m.normal = m.occlusion = m.emissive = {};
        m.emissiveFactor = glm::vec3(0.0f);
    }
    show(bare, layers);
    const core::Image without = drawBoth(layers, view, "materials_glb_bare");
    std::size_t covered = 0;
    for (std::size_t p = 0; p < layers.stack.pixelCount(); ++p)
        covered += layers.stack.layerCount(p) > 0;
    EXPECT_GT(differing(with, without, layers, 12), covered / 2);
}

} // namespace surface_maps_gltest
