// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/view/depth_layers_builder.h"

#include <QElapsedTimer>

#include <exception>
#include <new>
#include <optional>
#include <string>
#include <utility>

#include "core/document/document.h"
#include "ui/shell/background_task.h"
#include "ui/view/viewport.h"

namespace ui {

namespace {
constexpr int kDefaultSettleMs = 250;
} // namespace

struct DepthLayersBuilder::Job {
    std::uint64_t viewSerial = 0;
    std::uint64_t meshSerial = 0;
    QElapsedTimer clock; // from the start of the capture
    core::View view;
    core::DepthLayerOptions options;
    core::CaptureStats stats;
    std::optional<core::DepthLayers> layers;
    QString error; // shown to the user
};

struct DepthLayersBuilder::SymmetryJob {
    core::Document::SymmetryBuild build;
    bool built = false;
    QString error; // shown to the user
};

struct DepthLayersBuilder::Captured {
    std::shared_ptr<Job> job;
    core::Result<core::DepthStack> stack;
};

DepthLayersBuilder::DepthLayersBuilder(core::Document& document, Viewport& viewport,
                                       QObject* parent)
    : QObject(parent), m_document(document), m_viewport(viewport) {
    m_pool.setMaxThreadCount(1);
    m_symmetryPool.setMaxThreadCount(1);
    // Strokes here never capture on the GUI thread: the copies come from refreshSymmetry().
    m_document.setSymmetryBuiltOnStroke(false);
    m_settle.setSingleShot(true);
    m_settle.setInterval(kDefaultSettleMs);
    connect(&m_settle, &QTimer::timeout, this, &DepthLayersBuilder::onSettled);
    connect(&m_viewport, &Viewport::viewChanged, this, &DepthLayersBuilder::invalidate);
}

DepthLayersBuilder::~DepthLayersBuilder() {
    // The worker's report goes to a watcher that dies with this object; it only has to end first.
    m_symmetryWorker.cancel();
    m_pool.waitForDone();
    m_symmetryPool.waitForDone();
}

void DepthLayersBuilder::setSettleDelay(int milliseconds) {
    m_settle.setInterval(milliseconds);
}

void DepthLayersBuilder::setDepthLayerOptions(const core::DepthLayerOptions& options) {
    const bool hadLayers = m_document.depthLayers() != nullptr;
    m_document.setDepthLayerOptions(options);
    if (m_document.depthLayers()) {
        m_viewport.showSegmentation();
        emit segmentationChanged();
        refreshSymmetry(); // new regions: the copies' views are segmented again too
    } else if (hadLayers || !m_wanted) {
        // A capture option changed: the layers are gone and must be captured again.
        invalidate();
    }
}

void DepthLayersBuilder::invalidate() {
    const bool hadLayers = m_document.depthLayers() != nullptr;
    m_document.clearDepthLayers();
    cancelSymmetry(); // its views were of the old one
    m_wanted = true;
    m_settle.start();
    if (hadLayers)
        emit depthLayersCleared();
}

void DepthLayersBuilder::onSettled() {
    if (!m_wanted)
        return;
    if (m_viewport.isNavigating()) {
        // Still dragging, only paused: a capture now would stall the drag when it goes on.
        m_settle.start();
        return;
    }
    if (m_viewport.isPreparingMesh()) {
        // The model's buffers are being filled: a capture now would wait for them.
        m_settle.start();
        return;
    }
    if (!m_viewport.canCapture()) {
        // No context or no model yet; the viewport reports a view change when either comes.
        return;
    }
    if (m_workerBusy) {
        m_captureWhenIdle = true;
        return;
    }
    capture();
}

DepthLayersBuilder::Captured DepthLayersBuilder::captureView() {
    auto job = std::make_shared<Job>();
    job->clock.start();
    job->viewSerial = m_viewport.viewSerial();
    job->meshSerial = m_document.meshSerial();
    job->view = m_viewport.view();
    job->options = m_document.depthLayerOptions();
    // The GPU part, on this thread: the viewport's context is only current here.
    core::Result<core::DepthStack> stack = m_viewport.captureLayers(
        job->view, {job->options.cullBackFaces, m_document.topology().shownBackFaces}, &job->stats);
    ++m_captures;
    return {std::move(job), std::move(stack)};
}

void DepthLayersBuilder::capture() {
    m_captureWhenIdle = false;
    Captured captured = captureView();
    const std::shared_ptr<Job>& job = captured.job;
    if (!captured.stack) {
        m_wanted = false; // tried again at the next view change
        emit buildFailed(QString::fromStdString(captured.stack.error()));
        return;
    }

    // With the GL compute pass chosen, connectivity needs this thread's context: finish here
    // (a choice made where the GPU is fast).
    if (core::ConnectivityEngine* engine = m_viewport.connectivityEngine()) {
        m_document.setConnectivityEngine(engine);
        job->layers.emplace(core::finishDepthLayers(std::move(captured.stack).value(), job->stats,
                                                    m_document.mesh(), m_document.topology(),
                                                    job->view, job->options, engine));
        m_job = job;
        finish(job);
        return;
    }
    m_document.setConnectivityEngine(nullptr);

    // The CPU part on a worker. Mesh and topology are immutable and shared, so the document may
    // move on (even to another model) while it runs.
    m_workerBusy = true;
    m_job = job;
    m_worker = runInBackground(
        m_pool, this,
        [job, stack = std::move(captured.stack).value(), mesh = m_document.sharedMesh(),
         topology = m_document.sharedTopology()](const core::ProgressFn&) mutable {
            try {
                job->layers.emplace(core::finishDepthLayers(std::move(stack), job->stats, *mesh,
                                                            *topology, job->view, job->options));
            } catch (const std::bad_alloc&) {
                job->layers.reset();
                job->error = tr("not enough memory for the depth layers of this view");
            } catch (const std::exception& e) {
                job->layers.reset();
                job->error = QString::fromLocal8Bit(e.what());
            }
        },
        [this, job] { finish(job); });
}

bool DepthLayersBuilder::buildNow() {
    if (!m_wanted && m_document.depthLayers())
        return true;
    if (!m_viewport.canCapture())
        return false;
    m_settle.stop();
    m_wanted = true;
    // A worker's result for this view is as good as a new one and nearly done.
    m_worker.waitForFinished();
    std::shared_ptr<Job> job = std::move(m_job);
    m_workerBusy = false;
    m_captureWhenIdle = false;
    if (job && job->layers && adopt(*job))
        return true;

    Captured captured = captureView();
    job = captured.job;
    if (captured.stack) {
        try {
            core::ConnectivityEngine* engine = m_viewport.connectivityEngine();
            m_document.setConnectivityEngine(engine);
            job->layers.emplace(core::finishDepthLayers(
                std::move(captured.stack).value(), job->stats, m_document.mesh(),
                m_document.topology(), job->view, job->options, engine));
        } catch (const std::bad_alloc&) {
            job->error = tr("not enough memory for the depth layers of this view");
        } catch (const std::exception& e) {
            job->error = QString::fromLocal8Bit(e.what());
        }
    } else {
        job->error = QString::fromStdString(captured.stack.error());
    }
    if (job->layers && adopt(*job))
        return true;
    m_wanted = false; // tried again at the next view change
    emit buildFailed(job->error);
    return false;
}

bool DepthLayersBuilder::adopt(Job& job) {
    if (job.viewSerial != m_viewport.viewSerial() || !m_wanted ||
        !m_document.adoptLayers(std::move(*job.layers), job.meshSerial))
        return false;
    m_wanted = false;
    m_lastBuildMs = double(job.clock.nsecsElapsed()) / 1e6;
    m_viewport.showLayers();
    emit depthLayersBuilt();
    refreshSymmetry();
    return true;
}

void DepthLayersBuilder::finish(const std::shared_ptr<Job>& job) {
    if (job != m_job)
        return; // buildNow() already waited for it and settled it
    m_job.reset();
    m_workerBusy = false;

    const bool current = job->viewSerial == m_viewport.viewSerial();
    if (current && !job->layers) {
        m_wanted = false;
        emit buildFailed(job->error);
    } else if (current && job->layers && adopt(*job)) {
        return;
    }
    // Stale: the view, the mesh or a capture option changed meanwhile.
    if (m_captureWhenIdle)
        capture();
    else if (m_wanted && !m_settle.isActive())
        m_settle.start();
}

double DepthLayersBuilder::symmetryProgress() const {
    return m_symmetryJob ? jobProgress(m_symmetryWorker) : 0.0;
}

void DepthLayersBuilder::cancelSymmetry() {
    if (!m_symmetryJob)
        return;
    m_symmetryWorker.cancel(); // stops between copies; its report is ignored
    m_symmetryJob.reset();
    emit symmetryFinished();
}

void DepthLayersBuilder::refreshSymmetry() {
    std::optional<core::Document::SymmetryBuild> build = m_document.symmetryBuild();
    if (m_symmetryJob) {
        const core::Document::SymmetryBuild& running = m_symmetryJob->build;
        if (build && running.symmetry == build->symmetry &&
            running.depthLayersSerial == build->depthLayersSerial &&
            running.meshSerial == build->meshSerial)
            return; // already on its way
        cancelSymmetry();
    }
    if (!build)
        return;
    auto job = std::make_shared<SymmetryJob>();
    job->build = std::move(*build);
    m_symmetryJob = job;
    m_symmetryWorker = runInBackground(
        m_symmetryPool, this,
        [job](const core::ProgressFn& progress) {
            try {
                job->built = job->build.build(progress);
            } catch (const std::bad_alloc&) {
                job->error = tr("not enough memory for the symmetric views");
            } catch (const std::exception& e) {
                job->error = QString::fromLocal8Bit(e.what());
            }
        },
        [this, job] { finishSymmetry(job); });
    emit symmetryStarted();
}

void DepthLayersBuilder::finishSymmetry(const std::shared_ptr<SymmetryJob>& job) {
    if (job != m_symmetryJob)
        return; // cancelled, or settled by buildSymmetryNow()
    m_symmetryJob.reset();
    if (!job->error.isEmpty()) {
        // Settled as copies that paint nothing (as a copy whose capture fails), so the build is
        // not started again for the same layers and symmetry.
        job->build.layers.assign(job->build.transforms.size(), std::nullopt);
        job->built = true;
        emit buildFailed(job->error);
    }
    if (job->built)
        m_document.adoptSymmetry(std::move(job->build));
    emit symmetryFinished();
    refreshSymmetry(); // the symmetry may have changed meanwhile
}

bool DepthLayersBuilder::buildSymmetryNow() {
    if (m_document.symmetryReady())
        return true;
    refreshSymmetry();
    if (!m_symmetryJob)
        return m_document.symmetryReady();
    emit symmetryWaiting();
    const std::shared_ptr<SymmetryJob> job = m_symmetryJob;
    m_symmetryWorker.waitForFinished();
    finishSymmetry(job);
    return m_document.symmetryReady();
}

} // namespace ui
