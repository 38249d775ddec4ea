// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <string>

namespace cli {

struct UvLayoutArgs {
    std::string model;
    int resolution = 2048;
    int padding = 4;
    double texelsPerUnit = 0.0; // 0: fit one page
    unsigned threads = 0;
    float maxDeviation = 0.0f; // degrees; 0: the core's default
    float sharpEdge = 0.0f;    // degrees; 0: the core's default
    bool keepUvs = false;      // lay out even a model that has UVs (they are replaced)
    std::string jsonOut;
    std::string out;   // the laid-out mesh as .glb
    std::string image; // the pages side by side, each chart in its own colour
};

/**
 * `uv-layout MODEL`: makes an automatic UV layout and prints its quality figures and time as
 * JSON; optionally saves the laid-out mesh. The exit code.
 */
int runUvLayout(const UvLayoutArgs& args);

} // namespace cli
