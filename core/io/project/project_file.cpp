// SPDX-License-Identifier: GPL-3.0-or-later
// Project files: a binary glTF with the app state under asset.extras.layerpaint (the state itself
// is read and written by core/document/project_state.h).
#include "core/io/project/project_file.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <new>

#include "core/base/text.h"
#include "core/document/document.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/importer/mesh_io_in_process.h"
#include "core/io/project/project_file_paint_layers.h"
#include "core/io/project/project_file_tip.h"

namespace core {

namespace {

using Json = nlohmann::json;

bool isGltfPath(const std::string& path) {
    const std::string ext = lowerExtension(path);
    return ext == ".glb" || ext == ".gltf";
}

using MeshLoader = Result<Mesh> (*)(const std::string&, const ProgressFn&, const LoadLimits&);

Result<Project> load(const std::string& path, const ProgressFn& progress, const LoadLimits& limits,
                     MeshLoader loadMeshWith, GlbImageLoader loadImagesWith) {
    Project project;
    std::vector<std::string> warnings;
    Result<Json> extras = Json::object();
    if (isGltfPath(path) && path.rfind("builtin:", 0) != 0) {
        // The JSON alone first: a newer project is refused before its textures are decoded.
        extras = readGlbExtras(path);
        if (!extras) {
            // Not a glTF file at all: the model loader says what is wrong in plainer words. A
            // glTF whose JSON is more than can be read is refused without loading its model.
            if (extras.errorKind() == ErrorKind::Unsupported)
                return extras.takeError();
            if (Result<Mesh> mesh = loadMeshWith(path, progress, limits); !mesh)
                return mesh.takeError();
            return extras.takeError();
        }
        const auto it = extras->find(kProjectExtrasKey);
        if (it != extras->end()) {
            if (!it->is_object())
                return Error{path + ": extras.layerpaint is not a JSON object"};
            Result<ProjectState> state = projectStateFromJson(*it, &warnings);
            if (!state)
                return Error{path + ": " + state.error(), state.errorKind()};
            project.state = std::move(state).value();
        }
    }
    LoadLimits strict = limits;
    strict.requireTextures = project.state.has_value(); // they hold the painting
    Result<Mesh> mesh = loadMeshWith(path, progress, strict);
    if (!mesh)
        return mesh.takeError();
    project.mesh = std::move(mesh).value();
    if (project.state && project.state->paintLayers) {
        // The textures are the composite; the base and the layers' planes are images beside it.
        auto layers = std::make_shared<SavedPaintLayers>(*project.state->paintLayers);
        const Json& json = (*extras)[kProjectExtrasKey]["paint_layers"];
        if (Status read =
                readPaintLayerImages(path, json, limits, project.mesh, *layers, loadImagesWith);
            !read)
            return Error{path + ": " + withoutFileName(path, read.error()), read.errorKind()};
        project.state->paintLayers = std::move(layers);
    }
    if (project.state && project.state->brush.tip == kUserTip) {
        // The loaded brush tip; without it the brush falls back to the round tip.
        if (Status tip = readBrushTipImage(path, (*extras)[kProjectExtrasKey], limits,
                                           loadImagesWith, project.state->brush);
            !tip) {
            warnings.push_back(path + ": " + withoutFileName(path, tip.error()) +
                               "; the brush uses the round tip");
            project.state->brush.tip = std::string(kRoundTip);
        }
    }
    project.mesh.warnings.insert(project.mesh.warnings.end(), warnings.begin(), warnings.end());
    return project;
}

Result<Project> loadProjectWith(const std::string& path, const ProgressFn& progress,
                                const LoadLimits& limits, MeshLoader loadMeshWith,
                                GlbImageLoader loadImagesWith) {
    try {
        return load(path, progress, limits, loadMeshWith, loadImagesWith);
    } catch (const std::bad_alloc&) {
        return Error{path + ": too large for this machine's memory (an allocation failed while "
                            "loading it)"};
    } catch (const std::exception& e) {
        return Error{path + ": cannot be loaded (" + std::string(e.what()) + ")"};
    }
}

} // namespace

Result<Project> loadProject(const std::string& path, const ProgressFn& progress,
                            const LoadLimits& limits) {
    return loadProjectWith(path, progress, limits, &loadMesh, &loadGlbImages);
}

Result<Project> loadProjectInProcess(const std::string& path, const ProgressFn& progress,
                                     const LoadLimits& limits) {
    const MeshLoader finished = [](const std::string& file, const ProgressFn& report,
                                   const LoadLimits& within) {
        return loadMeshInProcess(file, report, within);
    };
    return loadProjectWith(path, progress, limits, finished, &loadGlbImagesInProcess);
}

Status saveProject(const std::string& path, const Mesh& paintedMesh, const ProjectState& state,
                   const ProgressFn& progress, bool keepBackup,
                   std::vector<std::string>* warnings) {
    GlbAdditions additions;
    additions.warnings = warnings;
    try {
        additions.extras = {{kProjectExtrasKey, projectStateToJson(state)}};
        if (const SavedPaintLayers* layers = state.paintLayers.get()) {
            // The pages are the painted mesh's base colour textures, its first ones.
            std::size_t pageCount = 0;
            for (const Material& m : paintedMesh.materials)
                pageCount = std::max(pageCount, std::size_t(m.baseColorTexture + 1));
            std::vector<PageSize> pages;
            for (std::size_t p = 0; p < pageCount && p < paintedMesh.textures.size(); ++p)
                pages.push_back({paintedMesh.textures[p].width, paintedMesh.textures[p].height});
            Json& json = additions.extras[kProjectExtrasKey]["paint_layers"];
            if (Status images = addPaintLayerImages(*layers, pages, json, additions.attachments);
                !images)
                return Error{path + ": " + images.error(), images.errorKind()};
            additions.attachmentsAt =
                Json::json_pointer("/" + std::string(kProjectExtrasKey) + "/paint_layers/images");
        }
        if (Status tip =
                addBrushTipImage(state.brush, additions.extras[kProjectExtrasKey], additions);
            !tip)
            return Error{path + ": " + tip.error(), tip.errorKind()};
    } catch (const std::bad_alloc&) {
        return Error{path + ": not enough memory to save the file"};
    } catch (const std::exception& e) {
        return Error{path + ": cannot be saved (" + std::string(e.what()) + ")"};
    }
    return saveGlbWith(path, paintedMesh, additions, progress, keepBackup);
}

Status saveProject(const std::string& path, const Document& doc, const ProjectState& state,
                   const ProgressFn& progress, std::vector<std::string>* warnings) {
    Mesh mesh;
    try {
        mesh = doc.paintedMesh();
    } catch (const std::bad_alloc&) {
        return Error{path + ": not enough memory to save the file"};
    }
    return saveProject(path, mesh, state, progress, true, warnings);
}

} // namespace core
