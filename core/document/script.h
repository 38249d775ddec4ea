// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/base/progress.h"
#include "core/base/result.h"
#include "core/model/camera.h"
#include "core/paint/brush/dab.h"
#include "core/paint/targets/paint_target.h"

namespace core {

class Document;

/**
 * A script: operations replayed through the Document, the code path of the GUI's clicks (the
 * format is in docs/architecture.md and the README). The settings apply before the first
 * operation; the headless tool honours all three, the GUI only the paint target (it paints in
 * its own view).
 */
struct Script {
    nlohmann::json operations = nlohmann::json::array();
    std::optional<std::string> size;  // "WxH" of the view
    std::optional<std::string> orbit; // "yaw,pitch,distance"
    std::optional<PaintTargetOptions> target;
};

/** The script in value (an array of operations or an object with "operations"); an Error if not. */
Result<Script> parseScript(const nlohmann::json& value);
/** Reads and parses a script file; an Error naming the file and the problem. */
Result<Script> readScript(const std::string& path);
/** The script as JSON (the object form), e.g. to save a recorded session. */
nlohmann::json scriptToJson(const Script& script);

/** "WxH", each 1 to 16384; an Error saying what is expected. */
Result<std::pair<int, int>> parseViewSize(const std::string& size);
/**
 * The camera of an orbit "yaw,pitch,distance" (degrees, unit-cube units > 0) about the centre of
 * bounds (Camera::fromOrbit); an Error saying what is expected.
 */
Result<Camera> parseOrbitCamera(const std::string& orbit, const Bounds& bounds);

/** The set-brush operation that sets every field of brush (and the pressure curve). */
nlohmann::json setBrushOperation(const Brush& brush, const PressureCurve& curve);
/**
 * The view operation of view, seen through camera: the camera's pose and the view's size, and
 * the exact matrices when the camera's own view is not this one (e.g. after orbit-about).
 */
nlohmann::json viewOperation(const Camera& camera, const View& view);

/**
 * What a script needs from whoever runs it: layers for a view. The headless tool captures with
 * its capturer; the GUI builds them in its viewport.
 */
class ScriptHost {
public:
    virtual ~ScriptHost() = default;
    /** Builds doc's layers for view, synchronously; an Error if they cannot be built. */
    virtual Status buildDepthLayers(Document& doc, const View& view) = 0;
    /** The script moved the camera (orbit, orbit-about, view); the view it paints in now. */
    virtual void viewChanged(const View& view) { (void)view; }
    /** Decodes an image file into a brush tip (set-brush "tip"); an Error naming the file. */
    virtual Result<std::shared_ptr<const TipImage>> loadTip(const std::string& path) {
        return Error{path + ": image tips cannot be loaded here"};
    }
};

/**
 * Replays operations on a document. Depth layers are built (through the host) whenever an operation
 * needs them and the document has none. Errors name the operation's number (1-based) and the
 * problem; the operations before it stay done. Each operation's handler is looked up by its name
 * in the table of core/document/script_ops.h.
 */
class ScriptRunner {
public:
    ScriptRunner(Document& doc, ScriptHost& host, const View& view);

    /** Runs one operation. */
    Status run(const nlohmann::json& operation);
    /** Runs every operation of script (its settings are the caller's); cancellable. */
    Status runAll(const Script& script, const ProgressFn& progress = {});

    /** The view operations are painted in (changed by orbit, orbit-about and view). */
    const View& view() const { return m_view; }
    /** Operations run so far. */
    std::size_t count() const { return m_count; }

private:
    Document& m_doc;
    ScriptHost& m_host;
    View m_view;
    std::size_t m_count = 0;
};

} // namespace core
