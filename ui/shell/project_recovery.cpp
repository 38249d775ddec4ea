// SPDX-License-Identifier: GPL-3.0-or-later
// The project controller's autosave and crash recovery: the recovery folder and this session's
// lock, the autosave timer and writes, and the offer to recover what a crashed session left.
#include "ui/shell/project_controller.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLocale>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>

#include <algorithm>
#include <cmath>

#include "core/io/gltf/gltf_export.h"
#include "core/io/project/project_file.h"
#include "ui/shell/background_task.h"
#include "ui/shell/notifier.h"
#include "ui/shell/project_snapshot.h"
#include "ui/shell/source_names.h"

namespace ui {

namespace {
const QString kAutosaveIntervalKey = QStringLiteral("autosave/intervalMinutes");
constexpr qint64 kIdleTickMs = 60000; // how often a disabled autosave looks at the setting again
} // namespace

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
    double minutes = QSettings().value(kAutosaveIntervalKey, kDefaultAutosaveMinutes).toDouble(&ok);
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
        const RecoveryAnswer answer = askRecovery(candidate);
        if (answer == RecoveryAnswer::Discard) {
            QFile::remove(candidate.filePath());
            probe.unlock();
            continue; // the next one, if any
        }
        if (answer != RecoveryAnswer::Recover)
            return false; // kept for the next start
        return adoptRecovery(candidate, probe);
    }
    return false;
}

QString ProjectController::recoveredWorkName(const QFileInfo& candidate) {
    QString belongsTo, source;
    core::Result<nlohmann::json> extras = core::readGlbExtras(encodePath(candidate.filePath()));
    if (extras && extras->contains("layerpaint") && (*extras)["layerpaint"].is_object()) {
        const nlohmann::json& lp = (*extras)["layerpaint"];
        if (lp.contains("recovery_for") && lp["recovery_for"].is_string())
            belongsTo =
                QFile::decodeName(QByteArray::fromStdString(lp["recovery_for"].get<std::string>()));
        if (lp.contains("source") && lp["source"].is_string())
            source = QFile::decodeName(QByteArray::fromStdString(lp["source"].get<std::string>()));
    }
    return belongsTo.isEmpty()
               ? tr("an unsaved painting of %1")
                     .arg(sourceDisplayName(source.isEmpty() ? candidate.fileName() : source))
               : QStringLiteral("“%1”").arg(QFileInfo(belongsTo).fileName());
}

ProjectController::RecoveryAnswer ProjectController::askRecovery(const QFileInfo& candidate) {
    const QString name = recoveredWorkName(candidate);
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
    if (box.clickedButton() == discard)
        return RecoveryAnswer::Discard;
    return box.clickedButton() == recover ? RecoveryAnswer::Recover : RecoveryAnswer::NotNow;
}

bool ProjectController::adoptRecovery(const QFileInfo& candidate, QLockFile& probe) {
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

bool ProjectController::isRecoveryFile(const QString& source) const {
    return QFileInfo(source).absolutePath() == QDir(recoveryFolder()).absolutePath();
}

} // namespace ui
