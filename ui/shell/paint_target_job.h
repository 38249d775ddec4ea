// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <QFuture>
#include <QObject>
#include <QPointer>
#include <QThreadPool>
#include <QTimer>

#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"
#include "core/paint/targets/paint_target.h"

class QProgressDialog;
class QWidget;

namespace ui {

/**
 * Makes a paint target that takes long (a texture over an automatic UV layout) off the GUI thread
 * with runInBackground(), showing a progress dialog with Cancel, and hands it back on the GUI
 * thread for core::Document::adoptPaintTarget(). One job at a time: starting another cancels the
 * running one and drops its result.
 */
class PaintTargetJob : public QObject {
    Q_OBJECT

public:
    /** What a finished job made: the target, or why not (cancelled: the user stopped it). */
    struct Outcome {
        std::unique_ptr<core::PaintTarget> target;
        core::PaintTargetOptions options;
        std::uint64_t meshSerial = 0;
        std::string error;
        bool cancelled = false;
    };

    /** dialogParent gets the progress dialog. */
    explicit PaintTargetJob(QWidget& dialogParent);
    /** Cancels a running job and waits for its worker. */
    ~PaintTargetJob() override;

    /**
     * Starts making the target for mesh (the document's at meshSerial) with options; name is the
     * model's, for the dialog.
     */
    void start(std::shared_ptr<const core::Mesh> mesh,
               std::shared_ptr<const core::MeshTopology> topology,
               const core::PaintTargetOptions& options, std::uint64_t meshSerial,
               const QString& name);
    /** Asks the running job to stop; finished() follows with Outcome::cancelled. */
    void cancel();
    bool isRunning() const { return m_running; }
    /** The running job's progress in [0, 1]. */
    double progress() const;

signals:
    void finished(std::shared_ptr<ui::PaintTargetJob::Outcome> outcome);

private:
    void closeDialog();

    QWidget& m_dialogParent;
    QThreadPool m_pool;
    QFuture<void> m_future;
    std::uint64_t m_job = 0; // the current job's number: older ones are dropped
    bool m_running = false;
    QPointer<QProgressDialog> m_dialog;
    QTimer m_timer;
};

} // namespace ui
