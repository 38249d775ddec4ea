// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QToolBar>

#include <vector>

#include "core/paint/brush/dab.h"
#include "core/paint/targets/paint_target.h"

class QComboBox;
class QSpinBox;
class QToolButton;

namespace ui {

/**
 * A minimal brush bar: colour (a QColorDialog), radius, hardness and opacity, and the paint
 * target: a texture (named by the sizes its materials paint at: a base colour texture's own, or
 * 512–8192 texels for the others), a texture over an automatic UV layout, or vertex colours.
 * Every change emits at once; setBrush() and setTarget() show values without emitting.
 */
class BrushToolBar : public QToolBar {
    Q_OBJECT

public:
    explicit BrushToolBar(QWidget* parent = nullptr);

    void setBrush(const core::Brush& brush);
    const core::Brush& brush() const { return m_brush; }
    /**
     * Shows the target options for mesh (nullptr: no model yet): its textures with their real
     * sizes, per material in the tooltips; textures over an automatic UV layout (the only ones
     * for a mesh without UVs, which the tooltip says); vertex colours. current: per material,
     * the size of the texture target in use (raised since it was made), or empty.
     */
    void setTarget(const core::PaintTargetOptions& options, const core::Mesh* mesh,
                   const std::vector<core::PageSize>& current = {});

    /** sRGB QColor ↔ the brush's linear colour. */
    static QColor toQColor(const glm::vec4& linear);
    static glm::vec4 toLinear(const QColor& color);

signals:
    void brushChanged(const core::Brush& brush);
    /** The user chose another paint target (the current painting would be replaced). */
    void targetRequested(const core::PaintTargetOptions& options);

private:
    struct TargetItem;
    std::vector<TargetItem> targetItems(const core::PaintTargetOptions& options,
                                        const core::Mesh* mesh) const;
    /** The entry of the texture in use named with current, the sizes it has now. */
    void showCurrentSizes(std::vector<TargetItem>& items, const core::PaintTargetOptions& options,
                          const core::Mesh& mesh, const std::vector<core::PageSize>& current) const;
    /** "256 × 256", or the smallest and the largest: "256 × 256 – 2048 × 2048". */
    QString sizesText(const std::vector<core::PageSize>& sizes) const;
    /** Per material: its name and the size it paints at (its own texture or a new one). */
    QString sizesTip(const std::vector<core::PageSize>& sizes, const core::Mesh& mesh,
                     bool automatic) const;
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
