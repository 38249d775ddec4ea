// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/depth/depth_layers.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "core/paint/brush/dab.h"
#include "core/paint/paint_layers/paint_layers.h"
#include "core/paint/targets/paint_target.h"

namespace core {

class Document;

/**
 * The project format version this build writes and the newest it reads. Version 1 is what
 * `layerpaint-cli paint` wrote before projects existed (extras.layerpaint with "script" and
 * "model" only); version 2 holds the whole ProjectState; version 3 adds the paint layers
 * (extras.layerpaint.paint_layers); version 4 stores a fill layer's colour linear, as every
 * other colour of the file (version 3 kept it sRGB-encoded). Versions before 3 open with no paint
 * layers.
 */
inline constexpr int kProjectFormatVersion = 4;

/** The key of the project state in the glTF asset's extras. */
inline constexpr const char* kProjectExtrasKey = "layerpaint";

/** A paint layer as a project keeps it: its id, settings and planes (null: never painted). */
struct SavedPaintLayer {
    std::uint64_t id = 0;
    PaintLayerSettings settings;
    std::array<std::shared_ptr<const TiledPlane>, kPaintChannels> channels;
    std::shared_ptr<const TiledPlane> mask;
};

/**
 * The most paint layers a document makes and a project may hold: opening composites every layer
 * over every page, so the time grows with layers × texels (1000 fill layers over a 2048² page
 * take seconds).
 */
inline constexpr std::size_t kMaxPaintLayers = 1000;

/**
 * The paint-layer stack of a texture target as a project keeps it. The structure (ids, settings,
 * order, selection) is JSON under extras.layerpaint.paint_layers; the planes and the base are
 * images in the file (core/io/project_file), so projectStateFromJson() gives the layers without
 * planes and loadProject() fills them in.
 */
struct SavedPaintLayers {
    std::vector<SavedPaintLayer> layers; // bottom first
    PaintSelection selection;
    /**
     * Per page, the base's colour (sRGB RGBA8) where it differs from the composite, else empty:
     * the file's base colour textures are the composite, so the base is kept beside them.
     */
    std::vector<Image> base;
    /**
     * Per page, the base's roughness and metallic (linear RGBA8, G roughness, B metallic) where
     * they differ from the composite, else empty: a page's painted composite is saved as its
     * materials' metallicRoughnessTexture, where the base would otherwise start again.
     */
    std::vector<Image> baseMetallicRoughness;
    /** Per page, the composite metallic-roughness image (empty without material channels). */
    std::vector<Image> metallicRoughness;
};

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
    DepthLayerOptions layers;
    /** Paint target kind (empty: automatic) and the resolution of a new texture. */
    PaintTargetOptions target;
    bool layerAware = true;
    bool autoPopUp = true;
    bool popUpTransparency = false;
    /** Autosaves only: the project file the recovered work belongs to (empty: never saved). */
    std::string recoveryFor;
    /**
     * The texture target's paint layers (null: none, or not a texture target). Shared, so that
     * copies of a state do not copy the planes.
     */
    std::shared_ptr<const SavedPaintLayers> paintLayers;

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

/** extras.layerpaint.paint_layers for layers: settings, ids, order and selection, no planes. */
nlohmann::json paintLayersToJson(const SavedPaintLayers& layers);
/**
 * The paint layers in extras.layerpaint.paint_layers, without their planes. A value of the wrong
 * type keeps its default with a warning; a layer without a valid unique id is an Error (its
 * planes could not be matched).
 */
Result<SavedPaintLayers> paintLayersFromJson(const nlohmann::json& paintLayers,
                                             std::vector<std::string>* warnings = nullptr);
/** The paint layers of doc's texture target (copies of the planes), or null for none. */
std::shared_ptr<const SavedPaintLayers> capturePaintLayers(const Document& doc);
/** The paint layers of target (copies of the planes), or null for none. */
std::shared_ptr<const SavedPaintLayers> capturePaintLayers(const PaintLayerTarget& target);
/**
 * Replaces the paint layers of doc's texture target with layers (not an undo step: a project
 * being opened). An Error, and nothing changed, when there is no texture target or a plane does
 * not fit its pages.
 */
Status restorePaintLayers(Document& doc, const SavedPaintLayers& layers);
/** restorePaintLayers() into target, which may be one no document holds yet. */
Status restorePaintLayers(PaintLayerTarget& target, const SavedPaintLayers& layers);

/**
 * base with the document's share of a project's state filled in: camera, brush, layer options,
 * paint target, paint layers, layer-aware mode, automatic pop-up, and the source (the document's
 * name) if base has none. What the document does not hold (colours, palette, see-through pop-ups)
 * stays as in base.
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
