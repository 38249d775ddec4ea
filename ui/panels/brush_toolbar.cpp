// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/brush_toolbar.h"

#include "core/base/color.h"
#include "ui/panels/value_spin_box.h"

#include <QColorDialog>
#include <QComboBox>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QScopedValueRollback>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QToolButton>

#include <cmath>

namespace ui {

namespace {
constexpr int kResolutions[] = {512, 1024, 2048, 4096, 8192};
constexpr int kVertexColorsItem = -1; // the combo's data for vertex colours
} // namespace

BrushToolBar::BrushToolBar(QWidget* parent) : QToolBar(parent) {
    // Named apart from the Brush panel (View ▸ Panels lists both).
    setWindowTitle(tr("Brush Bar"));
    setObjectName(QStringLiteral("brushToolBar"));

    m_color = new QToolButton(this);
    m_color->setObjectName(QStringLiteral("brushColor"));
    m_color->setToolTip(tr("Brush colour"));
    connect(m_color, &QToolButton::clicked, this, &BrushToolBar::chooseColor);
    addWidget(m_color);

    const auto addSpin = [this](const QString& label, const QString& name, int minimum, int maximum,
                                const QString& suffix, const QString& tip) {
        auto* text = new QLabel(label, this);
        text->setContentsMargins(6, 0, 2, 0);
        addWidget(text);
        QSpinBox* spin = makeValueSpinBox(this, name, minimum, maximum, suffix, tip);
        text->setBuddy(spin);
        addWidget(spin);
        return spin;
    };
    m_radius = addSpin(tr("&Radius"), QStringLiteral("brushRadius"), 1, 500, tr(" px"),
                       tr("Brush radius on screen ([ smaller, ] larger)"));
    m_hardness =
        addSpin(tr("&Hardness"), QStringLiteral("brushHardness"), 0, 100, tr(" %"),
                tr("0: soft falloff from the centre, 100: a hard edge (Shift+[ softer, Shift+] "
                   "harder)"));
    m_opacity = addSpin(tr("O&pacity"), QStringLiteral("brushOpacity"), 1, 100, tr(" %"),
                        tr("The most one stroke covers"));
    const auto changed = [this] {
        if (m_updating)
            return;
        m_brush.radius = float(m_radius->value());
        m_brush.hardness = float(m_hardness->value()) / 100.0f;
        m_brush.opacity = float(m_opacity->value()) / 100.0f;
        emit brushChanged(m_brush);
    };
    for (QSpinBox* spin : {m_radius, m_hardness, m_opacity})
        connect(spin, &QSpinBox::valueChanged, this, changed);

    addSeparator();
    auto* targetLabel = new QLabel(tr("Paint &into"), this);
    targetLabel->setContentsMargins(2, 0, 2, 0);
    addWidget(targetLabel);
    m_target = new QComboBox(this);
    m_target->setObjectName(QStringLiteral("paintTarget"));
    m_targetTip = tr("Where paint goes: a texture (meshes with UVs) or vertex colours. "
                     "Changing it starts the painting afresh.");
    m_target->setToolTip(m_targetTip);
    for (int resolution : kResolutions)
        m_target->addItem(tr("Texture %1 × %1").arg(resolution), resolution);
    m_target->addItem(tr("Vertex colours"), kVertexColorsItem);
    targetLabel->setBuddy(m_target);
    addWidget(m_target);
    connect(m_target, &QComboBox::activated, this, [this](int index) {
        if (m_updating)
            return;
        core::PaintTargetOptions options;
        const int choice = m_target->itemData(index).toInt();
        if (choice == kVertexColorsItem) {
            options.kind = core::PaintTargetKind::VertexColors;
        } else {
            options.kind = core::PaintTargetKind::Texture;
            options.resolution = choice;
        }
        emit targetRequested(options);
    });

    setBrush(m_brush);
}

void BrushToolBar::setBrush(const core::Brush& brush) {
    const QScopedValueRollback guard(m_updating, true);
    m_brush = brush;
    m_radius->setValue(int(std::lround(brush.radius)));
    m_hardness->setValue(int(std::lround(brush.hardness * 100.0f)));
    m_opacity->setValue(int(std::lround(brush.opacity * 100.0f)));
    updateColorIcon();
}

void BrushToolBar::setTarget(const core::PaintTargetOptions& options, bool meshHasUvs) {
    const QScopedValueRollback guard(m_updating, true);
    const bool texture = meshHasUvs && options.kind != core::PaintTargetKind::VertexColors;
    const QString why = tr("This model has no texture coordinates (UVs), so there is no texture "
                           "to paint into: it is painted with vertex colours.");
    m_target->setToolTip(meshHasUvs ? m_targetTip : m_targetTip + QStringLiteral("\n\n") + why);
    int current = m_target->count() - 1;
    for (int i = 0; i + 1 < m_target->count(); ++i) {
        // Disabled items of a QComboBox stay visible but cannot be chosen.
        auto* model = qobject_cast<QStandardItemModel*>(m_target->model());
        if (model) {
            model->item(i)->setEnabled(meshHasUvs);
            model->item(i)->setToolTip(meshHasUvs ? QString() : why);
        }
        if (texture && m_target->itemData(i).toInt() == options.resolution)
            current = i;
    }
    m_target->setCurrentIndex(current);
}

QColor BrushToolBar::toQColor(const glm::vec4& linear) {
    return QColor::fromRgb(core::linearToSrgb(linear.r), core::linearToSrgb(linear.g),
                           core::linearToSrgb(linear.b));
}

glm::vec4 BrushToolBar::toLinear(const QColor& color) {
    const QColor rgb = color.toRgb();
    return {core::srgbToLinear(std::uint8_t(rgb.red())),
            core::srgbToLinear(std::uint8_t(rgb.green())),
            core::srgbToLinear(std::uint8_t(rgb.blue())), 1.0f};
}

void BrushToolBar::chooseColor() {
    const QColor color = QColorDialog::getColor(toQColor(m_brush.color), this, tr("Brush Colour"));
    if (!color.isValid())
        return;
    m_brush.color = toLinear(color);
    updateColorIcon();
    emit brushChanged(m_brush);
}

void BrushToolBar::updateColorIcon() {
    QPixmap swatch(20, 20);
    swatch.fill(Qt::transparent);
    QPainter painter(&swatch);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(palette().color(QPalette::WindowText), 1.0));
    painter.setBrush(toQColor(m_brush.color));
    painter.drawRoundedRect(QRectF(1.5, 1.5, 17, 17), 3, 3);
    painter.end();
    m_color->setIcon(QIcon(swatch));
}

} // namespace ui
