// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>

#include "core/paint/paint_layers/paint_layers.h"

namespace ui {

/**
 * Small pictures of a paint layer for the Paint Layers panel, sampled from the first page's
 * tiles: unpainted tiles (TiledPlane::tile() is nullptr) cost nothing, so a thumbnail is cheap
 * enough to redo after every stroke. Transparent parts show a checkerboard.
 */
QImage layerThumbnail(const core::PaintLayer& layer, int size);
/** The base's own texels (what the model brought). */
QImage baseThumbnail(const core::PaintLayerStack& stack, int size);
/** The layer's mask: white shows, black hides; a selected mask gets a highlight frame. */
QImage maskThumbnail(const core::TiledPlane& mask, int size, bool selected);
/** An eye, open for a shown layer, closed (faint) for a hidden one. */
QImage eyeIcon(bool visible, int size);

} // namespace ui
