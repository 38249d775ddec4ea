// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>
#include <QString>

#include <memory>
#include <vector>

#include "core/io/texture_sets/texture_set_export.h"

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QSpinBox;

namespace ui {

/**
 * File ▸ Export Textures…: a preset (built-in or a preset file), the folder, the file format, bit
 * depth, normal convention, padding and size, with the list of files it will write. The choices
 * are remembered in QSettings under "textureExport/".
 */
class TextureExportDialog : public QDialog {
    Q_OBJECT

public:
    /** mesh: the painted mesh (its texture sets name the files); meshName is $mesh. */
    TextureExportDialog(std::shared_ptr<const core::Mesh> mesh, const QString& meshName,
                        const QString& folder, QWidget* parent = nullptr);

    /** The options as chosen (the preset with the dialog's format, padding, ... in it). */
    core::TextureExportOptions options() const;
    QString folder() const;
    /** The file names the export writes, as listed. */
    QStringList fileNames() const;
    /** Adds a preset file's preset to the list and chooses it; false (and why) if it is bad. */
    bool addPresetFile(const QString& path, QString* error = nullptr);
    /** Remembers the choices for the next time (called when the export starts). */
    void saveSettings() const;

private:
    void buildPresetRow();
    void buildFormatRows();
    void choosePreset(int index);
    void updateBitDepths();
    void updateFiles();
    void browseFolder();
    void loadPresetFile();
    void restoreSettings();

    std::shared_ptr<const core::Mesh> m_mesh;
    QString m_meshName;
    std::vector<core::ExportPreset> m_presets;
    QStringList m_presetFiles; // per preset: its file, or empty for a built-in one
    QComboBox* m_preset = nullptr;
    QLineEdit* m_folder = nullptr;
    QComboBox* m_format = nullptr;
    QComboBox* m_bitDepth = nullptr;
    QComboBox* m_normal = nullptr;
    QSpinBox* m_padding = nullptr;
    QCheckBox* m_fill = nullptr;
    QComboBox* m_size = nullptr;
    QListWidget* m_files = nullptr;
    QLabel* m_problem = nullptr;
    QDialogButtonBox* m_buttons = nullptr;
};

} // namespace ui
