// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/viewport.h"

#include <QMetaObject>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QWheelEvent>

#include <cmath>
#include <utility>

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

Viewport::Viewport(QWidget* parent) : QOpenGLWidget(parent) {
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

void Viewport::setMesh(std::shared_ptr<const core::Mesh> mesh) {
    m_mesh = std::move(mesh);
    m_meshDirty = true; // uploaded in paintGL, where the context is current
    if (m_mesh)
        m_camera.frame(m_mesh->bounds());
    emit cameraChanged();
    update();
}

core::View Viewport::view() const {
    const qreal ratio = devicePixelRatioF();
    return m_camera.view(qRound(width() * ratio), qRound(height() * ratio));
}

void Viewport::frameAll() {
    if (!m_mesh)
        return;
    m_camera.frame(m_mesh->bounds());
    emit cameraChanged();
    update();
}

void Viewport::setOrthographic(bool orthographic) {
    if (m_camera.orthographic == orthographic)
        return;
    m_camera.orthographic = orthographic;
    emit orthographicChanged(orthographic);
    emit cameraChanged();
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
    if (!m_glError.isEmpty()) {
        // Reported from the event loop: a modal dialog inside initializeGL would re-enter it.
        QMetaObject::invokeMethod(
            this, [this] { emit glInitializationFailed(m_glError); }, Qt::QueuedConnection);
    }
    m_meshDirty = true;
}

void Viewport::paintGL() {
    const render::DrawOptions options;
    if (!m_renderer || !m_mesh) {
        QOpenGLFunctions* gl = context()->functions();
        gl->glClearColor(options.background.r, options.background.g, options.background.b, 1.0f);
        gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        return;
    }
    if (m_meshDirty) {
        m_renderer->setMesh(*m_mesh);
        m_meshDirty = false;
    }
    // QOpenGLWidget has bound its own framebuffer; the renderer draws into whatever is bound.
    m_renderer->draw(view(), options);
}

void Viewport::releaseGl() {
    if (!m_renderer)
        return;
    makeCurrent();
    m_renderer.reset();
    doneCurrent();
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
        m_camera.orbit(float(-delta.x()) * kOrbitDegreesPerPixel,
                       float(delta.y()) * kOrbitDegreesPerPixel);
        break;
    case Drag::Pan:
        // Logical delta against logical height: the model follows the cursor at any DPI.
        m_camera.pan(float(delta.x()), float(delta.y()), height());
        break;
    case Drag::Zoom:
        // Right or up moves closer.
        m_camera.zoom(std::exp(float(delta.y() - delta.x()) * kZoomPerDragPixel));
        break;
    case Drag::Paint:
        emit paintMoved(toDevicePixels(event->position()), pressureOf(event));
        event->accept();
        return;
    case Drag::None:
        break;
    }
    emit cameraChanged();
    update();
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
    m_camera.zoom(std::pow(kZoomPerWheelStep, float(eighths) / 120.0f));
    emit cameraChanged();
    update();
    event->accept();
}

} // namespace ui
