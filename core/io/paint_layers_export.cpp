// SPDX-License-Identifier: GPL-3.0-or-later
// export --per-layer: each paint layer's channels and mask as images beside the export.
#include "core/io/paint_layers_export.h"

#include <array>
#include <cmath>
#include <filesystem>

#include "core/base/text.h"
#include "core/io/export.h"
#include "core/paint/paint_layers/tiled_plane.h"

namespace core {

namespace {

constexpr std::array<const char*, kPaintChannels> kChannelSuffixes = {"basecolor", "roughness",
                                                                      "metallic"};

std::uint8_t toByte(float v) {
    return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

/** A page of plane as RGBA: 4-byte texels as they are, value (+ coverage) bytes as grey. */
Image planeImage(const TiledPlane& plane, std::uint32_t page) {
    const PageSize size = plane.pages()[page];
    Image image{size.width, size.height, {}};
    image.rgba.resize(std::size_t(size.width) * std::size_t(size.height) * 4);
    const int tb = plane.texelBytes();
    std::uint8_t* out = image.rgba.data();
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x, out += 4) {
            const std::uint8_t* t = plane.texel(page, x, y);
            if (tb == 4) {
                std::copy(t, t + 4, out);
            } else {
                out[0] = out[1] = out[2] = t[0];
                out[3] = tb == 2 ? t[1] : 255;
            }
        }
    return image;
}

Image constantImage(PageSize size, std::array<std::uint8_t, 4> rgba) {
    Image image{size.width, size.height, {}};
    image.rgba.resize(std::size_t(size.width) * std::size_t(size.height) * 4);
    for (std::size_t i = 0; i < image.rgba.size(); i += 4)
        std::copy(rgba.begin(), rgba.end(), image.rgba.begin() + std::ptrdiff_t(i));
    return image;
}

/** The fill layer's value of channel c as a texel, or nothing where it leaves c alone. */
std::optional<std::array<std::uint8_t, 4>> fillTexel(const ChannelValues& fill, std::size_t c) {
    if (c == std::size_t(PaintChannel::BaseColor) && fill.baseColor)
        return std::array<std::uint8_t, 4>{toByte(fill.baseColor->r), toByte(fill.baseColor->g),
                                           toByte(fill.baseColor->b), 255};
    const std::optional<float> v = c == std::size_t(PaintChannel::Roughness)  ? fill.roughness
                                   : c == std::size_t(PaintChannel::Metallic) ? fill.metallic
                                                                              : std::nullopt;
    if (!v)
        return std::nullopt;
    const std::uint8_t b = toByte(*v);
    return std::array<std::uint8_t, 4>{b, b, b, 255};
}

} // namespace

std::string sanitizeLayerName(const std::string& name) {
    return fileNamePart(name, "layer");
}

PaintLayerExport paintLayerExport(const PaintLayerStack& stack) {
    PaintLayerExport out;
    out.pages = stack.pages();
    for (std::size_t i = 0; i < stack.size(); ++i) {
        const PaintLayer& layer = stack.layer(i);
        PaintLayerImages images;
        images.settings = layer.settings;
        for (std::size_t c = 0; c < kPaintChannels; ++c)
            if (layer.channels[c])
                images.channels[c] = std::make_shared<const TiledPlane>(*layer.channels[c]);
        if (layer.mask)
            images.mask = std::make_shared<const TiledPlane>(*layer.mask);
        out.layers.push_back(std::move(images));
    }
    return out;
}

Result<std::vector<std::string>> exportPaintLayerImages(const std::string& path,
                                                        const PaintLayerStack& stack,
                                                        const ProgressFn& progress) {
    return exportPaintLayerImages(path, paintLayerExport(stack), progress);
}

Result<std::vector<std::string>> exportPaintLayerImages(const std::string& path,
                                                        const PaintLayerExport& layers,
                                                        const ProgressFn& progress) {
    const std::filesystem::path target(path);
    const std::string stem = target.stem().string();
    const std::filesystem::path folder = target.parent_path();
    std::vector<std::string> files;
    const std::size_t pages = layers.pages.size();
    const std::size_t steps = std::max<std::size_t>(1, layers.layers.size() * pages);
    for (std::size_t i = 0; i < layers.layers.size(); ++i) {
        const PaintLayerImages& layer = layers.layers[i];
        const std::string prefix =
            stem + "_layer-" + std::to_string(i + 1) + "-" + sanitizeLayerName(layer.settings.name);
        for (std::uint32_t p = 0; p < pages; ++p) {
            if (!reportProgress(progress, double(i * pages + p) / double(steps)))
                return cancelledError(path + ": cancelled");
            const std::string page = p == 0 ? "" : "_" + std::to_string(p + 1);
            const auto write = [&](const std::string& suffix, const Image& image) -> Status {
                const std::string file =
                    (folder / (prefix + page + "_" + suffix + ".png")).string();
                if (Status s = exportTexture(file, ExportFormat::Png8, image); !s)
                    return s;
                files.push_back(file);
                return {};
            };
            for (std::size_t c = 0; c < kPaintChannels; ++c) {
                Image image;
                if (layer.settings.kind == PaintLayerKind::Fill) {
                    if (const auto texel = fillTexel(layer.settings.fill, c))
                        image = constantImage(layers.pages[p], *texel);
                } else if (layer.channels[c]) {
                    image = planeImage(*layer.channels[c], p);
                }
                if (image.empty())
                    continue;
                if (Status s = write(kChannelSuffixes[c], image); !s)
                    return s.takeError();
            }
            if (layer.mask)
                if (Status s = write("mask", planeImage(*layer.mask, p)); !s)
                    return s.takeError();
        }
    }
    reportProgress(progress, 1.0);
    return files;
}

} // namespace core
