// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

#include "core/depth/depth_layers.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;

namespace ui {

/**
 * The build_layers options: the depth threshold on a logarithmic slider (1e-5 … 1e-1 unit-cube
 * units, i.e. fractions of the model's longest side), the connection test and two-sided capture.
 * Every change emits optionsChanged() at once; the slider re-segments live.
 */
class SegmentationControls : public QWidget {
    Q_OBJECT

public:
    static constexpr float kMinThreshold = 1e-5f;
    static constexpr float kMaxThreshold = 1e-1f;
    /** Slider steps per factor of ten. */
    static constexpr int kStepsPerDecade = 50;

    explicit SegmentationControls(QWidget* parent = nullptr);

    /** Shows options without emitting optionsChanged(). */
    void setOptions(const core::DepthLayerOptions& options);
    core::DepthLayerOptions options() const { return m_options; }

    static float thresholdAt(int sliderPosition);
    static int sliderPositionFor(float threshold);
    /** The threshold as shown next to the slider: two significant digits, no exponent. */
    static QString formatThreshold(float threshold);

    /** The connectivity engine choice: render::ConnectivityBackend as int (Auto, Cpu, Gpu). */
    void setConnectivityBackend(int backend);
    /** Says which engine Auto resolved to, next to the choice. */
    void setConnectivityInUse(const QString& name);

signals:
    void optionsChanged(const core::DepthLayerOptions& options);
    void connectivityBackendChanged(int backend);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void updateLabels();

    core::DepthLayerOptions m_options;
    QSlider* m_threshold = nullptr;
    QLabel* m_thresholdValue = nullptr;
    QComboBox* m_test = nullptr;
    QCheckBox* m_twoSided = nullptr;
    QComboBox* m_connectivity = nullptr;
    bool m_updating = false;
};

} // namespace ui
