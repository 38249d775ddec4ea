// SPDX-License-Identifier: GPL-3.0-or-later
// `export`: the GUI's File ▸ Export headless. A project exports its paint; a plain model exports
// as loaded (a format conversion) unless a paint target is asked for.
#include <charconv>
#include <chrono>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli_commands.h"
#include "app/cli_timing.h"
#include "core/base/text.h"
#include "core/document/document.h"
#include "core/io/export.h"
#include "core/io/paint_layers_export.h"
#include "core/io/project/project_file.h"
#include "core/io/texture_sets/texture_set_export.h"

namespace cli {

namespace {

/** The format named, or the one the extension of out implies. */
std::optional<core::ExportFormat> formatOf(const ExportArgs& args) {
    if (!args.format.empty())
        return core::parseExportFormat(args.format);
    const std::string ext = core::lowerExtension(args.out);
    if (ext == ".glb")
        return core::ExportFormat::Glb;
    if (ext == ".obj")
        return core::ExportFormat::Obj;
    if (ext == ".ply")
        return core::ExportFormat::Ply;
    if (ext == ".png")
        return core::ExportFormat::Png8;
    if (ext == ".tif" || ext == ".tiff")
        return core::ExportFormat::Tiff;
    if (ext == ".exr")
        return core::ExportFormat::Exr;
    return std::nullopt;
}

std::optional<int> parseCount(const std::string& text) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value < 0)
        return std::nullopt;
    return value;
}

/** The preset of args with the options given beside it. */
core::Result<core::ExportPreset> presetOf(const ExportArgs& args) {
    core::Result<core::ExportPreset> preset = core::findPreset(args.preset);
    if (!preset)
        return preset;
    if (!args.mapFormat.empty()) {
        preset->format = *core::parseMapFileFormat(args.mapFormat);
        if (args.bitDepth == 0)
            preset->bitDepth = preset->format == core::MapFileFormat::Exr ? 16 : 8;
    }
    if (args.bitDepth != 0)
        preset->bitDepth = args.bitDepth;
    if (args.padding == "fill") {
        preset->padding = core::kPadToFill;
    } else if (!args.padding.empty()) {
        const std::optional<int> n = parseCount(args.padding);
        if (!n)
            return core::Error{"--padding: a number of texels or fill, not “" +
                               core::printable(args.padding) + "”"};
        preset->padding = *n;
    }
    if (const core::Status s = core::checkPreset(*preset); !s)
        return s.takeError();
    return preset;
}

/** The stem of input as $mesh: a file's name without its extension, builtin:NAME's NAME. */
std::string meshNameOf(const std::string& input) {
    constexpr std::string_view kBuiltin = "builtin:";
    if (input.starts_with(kBuiltin))
        return input.substr(kBuiltin.size(), input.find('?') - kBuiltin.size());
    return std::filesystem::path(input).stem().string();
}

/** Writes the texture sets of doc through the preset into args.out (made if missing). */
core::Result<std::vector<std::string>> exportThroughPreset(const ExportArgs& args,
                                                           core::Document& doc,
                                                           const core::ExportPreset& preset,
                                                           std::vector<std::string>& warnings) {
    const core::Result<core::PaintTarget*> target = doc.ensurePaintTarget();
    if (!target)
        return core::Error{args.input + ": " + target.error()};
    std::error_code ec;
    std::filesystem::create_directories(args.out, ec);
    if (!std::filesystem::is_directory(args.out))
        return core::Error{args.out + ": cannot make the folder" +
                           (ec ? " (" + ec.message() + ")" : std::string())};
    core::TextureExportOptions options{preset, meshNameOf(args.input), args.size};
    core::Result<std::vector<std::string>> files =
        core::exportTextureSets(args.out, doc.paintedMesh(), options, {}, &warnings);
    if (!files && files.errorKind() != core::ErrorKind::Failed)
        return core::Error{args.input + ": " + files.error()};
    return files;
}

} // namespace

int runExport(const ExportArgs& args) {
    std::optional<core::ExportPreset> preset;
    if (!args.preset.empty()) {
        core::Result<core::ExportPreset> found = presetOf(args);
        if (!found)
            return fail(found.error());
        preset = std::move(*found);
    }
    const std::optional<core::ExportFormat> format =
        preset ? std::optional(core::ExportFormat::Png8) : formatOf(args);
    if (!format)
        return fail(args.out + ": unknown export format (use --format glb, obj, ply, png, png16, "
                               "tiff or exr, or one of their extensions)");
    const auto start = std::chrono::steady_clock::now();
    auto project = core::loadProject(args.input);
    if (!project)
        return fail(project.error());
    // What loading corrected or left out, then what the written file cannot keep.
    std::vector<std::string> warnings = project->mesh.warnings;
    warn(warnings);
    core::Document doc;
    doc.setMesh(std::move(project->mesh), args.input);
    if (project->state) {
        if (const core::Status s = core::applyProjectState(doc, *project->state); !s)
            std::cerr << "layerpaint-cli: " << args.input << ": " << s.error() << '\n';
    }
    if (!args.target.empty() || args.resolution > 0) {
        core::PaintTargetOptions options = doc.paintTargetOptions();
        applyTargetArgs(args.target, args.resolution, options);
        if (const core::Status s = doc.setPaintTarget(options); !s)
            return fail(args.input + ": " + s.error());
    }
    const double loadMs = msSince(start);

    const auto exportStart = std::chrono::steady_clock::now();
    core::Result<std::vector<std::string>> files = std::vector<std::string>{};
    const std::size_t loadWarnings = warnings.size();
    if (preset) {
        files = exportThroughPreset(args, doc, *preset, warnings);
    } else if (core::isTextureFormat(*format)) {
        const core::Result<core::PaintTarget*> target = doc.ensurePaintTarget();
        if (!target)
            return fail(args.input + ": " + target.error());
        const core::PaintTarget& painted = **target;
        if (painted.pageCount() == 0)
            return fail(args.input + ": there is no paint texture to export (the model is "
                                     "painted with vertex colours)");
        std::vector<core::Image> pages, metallicRoughness;
        for (std::size_t i = 0; i < painted.pageCount(); ++i) {
            pages.push_back(painted.page(i));
            metallicRoughness.push_back(painted.metallicRoughnessPage(i));
        }
        files = core::exportChannelTextures(args.out, *format, pages, metallicRoughness);
    } else {
        // The painted mesh carries its materials' maps, painted roughness and metallic included.
        files = core::exportMesh(args.out, *format, doc.paintedMesh(), {}, &warnings);
    }
    if (!files)
        return fail(files.error());
    if (args.perLayer) {
        const core::PaintTarget* painted = doc.currentPaintTarget();
        const core::PaintLayerTarget* paintLayers = painted ? painted->paintLayers() : nullptr;
        if (!paintLayers)
            return fail(args.input + ": there are no paint layers to export (they need a paint "
                                     "texture)");
        // Beside the export, or with a preset in its folder as if the model were written there.
        const std::string beside =
            preset ? (std::filesystem::path(args.out) / (meshNameOf(args.input) + ".png")).string()
                   : args.out;
        auto layers = core::exportPaintLayerImages(beside, paintLayers->paintLayerStack());
        if (!layers)
            return fail(layers.error());
        files->insert(files->end(), layers->begin(), layers->end());
    }
    warn({warnings.begin() + std::ptrdiff_t(loadWarnings), warnings.end()});
    const nlohmann::json out = {{"format", preset ? core::mapFileFormatName(preset->format)
                                                  : core::exportFormatName(*format)},
                                {"files", *files},
                                {"warnings", warnings},
                                {"load_ms", loadMs},
                                {"export_ms", msSince(exportStart)}};
    std::cout << jsonText(out, 2) << '\n';
    return 0;
}

} // namespace cli
