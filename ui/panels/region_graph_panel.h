// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <QWidget>

class QGraphicsScene;
class QGraphicsView;
class QLabel;

namespace core {
struct Layers;
}

namespace ui {

class RegionGraphItem;

/**
 * The region graph (the paper's Figure 3, right): one column per depth layer, a node per region
 * in its segmentation-map colour and sized by its pixels, an edge per cross-layer connection,
 * wider for more pixel links. Within a column nodes follow the regions' height in the view,
 * nudged towards their neighbours, so most edges run level. The largest regions of a layer get
 * their own node; the rest of the layer share one grey node. Hovering a node emits
 * regionHovered(), clicking it regionActivated().
 */
class RegionGraphPanel : public QWidget {
    Q_OBJECT

public:
    /** Regions of one layer drawn as nodes of their own; the rest are merged. */
    static constexpr int kMaxNodesPerLayer = 24;

    explicit RegionGraphPanel(QWidget* parent = nullptr);
    ~RegionGraphPanel() override;

    /**
     * Shows the region graph of layers. nullptr means it is out of date (the view moves): the
     * old graph stays, dimmed and inert, until the next call.
     */
    void setLayers(const core::Layers* layers);

    /** Regions and connections of the graph shown (all of them, merged or not). */
    int regionCount() const { return m_regionCount; }
    int connectionCount() const { return m_connectionCount; }
    /** The region drawn as selected, or core::kNone. */
    std::uint32_t selectedRegion() const { return m_selected; }

    QGraphicsView* graphicsView() const { return m_view; }

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
    struct Layout;

    void nodeHovered(RegionGraphItem* node, bool entered);
    void nodeClicked(RegionGraphItem* node);
    /** Column spacing that gives the graph the view's aspect ratio. */
    double columnSpacing() const;
    void buildScene();
    void fitGraph();
    void setStale(bool stale);

    std::unique_ptr<Layout> m_layout;
    double m_spacing = 0.0; // of the scene shown

    QLabel* m_summary = nullptr;
    QGraphicsView* m_view = nullptr;
    QGraphicsScene* m_scene = nullptr;
    std::vector<RegionGraphItem*> m_nodes;
    int m_regionCount = 0;
    int m_connectionCount = 0;
    std::uint32_t m_selected;
    std::uint32_t m_hovered;
    bool m_stale = false;
};

} // namespace ui
