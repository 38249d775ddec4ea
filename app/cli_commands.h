// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/depth/depth_layers.h"
#include "core/document/script.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"

namespace core {
class Document;
class DepthCapturer;
} // namespace core
namespace render {
class HeadlessContext;
}

namespace cli {

/** How a command picks its view (docs/architecture.md §4). */
struct CameraArgs {
    std::string orbit;      // "yaw,pitch,distance" (degrees, unit-cube units); empty: framed
    std::string cameraFile; // {"view":[16], "proj":[16]} column-major
    std::string size = "1280x720";
};

struct DepthLayersArgs {
    std::string model;
    CameraArgs camera;
    std::optional<float> threshold;
    bool plainTest = false;
    bool twoSided = false;
    bool cpuCapture = false;
    std::string connectivity = "auto"; // auto | cpu | gpu
    std::string outDir;
    std::string script; // operations to replay before visible.tif is written
};

struct PaintArgs {
    std::string model;
    std::string script;
    std::string out;
    CameraArgs camera;
    bool cpuCapture = false;
    std::string target; // texture or vertex-colors: overrides the script's target
    int resolution = 0; // of a new texture; 0: the script's or the default
};

struct ExportArgs {
    std::string input; // a model, a project or builtin:NAME
    std::string out;
    std::string format;    // empty: from the extension of out
    std::string target;    // "", "texture" or "vertex-colors": paint target of a plain model
    int resolution = 0;    // > 0: size of a new paint texture
    bool perLayer = false; // also every paint layer's channels and mask as images
    // Texture sets through an export preset (out is then a folder):
    std::string preset;    // a built-in preset's id or a preset file; empty: none
    std::string mapFormat; // png, tiff, exr, tga; empty: the preset's
    int bitDepth = 0;      // 0: the preset's
    std::string padding;   // texels or "fill"; empty: the preset's
    int size = 0;          // the maps' longer side; 0: each texture set's own
};

struct BenchArgs {
    std::vector<std::string> models; // empty: builtin:trefoil
    std::vector<std::string> sizes = {"1280x720"};
    CameraArgs camera;
    int runs = 7;
    std::string connectivity = "auto"; // the engine build_layers uses; both are timed anyway
    int targetSize = 0; // the strokes' texture target, N × N; 0: the document's default target
    std::string jsonOut;
};

/**
 * The capturer a command builds layers with: the CPU one (cpu), or the GL one in a new headless
 * context, which is kept in context (it must outlive the capturer). The Error says why OpenGL
 * is unavailable.
 */
core::Result<std::unique_ptr<core::DepthCapturer>>
makeCapturer(bool cpu, std::unique_ptr<render::HeadlessContext>& context);

/**
 * Prints "layerpaint-cli: message" on stderr (one line: control characters escaped, cut after
 * 2000 characters) and returns the failure exit code.
 */
int fail(const std::string& message);
/** Prints "layerpaint-cli: warning: W" on stderr for each of warnings, as fail() does. */
void warn(const std::vector<std::string>& warnings);

/**
 * value as the CLI prints it; bytes that are not UTF-8 (a file's material or texture names can
 * hold any) become U+FFFD, where dump() would throw.
 */
std::string jsonText(const nlohmann::json& value, int indent);

/**
 * The command line's --target ("texture", "vertex-colors" or empty: unchanged) and --resolution
 * (0: unchanged) applied to options.
 */
void applyTargetArgs(const std::string& target, int resolution, core::PaintTargetOptions& options);
/**
 * The view of --orbit / --camera / --size for mesh; without either, fallback if given, else the
 * mesh framed, turned 30° and raised 20°.
 */
core::Result<core::View> makeView(const CameraArgs& args, const core::Mesh& mesh,
                                  const core::Camera* fallback = nullptr);
/** The orbit camera makeView() uses when there is no --camera file. */
core::Result<core::Camera> makeCamera(const CameraArgs& args, const core::Mesh& mesh,
                                      const core::Camera* fallback = nullptr);

/**
 * Replays script's operations on doc through the core's script runner (the GUI's code path),
 * building layers with capturer for view whenever an operation needs them; operations that move
 * the camera change view. An Error naming the file, the operation's number and the problem.
 */
core::Status replayScript(const core::Script& script, const std::string& path, core::Document& doc,
                          core::DepthCapturer& capturer, core::View& view);

/** `info MODEL`: prints the model's JSON summary on stdout; returns the exit code. */
int runInfo(const std::string& model);
/** `layers MODEL ...`: writes the files of docs/architecture.md §4; returns the exit code. */
int runDepthLayers(const DepthLayersArgs& args);
/** `paint MODEL --script S.json --out RESULT.glb`: replays and saves; the exit code. */
int runPaint(const PaintArgs& args);
/** `export INPUT --out FILE`: writes a model or paint texture format; the exit code. */
int runExport(const ExportArgs& args);
/** `bench [MODELS]`: Table 2 timings and the plain-pass baseline as JSON; the exit code. */
int runBench(const BenchArgs& args);

/**
 * `bench-load`: medians of loading each model in this process and through the importer process,
 * started for the load and started ahead (as the GUI does), as JSON on standard output.
 */
int runBenchLoad(const std::vector<std::string>& models, int runs);

} // namespace cli
