// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <QFuture>
#include <QObject>
#include <QThreadPool>

#include "core/model/mesh.h"

namespace ui {

/**
 * Fills a new model's GL buffers off the GUI thread: the fills that render::MeshRenderer and
 * render::DepthCapture's beginMesh() return (writes through buffers mapped on the GUI thread),
 * run with runInBackground() while the meshes they read are kept alive. The buffers are
 * finished (unmapped) on the GUI thread once finished() comes, or at once after wait(). A fill
 * cannot stop halfway (it writes into buffers the GL owns): wait() is how a job ends early.
 */
class MeshFillJob : public QObject {
    Q_OBJECT

public:
    explicit MeshFillJob(QObject* parent = nullptr);
    /** Waits for a running job. */
    ~MeshFillJob() override;

    /** Runs fills (empty ones skipped) in the background, keeping meshes alive meanwhile. */
    void start(std::vector<std::function<void()>> fills,
               std::vector<std::shared_ptr<const core::Mesh>> meshes);
    /** From start() until wait() (which returns at once after finished()). */
    bool isPending() const { return m_pending; }
    /** Waits for the running fills, if any; no finished() comes for them afterwards. */
    void wait();

signals:
    /** The pending job's fills have returned: its buffers can be finished. */
    void finished();

private:
    QThreadPool m_pool;
    QFuture<void> m_future;
    std::uint64_t m_job = 0; // the current job's number: an older one's report is dropped
    bool m_pending = false;
};

} // namespace ui
