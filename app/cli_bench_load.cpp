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
#include <vector>

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

/** One model's samples, one per run. */
struct LoadSamples {
    std::vector<double> local;   // in this process
    std::vector<double> cold;    // through an importer started for the load
    std::vector<double> paused;  // in this process after the pause
    std::vector<double> ahead;   // through the importer started ahead, after the pause
    std::vector<double> extra;   // ahead over paused, percent
    std::vector<double> extraMs; // ahead minus paused
    double setUp = 0.0;          // the document's set-up of the loaded mesh, median
};

const auto inProcess = [](const std::string& m) { return core::loadMeshInProcess(m); };
const auto outOfProcess = [](const std::string& m) { return core::loadMesh(m); };

/** Loads in this process and through an importer started for each; false if one fails. */
bool timeColdLoads(const std::string& model, int runs, LoadSamples& samples) {
    // One unmeasured load each way: the file and the libraries in the page cache.
    if (timed(model, inProcess) < 0.0 || timed(model, outOfProcess) < 0.0)
        return false;
    for (int r = 0; r < runs; ++r) {
        samples.local.push_back(timed(model, inProcess));
        samples.cold.push_back(timed(model, outOfProcess));
    }
    return true;
}

/**
 * The importer started ahead, against a load in process in the same conditions: each load after
 * the same pause (in which the next importer starts and waits, as between two opens in the GUI;
 * no load runs beside the start of the next one), the two in turn first. Its cost is the median
 * of the pairs' ratios. The importer must be kept ready (core::keepImporterReady()).
 */
void timeLoadsAhead(const std::string& model, int runs, LoadSamples& samples) {
    const auto afterPause = [&](const auto& load) {
        std::this_thread::sleep_for(std::chrono::seconds(2));
        return timed(model, load);
    };
    for (int r = 0; r < runs; ++r) {
        double viaImporter = 0.0, here = 0.0;
        if (r % 2 == 0) {
            viaImporter = afterPause(outOfProcess);
            here = afterPause(inProcess);
        } else {
            here = afterPause(inProcess);
            viaImporter = afterPause(outOfProcess);
        }
        samples.ahead.push_back(viaImporter);
        samples.paused.push_back(here);
        samples.extra.push_back(here > 0.0 ? 100.0 * (viaImporter / here - 1.0) : 0.0);
        samples.extraMs.push_back(viaImporter - here);
    }
}

/**
 * Opening a model goes on with the document's set-up: its topology and the paint target. False
 * (the message on stderr) if the model or its target fails.
 */
bool timeDocumentSetUp(const std::string& model, int runs, LoadSamples& samples) {
    const core::Result<core::Mesh> mesh = core::loadMeshInProcess(model);
    if (!mesh)
        return false;
    std::vector<double> times;
    for (int r = 0; r < runs; ++r) {
        core::Mesh copy = *mesh;
        core::Document doc;
        const Clock::time_point start = Clock::now();
        doc.setMesh(std::move(copy), model);
        if (const core::Result<core::PaintTarget*> target = doc.ensurePaintTarget(); !target) {
            std::cerr << "layerpaint-cli: " << model << ": " << target.error() << '\n';
            return false;
        }
        times.push_back(msSince(start));
    }
    samples.setUp = median(times);
    return true;
}

nlohmann::json loadJson(const std::string& model, int runs, const LoadSamples& samples) {
    const double base = median(samples.local);
    return {{"model", model},
            {"runs", runs},
            {"in_process_ms", base},
            {"in_process_after_pause_ms", median(samples.paused)},
            {"importer_started_for_the_load",
             {{"median_ms", median(samples.cold)},
              {"extra_percent", base > 0.0 ? 100.0 * (median(samples.cold) / base - 1.0) : 0.0}}},
            {"importer_started_ahead",
             {{"median_ms", median(samples.ahead)},
              {"extra_percent", median(samples.extra)},
              {"extra_ms", median(samples.extraMs)}}},
            {"document_set_up_ms", samples.setUp},
            {"importer_extra_percent_of_open",
             100.0 * median(samples.extraMs) / (median(samples.paused) + samples.setUp)}};
}

} // namespace

int runBenchLoad(const std::vector<std::string>& models, int runs) {
    std::vector<LoadSamples> samples(models.size());
    for (std::size_t i = 0; i < models.size(); ++i)
        if (!timeColdLoads(models[i], runs, samples[i]))
            return 1;
    core::keepImporterReady();
    for (std::size_t i = 0; i < models.size(); ++i)
        timeLoadsAhead(models[i], runs, samples[i]);
    for (std::size_t i = 0; i < models.size(); ++i)
        if (!timeDocumentSetUp(models[i], runs, samples[i]))
            return 1;
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i = 0; i < models.size(); ++i)
        out.push_back(loadJson(models[i], runs, samples[i]));
    std::cout << jsonText(out, 2) << '\n';
    return 0;
}

} // namespace cli
