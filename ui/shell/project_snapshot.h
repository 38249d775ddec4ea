// SPDX-License-Identifier: GPL-3.0-or-later
// What a save, an export or an autosave writes, copied on the GUI thread: shared by
// project_controller.cpp, project_export.cpp and project_recovery.cpp, included by no other file.
#pragma once

#include <optional>
#include <vector>

#include <QtGlobal>

#include "core/io/paint_layers_export.h"
#include "core/model/mesh.h"
#include "ui/shell/project_controller.h"

namespace ui {

struct ProjectController::Snapshot {
    core::Mesh mesh;
    core::ProjectState state;
    std::vector<core::Image> pages; // texture exports only
    /** Per page (texture exports) or mesh texture: the metallic-roughness composite. */
    std::vector<core::Image> metallicRoughness;
    /** Exports with one image per paint layer: a copy of the paint layers. */
    std::optional<core::PaintLayerExport> paintLayers;
    quint64 serial = 0;
};

} // namespace ui
