// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/stand_in_job.h"

#include <new>

#include "ui/shell/background_task.h"

namespace ui {

StandInJob::StandInJob(QObject* parent) : QObject(parent) {
    m_pool.setMaxThreadCount(1);
}

StandInJob::~StandInJob() {
    cancel();
    m_pool.waitForDone();
}

void StandInJob::start(std::shared_ptr<const core::Mesh> mesh, std::uint64_t meshSerial,
                       std::size_t targetTriangles) {
    cancel();
    const std::uint64_t job = ++m_job;
    m_running = true;
    auto made = std::make_shared<std::shared_ptr<core::StandIn>>();
    m_future = runInBackground(
        m_pool, this,
        [made, mesh = std::move(mesh), targetTriangles](const core::ProgressFn& progress) {
            try {
                auto standIn = core::simplifyForDisplay(*mesh, targetTriangles, progress);
                if (standIn)
                    *made = std::make_shared<core::StandIn>(std::move(standIn).value());
            } catch (const std::bad_alloc&) {
                made->reset(); // no stand-in: the full mesh is drawn while moving too
            }
        },
        [this, job, made, meshSerial] {
            if (job != m_job)
                return; // cancelled or replaced by a newer job
            m_running = false;
            emit finished(*made ? std::shared_ptr<const core::StandIn>(*made)
                                : std::make_shared<const core::StandIn>(),
                          meshSerial);
        });
}

void StandInJob::cancel() {
    m_future.cancel();
    ++m_job;
    m_running = false;
}

} // namespace ui
