// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>
#include <string>

namespace cli {

/** How a command picks its view (DESIGN.md §4). */
struct CameraArgs {
    std::string orbit;      // "yaw,pitch,distance" (degrees, unit-cube units); empty: framed
    std::string cameraFile; // {"view":[16], "proj":[16]} column-major
    std::string size = "1280x720";
};

struct LayersArgs {
    std::string model;
    CameraArgs camera;
    std::optional<float> threshold;
    bool plainTest = false;
    bool twoSided = false;
    bool cpuCapture = false;
    std::string outDir;
};

/** `info MODEL`: prints the model's JSON summary on stdout; returns the exit code. */
int runInfo(const std::string& model);
/** `layers MODEL ...`: writes the files of DESIGN.md §4; returns the exit code. */
int runLayers(const LayersArgs& args);

} // namespace cli
