// SPDX-License-Identifier: GPL-3.0-or-later
// The quick guide's pictures: the operations the guide explains, done by core::Document on the
// built-in row and shaded on the CPU, with the pointer's path drawn over them.
#include "ui/shell/quick_guide_pictures.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <QPainter>
#include <QPainterPath>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>

#include "core/base/color.h"
#include "core/depth/depth_layers.h"
#include "core/document/document.h"
#include "core/model/builtin_models.h"

namespace ui {

namespace {

/** The visible fragment of every pixel of doc's layers (core::kNone: background). */
std::vector<std::uint32_t> visibleFragments(const core::Document& doc) {
    std::vector<std::uint32_t> visible;
    if (const core::DepthLayers* layers = doc.depthLayers())
        for (std::size_t p = 0; p < layers->stack.pixelCount(); ++p)
            visible.push_back(doc.visibleFragment(p));
    return visible;
}

/**
 * The visible surface of doc's layers, lit from the camera, over a light background; with
 * before (visibleFragments() earlier), the pixels that show another surface now are tinted
 * amber: what a pop-up or a hide brought into view.
 */
QImage shade(core::Document& doc, const core::View& view,
             const std::vector<std::uint32_t>* before = nullptr) {
    const core::DepthLayers* layers = doc.depthLayers();
    QImage image(view.width, view.height, QImage::Format_RGB32);
    image.fill(QColor(236, 238, 242));
    if (!layers)
        return image;
    const core::DepthStack& stack = layers->stack;
    const core::Mesh& mesh = doc.mesh();
    const glm::mat3 toView(view.view);
    for (int y = 0; y < stack.height; ++y)
        for (int x = 0; x < stack.width; ++x) {
            const std::size_t pixel = std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
            const std::uint32_t fragment = doc.visibleFragment(pixel);
            if (fragment == core::kNone)
                continue;
            const std::size_t t = stack.triangle[fragment];
            const glm::vec3 a = mesh.positions[mesh.indices[3 * t]];
            const glm::vec3 b = mesh.positions[mesh.indices[3 * t + 1]];
            const glm::vec3 c = mesh.positions[mesh.indices[3 * t + 2]];
            const glm::vec3 n = toView * glm::cross(b - a, c - a);
            const float len = glm::length(n);
            const float light = 0.35f + 0.65f * (len > 0.0f ? std::abs(n.z) / len : 1.0f);
            glm::vec4 color = doc.pickColor(pixel).value_or(glm::vec4(0.7f));
            if (before && pixel < before->size() && (*before)[pixel] != fragment)
                color = glm::mix(color, glm::vec4(1.0f, 0.45f, 0.02f, 1.0f), 0.6f);
            image.setPixel(x, y,
                           qRgb(core::linearToSrgb(color.r * light),
                                core::linearToSrgb(color.g * light),
                                core::linearToSrgb(color.b * light)));
        }
    return image;
}

/** The pointer's path (and a dot where it pressed) over a picture. */
void drawPath(QImage& image, const std::vector<QPointF>& points, const QColor& color) {
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(color, 1.5, Qt::DashLine));
    QPainterPath path;
    path.moveTo(points.front());
    for (std::size_t i = 1; i < points.size(); ++i)
        path.lineTo(points[i]);
    painter.drawPath(path);
    painter.setBrush(color);
    painter.drawEllipse(points.front(), 3.0, 3.0);
}

/** A click: a ring at the spot. */
void drawClick(QImage& image, QPointF at, const QColor& color) {
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(color, 2.0));
    painter.drawEllipse(at, 6.0, 6.0);
    painter.drawEllipse(at, 1.5, 1.5);
}

/** The row of four bodies seen from the side a little, its layers built, a texture to paint. */
bool prepare(core::Document& doc, core::CpuDepthCapturer& capturer, const core::View& view) {
    capturer.setMesh(doc.mesh());
    if (!doc.buildDepthLayers(capturer, view))
        return false;
    core::PaintTargetOptions options;
    options.kind = core::PaintTargetKind::Texture;
    options.resolution = 512;
    return bool(doc.setPaintTarget(options));
}

/** What every picture is made from: the row, its first view, the capturer, the pointer's colour. */
struct GuideScene {
    core::Document doc;
    core::CpuDepthCapturer capturer;
    QSize size;
    float w = 0.0f, h = 0.0f;
    core::View view;
    float distance = 0.0f; // the camera's in the first view
    QColor pointer{20, 90, 200};
};

/** The camera's first view of the row. */
void setCameraStart(core::Camera& camera) {
    camera.yawDegrees = 35.0f;
    camera.pitchDegrees = 12.0f;
}

/** The built-in row in scene.doc, its camera a little from the side; false without the model. */
bool loadRow(GuideScene& scene) {
    core::Result<core::Mesh> mesh = core::makeBuiltinModel("row");
    if (!mesh)
        return false;
    core::Document& doc = scene.doc;
    doc.setMesh(std::move(mesh).value(), "row");
    doc.setViewAspect(float(scene.size.width()) / float(scene.size.height()));
    doc.resetCamera();
    setCameraStart(doc.camera());
    doc.camera().distance *= 0.5f; // the row, not the room around it
    scene.distance = doc.camera().distance;
    scene.view = doc.camera().view(scene.size.width(), scene.size.height());
    scene.w = float(scene.size.width());
    scene.h = float(scene.size.height());
    return true;
}

/** The first view again, its depth layers built anew, nothing popped up; false if they fail. */
bool resetScene(GuideScene& scene) {
    core::Document& doc = scene.doc;
    setCameraStart(doc.camera());
    doc.camera().distance = scene.distance;
    doc.clearDepthLayers();
    if (!prepare(doc, scene.capturer, scene.view))
        return false;
    doc.resetRegionOrder();
    return true;
}

/**
 * A stroke from the second body on to the right, behind the first: layer-aware, it stays on the
 * surface it started on.
 */
QImage drawLayerAwareStroke(GuideScene& scene) {
    core::Document& doc = scene.doc;
    const float w = scene.w, h = scene.h;
    doc.setLayerAware(true);
    doc.setAutoPopUp(false);
    doc.brush().radius = 0.03f * h;
    doc.brush().hardness = 0.8f;
    doc.brush().color = {0.85f, 0.12f, 0.08f, 1.0f};
    std::vector<QPointF> points;
    for (int i = 0; i <= 40; ++i) {
        const float t = float(i) / 40.0f;
        points.emplace_back(0.3f * w + t * 0.4f * w, 0.5f * h + 0.08f * h * std::sin(6.0f * t));
    }
    core::PaintChanges changes;
    if (doc.beginStroke({{float(points[0].x()), float(points[0].y())}, 1.0f}, changes)) {
        for (const QPointF& p : points)
            doc.moveStroke({{float(p.x()), float(p.y())}, 1.0f}, changes);
        doc.endStroke(changes);
    }
    QImage image = shade(doc, scene.view);
    drawPath(image, points, scene.pointer);
    return image;
}

/** How many pixels show another surface than before. */
std::size_t changedPixels(const std::vector<std::uint32_t>& before,
                          const std::vector<std::uint32_t>& after) {
    std::size_t changed = 0;
    for (std::size_t p = 0; p < std::min(before.size(), after.size()); ++p)
        changed += before[p] != after[p];
    return changed;
}

/**
 * Of points around the middle of the view, the one where a click pops up the most: where one
 * body hides much of another, so the picture shows what a pop-up does.
 */
glm::vec2 bestPopUpPoint(GuideScene& scene) {
    core::Document& doc = scene.doc;
    const std::vector<std::uint32_t> before = visibleFragments(doc);
    glm::vec2 best(0.5f * scene.w, 0.5f * scene.h);
    std::size_t most = 0;
    for (int j = 1; j <= 5; ++j)
        for (int i = 1; i <= 9; ++i) {
            const glm::vec2 at(scene.w * (0.2f + 0.06f * float(i)),
                               scene.h * (0.25f + 0.1f * float(j)));
            if (doc.popUpAt(at) == core::kNone)
                continue;
            const std::size_t changed = changedPixels(before, visibleFragments(doc));
            doc.resetRegionOrder();
            if (changed > most) {
                most = changed;
                best = at;
            }
        }
    return best;
}

/** A click where one body hides another pops the region below the visible one up (tinted). */
QImage drawPopUp(GuideScene& scene) {
    const glm::vec2 at = bestPopUpPoint(scene);
    const std::vector<std::uint32_t> before = visibleFragments(scene.doc);
    scene.doc.popUpAt(at);
    QImage image = shade(scene.doc, scene.view, &before);
    drawClick(image, QPointF(at.x, at.y), scene.pointer);
    return image;
}

/**
 * A short drag where one body hides another hides the regions it touches; what they hid shows
 * (tinted).
 */
QImage drawPaintToHide(GuideScene& scene) {
    core::Document& doc = scene.doc;
    const float w = scene.w, h = scene.h;
    const glm::vec2 at = bestPopUpPoint(scene);
    std::vector<QPointF> points;
    const std::vector<std::uint32_t> before = visibleFragments(doc);
    doc.beginHide();
    for (int i = 0; i <= 10; ++i) {
        const float t = float(i) / 10.0f;
        points.emplace_back(at.x - 0.04f * w + 0.08f * w * t, at.y);
        if (i > 0)
            doc.hideAlong({float(points[i - 1].x()), float(points[i - 1].y())},
                          {float(points[i].x()), float(points[i].y())}, 0.02f * h);
    }
    doc.endHide();
    QImage image = shade(doc, scene.view, &before);
    drawPath(image, points, scene.pointer);
    return image;
}

/**
 * Turned about a point on the second body: that point stays where it was. None if the turned
 * view's layers cannot be built.
 */
std::optional<QImage> drawOrbitAboutPoint(GuideScene& scene) {
    core::Document& doc = scene.doc;
    const float w = scene.w, h = scene.h;
    const QSize size = scene.size;
    const glm::vec2 at(0.6f * w, 0.5f * h);
    const std::optional<glm::vec3> pivot = doc.surfacePoint(at);
    QImage image;
    if (pivot) {
        doc.camera().orbitAbout(*pivot, -40.0f, 10.0f);
        const core::View turned = doc.camera().view(size.width(), size.height());
        doc.clearDepthLayers();
        scene.capturer.setMesh(doc.mesh());
        if (!doc.buildDepthLayers(scene.capturer, turned))
            return std::nullopt;
        image = shade(doc, turned);
    } else {
        image = shade(doc, scene.view);
    }
    // The pivot where the turned view shows it, and the turn around it.
    QPointF shown(at.x, at.y);
    if (pivot) {
        const core::View turned = doc.camera().view(size.width(), size.height());
        const glm::vec4 clip = turned.proj * turned.view * glm::vec4(*pivot, 1.0f);
        if (clip.w > 0.0f)
            shown = QPointF((clip.x / clip.w * 0.5 + 0.5) * w, (0.5 - clip.y / clip.w * 0.5) * h);
    }
    drawClick(image, shown, QColor(230, 120, 0));
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(QColor(230, 120, 0), 1.5));
    painter.drawArc(QRectF(shown.x() - 18.0, shown.y() - 10.0, 36.0, 20.0), 20 * 16, 300 * 16);
    return image;
}

/** One picture of the guide, drawn on a freshly reset scene; none if its layers failed. */
std::optional<QImage> drawPicture(GuideScene& scene, GuidePicture picture) {
    switch (picture) {
    case GuidePicture::LayerAwareStroke:
        return drawLayerAwareStroke(scene);
    case GuidePicture::PopUp:
        return drawPopUp(scene);
    case GuidePicture::PaintToHide:
        return drawPaintToHide(scene);
    case GuidePicture::OrbitAboutPoint:
        return drawOrbitAboutPoint(scene);
    case GuidePicture::Count:
        break;
    }
    return QImage();
}

} // namespace

std::vector<QImage> makeQuickGuidePictures(QSize size, const core::ProgressFn& progress) {
    const int count = int(GuidePicture::Count);
    std::vector<QImage> pictures;
    GuideScene scene;
    scene.size = size;
    if (!loadRow(scene))
        return pictures;
    for (int k = 0; k < count; ++k) {
        if (!core::reportProgress(progress, double(k) / double(count)))
            return {};
        if (!resetScene(scene))
            return {};
        std::optional<QImage> image = drawPicture(scene, GuidePicture(k));
        if (!image)
            return {};
        pictures.push_back(std::move(*image));
    }
    core::reportProgress(progress, 1.0);
    return pictures;
}

} // namespace ui
