// SPDX-License-Identifier: GPL-3.0-or-later
// The project controller's export: the Export dialog, what is exported copied on the GUI thread
// (the paint texture, the painted model, the paint layers) and written on the worker.
#include "ui/shell/project_controller.h"

#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QSettings>

#include <filesystem>

#include "core/document/document.h"
#include "core/io/export.h"
#include "core/io/paint_layers_export.h"
#include "core/paint/targets/paint_target.h"
#include "ui/shell/background_task.h"
#include "ui/shell/notifier.h"
#include "ui/shell/project_snapshot.h"
#include "ui/shell/texture_export_dialog.h"

namespace ui {

namespace {
const QString kExportDirectoryKey = QStringLiteral("export/directory");
const QString kExportPerLayerKey = QStringLiteral("export/perPaintLayer");
const QString kTextureExportFolderKey = QStringLiteral("textureExport/folder");
} // namespace

bool ProjectController::canExportTexture() const {
    const core::Document& doc = m_document;
    return doc.meshSerial() != 0 && doc.mesh().hasUvs() &&
           doc.paintTargetKind() == core::PaintTargetKind::Texture;
}

QString ProjectController::exportFilter(core::ExportFormat format) {
    switch (format) {
    case core::ExportFormat::Glb:
        return tr("glTF binary (*.glb)");
    case core::ExportFormat::Obj:
        return tr("Wavefront OBJ (*.obj)");
    case core::ExportFormat::Ply:
        return tr("Stanford PLY (*.ply)");
    case core::ExportFormat::Png8:
    case core::ExportFormat::Png16:
        return tr("PNG image (*.png)");
    case core::ExportFormat::Tiff:
        return tr("TIFF image (*.tif *.tiff)");
    case core::ExportFormat::Exr:
        return tr("OpenEXR image (*.exr)");
    }
    return {};
}

QString ProjectController::suggestExportPath(core::ExportFormat format,
                                             const QString& folder) const {
    const QString stem = QFileInfo(documentName()).completeBaseName();
    const QString suffix = QString::fromLatin1(core::exportExtension(format));
    const QString suggestion = QDir(folder).filePath(
        (core::isTextureFormat(format) ? stem + QStringLiteral("-paint") : stem) + suffix);
    // Never propose the open project (a .glb too) or the model it was painted from.
    if (isOpenDocumentFile(suggestion))
        return QDir(folder).filePath(stem + QStringLiteral("-export") + suffix);
    return suggestion;
}

QCheckBox* ProjectController::addPerPaintLayerBox(QFileDialog& dialog, bool hasLayers,
                                                  bool checked) {
    auto* perLayer = new QCheckBox(tr("Also write each &paint layer as images"), &dialog);
    perLayer->setObjectName(QStringLiteral("exportPerPaintLayer"));
    perLayer->setEnabled(hasLayers);
    perLayer->setChecked(checked);
    perLayer->setToolTip(
        hasLayers
            ? tr("Beside the export, per paint layer: NAME_layer-N-LAYER_basecolor.png and its "
                 "roughness, metallic and mask images, as the command line's --per-layer")
            : tr("The model has no paint layers"));
    if (auto* grid = qobject_cast<QGridLayout*>(dialog.layout()))
        grid->addWidget(perLayer, grid->rowCount(), 0, 1, grid->columnCount());
    else
        dialog.layout()->addWidget(perLayer);
    return perLayer;
}

void ProjectController::showExportDialog(core::ExportFormat format) {
    QSettings settings;
    const QString folder =
        settings
            .value(kExportDirectoryKey,
                   m_filePath.isEmpty() ? QDir::homePath() : QFileInfo(m_filePath).absolutePath())
            .toString();
    const QString suffix = QString::fromLatin1(core::exportExtension(format));
    const QString suggestion = suggestExportPath(format, folder);
    // Qt's own dialog, which can hold the check box (a platform one cannot).
    QFileDialog dialog(m_notifier.dialogParent(), tr("Export"), suggestion,
                       exportFilter(format) + QStringLiteral(";;") + tr("All files (*)"));
    dialog.setObjectName(QStringLiteral("exportDialog"));
    dialog.setOption(QFileDialog::DontUseNativeDialog);
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    dialog.setFileMode(QFileDialog::AnyFile);
    dialog.selectFile(suggestion);
    const bool layers = hasPaintLayers();
    QCheckBox* perLayer = addPerPaintLayerBox(
        dialog, layers, layers && settings.value(kExportPerLayerKey, false).toBool());
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

const core::PaintTarget* ProjectController::paintTextureToExport() {
    std::string error;
    const core::PaintTarget* painted = nullptr;
    if (canExportTexture()) {
        const core::Result<core::PaintTarget*> target = m_document.ensurePaintTarget();
        if (target)
            painted = *target;
        else
            error = target.error();
    }
    if (painted && painted->pageCount() > 0)
        return painted;
    const QString why = error.empty()
                            ? tr("The model is painted with vertex colours, so there is no "
                                 "paint texture: export it as glTF or PLY.")
                            : fromCore(error);
    m_notifier.showError(tr("Export Failed"), tr("Could not export the paint texture."), why);
    emit exportFailed(why);
    return nullptr;
}

bool ProjectController::snapshotPaintTexture(Snapshot& snap) {
    const core::PaintTarget* painted = paintTextureToExport();
    if (!painted)
        return false;
    for (std::size_t i = 0; i < painted->pageCount(); ++i) {
        snap.pages.push_back(painted->page(i));
        snap.metallicRoughness.push_back(painted->metallicRoughnessPage(i));
    }
    return true;
}

bool ProjectController::snapshotPaintedModel(Snapshot& snap) const {
    // The painted mesh carries its materials' maps, painted roughness and metallic included.
    snap.mesh = m_document.paintedMesh();
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
    auto warnings = std::make_shared<std::vector<std::string>>();
    finishExportWhenDone(path, files, warnings);
    const std::string file = encodePath(path);
    m_task->start([snap, files, warnings, file, format](const core::ProgressFn& progress) {
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
                                       core::MaterialChannels{snap->metallicRoughness}, first,
                                       warnings.get());
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

void ProjectController::finishExportWhenDone(
    const QString& path, const std::shared_ptr<QStringList>& files,
    const std::shared_ptr<std::vector<std::string>>& warnings) {
    connect(
        m_task, &BackgroundTask::finished, this,
        [this, files, warnings, path](const QString& error, bool cancelled) {
            finishExport(path, *files, *warnings, error, cancelled);
        },
        Qt::SingleShotConnection);
}

void ProjectController::finishExport(const QString& path, const QStringList& files,
                                     const std::vector<std::string>& warnings, const QString& error,
                                     bool cancelled) {
    stopProgress();
    if (!error.isEmpty()) {
        if (cancelled) {
            m_notifier.showStatus(tr("Export cancelled"), kStatusMs);
        } else {
            m_notifier.showError(tr("Export Failed"),
                                 tr("Could not export “%1”.").arg(QFileInfo(path).fileName()),
                                 error);
        }
        emit exportFailed(error);
        return;
    }
    const QString folder = QFileInfo(path).isDir() ? path : QFileInfo(path).absolutePath();
    m_notifier.showStatus(tr("Exported %n file(s) to %1", nullptr, int(files.size()))
                              .arg(QDir::toNativeSeparators(QDir(folder).absolutePath())),
                          kStatusMs);
    showUnkept(path, warnings);
    emit exported(files);
}

void ProjectController::showTextureExportDialog() {
    if (!paintTextureToExport())
        return;
    QSettings settings;
    const QString folder =
        settings
            .value(kTextureExportFolderKey,
                   settings.value(kExportDirectoryKey, m_filePath.isEmpty()
                                                           ? QDir::homePath()
                                                           : QFileInfo(m_filePath).absolutePath()))
            .toString();
    QString stem = QFileInfo(documentName()).completeBaseName();
    TextureExportDialog dialog(std::make_shared<const core::Mesh>(m_document.paintedMesh()), stem,
                               folder, m_notifier.dialogParent());
    if (dialog.exec() != QDialog::Accepted)
        return;
    dialog.saveSettings();
    settings.setValue(kTextureExportFolderKey, dialog.folder());
    exportTextureSets(dialog.folder(), dialog.options());
}

bool ProjectController::exportTextureSets(const QString& folder,
                                          const core::TextureExportOptions& options) {
    if (m_task->isRunning()) {
        m_notifier.showStatus(tr("Still busy with the last save or export"), kStatusMs);
        return false;
    }
    if (!paintTextureToExport())
        return false;
    auto snap = std::make_shared<Snapshot>();
    snap->mesh = m_document.paintedMesh();
    const QString path = QFileInfo(folder).absoluteFilePath();
    auto files = std::make_shared<QStringList>();
    auto warnings = std::make_shared<std::vector<std::string>>();
    finishExportWhenDone(path, files, warnings);
    startProgress(tr("Exporting textures to %1…").arg(QDir::toNativeSeparators(path)));
    const std::string dir = encodePath(path);
    m_task->start([snap, files, warnings, dir, options](const core::ProgressFn& progress) {
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        if (!std::filesystem::is_directory(dir))
            return fromCore(dir + ": cannot make the folder" +
                            (ec ? " (" + ec.message() + ")" : std::string()));
        core::Result<std::vector<std::string>> written =
            core::exportTextureSets(dir, snap->mesh, options, progress, warnings.get());
        if (!written)
            return written.cancelled() ? QStringLiteral("cancelled") : fromCore(written.error());
        for (const std::string& f : *written)
            files->append(QFile::decodeName(QByteArray::fromStdString(f)));
        return QString();
    });
    return true;
}

} // namespace ui
