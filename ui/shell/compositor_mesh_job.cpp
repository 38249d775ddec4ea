// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/compositor_mesh_job.h"

#include <new>
#include <utility>

#include "render/depth_compositor.h"
#include "ui/shell/background_task.h"

namespace ui {

CompositorMeshJob::CompositorMeshJob(QObject* parent) : QObject(parent) {
    m_pool.setMaxThreadCount(1);
}

CompositorMeshJob::~CompositorMeshJob() {
    cancel();
    m_pool.waitForDone();
}

void CompositorMeshJob::start(std::shared_ptr<const core::Mesh> geometry,
                              std::shared_ptr<const core::Mesh> look, std::size_t blockBytes) {
    cancel();
    const std::uint64_t job = ++m_job;
    m_pending = true;
    auto result = std::make_shared<PreparedCompositorMesh>();
    result->geometry = std::move(geometry);
    result->look = std::move(look);
    m_result = result;
    m_future = runInBackground(
        m_pool, this,
        [result, blockBytes](const core::ProgressFn&) {
            try {
                auto prepared = render::DepthCompositor::prepareMesh(*result->geometry,
                                                                     *result->look, blockBytes);
                if (prepared)
                    result->prepared = std::move(prepared).value();
                else
                    result->error = prepared.error();
            } catch (const std::bad_alloc&) {
                result->error = "layer compositor: out of memory preparing the mesh";
            }
        },
        [this, job] {
            if (job == m_job && m_pending)
                emit finished();
        });
}

void CompositorMeshJob::cancel() {
    m_future.cancel();
    ++m_job;
    m_pending = false;
    m_result.reset();
}

std::shared_ptr<const PreparedCompositorMesh> CompositorMeshJob::take() {
    if (!m_pending)
        return nullptr;
    m_future.waitForFinished();
    m_pending = false;
    ++m_job; // its finished() is not for anyone now
    return std::exchange(m_result, nullptr);
}

} // namespace ui
