// SPDX-License-Identifier: GPL-3.0-or-later
// The main window: its construction, docks and panels, the display modes and the layers' status,
// preferences, closing and dropped files. Actions and menus are in main_window_actions.cpp, tool
// dispatch and painting in main_window_painting.cpp, loading and projects in
// main_window_loading.cpp.
#include "ui/shell/main_window.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QKeySequence>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMimeData>
#include <QProgressDialog>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QUrl>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/model/builtin_models.h"
#include "ui/commands/history_bridge.h"
#include "ui/panels/depth_layers_panel.h"
#include "ui/panels/region_graph_panel.h"
#include "ui/panels/segmentation_controls.h"
#include "ui/shell/dock_size_keeper.h"
#include "ui/shell/elided_label.h"
#include "ui/shell/field_focus.h"
#include "ui/shell/model_loader.h"
#include "ui/shell/notifier.h"
#include "ui/shell/project_controller.h"
#include "ui/shell/source_names.h"
#include "ui/shell/stall_meter.h"
#include "ui/tools/region_tools.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/message_bar.h"
#include "ui/view/viewport.h"

namespace ui {

namespace {
const QString kGeometryKey = QStringLiteral("mainWindow/geometry");
const QString kStateKey = QStringLiteral("mainWindow/state");
const QString kThresholdKey = QStringLiteral("segmentation/threshold");
const QString kTestKey = QStringLiteral("segmentation/test");
const QString kTwoSidedKey = QStringLiteral("segmentation/twoSided");
const QString kChannelKey = QStringLiteral("view/channel");

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
    m_notifier = new Notifier(*this);
    restoreDepthLayerOptions();
    applyStartPreferences();
    createView();
    createStatusBarLabels();
    createPanels();
    createPaintActions();
    createProjectController();
    createToolActions();
    createMenus();
    // Enter and Escape in a tool bar or panel field give the keys back to the view.
    qApp->installEventFilter(new FieldFocus(*this, *m_viewport, this));
    connectLoader();
    connectViewport();
    connectDepthLayersBuilder();
    createSymmetryProgress();
    updateDepthLayerInfo();
    createLoadProgress();
    restoreWindowLayout();
}

void MainWindow::restoreDepthLayerOptions() {
    // The last session's segmentation options.
    const QSettings settings;
    core::DepthLayerOptions options;
    const float threshold = settings.value(kThresholdKey, options.threshold).toFloat();
    if (threshold >= SegmentationControls::kMinThreshold &&
        threshold <= SegmentationControls::kMaxThreshold)
        options.threshold = threshold;
    if (settings.value(kTestKey).toString() == QLatin1String("plain"))
        options.test = core::ConnectionTest::Plain;
    options.cullBackFaces = !settings.value(kTwoSidedKey, false).toBool();
    m_document->setDepthLayerOptions(options);
}

void MainWindow::applyStartPreferences() {
    m_preferences = Preferences::load();
    m_document->setPressureCurve(core::PressureCurve{m_preferences.pressureGamma});
    m_paintOptions.resolution = m_preferences.textureSize;
    m_document->setPaintOptions(m_paintOptions);
}

void MainWindow::createView() {
    m_viewport = new Viewport(*m_document, this);
    m_viewport->setCameraMapping(m_preferences.cameraMapping);
    setCentralWidget(m_viewport);
    // A click given while the window was frozen must not paint on what it shows afterwards.
    if (auto* app = dynamic_cast<MeteredApplication*>(QCoreApplication::instance()))
        app->guardFromQueuedInput(m_viewport);
    m_messageBar = new MessageBar(*m_viewport);
    m_builder = new DepthLayersBuilder(*m_document, *m_viewport, this);
    m_loader = new ModelLoader(this);
    m_targetJob = new PaintTargetJob(*this);
    connect(m_targetJob, &PaintTargetJob::finished, this, &MainWindow::paintTargetMade);
}

void MainWindow::createStatusBarLabels() {
    m_modelInfo = new ElidedLabel(this);
    statusBar()->addPermanentWidget(m_modelInfo);
    // Added after the model label (tests find that one first), but shown to its left.
    m_depthLayerInfo = new ElidedLabel(this);
    m_depthLayerInfo->setObjectName(QStringLiteral("layerInfo"));
    statusBar()->insertPermanentWidget(0, m_depthLayerInfo);
    m_brushInfo = new ElidedLabel(this);
    m_brushInfo->setObjectName(QStringLiteral("brushInfo"));
    m_brushInfo->setContentsMargins(12, 0, 12, 0); // apart from its neighbours
    statusBar()->insertPermanentWidget(1, m_brushInfo);
    m_paintIntoInfo = new ElidedLabel(this);
    m_paintIntoInfo->setObjectName(QStringLiteral("paintIntoInfo"));
    statusBar()->insertPermanentWidget(2, m_paintIntoInfo);
}

void MainWindow::createProjectController() {
    m_project = new ProjectController(*m_document, *m_history, *m_notifier,
                                      [this] { return projectState(); });
    connect(m_project, &ProjectController::openRequested, this, &MainWindow::openFile);
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
}

void MainWindow::connectLoader() {
    connect(m_loader, &ModelLoader::loaded, this, &MainWindow::onLoaded);
    connect(m_loader, &ModelLoader::failed, this, &MainWindow::onLoadFailed);
    connect(m_loader, &ModelLoader::cancelled, this, &MainWindow::onLoadCancelled);
}

void MainWindow::connectViewport() {
    connect(m_viewport, &Viewport::glInitializationFailed, this, [this](const QString& message) {
        showError(tr("OpenGL Error"), tr("The 3D view cannot be shown."), message);
    });
    connect(m_viewport, &Viewport::depthLayerRenderingFailed, this, [this](const QString& message) {
        statusBar()->showMessage(message, kStatusMessageMs);
    });
    connect(m_viewport, &Viewport::viewChanged, this, &MainWindow::updateDepthLayerInfo);
}

void MainWindow::connectDepthLayersBuilder() {
    connect(m_builder, &DepthLayersBuilder::depthLayersBuilt, this,
            &MainWindow::onDepthLayersBuilt);
    connect(m_builder, &DepthLayersBuilder::segmentationChanged, this,
            &MainWindow::onSegmentationChanged);
    connect(m_builder, &DepthLayersBuilder::depthLayersCleared, this,
            &MainWindow::onDepthLayersCleared);
    connect(m_builder, &DepthLayersBuilder::buildFailed, this, [this](const QString& message) {
        statusBar()->showMessage(tr("Could not build the depth layers: %1").arg(message),
                                 kStatusMessageMs);
        updateDepthLayerInfo();
    });
}

void MainWindow::createSymmetryProgress() {
    // The symmetric views build in the background after the layers; the status bar says how far.
    auto* symmetryTimer = new QTimer(this);
    symmetryTimer->setInterval(200);
    const auto showSymmetryProgress = [this] {
        statusBar()->showMessage(tr("Building the symmetric views… %1 %")
                                     .arg(std::lround(m_builder->symmetryProgress() * 100.0)));
    };
    connect(symmetryTimer, &QTimer::timeout, this, showSymmetryProgress);
    connect(m_builder, &DepthLayersBuilder::symmetryStarted, this,
            [symmetryTimer, showSymmetryProgress] {
                showSymmetryProgress();
                symmetryTimer->start();
            });
    connect(m_builder, &DepthLayersBuilder::symmetryFinished, this, [this, symmetryTimer] {
        if (symmetryTimer->isActive())
            statusBar()->clearMessage();
        symmetryTimer->stop();
    });
    connect(m_builder, &DepthLayersBuilder::symmetryWaiting, this, [this] {
        // The stroke waits for its copies rather than painting one side only.
        statusBar()->showMessage(tr("Waiting for the symmetric views before painting…"));
        statusBar()->repaint();
    });
}

void MainWindow::createLoadProgress() {
    // The worker only publishes a number; polling it keeps the event queue free of updates.
    m_progressTimer.setInterval(50);
    connect(&m_progressTimer, &QTimer::timeout, this, [this] {
        if (m_progress)
            m_progress->setValue(int(m_loader->progress() * kProgressSteps));
    });
}

void MainWindow::restoreWindowLayout() {
    const QSettings settings;
    if (!restoreGeometry(settings.value(kGeometryKey).toByteArray())) {
        // The first start: 1280 × 800, or nine tenths of a smaller screen, so it fits there.
        QSize size(1280, 800);
        if (const QScreen* shown = screen())
            size = size.boundedTo(shown->availableGeometry().size() * 9 / 10);
        resize(size);
    }
    arrangeDefaultDocks(); // what restoreState() replaces when the last session left a layout
    restoreState(settings.value(kStateKey).toByteArray());
    new DockSizeKeeper(this); // panels get their width back when the window grows again
}

MainWindow::~MainWindow() {
    // Children outlive the members: the ones that use the document go first.
    delete m_history;
    m_history = nullptr;
    delete m_builder;
    m_builder = nullptr;
    delete m_viewport;
    m_viewport = nullptr;
}

void MainWindow::openFile(const QString& source) {
    finishStroke();
    if (!m_project->maybeSave())
        return;
    const QString resolved =
        isBuiltinSource(source) ? source : QFileInfo(source).absoluteFilePath();
    startProgress(resolved);
    m_loader->load(resolved, newModelPaintOptions());
}

void MainWindow::openFromCommandLine(const QStringList& files) {
    openFile(files.isEmpty() ? QString::fromLatin1(core::kDefaultModel) : files.first());
}

void MainWindow::setErrorDialogsEnabled(bool enabled) {
    m_notifier->setDialogsEnabled(enabled);
}

bool MainWindow::errorDialogsEnabled() const {
    return m_notifier->dialogsEnabled();
}

bool MainWindow::isLoading() const {
    return m_loader->isLoading();
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
    m_segmentationControls->setOptions(m_document->depthLayerOptions());
    m_segmentationDock =
        makeDock(tr("Segmentation"), QStringLiteral("segmentationDock"), m_segmentationControls);
    connect(m_segmentationControls, &SegmentationControls::optionsChanged, this,
            &MainWindow::setDepthLayerOptions);
    connect(m_segmentationControls, &SegmentationControls::connectivityBackendChanged, this,
            [this](int backend) {
                setConnectivityBackend(QString::fromLatin1(render::connectivityBackendName(
                                           render::ConnectivityBackend(backend))),
                                       true);
            });
    setConnectivityBackend(QSettings()
                               .value(QStringLiteral("layers/connectivity"), QStringLiteral("auto"))
                               .toString());

    m_depthLayersPanel = new DepthLayersPanel(this);
    m_depthLayersDock =
        makeDock(tr("Depth Layers"), QStringLiteral("layersDock"), m_depthLayersPanel);
    connect(m_depthLayersPanel, &DepthLayersPanel::layerActivated, this,
            [this](std::uint32_t layer) {
                if (layer == 0)
                    setDisplay(m_allLayersDisplay);
                else
                    setDisplay(render::DepthLayerDisplay::SingleLayer, layer);
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
}

void MainWindow::arrangeDefaultDocks() {
    // Right: the settings panels as tabs at the top, as high as they need (Fill and Paint to
    // Hide come to the front with their tools); below them the stacks, Paint Layers in front of
    // Depth Layers and the Region Graph, with all the rest of the height for the paint layers'
    // list. Left: the Brush panel, and Colour with Brush Presets under it, the colour square
    // no higher than it needs.
    const std::array<QDockWidget*, 6> right = {m_segmentationDock, m_hiddenDock,      m_fillDock,
                                               m_paintLayersDock,  m_depthLayersDock, m_graphDock};
    for (QDockWidget* dock : right)
        removeDockWidget(dock);
    addDockWidget(Qt::RightDockWidgetArea, m_segmentationDock);
    tabifyDockWidget(m_segmentationDock, m_hiddenDock);
    tabifyDockWidget(m_segmentationDock, m_fillDock);
    addDockWidget(Qt::RightDockWidgetArea, m_paintLayersDock);
    tabifyDockWidget(m_paintLayersDock, m_depthLayersDock);
    tabifyDockWidget(m_paintLayersDock, m_graphDock);
    for (QDockWidget* dock : right)
        dock->show();
    m_segmentationDock->raise();
    m_paintLayersDock->raise();

    // As high as Segmentation's controls (the list of hidden regions gets shorter).
    const int settingsHeight = m_segmentationDock->sizeHint().height();
    const int rest = std::max(height() - settingsHeight, m_paintLayersDock->sizeHint().height());
    resizeDocks({m_segmentationDock, m_paintLayersDock}, {300, 300}, Qt::Horizontal);
    resizeDocks({m_segmentationDock, m_paintLayersDock}, {settingsHeight, rest}, Qt::Vertical);
    resizeDocks(
        {m_brushDock, m_colorDock},
        {std::max(height() - m_colorDock->sizeHint().height(), m_brushDock->sizeHint().height()),
         m_colorDock->sizeHint().height()},
        Qt::Vertical);
}

void MainWindow::createDisplayActions(QMenu* viewMenu) {
    // Ctrl+digits: plain letters, [ ] and Alt are kept for the paint tools.
    m_displayGroup = new QActionGroup(this);
    m_displayGroup->setExclusive(true);
    const auto addDisplay = [&](const QString& text, const QString& name, int digit,
                                const QString& tip, render::DepthLayerDisplay display) {
        QAction* action = viewMenu->addAction(text);
        action->setObjectName(name);
        action->setCheckable(true);
        action->setShortcut(QKeySequence(Qt::CTRL | Qt::Key(Qt::Key_0 + digit)));
        action->setStatusTip(tip);
        m_displayGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, display] { setDisplay(display); });
        return action;
    };
    m_shadedAction = addDisplay(tr("&Shaded"), QStringLiteral("actionDisplayShaded"), 1,
                                tr("Show the model shaded, all depth layers"),
                                render::DepthLayerDisplay::Composite);
    m_singleLayerAction =
        addDisplay(tr("Single Depth &Layer"), QStringLiteral("actionDisplaySingleLayer"), 2,
                   tr("Show one depth layer alone (choose it in the Depth Layers panel)"),
                   render::DepthLayerDisplay::SingleLayer);
    m_segmentationAction =
        addDisplay(tr("Se&gmentation Map"), QStringLiteral("actionDisplaySegmentation"), 3,
                   tr("Colour every region of the visible depth layer differently"),
                   render::DepthLayerDisplay::Segmentation);
    m_shadedAction->setChecked(true);

    m_boundariesAction = viewMenu->addAction(tr("Region &Boundaries"));
    m_boundariesAction->setObjectName(QStringLiteral("actionShowBoundaries"));
    m_boundariesAction->setCheckable(true);
    m_boundariesAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_4));
    m_boundariesAction->setStatusTip(tr("Outline where a surface is not connected to its "
                                        "neighbours on the same depth layer"));
    connect(m_boundariesAction, &QAction::toggled, m_viewport, &Viewport::setBoundariesVisible);
    viewMenu->addAction(m_brushMapsAction);
    createChannelActions(viewMenu);
}

void MainWindow::createChannelActions(QMenu* viewMenu) {
    QMenu* menu = viewMenu->addMenu(tr("&Channel"));
    menu->setObjectName(QStringLiteral("menuChannel"));
    auto* group = new QActionGroup(this);
    group->setExclusive(true);
    const int saved = QSettings().value(kChannelKey, 0).toInt();
    const auto addChannel = [&](const QString& text, const QString& name, const QString& tip,
                                render::MaterialChannel channel) {
        QAction* action = menu->addAction(text);
        action->setObjectName(name);
        action->setCheckable(true);
        action->setStatusTip(tip);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, channel] {
            m_viewport->setChannel(channel);
            QSettings().setValue(kChannelKey, int(channel));
        });
        if (saved == int(channel)) {
            action->setChecked(true);
            m_viewport->setChannel(channel);
        }
    };
    addChannel(tr("&Material"), QStringLiteral("actionChannelMaterial"),
               tr("Show the paint lit as a metallic-roughness material"),
               render::MaterialChannel::Material);
    addChannel(tr("&Base Colour"), QStringLiteral("actionChannelBaseColor"),
               tr("Show the base colour alone, unlit"), render::MaterialChannel::BaseColor);
    addChannel(tr("&Roughness"), QStringLiteral("actionChannelRoughness"),
               tr("Show roughness as grey: black smooth, white rough"),
               render::MaterialChannel::Roughness);
    addChannel(tr("M&etallic"), QStringLiteral("actionChannelMetallic"),
               tr("Show metallic as grey: black non-metal, white metal"),
               render::MaterialChannel::Metallic);
    if (!group->checkedAction())
        group->actions().front()->setChecked(true);
}

void MainWindow::setDisplay(render::DepthLayerDisplay display, std::uint32_t layer) {
    if (display == render::DepthLayerDisplay::SingleLayer) {
        if (layer != 0)
            m_viewport->setDisplayLayer(layer);
    } else {
        m_allLayersDisplay = display;
    }
    m_viewport->setDisplay(display);
    QAction* action = display == render::DepthLayerDisplay::Composite     ? m_shadedAction
                      : display == render::DepthLayerDisplay::SingleLayer ? m_singleLayerAction
                                                                          : m_segmentationAction;
    action->setChecked(true);
    m_depthLayersPanel->setThumbnailStyle(display == render::DepthLayerDisplay::Segmentation
                                              ? DepthLayersPanel::ThumbnailStyle::Regions
                                              : DepthLayersPanel::ThumbnailStyle::Shaded,
                                          m_document->depthLayers());
    m_depthLayersPanel->setCurrentLayer(
        display == render::DepthLayerDisplay::SingleLayer ? m_viewport->displayLayer() : 0);
}

void MainWindow::setDepthLayerOptions(const core::DepthLayerOptions& options) {
    m_builder->setDepthLayerOptions(options);
    m_project->markModified();
    QSettings settings;
    settings.setValue(kThresholdKey, double(options.threshold));
    settings.setValue(kTestKey, options.test == core::ConnectionTest::Plain
                                    ? QStringLiteral("plain")
                                    : QStringLiteral("surface"));
    settings.setValue(kTwoSidedKey, !options.cullBackFaces);
}

void MainWindow::onDepthLayersBuilt() {
    const core::DepthLayers* layers = m_document->depthLayers();
    if (!layers)
        return;
    m_segmentationControls->setConnectivityInUse(
        m_viewport->connectivityBackend() == render::ConnectivityBackend::Gpu ? tr("compute shader")
                                                                              : tr("C++"));
    // A layer shown alone that this view does not have: show its deepest one.
    const std::uint32_t deepest = std::max(1u, layers->stack.maxLayers());
    if (m_viewport->displayLayer() > deepest)
        m_viewport->setDisplayLayer(deepest);
    m_depthLayersPanel->setDepthLayers(layers);
    m_depthLayersPanel->setCurrentLayer(
        m_viewport->display() == render::DepthLayerDisplay::SingleLayer ? m_viewport->displayLayer()
                                                                        : 0);
    // Filling a panel can change the window's layout, and a resized view drops its layers
    // (onDepthLayersCleared() has run then).
    if (m_document->depthLayers() != layers)
        return;
    m_graphPanel->setDepthLayers(layers);
    if (m_document->depthLayers() != layers)
        return;
    m_regionTools->layersChanged();
    updateDepthLayerInfo();
}

void MainWindow::onSegmentationChanged() {
    const core::DepthLayers* layers = m_document->depthLayers();
    if (!layers)
        return;
    m_graphPanel->setDepthLayers(layers);
    if (m_document->depthLayers() != layers)
        return;                                 // see onDepthLayersBuilt()
    m_depthLayersPanel->setDepthLayers(layers); // region counts (and colours) per layer
    if (m_document->depthLayers() != layers)
        return;
    m_regionTools->layersChanged();
    updateDepthLayerInfo();
}

void MainWindow::onDepthLayersCleared() {
    m_viewport->setHighlightRegion(core::kNone);
    m_depthLayersPanel->setDepthLayers(nullptr);
    m_graphPanel->setDepthLayers(nullptr);
    m_regionTools->layersChanged();
    updateDepthLayerInfo();
}

void MainWindow::updateDepthLayerInfo() {
    const core::DepthLayers* layers = m_document->depthLayers();
    if (!layers) {
        m_depthLayerInfo->setText(m_builder->isBuilding() && m_viewport->canCapture()
                                      ? tr("Building depth layers…")
                                      : QString());
        m_depthLayerInfo->setToolTip(QString());
        return;
    }
    const QLocale locale;
    const core::DepthLayerTimings& t = layers->timings;
    // Label style ("Regions: 1") reads right in English for any count without plural forms.
    m_depthLayerInfo->setText(
        tr("Depth layers: %1 · Fragments: %2 · Regions: %3 · Built in %4 ms")
            .arg(locale.toString(layers->stack.maxLayers()),
                 locale.toString(qulonglong(layers->stack.fragmentCount())),
                 locale.toString(qulonglong(layers->segmentation.graph.regions.size())),
                 locale.toString(m_builder->lastBuildMs(), 'f', 0)));
    m_depthLayerInfo->setToolTip(tr("build_layers of this view:\n"
                                    "capture %1 ms (drawing), %2 ms (sorting)\n"
                                    "connectivity %3 ms, regions %4 ms\n"
                                    "%5 ms from the capture to the picture")
                                     .arg(locale.toString(t.capture.gpuMs, 'f', 1),
                                          locale.toString(t.capture.resolveMs, 'f', 1),
                                          locale.toString(t.connectivityMs, 'f', 1),
                                          locale.toString(t.segmentationMs, 'f', 1),
                                          locale.toString(m_builder->lastBuildMs(), 'f', 1)));
}

void MainWindow::setPreferences(const Preferences& preferences) {
    preferences.save();
    m_preferences = preferences;
    m_document->history().setBudget(std::size_t(preferences.undoBudgetMiB) << 20);
    setPressureCurve(core::PressureCurve{preferences.pressureGamma});
    m_viewport->setCameraMapping(preferences.cameraMapping);
    m_project->reloadAutosaveInterval();
    // The texture size is the default for the next model; the open one keeps its painting.
    // The language is read from the settings at the next start.
}

void MainWindow::showPreferences() {
    auto* dialog = new PreferencesDialog(m_preferences, this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    connect(dialog, &QDialog::accepted, this,
            [this, dialog] { setPreferences(dialog->preferences()); });
    dialog->open();
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
