// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/project_controller.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QLocale>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "core/document/document.h"
#include "core/io/export.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/paint_layers_export.h"
#include "core/io/project/project_file.h"
#include "core/model/builtin_models.h"
#include "core/paint/targets/paint_target.h"
#include "ui/commands/history_bridge.h"
#include "ui/shell/background_task.h"
#include "ui/shell/notifier.h"
#include "ui/shell/source_names.h"

namespace ui {

namespace {
const QString kIntervalKey = QStringLiteral("autosave/intervalMinutes");
const QString kDirectoryKey = QStringLiteral("project/directory");
const QString kExportDirectoryKey = QStringLiteral("export/directory");
const QString kExportPerLayerKey = QStringLiteral("export/perPaintLayer");
constexpr int kProgressSteps = 1000;
constexpr int kProgressDelayMs = 400;
constexpr int kStatusMs = 6000;
constexpr qint64 kIdleTickMs = 60000; // how often a disabled autosave looks at the setting again

std::string encodePath(const QString& path) {
    return QFile::encodeName(path).toStdString();
}

QString fromCore(const std::string& message) {
    return QString::fromStdString(message);
}
} // namespace

struct ProjectController::Snapshot {
    core::Mesh mesh;
    core::ProjectState state;
    std::vector<core::Image> pages; // texture exports only
    /** Per page (texture exports) or mesh texture: the metallic-roughness composite. */
    std::vector<core::Image> metallicRoughness;
    /** Exports with one image per paint layer: a copy of the paint layers. */
    std::optional<core::PaintLayerExport> paintLayers;
    quint64 serial = 0;
};

ProjectController::ProjectController(core::Document& document, HistoryBridge& history,
                                     Notifier& notifier,
                                     std::function<core::ProjectState()> projectState)
    : QObject(&notifier), m_document(document), m_history(history), m_notifier(notifier),
      m_projectState(std::move(projectState)), m_task(new BackgroundTask(this)),
      m_autosave(new BackgroundTask(this)) {
    m_sessionId = QStringLiteral("%1-%2")
                      .arg(QCoreApplication::applicationPid())
                      .arg(QDateTime::currentMSecsSinceEpoch(), 0, 36);
    connect(&m_history, &HistoryBridge::changed, this, [this] {
        ++m_changeSerial;
        updateModified();
    });
    connect(&m_history, &HistoryBridge::cleanChanged, this, &ProjectController::updateModified);
    connect(m_autosave, &BackgroundTask::finished, this, [this](const QString& error, bool) {
        if (error.isEmpty()) {
            m_notifier.showStatus(tr("Autosaved"), kStatusMs / 2);
            emit autosaved(autosavePath());
        } else {
            m_autosavedSerial = 0; // try again at the next tick
            m_notifier.showStatus(tr("Autosave failed: %1").arg(error), kStatusMs);
        }
    });
    m_progressTimer.setInterval(50);
    connect(&m_progressTimer, &QTimer::timeout, this, [this] {
        if (m_progress)
            m_progress->setValue(int(m_task->progress() * kProgressSteps));
    });
    connect(&m_autosaveTimer, &QTimer::timeout, this, &ProjectController::onAutosaveTimer);
    reloadAutosaveInterval();
}

ProjectController::~ProjectController() {
    m_task->wait();
    m_autosave->wait();
}

QString ProjectController::documentName() const {
    return m_filePath.isEmpty() ? m_modelName : QFileInfo(m_filePath).fileName();
}

bool ProjectController::isModified() const {
    return m_otherChanges || !m_history.isClean();
}

void ProjectController::markModified() {
    ++m_changeSerial;
    m_otherChanges = true;
    updateModified();
}

void ProjectController::updateModified() {
    const bool modified = isModified();
    if (modified == m_lastModified)
        return;
    m_lastModified = modified;
    emit modifiedChanged(modified);
}

void ProjectController::documentLoaded(const QString& source, bool isProject,
                                       const QString& recoveryFor, const QString& modelSource) {
    const bool recovered = !m_recovering.isEmpty() && source == m_recovering;
    m_history.markSaved();
    m_otherChanges = recovered; // recovered work is not saved anywhere yet
    if (recovered) {
        m_filePath = recoveryFor;
        m_modelName = sourceDisplayName(modelSource.isEmpty() ? source : modelSource);
        m_recovering.clear();
        m_autosavedSerial = m_changeSerial; // the autosave file holds exactly this
    } else {
        m_filePath = isProject ? source : QString();
        m_modelName = sourceDisplayName(source);
        m_autosavedSerial = m_changeSerial;
    }
    emit documentNameChanged();
    updateModified();
}

void ProjectController::documentLoadFailed(const QString& source) {
    if (source == m_recovering)
        m_recovering.clear(); // the file stays, as this session's autosave
}

bool ProjectController::samePath(const QString& a, const QString& b) {
    const QFileInfo fa(a), fb(b);
    if (fa.exists() && fb.exists())
        return fa.canonicalFilePath() == fb.canonicalFilePath(); // links and ".." agree
    return fa.absoluteFilePath() == fb.absoluteFilePath();
}

bool ProjectController::isOpenDocumentFile(const QString& path) const {
    const QString source = currentSource();
    return (!m_filePath.isEmpty() && samePath(path, m_filePath)) ||
           (!source.isEmpty() && !source.startsWith(QLatin1String(core::kBuiltinPrefix)) &&
            samePath(path, source));
}

QString ProjectController::currentSource() const {
    return QString::fromStdString(m_document.name());
}

bool ProjectController::isRecoveryFile(const QString& source) const {
    return QFileInfo(source).absolutePath() == QDir(recoveryFolder()).absolutePath();
}

// ---------------------------------------------------------------------------------------------
// Saving

std::shared_ptr<ProjectController::Snapshot> ProjectController::snapshot(QString& why) const {
    const core::Document& doc = m_document;
    if (doc.meshSerial() == 0 || doc.mesh().triangleCount() == 0) {
        why = tr("There is no model to save.");
        return nullptr;
    }
    auto snap = std::make_shared<Snapshot>();
    snap->mesh = doc.paintedMesh();
    snap->state = m_projectState();
    snap->serial = m_changeSerial;
    return snap;
}

bool ProjectController::isBusy() const {
    return m_task->isRunning();
}

void ProjectController::waitForTasks() {
    m_task->wait();
    m_autosave->wait();
}

bool ProjectController::save() {
    if (m_filePath.isEmpty())
        return saveAs();
    return saveTo(m_filePath);
}

QString ProjectController::askSavePath() {
    QSettings settings;
    QString suggestion = m_filePath;
    if (suggestion.isEmpty()) {
        const QString source = currentSource();
        const bool builtin = source.startsWith(QLatin1String(core::kBuiltinPrefix));
        const QString stem = builtin ? source.mid(int(std::strlen(core::kBuiltinPrefix)))
                                     : QFileInfo(source).completeBaseName();
        const QString folder =
            settings
                .value(kDirectoryKey, builtin ? QDir::homePath() : QFileInfo(source).absolutePath())
                .toString();
        suggestion = QDir(folder).filePath(stem + QStringLiteral(".glb"));
        // Never suggest writing over the model that was opened.
        if (QFileInfo(suggestion).absoluteFilePath() == QFileInfo(source).absoluteFilePath())
            suggestion = QDir(folder).filePath(stem + QStringLiteral("-painted.glb"));
    }
    QString path = QFileDialog::getSaveFileName(
        m_notifier.dialogParent(), tr("Save Project"), suggestion,
        tr("LayerPaint projects (*.glb)") + QStringLiteral(";;") + tr("All files (*)"));
    if (path.isEmpty())
        return {};
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".glb");
    settings.setValue(kDirectoryKey, QFileInfo(path).absolutePath());
    return path;
}

bool ProjectController::saveAs() {
    const QString path = askSavePath();
    return !path.isEmpty() && saveTo(path);
}

bool ProjectController::saveTo(const QString& given) {
    if (m_task->isRunning()) {
        m_notifier.showStatus(tr("Still busy with the last save or export"), kStatusMs);
        return false;
    }
    QString path = QFileInfo(given).absoluteFilePath();
    if (QFileInfo(path).suffix().isEmpty())
        path += QStringLiteral(".glb");
    QString why;
    const std::shared_ptr<Snapshot> snap = snapshot(why);
    if (!snap) {
        m_notifier.showError(tr("Save Failed"), tr("Could not save."), why);
        emit saveFailed(why);
        return false;
    }
    const std::string file = encodePath(path);
    startProgress(tr("Saving %1…").arg(QFileInfo(path).fileName()));
    connect(
        m_task, &BackgroundTask::finished, this,
        [this, snap, path](const QString& error, bool cancelled) {
            onSaveFinished(snap, path, error, cancelled);
        },
        Qt::SingleShotConnection);
    m_task->start([snap, file](const core::ProgressFn& progress) {
        const core::Status s = core::saveProject(file, snap->mesh, snap->state, progress);
        return s ? QString() : fromCore(s.error());
    });
    return true;
}

void ProjectController::onSaveFinished(const std::shared_ptr<Snapshot>& snap, const QString& path,
                                       const QString& error, bool cancelled) {
    stopProgress();
    if (!error.isEmpty()) {
        if (cancelled) {
            m_notifier.showStatus(tr("Saving cancelled; the file was not changed"), kStatusMs);
        } else {
            m_notifier.showStatus(tr("Could not save %1").arg(QFileInfo(path).fileName()),
                                  kStatusMs);
            m_notifier.showError(tr("Save Failed"),
                                 tr("Could not save “%1”. The file on disk was not changed.")
                                     .arg(QFileInfo(path).fileName()),
                                 error);
        }
        emit saveFailed(error);
        return;
    }
    m_filePath = path;
    if (snap->serial == m_changeSerial) {
        // Nothing changed while it was written: what is shown is what is saved.
        m_history.markSaved();
        m_otherChanges = false;
        // Nothing left to recover.
        m_autosave->wait();
        QFile::remove(autosavePath());
        m_autosavedSerial = m_changeSerial;
    }
    emit documentNameChanged();
    updateModified();
    m_notifier.showStatus(tr("Saved %1").arg(QFileInfo(path).fileName()), kStatusMs);
    emit saved(path);
}

bool ProjectController::saveAndWait(const QString& path) {
    m_task->wait();
    bool ok = false, done = false;
    QEventLoop loop;
    const auto onSaved = connect(this, &ProjectController::saved, &loop, [&] {
        ok = true;
        done = true;
        loop.quit();
    });
    const auto onFailed = connect(this, &ProjectController::saveFailed, &loop, [&] {
        done = true;
        loop.quit();
    });
    if (saveTo(path)) {
        if (m_progress)
            m_progress->setWindowModality(Qt::ApplicationModal); // nothing else may happen now
        if (!done)
            loop.exec();
    }
    disconnect(onSaved);
    disconnect(onFailed);
    return ok;
}

bool ProjectController::maybeSave() {
    if (!isModified())
        return true;
    if (!m_notifier.dialogsEnabled())
        return true; // tests: no modal questions, the changes go
    QMessageBox box(QMessageBox::Warning, tr("Unsaved Changes"),
                    tr("“%1” has unsaved changes.").arg(documentName()),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel,
                    m_notifier.dialogParent());
    box.setInformativeText(tr("Do you want to save them?"));
    box.setDefaultButton(QMessageBox::Save);
    box.setObjectName(QStringLiteral("unsavedChangesBox"));
    const int answer = box.exec();
    if (answer == QMessageBox::Discard)
        return true;
    if (answer != QMessageBox::Save)
        return false;
    const QString path = m_filePath.isEmpty() ? askSavePath() : m_filePath;
    return !path.isEmpty() && saveAndWait(path);
}

// ---------------------------------------------------------------------------------------------
// Export

bool ProjectController::canExportTexture() const {
    const core::Document& doc = m_document;
    return doc.meshSerial() != 0 && doc.mesh().hasUvs() &&
           doc.paintTargetKind() == core::PaintTargetKind::Texture;
}

void ProjectController::showExportDialog(core::ExportFormat format) {
    QString filter;
    switch (format) {
    case core::ExportFormat::Glb:
        filter = tr("glTF binary (*.glb)");
        break;
    case core::ExportFormat::Obj:
        filter = tr("Wavefront OBJ (*.obj)");
        break;
    case core::ExportFormat::Ply:
        filter = tr("Stanford PLY (*.ply)");
        break;
    case core::ExportFormat::Png8:
    case core::ExportFormat::Png16:
        filter = tr("PNG image (*.png)");
        break;
    case core::ExportFormat::Tiff:
        filter = tr("TIFF image (*.tif *.tiff)");
        break;
    case core::ExportFormat::Exr:
        filter = tr("OpenEXR image (*.exr)");
        break;
    }
    QSettings settings;
    const QString stem = QFileInfo(documentName()).completeBaseName();
    const QString folder =
        settings
            .value(kExportDirectoryKey,
                   m_filePath.isEmpty() ? QDir::homePath() : QFileInfo(m_filePath).absolutePath())
            .toString();
    const QString suffix = QString::fromLatin1(core::exportExtension(format));
    QString suggestion = QDir(folder).filePath(
        (core::isTextureFormat(format) ? stem + QStringLiteral("-paint") : stem) + suffix);
    // Never propose the open project (a .glb too) or the model it was painted from.
    if (isOpenDocumentFile(suggestion))
        suggestion = QDir(folder).filePath(stem + QStringLiteral("-export") + suffix);
    // Qt's own dialog, which can hold the check box (a platform one cannot).
    QFileDialog dialog(m_notifier.dialogParent(), tr("Export"), suggestion,
                       filter + QStringLiteral(";;") + tr("All files (*)"));
    dialog.setObjectName(QStringLiteral("exportDialog"));
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setFileMode(QFileDialog::AnyFile);
    dialog.selectFile(suggestion);
    auto* perLayer = new QCheckBox(tr("Also write each &paint layer as images"), &dialog);
    perLayer->setObjectName(QStringLiteral("exportPerPaintLayer"));
    const bool layers = hasPaintLayers();
    perLayer->setEnabled(layers);
    perLayer->setChecked(layers && settings.value(kExportPerLayerKey, false).toBool());
    perLayer->setToolTip(
        layers ? tr("Beside the export, per paint layer: NAME_layer-N-LAYER_basecolor.png and its "
                    "roughness, metallic and mask images, as the command line's --per-layer")
               : tr("The model has no paint layers"));
    if (auto* grid = qobject_cast<QGridLayout*>(dialog.layout()))
        grid->addWidget(perLayer, grid->rowCount(), 0, 1, grid->columnCount());
    else
        dialog.layout()->addWidget(perLayer);
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return;
    QString path = dialog.selectedFiles().constFirst();
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += suffix;
    settings.setValue(kExportDirectoryKey, QFileInfo(path).absolutePath());
    if (layers)
        settings.setValue(kExportPerLayerKey, perLayer->isChecked());
    exportTo(format, path, layers && perLayer->isChecked());
}

bool ProjectController::hasPaintLayers() const {
    const core::PaintTarget* painted = m_document.currentPaintTarget();
    return painted && painted->paintLayers() &&
           painted->paintLayers()->paintLayerStack().size() > 0;
}

bool ProjectController::exportTo(core::ExportFormat format, const QString& given,
                                 bool perPaintLayer) {
    if (m_task->isRunning()) {
        m_notifier.showStatus(tr("Still busy with the last save or export"), kStatusMs);
        return false;
    }
    const QString path = QFileInfo(given).absoluteFilePath();
    if (m_document.meshSerial() == 0 || m_document.mesh().triangleCount() == 0)
        return false;
    if (!m_filePath.isEmpty() && samePath(path, m_filePath)) {
        refuseExportOverProject(path);
        return false;
    }
    auto snap = std::make_shared<Snapshot>();
    const bool ready =
        core::isTextureFormat(format) ? snapshotPaintTexture(*snap) : snapshotPaintedModel(*snap);
    if (!ready || (perPaintLayer && !snapshotPaintLayers(*snap)))
        return false;
    startProgress(tr("Exporting %1…").arg(QFileInfo(path).fileName()));
    startExport(format, path, snap);
    return true;
}

void ProjectController::refuseExportOverProject(const QString& path) {
    // An export keeps no LayerPaint state: written over the project, it would lose it.
    const QString name = QFileInfo(path).fileName();
    const QString why =
        tr("“%1” is the open project. Exporting there would replace it with a plain model "
           "without its LayerPaint settings. Choose another name, or use File ▸ Save.")
            .arg(name);
    m_notifier.showStatus(tr("Not exported: “%1” is the open project").arg(name), kStatusMs);
    m_notifier.showError(tr("Export Refused"), tr("Could not export to “%1”.").arg(name), why);
    emit exportFailed(why);
}

bool ProjectController::snapshotPaintTexture(Snapshot& snap) {
    std::string error;
    const core::PaintTarget* painted = nullptr;
    if (canExportTexture()) {
        const core::Result<core::PaintTarget*> target = m_document.ensurePaintTarget();
        if (target)
            painted = *target;
        else
            error = target.error();
    }
    if (!painted || painted->pageCount() == 0) {
        const QString why = error.empty()
                                ? tr("The model is painted with vertex colours, so there is no "
                                     "paint texture: export it as glTF or PLY.")
                                : fromCore(error);
        m_notifier.showError(tr("Export Failed"), tr("Could not export the paint texture."), why);
        emit exportFailed(why);
        return false;
    }
    for (std::size_t i = 0; i < painted->pageCount(); ++i) {
        snap.pages.push_back(painted->page(i));
        snap.metallicRoughness.push_back(painted->metallicRoughnessPage(i));
    }
    return true;
}

bool ProjectController::snapshotPaintedModel(Snapshot& snap) const {
    snap.mesh = m_document.paintedMesh();
    // The painted mesh's texture i is page i: its roughness and metallic go beside it.
    if (const core::PaintTarget* painted = m_document.currentPaintTarget())
        for (std::size_t i = 0; i < painted->pageCount(); ++i)
            snap.metallicRoughness.push_back(painted->metallicRoughnessPage(i));
    return true;
}

bool ProjectController::snapshotPaintLayers(Snapshot& snap) {
    const core::PaintTarget* painted = m_document.currentPaintTarget();
    const core::PaintLayerTarget* layers = painted ? painted->paintLayers() : nullptr;
    if (!layers) {
        const QString why = tr("There are no paint layers to export (they need a paint "
                               "texture).");
        m_notifier.showError(tr("Export Failed"), tr("Could not export the paint layers."), why);
        emit exportFailed(why);
        return false;
    }
    snap.paintLayers = core::paintLayerExport(layers->paintLayerStack());
    return true;
}

void ProjectController::startExport(core::ExportFormat format, const QString& path,
                                    const std::shared_ptr<Snapshot>& snap) {
    auto files = std::make_shared<QStringList>();
    connect(
        m_task, &BackgroundTask::finished, this,
        [this, files, path](const QString& error, bool cancelled) {
            stopProgress();
            if (!error.isEmpty()) {
                if (cancelled) {
                    m_notifier.showStatus(tr("Export cancelled"), kStatusMs);
                } else {
                    m_notifier.showError(
                        tr("Export Failed"),
                        tr("Could not export “%1”.").arg(QFileInfo(path).fileName()), error);
                }
                emit exportFailed(error);
                return;
            }
            m_notifier.showStatus(
                tr("Exported %n file(s) to %1", nullptr, int(files->size()))
                    .arg(QDir::toNativeSeparators(QFileInfo(path).absolutePath())),
                kStatusMs);
            emit exported(*files);
        },
        Qt::SingleShotConnection);
    const std::string file = encodePath(path);
    m_task->start([snap, files, file, format](const core::ProgressFn& progress) {
        // With the paint layers, the export is the first half of the progress, they the second.
        const double share = snap->paintLayers ? 0.5 : 1.0;
        const core::ProgressFn first = [&](double f) {
            return core::reportProgress(progress, f * share);
        };
        core::Result<std::vector<std::string>> written =
            core::isTextureFormat(format)
                ? core::exportChannelTextures(file, format, snap->pages, snap->metallicRoughness,
                                              first)
                : core::exportMaterial(file, format, snap->mesh,
                                       core::MaterialChannels{snap->metallicRoughness}, first);
        if (!written)
            return fromCore(written.error());
        if (snap->paintLayers) {
            core::Result<std::vector<std::string>> layers =
                core::exportPaintLayerImages(file, *snap->paintLayers, [&](double f) {
                    return core::reportProgress(progress, 0.5 + 0.5 * f);
                });
            if (!layers)
                return fromCore(layers.error());
            written->insert(written->end(), layers->begin(), layers->end());
        }
        // Read on the GUI thread only after the job finished.
        for (const std::string& f : *written)
            files->append(QFile::decodeName(QByteArray::fromStdString(f)));
        return QString();
    });
}

// ---------------------------------------------------------------------------------------------
// Progress

void ProjectController::startProgress(const QString& text) {
    stopProgress();
    auto* dialog =
        new QProgressDialog(text, tr("Cancel"), 0, kProgressSteps, m_notifier.dialogParent());
    dialog->setObjectName(QStringLiteral("projectProgress"));
    dialog->setWindowTitle(tr("LayerPaint"));
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    dialog->setMinimumDuration(kProgressDelayMs);
    dialog->setValue(0);
    connect(dialog, &QProgressDialog::canceled, m_task, &BackgroundTask::cancel);
    m_progress = dialog;
    m_progressTimer.start();
    m_notifier.showStatus(text);
}

void ProjectController::stopProgress() {
    m_progressTimer.stop();
    delete m_progress.data(); // at once: a hidden dialog could still pop up by its own timer
    m_progress = nullptr;
}

// ---------------------------------------------------------------------------------------------
// Autosave and recovery

QString ProjectController::recoveryFolder() {
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
        .filePath(QStringLiteral("recovery"));
}

QString ProjectController::autosavePath() const {
    return QDir(recoveryFolder()).filePath(QStringLiteral("autosave-%1.glb").arg(m_sessionId));
}

bool ProjectController::takeLock() {
    if (m_lock)
        return true;
    if (!QDir().mkpath(recoveryFolder()))
        return false;
    auto lock = std::make_unique<QLockFile>(
        QDir(recoveryFolder()).filePath(QStringLiteral("autosave-%1.lock").arg(m_sessionId)));
    if (!lock->tryLock(0))
        return false;
    m_lock = std::move(lock);
    return true;
}

void ProjectController::reloadAutosaveInterval() {
    bool ok = false;
    double minutes = QSettings().value(kIntervalKey, kDefaultAutosaveMinutes).toDouble(&ok);
    if (!ok || !std::isfinite(minutes) || minutes < 0.0)
        minutes = kDefaultAutosaveMinutes;
    m_autosaveIntervalMs = qint64(std::min(minutes, 24.0 * 60.0) * 60000.0);
    const qint64 tick =
        m_autosaveIntervalMs > 0 ? std::max<qint64>(m_autosaveIntervalMs, 200) : kIdleTickMs;
    if (m_autosaveTimer.interval() != int(tick) || !m_autosaveTimer.isActive())
        m_autosaveTimer.start(int(tick));
}

void ProjectController::onAutosaveTimer() {
    reloadAutosaveInterval();
    if (m_autosaveIntervalMs > 0)
        autosaveNow();
}

bool ProjectController::autosaveNow() {
    if (!isModified() || m_changeSerial == m_autosavedSerial || m_autosave->isRunning() ||
        !m_recovering.isEmpty())
        return false;
    QString why;
    const std::shared_ptr<Snapshot> snap = snapshot(why);
    if (!snap || !takeLock())
        return false;
    snap->state.recoveryFor = encodePath(m_filePath);
    if (snap->state.source.empty())
        snap->state.source = encodePath(currentSource());
    m_autosavedSerial = snap->serial;
    const std::string file = encodePath(autosavePath());
    m_autosave->start([snap, file](const core::ProgressFn&) {
        // No backup: a recovery file is itself the copy; no progress: nobody waits for it.
        const core::Status s = core::saveProject(file, snap->mesh, snap->state, {}, false);
        return s ? QString() : fromCore(s.error());
    });
    return true;
}

void ProjectController::discardRecovery() {
    m_autosave->wait();
    QFile::remove(autosavePath());
    if (m_lock) {
        m_lock->unlock(); // removes the lock file
        m_lock.reset();
    }
}

bool ProjectController::offerRecovery() {
    if (!m_notifier.dialogsEnabled())
        return false;
    const QDir folder(recoveryFolder());
    QFileInfoList candidates =
        folder.entryInfoList({QStringLiteral("autosave-*.glb")}, QDir::Files, QDir::Time);
    for (const QFileInfo& candidate : candidates) {
        if (candidate.absoluteFilePath() == QFileInfo(autosavePath()).absoluteFilePath())
            continue;
        // Its session still runs while it holds the lock (a live process never goes stale).
        QLockFile probe(folder.filePath(candidate.completeBaseName() + QStringLiteral(".lock")));
        probe.setStaleLockTime(0);
        if (!probe.tryLock(0))
            continue;

        QString belongsTo, source;
        core::Result<nlohmann::json> extras = core::readGlbExtras(encodePath(candidate.filePath()));
        if (extras && extras->contains("layerpaint") && (*extras)["layerpaint"].is_object()) {
            const nlohmann::json& lp = (*extras)["layerpaint"];
            if (lp.contains("recovery_for") && lp["recovery_for"].is_string())
                belongsTo = QFile::decodeName(
                    QByteArray::fromStdString(lp["recovery_for"].get<std::string>()));
            if (lp.contains("source") && lp["source"].is_string())
                source =
                    QFile::decodeName(QByteArray::fromStdString(lp["source"].get<std::string>()));
        }
        const QString name =
            belongsTo.isEmpty()
                ? tr("an unsaved painting of %1")
                      .arg(sourceDisplayName(source.isEmpty() ? candidate.fileName() : source))
                : QStringLiteral("“%1”").arg(QFileInfo(belongsTo).fileName());
        QMessageBox box(
            QMessageBox::Question, tr("Recover Unsaved Work"),
            tr("LayerPaint was not closed properly. Work on %1 was autosaved at %2.")
                .arg(name, QLocale().toString(candidate.lastModified(), QLocale::ShortFormat)),
            QMessageBox::NoButton, m_notifier.dialogParent());
        box.setObjectName(QStringLiteral("recoveryBox"));
        box.setInformativeText(tr("Recover it? It opens as an unsaved document."));
        QPushButton* recover = box.addButton(tr("&Recover"), QMessageBox::AcceptRole);
        recover->setObjectName(QStringLiteral("recoverButton"));
        QPushButton* discard = box.addButton(tr("&Discard"), QMessageBox::DestructiveRole);
        discard->setObjectName(QStringLiteral("discardButton"));
        QPushButton* later = box.addButton(tr("&Not Now"), QMessageBox::RejectRole);
        later->setObjectName(QStringLiteral("notNowButton"));
        box.setDefaultButton(recover);
        box.exec();
        if (box.clickedButton() == discard) {
            QFile::remove(candidate.filePath());
            probe.unlock();
            continue; // the next one, if any
        }
        if (box.clickedButton() != recover)
            return false; // kept for the next start
        // Adopt it as this session's autosave: this session's lock protects it from now on.
        if (!takeLock())
            return false;
        QFile::remove(autosavePath());
        if (!QFile::rename(candidate.filePath(), autosavePath()))
            return false;
        probe.unlock();
        m_recovering = QFileInfo(autosavePath()).absoluteFilePath();
        emit openRequested(m_recovering);
        return true;
    }
    return false;
}

} // namespace ui
