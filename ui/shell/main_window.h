// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include <QList>
#include <QMainWindow>
#include <QPointF>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QTimer>

#include "core/document/document.h"
#include "core/io/project/project_file.h"
#include "core/model/mesh.h"
#include "render/depth_compositor.h"
#include "ui/shell/paint_target_job.h"
#include "ui/shell/preferences.h"
#include "ui/shell/recent_files.h"
#include "ui/tools/tool.h"

class QAction;
class QActionGroup;
class QCheckBox;
class QDockWidget;
class QLabel;
class QMenu;
class QProgressDialog;
class QToolBar;
class QToolButton;
class QUndoStack;

namespace ui {

class BrushPanel;
class BrushPresetsPanel;
class BrushToolBar;
class ColorPanel;
class FillPanel;
class HistoryBridge;
class ScriptActions;
class DepthLayersBuilder;
class DepthLayersPanel;
class MessageBar;
class ModelLoader;
struct LoadedModel;
class Notifier;
class PaintLayersPanel;
class PaintTargetJob;
class QuickGuideDialog;
class ProjectController;
class RegionGraphPanel;
class RegionTools;
class SegmentationControls;
class Viewport;

/**
 * The application window: owns the core::Document (model, camera, layers) and shows it in the
 * viewport and the Segmentation, Depth Layers, Region Graph, Paint to Hide, Fill, Brush, Colour
 * and Paint Layers panels (all dockable, the layout kept in QSettings); the
 * File/Edit/View/Paint/Paint Layers/Help menus, the
 * brush and tool bars, the status bar, the Preferences and the background loading of models.
 * Painting: the viewport's left button (or pen) drives the document's strokes and fills; every
 * change is a step of the document's one history, which the undo stack mirrors (HistoryBridge).
 * The brush bar, the Brush and Colour panels and the document's brush are kept in step by
 * setBrush(). The open model only changes when a load succeeds.
 */
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /**
     * Opens a file path (a model or a project) or "builtin:NAME" in the background, after asking
     * to save unsaved changes (ProjectController::maybeSave; nothing happens if the user
     * cancels). On success modelLoaded() follows; on failure loadFailed() and an error dialog,
     * with the current model left as it was.
     */
    void openFile(const QString& source);
    /** What the command line asks for: the first file, or the default model when there is none. */
    void openFromCommandLine(const QStringList& files);
    /**
     * Where build_layers computes connectivity: "auto", "cpu" or "gpu" (the --connectivity
     * option; the Segmentation panel's choice is saved in the settings). False for other names.
     */
    bool setConnectivityBackend(const QString& name, bool remember = false);

    Viewport* viewport() const { return m_viewport; }
    core::Document& document() { return *m_document; }
    const core::Document& document() const { return *m_document; }
    DepthLayersBuilder* depthLayersBuilder() const { return m_builder; }
    DepthLayersPanel* depthLayersPanel() const { return m_depthLayersPanel; }
    RegionGraphPanel* regionGraphPanel() const { return m_graphPanel; }
    RegionTools* regionTools() const { return m_regionTools; }
    SegmentationControls* segmentationControls() const { return m_segmentationControls; }
    BrushToolBar* brushToolBar() const { return m_brushBar; }
    FillPanel* fillPanel() const { return m_fillPanel; }
    BrushPanel* brushPanel() const { return m_brushPanel; }
    ColorPanel* colorPanel() const { return m_colorPanel; }
    PaintLayersPanel* paintLayersPanel() const { return m_paintLayersPanel; }
    BrushPresetsPanel* brushPresetsPanel() const { return m_presetsPanel; }
    /** Help ▸ Quick Guide: opens (or raises) the guide, not modal. */
    void showQuickGuide();
    /** The guide while it is open; nullptr otherwise. */
    QuickGuideDialog* quickGuide() const;
    /** At start (after show()): opens the guide on a first start, or when it asks to be shown. */
    void showQuickGuideAtStart();
    QUndoStack* undoStack() const { return m_undoStack; }
    /** Save, export, unsaved-changes tracking, autosave and recovery. */
    ProjectController* projectController() const { return m_project; }

    /**
     * The project state to save (ProjectController snapshots it): the document's share
     * (core::captureProjectState) and what this window's panels hold. Panels that add state
     * (colours, palette, pop-up settings) fill it in here and read it in applyProjectState().
     */
    core::ProjectState projectState() const;
    /**
     * Shows an opened project's state: document settings (core::applyProjectState) and the
     * widgets that show them. Call right after the document's mesh was set (onLoaded does); what
     * this window does not show yet is kept for the next save.
     */
    void applyProjectState(const core::ProjectState& state);

    /** The brush everywhere: the document's, the brush bar's and the panels'. */
    void setBrush(const core::Brush& brush);
    /** What pen pressure goes through before it reaches a stroke. */
    const core::PressureCurve& pressureCurve() const { return m_document->pressureCurve(); }
    /** The document's history as the GUI shows it. */
    HistoryBridge* history() const { return m_history; }
    /** Run Script and Copy Session as Script. */
    ScriptActions* scriptActions() const { return m_scriptActions; }
    /**
     * Shows what the document holds now in every widget (brush, modes, segmentation, paint
     * target, region order, camera), after something changed it wholesale (a script).
     */
    void showDocumentState();
    /** The preferences in use (Edit ▸ Preferences). */
    const Preferences& preferences() const { return m_preferences; }
    /** Saves preferences to the settings and applies them. */
    void setPreferences(const Preferences& preferences);
    /** Opens the Preferences dialog (window-modal, returns at once). */
    void showPreferences();

    /** The tool of the left button (the Tools toolbar and menu). */
    Tool tool() const { return m_tool; }
    void setTool(Tool tool);
    /** The checkable action that chooses tool (disabled while the tool cannot be used). */
    QAction* toolAction(Tool tool) const { return m_toolActions[std::size_t(tool)]; }

    /** What the last stroke's mouse moves cost on the GUI thread (tracking and painting). */
    struct StrokeStats {
        int moves = 0;
        double totalMs = 0.0;
        double maxMs = 0.0;
        double pressMs = 0.0; // the press, including a layer build it needed
    };
    const StrokeStats& lastStrokeStats() const { return m_strokeStats; }
    bool isPainting() const { return m_painting; }

    /**
     * Shows the layers as display; for SingleLayer, layer (1-based) is the one shown alone, 0
     * keeps the current one.
     */
    void setDisplay(render::DepthLayerDisplay display, std::uint32_t layer = 0);
    /** The open model's source (absolute path or "builtin:NAME"); empty before the first load. */
    QString currentSource() const { return m_source; }
    bool isLoading() const;
    QStringList recentFiles() const { return m_recent.files(); }

    /**
     * Tests turn the modal dialogs off: errors are only reported by signals (loadFailed(), ...)
     * and unsaved changes are discarded without asking.
     */
    void setErrorDialogsEnabled(bool enabled);
    bool errorDialogsEnabled() const;
    /** A warning box (window-modal, not blocking) unless dialogs are off. */
    void showError(const QString& title, const QString& text, const QString& details);

signals:
    void modelLoaded(const QString& source);
    /** message is core's error text; it names the file. */
    void loadFailed(const QString& message);
    /** A region was chosen (a click in the region graph). */
    void regionActivated(std::uint32_t region);
    void toolChanged(ui::Tool tool);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    // Shared by the files the window's code is split into.
    static constexpr int kStatusMessageMs = 10000;
    static constexpr int kPaintMessageMs = 3000;
    static constexpr int kProgressSteps = 1000;

    // The constructor's steps, in order (main_window.cpp).
    /** The last session's segmentation options, from the settings, to the document. */
    void restoreDepthLayerOptions();
    /** The preferences as they were saved: pressure curve and texture size for the document. */
    void applyStartPreferences();
    /** The viewport (the central widget), its message bar, the builder and the loaders. */
    void createView();
    /** The status bar's model, depth-layer and brush labels. */
    void createStatusBarLabels();
    /** Save, export, autosave and recovery, and what they change in the window. */
    void createProjectController();
    void connectLoader();
    /** What the viewport reports: GL errors, failed layer rendering, a changed view. */
    void connectViewport();
    /** A build of the depth layers (or of their segmentation) is shown, cleared or failed. */
    void connectDepthLayersBuilder();
    /** The status bar's progress of the symmetric views, polled while they build. */
    void createSymmetryProgress();
    /** The load progress dialog's value, polled from the loader. */
    void createLoadProgress();
    /** The window's size and dock layout of the last session (or the first start's size). */
    void restoreWindowLayout();

    void createPanels();
    /**
     * The first start's dock layout (for 1280 × 800 and larger): settings panels as tabs at the
     * top right, the stacks (Paint Layers in front) below with the rest of the height.
     */
    void arrangeDefaultDocks();
    /** A dock (on the right by default) named for saveState(). */
    QDockWidget* makeDock(const QString& title, const QString& name, QWidget* content,
                          Qt::DockWidgetArea area = Qt::RightDockWidgetArea);
    /** The menu bar: File, Edit, View, Paint, Paint Layers and Help, in that order. */
    void createMenus();
    void createFileMenu();
    void createEditMenu();
    void createViewMenu();
    void createPaintMenu();
    /** The Paint Layers panel's operations. */
    void createPaintLayersMenu();
    void createHelpMenu();
    void createDisplayActions(QMenu* viewMenu);
    /** View ▸ Channel: the material or one of its channels, remembered in the settings. */
    void createChannelActions(QMenu* viewMenu);
    /**
     * What painting needs: the history, the region tools, the brush bar, the Brush, Colour,
     * Brush Presets and Paint Layers panels, and the painting actions with their keys
     * (main_window_actions.cpp, in this order).
     */
    void createPaintActions();
    /** The document's history and the undo stack that mirrors it. */
    void createHistory();
    /** Paint to Hide and pop-up (RegionTools), with the Paint to Hide and Fill docks. */
    void createRegionTools();
    void createBrushBar();
    /** The Brush and Colour panels, docked on the left. */
    void createBrushAndColorPanels();
    /** The brush takes the Colour panel's colour (rounded to what it shows). */
    void matchBrushToColorPanel();
    /** Paint ▸ Layer-Aware Painting (L), and its check box on the brush bar. */
    void createLayerAwareAction();
    /** [ ] Shift+[ Shift+] for the brush's radius and hardness, and X to swap the colours. */
    void createBrushKeyActions();
    /** View ▸ Show Brush Maps. */
    void createBrushMapsAction();
    /** Edit ▸ Undo and Redo, named after the step they undo or redo. */
    void createUndoActions();
    void createToolActions();
    void onPaintPressed(QPointF pixel, qreal pressure, Qt::KeyboardModifiers modifiers);
    /**
     * Before a stroke or fill: the layers of this view (built now if missing) and a paint target
     * (made now if there is none); false, with a message, where either cannot be had.
     */
    bool preparePainting();
    /** Brush and eraser: starts a stroke (builds the layers first if they are missing). */
    void beginPaintStroke(QPointF pixel, qreal pressure, bool eraser);
    /**
     * A stroke went to a fill layer, which takes none: offers what was likely meant, painting its
     * mask or a paint layer above it.
     */
    void offerPaintableTarget();
    /** Shift+click with the brush or eraser: a straight line on from the last stroke. */
    void paintLine(QPointF pixel, qreal pressure, bool eraser);
    /** Paint ▸ Stroke Stabilizer: the brush's stabilizer on or off. */
    QAction* createStabilizerAction();
    /** Paint ▸ Symmetry, and the same menu on the brush bar's Symmetry button. */
    QMenu* createSymmetryMenu();
    /** Shows brush's symmetry in the Symmetry menu and on its button. */
    void showSymmetry(const core::BrushSymmetry& symmetry);
    /** The Fill tool: one flood fill at pixel with the Fill panel's options, one undo step. */
    void fillAt(QPointF pixel);
    /** The eyedropper: the brush takes the surface colour under pixel. */
    void pickColor(QPointF pixel);
    void onPaintMoved(QPointF pixel, qreal pressure);
    void onPaintReleased(QPointF pixel);
    /** Ends a stroke in progress and puts it on the undo stack. */
    void finishStroke();
    /** Undo/redo changed the document: show its paint, target and order. */
    void onHistoryApplied(const core::PaintChanges& changes);
    void setPaintTarget(const core::PaintTargetOptions& options);
    /**
     * Paint ▸ Raise Texture Size…: asks for a material and a larger size, then raises the size
     * of the texture it is painted into (Document::raiseTextureSize(), one undoable step).
     */
    void raiseTextureSize();
    /** The target made off the GUI thread (an automatic UV layout) is ready, or failed. */
    void paintTargetMade(const std::shared_ptr<PaintTargetJob::Outcome>& outcome);
    /**
     * For a model without UVs: the note over the view with the choice of target (a texture with
     * an automatic UV layout, or vertex colours), and the default (Document's rule) started.
     */
    void offerUvLayout();
    /** The brush bar's target, and what the Brush and Paint Layers panels can offer for it. */
    void updateBrushBar();
    /** The Brush Presets panel, the tool hint in the status bar and Help ▸ Quick Guide. */
    void createHelpAndPresets();
    /** The Paint Layers panel, its dock and what its operations change. */
    void createPaintLayersPanel();
    void updateBrushInfo();
    /** The status bar's note of what strokes paint: a paint layer, or its mask. */
    void updatePaintIntoInfo();
    /**
     * The view shows the document's paint target from now on (one made, replaced or restored);
     * remembered, so that an undo afterwards does not show it (upload the mesh) again.
     */
    void showPaintTarget();
    /** [ and ]: the radius a step (about 15 %) smaller or larger. */
    void stepBrushRadius(int direction);
    /** Shift+[ and Shift+]: the hardness 10 % down or up. */
    void stepBrushHardness(int direction);
    void setPressureCurve(const core::PressureCurve& curve);
    void setDepthLayerOptions(const core::DepthLayerOptions& options);
    void onDepthLayersBuilt();
    void onSegmentationChanged();
    void onDepthLayersCleared();
    void updateDepthLayerInfo();
    void updateRecentMenu();
    void showOpenDialog();
    void showAbout();
    void createProjectActions(QMenu* fileMenu);
    void updateWindowTitle();

    void onLoaded(const QString& source, std::shared_ptr<LoadedModel> model);
    /** The paint options a newly opened model starts with (the preferred texture size). */
    core::PaintTargetOptions newModelPaintOptions() const;
    void onLoadFailed(const QString& source, const QString& message);
    void onLoadCancelled(const QString& source);
    void startProgress(const QString& source);
    void stopProgress();
    /**
     * The status bar's model line and the notes over the view (warnings, note, no UVs).
     * plainModel: a model file, not a project (which keeps its own paint target).
     */
    void updateModelInfo(const core::Mesh& mesh, const QString& note = {}, bool plainModel = true);

    // ~MainWindow deletes the widgets that refer to it before it goes.
    std::unique_ptr<core::Document> m_document;
    Viewport* m_viewport = nullptr;
    /** Notes about the open model over the top of the viewport (load warnings, ...). */
    MessageBar* m_messageBar = nullptr;
    DepthLayersBuilder* m_builder = nullptr;
    ModelLoader* m_loader = nullptr;
    PaintTargetJob* m_targetJob = nullptr;
    SegmentationControls* m_segmentationControls = nullptr;
    DepthLayersPanel* m_depthLayersPanel = nullptr;
    RegionGraphPanel* m_graphPanel = nullptr;
    QDockWidget* m_segmentationDock = nullptr;
    QDockWidget* m_depthLayersDock = nullptr;
    QDockWidget* m_graphDock = nullptr;
    QDockWidget* m_hiddenDock = nullptr;
    RegionTools* m_regionTools = nullptr;
    /** What leaving the hide tool (which shows the segmentation map) shows again. */
    render::DepthLayerDisplay m_displayBeforeHide = render::DepthLayerDisplay::Composite;
    FillPanel* m_fillPanel = nullptr;
    QDockWidget* m_fillDock = nullptr;
    BrushPanel* m_brushPanel = nullptr;
    ColorPanel* m_colorPanel = nullptr;
    QDockWidget* m_brushDock = nullptr;
    QDockWidget* m_colorDock = nullptr;
    PaintLayersPanel* m_paintLayersPanel = nullptr;
    QDockWidget* m_paintLayersDock = nullptr;
    QActionGroup* m_displayGroup = nullptr;
    QAction* m_shadedAction = nullptr;
    QAction* m_singleLayerAction = nullptr;
    QAction* m_segmentationAction = nullptr;
    QAction* m_boundariesAction = nullptr;
    /** What "All depth layers" returns to: Composite or Segmentation. */
    render::DepthLayerDisplay m_allLayersDisplay = render::DepthLayerDisplay::Composite;
    QLabel* m_depthLayerInfo = nullptr;
    QLabel* m_brushInfo = nullptr;
    QLabel* m_paintIntoInfo = nullptr;

    BrushToolBar* m_brushBar = nullptr;
    QToolBar* m_toolBar = nullptr;
    QActionGroup* m_toolGroup = nullptr;
    std::array<QAction*, 6> m_toolActions{};
    Tool m_tool = Tool::Brush;
    QAction* m_layerAwareAction = nullptr;
    QCheckBox* m_layerAwareCheck = nullptr;
    QAction* m_swapColorsAction = nullptr;
    QAction* m_stabilizerAction = nullptr;
    std::array<QAction*, 3> m_mirrorActions{}; // Paint ▸ Symmetry ▸ Mirror X, Y, Z
    QToolButton* m_symmetryButton = nullptr;
    QAction* m_preferencesAction = nullptr;
    QList<QAction*> m_brushStepActions; // [ ] Shift+[ Shift+]
    QAction* m_brushMapsAction = nullptr;
    QAction* m_undoAction = nullptr;
    QAction* m_redoAction = nullptr;
    QUndoStack* m_undoStack = nullptr;
    /** The document's history as the undo stack shows it. */
    HistoryBridge* m_history = nullptr;
    ScriptActions* m_scriptActions = nullptr;
    std::uint64_t m_targetSerial = 0; // the document's paint target the view shows
    bool m_painting = false;
    bool m_picking = false;      // the eyedropper is held down
    float m_lastPressure = 1.0f; // of the stroke's last sample, for its end
    StrokeStats m_strokeStats;
    core::PaintTargetOptions m_paintOptions;
    Preferences m_preferences;

    RecentFiles m_recent;
    QMenu* m_recentMenu = nullptr;
    QAction* m_orthographicAction = nullptr;
    QLabel* m_modelInfo = nullptr;
    QPointer<QProgressDialog> m_progress;
    QTimer m_progressTimer;
    QString m_source;
    /** Status messages and warning boxes, for this window and its controllers. */
    Notifier* m_notifier = nullptr;

    ProjectController* m_project = nullptr;
    /** The state last opened: keeps what no panel of this window shows yet (projectState()). */
    core::ProjectState m_projectBase;
    QMenu* m_exportMenu = nullptr;

    BrushPresetsPanel* m_presetsPanel = nullptr;
    QDockWidget* m_presetsDock = nullptr;
    QLabel* m_toolHint = nullptr;
    QAction* m_quickGuideAction = nullptr;
    QPointer<QuickGuideDialog> m_guide;
};

} // namespace ui
