// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/brush_panel.h"

#include "ui/panels/brush_tip_box.h"
#include "ui/panels/stabilizer_box.h"
#include "ui/panels/symmetry_box.h"
#include "ui/panels/value_spin_box.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QPainter>
#include <QPainterPath>
#include <QScopedValueRollback>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

namespace {
// The curve slider is logarithmic in gamma: -100 .. 100 is 1/5 .. 5, the middle is linear.
constexpr double kGammaBase = 5.0;
constexpr int kGammaSteps = 100;

int gammaToSlider(float gamma) {
    return int(std::lround(std::log(double(gamma)) / std::log(kGammaBase) * kGammaSteps));
}

float sliderToGamma(int value) {
    return float(std::pow(kGammaBase, double(value) / kGammaSteps));
}
} // namespace

PressureCurveView::PressureCurveView(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    setToolTip(tr("Pen pressure (right) to stroke pressure (up)"));
}

void PressureCurveView::setCurve(const core::PressureCurve& curve) {
    m_curve = curve;
    update();
}

QSize PressureCurveView::sizeHint() const {
    return {48, 48};
}

void PressureCurveView::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF box = QRectF(rect()).adjusted(1.5, 1.5, -1.5, -1.5);
    painter.setPen(QPen(palette().color(QPalette::Mid), 1.0));
    painter.setBrush(palette().color(QPalette::Base));
    painter.drawRect(box);
    QPainterPath path;
    constexpr int kSamples = 32;
    for (int i = 0; i <= kSamples; ++i) {
        const float p = float(i) / kSamples;
        const QPointF point(box.left() + box.width() * p,
                            box.bottom() - box.height() * double(m_curve.apply(p)));
        if (i == 0)
            path.moveTo(point);
        else
            path.lineTo(point);
    }
    painter.setPen(QPen(palette().color(QPalette::Highlight), 2.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(path);
}

BrushPanel::BrushPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    m_form = new QFormLayout;
    layout->addLayout(m_form);
    addSizeRows();
    addPressureRows();
    addChannelRows();
    addPressureCurveRow();
    addTipBox(layout);
    addStabilizerBox(layout);
    addSymmetryBox(layout);
    layout->addStretch(1);

    setBrush(m_brush);
    setPressureCurve(m_curve);
}

void BrushPanel::addSizeRows() {
    m_radius = addRow(tr("&Radius"), QStringLiteral("brushPanelRadius"), 1, 500, tr(" px"),
                      tr("Brush radius on screen ([ and ] change it)"));
    m_hardness =
        addRow(tr("&Hardness"), QStringLiteral("brushPanelHardness"), 0, 100, tr(" %"),
               tr("0: soft falloff from the centre, 100: a hard edge (Shift+[ and Shift+])"));
    m_opacity = addRow(tr("O&pacity"), QStringLiteral("brushPanelOpacity"), 1, 100, tr(" %"),
                       tr("The most one stroke covers"));
    m_flow = addRow(tr("&Flow"), QStringLiteral("brushPanelFlow"), 1, 100, tr(" %"),
                    tr("How much one dab adds towards the opacity"));
    m_spacing = addRow(tr("&Spacing"), QStringLiteral("brushPanelSpacing"), 1, 200, tr(" %"),
                       tr("Distance between dabs, in per cent of the radius"));
    m_trackRadius = makeValueSpinBox(
        this, QStringLiteral("brushPanelTrackRadius"), 0, 4000, tr(" px"),
        tr("R_max: how far a layer-aware stroke looks for the surface it follows from one dab to "
           "the next; 0 chooses it from the radius"));
    m_form->addRow(tr("&Tracking (R_max)"), m_trackRadius);
    connect(m_trackRadius, &QSpinBox::valueChanged, this, &BrushPanel::readBrush);
}

void BrushPanel::addPressureRows() {
    m_pressureRadius = new QCheckBox(tr("Si&ze"), this);
    m_pressureRadius->setObjectName(QStringLiteral("brushPanelPressureRadius"));
    m_pressureRadius->setToolTip(tr("Pen pressure scales the radius"));
    m_pressureOpacity = new QCheckBox(tr("Opa&city"), this);
    m_pressureOpacity->setObjectName(QStringLiteral("brushPanelPressureOpacity"));
    m_pressureOpacity->setToolTip(tr("Pen pressure scales the opacity"));
    auto* pressureRow = new QHBoxLayout;
    pressureRow->addWidget(m_pressureRadius);
    pressureRow->addWidget(m_pressureOpacity);
    pressureRow->addStretch(1);
    m_form->addRow(tr("Pressure changes"), pressureRow);
    for (QCheckBox* box : {m_pressureRadius, m_pressureOpacity})
        connect(box, &QCheckBox::toggled, this, &BrushPanel::readBrush);
}

void BrushPanel::addChannelRows() {
    // The material channels a stroke paints, each with its own value (base colour: the Colour
    // panel's).
    m_paintBaseColor = new QCheckBox(tr("Base co&lour"), this);
    m_paintBaseColor->setObjectName(QStringLiteral("brushPanelPaintBaseColor"));
    m_paintBaseColor->setToolTip(tr("Strokes paint the base colour (the Colour panel's)"));
    m_form->addRow(m_paintBaseColor);
    const auto channelRow = [this](const QString& text, const QString& name, const QString& tip,
                                   QCheckBox*& box, QDoubleSpinBox*& value) {
        box = new QCheckBox(text, this);
        box->setObjectName(name);
        box->setToolTip(tip);
        value = new UnitSpinBox(this, name + QStringLiteral("Value"), tip, false);
        m_form->addRow(box, value);
        connect(box, &QCheckBox::toggled, this, &BrushPanel::readBrush);
        connect(value, &QDoubleSpinBox::valueChanged, this, &BrushPanel::readBrush);
    };
    channelRow(tr("R&oughness"), QStringLiteral("brushPanelPaintRoughness"),
               tr("Strokes paint this roughness (0: glossy, 1: matt)"), m_paintRoughness,
               m_roughness);
    channelRow(tr("&Metallic"), QStringLiteral("brushPanelPaintMetallic"),
               tr("Strokes paint this metalness (0: dielectric, 1: metal)"), m_paintMetallic,
               m_metallic);
    connect(m_paintBaseColor, &QCheckBox::toggled, this, &BrushPanel::readBrush);
    m_channelNote = new QLabel(this);
    m_channelNote->setObjectName(QStringLiteral("brushPanelChannelNote"));
    m_channelNote->setWordWrap(true);
    m_channelNote->hide();
    m_form->addRow(m_channelNote);
}

void BrushPanel::addPressureCurveRow() {
    m_gamma = new QSlider(Qt::Horizontal, this);
    m_gamma->setObjectName(QStringLiteral("brushPanelPressureCurve"));
    m_gamma->setRange(-kGammaSteps, kGammaSteps);
    m_gamma->setToolTip(tr("Pressure curve: left, a light touch gives much; right, it takes a "
                           "firm press"));
    m_gammaText = new QLabel(this);
    m_gammaText->setMinimumWidth(fontMetrics().horizontalAdvance(QStringLiteral("γ 0.00")));
    m_curveView = new PressureCurveView(this);
    auto* curveRow = new QHBoxLayout;
    curveRow->addWidget(m_gamma, 1);
    curveRow->addWidget(m_gammaText);
    curveRow->addWidget(m_curveView);
    m_form->addRow(tr("Pressure c&urve"), curveRow);
    if (auto* text = qobject_cast<QLabel*>(m_form->labelForField(curveRow)))
        text->setBuddy(m_gamma);
    connect(m_gamma, &QSlider::valueChanged, this, [this](int value) {
        if (m_updating)
            return;
        m_curve.gamma = sliderToGamma(value);
        m_gammaText->setText(tr("γ %1").arg(QLocale().toString(m_curve.gamma, 'f', 2)));
        m_curveView->setCurve(m_curve);
        emit pressureCurveChanged(m_curve);
    });
}

void BrushPanel::addTipBox(QVBoxLayout* layout) {
    m_tipBox = new BrushTipBox(this);
    layout->addWidget(m_tipBox);
    connect(m_tipBox, &BrushTipBox::changed, this, [this] {
        m_tipBox->apply(m_brush);
        emit brushChanged(m_brush);
    });
}

QSpinBox* BrushPanel::addRow(const QString& label, const QString& name, int minimum, int maximum,
                             const QString& suffix, const QString& tip) {
    QSpinBox* spin = makeValueSpinBox(this, name, minimum, maximum, suffix, tip);
    QHBoxLayout* row = sliderRow(spin);
    connect(spin, &QSpinBox::valueChanged, this, &BrushPanel::readBrush);
    m_form->addRow(label, row);
    if (auto* text = qobject_cast<QLabel*>(m_form->labelForField(row)))
        text->setBuddy(spin);
    return spin;
}

void BrushPanel::readBrush() {
    if (m_updating)
        return;
    m_brush.radius = float(m_radius->value());
    m_brush.hardness = float(m_hardness->value()) / 100.0f;
    m_brush.opacity = float(m_opacity->value()) / 100.0f;
    m_brush.flow = float(m_flow->value()) / 100.0f;
    m_brush.spacing = float(m_spacing->value()) / 100.0f;
    m_brush.trackRadius = float(m_trackRadius->value());
    m_brush.pressureRadius = m_pressureRadius->isChecked();
    m_brush.pressureOpacity = m_pressureOpacity->isChecked();
    m_brush.paintBaseColor = m_paintBaseColor->isChecked();
    m_brush.paintRoughness = m_paintRoughness->isChecked();
    m_brush.paintMetallic = m_paintMetallic->isChecked();
    m_brush.roughness = float(m_roughness->value());
    m_brush.metallic = float(m_metallic->value());
    m_stabilizer->readInto(m_brush);
    m_symmetry->readInto(m_brush);
    updateAutoTrackText();
    emit brushChanged(m_brush);
}

void BrushPanel::updateAutoTrackText() {
    core::Brush automatic = m_brush;
    automatic.trackRadius = 0.0f;
    m_trackRadius->setSpecialValueText(
        tr("Automatic (%1 px)").arg(std::lround(automatic.effectiveTrackRadius())));
}

void BrushPanel::setBrush(const core::Brush& brush) {
    const QScopedValueRollback guard(m_updating, true);
    m_brush = brush;
    m_radius->setValue(int(std::lround(brush.radius)));
    m_hardness->setValue(int(std::lround(brush.hardness * 100.0f)));
    m_opacity->setValue(int(std::lround(brush.opacity * 100.0f)));
    m_flow->setValue(int(std::lround(brush.flow * 100.0f)));
    m_spacing->setValue(int(std::lround(brush.spacing * 100.0f)));
    m_trackRadius->setValue(int(std::lround(brush.trackRadius)));
    m_pressureRadius->setChecked(brush.pressureRadius);
    m_pressureOpacity->setChecked(brush.pressureOpacity);
    m_paintBaseColor->setChecked(brush.paintBaseColor);
    m_paintRoughness->setChecked(brush.paintRoughness);
    m_paintMetallic->setChecked(brush.paintMetallic);
    m_roughness->setValue(double(brush.roughness));
    m_metallic->setValue(double(brush.metallic));
    m_stabilizer->setBrush(brush);
    m_symmetry->setBrush(brush);
    m_tipBox->show(brush);
    updateAutoTrackText();
}

void BrushPanel::setMaterialChannels(bool available, const QString& why) {
    for (QWidget* widget : std::initializer_list<QWidget*>{m_paintRoughness, m_roughness,
                                                           m_paintMetallic, m_metallic}) {
        widget->setEnabled(available);
        // The tip says why while disabled; the first part of it is the channel's own.
        QString tip = widget->toolTip().section(QStringLiteral("\n\n"), 0, 0);
        if (!available && !why.isEmpty())
            tip += QStringLiteral("\n\n") + why;
        widget->setToolTip(tip);
    }
    m_channelNote->setText(why);
    m_channelNote->setVisible(!available && !why.isEmpty());
}

void BrushPanel::setPressureCurve(const core::PressureCurve& curve) {
    const QScopedValueRollback guard(m_updating, true);
    m_curve = curve;
    m_gamma->setValue(gammaToSlider(curve.gamma));
    m_gammaText->setText(tr("γ %1").arg(QLocale().toString(curve.gamma, 'f', 2)));
    m_curveView->setCurve(curve);
}

void BrushPanel::addStabilizerBox(QLayout* layout) {
    m_stabilizer = new StabilizerBox(this);
    layout->addWidget(m_stabilizer);
    connect(m_stabilizer, &StabilizerBox::changed, this, &BrushPanel::readBrush);
}

void BrushPanel::addSymmetryBox(QLayout* layout) {
    m_symmetry = new SymmetryBox(this);
    layout->addWidget(m_symmetry);
    connect(m_symmetry, &SymmetryBox::changed, this, &BrushPanel::readBrush);
}

} // namespace ui
