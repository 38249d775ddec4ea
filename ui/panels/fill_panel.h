// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

#include "core/paint/targets/flood_fill.h"

class QComboBox;
class QLabel;
class QSlider;

namespace ui {

/**
 * The Fill tool's options: what a click fills (core::FillMode) and the colour tolerance of the
 * similar-colour mode, as a percentage slider. Both are remembered in the settings ("fill/mode",
 * "fill/tolerance") and restored on construction.
 */
class FillPanel : public QWidget {
    Q_OBJECT

public:
    explicit FillPanel(QWidget* parent = nullptr);

    core::FillMode mode() const;
    void setMode(core::FillMode mode);
    /** 0 (only the very colour clicked) … 1 (any colour). */
    float tolerance() const;
    void setTolerance(float tolerance);

signals:
    void optionsChanged();

private:
    void updateControls();

    QComboBox* m_mode = nullptr;
    QSlider* m_tolerance = nullptr;
    QLabel* m_toleranceValue = nullptr;
};

} // namespace ui
