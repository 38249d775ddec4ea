// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <QObject>
#include <QPointF>
#include <QString>

#include "core/regions/region_order.h"

class QAction;

namespace core {
class Document;
}

namespace ui {

class HiddenRegionsPanel;
class Viewport;

/**
 * The paper's region operations in the window: intentional pop-up (a click cycles through the
 * regions at a pixel), pop-up from the region graph, automatic pop-up while painting,
 * paint-to-hide, unhide, reset of the order, see-through pop-ups and layer-aware rotation.
 * Every change of the order is a step of the document's history; the Paint-to-Hide panel and
 * the viewport follow the document's order.
 */
class RegionTools : public QObject {
    Q_OBJECT

public:
    /**
     * ensureDepthLayers builds the current view's layers if they are missing (false if it could
     * not). Every change is an undo step of the document.
     */
    RegionTools(core::Document& document, Viewport& viewport,
                std::function<bool()> ensureDepthLayers, QObject* parent = nullptr);

    /** The Paint-to-Hide panel (owned by parent). */
    HiddenRegionsPanel* createPanel(QWidget* parent);

    QAction* autoPopUpAction() const { return m_autoPopUp; }
    QAction* transparencyAction() const { return m_transparency; }
    QAction* orbitAboutSurfaceAction() const { return m_orbitAboutSurface; }
    QAction* resetOrderAction() const { return m_resetOrder; }
    QAction* unhideAllAction() const { return m_unhideAll; }

    /** Intentional pop-up at a window pixel (device pixels): the pop-up tool or Ctrl+Shift+click.
     */
    void popUpAt(QPointF pixel);
    /** Intentional pop-up of a region (a click in the region graph). */
    void popUpRegion(std::uint32_t region);

    /** Paint-to-hide: a stroke of the hide tool, brush radius in device pixels. */
    void beginHide(QPointF pixel, float radius);
    void moveHide(QPointF pixel);
    void endHide();
    bool isHiding() const;

    /** A paint stroke starts / ended (its pop-ups are part of the stroke's undo step). */
    void beginStroke();
    void endStroke();
    /** Call while a stroke's dabs may have popped regions up: redraws with the new order. */
    void strokeMoved();
    /** The viewport and the panel show the document's order (after undo/redo too). */
    void orderApplied();

    /** The layers were built or re-segmented (a fresh order) or dropped. */
    void layersChanged();

signals:
    void message(const QString& text);

private:
    /** After a recorded change: redraw and tell. */
    void changed();

    core::Document& m_document;
    Viewport& m_viewport;
    std::function<bool()> m_ensureDepthLayers;
    HiddenRegionsPanel* m_panel = nullptr;
    QAction* m_autoPopUp = nullptr;
    QAction* m_transparency = nullptr;
    QAction* m_orbitAboutSurface = nullptr;
    QAction* m_resetOrder = nullptr;
    QAction* m_unhideAll = nullptr;

    // The stroke in progress: whether one is, the order it drew last; the hide stroke's last point.
    bool m_inStroke = false;
    std::uint64_t m_strokeOrderSerial = 0;
    QPointF m_hideLast;
    float m_hideRadius = 0.0f;
};

} // namespace ui
