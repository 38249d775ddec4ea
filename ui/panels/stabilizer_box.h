// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QGroupBox>

#include "core/paint/brush/dab.h"

class QCheckBox;
class QSpinBox;

namespace ui {

/**
 * The Brush panel's stroke stabilizer group (core::Brush's stabilizer fields): on or off (the
 * group's check), the string's length, the smoothing and the catch-up at release. changed() on
 * every edit; setBrush() shows values without emitting.
 */
class StabilizerBox : public QGroupBox {
    Q_OBJECT

public:
    explicit StabilizerBox(QWidget* parent = nullptr);

    void setBrush(const core::Brush& brush);
    /** Writes the group's settings into brush's stabilizer fields. */
    void readInto(core::Brush& brush) const;

signals:
    void changed();

private:
    QSpinBox* m_length = nullptr;
    QSpinBox* m_smoothing = nullptr;
    QCheckBox* m_catchUp = nullptr;
    bool m_updating = false;
};

} // namespace ui
