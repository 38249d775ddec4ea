// SPDX-License-Identifier: GPL-3.0-or-later
// The viewport's uploads: the mesh to the renderers and the capture when it changes (a new
// model's buffers filled and its share of the compositor prepared in the background), and what
// strokes changed, at the next frame.
#include "ui/view/viewport.h"

#include <QMetaObject>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "core/document/document.h"
#include "render/gl_depth_capturer.h"
#include "render/mesh_renderer.h"
#include "ui/shell/compositor_mesh_job.h"
#include "ui/shell/mesh_fill_job.h"

namespace ui {

void Viewport::uploadMeshIfDirty() {
    // A target made or replaced without paintTargetChanged() is caught here too.
    const core::PaintTarget* target =
        m_document.hasPaintTarget() ? m_document.paintTarget() : nullptr;
    if (target != m_shownTarget)
        m_paintedMeshDirty = true;
    if ((!m_meshDirty && !m_paintedMeshDirty) || !m_renderer)
        return;
    finishMeshFill(); // an earlier model's, still filling buffers replaced now
    // Once painted, the renderers draw the paint target's pages or colours; the capture needs
    // only the geometry, which painting never changes.
    std::vector<std::function<void()>> fills;
    if (m_meshDirty && m_capturer)
        fills.push_back(m_capturer->depthCapture().beginMesh(m_document.mesh()));
    // The target's look over its mesh's geometry, which is not copied.
    const std::shared_ptr<const core::Mesh> geometry =
        target ? target->sharedMesh() : m_document.sharedMesh();
    const std::shared_ptr<const core::Mesh> lookOf =
        target ? std::make_shared<const core::Mesh>(target->paintedLook()) : geometry;
    const core::Mesh &mesh = *geometry, &look = *lookOf;
    m_shownTarget = target;
    // Both renderers light with the metallic-roughness pages, so the view keeps its colours
    // while the camera moves.
    m_textures->create(look.textures);
    for (std::size_t page = 0; target && page < target->pageCount(); ++page)
        m_textures->setMetallicRoughness(std::uint32_t(page), target->metallicRoughnessPage(page));
    fills.push_back(
        m_renderer->beginMesh(mesh, look, m_textures, m_document.topology().shownBackFaces));
    // Filled by the job: a large new model's in the background (it takes seconds), the others'
    // at once.
    const bool inBackground = m_meshDirty && m_backgroundFillTriangles > 0 &&
                              mesh.triangleCount() >= m_backgroundFillTriangles;
    m_meshFill->start(std::move(fills), {geometry, m_document.sharedMesh()});
    if (!inBackground)
        finishMeshFill();
    m_pendingPaint.clear();
    m_compositorHasMesh = false;
    if (m_compositor)
        sendMeshToCompositor(geometry, lookOf, m_meshDirty);
    m_depthLayersShown = m_depthLayersShown && m_compositorHasMesh;
    m_meshDirty = false;
    m_paintedMeshDirty = false;
    m_standInDirty = true;             // setMesh dropped it
    m_maskViewDirty = m_maskView != 0; // the textures are the composite's again
    ++m_meshUploads;
}

bool Viewport::isPreparingMesh() const {
    return m_meshFill->isPending();
}

bool Viewport::finishMeshFill() {
    if (!m_meshFill->isPending())
        return false;
    m_meshFill->wait();
    if (m_capturer)
        m_capturer->depthCapture().finishMesh();
    m_renderer->finishMesh();
    if (!m_renderer->hasMesh()) {
        // Queued: this may run inside paintGL or with the context current.
        const QString message =
            tr("The model cannot be drawn: there is not enough memory for its GL buffers.");
        QMetaObject::invokeMethod(
            this, [this, message] { emit depthLayerRenderingFailed(message); },
            Qt::QueuedConnection);
    }
    return true;
}

void Viewport::meshFilled() {
    makeCurrent();
    finishMeshFill();
    doneCurrent();
    invalidateView(); // drawn at last: the depth layers can be built
}

void Viewport::sendMeshToCompositor(std::shared_ptr<const core::Mesh> geometry,
                                    std::shared_ptr<const core::Mesh> look, bool newGeometry) {
    // A new model's share is prepared in the background: the compositor draws only once the
    // model's depth layers are built, and showLayers() waits for it should it not be there yet.
    if (newGeometry) {
        m_compositorJob->start(std::move(geometry), std::move(look),
                               m_compositor->storageBlockBytes());
        return;
    }
    m_compositorJob->cancel();
    const core::Status status = m_compositor->setMesh(*geometry, *look, m_textures);
    m_compositorHasMesh = status.ok();
    if (!status)
        reportDepthLayerError(status);
}

void Viewport::installCompositorMesh() {
    const std::shared_ptr<const PreparedCompositorMesh> result = m_compositorJob->take();
    if (!result || !m_compositor)
        return;
    const core::Status status =
        result->prepared
            ? m_compositor->setMesh(*result->prepared, *result->geometry, *result->look, m_textures)
            : core::Status(core::Error{result->error});
    m_compositorHasMesh = status.ok();
    if (!status)
        reportDepthLayerError(status);
}

void Viewport::compositorMeshPrepared() {
    makeCurrent();
    installCompositorMesh();
    doneCurrent();
}

void Viewport::flushPaint(bool compositor) {
    if (!m_document.hasPaintTarget() || m_document.paintTarget() != m_shownTarget) {
        m_pendingPaint.clear();
        return;
    }
    const core::PaintTarget* target = m_document.paintTarget();
    flushPages(*target);
    flushVertexColors(*target, compositor);
}

void Viewport::flushPages(const core::PaintTarget& target) {
    const core::TiledPlane* mask = m_maskView != 0 ? shownMask() : nullptr;
    if (m_maskView != 0 && !mask)
        uploadMaskView(); // the mask went: the composite, whole
    for (std::size_t page = 0; page < m_pendingPaint.pages.size(); ++page) {
        const core::TexelRect& r = m_pendingPaint.pages[page];
        if (r.width <= 0 || page >= target.pageCount())
            continue;
        if (mask)
            uploadMaskRect(*mask, {std::uint32_t(page), r.x, r.y, r.width, r.height});
        else
            m_textures->updateTexels(std::uint32_t(page), r.x, r.y, r.width, r.height,
                                     target.page(page));
        m_textures->updateMetallicRoughness(std::uint32_t(page), r.x, r.y, r.width, r.height,
                                            target.metallicRoughnessPage(page));
    }
    m_pendingPaint.pages.clear();
}

void Viewport::flushVertexColors(const core::PaintTarget& target, bool compositor) {
    core::VertexRange& range =
        compositor ? m_pendingPaint.compositorVertices : m_pendingPaint.rendererVertices;
    const std::span<const glm::vec4> all = target.vertexColors();
    if (range.begin < range.end && range.end <= all.size()) {
        const std::span<const glm::vec4> changed =
            all.subspan(range.begin, range.end - range.begin);
        if (compositor)
            m_compositor->updateVertexColors(range.begin, changed);
        else
            m_renderer->updateVertexColors(range.begin, changed);
    }
    range = {};
}

} // namespace ui
