// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/tools/tool_hints.h"

#include <QCoreApplication>

namespace ui {

QString toolHint(Tool tool) {
    switch (tool) {
    case Tool::Brush:
        return QCoreApplication::translate(
            "ToolHints",
            "Brush: drag to paint; Shift+click draws a straight line on from the last stroke; "
            "Ctrl+click picks a colour; Alt+drag moves the camera");
    case Tool::Eraser:
        return QCoreApplication::translate(
            "ToolHints",
            "Eraser: drag to bring back the original surface; Shift+click erases a straight "
            "line; Alt+drag moves the camera");
    case Tool::Fill:
        return QCoreApplication::translate(
            "ToolHints", "Fill: click to fill with the brush colour (options in the Fill panel); "
                         "Ctrl+click picks a colour");
    case Tool::Eyedropper:
        return QCoreApplication::translate(
            "ToolHints",
            "Eyedropper: click to take the painted colour of the surface under the cursor");
    case Tool::Hide:
        return QCoreApplication::translate(
            "ToolHints", "Paint to Hide: paint over regions to hide them and see what lies behind; "
                         "Shift+H unhides all");
    case Tool::PopUp:
        return QCoreApplication::translate(
            "ToolHints",
            "Pop Up: click to bring the region below the visible one to the front; click "
            "again to go deeper (Ctrl+Shift+click with any tool)");
    }
    return {};
}

} // namespace ui
