// SPDX-License-Identifier: GPL-3.0-or-later
// Symmetric strokes (Brush::symmetry): every dab of a stroke is repeated through the view in
// which its mirrored or turned copy of the surface appears where the dab is (symmetricView()).
// Each copy has its own layers of that view and its own tracker, which follows the stroke's dabs
// on the same depth layer, so a copy reaches the far side of the model and surfaces hidden in
// this view exactly as the stroke reaches what it paints. A dab and its copies are one dab group
// of the paint target: where they overlap (near a mirror plane) nothing is painted twice.
#include <cmath>

#include "core/document/document.h"

namespace core {

std::vector<const Layers*> Document::symmetryLayers() const {
    std::vector<const Layers*> out;
    for (const auto& copy : m_copies)
        out.push_back(copy->layers.get());
    return out;
}

void Document::startSymmetry() {
    const BrushSymmetry& symmetry = m_brush.symmetry;
    if (!symmetry.active() || !m_layers) {
        m_copies.clear();
        return;
    }
    if (m_copies.empty() || m_copiesSymmetry != symmetry || m_copiesLayers != m_layersSerial ||
        m_copiesMesh != m_meshSerial) {
        m_copies.clear();
        m_copiesSymmetry = symmetry;
        m_copiesLayers = m_layersSerial;
        m_copiesMesh = m_meshSerial;
        const glm::vec3 centre = symmetry.center == BrushSymmetry::Center::Origin
                                     ? glm::vec3(0.0f)
                                     : m_mesh->bounds().center();
        CpuLayerCapturer capturer;
        capturer.setMesh(*m_mesh);
        for (const glm::mat4& transform : symmetryTransforms(symmetry, centre)) {
            Result<Layers> built = core::buildLayers(capturer, *m_mesh, *m_topology,
                                                     symmetricView(m_layers->view, transform),
                                                     m_layers->options, m_engine);
            if (!built)
                continue; // that copy paints nothing, the others still do
            auto copy = std::make_unique<SymmetryCopy>();
            copy->transform = transform;
            copy->reflects = symmetryReflects(transform);
            copy->layers = std::make_unique<Layers>(std::move(built).value());
            copy->tracker.setLayers(*copy->layers);
            m_copies.push_back(std::move(copy));
        }
    }
    for (auto& copy : m_copies) {
        copy->tracker.endStroke();
        copy->tracker.setLayerAware(m_tracker.layerAware());
        copy->started = false;
    }
}

void Document::paintCopies(const Dab& dab, PaintChanges& changes) {
    constexpr float kPi = 3.14159265358979f;
    for (auto& copy : m_copies) {
        Dab like;
        like.center = dab.center;
        like.radius = dab.radius;
        like.opacity = dab.opacity;
        like.angle = dab.angle;
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
        copy->tracker.followDab(like, m_copyDabs);
        for (const Dab& d : m_copyDabs) {
            const PaintChanges& dabChanges = m_paintTarget->paint(*copy->layers, d);
            changes.texels.insert(changes.texels.end(), dabChanges.texels.begin(),
                                  dabChanges.texels.end());
            changes.vertices.insert(changes.vertices.end(), dabChanges.vertices.begin(),
                                    dabChanges.vertices.end());
        }
    }
}

} // namespace core
