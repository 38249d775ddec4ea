// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/paint_layer_thumbnails.h"

#include <QPainter>
#include <QPainterPath>
#include <QPalette>

#include <algorithm>
#include <utility>

namespace ui {

namespace {

QImage checkerboard(int size) {
    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    const int cell = std::max(2, size / 8);
    for (int y = 0; y < size; ++y) {
        auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
        for (int x = 0; x < size; ++x)
            line[x] = ((x / cell + y / cell) % 2) ? qRgb(204, 204, 204) : qRgb(250, 250, 250);
    }
    return image;
}

/** The texel of a page under thumbnail pixel (i, j). */
QPoint texelOf(const core::PageSize& page, int i, int j, int size) {
    return {std::min(page.width - 1, int((i + 0.5) * page.width / size)),
            std::min(page.height - 1, int((j + 0.5) * page.height / size))};
}

/** Draws color with coverage alpha (0..255) over the thumbnail pixel (i, j). */
void over(QImage& image, int i, int j, QColor color, int alpha) {
    QRgb& pixel = reinterpret_cast<QRgb*>(image.scanLine(j))[i];
    const auto mix = [alpha](int below, int above) {
        return (below * (255 - alpha) + above * alpha + 127) / 255;
    };
    pixel = qRgb(mix(qRed(pixel), color.red()), mix(qGreen(pixel), color.green()),
                 mix(qBlue(pixel), color.blue()));
}

/** A plane's written texels of page p over the image: colour from the value bytes, alpha the
 * coverage. */
void drawPlane(QImage& image, const core::TiledPlane& plane, int size, bool coverage,
               std::uint32_t p) {
    if (p >= plane.pages().size() || !plane.anyTile(p))
        return;
    const core::PageSize page = plane.pages()[p];
    const int bytes = plane.texelBytes();
    for (int j = 0; j < size; ++j) {
        for (int i = 0; i < size; ++i) {
            const QPoint t = texelOf(page, i, j, size);
            const std::uint32_t tile = plane.tileAt(p, t.x(), t.y());
            const std::uint8_t* texels = plane.tile(p, tile);
            if (!texels)
                continue; // never painted: the fill value
            const core::TileRect rect = plane.tileRect(p, tile);
            const std::uint8_t* texel =
                texels + (std::size_t(t.y() - rect.y) * std::size_t(rect.width) +
                          std::size_t(t.x() - rect.x)) *
                             std::size_t(bytes);
            const QColor color = bytes >= 4 ? QColor(texel[0], texel[1], texel[2])
                                            : QColor(texel[0], texel[0], texel[0]);
            over(image, i, j, color, coverage ? texel[bytes - 1] : 255);
        }
    }
}

void frame(QImage& image, const QColor& color, int width) {
    QPainter painter(&image);
    painter.setPen(QPen(color, width));
    painter.setBrush(Qt::NoBrush);
    const qreal half = width / 2.0;
    painter.drawRect(QRectF(half, half, image.width() - width, image.height() - width));
}

/** The width of the frame around the thumbnail strokes paint. */
constexpr int kTargetFrame = 3;

/** The side of a thumbnail's picture: inside the frame of the one strokes paint. */
int pictureSide(int size, bool painted) {
    return painted ? std::max(1, size - 2 * kTargetFrame) : size;
}

/**
 * picture framed: for the thumbnail strokes paint (painted), a size² image with the picture
 * inside an amber frame with a dark inner line, which stands out on any picture and on the
 * selected row's highlight alike; else the picture with a thin grey frame.
 */
QImage framed(QImage picture, int size, bool painted) {
    if (!painted) {
        frame(picture, QColor(128, 128, 128), 1);
        return picture;
    }
    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    image.fill(QColor(255, 153, 0));
    QPainter painter(&image);
    painter.drawImage(kTargetFrame, kTargetFrame, picture);
    painter.setPen(QPen(QColor(40, 40, 40), 1));
    painter.setBrush(Qt::NoBrush);
    painter.drawRect(
        QRectF(kTargetFrame - 0.5, kTargetFrame - 0.5, picture.width() + 1, picture.height() + 1));
    return image;
}

QColor grey(float value) {
    const int v = std::clamp(int(value * 255.0f + 0.5f), 0, 255);
    return {v, v, v};
}

} // namespace

QImage layerThumbnail(const core::PaintLayer& layer, int size, bool painted, std::uint32_t page) {
    const int side = pictureSide(size, painted);
    QImage image = checkerboard(side);
    const core::PaintLayerSettings& settings = layer.settings;
    if (settings.kind == core::PaintLayerKind::Fill) {
        QColor color(128, 128, 128);
        if (const auto& c = settings.fill.baseColor)
            color = QColor::fromRgbF(std::clamp(c->x, 0.0f, 1.0f), std::clamp(c->y, 0.0f, 1.0f),
                                     std::clamp(c->z, 0.0f, 1.0f));
        else if (settings.fill.roughness)
            color = grey(*settings.fill.roughness);
        else if (settings.fill.metallic)
            color = grey(*settings.fill.metallic);
        image.fill(color);
    }
    // The base colour where it was painted, else the first material channel that was.
    for (const auto& plane : layer.channels) {
        if (plane && page < plane->pages().size() && plane->anyTile(page)) {
            drawPlane(image, *plane, side, true, page);
            break;
        }
    }
    return framed(std::move(image), size, painted);
}

QImage baseThumbnail(const core::PaintLayerStack& stack, int size, std::uint32_t p) {
    QImage image = checkerboard(size);
    if (p < stack.pages().size()) {
        const core::PageSize page = stack.pages()[p];
        const std::vector<std::uint8_t>& texels = stack.baseColor(p);
        if (page.width > 0 && page.height > 0 &&
            texels.size() >= std::size_t(page.width) * std::size_t(page.height) * 4) {
            for (int j = 0; j < size; ++j) {
                for (int i = 0; i < size; ++i) {
                    const QPoint t = texelOf(page, i, j, size);
                    const std::uint8_t* texel =
                        texels.data() +
                        (std::size_t(t.y()) * std::size_t(page.width) + std::size_t(t.x())) * 4;
                    over(image, i, j, QColor(texel[0], texel[1], texel[2]), texel[3]);
                }
            }
        }
    }
    frame(image, QColor(128, 128, 128), 1);
    return image;
}

QImage maskThumbnail(const core::TiledPlane& mask, int size, bool painted, std::uint32_t page) {
    const int side = pictureSide(size, painted);
    QImage image(side, side, QImage::Format_ARGB32_Premultiplied);
    image.fill(QColor(mask.fill()[0], mask.fill()[0], mask.fill()[0]));
    drawPlane(image, mask, side, false, page);
    return framed(std::move(image), size, painted);
}

QImage eyeIcon(bool visible, int size) {
    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    QColor ink = QPalette().color(QPalette::WindowText);
    if (!visible)
        ink.setAlpha(90);
    const qreal s = size;
    QPainterPath lid;
    lid.moveTo(0.08 * s, 0.5 * s);
    lid.quadTo(0.5 * s, visible ? 0.05 * s : 0.8 * s, 0.92 * s, 0.5 * s);
    if (visible)
        lid.quadTo(0.5 * s, 0.95 * s, 0.08 * s, 0.5 * s);
    painter.setPen(QPen(ink, std::max(1.0, s / 12.0)));
    painter.setBrush(Qt::NoBrush);
    painter.drawPath(lid);
    if (visible) {
        painter.setBrush(ink);
        painter.drawEllipse(QPointF(0.5 * s, 0.5 * s), 0.13 * s, 0.13 * s);
    }
    return image;
}

} // namespace ui
