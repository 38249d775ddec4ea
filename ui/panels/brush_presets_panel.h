// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <vector>

#include <QImage>
#include <QSize>
#include <QString>
#include <QWidget>

#include "core/document/brush_preset.h"

class QListWidget;
class QListWidgetItem;
class QPushButton;

namespace ui {

/**
 * The Brush Presets panel: a grid of presets, each shown as a stroke painted with it
 * (core::renderBrushPreview) and its name. A click chooses one (presetChosen()); New from
 * Current, Rename (or double-click, F2), Delete, Import… and Export… are buttons and the context
 * menu. The presets are kept in the settings (the group brushPresets); a first start gets the
 * starter set. A preset file (.lpbrush) is core::brushPresetToJson(); a bad one is one error naming
 * the file.
 */
class BrushPresetsPanel : public QWidget {
    Q_OBJECT

public:
    /** current gives the brush New from Current saves. */
    explicit BrushPresetsPanel(std::function<core::Brush()> current, QWidget* parent = nullptr);

    const std::vector<core::BrushPreset>& presets() const { return m_presets; }
    QListWidget* list() const { return m_list; }
    /** The preview shown for brush. */
    static QImage preview(const core::Brush& brush, QSize size);

    /** Saves the current brush as a new preset named name (selected); false for an empty name. */
    bool addFromCurrent(const QString& name);
    bool renamePreset(int row, const QString& name);
    bool deletePreset(int row);
    /** Adds the preset in the file at path; on failure errorOccurred() with "FILE: problem". */
    bool importFile(const QString& path);
    /** Writes the preset at row to path (atomically); on failure errorOccurred(). */
    bool exportFile(int row, const QString& path);
    /** Chooses the preset at row: presetChosen(). */
    void choose(int row);

signals:
    void presetChosen(const core::Brush& brush, const QString& name);
    void errorOccurred(const QString& message);

private:
    void load();
    void save() const;
    void rebuild(int selectRow);
    int currentRow() const;
    void askNewFromCurrent();
    void askImport();
    void askExport();
    void updateButtons();

    std::function<core::Brush()> m_current;
    std::vector<core::BrushPreset> m_presets;
    QListWidget* m_list = nullptr;
    QPushButton* m_newButton = nullptr;
    QPushButton* m_renameButton = nullptr;
    QPushButton* m_deleteButton = nullptr;
    QPushButton* m_importButton = nullptr;
    QPushButton* m_exportButton = nullptr;
    bool m_rebuilding = false;
};

} // namespace ui
