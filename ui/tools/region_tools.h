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
class QUndoStack;

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
 * Every change of the order is an OrderCommand on the undo stack; the Paint-to-Hide panel and
 * the viewport follow the document's order.
 */
class RegionTools : public QObject {
    Q_OBJECT

public:
    /**
     * ensureLayers builds the current view's layers if they are missing (false if it could not);
     * undoSuspended is the window's flag for rebuilding the undo stack.
     */
    RegionTools(core::Document& document, Viewport& viewport, QUndoStack& undoStack,
                const bool& undoSuspended, std::function<bool()> ensureLayers,
                QObject* parent = nullptr);

    /** The Paint-to-Hide panel (owned by parent). */
    HiddenRegionsPanel* createPanel(QWidget* parent);

    QAction* autoPopUpAction() const { return m_autoPopUp; }
    QAction* transparencyAction() const { return m_transparency; }
    QAction* orbitAboutSurfaceAction() const { return m_orbitAboutSurface; }
    QAction* resetOrderAction() const { return m_resetOrder; }
    QAction* unhideAllAction() const { return m_unhideAll; }

    /** Intentional pop-up at a window pixel (device pixels): the pop-up tool or Shift+click. */
    void popUpAt(QPointF pixel);
    /** Intentional pop-up of a region (a click in the region graph). */
    void popUpRegion(std::uint32_t region);

    /** Paint-to-hide: a stroke of the hide tool, brush radius in device pixels. */
    void beginHide(QPointF pixel, float radius);
    void moveHide(QPointF pixel);
    void endHide();
    bool isHiding() const { return m_hideRanks.has_value(); }

    /** A paint stroke starts / ended: pop-ups it made become one undo step, pushed at the end. */
    void beginStroke();
    void endStroke();
    /** Call while a stroke's dabs may have popped regions up: redraws with the new order. */
    void strokeMoved();

    /** The layers were built or re-segmented (a fresh order) or dropped. */
    void layersChanged();

signals:
    void message(const QString& text);

private:
    /** Pushes an OrderCommand for the change from before to the document's order. */
    void pushChange(core::RegionOrder before, const QString& text);
    void setOrder(core::RegionOrder order, const QString& text);
    /** The viewport and the panel show the document's order. */
    void orderApplied();

    core::Document& m_document;
    Viewport& m_viewport;
    QUndoStack& m_undoStack;
    const bool& m_undoSuspended;
    std::function<bool()> m_ensureLayers;
    HiddenRegionsPanel* m_panel = nullptr;
    QAction* m_autoPopUp = nullptr;
    QAction* m_transparency = nullptr;
    QAction* m_orbitAboutSurface = nullptr;
    QAction* m_resetOrder = nullptr;
    QAction* m_unhideAll = nullptr;

    // The stroke in progress: the order at its start, and the hide stroke's ranks and last point.
    std::optional<core::RegionOrder> m_strokeBefore;
    std::uint64_t m_strokeOrderSerial = 0;
    std::optional<std::vector<std::uint32_t>> m_hideRanks;
    core::RegionOrder m_hideBefore;
    QPointF m_hideLast;
    float m_hideRadius = 0.0f;
};

} // namespace ui
