// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "core/depth/depth_layers.h"
#include "core/document/script.h"
#include "core/model/camera.h"
#include "core/paint/brush/dab.h"
#include "core/paint/tracking/stroke_tracker.h"

namespace core {

class Document;

/**
 * What a user did to a document since its model was set, as script operations (Edit ▸ Copy
 * Session as Script): replayed on the same model, the script gives the same result. Before each
 * operation the view, brush, mode and segmentation settings it depends on are written when they
 * differ from what was written last; strokes keep the pen's pressure before the curve.
 */
class SessionLog {
public:
    /** Starts a new session (the settings are written again before the next operation). */
    void clear();
    /** Writes what of doc's state differs from the state written last (call before an op). */
    void noteState(const Document& doc);
    /** Appends an operation. */
    void add(nlohmann::json operation);
    /** The operation appended last (add() must have been called). */
    nlohmann::json& last() { return m_operations.back(); }
    /** Stroke points, collected until endStroke() writes the stroke. */
    void strokePoint(const StrokePoint& point);
    void endStroke();

    /** The session as a script (its paint target setting is the one the session started with). */
    Script script() const;
    std::size_t size() const { return m_operations.size(); }

private:
    nlohmann::json m_operations = nlohmann::json::array();
    nlohmann::json m_stroke = nlohmann::json::array();
    std::optional<PaintTargetOptions> m_target;
    std::optional<nlohmann::json> m_view;
    std::optional<Brush> m_brush;
    std::optional<float> m_curve;
    std::optional<std::pair<bool, bool>> m_mode;
    std::optional<std::uint32_t> m_shownLayer;
    std::optional<nlohmann::json> m_segmentation;
};

} // namespace core
