// SPDX-License-Identifier: GPL-3.0-or-later
// A texture target's paint layers as bytes, to compare before and after an operation, an undo or
// a save and reopen.
#pragma once

#include <cstdint>
#include <vector>

#include "core/document/document.h"
#include "core/paint/paint_layers/paint_layers.h"
#include "core/paint/targets/paint_target.h"

namespace core_test {

/** Every layer's id, settings and planes (with their bytes), the selection, the pages. */
struct PaintLayersSnapshot {
    std::vector<std::uint64_t> ids;
    std::vector<core::PaintLayerSettings> settings;
    std::vector<std::vector<std::uint8_t>> planes; // each channel of each layer, then its mask
    core::PaintSelection selection;
    std::vector<std::uint8_t> base, color, mr;

    friend bool operator==(const PaintLayersSnapshot&, const PaintLayersSnapshot&) = default;
};

/** A plane's texel size, fill and written tiles (index, then bytes), in order; {42} for none. */
inline std::vector<std::uint8_t> planeBytes(const core::TiledPlane* plane) {
    std::vector<std::uint8_t> out;
    if (!plane)
        return {42};
    out.push_back(std::uint8_t(plane->texelBytes()));
    out.insert(out.end(), plane->fill().begin(), plane->fill().end());
    for (const core::TileKey key : plane->writtenTiles()) {
        for (int k = 0; k < 4; ++k)
            out.push_back(std::uint8_t(key.tile >> (8 * k)));
        const std::uint8_t* t = plane->tile(key.page, key.tile);
        out.insert(out.end(), t, t + plane->tileBytes(key));
    }
    return out;
}

inline PaintLayersSnapshot paintLayersSnapshot(const core::TextureTarget& target) {
    PaintLayersSnapshot s;
    const core::PaintLayerStack& stack = target.paintLayerStack();
    for (std::size_t i = 0; i < stack.size(); ++i) {
        const core::PaintLayer& layer = stack.layer(i);
        s.ids.push_back(layer.id);
        s.settings.push_back(layer.settings);
        for (const auto& plane : layer.channels)
            s.planes.push_back(planeBytes(plane.get()));
        s.planes.push_back(planeBytes(layer.mask.get()));
    }
    s.selection = target.selection();
    s.base = target.basePixels(0);
    s.color = target.page(0).rgba;
    s.mr = target.metallicRoughnessPage(0).rgba;
    return s;
}

/** The snapshot of doc's current paint target, a texture target. */
inline PaintLayersSnapshot paintLayersSnapshot(const core::Document& doc) {
    return paintLayersSnapshot(dynamic_cast<const core::TextureTarget&>(*doc.currentPaintTarget()));
}

} // namespace core_test
