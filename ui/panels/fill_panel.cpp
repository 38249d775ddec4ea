// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/fill_panel.h"

#include <QComboBox>
#include <QFontMetrics>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSettings>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
const QString kModeKey = QStringLiteral("fill/mode");
const QString kToleranceKey = QStringLiteral("fill/tolerance");
constexpr int kDefaultTolerancePercent = 10;
} // namespace

FillPanel::FillPanel(QWidget* parent) : QWidget(parent) {
    m_mode = new QComboBox(this);
    m_mode->setObjectName(QStringLiteral("fillMode"));
    m_mode->addItem(tr("Region under the cursor"), int(core::FillMode::Region));
    m_mode->addItem(tr("Connected surface"), int(core::FillMode::Surface));
    m_mode->addItem(tr("Similar colour"), int(core::FillMode::Color));
    m_mode->setItemData(0,
                        tr("The segmented region clicked in this view, including the part of it "
                           "hidden behind other surfaces"),
                        Qt::ToolTipRole);
    m_mode->setItemData(1,
                        tr("Everything connected to the clicked surface in the mesh, seen or "
                           "not, from any side"),
                        Qt::ToolTipRole);
    m_mode->setItemData(2,
                        tr("The surface around the clicked point whose colour is within the "
                           "tolerance of the colour there"),
                        Qt::ToolTipRole);
    m_mode->setToolTip(tr("What a click with the Fill tool fills"));

    m_tolerance = new QSlider(Qt::Horizontal, this);
    m_tolerance->setObjectName(QStringLiteral("fillTolerance"));
    m_tolerance->setRange(0, 100);
    m_tolerance->setPageStep(5);
    m_tolerance->setAccessibleName(tr("Colour tolerance"));
    m_tolerance->setToolTip(tr("How far a colour may differ from the clicked one and still be "
                               "filled (in any channel): 0 % takes only the very same colour"));
    m_toleranceValue = new QLabel(this);
    m_toleranceValue->setObjectName(QStringLiteral("fillToleranceValue"));
    m_toleranceValue->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_toleranceValue->setMinimumWidth(
        QFontMetrics(m_toleranceValue->font()).horizontalAdvance(tr("%1 %").arg(100)) + 4);

    auto* toleranceRow = new QHBoxLayout;
    toleranceRow->setContentsMargins(0, 0, 0, 0);
    toleranceRow->addWidget(m_tolerance, 1);
    toleranceRow->addWidget(m_toleranceValue);

    auto* form = new QFormLayout(this);
    form->addRow(tr("&Fill:"), m_mode);
    form->addRow(tr("&Tolerance:"), toleranceRow);
    // The label's buddy is the row's layout: point it at the slider for the accelerator.
    if (auto* label = qobject_cast<QLabel*>(form->labelForField(toleranceRow)))
        label->setBuddy(m_tolerance);

    const QSettings settings;
    const auto saved = core::parseFillMode(settings.value(kModeKey).toString().toStdString());
    setMode(saved.value_or(core::FillMode::Region));
    setTolerance(float(settings.value(kToleranceKey, kDefaultTolerancePercent / 100.0).toDouble()));
    updateControls();

    connect(m_mode, &QComboBox::currentIndexChanged, this, [this] {
        QSettings().setValue(kModeKey, QString::fromLatin1(core::fillModeName(mode())));
        updateControls();
        emit optionsChanged();
    });
    connect(m_tolerance, &QSlider::valueChanged, this, [this] {
        QSettings().setValue(kToleranceKey, double(tolerance()));
        updateControls();
        emit optionsChanged();
    });
}

core::FillMode FillPanel::mode() const {
    return core::FillMode(m_mode->currentData().toInt());
}

void FillPanel::setMode(core::FillMode mode) {
    const int index = m_mode->findData(int(mode));
    if (index >= 0)
        m_mode->setCurrentIndex(index);
}

float FillPanel::tolerance() const {
    return float(m_tolerance->value()) / 100.0f;
}

void FillPanel::setTolerance(float tolerance) {
    const float t = std::isfinite(tolerance) ? std::clamp(tolerance, 0.0f, 1.0f) : 0.0f;
    m_tolerance->setValue(int(std::lround(t * 100.0f)));
}

void FillPanel::updateControls() {
    m_toleranceValue->setText(tr("%1 %").arg(QLocale().toString(m_tolerance->value())));
    // The tolerance only means something when filling by colour.
    m_tolerance->setEnabled(mode() == core::FillMode::Color);
    m_toleranceValue->setEnabled(m_tolerance->isEnabled());
}

} // namespace ui
