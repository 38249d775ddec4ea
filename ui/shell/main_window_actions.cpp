// SPDX-License-Identifier: GPL-3.0-or-later
// The main window's actions and menus: painting and tool actions with their keys, the menu bar,
// recent files, the open dialog, About, and the project actions of the File menu.
#include "ui/shell/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCheckBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>

#include "core/model/builtin_models.h"
#include "ui/commands/history_bridge.h"
#include "ui/panels/brush_panel.h"
#include "ui/panels/brush_tip_box.h"
#include "ui/panels/brush_toolbar.h"
#include "ui/panels/color_panel.h"
#include "ui/panels/fill_panel.h"
#include "ui/panels/hidden_regions_panel.h"
#include "ui/panels/paint_layers_panel.h"
#include "ui/panels/symmetry_box.h"
#include "ui/shell/notifier.h"
#include "ui/shell/project_controller.h"
#include "ui/shell/script_actions.h"
#include "ui/shell/source_names.h"
#include "ui/tools/region_tools.h"
#include "ui/tools/tool_cursors.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace ui {

namespace {
const QString kOpenDirectoryKey = QStringLiteral("mainWindow/openDirectory");

/**
 * A dock's scroll area with a minimum size of its own (the panel's width, a few rows high): what
 * the panel shows later (a model, more rows) never changes the window's minimum size.
 */
void fixScrollMinimum(QScrollArea& scroll) {
    scroll.setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll.setMinimumSize(scroll.widget()->minimumSizeHint().width() +
                              scroll.verticalScrollBar()->sizeHint().width(),
                          120);
}
} // namespace

void MainWindow::createPaintActions() {
    createHistory();
    createRegionTools();
    createBrushBar();
    createBrushAndColorPanels();
    createHelpAndPresets();
    createPaintLayersPanel();
    matchBrushToColorPanel();
    createLayerAwareAction();
    createBrushKeyActions();
    createBrushMapsAction();
    createUndoActions();
    // The view's left button (or pen) paints.
    connect(m_viewport, &Viewport::paintPressed, this, &MainWindow::onPaintPressed);
    connect(m_viewport, &Viewport::paintMoved, this, &MainWindow::onPaintMoved);
    connect(m_viewport, &Viewport::paintReleased, this, &MainWindow::onPaintReleased);
    updateBrushBar();
}

void MainWindow::createHistory() {
    m_history = new HistoryBridge(*m_document, this);
    m_undoStack = m_history->stack();
    m_document->history().setBudget(std::size_t(m_preferences.undoBudgetMiB) << 20);
    connect(m_history, &HistoryBridge::applied, this, &MainWindow::onHistoryApplied);
}

void MainWindow::createRegionTools() {
    m_regionTools = new RegionTools(
        *m_document, *m_viewport, [this] { return m_builder->buildNow(); }, this);
    connect(m_regionTools, &RegionTools::message, this,
            [this](const QString& text) { statusBar()->showMessage(text, kPaintMessageMs); });
    m_hiddenDock = makeDock(tr("Paint to Hide"), QStringLiteral("hiddenRegionsDock"),
                            m_regionTools->createPanel(this));
    m_fillPanel = new FillPanel(this);
    m_fillDock = makeDock(tr("Fill"), QStringLiteral("fillDock"), m_fillPanel);
    // Fill's options and the hidden regions come to the front with their tools.
    connect(this, &MainWindow::toolChanged, this, [this](Tool tool) {
        QDockWidget* dock = tool == Tool::Fill   ? m_fillDock
                            : tool == Tool::Hide ? m_hiddenDock
                                                 : nullptr;
        if (dock != nullptr) {
            dock->show();
            dock->raise();
        }
    });
}

void MainWindow::createBrushBar() {
    m_brushBar = new BrushToolBar(this);
    addToolBar(Qt::TopToolBarArea, m_brushBar);
    connect(m_brushBar, &BrushToolBar::brushChanged, this, &MainWindow::setBrush);
    connect(m_brushBar, &BrushToolBar::targetRequested, this, &MainWindow::setPaintTarget);
}

void MainWindow::createBrushAndColorPanels() {
    // The panels: the full brush settings and the colours, on the left of the view.
    m_brushPanel = new BrushPanel(this);
    m_brushPanel->setPressureCurve(m_document->pressureCurve());
    m_brushPanel->tipBox()->restore(m_document->brush()); // the tip settings of the last session
    SymmetryBox::restore(m_document->brush());
    // Scrolled where the window is too low for all its rows (the channels made it taller).
    auto* brushScroll = new QScrollArea(this);
    brushScroll->setWidget(m_brushPanel);
    brushScroll->setWidgetResizable(true);
    brushScroll->setFrameShape(QFrame::NoFrame);
    fixScrollMinimum(*brushScroll);
    m_brushDock =
        makeDock(tr("Brush"), QStringLiteral("brushDock"), brushScroll, Qt::LeftDockWidgetArea);
    connect(m_brushPanel, &BrushPanel::brushChanged, this, &MainWindow::setBrush);
    connect(m_brushPanel, &BrushPanel::pressureCurveChanged, this, &MainWindow::setPressureCurve);
    m_colorPanel = new ColorPanel(this);
    m_colorDock =
        makeDock(tr("Colour"), QStringLiteral("colorDock"), m_colorPanel, Qt::LeftDockWidgetArea);
    connect(m_colorPanel, &ColorPanel::foregroundChanged, this, [this](const QColor& color) {
        core::Brush brush = m_document->brush();
        brush.color = BrushToolBar::toLinear(color);
        setBrush(brush);
    });
}

void MainWindow::matchBrushToColorPanel() {
    // The colour panel's own colour, rounded to what it shows, is the brush's from the start.
    m_colorPanel->setForeground(BrushToolBar::toQColor(m_document->brush().color));
    core::Brush brush = m_document->brush();
    brush.color = BrushToolBar::toLinear(m_colorPanel->foreground());
    setBrush(brush);
}

void MainWindow::createLayerAwareAction() {
    // The paper's study checkbox: layer-aware or conventional painting, switchable any time.
    m_layerAwareAction = new QAction(tr("&Layer-Aware Painting"), this);
    m_layerAwareAction->setObjectName(QStringLiteral("actionLayerAware"));
    m_layerAwareAction->setCheckable(true);
    m_layerAwareAction->setChecked(m_document->layerAware());
    m_layerAwareAction->setShortcut(QKeySequence(Qt::Key_L));
    m_layerAwareAction->setToolTip(tr("Layer-aware painting (L): strokes follow a surface "
                                      "behind whatever covers it"));
    m_layerAwareAction->setStatusTip(tr("Paint across depth layers; off: only the front-most "
                                        "surface is paintable"));
    connect(m_layerAwareAction, &QAction::toggled, this, [this](bool on) {
        m_document->setLayerAware(on);
        if (m_project)
            m_project->markModified();
        statusBar()->showMessage(on ? tr("Layer-aware painting") : tr("Conventional painting"),
                                 kPaintMessageMs);
    });
    // Shown as a check box, as in the paper's study; the action (L, Paint menu) backs it.
    m_layerAwareCheck = new QCheckBox(tr("Layer-aware"), this);
    m_layerAwareCheck->setObjectName(QStringLiteral("layerAwareCheckBox"));
    m_layerAwareCheck->setChecked(m_layerAwareAction->isChecked());
    m_layerAwareCheck->setToolTip(m_layerAwareAction->toolTip());
    m_layerAwareCheck->setFocusPolicy(Qt::NoFocus); // keys stay with the view and shortcuts
    connect(m_layerAwareCheck, &QCheckBox::toggled, m_layerAwareAction, &QAction::setChecked);
    connect(m_layerAwareAction, &QAction::toggled, m_layerAwareCheck, &QCheckBox::setChecked);
    QAction* first = m_brushBar->actions().value(0);
    m_brushBar->insertWidget(first, m_layerAwareCheck);
    m_brushBar->insertSeparator(first);
}

void MainWindow::createBrushKeyActions() {
    // Painters' keys for the brush. One key each: a keyboard's Shift+[ matches both Shift+[ and
    // { (the platform offers the shifted and the unshifted key), and an action bound to both
    // would be an ambiguous shortcut that does nothing.
    struct StepInfo {
        QString name;
        QString text;
        QList<QKeySequence> keys;
        QString tip;
        bool radius;
        int direction;
    };
    const StepInfo steps[] = {
        {QStringLiteral("actionBrushSmaller"),
         tr("S&maller Brush"),
         {QKeySequence(Qt::Key_BracketLeft)},
         tr("Make the brush smaller"),
         true,
         -1},
        {QStringLiteral("actionBrushLarger"),
         tr("Lar&ger Brush"),
         {QKeySequence(Qt::Key_BracketRight)},
         tr("Make the brush larger"),
         true,
         1},
        {QStringLiteral("actionBrushSofter"),
         tr("Sof&ter Brush"),
         {QKeySequence(Qt::SHIFT | Qt::Key_BracketLeft)},
         tr("Lower the brush hardness"),
         false,
         -1},
        {QStringLiteral("actionBrushHarder"),
         tr("Har&der Brush"),
         {QKeySequence(Qt::SHIFT | Qt::Key_BracketRight)},
         tr("Raise the brush hardness"),
         false,
         1},
    };
    for (const StepInfo& step : steps) {
        auto* action = new QAction(step.text, this);
        action->setObjectName(step.name);
        action->setShortcuts(step.keys);
        action->setToolTip(QStringLiteral("%1 (%2)").arg(
            step.tip, step.keys.first().toString(QKeySequence::NativeText)));
        action->setStatusTip(step.tip);
        connect(action, &QAction::triggered, this,
                [this, radius = step.radius, direction = step.direction] {
                    if (radius)
                        stepBrushRadius(direction);
                    else
                        stepBrushHardness(direction);
                });
        addAction(action); // active while the menu bar is hidden too
        m_brushStepActions.append(action);
    }
    m_swapColorsAction = new QAction(tr("S&wap Colours"), this);
    m_swapColorsAction->setObjectName(QStringLiteral("actionSwapColors"));
    m_swapColorsAction->setShortcut(QKeySequence(Qt::Key_X));
    m_swapColorsAction->setToolTip(tr("Swap the foreground and background colours (X)"));
    m_swapColorsAction->setStatusTip(tr("Swap the foreground and background colours"));
    connect(m_swapColorsAction, &QAction::triggered, m_colorPanel, &ColorPanel::swapColors);
    addAction(m_swapColorsAction);
}

void MainWindow::createBrushMapsAction() {
    m_brushMapsAction = new QAction(tr("Show &Brush Maps"), this);
    m_brushMapsAction->setObjectName(QStringLiteral("actionShowBrushMaps"));
    m_brushMapsAction->setCheckable(true);
    m_brushMapsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_5));
    m_brushMapsAction->setStatusTip(tr("While painting, show the paintable (red) and trackable "
                                       "(blue) pixels around the brush"));
    connect(m_brushMapsAction, &QAction::toggled, m_viewport, &Viewport::setBrushMapsVisible);
}

void MainWindow::createUndoActions() {
    m_undoAction = new QAction(tr("&Undo"), this);
    m_undoAction->setObjectName(QStringLiteral("actionUndo"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_undoAction->setEnabled(false);
    connect(m_undoAction, &QAction::triggered, this, [this] {
        finishStroke();
        m_undoStack->undo();
    });
    connect(m_undoStack, &QUndoStack::canUndoChanged, m_undoAction, &QAction::setEnabled);
    connect(m_undoStack, &QUndoStack::undoTextChanged, this, [this](const QString& text) {
        m_undoAction->setText(text.isEmpty() ? tr("&Undo") : tr("&Undo %1").arg(text));
    });
    m_redoAction = new QAction(tr("&Redo"), this);
    m_redoAction->setObjectName(QStringLiteral("actionRedo"));
    m_redoAction->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    m_redoAction->setEnabled(false);
    connect(m_redoAction, &QAction::triggered, this, [this] {
        finishStroke();
        m_undoStack->redo();
    });
    connect(m_undoStack, &QUndoStack::canRedoChanged, m_redoAction, &QAction::setEnabled);
    connect(m_undoStack, &QUndoStack::redoTextChanged, this, [this](const QString& text) {
        m_redoAction->setText(text.isEmpty() ? tr("&Redo") : tr("&Redo %1").arg(text));
    });
}

void MainWindow::createToolActions() {
    // A row of its own: beside the brush bar, longer names (German) pushed tools into the
    // overflow menu at the window's minimum size.
    addToolBarBreak(Qt::TopToolBarArea);
    m_toolBar = addToolBar(tr("Tools"));
    m_toolBar->setObjectName(QStringLiteral("toolsToolBar"));
    m_toolGroup = new QActionGroup(this);
    m_toolGroup->setExclusive(true);
    struct ToolInfo {
        Tool tool;
        QString name;
        QString text;
        QKeySequence key;
        QString tip;
    };
    const ToolInfo tools[] = {
        {Tool::Brush, QStringLiteral("Brush"), tr("&Brush"), QKeySequence(Qt::Key_B),
         tr("Paint strokes with the brush; Shift+click draws a straight line on from the last "
            "stroke")},
        {Tool::Eraser, QStringLiteral("Eraser"), tr("&Eraser"), QKeySequence(Qt::Key_E),
         tr("Erase paint back to the model's original colours; Shift+click erases along a "
            "straight line from the last stroke")},
        {Tool::Fill, QStringLiteral("Fill"), tr("&Fill"), QKeySequence(Qt::Key_G),
         tr("Flood fill with the brush colour")},
        {Tool::Eyedropper, QStringLiteral("Eyedropper"), tr("E&yedropper"), QKeySequence(Qt::Key_I),
         tr("Pick the surface colour under the cursor (or Ctrl+click)")},
        {Tool::Hide, QStringLiteral("Hide"), tr("Paint to &Hide"), QKeySequence(Qt::Key_H),
         tr("Hide every region the brush touches, revealing what lies behind")},
        {Tool::PopUp, QStringLiteral("PopUp"), tr("&Pop Up"), QKeySequence(Qt::Key_P),
         tr("Bring the region below the visible one to the front (or Ctrl+Shift+click); click "
            "again to cycle")},
    };
    for (const ToolInfo& info : tools) {
        QAction* action = new QAction(info.text, m_toolGroup);
        action->setObjectName(QStringLiteral("actionTool") + info.name);
        action->setCheckable(true);
        action->setShortcut(info.key);
        action->setToolTip(
            QStringLiteral("%1 (%2)").arg(info.tip, info.key.toString(QKeySequence::NativeText)));
        action->setStatusTip(info.tip);
        connect(action, &QAction::triggered, this, [this, tool = info.tool] { setTool(tool); });
        m_toolActions[std::size_t(info.tool)] = action;
        m_toolBar->addAction(action);
    }
    toolAction(Tool::Brush)->setChecked(true);
    m_viewport->setToolCursor(toolCursor(m_tool), toolShowsBrushOutline(m_tool));
}

void MainWindow::createPaintLayersPanel() {
    m_paintLayersPanel = new PaintLayersPanel(*m_document, this);
    // In a scroll area: the dock may get smaller than the panel's controls need, so the window
    // keeps the minimum size it had.
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(m_paintLayersPanel);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    fixScrollMinimum(*scroll);
    m_paintLayersDock = makeDock(tr("Paint Layers"), QStringLiteral("paintLayersDock"), scroll);
    connect(m_paintLayersPanel, &PaintLayersPanel::changed, this,
            [this](const core::PaintChanges& changes) {
                // As after a stroke: the composite's texels to the view (the undo stack follows
                // the history by itself).
                if (m_document->paintTargetSerial() != m_targetSerial) {
                    showPaintTarget();
                } else {
                    m_viewport->applyPaintChanges(changes);
                }
            });
    connect(m_paintLayersPanel, &PaintLayersPanel::message, this,
            [this](const QString& text) { statusBar()->showMessage(text, kStatusMessageMs); });
    // The mask view: Alt+click on a mask in the panel; it ends there, or when the mask goes.
    connect(m_paintLayersPanel, &PaintLayersPanel::maskViewRequested, m_viewport,
            &Viewport::setMaskView);
    connect(m_viewport, &Viewport::maskViewChanged, this, [this](std::uint64_t id) {
        m_paintLayersPanel->setMaskView(id);
        statusBar()->showMessage(id != 0 ? tr("The mask alone: black hides, white shows. "
                                              "Alt+click it again to see the paint layers.")
                                         : tr("The paint layers again"),
                                 kStatusMessageMs);
    });
    // Strokes, fills, undo and redo change the stack and the thumbnails.
    connect(m_history, &HistoryBridge::changed, m_paintLayersPanel, &PaintLayersPanel::refresh);
    connect(m_paintLayersPanel, &PaintLayersPanel::refreshed, this,
            &MainWindow::updatePaintIntoInfo);
}

void MainWindow::createMenus() {
    createFileMenu();
    createEditMenu();
    createViewMenu();
    createPaintMenu();
    createPaintLayersMenu();
    createHelpMenu();
}

void MainWindow::createFileMenu() {
    QMenu* fileMenu = menuBar()->addMenu(tr("&File"));

    QAction* openAction = fileMenu->addAction(tr("&Open…"), this, &MainWindow::showOpenDialog);
    openAction->setObjectName(QStringLiteral("actionOpen"));
    openAction->setShortcut(QKeySequence::Open);

    QMenu* builtinMenu = fileMenu->addMenu(tr("New from &Built-in"));
    builtinMenu->setObjectName(QStringLiteral("builtinMenu"));
    for (const core::BuiltinModel& model : core::builtinModels()) {
        const QString name = QString::fromStdString(model.name);
        QAction* action = builtinMenu->addAction(builtinLabel(name));
        action->setObjectName(QStringLiteral("actionBuiltin_") + name);
        connect(action, &QAction::triggered, this,
                [this, name] { openFile(QString::fromLatin1(core::kBuiltinPrefix) + name); });
    }

    m_recentMenu = fileMenu->addMenu(tr("Open &Recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    // Rebuilt on every show so files deleted meanwhile disappear.
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::updateRecentMenu);
    updateRecentMenu();

    createProjectActions(fileMenu);

    fileMenu->addSeparator();
    QAction* quitAction = fileMenu->addAction(tr("&Quit"), this, &QWidget::close);
    quitAction->setObjectName(QStringLiteral("actionQuit"));
    quitAction->setShortcut(QKeySequence::Quit);
    quitAction->setMenuRole(QAction::QuitRole);
}

void MainWindow::createEditMenu() {
    QMenu* editMenu = menuBar()->addMenu(tr("&Edit"));
    editMenu->addAction(m_undoAction);
    editMenu->addAction(m_redoAction);
    editMenu->addSeparator();
    editMenu->addAction(m_scriptActions->copySessionAction());
    editMenu->addSeparator();
    m_preferencesAction =
        editMenu->addAction(tr("&Preferences…"), this, &MainWindow::showPreferences);
    m_preferencesAction->setObjectName(QStringLiteral("actionPreferences"));
    m_preferencesAction->setShortcut(QKeySequence::Preferences);
    m_preferencesAction->setMenuRole(QAction::PreferencesRole);
}

void MainWindow::createViewMenu() {
    QMenu* viewMenu = menuBar()->addMenu(tr("&View"));
    QAction* frameAction = viewMenu->addAction(tr("&Frame All"), m_viewport, &Viewport::frameAll);
    frameAction->setObjectName(QStringLiteral("actionFrameAll"));
    frameAction->setShortcuts({QKeySequence(Qt::Key_F), QKeySequence(Qt::Key_Home)});

    m_orthographicAction = viewMenu->addAction(tr("&Orthographic"));
    m_orthographicAction->setObjectName(QStringLiteral("actionOrthographic"));
    m_orthographicAction->setCheckable(true);
    // 5 is the numpad key Blender users expect; Qt also matches it with the keypad modifier.
    m_orthographicAction->setShortcuts({QKeySequence(Qt::Key_5), QKeySequence(Qt::Key_O)});
    connect(m_orthographicAction, &QAction::toggled, m_viewport, &Viewport::setOrthographic);
    connect(m_viewport, &Viewport::orthographicChanged, m_orthographicAction, &QAction::setChecked);

    viewMenu->addSeparator();
    createDisplayActions(viewMenu);

    viewMenu->addSeparator();
    QMenu* panelsMenu = viewMenu->addMenu(tr("&Panels"));
    panelsMenu->setObjectName(QStringLiteral("panelsMenu"));
    for (QDockWidget* dock :
         {m_brushDock, m_presetsDock, m_colorDock, m_paintLayersDock, m_segmentationDock,
          m_depthLayersDock, m_graphDock, m_hiddenDock, m_fillDock})
        panelsMenu->addAction(dock->toggleViewAction());
    panelsMenu->addSeparator();
    panelsMenu->addAction(m_brushBar->toggleViewAction());
    panelsMenu->addAction(m_toolBar->toggleViewAction());
    viewMenu->addSeparator();
    viewMenu->addAction(m_regionTools->transparencyAction());
    viewMenu->addAction(m_regionTools->orbitAboutSurfaceAction());
}

void MainWindow::createPaintMenu() {
    QMenu* paintMenu = menuBar()->addMenu(tr("&Paint"));
    paintMenu->addAction(m_layerAwareAction);
    paintMenu->addSeparator();
    paintMenu->addActions(m_toolGroup->actions());
    paintMenu->addSeparator();
    paintMenu->addAction(m_regionTools->autoPopUpAction());
    paintMenu->addAction(m_regionTools->resetOrderAction());
    paintMenu->addAction(m_regionTools->unhideAllAction());
    paintMenu->addSeparator();
    paintMenu->addActions(m_brushStepActions);
    paintMenu->addAction(m_swapColorsAction);
    paintMenu->addAction(createStabilizerAction());
    paintMenu->addMenu(createSymmetryMenu());
    paintMenu->addSeparator();
    QAction* raise =
        paintMenu->addAction(tr("&Raise Texture Size…"), this, &MainWindow::raiseTextureSize);
    raise->setObjectName(QStringLiteral("raiseTextureSizeAction"));
}

void MainWindow::createPaintLayersMenu() {
    QMenu* paintLayersMenu = menuBar()->addMenu(tr("Paint &Layers"));
    paintLayersMenu->setObjectName(QStringLiteral("paintLayersMenu"));
    for (QAction* action : m_paintLayersPanel->operationActions()) {
        if (action)
            paintLayersMenu->addAction(action);
        else
            paintLayersMenu->addSeparator();
    }
}

void MainWindow::createHelpMenu() {
    QMenu* helpMenu = menuBar()->addMenu(tr("&Help"));
    helpMenu->addAction(m_quickGuideAction);
    helpMenu->addSeparator();
    QAction* aboutAction =
        helpMenu->addAction(tr("&About LayerPaint"), this, &MainWindow::showAbout);
    aboutAction->setMenuRole(QAction::AboutRole);
    QAction* aboutQtAction = helpMenu->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
    aboutQtAction->setMenuRole(QAction::AboutQtRole);
}

void MainWindow::updateRecentMenu() {
    m_recentMenu->clear();
    const QStringList files = m_recent.files();
    for (int i = 0; i < files.size(); ++i) {
        const QString& path = files.at(i);
        // The number gives keyboard access; && keeps an & in a file name literal.
        const QString name =
            QFileInfo(path).fileName().replace(QLatin1Char('&'), QStringLiteral("&&"));
        const QString number = QString::number(i + 1);
        QAction* action = m_recentMenu->addAction(i < 9 ? tr("&%1 %2").arg(number, name)
                                                        : tr("%1 %2").arg(number, name));
        action->setData(path);
        action->setStatusTip(path);
        action->setToolTip(path);
        connect(action, &QAction::triggered, this, [this, path] { openFile(path); });
    }
    if (files.isEmpty()) {
        m_recentMenu->addAction(tr("No Recent Files"))->setEnabled(false);
        return;
    }
    m_recentMenu->addSeparator();
    m_recentMenu->addAction(tr("&Clear Menu"), this, [this] {
        m_recent.clear();
        updateRecentMenu();
    });
}

void MainWindow::showOpenDialog() {
    QSettings settings;
    const QString filters =
        tr("Projects and 3D models (*.glb *.gltf *.obj *.ply *.stl *.off)") + QStringLiteral(";;") +
        tr("LayerPaint projects (*.glb)") + QStringLiteral(";;") + tr("glTF 2.0 (*.gltf *.glb)") +
        QStringLiteral(";;") + tr("Wavefront OBJ (*.obj)") + QStringLiteral(";;") +
        tr("Stanford PLY (*.ply)") + QStringLiteral(";;") + tr("STL (*.stl)") +
        QStringLiteral(";;") + tr("Object File Format (*.off)") + QStringLiteral(";;") +
        tr("All files (*)");
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open Project or Model"), settings.value(kOpenDirectoryKey).toString(), filters);
    if (path.isEmpty())
        return;
    settings.setValue(kOpenDirectoryKey, QFileInfo(path).absolutePath());
    openFile(path);
}

void MainWindow::showAbout() {
    QMessageBox::about(
        this, tr("About LayerPaint"),
        tr("<h3>LayerPaint %1</h3>"
           "<p>Layer-aware 3D painting: paint surfaces hidden behind others in one stroke.</p>"
           "<p>License: GNU GPL version 3 or later.</p>")
            .arg(QApplication::applicationVersion().toHtmlEscaped()));
}

void MainWindow::createProjectActions(QMenu* fileMenu) {
    fileMenu->addSeparator();
    QAction* saveAction = fileMenu->addAction(tr("&Save"), m_project, &ProjectController::save);
    saveAction->setObjectName(QStringLiteral("actionSave"));
    saveAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_S));
    saveAction->setStatusTip(tr("Save the painting and its settings as a project (.glb)"));
    QAction* saveAsAction =
        fileMenu->addAction(tr("Save &As…"), m_project, &ProjectController::saveAs);
    saveAsAction->setObjectName(QStringLiteral("actionSaveAs"));
    saveAsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    saveAsAction->setStatusTip(tr("Save the project under another name"));

    m_scriptActions = new ScriptActions(*m_document, *m_viewport, *m_builder, *m_notifier);
    connect(m_scriptActions, &ScriptActions::documentStateChanged, this,
            &MainWindow::showDocumentState);
    fileMenu->addAction(m_scriptActions->runAction());

    m_exportMenu = fileMenu->addMenu(tr("&Export"));
    m_exportMenu->setObjectName(QStringLiteral("exportMenu"));
    struct ExportInfo {
        core::ExportFormat format;
        QString name;
        QString text;
    };
    const ExportInfo formats[] = {
        {core::ExportFormat::Glb, QStringLiteral("Glb"), tr("glTF &Binary (.glb)…")},
        {core::ExportFormat::Obj, QStringLiteral("Obj"),
         tr("Wavefront &OBJ (.obj + .mtl + textures)…")},
        {core::ExportFormat::Ply, QStringLiteral("Ply"), tr("Stanford &PLY with Vertex Colours…")},
        {core::ExportFormat::Png8, QStringLiteral("Png8"), tr("Paint Texture as P&NG (8-bit)…")},
        {core::ExportFormat::Png16, QStringLiteral("Png16"), tr("Paint Texture as PNG (&16-bit)…")},
        {core::ExportFormat::Tiff, QStringLiteral("Tiff"), tr("Paint Texture as &TIFF…")},
        {core::ExportFormat::Exr, QStringLiteral("Exr"), tr("Paint Texture as Open&EXR…")},
    };
    for (const ExportInfo& info : formats) {
        if (info.format == core::ExportFormat::Png8)
            m_exportMenu->addSeparator();
        QAction* action = m_exportMenu->addAction(info.text);
        action->setObjectName(QStringLiteral("actionExport") + info.name);
        action->setData(int(info.format));
        connect(action, &QAction::triggered, this,
                [this, format = info.format] { m_project->showExportDialog(format); });
    }
    QAction* exportTextures = fileMenu->addAction(tr("Export &Textures…"), m_project,
                                                  &ProjectController::showTextureExportDialog);
    exportTextures->setObjectName(QStringLiteral("actionExportTextures"));
    exportTextures->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E));
    exportTextures->setStatusTip(tr("Write each texture set's maps for a game engine or another "
                                    "tool, through an export preset"));
    connect(fileMenu, &QMenu::aboutToShow, this,
            [this, exportTextures] { exportTextures->setEnabled(m_project->canExportTexture()); });
    // Texture formats need a paint texture (not vertex colours); nothing without a model.
    connect(m_exportMenu, &QMenu::aboutToShow, this, [this] {
        const bool hasModel = m_document->meshSerial() != 0;
        for (QAction* action : m_exportMenu->actions()) {
            if (action->isSeparator())
                continue;
            const auto format = core::ExportFormat(action->data().toInt());
            action->setEnabled(hasModel &&
                               (!core::isTextureFormat(format) || m_project->canExportTexture()));
        }
    });
}

} // namespace ui
