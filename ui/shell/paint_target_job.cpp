// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/paint_target_job.h"

#include <new>

#include <QProgressDialog>
#include <QWidget>

#include "core/paint/targets/layout_target.h"
#include "ui/shell/background_task.h"

namespace ui {

namespace {
constexpr int kDialogSteps = 1000;
constexpr int kDialogDelayMs = 400; // a quick layout finishes without a dialog flashing up
} // namespace

PaintTargetJob::PaintTargetJob(QWidget& dialogParent)
    : QObject(&dialogParent), m_dialogParent(dialogParent) {
    m_pool.setMaxThreadCount(1);
    m_timer.setInterval(50);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        if (m_dialog)
            m_dialog->setValue(int(progress() * kDialogSteps));
    });
}

PaintTargetJob::~PaintTargetJob() {
    m_future.cancel();
    m_pool.waitForDone();
    closeDialog();
}

void PaintTargetJob::start(std::shared_ptr<const core::Mesh> mesh,
                           std::shared_ptr<const core::MeshTopology> topology,
                           const core::PaintTargetOptions& options, std::uint64_t meshSerial,
                           const QString& name) {
    m_future.cancel();
    closeDialog();
    const std::uint64_t job = ++m_job;
    m_running = true;
    auto outcome = std::make_shared<Outcome>();
    outcome->options = options;
    outcome->meshSerial = meshSerial;

    // Not modal: the model stays usable (painting goes into the current target meanwhile).
    auto* dialog = new QProgressDialog(tr("Making an automatic UV layout for “%1”…").arg(name),
                                       tr("Cancel"), 0, kDialogSteps, &m_dialogParent);
    dialog->setObjectName(QStringLiteral("uvLayoutProgress"));
    dialog->setWindowTitle(tr("Automatic UV Layout"));
    dialog->setAutoClose(false);
    dialog->setAutoReset(false);
    dialog->setMinimumDuration(kDialogDelayMs);
    dialog->setValue(0);
    connect(dialog, &QProgressDialog::canceled, this, &PaintTargetJob::cancel);
    m_dialog = dialog;
    m_timer.start();

    m_future = runInBackground(
        m_pool, this,
        [outcome, mesh = std::move(mesh), topology = std::move(topology),
         options](const core::ProgressFn& progress) {
            try {
                auto made = core::makePaintTargetWithLayout(mesh, topology, options, progress);
                if (made) {
                    outcome->target = std::move(made).value();
                } else {
                    outcome->cancelled = made.cancelled();
                    outcome->error = made.error();
                }
            } catch (const std::bad_alloc&) {
                outcome->target.reset();
                outcome->error = "not enough memory for the UV layout";
            }
        },
        [this, job, outcome] {
            if (job != m_job)
                return; // replaced by a newer job
            m_running = false;
            closeDialog();
            if (!outcome->target && outcome->error.empty())
                outcome->cancelled = true; // cancelled before it started
            emit finished(outcome);
        });
}

void PaintTargetJob::cancel() {
    m_future.cancel();
}

double PaintTargetJob::progress() const {
    return m_running ? jobProgress(m_future) : 0.0;
}

void PaintTargetJob::closeDialog() {
    m_timer.stop();
    // Deleted at once: a hidden dialog left for deleteLater could still be shown by its own
    // minimum-duration timer.
    delete m_dialog.data();
    m_dialog = nullptr;
}

} // namespace ui
