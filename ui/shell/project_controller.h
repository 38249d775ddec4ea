// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <QLockFile>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QTimer>

#include "core/document/project_state.h"
#include "core/io/export.h"
#include "core/io/texture_sets/texture_set_export.h"

class QCheckBox;
class QFileDialog;
class QFileInfo;
class QProgressDialog;

namespace core {
class Document;
class PaintTarget;
} // namespace core

namespace ui {

class BackgroundTask;
class HistoryBridge;
class Notifier;

/**
 * The project side of the main window (docs/architecture.md §3 step 7): which file the document is
 * saved to, whether it has unsaved changes, Save / Save As, Export, autosave and crash recovery.
 *
 * - Modified: the undo stack is away from its clean index (strokes, undo, redo), or a project
 *   setting changed (markModified()). Saving makes the document clean unless it changed while
 *   the save ran. The window title shows it with "[*]".
 * - Saving and exporting take a snapshot on the GUI thread (the painted mesh, the state) and
 *   encode and write it on a worker thread, with a progress dialog for long ones; the document
 *   stays usable. Writes are atomic; a failure leaves the old file and says so.
 * - Autosave: every "autosave/intervalMinutes" minutes (QSettings; default 5, 0 = off) a
 *   modified document is written to recoveryFolder(), held by a lock file while this session
 *   runs. A normal close removes it; one left by a crashed session is offered at the next start.
 */
class ProjectController : public QObject {
    Q_OBJECT

public:
    static constexpr int kDefaultAutosaveMinutes = 5;

    /**
     * Saves document (its history tells whether it changed since the last save) with the state
     * projectState returns (the document's and the window's panels'); tells the user through
     * notifier.
     */
    ProjectController(core::Document& document, HistoryBridge& history, Notifier& notifier,
                      std::function<core::ProjectState()> projectState);
    /** Waits for a save or export under way (an interrupted write would leave a temporary file). */
    ~ProjectController() override;

    /** The project file the document is saved to; empty until it is saved (or a project opened). */
    QString filePath() const { return m_filePath; }
    /** The name the title shows: the project file's, else the model's. */
    QString documentName() const;
    bool isModified() const;
    /** A project setting changed (brush, mode, segmentation, paint target, ...). */
    void markModified();
    /**
     * A document was loaded from source (isProject: a LayerPaint project). A project is saved to
     * its own file; a plain model or built-in is untitled. An autosave being recovered keeps the
     * file it belonged to (recoveryFor) and stays modified. Either way the undo stack is clean.
     */
    void documentLoaded(const QString& source, bool isProject, const QString& recoveryFor,
                        const QString& modelSource);
    /** Loading source failed (the document is unchanged). */
    void documentLoadFailed(const QString& source);
    /** Whether source is a file in the recovery folder (not worth a Recent entry). */
    bool isRecoveryFile(const QString& source) const;

    /** File ▸ Save: to filePath(), or through the Save As dialog without one. False if not started.
     */
    bool save();
    /** File ▸ Save As: asks for a file, then saves. False if cancelled or not started. */
    bool saveAs();
    /** Starts saving to path (".glb" is added without an extension); saved() or saveFailed()
     * follow. */
    bool saveTo(const QString& path);
    /** Saves to path and waits (with a modal progress dialog); true when it is saved. */
    bool saveAndWait(const QString& path);
    bool isBusy() const;
    /** Waits for a save or export under way. */
    void waitForTasks();

    /**
     * Before the document is replaced or closed: if it has unsaved changes, asks Save / Discard /
     * Cancel (without dialogs, see Notifier::setDialogsEnabled, the changes are discarded). True
     * to go on.
     */
    bool maybeSave();

    /**
     * Export ▸ format: asks for a file (and whether to write each paint layer too, remembered as
     * "export/perPaintLayer"), then exports.
     */
    void showExportDialog(core::ExportFormat format);
    /**
     * Starts exporting the painted model (or its paint texture) to path; exported() or
     * exportFailed() follow. perPaintLayer: also each paint layer's channels and mask as images
     * beside path (core::exportPaintLayerImages, as `layerpaint-cli export --per-layer`). False
     * if it cannot start (busy, no texture for a texture format or for the paint layers, or path
     * is the open project, which an export would replace without its state).
     */
    bool exportTo(core::ExportFormat format, const QString& path, bool perPaintLayer = false);
    /**
     * File ▸ Export Textures…: asks for a preset, folder and options (TextureExportDialog), then
     * writes every texture set through the preset on the worker; exported() or exportFailed()
     * follow.
     */
    void showTextureExportDialog();
    /** Starts writing the texture sets through options into folder (made if missing). */
    bool exportTextureSets(const QString& folder, const core::TextureExportOptions& options);
    /** Whether the document has paint layers (the export dialog offers an image per layer). */
    bool hasPaintLayers() const;
    /** Whether the document has a paint texture (texture formats can be exported). */
    bool canExportTexture() const;

    /** The folder of autosaves (under QStandardPaths::AppDataLocation). */
    static QString recoveryFolder();
    /** This session's autosave file. */
    QString autosavePath() const;
    /** Writes an autosave now if the document changed since the last one; false if not started. */
    bool autosaveNow();
    /**
     * Reads "autosave/intervalMinutes" again (the Preferences dialog changed it); a changed
     * interval applies at once, counted from now.
     */
    void reloadAutosaveInterval();
    /** Milliseconds until the autosave timer next fires. */
    int autosaveDueInMs() const { return m_autosaveTimer.remainingTime(); }
    /**
     * At startup: offers the newest autosave a crashed session left (Recover / Discard / Not
     * Now). Recover opens it as the (modified) document. True if a recovery is loading.
     */
    bool offerRecovery();
    /** The work is saved or discarded and the window closes: removes this session's autosave. */
    void discardRecovery();

signals:
    void modifiedChanged(bool modified);
    /** The document's file or name changed (title). */
    void documentNameChanged();
    void saved(const QString& path);
    /** message names the file and the problem; the old file is intact. */
    void saveFailed(const QString& message);
    void exported(const QStringList& files);
    void exportFailed(const QString& message);
    void autosaved(const QString& path);
    /** A recovered autosave is to be opened as the document (offerRecovery()). */
    void openRequested(const QString& path);

private:
    // Shared by the files the controller's code is split into.
    static constexpr int kStatusMs = 6000;
    /** A path as core's file functions take it (the file system's encoding). */
    static std::string encodePath(const QString& path);
    static QString fromCore(const std::string& message);

    /** Defined in project_snapshot.h. */
    struct Snapshot;
    /** The painted mesh and state now (GUI thread); null with why set if there is no model. */
    std::shared_ptr<Snapshot> snapshot(QString& why) const;
    QString askSavePath();
    /** Whether two paths name the same file (through links, when both exist). */
    static bool samePath(const QString& a, const QString& b);
    /** Whether path is the open project's file or the model file it was opened from. */
    bool isOpenDocumentFile(const QString& path) const;
    void startProgress(const QString& text);
    void stopProgress();
    /** The Export dialog's file filter for format. */
    static QString exportFilter(core::ExportFormat format);
    /** The file the Export dialog proposes in folder: named after the document, never itself. */
    QString suggestExportPath(core::ExportFormat format, const QString& folder) const;
    /** The Export dialog's "each paint layer as images" check box, below its other controls. */
    QCheckBox* addPerPaintLayerBox(QFileDialog& dialog, bool hasLayers, bool checked);
    /** Says why an export to the open project's own file is refused; exportFailed() follows. */
    void refuseExportOverProject(const QString& path);
    /** The paint target whose texture sets are exported, made if needed; null (reported) if none.
     */
    const core::PaintTarget* paintTextureToExport();
    /** Export steps: what is exported, copied on the GUI thread; false (reported) if missing. */
    bool snapshotPaintTexture(Snapshot& snap);
    bool snapshotPaintedModel(Snapshot& snap) const;
    bool snapshotPaintLayers(Snapshot& snap);
    /** Writes snap's export to path on the worker; exported() or exportFailed() follow. */
    void startExport(core::ExportFormat format, const QString& path,
                     const std::shared_ptr<Snapshot>& snap);
    /** finishExport() once the task's job (which fills files and warnings) has finished. */
    void finishExportWhenDone(const QString& path, const std::shared_ptr<QStringList>& files,
                              const std::shared_ptr<std::vector<std::string>>& warnings);
    /** Reports the end of an export (status bar, errors, what was not kept); the signals follow. */
    void finishExport(const QString& path, const QStringList& files,
                      const std::vector<std::string>& warnings, const QString& error,
                      bool cancelled);
    /** A warning box naming what a written file could not keep (nothing if warnings is empty). */
    void showUnkept(const QString& path, const std::vector<std::string>& warnings);
    void onSaveFinished(const std::shared_ptr<Snapshot>& snap, const QString& path,
                        const QString& error, bool cancelled);
    void updateModified();
    bool takeLock();
    void onAutosaveTimer();
    enum class RecoveryAnswer { Recover, Discard, NotNow };
    /** Asks whether to recover the autosave candidate a crashed session left. */
    RecoveryAnswer askRecovery(const QFileInfo& candidate);
    /** What the recovery question calls candidate's work: its project, or the model painted. */
    static QString recoveredWorkName(const QFileInfo& candidate);
    /**
     * Makes candidate this session's autosave (probe holds its old session's lock) and asks to
     * open it; false if it cannot be taken over.
     */
    bool adoptRecovery(const QFileInfo& candidate, QLockFile& probe);

    /** The open model's source (a path or "builtin:NAME"), as the document names it. */
    QString currentSource() const;

    core::Document& m_document;
    HistoryBridge& m_history;
    Notifier& m_notifier;
    std::function<core::ProjectState()> m_projectState;
    BackgroundTask* m_task = nullptr;     // saves and exports, one at a time
    BackgroundTask* m_autosave = nullptr; // autosaves, silently
    QString m_filePath;
    QString m_modelName; // the model's display name, for untitled documents
    bool m_otherChanges = false;
    bool m_lastModified = false;
    /** Counts every change: a snapshot is clean to mark saved only if none came after it. */
    quint64 m_changeSerial = 0;
    quint64 m_autosavedSerial = 0;
    QString m_recovering; // the autosave being loaded as the document
    QString m_sessionId;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_autosaveTimer;
    qint64 m_autosaveIntervalMs = 0;
    QPointer<QProgressDialog> m_progress;
    QTimer m_progressTimer;
};

} // namespace ui
