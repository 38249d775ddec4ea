// SPDX-License-Identifier: GPL-3.0-or-later
// `bench-load`: what parsing files in the importer process costs. Each run loads the model three
// ways: in this process (what the importer itself runs), through an importer started for the load
// (one-shot tools such as this CLI), and through one started ahead (the GUI, which keeps one
// ready; it is given two seconds to start, less than a user takes between two opens). A load
// through the importer started ahead is compared with one in process right after it (the same
// pause before, the same state of the machine); the one started for the load with the loads in
// process between them.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/cli_commands.h"
#include "core/io/mesh_io.h"
#include "core/io/mesh_io_in_process.h"

namespace cli {

namespace {

using Clock = std::chrono::steady_clock;

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n == 0 ? 0.0 : n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/** Milliseconds one load takes, or a negative number (and the message on stderr) if it fails. */
template <typename Load> double timed(const std::string& model, Load load) {
    const Clock::time_point start = Clock::now();
    const core::Result<core::Mesh> mesh = load(model);
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
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
        ahead(models.size()), paused(models.size());
    for (std::size_t i = 0; i < models.size(); ++i) {
        // One unmeasured load each way: the file and the libraries in the page cache.
        if (timed(models[i], inProcess) < 0.0 || timed(models[i], outOfProcess) < 0.0)
            return 1;
        for (int r = 0; r < runs; ++r) {
            local[i].push_back(timed(models[i], inProcess));
            cold[i].push_back(timed(models[i], outOfProcess));
        }
    }
    // Each load through the importer started ahead is followed by one in process, so that both
    // see the same state of the machine (other programs, caches after the pause).
    core::keepImporterReady();
    for (std::size_t i = 0; i < models.size(); ++i)
        for (int r = 0; r < runs; ++r) {
            std::this_thread::sleep_for(std::chrono::seconds(2));
            ahead[i].push_back(timed(models[i], outOfProcess));
            paused[i].push_back(timed(models[i], inProcess));
        }

    json out = json::array();
    for (std::size_t i = 0; i < models.size(); ++i) {
        auto entry = [](const std::vector<double>& samples, double base) {
            const double ms = median(samples);
            return json{{"median_ms", ms},
                        {"extra_percent", base > 0.0 ? 100.0 * (ms / base - 1.0) : 0.0}};
        };
        const double base = median(local[i]), basePaused = median(paused[i]);
        out.push_back({{"model", models[i]},
                       {"runs", runs},
                       {"in_process_ms", base},
                       {"in_process_after_pause_ms", basePaused},
                       {"importer_started_for_the_load", entry(cold[i], base)},
                       {"importer_started_ahead", entry(ahead[i], basePaused)}});
    }
    std::cout << out.dump(2) << '\n';
    return 0;
}

} // namespace cli
