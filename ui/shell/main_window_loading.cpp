// SPDX-License-Identifier: GPL-3.0-or-later
// The main window's loading and projects: a loaded model or project becomes the open document,
// the project state it saves and restores, load progress, failures and the model's summary.
#include "ui/shell/main_window.h"

#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QProgressDialog>
#include <QSignalBlocker>
#include <QStatusBar>

#include <utility>

#include "core/model/builtin_models.h"
#include "ui/commands/history_bridge.h"
#include "ui/panels/brush_toolbar.h"
#include "ui/panels/color_panel.h"
#include "ui/panels/segmentation_controls.h"
#include "ui/shell/elided_label.h"
#include "ui/shell/model_loader.h"
#include "ui/shell/notifier.h"
#include "ui/shell/project_controller.h"
#include "ui/shell/source_names.h"
#include "ui/tools/region_tools.h"
#include "ui/view/message_bar.h"
#include "ui/view/viewport.h"

namespace ui {

namespace {
constexpr int kProgressDelayMs = 400; // quick loads finish without a dialog flashing up
} // namespace

core::PaintTargetOptions MainWindow::newModelPaintOptions() const {
    // A new model starts with the preferred size for a new texture, on its own UVs.
    core::PaintTargetOptions options = m_paintOptions;
    options.resolution = m_preferences.textureSize;
    options.automaticUvs = false;
    return options;
}

void MainWindow::onLoaded(const QString& source, std::shared_ptr<LoadedModel> model) {
    stopProgress();
    const std::shared_ptr<const core::ProjectState>& state = model->state;
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
                .arg(sourceDisplayName(m_source),
                     QLocale().toString(QFileInfo(source).lastModified(), QLocale::ShortFormat));
    }
    updateModelInfo(*model->mesh, recoveredNote, !state);
    finishStroke();
    m_paintOptions = newModelPaintOptions();
    m_document->setPaintOptions(m_paintOptions);
    m_targetJob->cancel(); // a layout for the previous model
    m_document->setMesh(model->mesh, m_source.toStdString(), model->topology);
    // The paint target made with the model: the first frame shows it, the first stroke paints.
    if (model->paintTarget &&
        m_document->adoptModelPaintTarget(std::move(model->paintTarget), model->paintOptions))
        m_paintOptions = model->paintOptions;
    if (state) {
        applyProjectState(*state);
    } else {
        m_projectBase = {};
        if (!m_document->mesh().hasUvs()) {
            // Vertex colours until a texture is chosen (or its layout, made in the background,
            // arrives); the next model starts with the default again.
            m_paintOptions.kind.reset();
            m_document->setPaintOptions(m_paintOptions);
        }
    }
    m_viewport->meshChanged();
    if (m_document->hasPaintTarget())
        showPaintTarget();
    updateBrushBar();
    if (!state && !m_document->mesh().hasUvs())
        offerUvLayout();
    m_project->documentLoaded(source, state != nullptr,
                              state ? QString::fromStdString(state->recoveryFor) : QString(),
                              state ? QString::fromStdString(state->source) : QString());
    updateWindowTitle();
    if (!isBuiltinSource(source) && !m_project->isRecoveryFile(source)) {
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
    m_segmentationControls->setOptions(m_document->depthLayerOptions());
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

void MainWindow::onLoadFailed(const QString& source, const QString& message) {
    stopProgress();
    m_project->documentLoadFailed(source);
    if (!isBuiltinSource(source) && !QFileInfo(source).exists())
        m_recent.remove(source);
    statusBar()->showMessage(tr("Could not open %1").arg(sourceDisplayName(source)),
                             kStatusMessageMs);
    showError(tr("Open Failed"), tr("Could not open “%1”.").arg(sourceDisplayName(source)),
              message);
    emit loadFailed(message);
}

void MainWindow::onLoadCancelled(const QString& source) {
    stopProgress();
    statusBar()->showMessage(tr("Opening %1 cancelled").arg(sourceDisplayName(source)),
                             kStatusMessageMs);
}

void MainWindow::startProgress(const QString& source) {
    stopProgress();
    // Not modal: the current model stays usable, and setValue() never spins a nested loop.
    auto* dialog = new QProgressDialog(tr("Opening %1…").arg(sourceDisplayName(source)),
                                       tr("Cancel"), 0, kProgressSteps, this);
    dialog->setWindowTitle(tr("Opening Model"));
    dialog->setObjectName(QStringLiteral("loadProgress"));
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    dialog->setMinimumDuration(kProgressDelayMs);
    dialog->setValue(0);
    connect(dialog, &QProgressDialog::canceled, m_loader, &ModelLoader::cancel);
    m_progress = dialog;
    m_progressTimer.start();
    statusBar()->showMessage(tr("Opening %1…").arg(sourceDisplayName(source)));
}

void MainWindow::stopProgress() {
    m_progressTimer.stop();
    QProgressDialog* dialog = m_progress.data();
    m_progress = nullptr;
    // A cancelled dialog is hidden with its timer stopped, and this may run inside its canceled
    // signal: it goes once its click is handled. Any other is deleted at once: hidden and left for
    // deleteLater, its own minimum-duration timer could still show it.
    if (dialog && dialog->wasCanceled())
        dialog->deleteLater();
    else
        delete dialog;
}

void MainWindow::updateModelInfo(const core::Mesh& mesh, const QString& note, bool plainModel) {
    const QLocale locale;
    m_modelInfo->setText(tr("%1 — %2 vertices, %3 triangles")
                             .arg(sourceDisplayName(m_source),
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
    // Without UVs: a texture over an automatic UV layout where vertex colours would be coarse
    // (offerUvLayout() starts it and offers the other choice), else vertex colours.
    if (!mesh.hasUvs() && plainModel &&
        core::defaultTargetKind(mesh, core::Brush{}.radius) == core::PaintTargetKind::Texture)
        notes.append(tr("“%1” has no texture coordinates (UVs). Its vertices are far apart for "
                        "the brush, so it gets an automatic UV layout to paint into a texture.")
                         .arg(sourceDisplayName(m_source)));
    else if (!mesh.hasUvs())
        notes.append(tr("“%1” has no texture coordinates (UVs), so it is painted with vertex "
                        "colours: the paint's detail follows its vertices.")
                         .arg(sourceDisplayName(m_source)));
    // Whole, over the view, until dismissed: the status bar cuts long lines and moves on.
    if (warningCount > 0)
        m_messageBar->showMessage(
            MessageBar::Level::Warning,
            tr("Opening “%1” gave these warnings:").arg(sourceDisplayName(m_source)),
            warnings + notes);
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

void MainWindow::showError(const QString& title, const QString& text, const QString& details) {
    m_notifier->showError(title, text, details);
}

} // namespace ui
