// SPDX-License-Identifier: GPL-3.0-or-later
// The viewport: what it shows (the mesh, or the layers' composite with the brush overlay), its GL
// objects and the capture for build_layers; pointer input is in viewport_input.cpp.
#include "ui/view/viewport.h"

#include <QCoreApplication>
#include <QLinearGradient>
#include <QLocale>
#include <QMetaObject>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QResizeEvent>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/document/document.h"
#include "render/brush_overlay.h"
#include "render/gl_depth_capturer.h"
#include "render/mesh_renderer.h"
#include "render/software_gl.h"
#include "ui/shell/compositor_mesh_job.h"
#include "ui/shell/mesh_fill_job.h"
#include "ui/shell/stand_in_job.h"

namespace ui {

namespace {
constexpr float kPopUpOpacity = 0.55f; // see-through pop-ups: the surroundings stay readable
// Behind roughness or metallic shown as grey: a muted blue that no grey matches, so that low
// values (a roughness of 0.2) stand apart from it. sRGB-encoded.
constexpr glm::vec4 kGreyChannelBackground{0.13f, 0.2f, 0.34f, 1.0f};

bool isGreyChannel(render::MaterialChannel channel) {
    return channel == render::MaterialChannel::Roughness ||
           channel == render::MaterialChannel::Metallic;
}

render::PixelRect unite(const render::PixelRect& a, const render::PixelRect& b) {
    if (a.empty())
        return b;
    if (b.empty())
        return a;
    const int x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    const int x1 = std::max(a.x + a.width, b.x + b.width);
    const int y1 = std::max(a.y + a.height, b.y + b.height);
    return {x0, y0, x1 - x0, y1 - y0};
}
} // namespace

Viewport::Viewport(core::Document& document, QWidget* parent)
    : QOpenGLWidget(parent), m_document(document) {
    setFormat(requiredFormat());
    setFocusPolicy(Qt::StrongFocus);
    // Room to see a model and paint on it at the smallest window size.
    setMinimumSize(360, 240);
    // Hover moves draw the brush outline, a pen's too.
    setMouseTracking(true);
    setAttribute(Qt::WA_TabletTracking);
    // Every pen sample is a point of the stroke: a 200 Hz tablet must lose none to merging.
    // (Off by default in Qt 6; made sure of, as the stroke depends on it.)
    QCoreApplication::setAttribute(Qt::AA_CompressTabletEvents, false);
    // Qt sends proximity events to the application object, not to a widget.
    if (QCoreApplication* app = QCoreApplication::instance())
        app->installEventFilter(this);
    m_standInJob = new StandInJob(this);
    connect(m_standInJob, &StandInJob::finished, this, &Viewport::standInMade);
    m_compositorJob = new CompositorMeshJob(this);
    connect(m_compositorJob, &CompositorMeshJob::finished, this, &Viewport::compositorMeshPrepared);
    m_meshFill = new MeshFillJob(this);
    connect(m_meshFill, &MeshFillJob::finished, this, &Viewport::meshFilled);
    m_wheelRest.setSingleShot(true);
    m_wheelRest.setInterval(300);
    connect(&m_wheelRest, &QTimer::timeout, this, qOverload<>(&Viewport::update));
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
    startStandIn();
    // A new model starts in its default view (or a project's): the toggle follows.
    emit orthographicChanged(camera().orthographic);
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
    m_document.camera().frame(m_document.mesh().bounds(), m_document.viewAspect(),
                              core::kFrameMargin);
    cameraMoved();
}

void Viewport::setOrthographic(bool orthographic) {
    if (camera().orthographic == orthographic)
        return;
    m_document.camera().orthographic = orthographic;
    emit orthographicChanged(orthographic);
    cameraMoved();
}

void Viewport::setDisplay(render::DepthLayerDisplay display) {
    if (m_composite.display == display)
        return;
    m_composite.display = display;
    shownLayerChanged();
    update();
}

void Viewport::setDisplayLayer(std::uint32_t layer) {
    layer = std::max(layer, 1u);
    if (m_composite.layer == layer)
        return;
    m_composite.layer = layer;
    shownLayerChanged();
    update();
}

void Viewport::shownLayerChanged() {
    // What is painted, filled or picked is what this view shows.
    m_document.setShownLayer(
        m_composite.display == render::DepthLayerDisplay::SingleLayer ? m_composite.layer : 0);
    if (m_hoverHighlight)
        updateHoverHighlight();
}

void Viewport::setBoundariesVisible(bool visible) {
    if (m_composite.boundaries == visible)
        return;
    m_composite.boundaries = visible;
    update();
}

void Viewport::setChannel(render::MaterialChannel channel) {
    if (m_composite.channel == channel)
        return;
    m_composite.channel = channel;
    update();
}

void Viewport::setMaskView(std::uint64_t id) {
    if (m_maskView == id)
        return;
    m_maskView = id;
    m_maskViewDirty = true;
    update();
    emit maskViewChanged(id);
}

const core::TiledPlane* Viewport::shownMask() const {
    if (m_maskView == 0 || !m_document.hasPaintTarget())
        return nullptr;
    const core::PaintLayerTarget* layers = m_document.currentPaintTarget()->paintLayers();
    if (!layers)
        return nullptr;
    const core::PaintLayerStack& stack = layers->paintLayerStack();
    const std::optional<std::size_t> index = stack.indexOf(m_maskView);
    return index ? stack.layer(*index).mask.get() : nullptr;
}

void Viewport::uploadMaskView() {
    m_maskViewDirty = false;
    const core::PaintTarget* target = m_shownTarget;
    if (!target || !m_textures)
        return;
    const core::TiledPlane* mask = shownMask();
    if (m_maskView != 0 && !mask) {
        // The mask or its paint layer went (undo, delete): the composite again.
        m_maskView = 0;
        QMetaObject::invokeMethod(
            this, [this] { emit maskViewChanged(0); }, Qt::QueuedConnection);
    }
    m_maskPages.clear();
    for (std::uint32_t page = 0; page < target->pageCount(); ++page) {
        const core::Image& composite = target->page(page);
        const core::TexelRect all{page, 0, 0, composite.width, composite.height};
        if (mask) {
            m_maskPages.push_back({composite.width, composite.height,
                                   std::vector<std::uint8_t>(composite.rgba.size())});
            uploadMaskRect(*mask, all);
        } else {
            m_textures->updateTexels(page, 0, 0, composite.width, composite.height, composite);
        }
    }
}

void Viewport::uploadMaskRect(const core::TiledPlane& mask, const core::TexelRect& rect) {
    if (rect.page >= m_maskPages.size())
        return;
    core::Image& grey = m_maskPages[rect.page];
    core::writeMaskAsGrey(mask, rect.page, {rect.x, rect.y, rect.width, rect.height}, grey);
    m_textures->updateTexels(rect.page, rect.x, rect.y, rect.width, rect.height, grey);
}

void Viewport::setBrushMapsVisible(bool visible) {
    if (m_brushMapsVisible == visible)
        return;
    m_brushMapsVisible = visible;
    m_mapsRect = {};
    if (visible)
        brushMapsChanged();
    update();
}

void Viewport::setBrushRadius(float radius) {
    if (m_brushRadius == radius)
        return;
    m_brushRadius = radius;
    if (m_cursorInside)
        update();
}

void Viewport::setToolCursor(const QCursor& cursor, bool brushOutline) {
    setCursor(cursor);
    if (m_brushOutline == brushOutline)
        return;
    m_brushOutline = brushOutline;
    if (m_cursorInside)
        update();
}

void Viewport::paintTargetChanged() {
    m_paintedMeshDirty = true; // uploaded where the context is current
    m_pendingPaint.clear();
    setMaskView(0); // another target's paint layers
    update();
}

namespace {

/** The smallest range holding both (an empty one holds nothing). */
core::VertexRange unite(core::VertexRange a, core::VertexRange b) {
    if (a.begin >= a.end)
        return b;
    if (b.begin >= b.end)
        return a;
    return {std::min(a.begin, b.begin), std::max(a.end, b.end)};
}

} // namespace

void Viewport::PendingPaint::add(const core::PaintChanges& changes) {
    for (const core::TexelRect& rect : changes.texels) {
        if (rect.width <= 0 || rect.height <= 0)
            continue;
        if (pages.size() <= rect.page)
            pages.resize(std::size_t(rect.page) + 1);
        core::TexelRect& box = pages[rect.page];
        if (box.width <= 0) {
            box = rect;
            continue;
        }
        const int x1 = std::max(box.x + box.width, rect.x + rect.width);
        const int y1 = std::max(box.y + box.height, rect.y + rect.height);
        box.x = std::min(box.x, rect.x);
        box.y = std::min(box.y, rect.y);
        box.width = x1 - box.x;
        box.height = y1 - box.y;
    }
    for (const core::VertexRange& range : changes.vertices) {
        compositorVertices = unite(compositorVertices, range);
        rendererVertices = unite(rendererVertices, range);
    }
}

void Viewport::applyPaintChanges(const core::PaintChanges& changes) {
    if (changes.empty())
        return;
    m_pendingPaint.add(changes);
    update();
}

void Viewport::brushMapsChanged() {
    const core::DepthLayers* layers = m_document.depthLayers();
    if (!m_brushMapsVisible || !layers)
        return;
    const int width = layers->stack.width, height = layers->stack.height;
    m_brushMaps.resize(std::size_t(width) * std::size_t(height) * 4);
    if (!m_document.fillBrushMaps(m_brushMaps))
        return;
    // Mt (Mp included) is all the overlay shows: draw and upload only its bounding box.
    int x0 = width, y0 = height, x1 = 0, y1 = 0;
    for (const std::uint32_t pixel : m_document.strokeTracker().trackablePixels()) {
        const int x = int(pixel % std::uint32_t(width)), y = int(pixel / std::uint32_t(width));
        x0 = std::min(x0, x);
        y0 = std::min(y0, y);
        x1 = std::max(x1, x + 1);
        y1 = std::max(y1, y + 1);
    }
    const render::PixelRect rect =
        x0 < x1 ? render::PixelRect{x0, y0, x1 - x0, y1 - y0} : render::PixelRect{};
    // The previous box is uploaded too, so what the maps left is cleared.
    m_mapsUpload = unite(m_mapsUpload, unite(m_mapsRect, rect));
    m_mapsRect = rect;
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

core::Result<core::DepthStack> Viewport::captureLayers(const core::View& view,
                                                       const core::CaptureFaces& faces,
                                                       core::CaptureStats* stats) {
    if (!canCapture())
        return core::Error{tr("The depth-layer capture is not available.").toStdString()};
    makeCurrent();
    uploadMeshIfDirty();
    if (finishMeshFill()) // the capture needs its buffers whole; the notice goes
        update();
    auto stack = m_capturer->capture(view, faces, stats);
    doneCurrent();
    return stack;
}

void Viewport::showLayers() {
    const core::DepthLayers* layers = m_document.depthLayers();
    if (!m_compositor || !layers)
        return;
    makeCurrent();
    uploadMeshIfDirty();
    if (m_compositorJob->isPending())
        installCompositorMesh(); // not yet there: waits for it
    const core::Status status =
        m_compositorHasMesh ? m_compositor->setDepthLayers(*layers) : core::Status::success();
    doneCurrent();
    // Without them the mesh renderer goes on drawing the shaded view.
    m_depthLayersShown = m_compositorHasMesh && status.ok();
    if (!status)
        reportDepthLayerError(status);
    update();
}

void Viewport::showSegmentation() {
    const core::DepthLayers* layers = m_document.depthLayers();
    if (!m_compositor || !layers || !m_depthLayersShown)
        return;
    makeCurrent();
    const core::Status status = m_compositor->updateSegmentation(*layers);
    doneCurrent();
    if (!status) {
        m_depthLayersShown = false;
        reportDepthLayerError(status);
    }
    update();
}

void Viewport::regionOrderChanged() {
    if (!m_compositor || !m_depthLayersShown || !m_document.depthLayers())
        return;
    makeCurrent();
    // Pruned: the same picture, fewer regions to test per pixel.
    m_compositor->setRegionRanks(m_document.regionOrder().prunedRanks(popUpTransparency()));
    doneCurrent();
    updateHoverHighlight();
    update();
}

void Viewport::setPopUpTransparency(bool on) {
    if (on == popUpTransparency())
        return;
    m_composite.popUpOpacity = on ? kPopUpOpacity : 1.0f;
    regionOrderChanged();
    update();
}

void Viewport::setHoverHighlight(bool on) {
    m_hoverHighlight = on;
    if (!on)
        setHighlightRegion(core::kNone);
    else
        updateHoverHighlight();
}

void Viewport::updateHoverHighlight() {
    if (!m_hoverHighlight)
        return;
    std::uint32_t region = core::kNone;
    const core::DepthLayers* layers = m_document.depthLayers();
    if (m_cursorInside && isShowingDepthLayers() && layers && m_cursor.x() >= 0 &&
        m_cursor.y() >= 0 && m_cursor.x() < layers->stack.width &&
        m_cursor.y() < layers->stack.height) {
        const std::size_t pixel = std::size_t(m_cursor.y()) * std::size_t(layers->stack.width) +
                                  std::size_t(m_cursor.x());
        const std::uint32_t f = m_document.visibleFragment(pixel);
        if (f != core::kNone)
            region = layers->segmentation.region[f];
    }
    setHighlightRegion(region);
}

bool Viewport::isShowingDepthLayers() const {
    return m_depthLayersShown && m_compositor && m_document.depthLayers();
}

void Viewport::cameraMoved() {
    invalidateView();
    emit cameraChanged();
}

void Viewport::invalidateView() {
    ++m_viewSerial;
    m_depthLayersShown = false;
    m_mapsRect = {}; // they describe the old view
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
        if (status) {
            m_renderer = std::move(renderer);
            m_textures = std::make_shared<render::MaterialTextures>();
            m_slicedFrame = std::make_unique<render::SlicedFrame>();
            m_softwareGl = render::isSoftwareRenderer();
        } else {
            m_glError =
                tr("The renderer could not start: %1").arg(QString::fromStdString(status.error()));
        }
    }
    QString layerError;
    if (m_renderer) {
        // Without these the mesh still shows; only the layer views are missing.
        auto capturer = std::make_unique<render::GlDepthCapturer>();
        auto compositor = std::make_unique<render::DepthCompositor>();
        const core::Status captureStatus = capturer->initialize();
        const core::Status compositeStatus = compositor->initialize();
        if (captureStatus && compositeStatus) {
            m_capturer = std::move(capturer);
            m_compositor = std::move(compositor);
        } else {
            layerError = tr("The depth-layer views could not start: %1")
                             .arg(QString::fromStdString(captureStatus ? compositeStatus.error()
                                                                       : captureStatus.error()));
            capturer->depthCapture().release();
            compositor->release();
        }
        // Without it painting works, only the brush outline and maps are missing.
        auto overlay = std::make_unique<render::BrushOverlay>();
        if (overlay->initialize())
            m_overlay = std::move(overlay);
        else
            overlay->release();
    }
    // Reported from the event loop: a modal dialog inside initializeGL would re-enter it.
    if (!m_glError.isEmpty()) {
        QMetaObject::invokeMethod(
            this, [this] { emit glInitializationFailed(m_glError); }, Qt::QueuedConnection);
    } else if (!layerError.isEmpty()) {
        QMetaObject::invokeMethod(
            this, [this, layerError] { emit depthLayerRenderingFailed(layerError); },
            Qt::QueuedConnection);
    }
    m_meshDirty = true;
    m_pendingPaint.clear();
    m_mapsUpload = {};
    invalidateView(); // the GL objects are new: so are the layers they will hold
}

void Viewport::resizeGL(int, int) {
    invalidateView();
}

void Viewport::resizeEvent(QResizeEvent* event) {
    // The next model, and Frame All, are framed for this shape.
    if (width() > 0 && height() > 0)
        m_document.setViewAspect(float(width()) / float(height()));
    QOpenGLWidget::resizeEvent(event);
}

void Viewport::reportDepthLayerError(const core::Status& status) {
    // Queued: this may run inside paintGL or with the context current.
    const QString message =
        tr("The depth layers cannot be shown: %1").arg(QString::fromStdString(status.error()));
    QMetaObject::invokeMethod(
        this, [this, message] { emit depthLayerRenderingFailed(message); }, Qt::QueuedConnection);
}

void Viewport::paintGL() {
    render::CompositeOptions composite = m_composite;
    if (m_maskView != 0)
        composite.channel = render::MaterialChannel::BaseColor; // the mask's grey, unlit
    if (isGreyChannel(composite.channel) || m_maskView != 0)
        composite.background = kGreyChannelBackground;
    render::DrawOptions options;
    options.background = composite.background;
    QOpenGLFunctions* gl = context()->functions();
    gl->glClearColor(options.background.r, options.background.g, options.background.b, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (!m_renderer || !mesh())
        return;
    uploadMeshIfDirty();
    if (m_meshFill->isPending())
        return drawPreparingNotice();
    if (m_maskViewDirty)
        uploadMaskView();
    uploadStandInIfDirty();
    // QOpenGLWidget has bound its own framebuffer; both draw into whatever is bound.
    const core::View current = view();
    m_lastFrameTriangles = 0;
    if (isShowingDepthLayers()) {
        flushPaint(true);
        m_compositor->draw(composite);
    } else {
        flushPaint(false);
        options.standIn = isCameraMoving();
        options.channel = composite.channel;
        // The faces the capture keeps, so what shows is what a stroke can reach.
        options.cullBackFaces = m_document.depthLayerOptions().cullBackFaces;
        drawMeshFrame(current, options);
    }
    if (!m_overlay) {
        drawPainted();
        return;
    }
    render::BrushOverlayOptions overlay;
    overlay.viewWidth = current.width;
    overlay.viewHeight = current.height;
    const core::DepthLayers* layers = m_document.depthLayers();
    if (m_brushMapsVisible && layers && !m_mapsUpload.empty()) {
        m_overlay->setMaps(layers->stack.width, layers->stack.height, m_brushMaps, m_mapsUpload);
        m_mapsUpload = {};
    }
    if (m_brushMapsVisible && layers && isShowingDepthLayers())
        overlay.maps = m_mapsRect;
    if (brushOutlineVisible()) {
        overlay.center = {float(m_cursor.x()), float(m_cursor.y())};
        overlay.radius = m_brushRadius;
    }
    m_overlay->draw(overlay);
    drawPainted();
}

void Viewport::drawPainted() {
    drawStabilizerString();
    drawChannelLegend();
}

void Viewport::drawChannelLegend() {
    if ((!isGreyChannel(m_composite.channel) && m_maskView == 0) || !mesh())
        return;
    QPainter painter(this);
    const QFontMetrics metrics = painter.fontMetrics();
    const QLocale locale;
    const QString low = locale.toString(0), high = locale.toString(1);
    const QString name = m_maskView != 0 ? tr("Mask (black hides, white shows)")
                         : m_composite.channel == render::MaterialChannel::Roughness
                             ? tr("Roughness")
                             : tr("Metallic");
    constexpr int kMargin = 12, kBarWidth = 160, kBarHeight = 12;
    const int barLeft = kMargin + metrics.horizontalAdvance(low) + 6;
    const QRect bar(barLeft, height() - kMargin - kBarHeight, kBarWidth, kBarHeight);
    // As the view shows a value: its byte as the grey level.
    QLinearGradient ramp(bar.topLeft(), bar.topRight());
    ramp.setColorAt(0.0, Qt::black);
    ramp.setColorAt(1.0, Qt::white);
    painter.fillRect(bar, ramp);
    painter.setPen(QColor(255, 255, 255, 220));
    painter.drawRect(bar.adjusted(0, 0, -1, -1));
    const int baseline = bar.center().y() + metrics.ascent() / 2 - 1;
    painter.drawText(kMargin, baseline, low);
    painter.drawText(bar.right() + 6, baseline, high);
    painter.drawText(bar.left(), bar.top() - 4, name);
}

void Viewport::drawStabilizerString() {
    const core::StrokeStabilizer& stabilizer = m_document.stabilizer();
    if (m_drag != Drag::Paint || !stabilizer.stabilizing())
        return;
    // Device pixels (as the stroke's points) to the painter's logical ones.
    const qreal scale = 1.0 / devicePixelRatioF();
    const QPointF tip(stabilizer.tip().x * scale, stabilizer.tip().y * scale);
    const QPointF pointer(stabilizer.pointer().x * scale, stabilizer.pointer().y * scale);
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    // A dark line under a light one, so the string shows on any surface.
    for (const auto& [color, width] :
         {std::pair{QColor(0, 0, 0, 160), 3.0}, std::pair{QColor(255, 255, 255, 230), 1.5}}) {
        painter.setPen(QPen(color, width, Qt::SolidLine, Qt::RoundCap));
        painter.setBrush(Qt::NoBrush);
        painter.drawLine(tip, pointer);
        painter.drawEllipse(tip, 3.0, 3.0);
    }
}

/** The compute pass in the viewport's context, for build_layers on the GUI thread. */
class Viewport::ContextConnectivity : public core::ConnectivityEngine {
public:
    explicit ContextConnectivity(Viewport& viewport) : m_viewport(viewport) {}
    core::Connectivity compute(const core::DepthStack& stack,
                               const core::ConnectivityOptions& options,
                               const core::SurfaceGeometry* geometry) override {
        m_viewport.makeCurrent();
        core::Connectivity result = m_viewport.m_connectivity->compute(stack, options, geometry);
        m_viewport.doneCurrent();
        return result;
    }

private:
    Viewport& m_viewport;
};

void Viewport::setConnectivityBackend(render::ConnectivityBackend backend) {
    if (backend == m_connectivityRequest)
        return;
    m_connectivityRequest = backend;
    if (m_connectivity) {
        makeCurrent();
        m_connectivity.reset(); // made again, with the new choice, at the next use
        doneCurrent();
    }
}

core::ConnectivityEngine* Viewport::connectivityEngine() {
    if (!m_connectivity && m_capturer) {
        makeCurrent();
        m_connectivity = std::make_unique<render::GlConnectivityEngine>(m_connectivityRequest);
        doneCurrent();
    }
    if (!m_connectivity || m_connectivity->backend() != render::ConnectivityBackend::Gpu)
        return nullptr;
    if (!m_contextConnectivity)
        m_contextConnectivity = std::make_unique<ContextConnectivity>(*this);
    return m_contextConnectivity.get();
}

render::ConnectivityBackend Viewport::connectivityBackend() const {
    return m_connectivity ? m_connectivity->backend() : render::ConnectivityBackend::Cpu;
}

void Viewport::releaseGl() {
    if (!m_renderer && !m_capturer && !m_compositor && !m_overlay && !m_slicedFrame)
        return;
    makeCurrent();
    m_meshFill->wait(); // it writes into the buffers freed here
    m_overlay.reset();
    if (m_slicedFrame)
        m_slicedFrame->release();
    m_slicedFrame.reset();
    m_shownTarget = nullptr;
    m_compositor.reset();
    m_capturer.reset();
    m_connectivity.reset();
    m_renderer.reset();
    if (m_textures)
        m_textures->release();
    m_textures.reset();
    doneCurrent();
    m_depthLayersShown = false;
}

} // namespace ui
