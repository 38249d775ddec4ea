// SPDX-License-Identifier: GPL-3.0-or-later
// Symmetric strokes (Brush::symmetry): every dab of a stroke is repeated through the view in
// which its mirrored or turned copy of the surface appears where the dab is (symmetricView()).
// Each copy has its own layers of that view and its own tracker, which follows the stroke's dabs
// on the same depth layer, so a copy reaches the far side of the model and surfaces hidden in
// this view exactly as the stroke reaches what it paints. A dab and its copies are one dab group
// of the paint target: where they overlap (near a mirror plane) nothing is painted twice.
#include <cmath>
#include <optional>

#include "core/document/document.h"

namespace core {

std::vector<const DepthLayers*> Document::symmetryLayers() const {
    std::vector<const DepthLayers*> out;
    for (const auto& copy : m_copies)
        out.push_back(copy->layers.get());
    return out;
}

std::optional<Document::SymmetryBuild> Document::symmetryBuild() const {
    const BrushSymmetry& symmetry = m_brush.symmetry;
    if (!symmetry.active() || !m_depthLayers)
        return std::nullopt;
    if (m_copiesSymmetry == symmetry && m_copiesLayers == m_depthLayersSerial &&
        m_copiesMesh == m_meshSerial)
        return std::nullopt; // made for these (an empty list when every copy failed)
    SymmetryBuild build;
    build.symmetry = symmetry;
    build.depthLayersSerial = m_depthLayersSerial;
    build.meshSerial = m_meshSerial;
    build.mesh = m_mesh;
    build.topology = m_topology;
    build.options = m_depthLayers->options;
    const glm::vec3 centre = symmetry.center == BrushSymmetry::Center::Origin
                                 ? glm::vec3(0.0f)
                                 : m_mesh->bounds().center();
    build.transforms = symmetryTransforms(symmetry, centre);
    for (const glm::mat4& transform : build.transforms)
        build.views.push_back(symmetricView(m_depthLayers->view, transform));
    return build;
}

bool Document::SymmetryBuild::build(const ProgressFn& progress, ConnectivityEngine* engine) {
    layers.clear();
    CpuDepthCapturer capturer;
    capturer.setMesh(*mesh);
    for (std::size_t i = 0; i < views.size(); ++i) {
        if (!reportProgress(progress, double(i) / double(views.size()))) {
            layers.clear();
            return false;
        }
        CaptureStats stats;
        Result<DepthStack> stack =
            capturer.capture(views[i], {options.cullBackFaces, topology->shownBackFaces}, &stats);
        if (!stack) {
            layers.emplace_back(); // that copy paints nothing, the others still do
            continue;
        }
        // Capturing is about half of a copy's work: the status bar moves within one copy too.
        if (!reportProgress(progress, (double(i) + 0.5) / double(views.size()))) {
            layers.clear();
            return false;
        }
        layers.emplace_back(finishDepthLayers(std::move(stack).value(), stats, *mesh, *topology,
                                              views[i], options, engine));
    }
    reportProgress(progress, 1.0);
    return true;
}

bool Document::adoptSymmetry(SymmetryBuild build) {
    if (build.layers.size() != build.transforms.size() || build.meshSerial != m_meshSerial ||
        build.depthLayersSerial != m_depthLayersSerial || !m_depthLayers ||
        build.symmetry != m_brush.symmetry)
        return false;
    // Adopted during a stroke, the copies wait for the next one (startSymmetry()).
    m_copiesPaint = false;
    m_copies.clear();
    m_copiesSymmetry = build.symmetry;
    m_copiesLayers = build.depthLayersSerial;
    m_copiesMesh = build.meshSerial;
    for (std::size_t i = 0; i < build.transforms.size(); ++i) {
        if (!build.layers[i])
            continue;
        auto copy = std::make_unique<SymmetryCopy>();
        copy->transform = build.transforms[i];
        copy->reflects = symmetryReflects(copy->transform);
        copy->layers = std::make_unique<DepthLayers>(std::move(*build.layers[i]));
        copy->tracker.setDepthLayers(*copy->layers);
        m_copies.push_back(std::move(copy));
    }
    return true;
}

void Document::startSymmetry() {
    m_copiesPaint = false;
    if (!m_brush.symmetry.active() || !m_depthLayers)
        return; // the copies stay for these layers and symmetry: turned on again, they are ready
    if (std::optional<SymmetryBuild> build = symmetryBuild()) {
        m_copies.clear();
        if (!m_symmetryOnStroke)
            return; // not built yet: this stroke paints without its copies
        build->build({}, m_engine);
        adoptSymmetry(std::move(*build));
    }
    for (auto& copy : m_copies) {
        copy->tracker.endStroke();
        copy->tracker.setLayerAware(m_tracker.layerAware());
        copy->started = false;
    }
    m_copiesPaint = !m_copies.empty();
}

void Document::paintCopies(const Dab& dab, PaintChanges& changes) {
    constexpr float kPi = 3.14159265358979f;
    for (auto& copy : m_copies) {
        Dab like;
        like.center = dab.center;
        like.radius = dab.radius;
        like.opacity = dab.opacity;
        like.angle = dab.angle;
        like.paintable = std::move(m_copyPaintable); // the previous copy's map, reused
        if (copy->reflects) {
            // The copy's view is flipped left to right: so are the dab and its tip's turn.
            like.center.x = float(copy->layers->stack.width) - dab.center.x;
            like.angle = kPi - dab.angle;
        }
        if (!copy->started) {
            copy->tracker.startCopy(m_brush, dab.layer);
            copy->started = true;
        }
        m_copyDabs.clear();
        copy->tracker.followDab(std::move(like), m_copyDabs);
        for (const Dab& d : m_copyDabs) {
            const PaintChanges& dabChanges = m_paintTarget->paint(*copy->layers, d);
            changes.texels.insert(changes.texels.end(), dabChanges.texels.begin(),
                                  dabChanges.texels.end());
            changes.vertices.insert(changes.vertices.end(), dabChanges.vertices.begin(),
                                    dabChanges.vertices.end());
        }
        if (!m_copyDabs.empty())
            m_copyPaintable = std::move(m_copyDabs.back().paintable);
    }
}

} // namespace core
