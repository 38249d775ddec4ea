// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/document/session_log.h"

#include "core/document/document.h"

namespace core {

using nlohmann::json;

void SessionLog::clear() {
    *this = SessionLog{};
}

void SessionLog::noteState(const Document& doc) {
    if (!m_target) {
        m_target = doc.paintTargetOptions();
        m_target->kind = doc.paintTargetKind();
    }
    if (const DepthLayers* layers = doc.depthLayers()) {
        json view = viewOperation(doc.camera(), layers->view);
        if (m_view != view) {
            m_operations.push_back(view);
            m_view = std::move(view);
        }
    }
    const std::pair mode{doc.layerAware(), doc.autoPopUp()};
    if (m_mode != mode) {
        m_operations.push_back(
            {{"op", "set-mode"}, {"layer_aware", mode.first}, {"auto_pop_up", mode.second}});
        m_mode = mode;
    }
    if (m_shownLayer != doc.shownLayer()) {
        m_operations.push_back({{"op", "show-layer"}, {"layer", doc.shownLayer()}});
        m_shownLayer = doc.shownLayer();
    }
    const DepthLayerOptions& o = doc.depthLayerOptions();
    json segmentation = {{"op", "set-segmentation"},
                         {"threshold", o.threshold},
                         {"test", o.test == ConnectionTest::Plain ? "plain" : "surface"},
                         {"two_sided", !o.cullBackFaces}};
    if (m_segmentation != segmentation) {
        m_operations.push_back(segmentation);
        m_segmentation = std::move(segmentation);
    }
    if (m_brush != doc.brush() || m_curve != doc.pressureCurve().gamma) {
        m_operations.push_back(setBrushOperation(doc.brush(), doc.pressureCurve()));
        m_brush = doc.brush();
        m_curve = doc.pressureCurve().gamma;
    }
}

void SessionLog::add(json operation) {
    m_operations.push_back(std::move(operation));
}

void SessionLog::strokePoint(const StrokePoint& point) {
    m_stroke.push_back({point.position.x, point.position.y, point.pressure});
}

void SessionLog::endStroke() {
    if (m_stroke.empty())
        return;
    m_operations.push_back({{"op", "stroke"}, {"points", std::move(m_stroke)}});
    m_stroke = json::array();
}

Script SessionLog::script() const {
    Script script;
    script.operations = m_operations;
    script.target = m_target;
    if (m_view && m_view->contains("size"))
        script.size = (*m_view)["size"].get<std::string>();
    return script;
}

} // namespace core
