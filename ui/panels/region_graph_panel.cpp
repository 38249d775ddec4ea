// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/region_graph_panel.h"

#include <QEvent>
#include <QGraphicsEllipseItem>
#include <QGraphicsPathItem>
#include <QGraphicsScene>
#include <QGraphicsSceneHoverEvent>
#include <QGraphicsSceneMouseEvent>
#include <QGraphicsSimpleTextItem>
#include <QGraphicsView>
#include <QLabel>
#include <QLocale>
#include <QPainterPath>
#include <QPen>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/layers/layers.h"
#include "render/layer_compositor.h"

namespace ui {

namespace {
constexpr double kSceneHeight = 320.0; // the view's height maps onto this
constexpr double kNodeGap = 3.0;
constexpr double kMinRadius = 4.0;
constexpr double kMaxRadius = 18.0;
constexpr double kColumnGap = 44.0;
constexpr double kMaxZoom = 2.0;
constexpr int kBarycentricSweeps = 4;
constexpr double kMergedLabelSpace = 14.0; // under a merged node, for its "+N" label

const QColor kBackground(46, 48, 53);
const QColor kText(200, 203, 210);
const QColor kEdge(175, 180, 192, 110);
const QColor kEdgeHighlight(255, 236, 150, 230);
const QColor kOutline(22, 23, 26);
const QColor kSelected(255, 255, 255);
const QColor kHovered(255, 226, 110);
const QColor kMerged(120, 124, 132);

QColor toColor(const glm::vec4& c) {
    return QColor::fromRgbF(std::clamp(c.r, 0.0f, 1.0f), std::clamp(c.g, 0.0f, 1.0f),
                            std::clamp(c.b, 0.0f, 1.0f));
}

/** One drawn node: a region or the merged small regions of one layer. */
struct LayoutNode {
    std::uint32_t region = core::kNone; // kNone: merged
    std::uint32_t layer = 1;
    std::uint32_t members = 1;
    double pixels = 0.0;
    double home = 0.0; // where the view puts it: the regions' height in the picture
    double key = 0.0;  // home nudged towards the neighbours
    double y = 0.0;
    double radius = kMinRadius;
    std::vector<std::pair<int, double>> adjacent; // node, weight

    bool merged() const { return region == core::kNone; }
    /** Room the node needs below its centre. */
    double below() const { return radius + (merged() ? kMergedLabelSpace : 0.0); }
};

/** Places one column's nodes in key order, as near their keys as the sizes allow. */
void packColumn(std::vector<LayoutNode>& nodes, std::vector<int>& column) {
    std::sort(column.begin(), column.end(), [&](int a, int b) {
        return nodes[a].key != nodes[b].key ? nodes[a].key < nodes[b].key : a < b;
    });
    double previousBottom = -1e300;
    for (int index : column) {
        LayoutNode& node = nodes[index];
        node.y = std::max(node.key, previousBottom + kNodeGap + node.radius);
        previousBottom = node.y + node.below();
    }
    // Pushed past the bottom: pull back up as far as the top allows.
    double nextTop = kSceneHeight;
    for (auto it = column.rbegin(); it != column.rend(); ++it) {
        LayoutNode& node = nodes[*it];
        node.y = std::min(node.y, nextTop - kNodeGap - node.below());
        nextTop = node.y - node.radius;
    }
    // A column taller than the scene starts at the top instead.
    if (!column.empty() && nodes[column.front()].y - nodes[column.front()].radius < 0.0) {
        double top = 0.0;
        for (int index : column) {
            LayoutNode& node = nodes[index];
            node.y = std::max(node.y, top + node.radius);
            top = node.y + node.below() + kNodeGap;
        }
    }
}
} // namespace

/** A node of the graph: a region (or merged regions) that reports hover and clicks. */
class RegionGraphItem : public QGraphicsEllipseItem {
public:
    RegionGraphItem(RegionGraphPanel* panel, std::uint32_t region, double radius)
        : QGraphicsEllipseItem(-radius, -radius, 2.0 * radius, 2.0 * radius), m_panel(panel),
          m_region(region) {
        setAcceptHoverEvents(true);
        setAcceptedMouseButtons(Qt::LeftButton);
        setData(0, region == core::kNone ? QVariant() : QVariant(uint(region)));
    }

    std::uint32_t region() const { return m_region; }
    std::vector<QGraphicsPathItem*>& edges() { return m_edges; }

    void setState(bool hovered, bool selected) {
        if (selected)
            setPen(QPen(kSelected, 2.5));
        else if (hovered)
            setPen(QPen(kHovered, 2.5));
        else
            setPen(QPen(kOutline, 1.0));
        setZValue(hovered || selected ? 3.0 : 2.0);
        for (QGraphicsPathItem* edge : m_edges) {
            QPen pen = edge->pen();
            pen.setColor(hovered || selected ? kEdgeHighlight : kEdge);
            edge->setPen(pen);
            edge->setZValue(hovered || selected ? 1.5 : 1.0);
        }
    }

protected:
    void hoverEnterEvent(QGraphicsSceneHoverEvent* event) override {
        m_panel->nodeHovered(this, true);
        QGraphicsEllipseItem::hoverEnterEvent(event);
    }
    void hoverLeaveEvent(QGraphicsSceneHoverEvent* event) override {
        m_panel->nodeHovered(this, false);
        QGraphicsEllipseItem::hoverLeaveEvent(event);
    }
    void mousePressEvent(QGraphicsSceneMouseEvent* event) override {
        event->accept(); // the click happens at the release, on this item
    }
    void mouseReleaseEvent(QGraphicsSceneMouseEvent* event) override {
        if (contains(event->pos()))
            m_panel->nodeClicked(this);
        event->accept();
    }

private:
    RegionGraphPanel* m_panel;
    std::uint32_t m_region;
    std::vector<QGraphicsPathItem*> m_edges;
};

/** What the scene is drawn from: placed nodes and summed edges of one region graph. */
struct RegionGraphPanel::Layout {
    struct Edge {
        int a, b;
        std::uint64_t links;
    };
    std::vector<LayoutNode> nodes;
    std::vector<Edge> edges;
    std::uint32_t layerCount = 0;
    double top = 0.0, bottom = kSceneHeight; // of the nodes
    /** The region's tooltip facts, by node. */
    std::vector<std::uint32_t> regionPixels, regionNeighbors;
};

RegionGraphPanel::RegionGraphPanel(QWidget* parent)
    : QWidget(parent), m_selected(core::kNone), m_hovered(core::kNone) {
    m_summary = new QLabel(tr("No regions yet"), this);
    m_summary->setObjectName(QStringLiteral("regionSummary"));
    m_summary->setWordWrap(true);
    m_summary->setContentsMargins(4, 2, 4, 2);

    m_scene = new QGraphicsScene(this);
    m_scene->setBackgroundBrush(kBackground);
    m_view = new QGraphicsView(m_scene, this);
    m_view->setObjectName(QStringLiteral("regionGraphView"));
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_view->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_view->setFrameShape(QFrame::NoFrame);
    m_view->setMouseTracking(true);
    m_view->viewport()->setMouseTracking(true);
    m_view->setMinimumSize(120, 100);
    m_view->viewport()->installEventFilter(this);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_summary);
    layout->addWidget(m_view, 1);
}

RegionGraphPanel::~RegionGraphPanel() = default;

void RegionGraphPanel::setLayers(const core::Layers* layers) {
    if (!layers) {
        setStale(true);
        return;
    }
    if (m_hovered != core::kNone) {
        m_hovered = core::kNone;
        emit regionHovered(core::kNone);
    }
    m_selected = core::kNone;
    auto layout = std::make_unique<Layout>();

    const core::RegionGraph& graph = layers->segmentation.graph;
    const double imageHeight = std::max(1, layers->stack.height);
    m_regionCount = int(graph.regions.size());
    m_connectionCount = int(graph.neighbors.size() / 2);

    // Nodes: per layer the largest regions, then one node for the rest.
    std::uint32_t layerCount = 0;
    for (const core::Region& region : graph.regions)
        layerCount = std::max(layerCount, region.layer);
    std::vector<std::vector<std::uint32_t>> byLayer(layerCount);
    for (const core::Region& region : graph.regions) {
        if (region.layer >= 1)
            byLayer[region.layer - 1].push_back(region.id);
    }
    std::vector<LayoutNode>& nodes = layout->nodes;
    std::vector<int> nodeOf(graph.regions.size(), -1);
    std::vector<std::vector<int>> columns(layerCount);
    int merged = 0;
    for (std::uint32_t l = 0; l < layerCount; ++l) {
        std::vector<std::uint32_t>& ids = byLayer[l];
        const auto larger = [&](std::uint32_t a, std::uint32_t b) {
            return graph.regions[a].pixels != graph.regions[b].pixels
                       ? graph.regions[a].pixels > graph.regions[b].pixels
                       : a < b;
        };
        const std::size_t own = ids.size() <= std::size_t(kMaxNodesPerLayer)
                                    ? ids.size()
                                    : std::size_t(kMaxNodesPerLayer - 1);
        // Only the largest need an order: a tiny threshold can make 100,000 regions.
        std::partial_sort(ids.begin(), ids.begin() + std::ptrdiff_t(own), ids.end(), larger);
        int shared = -1; // the layer's node for its small regions
        for (std::size_t i = 0; i < ids.size(); ++i) {
            const core::Region& region = graph.regions[ids[i]];
            int index;
            if (i < own) {
                LayoutNode node;
                node.region = region.id;
                node.layer = l + 1;
                nodes.push_back(node);
                index = int(nodes.size() - 1);
                columns[l].push_back(index);
            } else {
                if (shared < 0) {
                    LayoutNode node;
                    node.layer = l + 1;
                    node.members = 0;
                    nodes.push_back(node);
                    shared = int(nodes.size() - 1);
                    columns[l].push_back(shared);
                }
                index = shared;
                ++nodes[index].members;
                ++merged;
            }
            nodeOf[region.id] = index;
            // Pixel-weighted sums, divided below.
            const double centre = 0.5 * (region.minY + region.maxY + 1) / imageHeight;
            nodes[index].home += centre * kSceneHeight * region.pixels;
            nodes[index].pixels += region.pixels;
        }
    }
    double maxPixels = 1.0;
    double lowest = kSceneHeight, highest = 0.0;
    for (LayoutNode& node : nodes) {
        node.home = node.pixels > 0.0 ? node.home / node.pixels : kSceneHeight / 2.0;
        if (!node.merged()) {
            lowest = std::min(lowest, node.home);
            highest = std::max(highest, node.home);
        }
        maxPixels = std::max(maxPixels, node.pixels);
    }
    // Spread the heights the regions actually use over the scene, keeping their order. A
    // layer's merged small regions always sit at the bottom of its column.
    for (LayoutNode& node : nodes) {
        if (node.merged())
            node.home = 2.0 * kSceneHeight;
        else if (highest - lowest > 1.0)
            node.home = kSceneHeight * (0.1 + 0.8 * (node.home - lowest) / (highest - lowest));
        else
            node.home = kSceneHeight / 2.0;
        node.key = node.home;
    }
    for (LayoutNode& node : nodes) {
        node.radius = kMinRadius + (kMaxRadius - kMinRadius) * std::sqrt(node.pixels / maxPixels);
        if (node.merged())
            node.radius = std::max(node.radius, 7.0);
    }

    // Edges between nodes, links summed over merged regions.
    std::unordered_map<std::uint64_t, std::uint64_t> edgeLinks;
    for (const core::Region& region : graph.regions) {
        for (const core::RegionLink& link : graph.neighborsOf(region.id)) {
            if (link.region <= region.id || link.region >= nodeOf.size())
                continue;
            const int a = nodeOf[region.id];
            const int b = nodeOf[link.region];
            if (a < 0 || b < 0 || a == b)
                continue;
            const auto key = (std::uint64_t(std::min(a, b)) << 32) | std::uint64_t(std::max(a, b));
            edgeLinks[key] += link.links;
        }
    }
    using Edge = Layout::Edge;
    std::vector<Edge>& edges = layout->edges;
    edges.reserve(edgeLinks.size());
    for (const auto& [key, links] : edgeLinks)
        edges.push_back({int(key >> 32), int(key & 0xffffffffu), links});
    std::sort(edges.begin(), edges.end(),
              [](const Edge& x, const Edge& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
    for (const Edge& edge : edges) {
        const double weight = 1.0 + std::log10(double(edge.links));
        nodes[edge.a].adjacent.emplace_back(edge.b, weight);
        nodes[edge.b].adjacent.emplace_back(edge.a, weight);
    }

    // Layout: columns by layer; in a column by height in the view, pulled towards neighbours.
    for (std::vector<int>& column : columns)
        packColumn(nodes, column);
    for (int sweep = 0; sweep < kBarycentricSweeps; ++sweep) {
        for (std::size_t i = 0; i < columns.size(); ++i) {
            std::vector<int>& column = columns[sweep % 2 == 0 ? i : columns.size() - 1 - i];
            for (int index : column) {
                LayoutNode& node = nodes[index];
                if (node.merged())
                    continue;
                double sum = 0.0, weights = 0.0;
                for (const auto& [other, weight] : node.adjacent) {
                    sum += nodes[other].y * weight;
                    weights += weight;
                }
                node.key = weights > 0.0 ? 0.5 * node.home + 0.5 * sum / weights : node.home;
            }
            packColumn(nodes, column);
        }
    }

    layout->layerCount = layerCount;
    layout->top = nodes.empty() ? 0.0 : 1e300;
    layout->bottom = nodes.empty() ? kSceneHeight : -1e300;
    for (const LayoutNode& node : nodes) {
        layout->top = std::min(layout->top, node.y - node.radius);
        layout->bottom = std::max(layout->bottom, node.y + node.below());
        const bool own = !node.merged();
        layout->regionPixels.push_back(own ? graph.regions[node.region].pixels
                                           : std::uint32_t(node.pixels));
        layout->regionNeighbors.push_back(own ? std::uint32_t(graph.neighborsOf(node.region).size())
                                              : 0u);
    }
    m_layout = std::move(layout);

    if (graph.regions.empty()) {
        m_summary->setText(tr("No regions in this view"));
    } else {
        QString text = tr("Regions: %1, connections: %2")
                           .arg(QLocale().toString(m_regionCount))
                           .arg(QLocale().toString(m_connectionCount));
        if (merged > 0)
            text += QLatin1Char('\n') +
                    tr("Small regions merged into grey nodes: %1").arg(QLocale().toString(merged));
        m_summary->setText(text);
    }
    buildScene();
    setStale(false);
}

double RegionGraphPanel::columnSpacing() const {
    const double minimum = 2.0 * kMaxRadius + kColumnGap;
    if (!m_layout || m_layout->layerCount < 2)
        return minimum;
    const QSize size = m_view->viewport()->size();
    const double aspect = size.height() > 0 ? double(size.width()) / size.height() : 1.0;
    const double height = m_layout->bottom - m_layout->top + 40.0; // with the headers
    const double spacing = (aspect * height - 2.0 * kMaxRadius - 16.0) / (m_layout->layerCount - 1);
    return std::clamp(spacing, minimum, 4.0 * minimum);
}

void RegionGraphPanel::buildScene() {
    if (m_hovered != core::kNone) {
        m_hovered = core::kNone;
        emit regionHovered(core::kNone);
    }
    m_nodes.clear();
    m_scene->clear();
    if (!m_layout)
        return;
    const std::vector<LayoutNode>& nodes = m_layout->nodes;
    const std::vector<Layout::Edge>& edges = m_layout->edges;
    const std::uint32_t layerCount = m_layout->layerCount;
    const double top = m_layout->top;
    const double bottom = m_layout->bottom;

    m_spacing = columnSpacing();
    const double spacing = m_spacing;
    const auto columnX = [&](std::uint32_t layer) { return (double(layer) - 1.0) * spacing; };

    // Scene: guides and headers, edges, nodes.
    QFont small = font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() * 0.85));
    for (std::uint32_t layer = 1; layer <= layerCount; ++layer) {
        const double x = columnX(layer);
        m_scene->addLine(x, top - 6.0, x, bottom + 6.0, QPen(QColor(255, 255, 255, 22), 1.0))
            ->setZValue(0.0);
        auto* header = m_scene->addSimpleText(tr("Layer %1").arg(layer), small);
        header->setBrush(kText);
        const QRectF box = header->boundingRect();
        header->setPos(x - box.width() / 2.0, top - 10.0 - box.height());
    }

    std::vector<RegionGraphItem*> items(nodes.size(), nullptr);
    const QLocale locale;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const LayoutNode& node = nodes[i];
        auto* item = new RegionGraphItem(this, node.region, node.radius);
        item->setPos(columnX(node.layer), node.y);
        item->setZValue(2.0);
        if (node.region == core::kNone) {
            item->setBrush(kMerged);
            item->setToolTip(tr("%1 small regions of layer %2\n%3 pixels together")
                                 .arg(locale.toString(node.members))
                                 .arg(node.layer)
                                 .arg(locale.toString(qulonglong(node.pixels))));
            auto* label = new QGraphicsSimpleTextItem(
                tr("+%1").arg(locale.toString(qulonglong(node.members))), item);
            label->setFont(small);
            label->setBrush(kText);
            const QRectF box = label->boundingRect();
            label->setPos(-box.width() / 2.0, node.radius + 1.0);
        } else {
            item->setBrush(toColor(render::regionColor(node.region)));
            item->setToolTip(tr("Region %1 on layer %2\n%3 pixels\nConnected regions: %4")
                                 .arg(node.region)
                                 .arg(node.layer)
                                 .arg(locale.toString(qulonglong(m_layout->regionPixels[i])))
                                 .arg(m_layout->regionNeighbors[i]));
        }
        item->setState(false, node.region != core::kNone && node.region == m_selected);
        m_scene->addItem(item);
        items[i] = item;
        m_nodes.push_back(item);
    }
    for (const Layout::Edge& edge : edges) {
        const LayoutNode& a = nodes[edge.a];
        const LayoutNode& b = nodes[edge.b];
        const QPointF from(columnX(a.layer), a.y);
        const QPointF to(columnX(b.layer), b.y);
        const double bend = (to.x() - from.x()) * 0.5;
        QPainterPath path(from);
        path.cubicTo(from + QPointF(bend, 0.0), to - QPointF(bend, 0.0), to);
        const double width = std::min(7.0, 0.8 + 1.2 * std::log10(double(edge.links)));
        QPen pen(kEdge, width);
        pen.setCapStyle(Qt::RoundCap);
        QGraphicsPathItem* item = m_scene->addPath(path, pen);
        item->setZValue(1.0);
        item->setToolTip(tr("%1 pixel links").arg(locale.toString(qulonglong(edge.links))));
        items[edge.a]->edges().push_back(item);
        items[edge.b]->edges().push_back(item);
    }

    const QRectF bounds = m_scene->itemsBoundingRect().adjusted(-8.0, -8.0, 8.0, 8.0);
    m_scene->setSceneRect(bounds);
    fitGraph();
}

void RegionGraphPanel::setStale(bool stale) {
    m_stale = stale;
    m_scene->setForegroundBrush(
        stale ? QBrush(QColor(kBackground.red(), kBackground.green(), kBackground.blue(), 170))
              : QBrush(Qt::NoBrush));
    m_view->setInteractive(!stale);
    m_summary->setEnabled(!stale);
    if (stale && m_hovered != core::kNone) {
        m_hovered = core::kNone;
        emit regionHovered(core::kNone);
    }
}

void RegionGraphPanel::nodeHovered(RegionGraphItem* node, bool entered) {
    if (m_stale)
        return;
    node->setState(entered, node->region() != core::kNone && node->region() == m_selected);
    const std::uint32_t region = entered ? node->region() : core::kNone;
    if (region == m_hovered)
        return;
    m_hovered = region;
    emit regionHovered(region);
}

void RegionGraphPanel::nodeClicked(RegionGraphItem* node) {
    if (m_stale || node->region() == core::kNone)
        return;
    m_selected = node->region();
    for (RegionGraphItem* item : m_nodes)
        item->setState(item == node || item->isUnderMouse(), item->region() == m_selected);
    emit regionActivated(m_selected);
}

void RegionGraphPanel::fitGraph() {
    const QRectF rect = m_scene->sceneRect();
    const QSize size = m_view->viewport()->size();
    if (rect.isEmpty() || size.isEmpty())
        return;
    const double scale = std::min(
        {double(size.width()) / rect.width(), double(size.height()) / rect.height(), kMaxZoom});
    m_view->setTransform(QTransform::fromScale(scale, scale));
    m_view->centerOn(rect.center());
}

bool RegionGraphPanel::eventFilter(QObject* watched, QEvent* event) {
    // The view also changes size when the summary above it gains or loses a line.
    if (watched == m_view->viewport() && event->type() == QEvent::Resize) {
        // Spread the columns to the view's shape; placing them again is cheap.
        if (m_layout && std::abs(columnSpacing() - m_spacing) > 0.05 * m_spacing)
            buildScene();
        else
            fitGraph();
    }
    return QWidget::eventFilter(watched, event);
}

void RegionGraphPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    fitGraph();
}

} // namespace ui
