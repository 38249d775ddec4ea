// SPDX-License-Identifier: GPL-3.0-or-later
// core/io/project/: LayerPaint projects: a binary glTF with the painted model, every
// paint layer's images and the state, read and written.
#pragma once

#include <optional>
#include <string>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/document/project_state.h"
#include "core/io/mesh_io.h"
#include "core/model/mesh.h"

namespace core {

class Document;

/** A loaded project: the painted mesh and, for LayerPaint projects, their state. */
struct Project {
    Mesh mesh;
    /** Empty for a plain model (no extras.layerpaint). */
    std::optional<ProjectState> state;
};

/**
 * Opens a project or a plain model. A .glb/.gltf file's extras.layerpaint is read first, so a
 * newer project is refused before any geometry is decoded; the mesh then comes from loadMesh(),
 * so the painted textures become the mesh's base colour textures (the paint target starts from
 * them byte for byte) and painted vertex colours its COLOR_0. In a project a texture that cannot
 * be read fails the load (it holds the painting). Other files and "builtin:NAME" load as plain
 * models. Settings that could not be read are reported in mesh.warnings.
 *
 * Returns an Error naming path and the problem (unreadable, corrupted, newer format, ...); never
 * throws.
 */
Result<Project> loadProject(const std::string& path, const ProgressFn& progress = {},
                            const LoadLimits& limits = {});

/**
 * Saves paintedMesh (Document::paintedMesh()) and state as a project: a binary glTF with the
 * state in asset.extras.layerpaint, written atomically with the previous file kept as
 * path + ".bak" unless keepBackup is false (saveGlb). A model read from a glTF file is saved
 * as that file's scene with what was painted changed (encodeGlb()); what cannot be kept is named
 * in warnings, if given. On failure the old file is intact and the Error names path and why.
 */
Status saveProject(const std::string& path, const Mesh& paintedMesh, const ProjectState& state,
                   const ProgressFn& progress = {}, bool keepBackup = true,
                   std::vector<std::string>* warnings = nullptr);
/** saveProject() of doc's painted mesh. */
Status saveProject(const std::string& path, const Document& doc, const ProjectState& state,
                   const ProgressFn& progress = {}, std::vector<std::string>* warnings = nullptr);

} // namespace core
