// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/mesh_fill_job.h"

#include <utility>

#include "ui/shell/background_task.h"

namespace ui {

MeshFillJob::MeshFillJob(QObject* parent) : QObject(parent) {
    m_pool.setMaxThreadCount(1);
}

MeshFillJob::~MeshFillJob() {
    wait();
    m_pool.waitForDone();
}

void MeshFillJob::start(std::vector<std::function<void()>> fills,
                        std::vector<std::shared_ptr<const core::Mesh>> meshes) {
    wait();
    const std::uint64_t job = ++m_job;
    m_pending = true;
    m_future = runInBackground(
        m_pool, this,
        [fills = std::move(fills), meshes = std::move(meshes)](const core::ProgressFn&) {
            try {
                for (const std::function<void()>& fill : fills)
                    if (fill)
                        fill();
            } catch (...) {
                // Out of memory (tangents, runs): finishing drops the buffers not written whole,
                // and the viewport says the model cannot be drawn.
            }
        },
        [this, job] {
            if (job == m_job && m_pending)
                emit finished();
        });
}

void MeshFillJob::wait() {
    m_future.waitForFinished();
    m_pending = false;
    ++m_job; // its report is for no one now
}

} // namespace ui
