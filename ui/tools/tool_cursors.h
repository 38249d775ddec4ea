// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCursor>

#include "ui/tools/tool.h"

namespace ui {

/**
 * The mouse cursor of a tool over the viewport: a small centre mark for the tools that draw the
 * brush outline (brush, eraser, paint to hide), a fill bucket, the eyedropper's crosshair and a
 * pointing hand for pop-up.
 */
QCursor toolCursor(Tool tool);
/** Whether the tool works with the brush radius (the viewport draws the brush outline). */
bool toolShowsBrushOutline(Tool tool);

} // namespace ui
