// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include <QFuture>
#include <QObject>
#include <QThreadPool>

#include "core/model/mesh.h"

namespace render {
struct CompositorMesh;
}

namespace ui {

/** A mesh prepared for the depth compositor, with the geometry and look it was made from. */
struct PreparedCompositorMesh {
    std::shared_ptr<const core::Mesh> geometry, look;
    std::shared_ptr<const render::CompositorMesh> prepared; // null if it failed
    std::string error;                                      // why it failed
};

/**
 * Prepares a new model for the depth compositor (render::DepthCompositor::prepareMesh: packing,
 * encoding, splitting) off the GUI thread with runInBackground(), so the first frame of a large
 * model sends only the plain renderer's and the capture's arrays; the compositor is not drawn
 * before its depth layers are built. One job at a time: starting another, or cancel(), drops
 * the running one's result. take() waits for the running job when its result is needed at once.
 */
class CompositorMeshJob : public QObject {
    Q_OBJECT

public:
    explicit CompositorMeshJob(QObject* parent = nullptr);
    /** Cancels a running job and waits for its worker. */
    ~CompositorMeshJob() override;

    /** Starts preparing geometry with look for storage blocks of blockBytes. */
    void start(std::shared_ptr<const core::Mesh> geometry, std::shared_ptr<const core::Mesh> look,
               std::size_t blockBytes);
    /** Stops the running job; no finished() comes for it. */
    void cancel();
    /** Whether a job runs or has a result not yet taken. */
    bool isPending() const { return m_pending; }
    /**
     * The result of the pending job, waiting for it if it runs; nothing when none is pending.
     * No finished() comes for it afterwards.
     */
    std::shared_ptr<const PreparedCompositorMesh> take();

signals:
    /** The pending job's result is ready for take(). */
    void finished();

private:
    QThreadPool m_pool;
    QFuture<void> m_future;
    std::shared_ptr<PreparedCompositorMesh> m_result;
    std::uint64_t m_job = 0; // the current job's number: older ones are dropped
    bool m_pending = false;
};

} // namespace ui
