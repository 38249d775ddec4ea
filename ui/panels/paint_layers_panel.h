// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

#include <QColor>
#include <QWidget>

#include "core/paint/targets/paint_target.h"

class QAction;
class QCheckBox;
class QBoxLayout;
class QComboBox;
class QFormLayout;
class QGridLayout;
class QHBoxLayout;
class QLabel;
class QSlider;
class QDoubleSpinBox;
class QSpinBox;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace core {
class Document;
}

namespace ui {

/**
 * The Paint Layers panel (a dock): the document's paint-layer stack, the uppermost layer on top
 * and the read-only Base at the bottom. Per row an eye (click: show or hide), a thumbnail of the
 * layer's tiles, the name (double-click: rename) and, with a mask, the mask's thumbnail (click:
 * paint the mask; Alt+click: see it alone in the view). Below: opacity, blend mode and lock
 * transparency of the current layer (of a fill layer also its colour, roughness and metallic, each
 * of which can be off), and buttons for every operation (also in the context menu and, through
 * actions(), a menu of the window). Rows are dragged to reorder. Each operation is a call on the
 * document (one undo step); changed() then reports what the composite changed. Selecting a row is
 * no undo step. For a model painted in vertex colours the panel is disabled and says why.
 */
class PaintLayersPanel : public QWidget {
    Q_OBJECT

public:
    explicit PaintLayersPanel(core::Document& document, QWidget* parent = nullptr);

    /** Shows the document's stack as it is now (call after strokes, undo, a new model, ...). */
    void refresh();

    QAction* newLayerAction() const { return m_newLayer; }
    QAction* newFillLayerAction() const { return m_newFill; }
    QAction* duplicateAction() const { return m_duplicate; }
    QAction* deleteAction() const { return m_delete; }
    QAction* mergeDownAction() const { return m_mergeDown; }
    QAction* flattenAction() const { return m_flatten; }
    QAction* addMaskAction() const { return m_addMask; }
    QAction* deleteMaskAction() const { return m_deleteMask; }
    /** Every operation, in menu order (nullptr: a separator). */
    QList<QAction*> operationActions() const;

    /** The list (top row: the uppermost layer; last row: Base), for tests. */
    QTreeWidget* list() const { return m_list; }
    /** The row of the layer with id (0: Base), or nullptr. */
    QTreeWidgetItem* rowOf(std::uint64_t id) const;
    /** Why the panel is disabled (empty while it is enabled). */
    QString disabledReason() const;
    /** The view shows the mask of paint layer id alone (0: the composite), as its row says. */
    void setMaskView(std::uint64_t id);

    /** The list's columns. */
    enum Column { EyeColumn, ThumbnailColumn, NameColumn, MaskColumn };

signals:
    /** An operation changed the document; changes is what the composite changed. */
    void changed(const core::PaintChanges& changes);
    /** Where painting goes changed (no undo step). */
    void selectionChanged();
    /** An operation could not be done: why, for the status bar. */
    void message(const QString& text);
    /** The rows were made again from the document (after any change or selection). */
    void refreshed();
    /** Alt+click on a mask: show it alone (its paint layer's id) or the composite again (0). */
    void maskViewRequested(std::uint64_t id);

private:
    void createActions();
    /** The rows: eye, thumbnail, name and mask of every paint layer, Base last. */
    void createList();
    /** The texture set box above the list (shown for more than one texture set). */
    void createTextureSetRow(QBoxLayout* layout);
    /** Fills the texture set box from the target's pages, keeping the one shown. */
    void updateTextureSets();
    /** The page (texture set) whose paint the thumbnails show. */
    std::uint32_t shownPage() const;
    /** The current layer's settings below the list (m_controls, laid out by m_form). */
    void createSettingsControls();
    void addOpacityRow();
    void addBlendRow();
    void addLockRow();
    /** A fill layer's base colour: on or off, and a swatch that opens a colour dialog. */
    void addFillColorRow();
    /** A fill layer's roughness and metallic, each of which can be off. */
    void addFillChannelRows();
    /** A button for every operation, four to a row. */
    QGridLayout* createOperationButtons();
    /** The target's stack, or nullptr (no model, vertex colours, or no target made yet). */
    const core::PaintLayerTarget* target() const;
    /** The selected layer's id (0: Base). */
    std::uint64_t selectedPaintLayer() const;
    /** Reports an operation's result: changed() when it worked, message() when not. */
    void finish(const core::Status& status, const core::PaintChanges& changes);
    void addLayer(bool fill);
    void select(std::uint64_t id, bool mask);
    void onItemClicked(QTreeWidgetItem* item, int column);
    void onItemChanged(QTreeWidgetItem* item, int column);
    /** Applies a change of the current layer's settings made by edit. */
    template <typename Edit> void editSettings(std::uint64_t id, Edit edit);
    /** A drop put the layer with id at top-down row (of the layer rows). */
    void moveToRow(std::uint64_t id, int row);
    void showContextMenu(const QPoint& position);
    void updateControls();

    core::Document& m_document;
    QLabel* m_reason = nullptr;
    QTreeWidget* m_list = nullptr;
    QWidget* m_textureSetRow = nullptr;
    QComboBox* m_textureSet = nullptr;
    QWidget* m_controls = nullptr;
    QSlider* m_opacity = nullptr;
    QLabel* m_opacityText = nullptr;
    QComboBox* m_blend = nullptr;
    QCheckBox* m_lock = nullptr;
    QFormLayout* m_form = nullptr;
    // A fill layer's values (rows shown only when a fill layer is current).
    QHBoxLayout* m_fillColorRow = nullptr;
    QCheckBox* m_fillColorOn = nullptr;
    QToolButton* m_fillColor = nullptr;
    QColor m_fillColorValue{Qt::white};
    QDoubleSpinBox* m_fillRoughness = nullptr;
    QDoubleSpinBox* m_fillMetallic = nullptr;
    QAction* m_newLayer = nullptr;
    QAction* m_newFill = nullptr;
    QAction* m_duplicate = nullptr;
    QAction* m_delete = nullptr;
    QAction* m_mergeDown = nullptr;
    QAction* m_flatten = nullptr;
    QAction* m_addMask = nullptr;
    QAction* m_deleteMask = nullptr;
    QAction* m_rename = nullptr;
    bool m_updating = false;
    int m_nextNumber = 1;
    std::uint64_t m_maskView = 0;
};

} // namespace ui
