// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/paint/paint_layers/paint_layers.h"

namespace core {

/**
 * A paint layer's name as a file name part: letters, digits, '-' and '_' kept, runs of anything
 * else one '-', at most 40 characters; "layer" when nothing is left.
 */
std::string sanitizeLayerName(const std::string& name);

/** A paint layer's settings and planes (null: none), as exportPaintLayerImages() reads them. */
struct PaintLayerImages {
    PaintLayerSettings settings;
    std::array<std::shared_ptr<const TiledPlane>, kPaintChannels> channels;
    std::shared_ptr<const TiledPlane> mask;
};

/** A copy of the paint layers of a stack (bottom first) that another thread can export. */
struct PaintLayerExport {
    std::vector<PageSize> pages;
    std::vector<PaintLayerImages> layers;
};

/** Copies the planes of stack's layers (taken on the thread that owns the stack). */
PaintLayerExport paintLayerExport(const PaintLayerStack& stack);

/**
 * Writes every paint layer of stack as PNG images beside path (STEM.EXT): per layer (index from
 * 1, the one right above the base) and page, STEM_layer-INDEX-NAME_CHANNEL.png with CHANNEL
 * basecolor (RGBA, sRGB, alpha the layer's coverage), roughness and metallic (grey, linear,
 * alpha the coverage) for the channels it holds, and mask (grey) where it has one; page i from
 * 2 adds _i after NAME. A fill layer's channels are its values everywhere. Returns the paths
 * written, or the first Error naming the file.
 */
Result<std::vector<std::string>> exportPaintLayerImages(const std::string& path,
                                                        const PaintLayerStack& stack,
                                                        const ProgressFn& progress = {});
/** The same for a copy made by paintLayerExport() (the GUI exports it on a worker thread). */
Result<std::vector<std::string>> exportPaintLayerImages(const std::string& path,
                                                        const PaintLayerExport& layers,
                                                        const ProgressFn& progress = {});

} // namespace core
