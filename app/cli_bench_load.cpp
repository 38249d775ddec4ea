// SPDX-License-Identifier: GPL-3.0-or-later
// `bench-load`: what parsing files in the importer process costs. Each run loads the model three
// ways: in this process (what the importer itself runs), through an importer started for the load
// (one-shot tools such as this CLI), and through one started ahead (the GUI, which keeps one
// ready; it is given two seconds to start, less than a user takes between two opens). A load
// through the importer started ahead is paired with one in process after the same pause; the one
// started for the load is compared with the loads in process between them. The document's set-up
// of the loaded mesh (what opening a model does after the load, before any GPU work) is timed
// too, so the importer's cost can be read against the whole open.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/cli_commands.h"
#include "app/cli_timing.h"
#include "core/document/document.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/mesh_io.h"

namespace cli {

namespace {

/** Milliseconds one load takes, or a negative number (and the message on stderr) if it fails. */
template <typename Load> double timed(const std::string& model, Load load) {
    const Clock::time_point start = Clock::now();
    const core::Result<core::Mesh> mesh = load(model);
    const double ms = msSince(start);
    if (!mesh) {
        std::cerr << "layerpaint-cli: " << mesh.error() << '\n';
        return -1.0;
    }
    return ms;
}

} // namespace

int runBenchLoad(const std::vector<std::string>& models, int runs) {
    using nlohmann::json;
    auto inProcess = [](const std::string& m) { return core::loadMeshInProcess(m); };
    auto outOfProcess = [](const std::string& m) { return core::loadMesh(m); };
    std::vector<std::vector<double>> local(models.size()), cold(models.size()),
        paused(models.size()), ahead(models.size()), extra(models.size()), extraMs(models.size());
    for (std::size_t i = 0; i < models.size(); ++i) {
        // One unmeasured load each way: the file and the libraries in the page cache.
        if (timed(models[i], inProcess) < 0.0 || timed(models[i], outOfProcess) < 0.0)
            return 1;
        for (int r = 0; r < runs; ++r) {
            local[i].push_back(timed(models[i], inProcess));
            cold[i].push_back(timed(models[i], outOfProcess));
        }
    }
    // The importer started ahead, against a load in process in the same conditions: each load
    // after the same pause (in which the next importer starts and waits, as between two opens in
    // the GUI; no load runs beside the start of the next one), the two in turn first. Its cost
    // is the median of the pairs' ratios.
    core::keepImporterReady();
    const auto afterPause = [&](const std::string& model, const auto& load) {
        std::this_thread::sleep_for(std::chrono::seconds(2));
        return timed(model, load);
    };
    for (std::size_t i = 0; i < models.size(); ++i)
        for (int r = 0; r < runs; ++r) {
            double viaImporter = 0.0, here = 0.0;
            if (r % 2 == 0) {
                viaImporter = afterPause(models[i], outOfProcess);
                here = afterPause(models[i], inProcess);
            } else {
                here = afterPause(models[i], inProcess);
                viaImporter = afterPause(models[i], outOfProcess);
            }
            ahead[i].push_back(viaImporter);
            paused[i].push_back(here);
            extra[i].push_back(here > 0.0 ? 100.0 * (viaImporter / here - 1.0) : 0.0);
            extraMs[i].push_back(viaImporter - here);
        }

    // Opening a model goes on with the document's set-up: its topology and the paint target.
    std::vector<double> setUp(models.size());
    for (std::size_t i = 0; i < models.size(); ++i) {
        const core::Result<core::Mesh> mesh = core::loadMeshInProcess(models[i]);
        if (!mesh)
            return 1;
        std::vector<double> samples;
        for (int r = 0; r < runs; ++r) {
            core::Mesh copy = *mesh;
            core::Document doc;
            const Clock::time_point start = Clock::now();
            doc.setMesh(std::move(copy), models[i]);
            if (const core::Result<core::PaintTarget*> target = doc.ensurePaintTarget(); !target) {
                std::cerr << "layerpaint-cli: " << models[i] << ": " << target.error() << '\n';
                return 1;
            }
            samples.push_back(msSince(start));
        }
        setUp[i] = median(samples);
    }

    json out = json::array();
    for (std::size_t i = 0; i < models.size(); ++i) {
        const double base = median(local[i]);
        out.push_back(
            {{"model", models[i]},
             {"runs", runs},
             {"in_process_ms", base},
             {"in_process_after_pause_ms", median(paused[i])},
             {"importer_started_for_the_load",
              {{"median_ms", median(cold[i])},
               {"extra_percent", base > 0.0 ? 100.0 * (median(cold[i]) / base - 1.0) : 0.0}}},
             {"importer_started_ahead",
              {{"median_ms", median(ahead[i])},
               {"extra_percent", median(extra[i])},
               {"extra_ms", median(extraMs[i])}}},
             {"document_set_up_ms", setUp[i]},
             {"importer_extra_percent_of_open",
              100.0 * median(extraMs[i]) / (median(paused[i]) + setUp[i])}});
    }
    std::cout << jsonText(out, 2) << '\n';
    return 0;
}

} // namespace cli
