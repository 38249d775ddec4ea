// SPDX-License-Identifier: GPL-3.0-or-later
// layerpaint-cli: the headless tool (docs/architecture.md §4). Needs no Qt and no display.
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli_commands.h"
#include "app/cli_uv_layout.h"
#include "core/base/huge_pages.h"

namespace {
void addCameraOptions(CLI::App* command, cli::CameraArgs& camera) {
    auto* orbit = command->add_option(
        "--orbit", camera.orbit,
        "yaw,pitch,distance: degrees and unit-cube units about the bounding-box centre");
    command
        ->add_option("--camera", camera.cameraFile,
                     "JSON file {\"view\":[16],\"proj\":[16]}, column-major matrices")
        ->excludes(orbit)
        ->check(CLI::ExistingFile);
    command->add_option("--size", camera.size, "Image size WIDTHxHEIGHT")->capture_default_str();
}

/** Every subcommand's arguments, filled in by the parse. */
struct CommandLine {
    std::string infoModel;
    cli::DepthLayersArgs layers;
    cli::PaintArgs paint;
    cli::ExportArgs exportArgs;
    cli::BenchArgs bench;
    std::vector<std::string> loadModels;
    int loadRuns = 9;
    cli::UvLayoutArgs uvLayout;
};

CLI::App* addInfoCommand(CLI::App& app, std::string& model) {
    CLI::App* info = app.add_subcommand("info", "Print a model's summary as JSON");
    info->add_option("MODEL", model, "Model file or builtin:NAME")->required();
    return info;
}

CLI::App* addDepthLayersCommand(CLI::App& app, cli::DepthLayersArgs& layers) {
    CLI::App* layersCommand = app.add_subcommand(
        "layers", "Capture a view's depth layers, connectivity and regions into files");
    layersCommand->add_option("MODEL", layers.model, "Model file or builtin:NAME")->required();
    addCameraOptions(layersCommand, layers.camera);
    layersCommand->add_option("--threshold", layers.threshold,
                              "Connectivity threshold in unit-cube units (default 0.001)");
    layersCommand->add_flag("--plain", layers.plainTest,
                            "Use the paper's plain depth-difference test");
    layersCommand->add_flag("--two-sided", layers.twoSided, "Capture back faces too");
    layersCommand->add_flag("--cpu", layers.cpuCapture,
                            "Capture on the CPU instead of OpenGL (no EGL needed)");
    layersCommand
        ->add_option("--connectivity", layers.connectivity,
                     "Connectivity engine: auto (the faster here), cpu or gpu")
        ->check(CLI::IsMember({"auto", "cpu", "gpu"}))
        ->capture_default_str();
    layersCommand->add_option("--out", layers.outDir, "Output folder")->required();
    layersCommand->add_option("--script", layers.script,
                              "Paint script whose operations (pop-up, hide, ...) run before "
                              "visible.tif is written");
    return layersCommand;
}

CLI::App* addPaintCommand(CLI::App& app, cli::PaintArgs& paint) {
    CLI::App* paintCommand = app.add_subcommand(
        "paint", "Replay a JSON script of painting operations and save the result as a project");
    paintCommand->add_option("MODEL", paint.model, "Model file, project or builtin:NAME")
        ->required();
    paintCommand->add_option("--script", paint.script, "The operations (see README)")
        ->required()
        ->check(CLI::ExistingFile);
    paintCommand->add_option("--out", paint.out, "The project to write (.glb)")->required();
    addCameraOptions(paintCommand, paint.camera);
    paintCommand->add_flag("--cpu", paint.cpuCapture,
                           "Capture on the CPU instead of OpenGL (no EGL needed)");
    paintCommand
        ->add_option("--target", paint.target,
                     "Paint target: texture (an automatic UV layout for a model without UVs) "
                     "or vertex-colors; overrides the script's")
        ->check(CLI::IsMember({"texture", "vertex-colors"}));
    paintCommand
        ->add_option("--resolution", paint.resolution, "Size of a new paint texture (512 to 8192)")
        ->check(CLI::Range(512, 8192));
    return paintCommand;
}

CLI::App* addExportCommand(CLI::App& app, cli::ExportArgs& exportArgs) {
    CLI::App* exportCommand = app.add_subcommand(
        "export", "Export a project or model as glb, obj (+ mtl + png), ply, or its paint "
                  "texture as png, png16, tiff, exr");
    exportCommand->add_option("INPUT", exportArgs.input, "Project, model file or builtin:NAME")
        ->required();
    exportCommand
        ->add_option("--out", exportArgs.out, "The file to write (with --preset: the folder)")
        ->required();
    exportCommand
        ->add_option("--format", exportArgs.format,
                     "glb, obj, ply, png, png16, tiff or exr (default: from the extension)")
        ->check(CLI::IsMember({"glb", "obj", "ply", "png", "png16", "tiff", "exr"}));
    exportCommand
        ->add_option("--target", exportArgs.target,
                     "Paint target to make for a plain model: texture (an automatic UV layout "
                     "for a model without UVs) or vertex-colors")
        ->check(CLI::IsMember({"texture", "vertex-colors"}));
    exportCommand
        ->add_option("--resolution", exportArgs.resolution,
                     "Size of a new paint texture (512 to 8192)")
        ->check(CLI::Range(512, 8192));
    exportCommand->add_flag("--per-layer", exportArgs.perLayer,
                            "Also write each paint layer's channels and mask as PNG images "
                            "beside the export");
    CLI::Option* preset =
        exportCommand->add_option("--preset", exportArgs.preset,
                                  "Write each texture set's maps through an export preset: gltf, "
                                  "unreal, unity, orm or a preset file (JSON)");
    preset->excludes("--format");
    exportCommand
        ->add_option("--map-format", exportArgs.mapFormat,
                     "With --preset: png, tiff, exr or tga (default: the preset's)")
        ->check(CLI::IsMember({"png", "tiff", "exr", "tga"}))
        ->needs(preset);
    exportCommand
        ->add_option("--bit-depth", exportArgs.bitDepth,
                     "With --preset: 8 or 16 (PNG, TIFF), 16 or 32 (EXR)")
        ->check(CLI::IsMember({8, 16, 32}))
        ->needs(preset);
    exportCommand
        ->add_option("--padding", exportArgs.padding,
                     "With --preset: texels of padding around the charts, or fill")
        ->needs(preset);
    exportCommand
        ->add_option("--size", exportArgs.size,
                     "With --preset: the maps' longer side in texels (default: each texture "
                     "set's own)")
        ->check(CLI::Range(1, 16384))
        ->needs(preset);
    return exportCommand;
}

CLI::App* addBenchCommand(CLI::App& app, cli::BenchArgs& bench) {
    CLI::App* benchCommand = app.add_subcommand(
        "bench", "Time build_layers and draw_layers against a plain z-buffer pass (medians)");
    benchCommand->add_option("MODELS", bench.models, "Models (default builtin:trefoil)");
    benchCommand->add_option("--size", bench.sizes, "Image size WIDTHxHEIGHT (repeatable)")
        ->capture_default_str();
    auto* benchOrbit = benchCommand->add_option("--orbit", bench.camera.orbit,
                                                "yaw,pitch,distance (default: framed, 30°, 20°)");
    benchCommand->add_option("--camera", bench.camera.cameraFile, "Camera JSON file")
        ->excludes(benchOrbit)
        ->check(CLI::ExistingFile);
    benchCommand->add_option("--runs", bench.runs, "Measured runs per case")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    benchCommand
        ->add_option("--connectivity", bench.connectivity,
                     "Engine inside build_layers: auto, cpu or gpu (both are timed alone too)")
        ->check(CLI::IsMember({"auto", "cpu", "gpu"}))
        ->capture_default_str();
    benchCommand
        ->add_option("--target-size", bench.targetSize,
                     "Paint the strokes on a texture target of N x N texels (default: the "
                     "document's choice, 2048 on a mesh with UVs, else vertex colours)")
        ->check(CLI::Range(512, 8192));
    benchCommand->add_option("--json", bench.jsonOut, "Also write the results to this file");
    return benchCommand;
}

CLI::App* addBenchLoadCommand(CLI::App& app, std::vector<std::string>& models, int& runs) {
    CLI::App* benchLoadCommand = app.add_subcommand(
        "bench-load", "Time loading models in this process and through the importer process "
                      "(medians)");
    benchLoadCommand->add_option("MODELS", models, "Model files")->required();
    benchLoadCommand->add_option("--runs", runs, "Measured runs per case")
        ->capture_default_str()
        ->check(CLI::Range(1, 1000));
    return benchLoadCommand;
}

CLI::App* addUvLayoutCommand(CLI::App& app, cli::UvLayoutArgs& uvLayout) {
    CLI::App* uvLayoutCommand = app.add_subcommand(
        "uv-layout", "Make an automatic UV layout for a model without texture coordinates and "
                     "print its quality figures as JSON");
    uvLayoutCommand->add_option("MODEL", uvLayout.model, "Model file or builtin:NAME")->required();
    uvLayoutCommand->add_option("--resolution", uvLayout.resolution, "Page size in texels")
        ->capture_default_str()
        ->check(CLI::Range(64, 16384));
    uvLayoutCommand->add_option("--padding", uvLayout.padding, "Empty texels between charts")
        ->capture_default_str()
        ->check(CLI::Range(0, 256));
    uvLayoutCommand
        ->add_option("--texels-per-unit", uvLayout.texelsPerUnit,
                     "Texel density (default: the largest that fits one page; else as many "
                     "pages as needed)")
        ->check(CLI::PositiveNumber);
    uvLayoutCommand->add_option("--threads", uvLayout.threads, "Worker threads (0: one per core)")
        ->capture_default_str();
    uvLayoutCommand
        ->add_option("--max-deviation", uvLayout.maxDeviation,
                     "Degrees a chart's normals may turn from its mean (default 50)")
        ->check(CLI::Range(1.0f, 179.0f));
    uvLayoutCommand
        ->add_option("--sharp-edge", uvLayout.sharpEdge,
                     "Edges bending more than this many degrees cut charts (default 40)")
        ->check(CLI::Range(1.0f, 180.0f));
    uvLayoutCommand->add_flag("--replace-uvs", uvLayout.keepUvs,
                              "Lay out a model that has texture coordinates too");
    uvLayoutCommand->add_option("--json", uvLayout.jsonOut, "Also write the figures to this file");
    uvLayoutCommand->add_option("--out", uvLayout.out, "Save the laid-out mesh (.glb)");
    uvLayoutCommand->add_option("--image", uvLayout.image,
                                "Draw the pages' charts side by side into this image (.png)");
    return uvLayoutCommand;
}

/** A subcommand, and what runs it once it is the one parsed. */
struct Command {
    CLI::App* options;
    std::function<int()> run;
};

/** Every subcommand, in the order the help lists them, reading its arguments from args. */
std::vector<Command> addCommands(CLI::App& app, CommandLine& args) {
    return {
        {addInfoCommand(app, args.infoModel), [&args] { return cli::runInfo(args.infoModel); }},
        {addDepthLayersCommand(app, args.layers),
         [&args] { return cli::runDepthLayers(args.layers); }},
        {addPaintCommand(app, args.paint), [&args] { return cli::runPaint(args.paint); }},
        {addExportCommand(app, args.exportArgs),
         [&args] { return cli::runExport(args.exportArgs); }},
        {addBenchCommand(app, args.bench), [&args] { return cli::runBench(args.bench); }},
        {addBenchLoadCommand(app, args.loadModels, args.loadRuns),
         [&args] { return cli::runBenchLoad(args.loadModels, args.loadRuns); }},
        {addUvLayoutCommand(app, args.uvLayout),
         [&args] { return cli::runUvLayout(args.uvLayout); }},
    };
}

} // namespace

int main(int argc, char** argv) {
    core::restartWithHugePages(argv); // a large model's arrays fill faster
    CLI::App app{"LayerPaint headless tool: inspect models, capture depth layers, replay painting "
                 "scripts and benchmark.\nMODEL is a file (.gltf .glb .obj .ply .stl .off ...) or "
                 "builtin:trefoil, builtin:hexring, builtin:row, builtin:knot?triangles=N (1000 to "
                 "50000000)."};
    app.set_version_flag("--version", std::string("layerpaint-cli ") + LAYERPAINT_VERSION);
    app.require_subcommand(1);
    CommandLine args;
    const std::vector<Command> commands = addCommands(app, args);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    for (const Command& command : commands)
        if (command.options->parsed())
            return command.run();
    return 1;
}
