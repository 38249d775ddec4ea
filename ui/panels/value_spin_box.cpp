// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/value_spin_box.h"

#include <QHBoxLayout>
#include <QLocale>
#include <QSlider>
#include <QSpinBox>

#include <algorithm>

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

UnitSpinBox::UnitSpinBox(QWidget* parent, const QString& name, const QString& tip, bool off)
    : QDoubleSpinBox(parent) {
    setObjectName(name);
    setDecimals(2);
    setSingleStep(0.05);
    setRange(off ? -0.01 : 0.0, 1.0);
    if (off)
        setSpecialValueText(tr("Off"));
    setToolTip(tip);
    setKeyboardTracking(false);
}

bool UnitSpinBox::number(QString text, double& out, bool& percent) const {
    text = text.trimmed();
    percent = text.endsWith(QLatin1Char('%'));
    if (percent)
        text.chop(1);
    bool ok = false;
    out = locale().toDouble(text.trimmed(), &ok);
    if (!ok)
        out = text.trimmed().toDouble(&ok); // a '.' typed under a ',' locale
    return ok;
}

QValidator::State UnitSpinBox::validate(QString& text, int& pos) const {
    if (!specialValueText().isEmpty() && text == specialValueText())
        return QValidator::Acceptable;
    double value = 0.0;
    bool percent = false;
    if (!number(text, value, percent)) {
        const QString trimmed = text.trimmed();
        return trimmed.isEmpty() || trimmed == QStringLiteral("-") ||
                       trimmed == QStringLiteral(".") || trimmed == locale().decimalPoint()
                   ? QValidator::Intermediate
                   : QDoubleSpinBox::validate(text, pos);
    }
    return value >= 0.0 && value <= 100.0 ? QValidator::Acceptable : QValidator::Invalid;
}

double UnitSpinBox::valueFromText(const QString& text) const {
    if (!specialValueText().isEmpty() && text == specialValueText())
        return minimum();
    double value = 0.0;
    bool percent = false;
    if (!number(text, value, percent))
        return QDoubleSpinBox::valueFromText(text);
    return std::clamp(percent || value > 1.0 ? value / 100.0 : value, 0.0, 1.0);
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
