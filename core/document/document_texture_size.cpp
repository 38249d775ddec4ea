// SPDX-License-Identifier: GPL-3.0-or-later
// Document::raiseTextureSize(): a texture target's page made larger. The target is made anew
// from the mesh as painted (its pages as the materials' textures, factors and vertex colours
// baked in), the raised page resampled bilinearly; the old target stays in the history step.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "core/document/document.h"

namespace core {

namespace {

constexpr int kMaxTextureSide = 8192;

/** image resampled bilinearly (texel centres, edges clamped) to width × height, per byte. */
Image resampled(const Image& image, int width, int height) {
    Image out;
    out.width = width;
    out.height = height;
    out.rgba.resize(std::size_t(width) * std::size_t(height) * 4);
    const double sx = double(image.width) / width, sy = double(image.height) / height;
    const auto texel = [&image](int x, int y, int k) {
        x = std::clamp(x, 0, image.width - 1);
        y = std::clamp(y, 0, image.height - 1);
        return double(image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4 +
                                 std::size_t(k)]);
    };
    for (int y = 0; y < height; ++y) {
        const double fy = (y + 0.5) * sy - 0.5;
        const int y0 = int(std::floor(fy));
        const double ty = fy - y0;
        for (int x = 0; x < width; ++x) {
            const double fx = (x + 0.5) * sx - 0.5;
            const int x0 = int(std::floor(fx));
            const double tx = fx - x0;
            std::uint8_t* px =
                &out.rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
            for (int k = 0; k < 4; ++k) {
                const double top = texel(x0, y0, k) * (1 - tx) + texel(x0 + 1, y0, k) * tx;
                const double bottom =
                    texel(x0, y0 + 1, k) * (1 - tx) + texel(x0 + 1, y0 + 1, k) * tx;
                px[k] = std::uint8_t(std::lround(top * (1 - ty) + bottom * ty));
            }
        }
    }
    return out;
}

} // namespace

Status Document::raiseTextureSize(std::uint32_t material, int width) {
    const auto* target = dynamic_cast<const TextureTarget*>(m_paintTarget.get());
    if (target == nullptr)
        return Error{"the paint target is not a texture"};
    if (material >= target->mesh().materials.size())
        return Error{"there is no material " + std::to_string(material) + " (the model has " +
                     std::to_string(target->mesh().materials.size()) + ")"};
    if (target->paintLayerStack().size() > 0)
        return Error{"the texture size cannot change while there are paint layers (their planes "
                     "are not resampled): merge or delete them first"};
    const std::uint32_t page = target->materialPage(material);
    const Image& current = target->page(page);
    const int height = int(std::lround(double(current.height) * width / current.width));
    if (width <= current.width)
        return Error{"the texture is " + std::to_string(current.width) + " × " +
                     std::to_string(current.height) + " already: give a larger width"};
    if (width > kMaxTextureSide || height > kMaxTextureSide)
        return Error{"a texture can be at most " + std::to_string(kMaxTextureSide) + " texels " +
                     "on a side"};

    // The mesh as painted paints back into its pages (the factors are baked in, so every page
    // is its texture byte for byte); only the raised one is new.
    Mesh painted = target->paintedMesh();
    painted.textures[page] = resampled(painted.textures[page], width, height);
    if (page < painted.textureOrigins.size())
        painted.textureOrigins[page].unchanged = false;
    if (page < painted.textureSources.size())
        painted.textureSources[page] = {};
    PaintTargetOptions options = m_paintOptions;
    options.kind = PaintTargetKind::Texture;
    options.reuseTextures = true;
    // A layout target's mesh has its own vertices: its topology is made anew.
    auto raised =
        TextureTarget::create(std::make_shared<const Mesh>(std::move(painted)),
                              &target->mesh() == m_mesh.get() ? m_topology : nullptr, options);
    if (!raised)
        return raised.takeError();
    installPaintTarget(std::move(raised).value(), m_paintOptions,
                       {{"op", "raise-texture-size"}, {"material", material}, {"width", width}});
    return {};
}

} // namespace core
