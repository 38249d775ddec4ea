// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/model_loader.h"

#include <QFile>
#include <QMetaObject>

#include <algorithm>
#include <atomic>
#include <exception>
#include <new>
#include <optional>
#include <string>
#include <thread>

#include "core/io/mesh_io.h"
#include "core/io/project_file.h"

namespace ui {

struct ModelLoader::Job {
    QString source;
    std::atomic<bool> cancel{false};
    std::atomic<double> progress{0.0};
    std::thread thread;
};

struct ModelLoader::Outcome {
    std::optional<core::Mesh> mesh;
    std::shared_ptr<const core::ProjectState> state;
    std::string error;
};

ModelLoader::ModelLoader(QObject* parent) : QObject(parent) {
    // Files are parsed in an importer process: one started ahead spares each open its start-up.
    core::keepImporterReady();
}

ModelLoader::~ModelLoader() {
    // Workers post their result to this object; joining them here, before ~QObject removes the
    // pending events, guarantees none runs against a destroyed loader.
    for (auto& job : m_jobs)
        job->cancel = true;
    for (auto& job : m_jobs) {
        if (job->thread.joinable())
            job->thread.join();
    }
}

void ModelLoader::load(const QString& source) {
    cancel();
    auto job = std::make_unique<Job>();
    job->source = source;
    Job* raw = job.get();
    m_jobs.push_back(std::move(job));
    m_current = raw;

    // QFile::encodeName gives the bytes the file system expects for the path.
    const std::string path = QFile::encodeName(source).toStdString();
    raw->thread = std::thread([this, raw, path] {
        auto outcome = std::make_shared<Outcome>();
        try {
            const core::ProgressFn progress = [raw](double fraction) {
                raw->progress.store(fraction, std::memory_order_relaxed);
                return !raw->cancel.load(std::memory_order_relaxed);
            };
            core::Result<core::Project> result = core::loadProject(path, progress);
            if (result) {
                outcome->mesh.emplace(std::move(result->mesh));
                if (result->state)
                    outcome->state =
                        std::make_shared<const core::ProjectState>(std::move(*result->state));
            } else {
                outcome->error = result.error();
            }
        } catch (const std::bad_alloc&) {
            // loadProject reports its own errors; only an allocation failure can still escape.
            outcome->mesh.reset();
            outcome->error = path + ": not enough memory";
        } catch (const std::exception& e) {
            outcome->mesh.reset();
            outcome->error = path + ": " + e.what();
        }
        QMetaObject::invokeMethod(
            this, [this, raw, outcome] { finish(raw, outcome); }, Qt::QueuedConnection);
    });
}

void ModelLoader::cancel() {
    if (m_current)
        m_current->cancel = true;
}

bool ModelLoader::isLoading() const {
    return m_current != nullptr;
}

QString ModelLoader::currentSource() const {
    return m_current ? m_current->source : QString();
}

double ModelLoader::progress() const {
    return m_current ? m_current->progress.load(std::memory_order_relaxed) : 0.0;
}

void ModelLoader::finish(Job* job, const std::shared_ptr<Outcome>& outcome) {
    const auto it = std::find_if(m_jobs.begin(), m_jobs.end(),
                                 [job](const auto& candidate) { return candidate.get() == job; });
    if (it == m_jobs.end())
        return;
    std::unique_ptr<Job> owned = std::move(*it);
    m_jobs.erase(it);
    // The worker posted this as its last step, so the join returns at once.
    owned->thread.join();

    const bool current = owned.get() == m_current;
    if (!current)
        return; // superseded by a newer load
    m_current = nullptr;
    const QString source = owned->source;
    if (owned->cancel)
        emit cancelled(source);
    else if (outcome->mesh)
        emit loaded(source, std::make_shared<core::Mesh>(std::move(*outcome->mesh)),
                    outcome->state);
    else
        emit failed(source, QString::fromStdString(outcome->error));
}

} // namespace ui
