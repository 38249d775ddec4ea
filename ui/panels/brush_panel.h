// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

#include "core/paint/brush/dab.h"

class QCheckBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QSlider;
class QSpinBox;
class QVBoxLayout;

namespace ui {

class BrushTipBox;
class StabilizerBox;
class SymmetryBox;

/** A small plot of a pressure curve: pen pressure to the right, stroke pressure up. */
class PressureCurveView : public QWidget {
    Q_OBJECT

public:
    explicit PressureCurveView(QWidget* parent = nullptr);
    void setCurve(const core::PressureCurve& curve);
    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    core::PressureCurve m_curve;
};

/**
 * The Brush panel (a dock): every setting of core::Brush — radius, hardness, opacity, flow,
 * spacing, R_max (0 = automatic), what pen pressure changes, the material channels it paints
 * (base colour, roughness, metallic, each on or off with its value), the stroke stabilizer — and
 * the pressure curve. Every
 * change emits at once; setBrush() and setPressureCurve() show values without emitting, so the
 * window can keep this panel, the brush bar and the document in step.
 */
class BrushPanel : public QWidget {
    Q_OBJECT

public:
    explicit BrushPanel(QWidget* parent = nullptr);

    void setBrush(const core::Brush& brush);
    const core::Brush& brush() const { return m_brush; }
    void setPressureCurve(const core::PressureCurve& curve);
    const core::PressureCurve& pressureCurve() const { return m_curve; }
    /**
     * Whether roughness and metallic can be painted (texture targets); without, they are shown
     * disabled with why as their tip.
     */
    void setMaterialChannels(bool available, const QString& why = {});
    /** The tip settings (the brush's tip, its angle and jitter). */
    BrushTipBox* tipBox() const { return m_tipBox; }
    SymmetryBox* symmetryBox() const { return m_symmetry; }

signals:
    void brushChanged(const core::Brush& brush);
    void pressureCurveChanged(const core::PressureCurve& curve);

private:
    QSpinBox* addRow(const QString& label, const QString& name, int minimum, int maximum,
                     const QString& suffix, const QString& tip);
    /** Radius, hardness, opacity, flow, spacing and the tracking radius R_max. */
    void addSizeRows();
    /** What pen pressure changes: size, opacity. */
    void addPressureRows();
    /** The material channels a stroke paints, each on or off with its value. */
    void addChannelRows();
    /** The pressure curve's slider, its gamma and a plot of it. */
    void addPressureCurveRow();
    void readBrush();
    void updateAutoTrackText();
    /** The stroke stabilizer's group box, below the other settings. */
    void addStabilizerBox(QLayout* layout);
    void addSymmetryBox(QLayout* layout);
    void addTipBox(QVBoxLayout* layout);

    core::Brush m_brush;
    core::PressureCurve m_curve;
    QFormLayout* m_form = nullptr;
    QSpinBox* m_radius = nullptr;
    QSpinBox* m_hardness = nullptr;
    QSpinBox* m_opacity = nullptr;
    QSpinBox* m_flow = nullptr;
    QSpinBox* m_spacing = nullptr;
    QSpinBox* m_trackRadius = nullptr;
    QCheckBox* m_pressureRadius = nullptr;
    QCheckBox* m_pressureOpacity = nullptr;
    QCheckBox* m_paintBaseColor = nullptr;
    QCheckBox* m_paintRoughness = nullptr;
    QCheckBox* m_paintMetallic = nullptr;
    QDoubleSpinBox* m_roughness = nullptr;
    QDoubleSpinBox* m_metallic = nullptr;
    QLabel* m_channelNote = nullptr;
    QSlider* m_gamma = nullptr;
    QLabel* m_gammaText = nullptr;
    PressureCurveView* m_curveView = nullptr;
    BrushTipBox* m_tipBox = nullptr;
    bool m_updating = false;
    StabilizerBox* m_stabilizer = nullptr;
    SymmetryBox* m_symmetry = nullptr;
};

} // namespace ui
