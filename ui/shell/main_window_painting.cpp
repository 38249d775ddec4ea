// SPDX-License-Identifier: GPL-3.0-or-later
// The main window's tool dispatch and painting: the viewport's press, move and release go to the
// current tool (stroke, fill, eyedropper, region tools); the history bridge is synced after every
// change; the brush and paint target settings.
#include "ui/shell/main_window.h"

#include <QAction>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QToolButton>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "ui/commands/history_bridge.h"
#include "ui/panels/brush_panel.h"
#include "ui/panels/brush_toolbar.h"
#include "ui/panels/color_panel.h"
#include "ui/panels/fill_panel.h"
#include "ui/panels/paint_layers_panel.h"
#include "ui/panels/segmentation_controls.h"
#include "ui/panels/symmetry_box.h"
#include "ui/shell/elided_label.h"
#include "ui/shell/project_controller.h"
#include "ui/shell/source_names.h"
#include "ui/tools/region_tools.h"
#include "ui/tools/tool_cursors.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/message_bar.h"
#include "ui/view/viewport.h"

namespace ui {

namespace {
constexpr float kMinBrushRadius = 1.0f;
constexpr float kMaxBrushRadius = 500.0f; // as the brush bar and panel offer

double elapsedMs(const QElapsedTimer& clock) {
    return double(clock.nsecsElapsed()) / 1e6;
}
} // namespace

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
        setDisplay(render::DepthLayerDisplay::Segmentation);
    } else if (m_tool == Tool::Hide &&
               m_viewport->display() == render::DepthLayerDisplay::Segmentation) {
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
    if (pressDrawsLine(tool, modifiers)) {
        paintLine(pixel, pressure, tool == Tool::Eraser);
        return;
    }
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
    const core::DepthLayers* layers = m_document->depthLayers();
    if (!layers)
        return;
    const double x = std::floor(pixel.x()), y = std::floor(pixel.y());
    std::optional<glm::vec4> color;
    if (x >= 0.0 && y >= 0.0 && x < layers->stack.width && y < layers->stack.height) {
        const bool hadTarget = m_document->hasPaintTarget();
        color = m_document->pickColor(std::size_t(y) * std::size_t(layers->stack.width) +
                                      std::size_t(x));
        if (!hadTarget && m_document->hasPaintTarget())
            showPaintTarget();
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
    if (const core::Result<core::PaintTarget*> target = m_document->ensurePaintTarget(); !target) {
        statusBar()->showMessage(
            tr("Cannot paint this model: %1").arg(QString::fromStdString(target.error())),
            kStatusMessageMs);
        return false;
    }
    if (!hadTarget)
        showPaintTarget();
    // A symmetric stroke paints its copies from the first dab: wait for them if still building.
    if (!m_builder->buildSymmetryNow())
        statusBar()->showMessage(tr("The symmetric views could not be built: this stroke paints "
                                    "without its copies"),
                                 kStatusMessageMs);
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
        if (m_document->selectedFillLayer())
            offerPaintableTarget();
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

void MainWindow::offerPaintableTarget() {
    const core::PaintLayer* fill = m_document->selectedFillLayer();
    const auto* shown = findChild<QMessageBox*>(QStringLiteral("fillLayerOffer"));
    if (!fill || (shown && shown->isVisible()))
        return;
    const std::uint64_t id = fill->id;
    const bool hasMask = fill->mask != nullptr;
    auto* box = new QMessageBox(QMessageBox::Information, tr("A Fill Layer Takes No Strokes"),
                                tr("“%1” is a fill layer: its values are the same everywhere. "
                                   "Paint its mask to shape where it shows, or paint on a paint "
                                   "layer above it.")
                                    .arg(QString::fromStdString(fill->settings.name)),
                                QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("fillLayerOffer"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    QPushButton* mask = box->addButton(
        hasMask ? tr("Paint Its Mask") : tr("Add a Mask and Paint It"), QMessageBox::AcceptRole);
    mask->setObjectName(QStringLiteral("fillLayerOfferMask"));
    QPushButton* above = box->addButton(tr("Add a Paint Layer Above"), QMessageBox::AcceptRole);
    above->setObjectName(QStringLiteral("fillLayerOfferPaintLayer"));
    box->setDefaultButton(mask);
    connect(box, &QMessageBox::buttonClicked, this,
            [this, mask, above, id, hasMask](QAbstractButton* clicked) {
                if (clicked == mask && hasMask) {
                    m_document->selectPaint({id, true});
                    m_paintLayersPanel->refresh();
                } else if (clicked == mask) {
                    m_paintLayersPanel->addMaskAction()->trigger();
                } else if (clicked == above) {
                    m_paintLayersPanel->newLayerAction()->trigger();
                }
            });
    box->open();
}

void MainWindow::paintLine(QPointF pixel, qreal pressure, bool eraser) {
    if (!preparePainting())
        return;
    m_document->brush().eraser = eraser;
    const bool fromStroke = m_document->lineStart().has_value();
    core::PaintChanges changes;
    m_regionTools->beginStroke();
    const core::Status status =
        m_document->lineTo({{float(pixel.x()), float(pixel.y())}, float(pressure)}, changes);
    m_regionTools->endStroke(); // a line into a hidden surface may have popped it up
    if (!status) {
        statusBar()->showMessage(tr("Cannot paint: %1").arg(QString::fromStdString(status.error())),
                                 kStatusMessageMs);
        return;
    }
    if (!eraser)
        m_colorPanel->addRecent(BrushToolBar::toQColor(m_document->brush().color));
    m_viewport->applyPaintChanges(changes);
    m_viewport->brushMapsChanged();
    statusBar()->showMessage(fromStroke ? tr("Straight line from the end of the last stroke")
                                        : tr("No stroke to go on from: a dot here; the next "
                                             "Shift+click draws a line from it"),
                             kPaintMessageMs);
}

QAction* MainWindow::createStabilizerAction() {
    m_stabilizerAction = new QAction(tr("Stroke Stabili&zer"), this);
    m_stabilizerAction->setObjectName(QStringLiteral("actionStabilizer"));
    m_stabilizerAction->setCheckable(true);
    m_stabilizerAction->setChecked(m_document->brush().stabilizer);
    m_stabilizerAction->setStatusTip(tr("Strokes follow the pointer on a string, smoothing out "
                                        "wobbles (length and smoothing in the Brush panel)"));
    connect(m_stabilizerAction, &QAction::toggled, this, [this](bool on) {
        if (on == m_document->brush().stabilizer)
            return;
        core::Brush brush = m_document->brush();
        brush.stabilizer = on;
        setBrush(brush);
    });
    return m_stabilizerAction;
}

QMenu* MainWindow::createSymmetryMenu() {
    auto* menu = new QMenu(tr("S&ymmetry"), this);
    menu->setObjectName(QStringLiteral("symmetryMenu"));
    const QString texts[3] = {tr("Mirror &X"), tr("Mirror &Y"), tr("Mirror &Z")};
    for (int i = 0; i < 3; ++i) {
        QAction* action = menu->addAction(texts[i]);
        action->setObjectName(QStringLiteral("actionMirror") + QChar('X' + i));
        action->setCheckable(true);
        action->setStatusTip(tr("Repeat every dab mirrored across the model's plane across this "
                                "axis, also where that side is hidden or faces away"));
        connect(action, &QAction::toggled, this, [this, i](bool on) {
            core::Brush brush = m_document->brush();
            bool* mirrors[3] = {&brush.symmetry.mirrorX, &brush.symmetry.mirrorY,
                                &brush.symmetry.mirrorZ};
            if (*mirrors[i] == on)
                return;
            *mirrors[i] = on;
            SymmetryBox::remember(brush.symmetry);
            setBrush(brush);
        });
        m_mirrorActions[std::size_t(i)] = action;
    }
    menu->addSeparator();
    QAction* off = menu->addAction(tr("Symmetry &Off"));
    off->setObjectName(QStringLiteral("actionSymmetryOff"));
    off->setStatusTip(tr("No mirrored or radial copies of the dabs"));
    connect(off, &QAction::triggered, this, [this] {
        core::Brush brush = m_document->brush();
        brush.symmetry.mirrorX = brush.symmetry.mirrorY = brush.symmetry.mirrorZ = false;
        brush.symmetry.radial = 1;
        SymmetryBox::remember(brush.symmetry);
        setBrush(brush);
    });
    QAction* settings = menu->addAction(tr("Symmetry &Settings…"));
    settings->setObjectName(QStringLiteral("actionSymmetrySettings"));
    settings->setStatusTip(tr("Show the Brush panel's symmetry settings: the centre and radial "
                              "copies"));
    connect(settings, &QAction::triggered, this, [this] {
        m_brushDock->show();
        m_brushDock->raise();
        if (auto* scroll = qobject_cast<QScrollArea*>(m_brushDock->widget()))
            scroll->ensureWidgetVisible(m_brushPanel->symmetryBox());
    });

    // The same menu on the brush bar: symmetry without scrolling the Brush panel.
    m_symmetryButton = new QToolButton(this);
    m_symmetryButton->setObjectName(QStringLiteral("symmetryButton"));
    m_symmetryButton->setMenu(menu);
    m_symmetryButton->setPopupMode(QToolButton::InstantPopup);
    m_symmetryButton->setFocusPolicy(Qt::NoFocus); // keys stay with the view and shortcuts
    m_symmetryButton->setToolTip(tr("Symmetry: every dab repeated on the mirrored surface, "
                                    "also where it is hidden (radial copies in the Brush panel)"));
    m_brushBar->addSeparator();
    m_brushBar->addWidget(m_symmetryButton);
    showSymmetry(m_document->brush().symmetry);
    return menu;
}

void MainWindow::showSymmetry(const core::BrushSymmetry& symmetry) {
    const bool mirrors[3] = {symmetry.mirrorX, symmetry.mirrorY, symmetry.mirrorZ};
    QStringList on;
    for (int i = 0; i < 3; ++i) {
        if (QAction* action = m_mirrorActions[std::size_t(i)]) {
            const QSignalBlocker quiet(action);
            action->setChecked(mirrors[i]);
        }
        if (mirrors[i])
            on << QString(QChar('X' + i));
    }
    if (symmetry.radial > 1)
        on << tr("%1× radial").arg(symmetry.radial);
    if (m_symmetryButton)
        m_symmetryButton->setText(on.isEmpty() ? tr("Symmetry: off")
                                               : tr("Symmetry: %1").arg(on.join(QLatin1Char(' '))));
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
    // The stroke and the pop-ups it made are one step of the document's history; a stabilized
    // stroke's catch-up paints its last stretch here.
    core::PaintChanges changes;
    m_document->endStroke(changes);
    m_viewport->applyPaintChanges(changes);
    m_viewport->update(); // the stabilizer's string goes
    m_regionTools->endStroke();
}

void MainWindow::showDocumentState() {
    setBrush(m_document->brush());
    m_layerAwareAction->setChecked(m_document->layerAware());
    m_regionTools->autoPopUpAction()->setChecked(m_document->autoPopUp());
    m_segmentationControls->setOptions(m_document->depthLayerOptions());
    m_brushPanel->setPressureCurve(m_document->pressureCurve());
    m_targetSerial = m_document->paintTargetSerial();
    m_paintOptions = m_document->paintTargetOptions();
    if (m_document->hasPaintTarget())
        showPaintTarget();
    updateBrushBar();
    m_viewport->cameraMoved();
    m_regionTools->orderApplied();
    m_project->markModified();
}

void MainWindow::onHistoryApplied(const core::PaintChanges& changes) {
    m_viewport->applyPaintChanges(changes);
    if (m_document->paintTargetSerial() != m_targetSerial) {
        m_paintOptions = m_document->paintTargetOptions();
        showPaintTarget();
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
    if (core::needsUvLayout(m_document->mesh(), options)) {
        // Seconds on a big model: made off the GUI thread, adopted in paintTargetMade().
        m_targetJob->start(m_document->sharedMesh(), m_document->sharedTopology(), options,
                           m_document->meshSerial(), sourceDisplayName(m_source));
        statusBar()->showMessage(tr("Making an automatic UV layout…"));
        return;
    }
    m_targetJob->cancel(); // a layout still running would replace this choice
    const core::Status status = m_document->setPaintTarget(options);
    if (!status) {
        statusBar()->showMessage(
            tr("Cannot paint into that target: %1").arg(QString::fromStdString(status.error())),
            kStatusMessageMs);
    } else {
        m_paintOptions = options;
        showPaintTarget();
        statusBar()->showMessage(tr("Painting into a new target (Undo brings the previous one "
                                    "back)"),
                                 kStatusMessageMs);
    }
    updateBrushBar();
}

namespace {

/** Per material, the size of the page it is painted into now (empty for vertex colours). */
std::vector<core::PageSize> currentPageSizes(const core::Document& document) {
    std::vector<core::PageSize> sizes;
    const auto* target = dynamic_cast<const core::TextureTarget*>(document.currentPaintTarget());
    if (target == nullptr)
        return sizes;
    for (std::size_t m = 0; m < target->mesh().materials.size(); ++m) {
        const core::Image& page = target->page(target->materialPage(m));
        sizes.push_back({page.width, page.height});
    }
    return sizes;
}

} // namespace

void MainWindow::raiseTextureSize() {
    finishStroke();
    const bool texture = m_document->meshSerial() != 0 &&
                         m_document->paintTargetKind() == core::PaintTargetKind::Texture;
    const auto* target =
        texture ? dynamic_cast<const core::TextureTarget*>(m_document->paintTarget()) : nullptr;
    if (target == nullptr) {
        statusBar()->showMessage(tr("A texture's size can be raised while painting into a "
                                    "texture (Paint into, on the brush bar)"),
                                 kStatusMessageMs);
        return;
    }
    // The materials the triangles use (a loader may add one no triangle uses).
    const std::vector<core::PageSize> sizes = currentPageSizes(*m_document);
    const core::Mesh& mesh = target->mesh();
    std::vector<std::uint32_t> used;
    for (std::uint32_t m : mesh.triangleMaterial)
        if (m < sizes.size() && std::find(used.begin(), used.end(), m) == used.end())
            used.push_back(m);
    std::sort(used.begin(), used.end());
    QStringList materials;
    for (std::uint32_t m : used) {
        const QString name = mesh.materials[m].name.empty()
                                 ? tr("material %1").arg(m + 1)
                                 : QString::fromStdString(mesh.materials[m].name);
        materials.append(
            tr("%1. %2 (%3 × %4)").arg(m + 1).arg(name).arg(sizes[m].width).arg(sizes[m].height));
    }
    bool ok = !used.empty();
    qsizetype chosen = 0;
    if (materials.size() > 1)
        chosen = materials.indexOf(QInputDialog::getItem(
            this, tr("Raise Texture Size"), tr("The material whose texture gets larger:"),
            materials, 0, false, &ok));
    if (!ok || chosen < 0)
        return;
    const std::uint32_t material = used[std::size_t(chosen)];
    const core::PageSize now = sizes[material];
    QStringList choices;
    std::vector<int> widths;
    for (int width = now.width * 2; width <= 8192; width *= 2) {
        const qint64 height = (qint64(now.height) * width + now.width / 2) / now.width;
        if (height > 8192)
            break;
        choices.append(tr("%1 × %2").arg(width).arg(height));
        widths.push_back(width);
    }
    if (choices.isEmpty()) {
        statusBar()->showMessage(tr("That texture is as large as a texture can be (8192 texels "
                                    "on a side)"),
                                 kStatusMessageMs);
        return;
    }
    const QString size = QInputDialog::getItem(
        this, tr("Raise Texture Size"),
        tr("New size (now %1 × %2; what is painted is resampled):").arg(now.width).arg(now.height),
        choices, 0, false, &ok);
    if (!ok || !choices.contains(size))
        return;
    const core::Status status =
        m_document->raiseTextureSize(material, widths[std::size_t(choices.indexOf(size))]);
    if (!status) {
        statusBar()->showMessage(
            tr("Cannot raise the texture size: %1").arg(QString::fromStdString(status.error())),
            kStatusMessageMs);
    } else {
        showPaintTarget();
        statusBar()->showMessage(
            tr("The texture is %1 now (Undo brings the previous size back)").arg(size),
            kStatusMessageMs);
    }
    updateBrushBar();
}

void MainWindow::paintTargetMade(const std::shared_ptr<PaintTargetJob::Outcome>& outcome) {
    if (outcome->cancelled) {
        statusBar()->showMessage(tr("The automatic UV layout was cancelled; the paint target "
                                    "stays as it was"),
                                 kStatusMessageMs);
        updateBrushBar();
        return;
    }
    finishStroke();
    const bool replaces = m_document->hasPaintTarget();
    core::Status status = outcome->target
                              ? m_document->adoptPaintTarget(std::move(outcome->target),
                                                             outcome->options, outcome->meshSerial)
                              : core::Status(core::Error{outcome->error});
    if (!status) {
        statusBar()->showMessage(tr("Cannot paint into a texture with an automatic UV layout: %1")
                                     .arg(QString::fromStdString(status.error())),
                                 kStatusMessageMs);
    } else {
        m_paintOptions = outcome->options;
        showPaintTarget();
        statusBar()->showMessage(replaces ? tr("Painting into a texture with an automatic UV "
                                               "layout (Undo brings the previous target back)")
                                          : tr("Painting into a texture with an automatic UV "
                                               "layout"),
                                 kStatusMessageMs);
    }
    updateBrushBar();
}

void MainWindow::offerUvLayout() {
    // updateModelInfo() has said which target the model gets; the button offers the other.
    const bool texture = m_document->suggestedPaintTargetKind() == core::PaintTargetKind::Texture;
    core::PaintTargetOptions other = m_paintOptions;
    other.kind = texture ? core::PaintTargetKind::VertexColors : core::PaintTargetKind::Texture;
    m_messageBar->addButton(texture ? tr("Use Vertex Colours Instead")
                                    : tr("Paint into a Texture (Automatic UV Layout)"),
                            [this, other] { setPaintTarget(other); });
    if (texture) {
        core::PaintTargetOptions layout = m_paintOptions;
        layout.kind = core::PaintTargetKind::Texture;
        setPaintTarget(layout);
    }
}

void MainWindow::updateBrushBar() {
    m_brushBar->setTarget(m_paintOptions,
                          m_document->meshSerial() == 0 ? nullptr : &m_document->mesh(),
                          currentPageSizes(*m_document));
    const bool texture = m_document->meshSerial() == 0 ||
                         m_document->paintTargetKind() == core::PaintTargetKind::Texture;
    m_brushPanel->setMaterialChannels(
        texture, texture ? QString()
                         : tr("Vertex colours hold base colour only: roughness and metallic "
                              "need a texture as the paint target."));
    m_paintLayersPanel->refresh();
}

void MainWindow::setBrush(const core::Brush& brush) {
    m_document->brush() = brush; // the next stroke uses it
    m_brushBar->setBrush(brush);
    m_brushPanel->setBrush(brush);
    if (m_stabilizerAction)
        m_stabilizerAction->setChecked(brush.stabilizer);
    showSymmetry(brush.symmetry);
    const QColor color = BrushToolBar::toQColor(brush.color);
    if (color != m_colorPanel->foreground())
        m_colorPanel->setForeground(color);
    m_viewport->setBrushRadius(brush.radius);
    if (m_builder)
        m_builder->refreshSymmetry(); // new symmetry: its views build in the background
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

void MainWindow::showPaintTarget() {
    m_targetSerial = m_document->paintTargetSerial();
    m_viewport->paintTargetChanged();
}

void MainWindow::updatePaintIntoInfo() {
    const core::PaintLayerTarget* layers =
        m_document->meshSerial() != 0 && m_document->hasPaintTarget()
            ? m_document->currentPaintTarget()->paintLayers()
            : nullptr;
    const core::PaintSelection selection = layers ? layers->selection() : core::PaintSelection{};
    const auto index = layers && selection.layer != 0
                           ? layers->paintLayerStack().indexOf(selection.layer)
                           : std::nullopt;
    if (!index) {
        m_paintIntoInfo->clear();
        m_paintIntoInfo->setToolTip(QString());
        return;
    }
    const QString name =
        QString::fromStdString(layers->paintLayerStack().layer(*index).settings.name);
    // A mask is easily mistaken for the paint layer it belongs to: said in its own colour.
    m_paintIntoInfo->setText(selection.mask ? tr("Painting the mask of “%1”").arg(name)
                                            : tr("Painting “%1”").arg(name));
    m_paintIntoInfo->setStyleSheet(selection.mask ? QStringLiteral("color: #b35900;") : QString());
    m_paintIntoInfo->setToolTip(selection.mask
                                    ? tr("Strokes paint the mask: black hides the paint layer, "
                                         "white shows it")
                                    : tr("Strokes paint this paint layer"));
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

} // namespace ui
