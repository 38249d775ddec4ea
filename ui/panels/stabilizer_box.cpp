// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/stabilizer_box.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QScopedValueRollback>
#include <QSpinBox>

#include <cmath>

#include "ui/panels/value_spin_box.h"

namespace ui {

StabilizerBox::StabilizerBox(QWidget* parent) : QGroupBox(tr("Stroke sta&bilizer"), parent) {
    setObjectName(QStringLiteral("brushPanelStabilizer"));
    setCheckable(true);
    setToolTip(tr("The brush follows the pointer on a string: small wobbles never reach the "
                  "stroke, for pen and mouse alike"));
    auto* form = new QFormLayout(this);
    m_length =
        makeValueSpinBox(this, QStringLiteral("brushPanelStabilizerLength"), 0, 500, tr(" px"),
                         tr("Length of the string: how far the pointer moves before "
                            "the brush follows"));
    QHBoxLayout* lengthRow = sliderRow(m_length);
    form->addRow(tr("Len&gth"), lengthRow);
    m_smoothing =
        makeValueSpinBox(this, QStringLiteral("brushPanelStabilizerSmoothing"), 0, 100, tr(" %"),
                         tr("Averages the pointer's positions before the string "
                            "pulls: 0 takes each as it comes"));
    QHBoxLayout* smoothingRow = sliderRow(m_smoothing);
    form->addRow(tr("Smoothi&ng"), smoothingRow);
    for (QLayout* row : {static_cast<QLayout*>(lengthRow), static_cast<QLayout*>(smoothingRow)})
        if (auto* text = qobject_cast<QLabel*>(form->labelForField(row)))
            text->setBuddy(row == lengthRow ? m_length : m_smoothing);
    m_catchUp = new QCheckBox(tr("C&atch up at release"), this);
    m_catchUp->setObjectName(QStringLiteral("brushPanelStabilizerCatchUp"));
    m_catchUp->setToolTip(tr("On release the stroke goes on to where the pointer is; off, it "
                             "ends where the brush was"));
    form->addRow(m_catchUp);

    const auto edited = [this] {
        if (!m_updating)
            emit changed();
    };
    connect(this, &QGroupBox::toggled, this, edited);
    connect(m_length, &QSpinBox::valueChanged, this, edited);
    connect(m_smoothing, &QSpinBox::valueChanged, this, edited);
    connect(m_catchUp, &QCheckBox::toggled, this, edited);
}

void StabilizerBox::setBrush(const core::Brush& brush) {
    const QScopedValueRollback guard(m_updating, true);
    setChecked(brush.stabilizer);
    m_length->setValue(int(std::lround(brush.stabilizerLength)));
    m_smoothing->setValue(int(std::lround(brush.stabilizerSmoothing * 100.0f)));
    m_catchUp->setChecked(brush.stabilizerCatchUp);
}

void StabilizerBox::readInto(core::Brush& brush) const {
    brush.stabilizer = isChecked();
    brush.stabilizerLength = float(m_length->value());
    brush.stabilizerSmoothing = float(m_smoothing->value()) / 100.0f;
    brush.stabilizerCatchUp = m_catchUp->isChecked();
}

} // namespace ui
