// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/viewport.h"

#include <QMetaObject>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/document.h"
#include "render/gl_layer_capturer.h"
#include "render/mesh_renderer.h"

namespace ui {

namespace {
constexpr float kOrbitDegreesPerPixel = 0.4f;
constexpr float kZoomPerWheelStep = 0.85f; // one 15° notch moves 15% closer
constexpr float kZoomPerDragPixel = 0.005f;

qreal pressureOf(const QMouseEvent* event) {
    // Mice report 1 while a button is down; tablets their pen pressure.
    return event->points().isEmpty() ? 1.0 : event->points().first().pressure();
}
} // namespace

Viewport::Viewport(core::Document& document, QWidget* parent)
    : QOpenGLWidget(parent), m_document(document) {
    setFormat(requiredFormat());
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(160, 120);
}

Viewport::~Viewport() {
    releaseGl();
    // ~QOpenGLWidget destroys the context after this object stopped being a Viewport: the
    // aboutToBeDestroyed connection must not reach releaseGl() then.
    if (QOpenGLContext* current = context())
        disconnect(current, nullptr, this, nullptr);
}

QSurfaceFormat Viewport::requiredFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(4, 5);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    return format;
}

void Viewport::meshChanged() {
    m_meshDirty = true; // uploaded where the context is current
    cameraMoved();
}

std::shared_ptr<const core::Mesh> Viewport::mesh() const {
    return m_document.meshSerial() != 0 ? m_document.sharedMesh() : nullptr;
}

const core::Camera& Viewport::camera() const {
    return m_document.camera();
}

core::View Viewport::view() const {
    const qreal ratio = devicePixelRatioF();
    return camera().view(qRound(width() * ratio), qRound(height() * ratio));
}

bool Viewport::isNavigating() const {
    return m_drag == Drag::Orbit || m_drag == Drag::Pan || m_drag == Drag::Zoom;
}

bool Viewport::isOrthographic() const {
    return camera().orthographic;
}

void Viewport::frameAll() {
    if (!mesh())
        return;
    m_document.camera().frame(m_document.mesh().bounds());
    cameraMoved();
}

void Viewport::setOrthographic(bool orthographic) {
    if (camera().orthographic == orthographic)
        return;
    m_document.camera().orthographic = orthographic;
    emit orthographicChanged(orthographic);
    cameraMoved();
}

void Viewport::setDisplay(render::LayerDisplay display) {
    if (m_composite.display == display)
        return;
    m_composite.display = display;
    update();
}

void Viewport::setDisplayLayer(std::uint32_t layer) {
    layer = std::max(layer, 1u);
    if (m_composite.layer == layer)
        return;
    m_composite.layer = layer;
    update();
}

void Viewport::setBoundariesVisible(bool visible) {
    if (m_composite.boundaries == visible)
        return;
    m_composite.boundaries = visible;
    update();
}

void Viewport::setHighlightRegion(std::uint32_t region) {
    if (m_composite.highlightRegion == region)
        return;
    m_composite.highlightRegion = region;
    update();
}

bool Viewport::canCapture() const {
    return m_capturer && mesh() && m_document.mesh().triangleCount() > 0;
}

core::Result<core::LayerStack> Viewport::captureLayers(const core::View& view, bool cullBackFaces,
                                                       core::CaptureStats* stats) {
    if (!canCapture())
        return core::Error{tr("The layer capture is not available.").toStdString()};
    makeCurrent();
    uploadMeshIfDirty();
    auto stack = m_capturer->capture(view, cullBackFaces, stats);
    doneCurrent();
    return stack;
}

void Viewport::showLayers() {
    const core::Layers* layers = m_document.layers();
    if (!m_compositor || !layers)
        return;
    makeCurrent();
    uploadMeshIfDirty();
    const core::Status status =
        m_compositorHasMesh ? m_compositor->setLayers(*layers) : core::Status::success();
    doneCurrent();
    // Without them the mesh renderer goes on drawing the shaded view.
    m_layersShown = m_compositorHasMesh && status.ok();
    if (!status)
        reportLayerError(status);
    update();
}

void Viewport::showSegmentation() {
    const core::Layers* layers = m_document.layers();
    if (!m_compositor || !layers || !m_layersShown)
        return;
    makeCurrent();
    const core::Status status = m_compositor->updateSegmentation(*layers);
    doneCurrent();
    if (!status) {
        m_layersShown = false;
        reportLayerError(status);
    }
    update();
}

bool Viewport::isShowingLayers() const {
    return m_layersShown && m_compositor && m_document.layers();
}

void Viewport::cameraMoved() {
    invalidateView();
    emit cameraChanged();
}

void Viewport::invalidateView() {
    ++m_viewSerial;
    m_layersShown = false;
    emit viewChanged();
    update();
}

void Viewport::initializeGL() {
    // A new context (first show, or after reparenting) has none of our objects yet.
    releaseGl();
    connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &Viewport::releaseGl,
            Qt::UniqueConnection);
    m_glError.clear();

    const QSurfaceFormat format = context()->format();
    if (format.version() < qMakePair(4, 5)) {
        m_glError = tr("LayerPaint needs OpenGL 4.5, but this system provides OpenGL %1.%2.")
                        .arg(format.majorVersion())
                        .arg(format.minorVersion());
    } else {
        auto renderer = std::make_unique<render::MeshRenderer>();
        const core::Status status = renderer->initialize();
        if (status)
            m_renderer = std::move(renderer);
        else
            m_glError =
                tr("The renderer could not start: %1").arg(QString::fromStdString(status.error()));
    }
    QString layerError;
    if (m_renderer) {
        // Without these the mesh still shows; only the layer views are missing.
        auto capturer = std::make_unique<render::GlLayerCapturer>();
        auto compositor = std::make_unique<render::LayerCompositor>();
        const core::Status captureStatus = capturer->initialize();
        const core::Status compositeStatus = compositor->initialize();
        if (captureStatus && compositeStatus) {
            m_capturer = std::move(capturer);
            m_compositor = std::move(compositor);
        } else {
            layerError = tr("The layer views could not start: %1")
                             .arg(QString::fromStdString(captureStatus ? compositeStatus.error()
                                                                       : captureStatus.error()));
            capturer->layerCapture().release();
            compositor->release();
        }
    }
    // Reported from the event loop: a modal dialog inside initializeGL would re-enter it.
    if (!m_glError.isEmpty()) {
        QMetaObject::invokeMethod(
            this, [this] { emit glInitializationFailed(m_glError); }, Qt::QueuedConnection);
    } else if (!layerError.isEmpty()) {
        QMetaObject::invokeMethod(
            this, [this, layerError] { emit layerRenderingFailed(layerError); },
            Qt::QueuedConnection);
    }
    m_meshDirty = true;
    invalidateView(); // the GL objects are new: so are the layers they will hold
}

void Viewport::resizeGL(int, int) {
    invalidateView();
}

void Viewport::uploadMeshIfDirty() {
    if (!m_meshDirty || !m_renderer)
        return;
    const core::Mesh& mesh = m_document.mesh();
    m_renderer->setMesh(mesh);
    if (m_capturer)
        m_capturer->setMesh(mesh);
    m_compositorHasMesh = false;
    if (m_compositor) {
        const core::Status status = m_compositor->setMesh(mesh);
        m_compositorHasMesh = status.ok();
        if (!status)
            reportLayerError(status);
    }
    m_meshDirty = false;
}

void Viewport::reportLayerError(const core::Status& status) {
    // Queued: this may run inside paintGL or with the context current.
    const QString message =
        tr("The layers cannot be shown: %1").arg(QString::fromStdString(status.error()));
    QMetaObject::invokeMethod(
        this, [this, message] { emit layerRenderingFailed(message); }, Qt::QueuedConnection);
}

void Viewport::paintGL() {
    render::DrawOptions options;
    options.background = m_composite.background;
    QOpenGLFunctions* gl = context()->functions();
    gl->glClearColor(options.background.r, options.background.g, options.background.b, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!m_renderer || !mesh())
        return;
    uploadMeshIfDirty();
    // QOpenGLWidget has bound its own framebuffer; both draw into whatever is bound.
    if (isShowingLayers())
        m_compositor->draw(m_composite);
    else
        m_renderer->draw(view(), options);
}

void Viewport::releaseGl() {
    if (!m_renderer && !m_capturer && !m_compositor)
        return;
    makeCurrent();
    m_compositor.reset();
    m_capturer.reset();
    m_renderer.reset();
    doneCurrent();
    m_layersShown = false;
}

Viewport::Drag Viewport::dragFor(Qt::MouseButton button, Qt::KeyboardModifiers modifiers) {
    if (modifiers & Qt::AltModifier) {
        switch (button) {
        case Qt::LeftButton:
            return Drag::Orbit;
        case Qt::RightButton:
            return Drag::Zoom;
        case Qt::MiddleButton:
            return Drag::Pan;
        default:
            return Drag::None;
        }
    }
    if (button == Qt::MiddleButton)
        return (modifiers & Qt::ShiftModifier) ? Drag::Pan : Drag::Orbit;
    if (button == Qt::LeftButton)
        return Drag::Paint;
    return Drag::None;
}

QPointF Viewport::toDevicePixels(QPointF logical) const {
    return logical * devicePixelRatioF();
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    if (m_drag != Drag::None) {
        event->accept(); // a second button during a drag is ignored
        return;
    }
    const Drag drag = dragFor(event->button(), event->modifiers());
    if (drag == Drag::None) {
        QOpenGLWidget::mousePressEvent(event);
        return;
    }
    // The mode is fixed at the press, so releasing a modifier mid-drag does not switch it.
    m_drag = drag;
    m_dragButton = event->button();
    m_lastPos = event->position();
    if (drag == Drag::Paint)
        emit paintPressed(toDevicePixels(event->position()), pressureOf(event));
    event->accept();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    if (m_drag == Drag::None) {
        QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    const QPointF delta = event->position() - m_lastPos;
    m_lastPos = event->position();
    switch (m_drag) {
    case Drag::Orbit:
        // Dragging right turns the model right; dragging down shows more of its top.
        m_document.camera().orbit(float(-delta.x()) * kOrbitDegreesPerPixel,
                                  float(delta.y()) * kOrbitDegreesPerPixel);
        break;
    case Drag::Pan:
        // Logical delta against logical height: the model follows the cursor at any DPI.
        m_document.camera().pan(float(delta.x()), float(delta.y()), height());
        break;
    case Drag::Zoom:
        // Right or up moves closer.
        m_document.camera().zoom(std::exp(float(delta.y() - delta.x()) * kZoomPerDragPixel));
        break;
    case Drag::Paint:
        emit paintMoved(toDevicePixels(event->position()), pressureOf(event));
        event->accept();
        return;
    case Drag::None:
        break;
    }
    cameraMoved();
    event->accept();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (m_drag == Drag::None || event->button() != m_dragButton) {
        QOpenGLWidget::mouseReleaseEvent(event);
        return;
    }
    if (m_drag == Drag::Paint)
        emit paintReleased(toDevicePixels(event->position()));
    m_drag = Drag::None;
    m_dragButton = Qt::NoButton;
    event->accept();
}

void Viewport::wheelEvent(QWheelEvent* event) {
    // Alt turns vertical wheel motion into horizontal on some platforms; take whichever is set.
    const QPoint angle = event->angleDelta();
    const int eighths = angle.y() != 0 ? angle.y() : angle.x();
    if (eighths == 0) {
        event->ignore();
        return;
    }
    m_document.camera().zoom(std::pow(kZoomPerWheelStep, float(eighths) / 120.0f));
    cameraMoved();
    event->accept();
}

} // namespace ui
