// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/symmetry_box.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QScopedValueRollback>
#include <QSettings>
#include <QSpinBox>

#include <algorithm>

namespace ui {

namespace {

const QString kKey = QStringLiteral("brush/symmetry/");

} // namespace

SymmetryBox::SymmetryBox(QWidget* parent) : QGroupBox(tr("Symmetry"), parent) {
    setObjectName(QStringLiteral("brushPanelSymmetry"));
    setToolTip(tr("Every dab is repeated on the mirrored or turned surface, also where that "
                  "side is hidden or faces away in this view"));
    auto* form = new QFormLayout(this);
    auto* mirrorRow = new QHBoxLayout;
    const QString names[3] = {tr("&X"), tr("Y"), tr("Z")};
    for (int i = 0; i < 3; ++i) {
        m_mirror[i] = new QCheckBox(names[i], this);
        m_mirror[i]->setObjectName(QStringLiteral("brushPanelSymmetryMirror") + QChar('X' + i));
        m_mirror[i]->setToolTip(tr("Mirror across the model's plane across this axis"));
        mirrorRow->addWidget(m_mirror[i]);
    }
    mirrorRow->addStretch(1);
    form->addRow(tr("Mirror"), mirrorRow);
    m_center = new QComboBox(this);
    m_center->setObjectName(QStringLiteral("brushPanelSymmetryCenter"));
    m_center->addItem(tr("Bounding-box centre"));
    m_center->addItem(tr("Origin"));
    m_center->setToolTip(tr("Where the mirror planes and the radial axis pass through"));
    form->addRow(tr("Centre"), m_center);
    m_radial = new QSpinBox(this);
    m_radial->setObjectName(QStringLiteral("brushPanelSymmetryRadial"));
    m_radial->setRange(1, core::BrushSymmetry::kMaxRadial);
    m_radial->setToolTip(tr("Copies turned about the axis, the stroke included; 1 for none"));
    m_axis = new QComboBox(this);
    m_axis->setObjectName(QStringLiteral("brushPanelSymmetryAxis"));
    m_axis->addItems({tr("X axis"), tr("Y axis"), tr("Z axis")});
    auto* radialRow = new QHBoxLayout;
    radialRow->addWidget(m_radial);
    radialRow->addWidget(m_axis, 1);
    form->addRow(tr("Radial"), radialRow);

    const auto edited = [this] {
        if (!m_updating)
            emit changed();
    };
    for (QCheckBox* box : m_mirror)
        connect(box, &QCheckBox::toggled, this, edited);
    connect(m_center, &QComboBox::currentIndexChanged, this, edited);
    connect(m_radial, &QSpinBox::valueChanged, this, edited);
    connect(m_axis, &QComboBox::currentIndexChanged, this, edited);
}

void SymmetryBox::setBrush(const core::Brush& brush) {
    const QScopedValueRollback guard(m_updating, true);
    const core::BrushSymmetry& s = brush.symmetry;
    m_mirror[0]->setChecked(s.mirrorX);
    m_mirror[1]->setChecked(s.mirrorY);
    m_mirror[2]->setChecked(s.mirrorZ);
    m_center->setCurrentIndex(s.center == core::BrushSymmetry::Center::Origin ? 1 : 0);
    m_radial->setValue(s.radial);
    m_axis->setCurrentIndex(std::clamp(s.axis, 0, 2));
}

void SymmetryBox::readInto(core::Brush& brush) const {
    core::BrushSymmetry& s = brush.symmetry;
    s.mirrorX = m_mirror[0]->isChecked();
    s.mirrorY = m_mirror[1]->isChecked();
    s.mirrorZ = m_mirror[2]->isChecked();
    s.center = m_center->currentIndex() == 1 ? core::BrushSymmetry::Center::Origin
                                             : core::BrushSymmetry::Center::BoundingBox;
    s.radial = m_radial->value();
    s.axis = m_axis->currentIndex();
    remember(s);
}

void SymmetryBox::remember(const core::BrushSymmetry& s) {
    QSettings settings;
    settings.setValue(kKey + QStringLiteral("mirror"),
                      QString::fromStdString(core::symmetryMirrorName(s)));
    settings.setValue(kKey + QStringLiteral("center"),
                      QString::fromLatin1(core::symmetryCenterName(s.center)));
    settings.setValue(kKey + QStringLiteral("radial"), s.radial);
    settings.setValue(kKey + QStringLiteral("axis"),
                      QString::fromLatin1(core::symmetryAxisName(s.axis)));
}

void SymmetryBox::restore(core::Brush& brush) {
    const QSettings settings;
    core::BrushSymmetry s;
    // Values the program did not write are ignored: the default (off) stays.
    core::symmetryMirrorFromName(
        settings.value(kKey + QStringLiteral("mirror")).toString().toStdString(), s);
    core::symmetryCenterFromName(
        settings.value(kKey + QStringLiteral("center")).toString().toStdString(), s.center);
    bool ok = false;
    const int radial = settings.value(kKey + QStringLiteral("radial"), 1).toInt(&ok);
    if (ok && radial >= 1 && radial <= core::BrushSymmetry::kMaxRadial)
        s.radial = radial;
    core::symmetryAxisFromName(
        settings.value(kKey + QStringLiteral("axis")).toString().toStdString(), s.axis);
    brush.symmetry = s;
}

} // namespace ui
