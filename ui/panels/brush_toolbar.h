// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QToolBar>

#include "core/paint/brush/dab.h"
#include "core/paint/targets/paint_target.h"

class QComboBox;
class QSpinBox;
class QToolButton;

namespace ui {

/**
 * A minimal brush bar: colour (a QColorDialog), radius, hardness and opacity, and the paint
 * target (a texture of 512–8192 texels for meshes with UVs, or vertex colours). Every change
 * emits at once; setBrush() and setTarget() show values without emitting.
 */
class BrushToolBar : public QToolBar {
    Q_OBJECT

public:
    explicit BrushToolBar(QWidget* parent = nullptr);

    void setBrush(const core::Brush& brush);
    const core::Brush& brush() const { return m_brush; }
    /**
     * Shows the target options; texture entries are offered only when the mesh has UVs (the
     * tooltips say why they are not).
     */
    void setTarget(const core::PaintTargetOptions& options, bool meshHasUvs);

    /** sRGB QColor ↔ the brush's linear colour. */
    static QColor toQColor(const glm::vec4& linear);
    static glm::vec4 toLinear(const QColor& color);

signals:
    void brushChanged(const core::Brush& brush);
    /** The user chose another paint target (the current painting would be replaced). */
    void targetRequested(const core::PaintTargetOptions& options);

private:
    void chooseColor();
    void updateColorIcon();

    core::Brush m_brush;
    QToolButton* m_color = nullptr;
    QSpinBox* m_radius = nullptr;
    QSpinBox* m_hardness = nullptr;
    QSpinBox* m_opacity = nullptr;
    QComboBox* m_target = nullptr;
    QString m_targetTip; // the target box's tooltip for meshes with UVs
    bool m_updating = false;
};

} // namespace ui
