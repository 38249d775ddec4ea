// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include <QOpenGLWidget>
#include <QPointF>
#include <QSurfaceFormat>

#include "core/camera.h"
#include "core/mesh.h"

namespace render {
class MeshRenderer;
}

namespace ui {

/**
 * The 3D view: draws the mesh with render::MeshRenderer and turns mouse input into core::Camera
 * moves. Middle drag orbits, Shift+middle pans, the wheel zooms; Alt+left/right/middle orbit,
 * zoom and pan for tablets. The plain left button belongs to painting (the paint* signals).
 */
class Viewport : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit Viewport(QWidget* parent = nullptr);
    ~Viewport() override;

    /** OpenGL 4.5 core with a depth buffer: what render needs. Set it as the default format. */
    static QSurfaceFormat requiredFormat();

    /** Shows mesh (may be null) and frames it. */
    void setMesh(std::shared_ptr<const core::Mesh> mesh);
    const std::shared_ptr<const core::Mesh>& mesh() const { return m_mesh; }

    const core::Camera& camera() const { return m_camera; }
    /** The current view in device pixels (what is drawn and what paint coordinates refer to). */
    core::View view() const;

    bool isOrthographic() const { return m_camera.orthographic; }

    /** The GL error met in initializeGL, or empty. */
    QString glError() const { return m_glError; }

public slots:
    void frameAll();
    void setOrthographic(bool orthographic);

signals:
    void orthographicChanged(bool orthographic);
    void cameraChanged();
    /** Emitted once, from the event loop, if the renderer cannot start (message for the user). */
    void glInitializationFailed(const QString& message);

    // The painting hook: positions in device pixels, origin top-left (DESIGN.md §4).
    void paintPressed(QPointF pixel, qreal pressure);
    void paintMoved(QPointF pixel, qreal pressure);
    void paintReleased(QPointF pixel);

protected:
    void initializeGL() override;
    void paintGL() override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

private:
    enum class Drag { None, Orbit, Pan, Zoom, Paint };
    static Drag dragFor(Qt::MouseButton button, Qt::KeyboardModifiers modifiers);

    QPointF toDevicePixels(QPointF logical) const;
    void releaseGl();

    std::unique_ptr<render::MeshRenderer> m_renderer; // lives only while the context does
    std::shared_ptr<const core::Mesh> m_mesh;
    bool m_meshDirty = false;
    core::Camera m_camera;
    QString m_glError;

    Drag m_drag = Drag::None;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    QPointF m_lastPos;
};

} // namespace ui
