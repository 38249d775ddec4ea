// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <vector>

#include <QImage>
#include <QSize>

#include "core/base/progress.h"

namespace ui {

/** The pictures of the quick guide, in its order. */
enum class GuidePicture { LayerAwareStroke, PopUp, PaintToHide, OrbitAboutPoint, Count };

/**
 * Draws the quick guide's pictures with the app's own controller: the built-in row of four
 * bodies, captured on the CPU (no GL, so it runs on any thread), painted, popped up, hidden and
 * turned through core::Document exactly as the tools do, shaded from the visible fragments.
 * Returns one image per GuidePicture of size, or none when progress cancelled.
 */
std::vector<QImage> makeQuickGuidePictures(QSize size, const core::ProgressFn& progress = {});

} // namespace ui
