// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include <QMainWindow>
#include <QPointer>
#include <QString>
#include <QStringList>
#include <QTimer>

#include "core/mesh.h"
#include "ui/recent_files.h"

class QAction;
class QLabel;
class QMenu;
class QProgressDialog;

namespace ui {

class ModelLoader;
class Viewport;

/**
 * The application window: the viewport, the File/View/Help menus, the status bar and the
 * background loading of models. The open model only changes when a load succeeds.
 */
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /**
     * Opens a file path or "builtin:NAME" in the background. On success modelLoaded() follows;
     * on failure loadFailed() and an error dialog, with the current model left as it was.
     */
    void openFile(const QString& source);
    /** What the command line asks for: the first file, or the default model when there is none. */
    void openFromCommandLine(const QStringList& files);

    Viewport* viewport() const { return m_viewport; }
    /** The open model's source (absolute path or "builtin:NAME"); empty before the first load. */
    QString currentSource() const { return m_source; }
    bool isLoading() const;
    QStringList recentFiles() const { return m_recent.files(); }

    /** Tests turn the modal error dialogs off; loadFailed() is emitted either way. */
    void setErrorDialogsEnabled(bool enabled) { m_errorDialogs = enabled; }

    /** The translated name of a built-in model ("trefoil" → "Trefoil knot"). */
    static QString builtinLabel(const QString& name);
    /** The name shown for a source: a built-in's label or the file name. */
    static QString displayName(const QString& source);

signals:
    void modelLoaded(const QString& source);
    /** message is core's error text; it names the file. */
    void loadFailed(const QString& message);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createMenus();
    void updateRecentMenu();
    void showOpenDialog();
    void showAbout();
    void showError(const QString& title, const QString& text, const QString& details);

    void onLoaded(const QString& source, std::shared_ptr<core::Mesh> mesh);
    void onLoadFailed(const QString& source, const QString& message);
    void onLoadCancelled(const QString& source);
    void startProgress(const QString& source);
    void stopProgress();
    void updateModelInfo(const core::Mesh& mesh);

    Viewport* m_viewport = nullptr;
    ModelLoader* m_loader = nullptr;
    RecentFiles m_recent;
    QMenu* m_recentMenu = nullptr;
    QAction* m_orthographicAction = nullptr;
    QLabel* m_modelInfo = nullptr;
    QPointer<QProgressDialog> m_progress;
    QTimer m_progressTimer;
    QString m_source;
    bool m_errorDialogs = true;
};

} // namespace ui
