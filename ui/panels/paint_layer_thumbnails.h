// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>

#include "core/paint/paint_layers/paint_layers.h"

namespace ui {

/**
 * Small pictures of a paint layer for the Paint Layers panel, sampled from one page's (texture
 * set's) tiles: unpainted tiles (TiledPlane::tile() is nullptr) cost nothing, so a thumbnail is
 * cheap enough to redo after every stroke. Transparent parts show a checkerboard. The thumbnail
 * strokes paint (painted: the layer's, or its mask's) gets a wide amber frame.
 */
QImage layerThumbnail(const core::PaintLayer& layer, int size, bool painted, std::uint32_t page);
/** The base's own texels on page (what the model brought). */
QImage baseThumbnail(const core::PaintLayerStack& stack, int size, std::uint32_t page);
/** The layer's mask on page: white shows, black hides. */
QImage maskThumbnail(const core::TiledPlane& mask, int size, bool painted, std::uint32_t page);
/** An eye, open for a shown layer, closed (faint) for a hidden one. */
QImage eyeIcon(bool visible, int size);

} // namespace ui
