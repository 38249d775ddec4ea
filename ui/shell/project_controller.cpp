// SPDX-License-Identifier: GPL-3.0-or-later
// The project controller: its construction, the modified state and the document's file, saving
// (Save, Save As, the unsaved-changes question) and the progress dialog of saves and exports.
// Export is in project_export.cpp, autosave and crash recovery in project_recovery.cpp.
#include "ui/shell/project_controller.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSettings>

#include <cstring>

#include "core/document/document.h"
#include "core/io/project/project_file.h"
#include "core/model/builtin_models.h"
#include "ui/commands/history_bridge.h"
#include "ui/shell/background_task.h"
#include "ui/shell/notifier.h"
#include "ui/shell/project_snapshot.h"
#include "ui/shell/source_names.h"

namespace ui {

namespace {
const QString kProjectDirectoryKey = QStringLiteral("project/directory");
constexpr int kProgressSteps = 1000;
constexpr int kProgressDelayMs = 400;
} // namespace

std::string ProjectController::encodePath(const QString& path) {
    return QFile::encodeName(path).toStdString();
}

QString ProjectController::fromCore(const std::string& message) {
    return QString::fromStdString(message);
}

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
                .value(kProjectDirectoryKey,
                       builtin ? QDir::homePath() : QFileInfo(source).absolutePath())
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
    settings.setValue(kProjectDirectoryKey, QFileInfo(path).absolutePath());
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
    auto warnings = std::make_shared<std::vector<std::string>>();
    connect(
        m_task, &BackgroundTask::finished, this,
        [this, snap, path, warnings](const QString& error, bool cancelled) {
            onSaveFinished(snap, path, error, cancelled);
            if (error.isEmpty())
                showUnkept(path, *warnings);
        },
        Qt::SingleShotConnection);
    m_task->start([snap, file, warnings](const core::ProgressFn& progress) {
        const core::Status s =
            core::saveProject(file, snap->mesh, snap->state, progress, true, warnings.get());
        return s ? QString() : fromCore(s.error());
    });
    return true;
}

void ProjectController::showUnkept(const QString& path, const std::vector<std::string>& warnings) {
    if (warnings.empty())
        return;
    QStringList lines;
    for (const std::string& w : warnings)
        lines.append(QString::fromStdString(w));
    m_notifier.showError(tr("Not Everything Was Kept"),
                         tr("“%1” was written, but not all of the model could be kept:")
                             .arg(QFileInfo(path).fileName()),
                         lines.join(QLatin1Char('\n')));
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

} // namespace ui
