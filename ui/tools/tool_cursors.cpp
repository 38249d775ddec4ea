// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/tools/tool_cursors.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>

namespace ui {

namespace {

/** Strokes path white and wide, then dark on top: readable on any background. */
void strokeOutlined(QPainter& painter, const QPainterPath& path, const QColor& fill) {
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(Qt::white, 3.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.drawPath(path);
    painter.setPen(QPen(QColor(20, 20, 20), 1.2, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter.setBrush(fill);
    painter.drawPath(path);
}

/** A dot in a ring: the centre of the brush outline, which shows the size. */
QCursor centreMarkCursor() {
    QPixmap pixmap(11, 11);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(Qt::white, 3.0));
    painter.drawEllipse(QPointF(5.5, 5.5), 2.5, 2.5);
    painter.setPen(QPen(QColor(20, 20, 20), 1.2));
    painter.drawEllipse(QPointF(5.5, 5.5), 2.5, 2.5);
    painter.end();
    return QCursor(pixmap, 5, 5);
}

/** A tipped paint bucket pouring a drop; the hot spot is the drop's tip. */
QCursor fillBucketCursor() {
    QPixmap pixmap(32, 32);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);

    // The bucket, tipped to the left: a tapered body under a handle.
    painter.save();
    painter.translate(18.0, 14.0);
    painter.rotate(-35.0);
    QPainterPath body;
    body.moveTo(-7.0, -6.0);
    body.lineTo(7.0, -6.0);
    body.lineTo(5.5, 8.0);
    body.lineTo(-5.5, 8.0);
    body.closeSubpath();
    strokeOutlined(painter, body, QColor(235, 235, 235));
    QPainterPath handle;
    handle.moveTo(-6.0, -6.0);
    handle.cubicTo(-6.0, -14.0, 6.0, -14.0, 6.0, -6.0);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(Qt::white, 3.0, Qt::SolidLine, Qt::RoundCap));
    painter.drawPath(handle);
    painter.setPen(QPen(QColor(20, 20, 20), 1.2, Qt::SolidLine, Qt::RoundCap));
    painter.drawPath(handle);
    // The paint at the rim.
    QPainterPath paint;
    paint.addEllipse(QPointF(0.0, -6.0), 7.0, 2.2);
    strokeOutlined(painter, paint, QColor(40, 110, 220));
    painter.restore();

    // The drop falling from the rim, its tip where the fill starts.
    QPainterPath drop;
    drop.moveTo(5.0, 29.0);
    drop.cubicTo(1.0, 29.0, 1.0, 24.0, 5.0, 18.0);
    drop.cubicTo(9.0, 24.0, 9.0, 29.0, 5.0, 29.0);
    strokeOutlined(painter, drop, QColor(40, 110, 220));
    painter.end();
    return QCursor(pixmap, 5, 29);
}

} // namespace

QCursor toolCursor(Tool tool) {
    switch (tool) {
    case Tool::Brush:
    case Tool::Eraser:
    case Tool::Hide: {
        static const QCursor mark = centreMarkCursor();
        return mark;
    }
    case Tool::Fill: {
        static const QCursor bucket = fillBucketCursor();
        return bucket;
    }
    case Tool::Eyedropper:
        return QCursor(Qt::CrossCursor);
    case Tool::PopUp:
        return QCursor(Qt::PointingHandCursor);
    }
    return QCursor(Qt::ArrowCursor);
}

bool toolShowsBrushOutline(Tool tool) {
    return tool == Tool::Brush || tool == Tool::Eraser || tool == Tool::Hide;
}

} // namespace ui
