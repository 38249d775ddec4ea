// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <vector>

#include <QRectF>
#include <QWidget>

#include "core/regions/region_graph_layout.h"
#include "core/regions/segmentation.h"

class QCheckBox;
class QGraphicsItem;
class QGraphicsScene;
class QGraphicsSimpleTextItem;
class QGraphicsView;
class QLabel;
class QSpinBox;
class QToolButton;

namespace core {
struct DepthLayers;
}

namespace ui {

class RegionGraphItem;

/**
 * The region graph (the paper's Figure 3, right), drawn from core::layoutRegionGraph(): one
 * column per depth layer, a node per region in its segmentation-map colour and sized by its
 * pixels, an edge per cross-layer connection, wider for more pixel links; a layer's small
 * regions share one grey node. The wheel zooms about the pointer, dragging the background pans,
 * Fit (the button, or F / Home while the graph has the focus) shows it whole; labels keep their
 * size at any zoom. A filter hides regions under a number of pixels, or shows only the selected
 * region (the last one clicked) and its neighbours. Hovering a node emits regionHovered(),
 * clicking it regionActivated().
 */
class RegionGraphPanel : public QWidget {
    Q_OBJECT

public:
    /** Regions of one layer drawn as nodes of their own; the rest are merged. */
    static constexpr int kMaxNodesPerLayer = 24;
    /** How far the wheel zooms in, relative to the whole graph in view. */
    static constexpr double kMaxZoomIn = 40.0;

    explicit RegionGraphPanel(QWidget* parent = nullptr);
    ~RegionGraphPanel() override;

    /**
     * Shows the region graph of layers. nullptr means it is out of date (the view moves): the
     * old graph stays, dimmed and inert, until the next call.
     */
    void setDepthLayers(const core::DepthLayers* layers);

    /** Regions and connections of the graph (all of them, shown, merged or filtered out). */
    int regionCount() const { return m_regionCount; }
    int connectionCount() const { return m_connectionCount; }
    /** Regions left out by the filter. */
    int hiddenRegionCount() const { return int(m_layout.hiddenRegions); }
    /** The region drawn as selected, or core::kNone. */
    std::uint32_t selectedRegion() const { return m_selected; }
    /** The layout drawn. */
    const core::RegionGraphLayout& layout() const { return m_layout; }

    /** Regions under this many pixels are not drawn (0 draws all). */
    void setMinimumPixels(std::uint32_t pixels);
    std::uint32_t minimumPixels() const { return m_options.minPixels; }
    /** Draws only the selected region and its neighbours (all while none is selected). */
    void setNeighbourhoodOnly(bool on);
    bool neighbourhoodOnly() const { return m_neighbourhood; }

    /** The view's scale over the scale that shows the whole graph (1 after fitGraph()). */
    double zoom() const;

    QGraphicsView* graphicsView() const { return m_view; }

public slots:
    /** Shows the whole graph. */
    void fitGraph();

signals:
    /** The pointer entered a region's node; core::kNone when it left. */
    void regionHovered(std::uint32_t region);
    /** A region's node was clicked. */
    void regionActivated(std::uint32_t region);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    friend class RegionGraphItem;

    void nodeHovered(RegionGraphItem* node, bool entered);
    void nodeClicked(RegionGraphItem* node);
    /** Column spacing that gives the graph the view's aspect ratio. */
    double columnSpacing() const;
    /** Lays the graph out again with the current filter, then draws it. */
    void relayout();
    void buildScene();
    /** The scale at which the whole scene fits the view. */
    double fitScale() const;
    void zoomBy(double factor, QPointF anchor);
    void updateSummary();
    void setStale(bool stale);

    core::RegionGraph m_graph;
    int m_imageHeight = 1;
    core::RegionGraphLayoutOptions m_options;
    bool m_neighbourhood = false;
    core::RegionGraphLayout m_layout;
    bool m_haveGraph = false;
    double m_spacing = 0.0; // of the scene shown
    QRectF m_graphRect;     // the graph with its labels, in scene units
    bool m_zoomed = false;  // the artist zoomed or panned: resizing keeps that

    QLabel* m_summary = nullptr;
    QToolButton* m_fitButton = nullptr;
    QSpinBox* m_minPixels = nullptr;
    QCheckBox* m_neighbourhoodBox = nullptr;
    QGraphicsView* m_view = nullptr;
    QGraphicsScene* m_scene = nullptr;
    std::vector<RegionGraphItem*> m_nodes;
    std::vector<QGraphicsSimpleTextItem*> m_headers; // the layer of each in data(1)
    std::vector<QGraphicsItem*> m_countLabels;       // the "+N" of merged nodes
    int m_regionCount = 0;
    int m_connectionCount = 0;
    std::uint32_t m_selected;
    std::uint32_t m_hovered;
    bool m_stale = false;
};

} // namespace ui
