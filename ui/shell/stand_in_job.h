// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include <QFuture>
#include <QObject>
#include <QThreadPool>

#include "core/model/mesh.h"
#include "core/model/stand_in.h"

namespace ui {

/**
 * Makes a model's stand-in (core::simplifyForDisplay) off the GUI thread with runInBackground()
 * and hands it back on the GUI thread. Quiet: it shows no dialog, as nothing waits for it (the
 * full mesh is drawn until it is there). One job at a time: starting another, or cancel(),
 * stops the running one and drops its result.
 */
class StandInJob : public QObject {
    Q_OBJECT

public:
    explicit StandInJob(QObject* parent = nullptr);
    /** Cancels a running job and waits for its worker. */
    ~StandInJob() override;

    /** Starts simplifying mesh (the document's at meshSerial) to at most targetTriangles. */
    void start(std::shared_ptr<const core::Mesh> mesh, std::uint64_t meshSerial,
               std::size_t targetTriangles);
    /** Stops the running job; no finished() comes for it. */
    void cancel();
    bool isRunning() const { return m_running; }

signals:
    /** A stand-in for the mesh of meshSerial (empty if it could not be made). */
    void finished(std::shared_ptr<const core::StandIn> standIn, std::uint64_t meshSerial);

private:
    QThreadPool m_pool;
    QFuture<void> m_future;
    std::uint64_t m_job = 0; // the current job's number: older ones are dropped
    bool m_running = false;
};

} // namespace ui
