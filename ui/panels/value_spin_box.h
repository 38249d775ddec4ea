// SPDX-License-Identifier: GPL-3.0-or-later
// The number fields the brush panel and the brush bar share: a spin box, alone or with a slider.
#pragma once

#include <QString>

class QHBoxLayout;
class QSpinBox;
class QWidget;

namespace ui {

/**
 * A spin box for one value: object name (tests and remembered layouts find it by it), range,
 * suffix and tooltip; it reports a typed value once, when it is complete (no keyboard tracking).
 */
QSpinBox* makeValueSpinBox(QWidget* parent, const QString& name, int minimum, int maximum,
                           const QString& suffix, const QString& tip);

/** A row of a slider over spin's range, with spin's tooltip, beside spin; the two follow each
 * other. */
QHBoxLayout* sliderRow(QSpinBox* spin);

} // namespace ui
