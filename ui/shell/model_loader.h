// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <QFuture>
#include <QObject>
#include <QString>
#include <QThreadPool>

#include "core/io/project/project_file.h"
#include "core/model/mesh.h"
#include "core/model/mesh_topology.h"
#include "core/paint/targets/paint_target.h"

namespace core {
class PaintTarget;
}

namespace ui {

/** What a load delivers (ModelLoader::loaded()), made in the background. */
struct LoadedModel {
    std::shared_ptr<const core::Mesh> mesh;
    std::shared_ptr<const core::MeshTopology> topology;
    /** The project's state (a LayerPaint project), or null for a plain model. */
    std::shared_ptr<const core::ProjectState> state;
    /**
     * A plain model's paint target on its own UVs, made with the options load() was given (so
     * the first stroke does not wait for it, and the first frame shows it); null if none.
     */
    std::unique_ptr<core::PaintTarget> paintTarget;
    core::PaintTargetOptions paintOptions;

    ~LoadedModel();
};

/**
 * Loads models and projects with core::loadProject, and makes their topology, in the background
 * (runInBackground()) and reports back on the GUI thread, so the event loop never waits for a
 * file. One load is current at
 * a time: starting another cancels the previous one and drops its result.
 */
class ModelLoader : public QObject {
    Q_OBJECT

public:
    explicit ModelLoader(QObject* parent = nullptr);
    /** Cancels every running load and waits for the workers to stop. */
    ~ModelLoader() override;

    /**
     * Starts loading source: a file path or "builtin:NAME". A plain model with UVs gets its paint
     * target made with paintOptions too (none made when paintOptions asks for an automatic UV
     * layout).
     */
    void load(const QString& source, const core::PaintTargetOptions& paintOptions = {});
    /**
     * Stops the current load: cancelled() is emitted before this returns and nothing of the load
     * arrives later (its worker stops at its next progress report).
     */
    void cancel();

    bool isLoading() const;
    /** The current load's source, or empty. */
    QString currentSource() const;
    /** Loads whose workers have not ended yet (cancelled and superseded ones included). */
    int runningJobs() const { return int(m_jobs.size()); }
    /** Progress of the current load in [0, 1]; safe to poll from the GUI thread. */
    double progress() const;

signals:
    /** The model, its topology and paint target or project state (see LoadedModel). */
    void loaded(const QString& source, std::shared_ptr<ui::LoadedModel> model);
    /** message comes from core and names the file. */
    void failed(const QString& source, const QString& message);
    void cancelled(const QString& source);

private:
    struct Job;
    struct Outcome;
    /**
     * The project or model at path and its topology into outcome, or its error; nothing when
     * progress says cancelled. On a worker thread.
     */
    static void loadInto(Outcome& outcome, const std::string& path,
                         const core::PaintTargetOptions& paintOptions,
                         const core::ProgressFn& progress);
    /** model's paint target made with options (on the worker; none if it cannot be made). */
    static void makePaintTarget(LoadedModel& model, const core::PaintTargetOptions& options,
                                const core::ProgressFn& progress);
    void finish(Job* job, const std::shared_ptr<Outcome>& outcome);
    /** Stops the current load without a word (its worker ends on its own, its result dropped). */
    void dropCurrent();

    QThreadPool m_pool; // a cancelled or superseded load runs on until its next progress report
    std::vector<std::unique_ptr<Job>> m_jobs; // current one last; touched on the GUI thread only
    Job* m_current = nullptr;
};

} // namespace ui
