// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QString>

#include "ui/view/viewport.h"

class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace ui {

/**
 * The settings of Edit ▸ Preferences, kept in QSettings under the keys below (other parts read
 * some of them directly: the translation loader "ui/language", autosave
 * "autosave/intervalMinutes").
 */
struct Preferences {
    static const QString kUndoBudgetKey;      // int MiB
    static const QString kTextureSizeKey;     // int texels, a new texture's size
    static const QString kPressureGammaKey;   // double, core::PressureCurve::gamma
    static const QString kCameraMappingKey;   // "both", "blender" or "alt"
    static const QString kLanguageKey;        // "", "en", "de", "zh_CN"
    static const QString kAutosaveMinutesKey; // int, 0 = off

    static constexpr int kMinUndoBudgetMiB = 16;
    static constexpr int kMaxUndoBudgetMiB = 65536;
    static constexpr int kMaxAutosaveMinutes = 120;

    int undoBudgetMiB = 512; // strokes are tiles of 64² texels: hundreds fit
    int textureSize = 2048;
    float pressureGamma = 1.0f;
    CameraMapping cameraMapping = CameraMapping::Both;
    QString language; // empty: the system's
    int autosaveMinutes = 5;

    /** Reads the settings; a missing or out-of-range value gives the default. */
    static Preferences load();
    void save() const;
    bool operator==(const Preferences&) const = default;
};

/** Edit ▸ Preferences: edits a Preferences; the caller saves and applies the result. */
class PreferencesDialog : public QDialog {
    Q_OBJECT

public:
    explicit PreferencesDialog(const Preferences& preferences, QWidget* parent = nullptr);

    /** The values as edited. */
    Preferences preferences() const;

private:
    QSpinBox* m_undoBudget = nullptr;
    QComboBox* m_textureSize = nullptr;
    QDoubleSpinBox* m_pressureGamma = nullptr;
    QComboBox* m_cameraMapping = nullptr;
    QComboBox* m_language = nullptr;
    QSpinBox* m_autosave = nullptr;
};

} // namespace ui
