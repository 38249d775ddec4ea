// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCheckBox>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QScopedValueRollback>
#include <QSettings>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>
#include <QUrl>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "core/model/builtin_models.h"
#include "ui/commands/history_bridge.h"
#include "ui/panels/brush_panel.h"
#include "ui/panels/brush_toolbar.h"
#include "ui/panels/color_panel.h"
#include "ui/panels/fill_panel.h"
#include "ui/panels/hidden_regions_panel.h"
#include "ui/panels/layers_panel.h"
#include "ui/panels/region_graph_panel.h"
#include "ui/panels/segmentation_controls.h"
#include "ui/shell/dock_size_keeper.h"
#include "ui/shell/elided_label.h"
#include "ui/shell/field_focus.h"
#include "ui/shell/model_loader.h"
#include "ui/shell/project_controller.h"
#include "ui/shell/script_actions.h"
#include "ui/tools/region_tools.h"
#include "ui/tools/tool_cursors.h"
#include "ui/view/layer_builder.h"
#include "ui/view/message_bar.h"
#include "ui/view/viewport.h"

namespace ui {

namespace {
constexpr int kProgressSteps = 1000;
constexpr int kProgressDelayMs = 400; // quick loads finish without a dialog flashing up
constexpr int kStatusMessageMs = 10000;

const QString kBuiltinPrefix = QString::fromLatin1(core::kBuiltinPrefix);
const QString kGeometryKey = QStringLiteral("mainWindow/geometry");
const QString kStateKey = QStringLiteral("mainWindow/state");
const QString kOpenDirectoryKey = QStringLiteral("mainWindow/openDirectory");
const QString kThresholdKey = QStringLiteral("segmentation/threshold");
const QString kTestKey = QStringLiteral("segmentation/test");
const QString kTwoSidedKey = QStringLiteral("segmentation/twoSided");
constexpr int kPaintMessageMs = 3000;
constexpr float kMinBrushRadius = 1.0f;
constexpr float kMaxBrushRadius = 500.0f; // as the brush bar and panel offer

double elapsedMs(const QElapsedTimer& clock) {
    return double(clock.nsecsElapsed()) / 1e6;
}

bool isBuiltin(const QString& source) {
    return source.startsWith(kBuiltinPrefix);
}

/** The first local file among dragged URLs, or empty. */
QString droppedFile(const QMimeData* mime) {
    if (!mime || !mime->hasUrls())
        return {};
    for (const QUrl& url : mime->urls()) {
        if (url.isLocalFile())
            return url.toLocalFile();
    }
    return {};
}
} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_document(std::make_unique<core::Document>()) {
    setWindowTitle(tr("LayerPaint"));
    setAcceptDrops(true);
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);

    {
        // The last session's segmentation options.
        const QSettings settings;
        core::LayerOptions options;
        const float threshold = settings.value(kThresholdKey, options.threshold).toFloat();
        if (threshold >= SegmentationControls::kMinThreshold &&
            threshold <= SegmentationControls::kMaxThreshold)
            options.threshold = threshold;
        if (settings.value(kTestKey).toString() == QLatin1String("plain"))
            options.test = core::ConnectionTest::Plain;
        options.cullBackFaces = !settings.value(kTwoSidedKey, false).toBool();
        m_document->setLayerOptions(options);
    }

    m_preferences = Preferences::load();
    m_document->setPressureCurve(core::PressureCurve{m_preferences.pressureGamma});
    m_paintOptions.resolution = m_preferences.textureSize;
    m_document->setPaintOptions(m_paintOptions);

    m_viewport = new Viewport(*m_document, this);
    m_viewport->setCameraMapping(m_preferences.cameraMapping);
    setCentralWidget(m_viewport);
    m_messageBar = new MessageBar(*m_viewport);
    m_builder = new LayerBuilder(*m_document, *m_viewport, this);
    m_loader = new ModelLoader(this);

    m_modelInfo = new ElidedLabel(this);
    statusBar()->addPermanentWidget(m_modelInfo);
    // Added after the model label (tests find that one first), but shown to its left.
    m_layerInfo = new ElidedLabel(this);
    m_layerInfo->setObjectName(QStringLiteral("layerInfo"));
    statusBar()->insertPermanentWidget(0, m_layerInfo);
    m_brushInfo = new ElidedLabel(this);
    m_brushInfo->setObjectName(QStringLiteral("brushInfo"));
    m_brushInfo->setContentsMargins(12, 0, 12, 0); // apart from its neighbours
    statusBar()->insertPermanentWidget(1, m_brushInfo);

    createPanels();
    createPaintActions();
    m_project = new ProjectController(*this);
    connect(m_project, &ProjectController::modifiedChanged, this, &MainWindow::updateWindowTitle);
    connect(m_project, &ProjectController::documentNameChanged, this,
            &MainWindow::updateWindowTitle);
    connect(m_project, &ProjectController::saved, this, [this](const QString& path) {
        m_recent.add(path);
        updateRecentMenu();
    });
    // Project settings that live in other widgets.
    for (QAction* action : {m_regionTools->autoPopUpAction(), m_regionTools->transparencyAction()})
        connect(action, &QAction::toggled, m_project, &ProjectController::markModified);
    createToolActions();
    createMenus();
    // Enter and Escape in a tool bar or panel field give the keys back to the view.
    qApp->installEventFilter(new FieldFocus(*this, *m_viewport, this));

    connect(m_loader, &ModelLoader::loaded, this, &MainWindow::onLoaded);
    connect(m_loader, &ModelLoader::failed, this, &MainWindow::onLoadFailed);
    connect(m_loader, &ModelLoader::cancelled, this, &MainWindow::onLoadCancelled);
    connect(m_viewport, &Viewport::glInitializationFailed, this, [this](const QString& message) {
        showError(tr("OpenGL Error"), tr("The 3D view cannot be shown."), message);
    });
    connect(m_viewport, &Viewport::layerRenderingFailed, this, [this](const QString& message) {
        statusBar()->showMessage(message, kStatusMessageMs);
    });
    connect(m_viewport, &Viewport::viewChanged, this, &MainWindow::updateLayerInfo);
    connect(m_builder, &LayerBuilder::layersBuilt, this, &MainWindow::onLayersBuilt);
    connect(m_builder, &LayerBuilder::segmentationChanged, this,
            &MainWindow::onSegmentationChanged);
    connect(m_builder, &LayerBuilder::layersCleared, this, &MainWindow::onLayersCleared);
    connect(m_builder, &LayerBuilder::buildFailed, this, [this](const QString& message) {
        statusBar()->showMessage(tr("Could not build the layers: %1").arg(message),
                                 kStatusMessageMs);
        updateLayerInfo();
    });
    updateLayerInfo();

    // The worker only publishes a number; polling it keeps the event queue free of updates.
    m_progressTimer.setInterval(50);
    connect(&m_progressTimer, &QTimer::timeout, this, [this] {
        if (m_progress)
            m_progress->setValue(int(m_loader->progress() * kProgressSteps));
    });

    const QSettings settings;
    if (!restoreGeometry(settings.value(kGeometryKey).toByteArray()))
        resize(1280, 800);
    restoreState(settings.value(kStateKey).toByteArray());
    new DockSizeKeeper(this); // panels get their width back when the window grows again
}

MainWindow::~MainWindow() {
    // Children outlive the members: the ones that use the document go first.
    delete m_builder;
    m_builder = nullptr;
    delete m_viewport;
    m_viewport = nullptr;
}

void MainWindow::openFile(const QString& source) {
    finishStroke();
    if (!m_project->maybeSave())
        return;
    const QString resolved = isBuiltin(source) ? source : QFileInfo(source).absoluteFilePath();
    startProgress(resolved);
    m_loader->load(resolved);
}

void MainWindow::openFromCommandLine(const QStringList& files) {
    openFile(files.isEmpty() ? QString::fromLatin1(core::kDefaultModel) : files.first());
}

bool MainWindow::isLoading() const {
    return m_loader->isLoading();
}

QString MainWindow::builtinLabel(const QString& name) {
    if (name == QLatin1String("trefoil"))
        return tr("Trefoil knot");
    if (name == QLatin1String("hexring"))
        return tr("Hexagonal ring");
    if (name == QLatin1String("row"))
        return tr("Row of four");
    // A model added to core before the GUI learnt its label: its English description.
    for (const core::BuiltinModel& model : core::builtinModels()) {
        if (QString::fromStdString(model.name) == name)
            return QString::fromStdString(model.description);
    }
    return name;
}

QString MainWindow::displayName(const QString& source) {
    if (isBuiltin(source))
        return builtinLabel(source.mid(kBuiltinPrefix.size()));
    return QFileInfo(source).fileName();
}

QDockWidget* MainWindow::makeDock(const QString& title, const QString& name, QWidget* content,
                                  Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name); // saveState() knows docks by name
    dock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea |
                          Qt::BottomDockWidgetArea);
    dock->setWidget(content);
    addDockWidget(area, dock);
    return dock;
}

void MainWindow::createPanels() {
    m_segmentationControls = new SegmentationControls(this);
    m_segmentationControls->setOptions(m_document->layerOptions());
    m_segmentationDock =
        makeDock(tr("Segmentation"), QStringLiteral("segmentationDock"), m_segmentationControls);
    connect(m_segmentationControls, &SegmentationControls::optionsChanged, this,
            &MainWindow::setLayerOptions);
    connect(m_segmentationControls, &SegmentationControls::connectivityBackendChanged, this,
            [this](int backend) {
                setConnectivityBackend(QString::fromLatin1(render::connectivityBackendName(
                                           render::ConnectivityBackend(backend))),
                                       true);
            });
    setConnectivityBackend(QSettings()
                               .value(QStringLiteral("layers/connectivity"), QStringLiteral("auto"))
                               .toString());

    m_layersPanel = new LayersPanel(this);
    m_layersDock = makeDock(tr("Layers"), QStringLiteral("layersDock"), m_layersPanel);
    connect(m_layersPanel, &LayersPanel::layerActivated, this, [this](std::uint32_t layer) {
        if (layer == 0)
            setDisplay(m_allLayersDisplay);
        else
            setDisplay(render::LayerDisplay::SingleLayer, layer);
    });

    m_graphPanel = new RegionGraphPanel(this);
    m_graphDock = makeDock(tr("Region Graph"), QStringLiteral("regionGraphDock"), m_graphPanel);
    connect(m_graphPanel, &RegionGraphPanel::regionHovered, m_viewport,
            &Viewport::setHighlightRegion);
    connect(m_graphPanel, &RegionGraphPanel::regionActivated, this, [this](std::uint32_t region) {
        statusBar()->showMessage(tr("Region %1 popped up").arg(region), kStatusMessageMs);
        m_regionTools->popUpRegion(region);
        emit regionActivated(region);
    });

    // Default layout (restoreState() may replace it): a column on the right.
    resizeDocks({m_segmentationDock, m_layersDock, m_graphDock}, {300, 300, 300}, Qt::Horizontal);
    resizeDocks({m_segmentationDock, m_layersDock, m_graphDock},
                {m_segmentationControls->sizeHint().height(), 280, 420}, Qt::Vertical);
}

void MainWindow::createDisplayActions(QMenu* viewMenu) {
    // Ctrl+digits: plain letters, [ ] and Alt are kept for the paint tools.
    m_displayGroup = new QActionGroup(this);
    m_displayGroup->setExclusive(true);
    const auto addDisplay = [&](const QString& text, const QString& name, int digit,
                                const QString& tip, render::LayerDisplay display) {
        QAction* action = viewMenu->addAction(text);
        action->setObjectName(name);
        action->setCheckable(true);
        action->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(Qt::Key_0 + digit)));
        action->setStatusTip(tip);
        m_displayGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, display] { setDisplay(display); });
        return action;
    };
    m_shadedAction =
        addDisplay(tr("&Shaded"), QStringLiteral("actionDisplayShaded"), 1,
                   tr("Show the model shaded, all layers"), render::LayerDisplay::Composite);
    m_singleLayerAction =
        addDisplay(tr("Single &Layer"), QStringLiteral("actionDisplaySingleLayer"), 2,
                   tr("Show one depth layer alone (choose it in the Layers panel)"),
                   render::LayerDisplay::SingleLayer);
    m_segmentationAction =
        addDisplay(tr("Se&gmentation Map"), QStringLiteral("actionDisplaySegmentation"), 3,
                   tr("Colour every region of the visible layer differently"),
                   render::LayerDisplay::Segmentation);
    m_shadedAction->setChecked(true);

    m_boundariesAction = viewMenu->addAction(tr("Region &Boundaries"));
    m_boundariesAction->setObjectName(QStringLiteral("actionShowBoundaries"));
    m_boundariesAction->setCheckable(true);
    m_boundariesAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_4));
    m_boundariesAction->setStatusTip(tr("Outline where a surface is not connected to its "
                                        "neighbours on the same layer"));
    connect(m_boundariesAction, &QAction::toggled, m_viewport, &Viewport::setBoundariesVisible);
    viewMenu->addAction(m_brushMapsAction);
}

void MainWindow::setDisplay(render::LayerDisplay display, std::uint32_t layer) {
    if (display == render::LayerDisplay::SingleLayer) {
        if (layer != 0)
            m_viewport->setDisplayLayer(layer);
    } else {
        m_allLayersDisplay = display;
    }
    m_viewport->setDisplay(display);
    QAction* action = display == render::LayerDisplay::Composite     ? m_shadedAction
                      : display == render::LayerDisplay::SingleLayer ? m_singleLayerAction
                                                                     : m_segmentationAction;
    action->setChecked(true);
    m_layersPanel->setThumbnailStyle(display == render::LayerDisplay::Segmentation
                                         ? LayersPanel::ThumbnailStyle::Regions
                                         : LayersPanel::ThumbnailStyle::Shaded,
                                     m_document->layers());
    m_layersPanel->setCurrentLayer(
        display == render::LayerDisplay::SingleLayer ? m_viewport->displayLayer() : 0);
}

void MainWindow::setLayerOptions(const core::LayerOptions& options) {
    m_builder->setLayerOptions(options);
    m_project->markModified();
    QSettings settings;
    settings.setValue(kThresholdKey, double(options.threshold));
    settings.setValue(kTestKey, options.test == core::ConnectionTest::Plain
                                    ? QStringLiteral("plain")
                                    : QStringLiteral("surface"));
    settings.setValue(kTwoSidedKey, !options.cullBackFaces);
}

void MainWindow::onLayersBuilt() {
    const core::Layers* layers = m_document->layers();
    if (!layers)
        return;
    m_segmentationControls->setConnectivityInUse(
        m_viewport->connectivityBackend() == render::ConnectivityBackend::Gpu ? tr("compute shader")
                                                                              : tr("C++"));
    // A layer shown alone that this view does not have: show its deepest one.
    const std::uint32_t deepest = std::max(1u, layers->stack.maxLayers());
    if (m_viewport->displayLayer() > deepest)
        m_viewport->setDisplayLayer(deepest);
    m_layersPanel->setLayers(layers);
    m_layersPanel->setCurrentLayer(m_viewport->display() == render::LayerDisplay::SingleLayer
                                       ? m_viewport->displayLayer()
                                       : 0);
    // Filling a panel can change the window's layout, and a resized view drops its layers
    // (onLayersCleared() has run then).
    if (m_document->layers() != layers)
        return;
    m_graphPanel->setLayers(layers);
    if (m_document->layers() != layers)
        return;
    m_regionTools->layersChanged();
    m_history->sync(); // order steps of the old regions go
    updateLayerInfo();
}

void MainWindow::onSegmentationChanged() {
    const core::Layers* layers = m_document->layers();
    if (!layers)
        return;
    m_graphPanel->setLayers(layers);
    if (m_document->layers() != layers)
        return;                       // see onLayersBuilt()
    m_layersPanel->setLayers(layers); // region counts (and colours) per layer
    if (m_document->layers() != layers)
        return;
    m_regionTools->layersChanged();
    m_history->sync();
    updateLayerInfo();
}

void MainWindow::onLayersCleared() {
    m_viewport->setHighlightRegion(core::kNone);
    m_layersPanel->setLayers(nullptr);
    m_graphPanel->setLayers(nullptr);
    m_regionTools->layersChanged();
    m_history->sync();
    updateLayerInfo();
}

void MainWindow::updateLayerInfo() {
    const core::Layers* layers = m_document->layers();
    if (!layers) {
        m_layerInfo->setText(m_builder->isBuilding() && m_viewport->canCapture()
                                 ? tr("Building layers…")
                                 : QString());
        m_layerInfo->setToolTip(QString());
        return;
    }
    const QLocale locale;
    const core::LayerTimings& t = layers->timings;
    // Label style ("Regions: 1") reads right in English for any count without plural forms.
    m_layerInfo->setText(
        tr("Layers: %1 · Fragments: %2 · Regions: %3 · Built in %4 ms")
            .arg(locale.toString(layers->stack.maxLayers()),
                 locale.toString(qulonglong(layers->stack.fragmentCount())),
                 locale.toString(qulonglong(layers->segmentation.graph.regions.size())),
                 locale.toString(m_builder->lastBuildMs(), 'f', 0)));
    m_layerInfo->setToolTip(tr("build_layers of this view:\n"
                               "capture %1 ms (drawing), %2 ms (sorting)\n"
                               "connectivity %3 ms, regions %4 ms\n"
                               "%5 ms from the capture to the picture")
                                .arg(locale.toString(t.capture.gpuMs, 'f', 1),
                                     locale.toString(t.capture.resolveMs, 'f', 1),
                                     locale.toString(t.connectivityMs, 'f', 1),
                                     locale.toString(t.segmentationMs, 'f', 1),
                                     locale.toString(m_builder->lastBuildMs(), 'f', 1)));
}

void MainWindow::createPaintActions() {
    m_history = new HistoryBridge(*m_document, this);
    m_undoStack = m_history->stack();
    m_document->history().setBudget(std::size_t(m_preferences.undoBudgetMiB) << 20);
    connect(m_history, &HistoryBridge::applied, this, &MainWindow::onHistoryApplied);

    m_regionTools = new RegionTools(
        *m_document, *m_viewport, [this] { return m_builder->buildNow(); }, this);
    connect(m_regionTools, &RegionTools::edited, m_history, &HistoryBridge::sync);
    connect(m_regionTools, &RegionTools::message, this,
            [this](const QString& text) { statusBar()->showMessage(text, kPaintMessageMs); });
    m_hiddenDock = makeDock(tr("Paint to Hide"), QStringLiteral("hiddenRegionsDock"),
                            m_regionTools->createPanel(this));
    // A tab behind the region graph: the column keeps its height.
    tabifyDockWidget(m_graphDock, m_hiddenDock);
    m_fillPanel = new FillPanel(this);
    m_fillDock = makeDock(tr("Fill"), QStringLiteral("fillDock"), m_fillPanel);
    tabifyDockWidget(m_graphDock, m_fillDock);
    m_graphDock->raise();
    // Fill's options come to the front with the tool.
    connect(this, &MainWindow::toolChanged, this, [this](Tool tool) {
        if (tool == Tool::Fill) {
            m_fillDock->show();
            m_fillDock->raise();
        }
    });

    m_brushBar = new BrushToolBar(this);
    addToolBar(Qt::TopToolBarArea, m_brushBar);
    connect(m_brushBar, &BrushToolBar::brushChanged, this, &MainWindow::setBrush);
    connect(m_brushBar, &BrushToolBar::targetRequested, this, &MainWindow::setPaintTarget);

    // The panels: the full brush settings and the colours, on the left of the view.
    m_brushPanel = new BrushPanel(this);
    m_brushPanel->setPressureCurve(m_document->pressureCurve());
    m_brushDock =
        makeDock(tr("Brush"), QStringLiteral("brushDock"), m_brushPanel, Qt::LeftDockWidgetArea);
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
    // The colour panel's own colour, rounded to what it shows, is the brush's from the start.
    m_colorPanel->setForeground(BrushToolBar::toQColor(m_document->brush().color));
    {
        core::Brush brush = m_document->brush();
        brush.color = BrushToolBar::toLinear(m_colorPanel->foreground());
        setBrush(brush);
    }

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

    m_brushMapsAction = new QAction(tr("Show &Brush Maps"), this);
    m_brushMapsAction->setObjectName(QStringLiteral("actionShowBrushMaps"));
    m_brushMapsAction->setCheckable(true);
    m_brushMapsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_5));
    m_brushMapsAction->setStatusTip(tr("While painting, show the paintable (red) and trackable "
                                       "(blue) pixels around the brush"));
    connect(m_brushMapsAction, &QAction::toggled, m_viewport, &Viewport::setBrushMapsVisible);

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

    connect(m_viewport, &Viewport::paintPressed, this, &MainWindow::onPaintPressed);
    connect(m_viewport, &Viewport::paintMoved, this, &MainWindow::onPaintMoved);
    connect(m_viewport, &Viewport::paintReleased, this, &MainWindow::onPaintReleased);
    updateBrushBar();
}

void MainWindow::createToolActions() {
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
         tr("Paint strokes with the brush")},
        {Tool::Eraser, QStringLiteral("Eraser"), tr("&Eraser"), QKeySequence(Qt::Key_E),
         tr("Erase paint back to the model's original colours")},
        {Tool::Fill, QStringLiteral("Fill"), tr("&Fill"), QKeySequence(Qt::Key_G),
         tr("Flood fill with the brush colour")},
        {Tool::Eyedropper, QStringLiteral("Eyedropper"), tr("E&yedropper"), QKeySequence(Qt::Key_I),
         tr("Pick the surface colour under the cursor (or Ctrl+click)")},
        {Tool::Hide, QStringLiteral("Hide"), tr("Paint to &Hide"), QKeySequence(Qt::Key_H),
         tr("Hide every region the brush touches, revealing what lies behind")},
        {Tool::PopUp, QStringLiteral("PopUp"), tr("&Pop Up"), QKeySequence(Qt::Key_P),
         tr("Bring the region below the visible one to the front (or Shift+click); click again "
            "to cycle")},
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

void MainWindow::setTool(Tool tool) {
    QAction* action = toolAction(tool);
    if (!action->isEnabled())
        return;
    finishStroke();
    action->setChecked(true);
    if (tool == m_tool)
        return;
    // Paint-to-hide works on the segmentation map; leaving it brings the display back.
    if (tool == Tool::Hide) {
        m_displayBeforeHide = m_viewport->display();
        setDisplay(render::LayerDisplay::Segmentation);
    } else if (m_tool == Tool::Hide &&
               m_viewport->display() == render::LayerDisplay::Segmentation) {
        setDisplay(m_displayBeforeHide);
    }
    m_tool = tool;
    m_viewport->setHoverHighlight(tool == Tool::Hide || tool == Tool::PopUp);
    m_viewport->setToolCursor(toolCursor(tool), toolShowsBrushOutline(tool));
    emit toolChanged(tool);
}

void MainWindow::onPaintPressed(QPointF pixel, qreal pressure, Qt::KeyboardModifiers modifiers) {
    finishStroke();
    m_picking = false;
    if (m_document->meshSerial() == 0 || m_document->mesh().triangleCount() == 0)
        return;
    // The pen's eraser end erases, whatever tool is chosen.
    const Tool tool = m_viewport->pressPointer() == PointerKind::Eraser
                          ? Tool::Eraser
                          : toolForPress(m_tool, modifiers);
    if (!toolAction(tool)->isEnabled())
        return;
    switch (tool) {
    case Tool::Brush:
    case Tool::Eraser:
        beginPaintStroke(pixel, pressure, tool == Tool::Eraser);
        return;
    case Tool::Hide:
        m_regionTools->beginHide(pixel, m_document->brush().radius);
        return;
    case Tool::PopUp:
        m_regionTools->popUpAt(pixel);
        return;
    case Tool::Fill:
        fillAt(pixel);
        return;
    case Tool::Eyedropper:
        m_picking = true;
        pickColor(pixel);
        return;
    }
}

void MainWindow::pickColor(QPointF pixel) {
    // Never pick from the layers of another view: build them now if they are not there.
    if (!m_builder->buildNow())
        return; // buildFailed() reported why
    const core::Layers* layers = m_document->layers();
    if (!layers)
        return;
    const double x = std::floor(pixel.x()), y = std::floor(pixel.y());
    std::optional<glm::vec4> color;
    if (x >= 0.0 && y >= 0.0 && x < layers->stack.width && y < layers->stack.height) {
        const bool hadTarget = m_document->hasPaintTarget();
        color = m_document->pickColor(std::size_t(y) * std::size_t(layers->stack.width) +
                                      std::size_t(x));
        if (!hadTarget && m_document->hasPaintTarget())
            m_viewport->paintTargetChanged();
    }
    if (!color) {
        statusBar()->showMessage(tr("No surface here to pick a colour from"), kPaintMessageMs);
        return;
    }
    // As the colour panel shows it (sRGB bytes): a painted texel comes back exactly.
    const QColor picked = BrushToolBar::toQColor(*color);
    core::Brush brush = m_document->brush();
    brush.color = BrushToolBar::toLinear(picked);
    setBrush(brush);
    statusBar()->showMessage(tr("Picked %1").arg(ColorPanel::hexName(picked)), kPaintMessageMs);
}

bool MainWindow::preparePainting() {
    // Never paint with the layers of another view: build them now if they are not there.
    if (!m_builder->buildNow())
        return false; // buildFailed() reported why
    const bool hadTarget = m_document->hasPaintTarget();
    std::string error;
    if (!m_document->paintTarget(&error)) {
        statusBar()->showMessage(
            tr("Cannot paint this model: %1").arg(QString::fromStdString(error)), kStatusMessageMs);
        return false;
    }
    if (!hadTarget)
        m_viewport->paintTargetChanged();
    return true;
}

void MainWindow::beginPaintStroke(QPointF pixel, qreal pressure, bool eraser) {
    QElapsedTimer clock;
    clock.start();
    m_strokeStats = {};
    if (!preparePainting())
        return;
    m_document->brush().eraser = eraser;
    m_lastPressure = float(pressure);
    core::PaintChanges changes;
    m_regionTools->beginStroke();
    const core::Status status =
        m_document->beginStroke({{float(pixel.x()), float(pixel.y())}, m_lastPressure}, changes);
    if (!status) {
        m_regionTools->endStroke();
        statusBar()->showMessage(tr("Cannot paint: %1").arg(QString::fromStdString(status.error())),
                                 kStatusMessageMs);
        return;
    }
    m_painting = true;
    m_regionTools->strokeMoved(); // the first dab may have popped a region up
    if (!eraser)
        m_colorPanel->addRecent(BrushToolBar::toQColor(m_document->brush().color));
    m_viewport->applyPaintChanges(changes);
    m_viewport->brushMapsChanged();
    m_strokeStats.pressMs = elapsedMs(clock);
}

void MainWindow::fillAt(QPointF pixel) {
    QElapsedTimer clock;
    clock.start();
    if (!preparePainting())
        return;
    const std::uint64_t revision = m_document->history().revision();
    core::PaintChanges changes;
    const core::Status status =
        m_document->fill({float(pixel.x()), float(pixel.y())}, m_fillPanel->mode(),
                         m_fillPanel->tolerance(), changes);
    if (!status) {
        statusBar()->showMessage(tr("Cannot fill: %1").arg(QString::fromStdString(status.error())),
                                 kStatusMessageMs);
        return;
    }
    m_viewport->applyPaintChanges(changes);
    if (m_document->history().revision() != revision) {
        m_colorPanel->addRecent(BrushToolBar::toQColor(m_document->brush().color));
        statusBar()->showMessage(
            tr("Filled in %1 ms").arg(QLocale().toString(elapsedMs(clock), 'f', 0)),
            kPaintMessageMs);
    } else {
        statusBar()->showMessage(tr("Nothing to fill there"), kPaintMessageMs);
    }
    m_history->sync();
}

void MainWindow::onPaintMoved(QPointF pixel, qreal pressure) {
    if (m_regionTools->isHiding())
        m_regionTools->moveHide(pixel);
    if (m_picking) {
        pickColor(pixel); // the eyedropper follows while held
        return;
    }
    if (!m_painting)
        return;
    QElapsedTimer clock;
    clock.start();
    core::PaintChanges changes;
    m_lastPressure = float(pressure);
    m_document->moveStroke({{float(pixel.x()), float(pixel.y())}, m_lastPressure}, changes);
    m_viewport->applyPaintChanges(changes);
    m_viewport->brushMapsChanged();
    m_regionTools->strokeMoved(); // automatic pop-up
    const double ms = elapsedMs(clock);
    ++m_strokeStats.moves;
    m_strokeStats.totalMs += ms;
    m_strokeStats.maxMs = std::max(m_strokeStats.maxMs, ms);
}

void MainWindow::onPaintReleased(QPointF pixel) {
    m_picking = false;
    if (m_regionTools->isHiding()) {
        m_regionTools->moveHide(pixel);
        m_regionTools->endHide();
    }
    if (!m_painting)
        return;
    core::PaintChanges changes;
    // A release carries no pressure: the end keeps the last sample's, so a pen stroke's tail
    // does not swell.
    m_document->moveStroke({{float(pixel.x()), float(pixel.y())}, m_lastPressure}, changes);
    m_viewport->applyPaintChanges(changes);
    finishStroke();
}

void MainWindow::finishStroke() {
    if (!m_painting)
        return;
    m_painting = false;
    // The stroke and the pop-ups it made are one step of the document's history.
    m_document->endStroke();
    m_regionTools->endStroke();
    m_history->sync();
}

void MainWindow::showDocumentState() {
    setBrush(m_document->brush());
    m_layerAwareAction->setChecked(m_document->layerAware());
    m_regionTools->autoPopUpAction()->setChecked(m_document->autoPopUp());
    m_segmentationControls->setOptions(m_document->layerOptions());
    m_brushPanel->setPressureCurve(m_document->pressureCurve());
    m_targetSerial = m_document->paintTargetSerial();
    m_paintOptions = m_document->paintTargetOptions();
    if (m_document->hasPaintTarget())
        m_viewport->paintTargetChanged();
    updateBrushBar();
    m_viewport->cameraMoved();
    m_regionTools->orderApplied();
    m_history->sync();
    m_project->markModified();
}

void MainWindow::onHistoryApplied(const core::PaintChanges& changes) {
    m_viewport->applyPaintChanges(changes);
    if (m_document->paintTargetSerial() != m_targetSerial) {
        m_targetSerial = m_document->paintTargetSerial();
        m_paintOptions = m_document->paintTargetOptions();
        m_viewport->paintTargetChanged();
        updateBrushBar();
    }
    m_regionTools->orderApplied();
}

void MainWindow::setPaintTarget(const core::PaintTargetOptions& options) {
    finishStroke();
    if (m_document->meshSerial() == 0) {
        m_paintOptions = options;
        updateBrushBar();
        return;
    }
    const core::Status status = m_document->setPaintTarget(options);
    if (!status) {
        statusBar()->showMessage(
            tr("Cannot paint into that target: %1").arg(QString::fromStdString(status.error())),
            kStatusMessageMs);
    } else {
        m_paintOptions = options;
        m_targetSerial = m_document->paintTargetSerial();
        m_viewport->paintTargetChanged();
        statusBar()->showMessage(tr("Painting into a new target (Undo brings the previous one "
                                    "back)"),
                                 kStatusMessageMs);
    }
    m_history->sync();
    updateBrushBar();
}

void MainWindow::updateBrushBar() {
    const bool hasUvs = m_document->meshSerial() == 0 || m_document->mesh().hasUvs();
    m_brushBar->setTarget(m_paintOptions, hasUvs);
}

void MainWindow::setBrush(const core::Brush& brush) {
    m_document->brush() = brush; // the next stroke uses it
    m_brushBar->setBrush(brush);
    m_brushPanel->setBrush(brush);
    const QColor color = BrushToolBar::toQColor(brush.color);
    if (color != m_colorPanel->foreground())
        m_colorPanel->setForeground(color);
    m_viewport->setBrushRadius(brush.radius);
    updateBrushInfo();
    if (m_project && m_document->meshSerial() != 0)
        m_project->markModified();
}

void MainWindow::updateBrushInfo() {
    const core::Brush& brush = m_document->brush();
    const QLocale locale;
    m_brushInfo->setText(tr("Brush %1 px · %2 % hard")
                             .arg(locale.toString(std::lround(brush.radius)),
                                  locale.toString(std::lround(brush.hardness * 100.0f))));
    m_brushInfo->setToolTip(tr("Brush radius and hardness ([ ] and Shift+[ ] change them)"));
}

void MainWindow::stepBrushRadius(int direction) {
    core::Brush brush = m_document->brush();
    // Steps of 15 %, at least a pixel, on whole pixels as the spin boxes show; a step up and
    // one down come back to the same size.
    constexpr float kFactor = 1.15f;
    const float radius = std::round(brush.radius);
    const float next = direction > 0 ? std::max(radius + 1.0f, std::round(radius * kFactor))
                                     : std::min(radius - 1.0f, std::round(radius / kFactor));
    brush.radius = std::clamp(next, kMinBrushRadius, kMaxBrushRadius);
    setBrush(brush);
}

void MainWindow::stepBrushHardness(int direction) {
    core::Brush brush = m_document->brush();
    brush.hardness =
        std::clamp(std::round(brush.hardness * 10.0f + float(direction)) / 10.0f, 0.0f, 1.0f);
    setBrush(brush);
}

void MainWindow::setPressureCurve(const core::PressureCurve& curve) {
    m_document->setPressureCurve(curve);
    m_brushPanel->setPressureCurve(curve);
    if (m_preferences.pressureGamma != curve.gamma) {
        m_preferences.pressureGamma = curve.gamma;
        QSettings().setValue(Preferences::kPressureGammaKey, double(curve.gamma));
    }
}

void MainWindow::setPreferences(const Preferences& preferences) {
    preferences.save();
    m_preferences = preferences;
    m_document->history().setBudget(std::size_t(preferences.undoBudgetMiB) << 20);
    m_history->sync(); // the budget may have dropped steps
    setPressureCurve(core::PressureCurve{preferences.pressureGamma});
    m_viewport->setCameraMapping(preferences.cameraMapping);
    // The texture size is the default for the next model; the open one keeps its painting.
    // Language and autosave are read from the settings where they are used.
}

void MainWindow::showPreferences() {
    auto* dialog = new PreferencesDialog(m_preferences, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this,
            [this, dialog] { setPreferences(dialog->preferences()); });
    dialog->open();
}

void MainWindow::createMenus() {
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
                [this, name] { openFile(kBuiltinPrefix + name); });
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
    for (QDockWidget* dock : {m_brushDock, m_colorDock, m_segmentationDock, m_layersDock,
                              m_graphDock, m_hiddenDock, m_fillDock})
        panelsMenu->addAction(dock->toggleViewAction());
    panelsMenu->addSeparator();
    panelsMenu->addAction(m_brushBar->toggleViewAction());
    panelsMenu->addAction(m_toolBar->toggleViewAction());
    viewMenu->addSeparator();
    viewMenu->addAction(m_regionTools->transparencyAction());
    viewMenu->addAction(m_regionTools->orbitAboutSurfaceAction());

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

    QMenu* helpMenu = menuBar()->addMenu(tr("&Help"));
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

void MainWindow::showError(const QString& title, const QString& text, const QString& details) {
    if (!m_errorDialogs)
        return;
    // Window-modal and opened, not exec()'d: no nested event loop.
    auto* box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, this);
    box->setInformativeText(details);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setWindowModality(Qt::WindowModal);
    box->open();
}

void MainWindow::onLoaded(const QString& source, std::shared_ptr<core::Mesh> mesh,
                          std::shared_ptr<const core::ProjectState> state) {
    stopProgress();
    // Recovered work is shown under its own name: the project it belongs to, else the model it
    // was painted from; the autosave's name is an internal one.
    const bool recovered = state && m_project->isRecoveryFile(source);
    m_source = source;
    QString recoveredNote;
    if (recovered) {
        const auto decode = [](const std::string& path) {
            return QFile::decodeName(QByteArray::fromStdString(path));
        };
        if (!state->recoveryFor.empty())
            m_source = decode(state->recoveryFor);
        else if (!state->source.empty())
            m_source = decode(state->source);
        recoveredNote =
            tr("Recovered the unsaved work on “%1” that was autosaved at %2. Save it "
               "to keep it.")
                .arg(displayName(m_source),
                     QLocale().toString(QFileInfo(source).lastModified(), QLocale::ShortFormat));
    }
    updateModelInfo(*mesh, recoveredNote);
    finishStroke();
    // A new model starts with the preferred size for a new texture.
    m_paintOptions.resolution = m_preferences.textureSize;
    m_document->setPaintOptions(m_paintOptions);
    // This window is the loader's only listener: the mesh moves into the document.
    m_document->setMesh(std::move(*mesh), m_source.toStdString());
    if (state) {
        applyProjectState(*state);
    } else {
        m_projectBase = {};
        if (m_paintOptions.kind == core::PaintTargetKind::Texture && !m_document->mesh().hasUvs()) {
            // The document keeps its target options: vertex colours for this model, and the
            // default (a texture when there are UVs) for the next.
            m_paintOptions.kind.reset();
            m_document->setPaintTarget(m_paintOptions);
        }
    }
    m_viewport->meshChanged();
    if (m_document->hasPaintTarget())
        m_viewport->paintTargetChanged();
    m_history->sync();
    updateBrushBar();
    m_project->documentLoaded(source, state != nullptr,
                              state ? QString::fromStdString(state->recoveryFor) : QString(),
                              state ? QString::fromStdString(state->source) : QString());
    updateWindowTitle();
    if (!isBuiltin(source) && !m_project->isRecoveryFile(source)) {
        m_recent.add(source);
        updateRecentMenu();
    }
    emit modelLoaded(source);
}

core::ProjectState MainWindow::projectState() const {
    core::ProjectState state = core::captureProjectState(*m_document, m_projectBase);
    // Panels with state of their own add it here and read it in applyProjectState().
    state.popUpTransparency = m_viewport->popUpTransparency();
    state.foreground = BrushToolBar::toLinear(m_colorPanel->foreground());
    state.background = BrushToolBar::toLinear(m_colorPanel->background());
    state.palette.clear();
    for (const QColor& color : m_colorPanel->recentColors())
        state.palette.push_back(BrushToolBar::toLinear(color));
    return state;
}

void MainWindow::applyProjectState(const core::ProjectState& state) {
    m_projectBase = state;
    if (const core::Status status = core::applyProjectState(*m_document, state); !status)
        statusBar()->showMessage(QString::fromStdString(status.error()), kStatusMessageMs);
    m_paintOptions = m_document->paintTargetOptions();
    if (m_document->hasPaintTarget())
        m_paintOptions.kind = m_document->paintTargetKind();
    m_segmentationControls->setOptions(m_document->layerOptions());
    m_colorPanel->setBackground(BrushToolBar::toQColor(state.background));
    // Oldest first, so the project's most recent colour ends up first.
    for (auto it = state.palette.rbegin(); it != state.palette.rend(); ++it)
        m_colorPanel->addRecent(BrushToolBar::toQColor(*it));
    setBrush(m_document->brush()); // the bar, the panels and the colour follow
    {
        const QSignalBlocker blocker(m_layerAwareAction);
        m_layerAwareAction->setChecked(m_document->layerAware());
    }
    {
        const QSignalBlocker blocker(m_orthographicAction);
        m_orthographicAction->setChecked(m_document->camera().orthographic);
    }
    // The pop-up toggles are remembered settings too: the project's become the current ones.
    m_regionTools->autoPopUpAction()->setChecked(state.autoPopUp);
    m_regionTools->transparencyAction()->setChecked(state.popUpTransparency);
    updateBrushBar();
}

void MainWindow::updateWindowTitle() {
    const QString name = m_project->documentName();
    // [*] shows the unsaved-changes mark where the platform puts it.
    setWindowTitle(name.isEmpty() ? tr("LayerPaint") : tr("%1[*] — LayerPaint").arg(name));
    setWindowModified(!name.isEmpty() && m_project->isModified()); // no mark without a document
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

    m_scriptActions = new ScriptActions(*this);
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

void MainWindow::onLoadFailed(const QString& source, const QString& message) {
    stopProgress();
    m_project->documentLoadFailed(source);
    if (!isBuiltin(source) && !QFileInfo(source).exists())
        m_recent.remove(source);
    statusBar()->showMessage(tr("Could not open %1").arg(displayName(source)), kStatusMessageMs);
    showError(tr("Open Failed"), tr("Could not open “%1”.").arg(displayName(source)), message);
    emit loadFailed(message);
}

void MainWindow::onLoadCancelled(const QString& source) {
    stopProgress();
    statusBar()->showMessage(tr("Opening %1 cancelled").arg(displayName(source)), kStatusMessageMs);
}

void MainWindow::startProgress(const QString& source) {
    stopProgress();
    // Not modal: the current model stays usable, and setValue() never spins a nested loop.
    auto* dialog = new QProgressDialog(tr("Opening %1…").arg(displayName(source)), tr("Cancel"), 0,
                                       kProgressSteps, this);
    dialog->setWindowTitle(tr("Opening Model"));
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    dialog->setMinimumDuration(kProgressDelayMs);
    dialog->setValue(0);
    connect(dialog, &QProgressDialog::canceled, m_loader, &ModelLoader::cancel);
    m_progress = dialog;
    m_progressTimer.start();
    statusBar()->showMessage(tr("Opening %1…").arg(displayName(source)));
}

void MainWindow::stopProgress() {
    m_progressTimer.stop();
    // Deleted at once: a hidden dialog left for deleteLater could still be shown by its own
    // minimum-duration timer. Never called from inside the dialog's methods.
    delete m_progress.data();
    m_progress = nullptr;
}

void MainWindow::updateModelInfo(const core::Mesh& mesh, const QString& note) {
    const QLocale locale;
    m_modelInfo->setText(tr("%1 — %2 vertices, %3 triangles")
                             .arg(displayName(m_source),
                                  locale.toString(qulonglong(mesh.vertexCount())),
                                  locale.toString(qulonglong(mesh.triangleCount()))));
    QStringList warnings;
    for (const std::string& warning : mesh.warnings)
        warnings.append(QString::fromStdString(warning));
    m_modelInfo->setToolTip(warnings.join(QLatin1Char('\n')));
    const int warningCount = int(warnings.size());
    QStringList notes;
    if (!note.isEmpty())
        notes.append(note);
    // Without UVs there is no texture to paint into (BrushToolBar::setTarget says so too).
    if (!mesh.hasUvs())
        notes.append(tr("“%1” has no texture coordinates (UVs), so it is painted with vertex "
                        "colours: the paint's detail follows its vertices.")
                         .arg(displayName(m_source)));
    // Whole, over the view, until dismissed: the status bar cuts long lines and moves on.
    if (warningCount > 0)
        m_messageBar->showMessage(
            MessageBar::Level::Warning,
            tr("Opening “%1” gave these warnings:").arg(displayName(m_source)), warnings + notes);
    else if (!notes.isEmpty())
        m_messageBar->showMessage(MessageBar::Level::Information, notes.join(QLatin1Char('\n')));
    else
        m_messageBar->dismiss();
    if (warningCount == 0)
        statusBar()->clearMessage();
    else
        statusBar()->showMessage(tr("Warnings while loading are shown above the view"),
                                 kStatusMessageMs);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    finishStroke();
    if (!m_project->maybeSave()) {
        event->ignore();
        return;
    }
    // Saved or discarded: nothing is left to recover.
    m_project->waitForTasks();
    m_project->discardRecovery();
    QSettings settings;
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    QMainWindow::closeEvent(event);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (!droppedFile(event->mimeData()).isEmpty())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QString path = droppedFile(event->mimeData());
    if (path.isEmpty())
        return;
    event->acceptProposedAction();
    openFile(path);
}

bool MainWindow::setConnectivityBackend(const QString& name, bool remember) {
    const auto backend = render::parseConnectivityBackend(name.toStdString());
    if (!backend)
        return false;
    m_viewport->setConnectivityBackend(*backend);
    m_segmentationControls->setConnectivityBackend(int(*backend));
    if (remember)
        QSettings().setValue(QStringLiteral("layers/connectivity"),
                             QString::fromLatin1(render::connectivityBackendName(*backend)));
    m_builder->invalidate(); // rebuilt with the new engine once the view settles
    return true;
}

} // namespace ui
