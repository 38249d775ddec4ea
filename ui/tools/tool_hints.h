// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include "ui/tools/tool.h"

namespace ui {

/**
 * One line for the status bar: what a click and drag with tool does and what the modifiers
 * borrow (toolForPress(), pressDrawsLine()), translated.
 */
QString toolHint(Tool tool);

} // namespace ui
