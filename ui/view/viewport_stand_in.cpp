// SPDX-License-Identifier: GPL-3.0-or-later
// The viewport's stand-in: a simplified copy of a large model, made in the background once per
// model and drawn by the mesh renderer while the camera moves.
#include "ui/view/viewport.h"

#include "core/document/document.h"
#include "render/mesh_renderer.h"
#include "ui/shell/stand_in_job.h"

namespace ui {

bool Viewport::isCameraMoving() const {
    return isNavigating() || m_wheelRest.isActive();
}

bool Viewport::hasStandIn() const {
    return m_standIn && !m_standIn->empty() && m_standInSerial == m_document.meshSerial();
}

void Viewport::startStandIn() {
    m_standIn.reset();
    m_standInDirty = true;
    const std::shared_ptr<const core::Mesh> current = mesh();
    // A model that draws fast enough gets none.
    if (current && m_standInTriangles > 0 &&
        current->triangleCount() > m_standInTriangles + m_standInTriangles / 2)
        m_standInJob->start(current, m_document.meshSerial(), m_standInTriangles);
    else
        m_standInJob->cancel();
}

void Viewport::standInMade(std::shared_ptr<const core::StandIn> standIn, std::uint64_t meshSerial) {
    if (meshSerial != m_document.meshSerial())
        return; // made for a model no longer open
    m_standIn = std::move(standIn);
    m_standInSerial = meshSerial;
    m_standInDirty = true;
    if (hasStandIn())
        emit standInReady();
    update();
}

void Viewport::uploadStandInIfDirty() {
    if (!m_standInDirty || !m_renderer || !m_renderer->hasMesh())
        return;
    m_standInDirty = false;
    if (!hasStandIn()) {
        m_renderer->clearStandIn();
        return;
    }
    // The renderer holds the paint target's mesh once there is one: the same triangles, its
    // vertices perhaps split further (an automatic UV layout).
    const core::Mesh& drawn = m_shownTarget ? m_shownTarget->mesh() : m_document.mesh();
    const core::StandIn standIn = core::standInFor(*m_standIn, m_document.mesh(), drawn);
    m_renderer->setStandIn(standIn.indices, standIn.triangleMaterial);
}

void Viewport::wheelMoved() {
    m_wheelRest.start();
}

} // namespace ui
