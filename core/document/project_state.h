// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/layers/layers.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "core/paint/dab.h"
#include "core/paint/paint_target.h"

namespace core {

class Document;

/**
 * The project format version this build writes and the newest it reads. Version 1 is what
 * `layerpaint-cli paint` wrote before projects existed (extras.layerpaint with "script" and
 * "model" only); version 2 holds the whole ProjectState.
 */
inline constexpr int kProjectFormatVersion = 2;

/** The key of the project state in the glTF asset's extras. */
inline constexpr const char* kProjectExtrasKey = "layerpaint";

/**
 * The app state a project keeps beside the painted mesh (docs/architecture.md §3 step 7), stored
 * under the glTF asset's extras.layerpaint. Colours are linear RGBA. Fields the GUI does not have
 * yet are kept as read, so a project saved again keeps them.
 */
struct ProjectState {
    /** The version the state was read from (saving always writes kProjectFormatVersion). */
    int formatVersion = kProjectFormatVersion;
    /** The model the painting started from: a path or "builtin:NAME" (information only). */
    std::string source;
    /** The view; empty: frame the model (files without one). */
    std::optional<Camera> camera;
    Brush brush;
    glm::vec4 foreground{0.8f, 0.1f, 0.1f, 1.0f};
    glm::vec4 background{1.0f};
    /** Recently used colours, most recent first (at most kMaxPaletteColors are kept). */
    std::vector<glm::vec4> palette;
    /** Threshold, connection test and back-face culling (two-sided = !cullBackFaces). */
    LayerOptions layers;
    /** Paint target kind (empty: automatic) and the resolution of a new texture. */
    PaintTargetOptions target;
    bool layerAware = true;
    bool autoPopUp = true;
    bool popUpTransparency = false;
    /** Autosaves only: the project file the recovered work belongs to (empty: never saved). */
    std::string recoveryFor;

    static constexpr std::size_t kMaxPaletteColors = 256;
};

/** extras.layerpaint for state (always the current format version). */
nlohmann::json projectStateToJson(const ProjectState& state);

/**
 * The state in an extras.layerpaint object, upgraded from older format versions. An Error when
 * it is not an object, its version is not a whole number from 1, or it is newer than this build
 * reads. A value of the wrong type or out of range keeps its default and adds a warning (the
 * painting matters more than one setting).
 */
Result<ProjectState> projectStateFromJson(const nlohmann::json& layerpaint,
                                          std::vector<std::string>* warnings = nullptr);

/**
 * Upgrades extras.layerpaint of format version `from` (1 ≤ from < kProjectFormatVersion) to the
 * current version, step by step; a current one is returned as is. Exposed for tests.
 */
nlohmann::json upgradeProjectJson(nlohmann::json layerpaint, int from);

/**
 * base with the document's share of a project's state filled in: camera, brush, layer options,
 * paint target, layer-aware mode, automatic pop-up, and the source (the document's name) if base
 * has none. What the document does not hold (colours, palette, see-through pop-ups) stays as in
 * base.
 */
ProjectState captureProjectState(const Document& doc, ProjectState base = {});

/**
 * Applies state to a document that holds the project's mesh: layer options, brush, mode,
 * automatic pop-up, camera
 * (kept framed when the state has none) and the paint target. If the target cannot be made as
 * asked (e.g. a texture on a mesh without UVs), the automatic one is made and the returned
 * Status says why; the rest is applied either way.
 */
Status applyProjectState(Document& doc, const ProjectState& state);

} // namespace core
