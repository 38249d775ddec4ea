// SPDX-License-Identifier: GPL-3.0-or-later
// The viewport's frame of the mesh renderer: drawn at once, or, for a large model on a software
// renderer, a slice per event into a frame of its own while the stand-in shows; a notice while
// a new model's buffers are filled.
#include "ui/view/viewport.h"

#include <QMetaObject>
#include <QPainter>

#include "render/mesh_renderer.h"

namespace ui {

bool Viewport::slicesFrame(std::size_t triangles) const {
    return m_softwareGl && m_frameSliceTriangles > 0 && triangles > 2 * m_frameSliceTriangles;
}

void Viewport::drawMeshFrame(const core::View& view, render::DrawOptions options) {
    // Without a stand-in the renderer draws the mesh anyway: the same frame as at rest.
    options.standIn = options.standIn && m_renderer->hasStandIn();
    const auto drawAtOnce = [&] {
        m_renderer->draw(view, options);
        m_lastFrameTriangles = m_renderer->lastDrawnTriangles();
    };
    m_frameWhole = true;
    if (!slicesFrame(m_renderer->frameTriangles(options)))
        return drawAtOnce();
    const core::Result<bool> whole =
        m_slicedFrame->advance(*m_renderer, view, options, m_frameSliceTriangles);
    if (!whole)
        return drawAtOnce(); // no framebuffer for the slices
    m_frameWhole = *whole;
    if (!m_frameWhole) // the next slice once the events given meanwhile are handled
        QMetaObject::invokeMethod(
            this, [this] { update(); }, Qt::QueuedConnection);
    if (m_frameWhole || !m_renderer->hasStandIn()) {
        m_slicedFrame->copyTo(defaultFramebufferObject());
        m_lastFrameTriangles = m_slicedFrame->drawnTriangles();
        return;
    }
    options.standIn = true;
    drawAtOnce();
}

void Viewport::drawPreparingNotice() {
    m_lastFrameTriangles = 0;
    const QString notice = tr("Preparing the model for display…");
    QPainter painter(this);
    // Dark under light, so it reads on any background.
    painter.setPen(QColor(0, 0, 0, 160));
    painter.drawText(rect().translated(1, 1), Qt::AlignCenter, notice);
    painter.setPen(QColor(255, 255, 255, 230));
    painter.drawText(rect(), Qt::AlignCenter, notice);
}

} // namespace ui
