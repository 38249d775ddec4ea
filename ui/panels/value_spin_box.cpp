// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/value_spin_box.h"

#include <QHBoxLayout>
#include <QSlider>
#include <QSpinBox>

namespace ui {

QSpinBox* makeValueSpinBox(QWidget* parent, const QString& name, int minimum, int maximum,
                           const QString& suffix, const QString& tip) {
    auto* spin = new QSpinBox(parent);
    spin->setObjectName(name);
    spin->setRange(minimum, maximum);
    spin->setSuffix(suffix);
    spin->setToolTip(tip);
    spin->setKeyboardTracking(false);
    return spin;
}

QHBoxLayout* sliderRow(QSpinBox* spin) {
    auto* slider = new QSlider(Qt::Horizontal, spin->parentWidget());
    slider->setRange(spin->minimum(), spin->maximum());
    slider->setToolTip(spin->toolTip());
    QWidget::setTabOrder(slider, spin); // the order they are shown in
    QObject::connect(slider, &QSlider::valueChanged, spin, &QSpinBox::setValue);
    QObject::connect(spin, &QSpinBox::valueChanged, slider, &QSlider::setValue);
    auto* row = new QHBoxLayout;
    row->addWidget(slider, 1);
    row->addWidget(spin);
    return row;
}

} // namespace ui
