// SPDX-License-Identifier: GPL-3.0-or-later
// The quick guide's pictures: the operations the guide explains, done by core::Document on the
// built-in row and shaded on the CPU, with the pointer's path drawn over them.
#include "ui/shell/quick_guide_pictures.h"

#include <algorithm>
#include <cmath>
#include <optional>

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

/** The visible surface of doc's layers, lit from the camera, over a light background. */
QImage shade(core::Document& doc, const core::View& view) {
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
            const glm::vec4 color = doc.pickColor(pixel).value_or(glm::vec4(0.7f));
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

} // namespace

std::vector<QImage> makeQuickGuidePictures(QSize size, const core::ProgressFn& progress) {
    const int count = int(GuidePicture::Count);
    std::vector<QImage> pictures;
    core::Result<core::Mesh> mesh = core::makeBuiltinModel("row");
    if (!mesh)
        return pictures;
    core::Document doc;
    doc.setMesh(std::move(mesh).value(), "row");
    doc.setViewAspect(float(size.width()) / float(size.height()));
    doc.resetCamera();
    doc.camera().yawDegrees = 35.0f;
    doc.camera().pitchDegrees = 12.0f;
    doc.camera().distance *= 0.5f; // the row, not the room around it
    const float distance = doc.camera().distance;
    const core::View view = doc.camera().view(size.width(), size.height());
    core::CpuDepthCapturer capturer;
    const float w = float(size.width()), h = float(size.height());
    const QColor pointer(20, 90, 200);

    for (int k = 0; k < count; ++k) {
        if (!core::reportProgress(progress, double(k) / double(count)))
            return {};
        doc.camera().yawDegrees = 35.0f;
        doc.camera().pitchDegrees = 12.0f;
        doc.camera().distance = distance;
        doc.clearDepthLayers();
        if (!prepare(doc, capturer, view))
            return {};
        doc.resetRegionOrder();
        QImage image;
        switch (GuidePicture(k)) {
        case GuidePicture::LayerAwareStroke: {
            // A stroke from the second body on to the right, behind the first: layer-aware, it
            // stays on the surface it started on.
            doc.setLayerAware(true);
            doc.setAutoPopUp(false);
            doc.brush().radius = 0.03f * h;
            doc.brush().hardness = 0.8f;
            doc.brush().color = {0.85f, 0.12f, 0.08f, 1.0f};
            std::vector<QPointF> points;
            for (int i = 0; i <= 40; ++i) {
                const float t = float(i) / 40.0f;
                points.emplace_back(0.3f * w + t * 0.4f * w,
                                    0.5f * h + 0.08f * h * std::sin(6.0f * t));
            }
            core::PaintChanges changes;
            if (doc.beginStroke({{float(points[0].x()), float(points[0].y())}, 1.0f}, changes)) {
                for (const QPointF& p : points)
                    doc.moveStroke({{float(p.x()), float(p.y())}, 1.0f}, changes);
                doc.endStroke(changes);
            }
            image = shade(doc, view);
            drawPath(image, points, pointer);
            break;
        }
        case GuidePicture::PopUp: {
            const glm::vec2 at(0.5f * w, 0.5f * h);
            doc.popUpAt(at);
            image = shade(doc, view);
            drawClick(image, QPointF(at.x, at.y), pointer);
            break;
        }
        case GuidePicture::PaintToHide: {
            std::vector<QPointF> points;
            doc.beginHide();
            for (int i = 0; i <= 10; ++i) {
                const float t = float(i) / 10.0f;
                points.emplace_back(0.42f * w + 0.08f * w * t, 0.5f * h);
                if (i > 0)
                    doc.hideAlong({float(points[i - 1].x()), float(points[i - 1].y())},
                                  {float(points[i].x()), float(points[i].y())}, 0.02f * h);
            }
            doc.endHide();
            image = shade(doc, view);
            drawPath(image, points, pointer);
            break;
        }
        case GuidePicture::OrbitAboutPoint: {
            // Turned about a point on the second body: that point stays where it was.
            const glm::vec2 at(0.6f * w, 0.5f * h);
            const std::optional<glm::vec3> pivot = doc.surfacePoint(at);
            if (pivot) {
                doc.camera().orbitAbout(*pivot, -40.0f, 10.0f);
                const core::View turned = doc.camera().view(size.width(), size.height());
                doc.clearDepthLayers();
                capturer.setMesh(doc.mesh());
                if (!doc.buildDepthLayers(capturer, turned))
                    return {};
                image = shade(doc, turned);
            } else {
                image = shade(doc, view);
            }
            // The pivot where the turned view shows it, and the turn around it.
            QPointF shown(at.x, at.y);
            if (pivot) {
                const core::View turned = doc.camera().view(size.width(), size.height());
                const glm::vec4 clip = turned.proj * turned.view * glm::vec4(*pivot, 1.0f);
                if (clip.w > 0.0f)
                    shown = QPointF((clip.x / clip.w * 0.5 + 0.5) * w,
                                    (0.5 - clip.y / clip.w * 0.5) * h);
            }
            drawClick(image, shown, QColor(230, 120, 0));
            QPainter painter(&image);
            painter.setRenderHint(QPainter::Antialiasing);
            painter.setPen(QPen(QColor(230, 120, 0), 1.5));
            painter.drawArc(QRectF(shown.x() - 18.0, shown.y() - 10.0, 36.0, 20.0), 20 * 16,
                            300 * 16);
            break;
        }
        case GuidePicture::Count:
            break;
        }
        pictures.push_back(std::move(image));
    }
    core::reportProgress(progress, 1.0);
    return pictures;
}

} // namespace ui
