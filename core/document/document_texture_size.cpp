// SPDX-License-Identifier: GPL-3.0-or-later
// Document::raiseTextureSize(): a texture target's page made larger. The target is made anew
// from the mesh as painted (its pages as the materials' textures, factors and vertex colours
// baked in), the raised page resampled bilinearly; its paint layers go along, their planes and
// base on that page resampled too (coverage-weighted, so paint does not darken at its edges).
// The old target stays in the history step.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/document/document.h"
#include "core/document/project_state.h"

namespace core {

namespace {

constexpr int kMaxTextureSide = 8192;

/** The four texels around a sample and their weights (texel centres, edges clamped). */
struct Taps {
    int x[4], y[4];
    double weight[4];
};

/** The taps of texel (x, y) of an image of size to, sampled from one of size from. */
Taps tapsFor(int x, int y, PageSize from, PageSize to) {
    const double fx = (x + 0.5) * double(from.width) / to.width - 0.5;
    const double fy = (y + 0.5) * double(from.height) / to.height - 0.5;
    const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
    const double tx = fx - x0, ty = fy - y0;
    const int x1 = std::clamp(x0 + 1, 0, from.width - 1),
              y1 = std::clamp(y0 + 1, 0, from.height - 1);
    const int cx = std::clamp(x0, 0, from.width - 1), cy = std::clamp(y0, 0, from.height - 1);
    return {{cx, x1, cx, x1},
            {cy, cy, y1, y1},
            {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty}};
}

/** image resampled bilinearly to width × height, per byte. */
Image resampled(const Image& image, int width, int height) {
    Image out;
    out.width = width;
    out.height = height;
    out.rgba.resize(std::size_t(width) * std::size_t(height) * 4);
    const PageSize from{image.width, image.height}, to{width, height};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Taps taps = tapsFor(x, y, from, to);
            std::uint8_t* px =
                &out.rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4];
            for (int k = 0; k < 4; ++k) {
                double sum = 0.0;
                for (int i = 0; i < 4; ++i)
                    sum += taps.weight[i] *
                           image.rgba[(std::size_t(taps.y[i]) * std::size_t(image.width) +
                                       std::size_t(taps.x[i])) *
                                          4 +
                                      std::size_t(k)];
                px[k] = std::uint8_t(std::lround(sum));
            }
        }
    return out;
}

/**
 * Texel (x, y) of page of the resampled plane into out (texelBytes bytes). With more than one
 * byte the last is the coverage and the values are weighted by it, so a painted texel beside an
 * unpainted one keeps its value and only its coverage falls off.
 */
void resampledTexel(const TiledPlane& plane, std::uint32_t page, const Taps& taps,
                    std::uint8_t* out) {
    const int bytes = plane.texelBytes();
    const int values = bytes > 1 ? bytes - 1 : 1;
    double sums[4] = {}, coverage = 0.0; // coverage in byte units
    for (int i = 0; i < 4; ++i) {
        const std::uint8_t* t = plane.texel(page, taps.x[i], taps.y[i]);
        const double w = taps.weight[i] * (bytes > 1 ? t[bytes - 1] : 255);
        coverage += w;
        for (int k = 0; k < values; ++k)
            sums[k] += w * t[k];
    }
    for (int k = 0; k < values; ++k)
        out[k] = coverage > 0.0 ? std::uint8_t(std::lround(sums[k] / coverage))
                                : plane.fill()[std::size_t(k)];
    if (bytes > 1)
        out[bytes - 1] = std::uint8_t(std::lround(coverage));
}

/** plane over pages, page resampled to its new size there and the other pages' tiles copied. */
std::shared_ptr<const TiledPlane> resampledPlane(const std::shared_ptr<const TiledPlane>& plane,
                                                 std::uint32_t page,
                                                 const std::vector<PageSize>& pages) {
    if (!plane)
        return nullptr;
    auto out = std::make_shared<TiledPlane>(pages, plane->texelBytes(), plane->fill());
    std::vector<std::uint8_t> bytes;
    for (const TileKey& key : plane->writtenTiles())
        if (key.page != page) {
            bytes.resize(plane->tileBytes(key));
            if (plane->readTile(key, bytes))
                out->writeTile(key, bytes);
        }
    if (!plane->anyTile(page))
        return out;
    const PageSize from = plane->pages()[page], to = pages[page];
    const auto texelBytes = std::size_t(plane->texelBytes());
    for (std::uint32_t tile = 0; tile < out->tileCount(page); ++tile) {
        const TileRect rect = out->tileRect(page, tile);
        bytes.assign(std::size_t(rect.width) * std::size_t(rect.height) * texelBytes, 0);
        for (int y = 0; y < rect.height; ++y)
            for (int x = 0; x < rect.width; ++x)
                resampledTexel(*plane, page, tapsFor(rect.x + x, rect.y + y, from, to),
                               &bytes[(std::size_t(y) * std::size_t(rect.width) + std::size_t(x)) *
                                      texelBytes]);
        out->writeTile({page, tile, 0}, bytes);
    }
    return out;
}

/**
 * layers (of stack) over pages: every plane's page resampled to its new size, and that page's
 * base always given (the new target's own base there would be the composite).
 */
SavedPaintLayers resampledPaintLayers(const SavedPaintLayers& layers, const PaintLayerStack& stack,
                                      std::uint32_t page, const std::vector<PageSize>& pages) {
    SavedPaintLayers out = layers;
    for (SavedPaintLayer& layer : out.layers) {
        for (auto& channel : layer.channels)
            channel = resampledPlane(channel, page, pages);
        layer.mask = resampledPlane(layer.mask, page, pages);
    }
    const PageSize from = stack.pages()[page], to = pages[page];
    out.base.resize(pages.size());
    out.base[page] =
        resampled(Image{from.width, from.height, stack.baseColor(page)}, to.width, to.height);
    if (stack.hasMaterialChannels()) {
        out.baseMetallicRoughness.resize(pages.size());
        out.baseMetallicRoughness[page] = resampled(
            Image{from.width, from.height, stack.baseMetallicRoughness(page)}, to.width, to.height);
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
    // is its texture byte for byte); only the raised one is new. Paint layers keep their own
    // base beside it.
    const std::shared_ptr<const SavedPaintLayers> layers = capturePaintLayers(*target);
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
    if (layers) {
        PaintLayerTarget& raisedLayers = *(*raised)->paintLayers();
        const SavedPaintLayers resampledLayers = resampledPaintLayers(
            *layers, target->paintLayerStack(), page, raisedLayers.paintLayerStack().pages());
        if (const Status restored = restorePaintLayers(raisedLayers, resampledLayers); !restored)
            return restored;
    }
    installPaintTarget(std::move(raised).value(), m_paintOptions,
                       {{"op", "raise-texture-size"}, {"material", material}, {"width", width}});
    return {};
}

} // namespace core
