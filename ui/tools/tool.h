// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <Qt>

namespace ui {

/** What the left button does in the viewport (the Tools toolbar; Alt always moves the camera). */
enum class Tool {
    Brush,      // B: paint a stroke
    Eraser,     // E: a stroke back to the original surface colour
    Fill,       // G: flood fill
    Eyedropper, // I, or Ctrl+click with any tool: pick the colour under the cursor
    Hide,       // H: paint-to-hide regions on the segmentation map
    PopUp,      // P, or Shift+click with any tool: pop up the region below the visible one
};

/** The tool a press with modifiers uses while tool is chosen (Ctrl and Shift borrow a tool). */
inline Tool toolForPress(Tool tool, Qt::KeyboardModifiers modifiers) {
    if (modifiers & Qt::ControlModifier)
        return Tool::Eyedropper;
    if (modifiers & Qt::ShiftModifier)
        return Tool::PopUp;
    return tool;
}

} // namespace ui
