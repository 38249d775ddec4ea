// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/model_loader.h"

#include <QFile>

#include <algorithm>
#include <exception>
#include <new>
#include <optional>
#include <string>

#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/paint/targets/layout_target.h"
#include "ui/shell/background_task.h"

namespace ui {

namespace {
// Superseded loads stop at their next progress report; until then each holds a thread.
constexpr int kMaxLoadThreads = 8;
} // namespace

struct ModelLoader::Job {
    QString source;
    QFuture<void> future;
};

// What the file takes of a load's progress; the mesh's topology and paint target the rest.
constexpr double kFileShare = 0.8;
constexpr double kTopologyShare = 0.15;

LoadedModel::~LoadedModel() = default;

struct ModelLoader::Outcome {
    std::shared_ptr<LoadedModel> model;
    std::string error;
};

void ModelLoader::loadInto(Outcome& outcome, const std::string& path,
                           const core::PaintTargetOptions& paintOptions,
                           const core::ProgressFn& progress) {
    core::Result<core::Project> result =
        core::loadProject(path, [&progress](double f) { return progress(kFileShare * f); });
    if (!result) {
        outcome.error = result.error();
        return;
    }
    std::optional<core::MeshTopology> topology = core::buildMeshTopology(
        result->mesh, [&progress](double f) { return progress(kFileShare + kTopologyShare * f); });
    if (!topology)
        return; // cancelled
    auto model = std::make_shared<LoadedModel>();
    model->topology = std::make_shared<const core::MeshTopology>(std::move(*topology));
    model->mesh = std::make_shared<const core::Mesh>(std::move(result->mesh));
    if (result->state)
        model->state = std::make_shared<const core::ProjectState>(std::move(*result->state));
    else if (model->mesh->hasUvs() && !core::needsUvLayout(*model->mesh, paintOptions))
        makePaintTarget(*model, paintOptions, progress);
    if (!progress(1.0))
        return; // cancelled
    outcome.model = std::move(model);
}

void ModelLoader::makePaintTarget(LoadedModel& model, const core::PaintTargetOptions& options,
                                  const core::ProgressFn& progress) {
    if (!progress(kFileShare + kTopologyShare))
        return;
    // Made as the document would on the first stroke; without one (an error, or too little
    // memory for it now) the first stroke still tries, and says why it cannot.
    try {
        core::Result<std::unique_ptr<core::PaintTarget>> target =
            core::makePaintTargetWithLayout(model.mesh, model.topology, options);
        if (!target)
            return;
        target.value()->prepareForStrokes();
        model.paintTarget = std::move(target).value();
        model.paintOptions = options;
    } catch (const std::bad_alloc&) {
        model.paintTarget.reset();
    }
}

ModelLoader::ModelLoader(QObject* parent) : QObject(parent) {
    m_pool.setMaxThreadCount(kMaxLoadThreads);
    // Files are parsed in an importer process: one started ahead spares each open its start-up.
    core::keepImporterReady();
}

ModelLoader::~ModelLoader() {
    // Their reports go to watchers that die with this object; the jobs only have to end first.
    for (auto& job : m_jobs)
        job->future.cancel();
    m_pool.waitForDone();
}

void ModelLoader::load(const QString& source, const core::PaintTargetOptions& paintOptions) {
    dropCurrent(); // superseded: no cancelled()
    auto job = std::make_unique<Job>();
    job->source = source;
    Job* raw = job.get();
    m_jobs.push_back(std::move(job));
    m_current = raw;

    // QFile::encodeName gives the bytes the file system expects for the path.
    const std::string path = QFile::encodeName(source).toStdString();
    auto outcome = std::make_shared<Outcome>();
    raw->future = runInBackground(
        m_pool, this,
        [outcome, path, paintOptions](const core::ProgressFn& progress) {
            try {
                loadInto(*outcome, path, paintOptions, progress);
            } catch (const std::bad_alloc&) {
                // loadProject reports its own errors; only an allocation failure can still escape.
                outcome->model.reset();
                outcome->error = path + ": not enough memory";
            } catch (const std::exception& e) {
                outcome->model.reset();
                outcome->error = path + ": " + e.what();
            }
        },
        [this, raw, outcome] { finish(raw, outcome); });
}

void ModelLoader::cancel() {
    if (!m_current)
        return;
    // Said at once: the worker stops at its next progress report, and its result is dropped.
    const QString source = m_current->source;
    dropCurrent();
    emit cancelled(source);
}

void ModelLoader::dropCurrent() {
    if (!m_current)
        return;
    m_current->future.cancel();
    m_current = nullptr;
}

bool ModelLoader::isLoading() const {
    return m_current != nullptr;
}

QString ModelLoader::currentSource() const {
    return m_current ? m_current->source : QString();
}

double ModelLoader::progress() const {
    return m_current ? jobProgress(m_current->future) : 0.0;
}

void ModelLoader::finish(Job* job, const std::shared_ptr<Outcome>& outcome) {
    const auto it = std::find_if(m_jobs.begin(), m_jobs.end(),
                                 [job](const auto& candidate) { return candidate.get() == job; });
    if (it == m_jobs.end())
        return;
    std::unique_ptr<Job> owned = std::move(*it);
    m_jobs.erase(it);

    const bool current = owned.get() == m_current;
    if (!current)
        return; // superseded by a newer load
    m_current = nullptr;
    const QString source = owned->source;
    if (outcome->model)
        emit loaded(source, std::move(outcome->model));
    else
        emit failed(source, QString::fromStdString(outcome->error));
}

} // namespace ui
