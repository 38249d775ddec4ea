// SPDX-License-Identifier: GPL-3.0-or-later
// `paint`: replays a JSON script of operations through the controller (core::Document) — the
// code path of the GUI's clicks — and saves the result as a project (core/project.h), as the
// GUI's File ▸ Save does. A project as MODEL continues with its paint, settings and view.
#include <iostream>
#include <memory>

#include "app/cli_commands.h"
#include "core/document/document.h"
#include "core/document/script.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/io/project/project_file_tip.h"
#include "render/gl_context.h"
#include "render/gl_depth_capturer.h"

namespace cli {

/** The headless tool's script host: layers captured by capturer (GL or the CPU reference). */
class CapturerHost final : public core::ScriptHost {
public:
    explicit CapturerHost(core::DepthCapturer& capturer) : m_capturer(capturer) {}
    core::Status buildDepthLayers(core::Document& doc, const core::View& view) override {
        return doc.buildDepthLayers(m_capturer, view);
    }
    core::Result<std::shared_ptr<const core::TipImage>> loadTip(const std::string& path) override {
        return core::loadTipImageFile(path);
    }

private:
    core::DepthCapturer& m_capturer;
};

core::Status replayScript(const core::Script& script, const std::string& path, core::Document& doc,
                          core::DepthCapturer& capturer, core::View& view) {
    CapturerHost host(capturer);
    core::ScriptRunner runner(doc, host, view);
    const core::Status status = runner.runAll(script);
    view = runner.view();
    if (!status)
        return core::Error{path + ": " + status.error(), status.errorKind()};
    return {};
}

int runPaint(const PaintArgs& args) {
    auto script = core::readScript(args.script);
    if (!script)
        return fail(script.error());
    // A project continues with its paint and settings; a plain model starts afresh.
    auto project = core::loadProject(args.model);
    if (!project)
        return fail(project.error());
    warn(project->mesh.warnings); // what loading corrected or left out
    core::Document doc;
    doc.setMesh(std::move(project->mesh), args.model);
    core::ProjectState base;
    if (project->state) {
        base = *project->state;
        if (const core::Status s = core::applyProjectState(doc, base); !s)
            std::cerr << "layerpaint-cli: " << args.model << ": " << s.error() << '\n';
    }

    CameraArgs camera = args.camera;
    if (script->size)
        camera.size = *script->size;
    if (script->orbit && camera.cameraFile.empty())
        camera.orbit = *script->orbit;
    if (script->target || !args.target.empty() || args.resolution > 0) {
        core::PaintTargetOptions options =
            script->target ? *script->target : doc.paintTargetOptions();
        applyTargetArgs(args.target, args.resolution, options);
        // A texture on a model without UVs makes the automatic UV layout here.
        if (const core::Status s = doc.setPaintTarget(options); !s)
            return fail((script->target && args.target.empty() ? args.script : args.model) + ": " +
                        s.error());
    }
    // Without --orbit or --camera a project is painted from its saved view.
    const core::Camera* saved = project->state && project->state->camera ? &doc.camera() : nullptr;
    auto view = makeView(camera, doc.mesh(), saved);
    if (!view)
        return fail(view.error());
    if (camera.cameraFile.empty()) {
        auto orbitCamera = makeCamera(camera, doc.mesh(), saved);
        if (orbitCamera)
            doc.camera() = *orbitCamera;
    }

    std::unique_ptr<render::HeadlessContext> context;
    auto made = makeCapturer(args.cpuCapture, context);
    if (!made)
        return fail(made.error());
    std::unique_ptr<core::DepthCapturer> capturer = std::move(made).value();
    capturer->setMesh(doc.mesh());

    if (const core::Status s = replayScript(*script, args.script, doc, *capturer, *view); !s)
        return fail(s.error());
    // The same save as the GUI's: a project with the script's end state.
    const core::ProjectState state = core::captureProjectState(doc, base);
    std::vector<std::string> warnings;
    if (const core::Status s = core::saveProject(args.out, doc, state, {}, &warnings); !s)
        return fail(s.error());
    warn(warnings);
    return 0;
}

} // namespace cli
