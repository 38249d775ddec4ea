// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QGroupBox>

#include "core/paint/brush/dab.h"

class QCheckBox;
class QComboBox;
class QSpinBox;

namespace ui {

/**
 * The Brush panel's symmetry group (core::Brush::symmetry): mirrors across the model's X, Y and Z
 * planes through the bounding-box centre or the origin, and radial copies about an axis.
 * changed() on every edit; setBrush() shows values without emitting. The settings remember it.
 */
class SymmetryBox : public QGroupBox {
    Q_OBJECT

public:
    explicit SymmetryBox(QWidget* parent = nullptr);

    void setBrush(const core::Brush& brush);
    /** Writes the group's settings into brush.symmetry and remembers them in the settings. */
    void readInto(core::Brush& brush) const;
    /** Sets brush.symmetry to what the settings remember (off when nothing is). */
    static void restore(core::Brush& brush);
    /** Remembers symmetry in the settings, for restore() in the next session. */
    static void remember(const core::BrushSymmetry& symmetry);

signals:
    void changed();

private:
    QCheckBox* m_mirror[3] = {};
    QComboBox* m_center = nullptr;
    QSpinBox* m_radial = nullptr;
    QComboBox* m_axis = nullptr;
    bool m_updating = false;
};

} // namespace ui
