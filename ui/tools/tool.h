// SPDX-License-Identifier: GPL-3.0-or-later
// ui/tools/: the left button's tools, their cursors and hints, and the region operations.
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
    PopUp,      // P, or Ctrl+Shift+click with any tool: pop up the region below the visible one
};

/**
 * The tool a press with modifiers uses while tool is chosen (Ctrl and Ctrl+Shift borrow a tool).
 * Shift alone keeps the tool: with the brush or eraser it draws a straight line
 * (pressDrawsLine()).
 */
inline Tool toolForPress(Tool tool, Qt::KeyboardModifiers modifiers) {
    if ((modifiers & Qt::ControlModifier) && (modifiers & Qt::ShiftModifier))
        return Tool::PopUp;
    if (modifiers & Qt::ControlModifier)
        return Tool::Eyedropper;
    return tool;
}

/** Whether a press of tool with modifiers is a straight line from the last stroke (Shift). */
inline bool pressDrawsLine(Tool tool, Qt::KeyboardModifiers modifiers) {
    return (modifiers & Qt::ShiftModifier) && !(modifiers & Qt::ControlModifier) &&
           (tool == Tool::Brush || tool == Tool::Eraser);
}

} // namespace ui
