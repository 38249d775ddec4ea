// SPDX-License-Identifier: GPL-3.0-or-later
// The Brush panel's tip settings: the tip (built-in or loaded), its angle and the jitter per dab.
#pragma once

#include <QGroupBox>
#include <QThreadPool>

#include <optional>

#include "core/paint/brush/dab.h"

class QComboBox;
class QListWidget;
class QPushButton;
class QSpinBox;

namespace ui {

/**
 * A group box with a tip chooser (previews of the built-in tips and the loaded one, Load Tip…),
 * the angle mode and angle, the jitter of size, opacity, angle and scatter, and the seed. It edits
 * the tip fields of a brush (apply()) and remembers them in the settings.
 */
class BrushTipBox : public QGroupBox {
    Q_OBJECT

public:
    explicit BrushTipBox(QWidget* parent = nullptr);
    ~BrushTipBox() override;

    /** Shows brush's tip settings (without emitting changed()). */
    void show(const core::Brush& brush);
    /**
     * Writes the box's tip settings into brush, and the spacing of a built-in tip just chosen
     * (core::tipCharacter(): choosing a tip sets its spacing, turn and jitter).
     */
    void apply(core::Brush& brush);
    /** Settings remembered from the last session (the built-in tip, angle, jitter, seed). */
    void restore(core::Brush& brush) const;

    /**
     * Loads an image file as the brush's tip in the importer process, off the GUI thread;
     * changed() when it is in, loadFailed() with a message naming the file otherwise.
     */
    void loadTip(const QString& path);

signals:
    void changed();
    void loadFailed(const QString& message);

private:
    void chooseFile();
    void addUserItem();
    void readControls();
    void remember() const;

    QListWidget* m_tips = nullptr;
    QPushButton* m_load = nullptr;
    QComboBox* m_angleMode = nullptr;
    QSpinBox* m_angle = nullptr;
    QSpinBox* m_jitterSize = nullptr;
    QSpinBox* m_jitterOpacity = nullptr;
    QSpinBox* m_jitterAngle = nullptr;
    QSpinBox* m_jitterScatter = nullptr;
    QSpinBox* m_seed = nullptr;
    core::Brush m_tip;                    // the tip fields shown (the rest unused)
    std::optional<float> m_chosenSpacing; // a tip's, chosen since the last apply()
    bool m_updating = false;
    QThreadPool m_pool;
};

} // namespace ui
