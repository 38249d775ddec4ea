// SPDX-License-Identifier: GPL-3.0-or-later
// The viewport's pointer input: mouse, tablet and wheel events become camera drags (orbit, pan,
// zoom) or the press, move and release of the current tool.
#include "ui/view/viewport.h"

#include <QMouseEvent>
#include <QPointingDevice>
#include <QTabletEvent>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

#include "core/document/document.h"

namespace ui {

namespace {
constexpr float kOrbitDegreesPerPixel = 0.4f;
constexpr float kZoomPerWheelStep = 0.85f; // one 15° notch moves 15% closer
constexpr float kZoomPerDragPixel = 0.005f;
} // namespace

Viewport::Drag Viewport::dragFor(Qt::MouseButton button, Qt::KeyboardModifiers modifiers) const {
    const bool altMapping = m_mapping != CameraMapping::Blender;
    const bool middleMapping = m_mapping != CameraMapping::AltBased;
    if (modifiers & Qt::AltModifier) {
        // Alt belongs to the camera even where it moves nothing: an Alt+click never paints.
        if (!altMapping)
            return Drag::None;
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
    if (button == Qt::MiddleButton) {
        if (!middleMapping)
            return Drag::None;
        if (modifiers & Qt::ShiftModifier)
            return Drag::Pan;
        if (modifiers & Qt::ControlModifier)
            return Drag::Zoom;
        return Drag::Orbit;
    }
    if (button == Qt::LeftButton)
        return Drag::Paint;
    return Drag::None;
}

QPointF Viewport::toDevicePixels(QPointF logical) const {
    return logical * devicePixelRatioF();
}

bool Viewport::pointerPress(Qt::MouseButton button, Qt::KeyboardModifiers modifiers,
                            QPointF position, qreal pressure, PointerKind pointer) {
    if (m_drag != Drag::None)
        return true; // a second button during a drag is ignored
    const Drag drag = dragFor(button, modifiers);
    if (drag == Drag::None)
        return false;
    // The mode is fixed at the press, so releasing a modifier mid-drag does not switch it.
    m_drag = drag;
    m_dragButton = button;
    m_lastPos = position;
    m_cursor = toDevicePixels(position);
    m_cursorInside = true;
    m_pressPointer = pointer;
    // Layer-aware rotation: about the visible surface point under the cursor, on any layer.
    m_orbitPivot.reset();
    if (drag == Drag::Orbit && m_orbitAboutSurface && isShowingDepthLayers())
        m_orbitPivot = m_document.surfacePoint({float(m_cursor.x()), float(m_cursor.y())});
    if (drag == Drag::Paint)
        emit paintPressed(toDevicePixels(position), pressure, modifiers);
    return true;
}

bool Viewport::pointerMove(QPointF position, qreal pressure) {
    m_cursor = toDevicePixels(position);
    m_cursorInside = true;
    if (m_drag == Drag::None) {
        if (m_brushOutline && m_brushRadius > 0.0f)
            update(); // the outline follows
        updateHoverHighlight();
        return false;
    }
    const QPointF delta = position - m_lastPos;
    m_lastPos = position;
    switch (m_drag) {
    case Drag::Orbit:
        // Dragging right turns the model right; dragging down shows more of its top.
        if (m_orbitPivot)
            m_document.camera().orbitAbout(*m_orbitPivot, float(-delta.x()) * kOrbitDegreesPerPixel,
                                           float(delta.y()) * kOrbitDegreesPerPixel);
        else
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
        emit paintMoved(toDevicePixels(position), pressure);
        if (m_document.stabilizer().stabilizing())
            update(); // the string follows the pointer even where nothing is painted
        return true;
    case Drag::None:
        break;
    }
    cameraMoved();
    return true;
}

bool Viewport::pointerRelease(Qt::MouseButton button, QPointF position) {
    if (m_drag == Drag::None || button != m_dragButton)
        return false;
    if (m_drag == Drag::Paint)
        emit paintReleased(toDevicePixels(position));
    else
        update(); // the view settled: the full mesh again
    m_drag = Drag::None;
    m_dragButton = Qt::NoButton;
    return true;
}

void Viewport::mousePressEvent(QMouseEvent* event) {
    // A mouse paints at full pressure (the pen comes through tabletEvent).
    if (pointerPress(event->button(), event->modifiers(), event->position(), 1.0,
                     PointerKind::Mouse))
        event->accept();
    else
        QOpenGLWidget::mousePressEvent(event);
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
    if (pointerMove(event->position(), 1.0))
        event->accept();
    else
        QOpenGLWidget::mouseMoveEvent(event);
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
    if (pointerRelease(event->button(), event->position()))
        event->accept();
    else
        QOpenGLWidget::mouseReleaseEvent(event);
}

void Viewport::tabletEvent(QTabletEvent* event) {
    m_tilt = {event->xTilt(), event->yTilt()};
    m_penInProximity = true;
    const PointerKind pointer = event->pointerType() == QPointingDevice::PointerType::Eraser
                                    ? PointerKind::Eraser
                                    : PointerKind::Pen;
    switch (event->type()) {
    case QEvent::TabletPress:
        pointerPress(event->button(), event->modifiers(), event->position(), event->pressure(),
                     pointer);
        break;
    case QEvent::TabletMove:
        pointerMove(event->position(), event->pressure());
        break;
    case QEvent::TabletRelease:
        pointerRelease(event->button(), event->position());
        break;
    default:
        break;
    }
    // Always accepted: a mouse event synthesized from it would repeat the sample (or, for a
    // button no drag uses, do nothing either).
    event->accept();
}

bool Viewport::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::TabletEnterProximity)
        proximityChanged(true);
    else if (event->type() == QEvent::TabletLeaveProximity)
        proximityChanged(false);
    return QOpenGLWidget::eventFilter(watched, event);
}

void Viewport::proximityChanged(bool inProximity) {
    m_penInProximity = inProximity;
    if (!inProximity && m_drag == Drag::None && m_cursorInside) {
        // The pen is lifted away: no outline until a pointer moves over the view again.
        m_cursorInside = false;
        update();
    } else if (inProximity && underMouse() && !m_cursorInside) {
        // Back over the view: the outline shows where the pointer was last seen until it moves.
        m_cursorInside = true;
        update();
    }
}

void Viewport::leaveEvent(QEvent* event) {
    m_cursorInside = false;
    update();
    QOpenGLWidget::leaveEvent(event);
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
    wheelMoved();
    cameraMoved();
    event->accept();
}

} // namespace ui
