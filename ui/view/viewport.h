// SPDX-License-Identifier: GPL-3.0-or-later
// ui/view/: the 3D view: the viewport widget, its input and stand-in, the background
// depth-layer builder, the message bar over it.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <QCursor>
#include <QOpenGLWidget>
#include <QPointF>
#include <QSurfaceFormat>
#include <QTimer>

#include "core/base/result.h"
#include "core/depth/depth_layers.h"
#include "core/depth/depth_stack.h"
#include "core/model/camera.h"
#include "core/model/mesh.h"
#include "core/model/stand_in.h"
#include "core/paint/targets/paint_target.h"
#include "render/brush_overlay.h"
#include "render/depth_compositor.h"
#include "render/gpu_connectivity.h"
#include "render/sliced_frame.h"

namespace core {
class Document;
}

namespace render {
class BrushOverlay;
class GlDepthCapturer;
class MeshRenderer;
} // namespace render

namespace ui {

class StandInJob;
class CompositorMeshJob;
class MeshFillJob;

/**
 * Which buttons move the camera (Preferences). Both, the default, offers the Blender-like and
 * the Alt-based mapping at once; the other two keep only theirs, so Alt or the middle button is
 * free for other uses. The wheel zooms in all of them.
 */
enum class CameraMapping {
    Both,     // the two below together
    Blender,  // middle drag orbits, Shift+middle pans, Ctrl+middle zooms
    AltBased, // Alt+left orbits, Alt+middle pans, Alt+right zooms (tablets, laptops)
};

/** What pressed the button of the current (or last) stroke. */
enum class PointerKind { Mouse, Pen, Eraser };

/**
 * The 3D view of a core::Document: turns mouse input into moves of the document's camera and
 * draws the model. While the view moves, or before the layers of the current view exist, it
 * draws the mesh with render::MeshRenderer; once they exist, it draws them with
 * render::DepthCompositor in the chosen display. The camera buttons follow the CameraMapping
 * (by default middle drag orbits, Shift+middle pans, the wheel zooms, and Alt+left/right/middle
 * orbit, zoom and pan for tablets). The plain left button belongs to painting (the paint*
 * signals). Painting shows without a recapture: once the document has a paint target the
 * renderers draw its painted mesh, and applyPaintChanges() updates only what a dab changed, at
 * the next frame. The brush outline follows the mouse or the pen.
 *
 * While the camera moves (an orbit, pan or zoom drag, or the wheel until it rests for a moment)
 * the mesh renderer draws a simplified stand-in of a large model, made in the background
 * (ui::StandInJob) once per model; the full mesh is drawn again when the view settles. Depth
 * layers, picking and painting always use the full mesh.
 *
 * Tablets: every QTabletEvent is handled and accepted (so Qt synthesizes no mouse events from
 * it) and each sample is passed on, none merged; the pen tip paints with its pressure, the
 * eraser end reports PointerKind::Eraser, leaving proximity hides the outline. Mouse input is
 * handled the same way with pressure 1.
 */
class Viewport : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit Viewport(core::Document& document, QWidget* parent = nullptr);
    ~Viewport() override;

    /** OpenGL 4.5 core with a depth buffer: what render needs. Set it as the default format. */
    static QSurfaceFormat requiredFormat();

    /**
     * Call after replacing the document's mesh: uploads it at the next draw and shows the
     * camera's projection (orthographicChanged()).
     */
    void meshChanged();
    /** The document's mesh, or null before the first model. */
    std::shared_ptr<const core::Mesh> mesh() const;

    const core::Camera& camera() const;
    /** The current view in device pixels (what is drawn and what paint coordinates refer to). */
    core::View view() const;
    /** Changes with every change of camera, size or mesh: layers made before describe another. */
    std::uint64_t viewSerial() const { return m_viewSerial; }
    /** True during an orbit, pan or zoom drag. */
    bool isNavigating() const;
    /** True during a camera drag, and after a wheel turn until the wheel rests for a moment. */
    bool isCameraMoving() const;

    // The stand-in drawn while the camera moves.
    /**
     * Models with more than 1.5 × triangles triangles get a stand-in of at most triangles
     * (0: never); from the next model on.
     */
    void setStandInTriangles(std::size_t triangles) { m_standInTriangles = triangles; }
    std::size_t standInTriangles() const { return m_standInTriangles; }
    /** The current model's stand-in is made (it is drawn while the camera moves). */
    bool hasStandIn() const;
    /**
     * Triangles of the mesh the last frame showed: the mesh renderer's, the stand-in's, or a
     * sliced frame's drawn so far; 0 when the depth layers showed.
     */
    std::size_t lastFrameTriangles() const { return m_lastFrameTriangles; }
    /**
     * On a software renderer, a frame of the mesh of more than 2 × triangles triangles is drawn
     * triangles at a time, a slice per event, so the window answers meanwhile; the stand-in (or,
     * without one, what is drawn so far) shows until it is whole. 0: always drawn at once.
     */
    void setFrameSliceTriangles(std::size_t triangles) { m_frameSliceTriangles = triangles; }
    /** False while the mesh renderer's frame is being drawn in slices. */
    bool isFrameWhole() const { return m_frameWhole; }
    /** How often the mesh went to the GPU (a new model or paint target); for tests. */
    int meshUploads() const { return m_meshUploads; }
    /**
     * A new model of triangles triangles or more has its GL buffers filled in the background
     * (the view says so meanwhile, and a capture waits for them); 0: always at once.
     */
    void setBackgroundFillTriangles(std::size_t triangles) {
        m_backgroundFillTriangles = triangles;
    }
    /** True while a new model's GL buffers are filled in the background. */
    bool isPreparingMesh() const;

    bool isOrthographic() const;

    /** The GL error met in initializeGL, or empty. */
    QString glError() const { return m_glError; }

    // Depth layers, driven by ui::DepthLayersBuilder (the GL work it needs happens in this widget's
    // context).
    /** True once the context is up and a model is loaded: captureLayers() can run. */
    bool canCapture() const;
    /**
     * Where build_layers computes pixel connectivity (docs/architecture.md §2: the faster of the
     * C++ path and the GL compute pass; Auto picks by renderer). Takes effect at the next build.
     */
    void setConnectivityBackend(render::ConnectivityBackend backend);
    /**
     * The engine for core::finishDepthLayers / resegmentDepthLayers: nullptr for the C++ reference
     * (safe on any thread), or the compute pass in this widget's context (GUI thread only).
     */
    core::ConnectivityEngine* connectivityEngine();
    /** The backend in use once resolved for this renderer (Cpu before the first use). */
    render::ConnectivityBackend connectivityBackend() const;
    /** The GPU part of build_layers for view, with this widget's context current. */
    core::Result<core::DepthStack> captureLayers(const core::View& view,
                                                 const core::CaptureFaces& faces,
                                                 core::CaptureStats* stats);
    /** Shows the document's layers with the compositor (they must be of the current view). */
    void showLayers();
    /** The document's layers were re-segmented: updates the compositor's regions. */
    void showSegmentation();
    /** True while the picture comes from the layers (the compositor), not from the mesh. */
    bool isShowingDepthLayers() const;
    /** The document's region order changed (pop-up, hiding, undo): redraws with it. */
    void regionOrderChanged();
    /**
     * See-through pop-ups (the paper's exploded view): regions not on layer 1 that are shown
     * are drawn half transparent over what lies under them in the order.
     */
    void setPopUpTransparency(bool on);
    bool popUpTransparency() const { return m_composite.popUpOpacity < 1.0f; }
    /** What the shaded views show: the lit material or one channel of it alone. */
    void setChannel(render::MaterialChannel channel);
    render::MaterialChannel channel() const { return m_composite.channel; }
    /**
     * The mask view: the mask of paint layer id shown alone, unlit grey (black hides, white
     * shows) in place of the composite, strokes on it shown as they go; 0 goes back. It ends by
     * itself when the mask is gone (maskViewChanged()).
     */
    void setMaskView(std::uint64_t id);
    /** The paint layer whose mask is shown alone (0: none). */
    std::uint64_t maskView() const { return m_maskView; }
    /**
     * Layer-aware rotation (default on): an orbit that starts on a surface point of the shown
     * layers (any layer: what is visible there, popped-up or revealed) turns about that point.
     */
    void setOrbitAboutSurface(bool on) { m_orbitAboutSurface = on; }
    bool orbitAboutSurface() const { return m_orbitAboutSurface; }
    /** The pivot of the current or last orbit drag, if it was a surface point. */
    std::optional<glm::vec3> orbitPivot() const { return m_orbitPivot; }
    /** Highlights the region under the cursor while the layers are shown (pop-up, hide tools). */
    void setHoverHighlight(bool on);

    // Painting.
    /** The document's paint target was created or replaced: draw its painted mesh from now on. */
    void paintTargetChanged();
    /** Paint changed these texels or vertices of the paint target: shown at the next frame. */
    void applyPaintChanges(const core::PaintChanges& changes);
    /** The stroke moved: refreshes the Mp/Mt overlay when it is shown. */
    void brushMapsChanged();
    bool brushMapsVisible() const { return m_brushMapsVisible; }
    /** The radius of the brush outline, in device pixels (0 hides it). */
    void setBrushRadius(float radius);
    float brushRadius() const { return m_brushRadius; }
    /**
     * The cursor of the chosen tool over the view, and whether the brush outline goes with it
     * (only tools that use the brush radius show it).
     */
    void setToolCursor(const QCursor& cursor, bool brushOutline);
    /** Whether the brush outline is drawn now (pointer over the view, not navigating). */
    bool brushOutlineVisible() const {
        return m_brushOutline && m_brushRadius > 0.0f && m_cursorInside && !isNavigating();
    }
    /** Where the brush outline is, in device pixels. */
    QPointF cursorPosition() const { return m_cursor; }

    // Input.
    void setCameraMapping(CameraMapping mapping) { m_mapping = mapping; }
    CameraMapping cameraMapping() const { return m_mapping; }
    /** The pointer of the current or last press (the pen's eraser end erases). */
    PointerKind pressPointer() const { return m_pressPointer; }
    /** True between a pen's enter and leave proximity events. */
    bool penInProximity() const { return m_penInProximity; }
    /** The last tablet tilt in degrees (x, y); read for later brush shapes, unused for now. */
    QPointF penTilt() const { return m_tilt; }

    const render::CompositeOptions& compositeOptions() const { return m_composite; }
    render::DepthLayerDisplay display() const { return m_composite.display; }
    std::uint32_t displayLayer() const { return m_composite.layer; }

public slots:
    /** The document's camera moved (by a script, an orbit...): the view and layers follow. */
    void cameraMoved();
    void frameAll();
    void setOrthographic(bool orthographic);
    void setDisplay(render::DepthLayerDisplay display);
    /** The layer the SingleLayer display shows (1-based). */
    void setDisplayLayer(std::uint32_t layer);
    void setBoundariesVisible(bool visible);
    /** A region drawn highlighted, or core::kNone. */
    void setHighlightRegion(std::uint32_t region);
    /** Shows the paintable (red) and trackable (blue) maps of the last dab (the paper's Fig. 4). */
    void setBrushMapsVisible(bool visible);

signals:
    void orthographicChanged(bool orthographic);
    void cameraChanged();
    /** Camera, size or mesh changed: viewSerial() moved on and the layers are out of date. */
    void viewChanged();
    /** Emitted once, from the event loop, if the renderer cannot start (message for the user). */
    void glInitializationFailed(const QString& message);
    /** A render part other than the mesh renderer failed to start (layers will not show). */
    void depthLayerRenderingFailed(const QString& message);
    /** The current model's stand-in was made (hasStandIn()). */
    void standInReady();
    /** The mask view began (the paint layer's id) or ended (0). */
    void maskViewChanged(std::uint64_t id);

    // The painting hook: positions in device pixels, origin top-left (docs/architecture.md §4).
    // modifiers are those held at the press (ui::toolForPress).
    void paintPressed(QPointF pixel, qreal pressure, Qt::KeyboardModifiers modifiers);
    void paintMoved(QPointF pixel, qreal pressure);
    void paintReleased(QPointF pixel);

protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void resizeEvent(QResizeEvent* event) override;
    void paintGL() override;
    /** The stroke stabilizer's string from the brush tip to the pointer, while it pulls. */
    void drawStabilizerString();
    /** What QPainter draws over the GL picture: the stabilizer's string, a channel's legend. */
    void drawPainted();
    /** Roughness and metallic shown as grey: a legend from 0 to 1 in the bottom-left corner. */
    void drawChannelLegend();
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void tabletEvent(QTabletEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    enum class Drag { None, Orbit, Pan, Zoom, Paint };
    Drag dragFor(Qt::MouseButton button, Qt::KeyboardModifiers modifiers) const;
    // Mouse and pen share these; positions are logical widget pixels. They return whether the
    // event was used.
    bool pointerPress(Qt::MouseButton button, Qt::KeyboardModifiers modifiers, QPointF position,
                      qreal pressure, PointerKind pointer);
    bool pointerMove(QPointF position, qreal pressure);
    bool pointerRelease(Qt::MouseButton button, QPointF position);
    void proximityChanged(bool inProximity);

    QPointF toDevicePixels(QPointF logical) const;
    /** The display or its layer changed: the document follows (Document::setShownLayer()). */
    void shownLayerChanged();
    void updateHoverHighlight();
    void invalidateView();
    void uploadMeshIfDirty();
    /** The compositor's copy of the mesh: a new geometry's prepared in the background. */
    void sendMeshToCompositor(std::shared_ptr<const core::Mesh> geometry,
                              std::shared_ptr<const core::Mesh> look, bool newGeometry);
    /** Uploads the prepared compositor mesh, waiting for it if need be (context current). */
    void installCompositorMesh();
    void compositorMeshPrepared();
    /**
     * Finishes the renderer's and the capture's new buffers, waiting for their fill (context
     * current); false when none were being filled.
     */
    bool finishMeshFill();
    void meshFilled();
    /** While the buffers are filled: the background, and a word why nothing shows yet. */
    void drawPreparingNotice();
    // The stand-in (viewport_stand_in.cpp).
    void startStandIn();
    void standInMade(std::shared_ptr<const core::StandIn> standIn, std::uint64_t meshSerial);
    void uploadStandInIfDirty();
    /** The camera moved by the wheel: the stand-in shows until it rests. */
    void wheelMoved();
    // The mesh renderer's frame (viewport_frame.cpp).
    /** Draws the mesh renderer's frame, at once or its next slice (setFrameSliceTriangles()). */
    void drawMeshFrame(const core::View& view, render::DrawOptions options);
    /** Whether a frame of triangles is drawn in slices. */
    bool slicesFrame(std::size_t triangles) const;
    void reportDepthLayerError(const core::Status& status);
    void releaseGl();
    /**
     * What paint changed since it was last uploaded: a bounding rectangle per page (to the
     * textures both renderers share, once) and the vertex colours (each renderer has its own).
     */
    struct PendingPaint {
        std::vector<core::TexelRect> pages;   // width 0: clean
        core::VertexRange compositorVertices; // begin == end: clean
        core::VertexRange rendererVertices;
        void add(const core::PaintChanges& changes);
        void clear() {
            pages.clear();
            compositorVertices = rendererVertices = {};
        }
    };
    /** Uploads the pending paint the compositor's or the mesh renderer's next draw shows. */
    void flushPaint(bool compositor);
    /** flushPaint()'s steps: the changed texels of the pages, the changed vertex colours. */
    void flushPages(const core::PaintTarget& target);
    void flushVertexColors(const core::PaintTarget& target, bool compositor);
    /** The mask the mask view shows, or nullptr (none, or it is gone). */
    const core::TiledPlane* shownMask() const;
    /** Uploads the mask view's pages (or the composite's again when it ended). */
    void uploadMaskView();
    /** Writes rect of the mask view's page into its grey picture and uploads it. */
    void uploadMaskRect(const core::TiledPlane& mask, const core::TexelRect& rect);

    core::Document& m_document;
    // These live only while the context does.
    std::unique_ptr<render::MeshRenderer> m_renderer;
    /** The textures the renderer and the compositor both draw with. */
    std::shared_ptr<render::MaterialTextures> m_textures;
    std::unique_ptr<render::GlDepthCapturer> m_capturer;
    class ContextConnectivity;
    render::ConnectivityBackend m_connectivityRequest = render::ConnectivityBackend::Auto;
    std::unique_ptr<render::GlConnectivityEngine> m_connectivity;
    std::unique_ptr<ContextConnectivity> m_contextConnectivity;
    std::unique_ptr<render::DepthCompositor> m_compositor;
    std::unique_ptr<render::BrushOverlay> m_overlay;
    std::unique_ptr<render::SlicedFrame> m_slicedFrame;
    bool m_softwareGl = false;
    bool m_meshDirty = false;
    int m_meshUploads = 0;
    bool m_paintedMeshDirty = false; // only the paint target's textures or colours are new
    /** The paint target whose painted mesh the renderers hold (nullptr: the plain mesh). */
    const core::PaintTarget* m_shownTarget = nullptr;
    bool m_compositorHasMesh = false;
    /** The compositor holds the document's layers of the current view. */
    bool m_depthLayersShown = false;
    std::uint64_t m_viewSerial = 1;
    render::CompositeOptions m_composite;
    std::uint64_t m_maskView = 0;
    bool m_maskViewDirty = false;         // its pages (or the composite's) to upload
    std::vector<core::Image> m_maskPages; // the mask as grey, page by page
    QString m_glError;

    // Painting: uploaded when a renderer draws next (the mesh renderer's vertex colours only
    // after the view moves), so a stroke costs the compositor's compose pass per frame.
    PendingPaint m_pendingPaint;
    bool m_brushMapsVisible = false;
    std::vector<std::uint8_t> m_brushMaps; // view-sized RGBA, as Document::fillBrushMaps fills it
    render::PixelRect m_mapsRect;          // what the maps cover now
    render::PixelRect m_mapsUpload;        // what changed since the last upload
    float m_brushRadius = 0.0f;
    bool m_brushOutline = true; // the tool uses the brush radius
    QPointF m_cursor;           // device pixels
    bool m_cursorInside = false;
    bool m_hoverHighlight = false;
    bool m_orbitAboutSurface = true;
    std::optional<glm::vec3> m_orbitPivot;

    // The stand-in: made for the document's mesh at m_standInSerial, uploaded when dirty.
    static constexpr std::size_t kStandInTriangles = 250'000;
    std::size_t m_standInTriangles = kStandInTriangles;
    StandInJob* m_standInJob = nullptr;
    CompositorMeshJob* m_compositorJob = nullptr;
    MeshFillJob* m_meshFill = nullptr;
    static constexpr std::size_t kBackgroundFillTriangles = 1'000'000;
    std::size_t m_backgroundFillTriangles = kBackgroundFillTriangles;
    std::shared_ptr<const core::StandIn> m_standIn;
    std::uint64_t m_standInSerial = 0;
    bool m_standInDirty = false;
    QTimer m_wheelRest; // runs from a wheel turn until the wheel rests
    std::size_t m_lastFrameTriangles = 0;
    static constexpr std::size_t kFrameSliceTriangles = 1'000'000;
    std::size_t m_frameSliceTriangles = kFrameSliceTriangles;
    bool m_frameWhole = true;

    Drag m_drag = Drag::None;
    Qt::MouseButton m_dragButton = Qt::NoButton;
    QPointF m_lastPos;
    CameraMapping m_mapping = CameraMapping::Both;
    PointerKind m_pressPointer = PointerKind::Mouse;
    bool m_penInProximity = false;
    QPointF m_tilt;
};

} // namespace ui
