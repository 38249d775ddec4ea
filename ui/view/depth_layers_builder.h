// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <memory>

#include <QFuture>
#include <QObject>
#include <QString>
#include <QThreadPool>
#include <QTimer>

#include "core/depth/depth_layers.h"

namespace core {
class Document;
}

namespace ui {

class Viewport;

/**
 * Runs build_layers (docs/architecture.md §3 step 2) when the view settles, without ever blocking
 * orbiting. Any view change drops the document's layers at once and restarts a short timer; when it
 * fires (and no drag is in progress), the viewport captures the fragments on the GUI thread in its
 * GL context, and a background job (runInBackground()) finishes them (connectivity, regions, region
 * graph). The result is adopted only if view, mesh and capture options are still those it was made
 * for; a stale one is dropped. Threshold and test changes re-segment the current layers without a
 * capture.
 */
class DepthLayersBuilder : public QObject {
    Q_OBJECT

public:
    DepthLayersBuilder(core::Document& document, Viewport& viewport, QObject* parent = nullptr);
    /** Waits for a running worker (its result is dropped). */
    ~DepthLayersBuilder() override;

    /** Milliseconds the view must stay still before a build starts. */
    void setSettleDelay(int milliseconds);
    int settleDelay() const { return m_settle.interval(); }

    /**
     * Sets the document's options: a new threshold or test re-segments the current layers at
     * once (segmentationChanged()); a new capture option drops them and builds again.
     */
    void setDepthLayerOptions(const core::DepthLayerOptions& options);

    /** True from a view change until the new layers are adopted (or the build failed). */
    bool isBuilding() const { return m_wanted; }
    /** Captures done so far (the threshold slider must not add any). */
    int captureCount() const { return m_captures; }
    /** Wall-clock milliseconds of the last adopted build, from capture start to adoption. */
    double lastBuildMs() const { return m_lastBuildMs; }

    /**
     * Makes sure the document has the layers of the current view now, building them on this
     * thread if needed (a press must never paint with stale layers): adopts a running worker's
     * result when it is for this view, else captures and finishes here. False if they cannot
     * be built (no model or context, or the capture failed: buildFailed()).
     */
    bool buildNow();

    /**
     * The symmetric views (Brush::symmetry) of the current layers, built in the background after
     * the layers and whenever the symmetry changes (refreshSymmetry()), so a symmetric stroke
     * never captures on this thread while the artist waits. Only on the CPU, as a script's
     * stroke builds them, so both paint the same.
     */
    bool isBuildingSymmetry() const { return m_symmetryJob != nullptr; }
    /** Progress of the symmetric views' build in [0, 1]. */
    double symmetryProgress() const;
    /**
     * Makes sure a stroke can paint its symmetric copies now: waits for their build (started
     * first if none runs), telling symmetryWaiting() first. False when they are still not
     * there (the stroke paints without them).
     */
    bool buildSymmetryNow();

public slots:
    /** The view changed: drops the layers and builds again once the view has settled. */
    void invalidate();
    /**
     * The brush's symmetry may have changed: starts building the views it needs (cancelling a
     * build for other ones), or does nothing when they are there or symmetry is off.
     */
    void refreshSymmetry();

signals:
    /** The document's layers were dropped (they described another view). */
    void depthLayersCleared();
    /** New layers of the current view are in the document and shown by the viewport. */
    void depthLayersBuilt();
    /** The current layers were re-segmented (same capture, new regions). */
    void segmentationChanged();
    /** A capture failed; message is for the user. */
    void buildFailed(const QString& message);
    /** The symmetric views started building in the background. */
    void symmetryStarted();
    /** The symmetric views of the current layers are ready (or their build was dropped). */
    void symmetryFinished();
    /** A stroke waits for the symmetric views (buildSymmetryNow()). */
    void symmetryWaiting();

private:
    struct Job;
    struct Captured;

    void onSettled();
    /** A new job for the current view and its fragments, captured on this thread. */
    Captured captureView();
    void capture();
    void finish(const std::shared_ptr<Job>& job);
    /** Adopts a finished job's layers if still current; true when adopted. */
    bool adopt(Job& job);

    struct SymmetryJob;
    void finishSymmetry(const std::shared_ptr<SymmetryJob>& job);
    void cancelSymmetry();

    core::Document& m_document;
    Viewport& m_viewport;
    QTimer m_settle;
    QThreadPool m_pool; // one thread: one worker job at a time
    QFuture<void> m_worker;
    /** The worker's job; a finish() for any other was settled by buildNow(). */
    std::shared_ptr<Job> m_job;
    bool m_workerBusy = false;
    /** Depth layers of the current view are wanted and not yet there. */
    bool m_wanted = false;
    /** The view settled while the worker was busy: capture once it reports. */
    bool m_captureWhenIdle = false;
    QThreadPool m_symmetryPool; // the symmetric views' worker, beside the layers' one
    QFuture<void> m_symmetryWorker;
    std::shared_ptr<SymmetryJob> m_symmetryJob; // the running build, or null
    int m_captures = 0;
    double m_lastBuildMs = 0.0;
};

} // namespace ui
