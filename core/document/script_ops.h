// SPDX-License-Identifier: GPL-3.0-or-later
// The script runner's table of operations: what a handler works on, and the handlers each
// script_*.cpp file lists under their operation names. ScriptRunner (core/document/script.cpp)
// looks an operation's name up in them.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/base/result.h"
#include "core/model/camera.h"
#include "core/paint/targets/paint_target.h"

namespace core {

class Document;
class ScriptHost;

/** A problem with one operation; the runner adds the operation's number. */
struct ScriptOpError {
    std::string message;
};

/** Throws status's error (its message) as a ScriptOpError. */
inline void throwIfError(const Status& status) {
    if (!status)
        throw ScriptOpError{status.error()};
}

/** One operation being run: the operation, and the runner's document, host and view. */
struct ScriptOp {
    const nlohmann::json& op;
    Document& doc;
    ScriptHost& host;
    View& view;           // the view operations are painted in (the runner's)
    PaintChanges changes; // the caller refreshes its own copy of the target

    /** Builds the document's depth layers through the host if it has none; throws if it cannot. */
    void needDepthLayers();
    /** Paints in view from now on: the document's depth layers go and the host is told. */
    void setView(const View& newView);
};

/** Runs one operation; throws a ScriptOpError saying what is wrong with it. */
using ScriptOpHandler = void (*)(ScriptOp& s);

struct ScriptOpEntry {
    std::string_view name; // the operation's "op"
    ScriptOpHandler run;
};

/**
 * The document's own operations (script_ops.cpp): settings (set-mode, set-brush, set-target,
 * show-layer, set-segmentation), painting (stroke, fill, pick, undo, redo), the camera (orbit,
 * view, orbit-about) and the regions (build-layers, popup, hide, unhide, unhide-all,
 * reset-order).
 */
std::span<const ScriptOpEntry> documentOperations();
/** The straight lines (script_stroke.cpp): line, line-to. */
std::span<const ScriptOpEntry> lineOperations();
/** The paint-layer operations (script_paint_layers.cpp): layer-add, layer-select, ... */
std::span<const ScriptOpEntry> paintLayerOperations();

/** A script's or set-target's "target" object ("kind", "resolution"); an Error if not one. */
Result<PaintTargetOptions> targetOptionsFromJson(const nlohmann::json& target);

} // namespace core
