// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/panels/region_graph_panel.h"

#include <QCheckBox>
#include <QEvent>
#include <QFontMetricsF>
#include <QGraphicsEllipseItem>
#include <QGraphicsPathItem>
#include <QGraphicsScene>
#include <QGraphicsSceneHoverEvent>
#include <QGraphicsSceneMouseEvent>
#include <QGraphicsSimpleTextItem>
#include <QGraphicsView>
#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLocale>
#include <QPainterPath>
#include <QPen>
#include <QScrollBar>
#include <QSpinBox>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

#include "core/depth/depth_layers.h"
#include "render/depth_compositor.h"

namespace ui {

namespace {
using Layout = core::RegionGraphLayout;

constexpr double kColumnGap = 44.0;
constexpr double kMaxFitZoom = 2.0;      // a small graph is not blown up to fill the view
constexpr double kMinZoomOut = 0.5;      // relative to the whole graph in view
constexpr double kZoomPerNotch = 1.25;   // one 15° wheel notch
constexpr double kNodeLabelRadius = 9.0; // on-screen radius from which a node shows its id

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

QPen cosmeticPen(const QColor& color, double width) {
    QPen pen(color, width);
    pen.setCosmetic(true); // the same on screen at any zoom
    pen.setCapStyle(Qt::RoundCap);
    return pen;
}

/**
 * A label that keeps its size on screen at any zoom, anchored at pos (in parent or scene
 * coordinates): centred on it horizontally, above it (up), below it, or centred on it.
 */
enum class LabelSide { Above, Below, Centre };
QGraphicsItem* addLabel(QGraphicsScene* scene, QGraphicsItem* parent, const QString& text,
                        const QFont& font, QPointF pos, LabelSide side) {
    auto* anchor = new QGraphicsRectItem(parent);
    anchor->setPen(Qt::NoPen);
    anchor->setBrush(Qt::NoBrush);
    anchor->setFlag(QGraphicsItem::ItemIgnoresTransformations);
    anchor->setAcceptedMouseButtons(Qt::NoButton);
    anchor->setPos(pos);
    auto* label = new QGraphicsSimpleTextItem(text, anchor);
    label->setFont(font);
    label->setBrush(kText);
    label->setAcceptedMouseButtons(Qt::NoButton);
    const QRectF box = label->boundingRect();
    const double y = side == LabelSide::Above   ? -box.height() - 2.0
                     : side == LabelSide::Below ? 1.0
                                                : -box.height() / 2.0;
    label->setPos(-box.width() / 2.0, y);
    if (!parent)
        scene->addItem(anchor);
    return anchor;
}
} // namespace

/** A node of the graph: a region (or merged regions) that reports hover and clicks. */
class RegionGraphItem : public QGraphicsEllipseItem {
public:
    RegionGraphItem(RegionGraphPanel* panel, std::uint32_t region, double radius)
        : QGraphicsEllipseItem(-radius, -radius, 2.0 * radius, 2.0 * radius), m_panel(panel),
          m_region(region), m_radius(radius) {
        setAcceptHoverEvents(true);
        setAcceptedMouseButtons(Qt::LeftButton);
        setData(0, region == core::kNone ? QVariant() : QVariant(uint(region)));
    }

    std::uint32_t region() const { return m_region; }
    double radius() const { return m_radius; }
    std::vector<QGraphicsPathItem*>& edges() { return m_edges; }
    /** The id label shown when the node is big enough on screen. */
    QGraphicsItem*& idLabel() { return m_idLabel; }

    void setState(bool hovered, bool selected) {
        if (selected)
            setPen(cosmeticPen(kSelected, 2.5));
        else if (hovered)
            setPen(cosmeticPen(kHovered, 2.5));
        else
            setPen(cosmeticPen(kOutline, 1.0));
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
        event->accept(); // the click happens at the release, on this item; no panning
    }
    void mouseReleaseEvent(QGraphicsSceneMouseEvent* event) override {
        if (contains(event->pos()))
            m_panel->nodeClicked(this);
        event->accept();
    }

private:
    RegionGraphPanel* m_panel;
    std::uint32_t m_region;
    double m_radius;
    std::vector<QGraphicsPathItem*> m_edges;
    QGraphicsItem* m_idLabel = nullptr;
};

RegionGraphPanel::RegionGraphPanel(QWidget* parent)
    : QWidget(parent), m_selected(core::kNone), m_hovered(core::kNone) {
    m_options.maxNodesPerLayer = kMaxNodesPerLayer;

    m_summary = new QLabel(tr("No regions yet"), this);
    m_summary->setObjectName(QStringLiteral("regionSummary"));
    m_summary->setWordWrap(true);
    m_summary->setContentsMargins(4, 2, 4, 2);

    m_fitButton = new QToolButton(this);
    m_fitButton->setObjectName(QStringLiteral("regionGraphFit"));
    m_fitButton->setText(tr("Fit"));
    m_fitButton->setToolTip(tr("Show the whole graph (F or Home in the graph). The wheel "
                               "zooms, dragging the background pans."));
    connect(m_fitButton, &QToolButton::clicked, this, &RegionGraphPanel::fitGraph);

    m_minPixels = new QSpinBox(this);
    m_minPixels->setObjectName(QStringLiteral("regionGraphMinPixels"));
    m_minPixels->setRange(0, 10'000'000);
    m_minPixels->setSingleStep(50);
    m_minPixels->setSuffix(tr(" px"));
    m_minPixels->setSpecialValueText(tr("All sizes"));
    m_minPixels->setKeyboardTracking(false);
    m_minPixels->setToolTip(tr("Hide regions smaller than this many pixels"));
    auto* minLabel = new QLabel(tr("&Hide under:"), this);
    minLabel->setBuddy(m_minPixels);
    connect(m_minPixels, &QSpinBox::valueChanged, this,
            [this](int value) { setMinimumPixels(std::uint32_t(std::max(0, value))); });

    m_neighbourhoodBox = new QCheckBox(tr("&Neighbours only"), this);
    m_neighbourhoodBox->setObjectName(QStringLiteral("regionGraphNeighbours"));
    m_neighbourhoodBox->setToolTip(
        tr("Show only the selected region (click a node) and the regions connected to it"));
    connect(m_neighbourhoodBox, &QCheckBox::toggled, this, &RegionGraphPanel::setNeighbourhoodOnly);

    m_scene = new QGraphicsScene(this);
    m_scene->setBackgroundBrush(kBackground);
    m_view = new QGraphicsView(m_scene, this);
    m_view->setObjectName(QStringLiteral("regionGraphView"));
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_view->setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_view->setFrameShape(QFrame::NoFrame);
    m_view->setDragMode(QGraphicsView::ScrollHandDrag);
    m_view->setTransformationAnchor(QGraphicsView::NoAnchor);
    m_view->setResizeAnchor(QGraphicsView::AnchorViewCenter);
    m_view->setFocusPolicy(Qt::StrongFocus);
    m_view->setMouseTracking(true);
    m_view->viewport()->setMouseTracking(true);
    m_view->setMinimumSize(120, 100);
    m_view->installEventFilter(this);
    m_view->viewport()->installEventFilter(this);

    // Two short rows: the panel stays as narrow as the others in its dock column.
    auto* controls = new QGridLayout;
    controls->setContentsMargins(4, 0, 4, 2);
    controls->setHorizontalSpacing(4);
    controls->setVerticalSpacing(2);
    controls->addWidget(m_fitButton, 0, 0);
    controls->addWidget(m_neighbourhoodBox, 0, 1, 1, 2);
    controls->addWidget(minLabel, 1, 0, 1, 2);
    controls->addWidget(m_minPixels, 1, 2);
    controls->setColumnStretch(2, 1);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(m_summary);
    layout->addLayout(controls);
    layout->addWidget(m_view, 1);
}

RegionGraphPanel::~RegionGraphPanel() = default;

void RegionGraphPanel::setDepthLayers(const core::DepthLayers* layers) {
    if (!layers) {
        setStale(true);
        return;
    }
    if (m_hovered != core::kNone) {
        m_hovered = core::kNone;
        emit regionHovered(core::kNone);
    }
    m_selected = core::kNone;
    m_graph = layers->segmentation.graph;
    m_imageHeight = std::max(1, layers->stack.height);
    m_haveGraph = true;
    m_regionCount = int(m_graph.regions.size());
    m_connectionCount = int(m_graph.neighbors.size() / 2);
    relayout();
    setStale(false);
}

void RegionGraphPanel::setMinimumPixels(std::uint32_t pixels) {
    if (m_minPixels->value() != int(std::min<std::uint32_t>(pixels, 10'000'000))) {
        m_minPixels->setValue(int(std::min<std::uint32_t>(pixels, 10'000'000)));
        return; // back here through valueChanged
    }
    if (m_options.minPixels == pixels)
        return;
    m_options.minPixels = pixels;
    relayout();
}

void RegionGraphPanel::setNeighbourhoodOnly(bool on) {
    if (m_neighbourhoodBox->isChecked() != on) {
        m_neighbourhoodBox->setChecked(on);
        return; // back here through toggled
    }
    if (m_neighbourhood == on)
        return;
    m_neighbourhood = on;
    relayout();
}

void RegionGraphPanel::relayout() {
    if (!m_haveGraph)
        return;
    m_options.focus = m_neighbourhood ? m_selected : core::kNone;
    m_layout = core::layoutRegionGraph(m_graph, m_imageHeight, m_options);
    updateSummary();
    buildScene();
    fitGraph();
}

void RegionGraphPanel::updateSummary() {
    if (m_graph.regions.empty()) {
        m_summary->setText(tr("No regions in this view"));
        return;
    }
    const QLocale locale;
    QString text = tr("Regions: %1, connections: %2")
                       .arg(locale.toString(m_regionCount), locale.toString(m_connectionCount));
    if (m_neighbourhood && m_selected == core::kNone)
        text += QLatin1Char('\n') + tr("Click a node to see its neighbours only");
    else if (m_layout.hiddenRegions > 0)
        text +=
            QLatin1Char('\n') +
            tr("Shown: %1 (filtered out: %2), in grey nodes: %3")
                .arg(locale.toString(qulonglong(m_graph.regions.size() - m_layout.hiddenRegions)),
                     locale.toString(qulonglong(m_layout.hiddenRegions)),
                     locale.toString(qulonglong(m_layout.mergedRegions)));
    else if (m_layout.mergedRegions > 0)
        text += QLatin1Char('\n') + tr("Small regions merged into grey nodes: %1")
                                        .arg(locale.toString(qulonglong(m_layout.mergedRegions)));
    m_summary->setText(text);
}

double RegionGraphPanel::columnSpacing() const {
    const double minimum = 2.0 * Layout::kMaxRadius + kColumnGap;
    if (m_layout.layerCount < 2)
        return minimum;
    const QSize size = m_view->viewport()->size();
    const double aspect = size.height() > 0 ? double(size.width()) / size.height() : 1.0;
    const double height = m_layout.bottom - m_layout.top + 40.0; // with the headers
    const double spacing =
        (aspect * height - 2.0 * Layout::kMaxRadius - 16.0) / double(m_layout.layerCount - 1);
    return std::clamp(spacing, minimum, 4.0 * minimum);
}

void RegionGraphPanel::buildScene() {
    if (m_hovered != core::kNone) {
        m_hovered = core::kNone;
        emit regionHovered(core::kNone);
    }
    m_nodes.clear();
    m_headers.clear();
    m_countLabels.clear();
    m_scene->clear();
    if (!m_haveGraph)
        return;
    const std::vector<Layout::Node>& nodes = m_layout.nodes;
    const double top = m_layout.top;
    const double bottom = m_layout.bottom;

    m_spacing = columnSpacing();
    const double spacing = m_spacing;
    const auto columnX = [&](std::uint32_t layer) { return (double(layer) - 1.0) * spacing; };

    // Scene: guides and headers, edges, nodes. Labels keep their size at any zoom.
    QFont small = font();
    small.setPointSizeF(std::max(7.0, small.pointSizeF() * 0.85));
    std::vector<std::uint8_t> columnUsed(m_layout.layerCount + 1, 0);
    for (const Layout::Node& node : nodes)
        columnUsed[node.layer] = 1;
    for (std::uint32_t layer = 1; layer <= m_layout.layerCount; ++layer) {
        if (!columnUsed[layer])
            continue;
        const double x = columnX(layer);
        m_scene->addLine(x, top - 6.0, x, bottom + 6.0, cosmeticPen(QColor(255, 255, 255, 22), 1.0))
            ->setZValue(0.0);
        QGraphicsItem* header = addLabel(m_scene, nullptr, tr("Depth layer %1").arg(layer), small,
                                         QPointF(x, top - 6.0), LabelSide::Above);
        header->setZValue(4.0);
        header->childItems().front()->setData(1, uint(layer));
        m_headers.push_back(static_cast<QGraphicsSimpleTextItem*>(header->childItems().front()));
    }

    std::vector<RegionGraphItem*> items(nodes.size(), nullptr);
    const QLocale locale;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const Layout::Node& node = nodes[i];
        auto* item = new RegionGraphItem(this, node.region, node.radius);
        item->setPos(columnX(node.layer), node.y);
        if (node.merged()) {
            item->setBrush(kMerged);
            item->setToolTip(tr("%1 small regions of depth layer %2\n%3 pixels together")
                                 .arg(locale.toString(node.members))
                                 .arg(node.layer)
                                 .arg(locale.toString(qulonglong(node.pixels))));
            m_countLabels.push_back(
                addLabel(m_scene, item, tr("+%1").arg(locale.toString(qulonglong(node.members))),
                         small, QPointF(0.0, node.radius), LabelSide::Below));
        } else {
            item->setBrush(toColor(render::regionColor(node.region)));
            item->setToolTip(tr("Region %1 on depth layer %2\n%3 pixels\nConnected regions: %4")
                                 .arg(node.region)
                                 .arg(node.layer)
                                 .arg(locale.toString(qulonglong(node.pixels)))
                                 .arg(node.neighbors));
            item->idLabel() = addLabel(m_scene, item, QString::number(node.region), small,
                                       QPointF(0.0, 0.0), LabelSide::Centre);
        }
        item->setState(false, !node.merged() && node.region == m_selected);
        m_scene->addItem(item);
        items[i] = item;
        m_nodes.push_back(item);
    }
    for (const Layout::Edge& edge : m_layout.edges) {
        const Layout::Node& a = nodes[std::size_t(edge.a)];
        const Layout::Node& b = nodes[std::size_t(edge.b)];
        const QPointF from(columnX(a.layer), a.y);
        const QPointF to(columnX(b.layer), b.y);
        const double bend = (to.x() - from.x()) * 0.5;
        QPainterPath path(from);
        path.cubicTo(from + QPointF(bend, 0.0), to - QPointF(bend, 0.0), to);
        const double width =
            std::min(5.0, 0.8 + 0.9 * std::log10(double(std::max<std::uint64_t>(edge.links, 1))));
        QGraphicsPathItem* item = m_scene->addPath(path, cosmeticPen(kEdge, width));
        item->setZValue(1.0);
        item->setToolTip(tr("%1 pixel links").arg(locale.toString(qulonglong(edge.links))));
        items[std::size_t(edge.a)]->edges().push_back(item);
        items[std::size_t(edge.b)]->edges().push_back(item);
    }
    for (RegionGraphItem* item : items)
        item->setState(false, item->region() != core::kNone && item->region() == m_selected);

    // Room around the nodes for the labels (their size on screen is not known here). The
    // scene reaches a graph's size beyond it on every side, so any part of the graph can be
    // zoomed into and panned to the middle of the view.
    const QRectF nodesBox(
        QPointF(-Layout::kMaxRadius, top),
        QPointF(columnX(std::max(1u, m_layout.layerCount)) + Layout::kMaxRadius, bottom));
    m_graphRect = nodesBox.adjusted(-24.0, -28.0, 24.0, 12.0);
    m_scene->setSceneRect(m_graphRect.adjusted(-m_graphRect.width(), -m_graphRect.height(),
                                               m_graphRect.width(), m_graphRect.height()));
}

double RegionGraphPanel::fitScale() const {
    const QRectF rect = m_graphRect;
    const QSize size = m_view->viewport()->size();
    if (rect.isEmpty() || size.isEmpty())
        return 1.0;
    return std::min(
        {double(size.width()) / rect.width(), double(size.height()) / rect.height(), kMaxFitZoom});
}

double RegionGraphPanel::zoom() const {
    return m_view->transform().m11() / fitScale();
}

void RegionGraphPanel::fitGraph() {
    const double scale = fitScale();
    m_view->setTransform(QTransform::fromScale(scale, scale));
    m_view->centerOn(m_graphRect.center());
    m_zoomed = false;
    zoomBy(1.0, QPointF()); // labels for this zoom
}

void RegionGraphPanel::zoomBy(double factor, QPointF anchor) {
    const double fit = fitScale();
    const double current = m_view->transform().m11();
    const double scale = std::clamp(current * factor, fit * kMinZoomOut, fit * kMaxZoomIn);
    if (scale != current) {
        // The scene point under the anchor stays there.
        const QPointF scenePoint = m_view->mapToScene(anchor.toPoint());
        m_view->setTransform(QTransform::fromScale(scale, scale));
        const QPointF moved = QPointF(m_view->mapFromScene(scenePoint)) - anchor;
        m_view->horizontalScrollBar()->setValue(m_view->horizontalScrollBar()->value() +
                                                int(std::lround(moved.x())));
        m_view->verticalScrollBar()->setValue(m_view->verticalScrollBar()->value() +
                                              int(std::lround(moved.y())));
        m_zoomed = true;
    }
    // Region ids on the nodes that are big enough on screen to hold them.
    for (RegionGraphItem* item : m_nodes)
        if (QGraphicsItem* label = item->idLabel())
            label->setVisible(item->radius() * scale >= kNodeLabelRadius);
    // Column labels as long as the columns' distance on screen leaves room for.
    const double room = m_spacing * scale - 6.0;
    for (QGraphicsSimpleTextItem* header : m_headers) {
        const uint layer = header->data(1).toUInt();
        const QString full = tr("Depth layer %1").arg(layer);
        const QFontMetricsF metrics(header->font());
        const QString text = metrics.horizontalAdvance(full) <= room || m_headers.size() == 1
                                 ? full
                                 : QString::number(layer);
        if (header->text() != text) {
            header->setText(text);
            header->setPos(-header->boundingRect().width() / 2.0, header->pos().y());
        }
    }
    for (QGraphicsItem* label : m_countLabels)
        label->setVisible(m_headers.size() <= 1 ||
                          label->childItems().front()->boundingRect().width() <= room);
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
    if (m_neighbourhood) {
        // Not from inside the clicked item's own event: the scene is rebuilt.
        QTimer::singleShot(0, this, &RegionGraphPanel::relayout);
    }
    emit regionActivated(m_selected);
}

bool RegionGraphPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_view) {
        // F and Home fit the graph while it has the focus (elsewhere they frame the model).
        if (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress) {
            const auto* key = static_cast<QKeyEvent*>(event);
            if ((key->key() == Qt::Key_F || key->key() == Qt::Key_Home) &&
                key->modifiers() == Qt::NoModifier) {
                event->accept();
                if (event->type() == QEvent::KeyPress)
                    fitGraph();
                return true;
            }
        }
    } else if (watched == m_view->viewport()) {
        if (event->type() == QEvent::Wheel) {
            const auto* wheel = static_cast<QWheelEvent*>(event);
            const int eighths = wheel->angleDelta().y();
            if (eighths != 0)
                zoomBy(std::pow(kZoomPerNotch, double(eighths) / 120.0), wheel->position());
            return true;
        }
        // The view also changes size when the summary above it gains or loses a line.
        if (event->type() == QEvent::Resize && m_haveGraph) {
            // Spread the columns to the view's shape; placing them again is cheap.
            if (!m_zoomed && std::abs(columnSpacing() - m_spacing) > 0.05 * m_spacing) {
                buildScene();
                fitGraph();
            } else if (!m_zoomed) {
                fitGraph();
            }
        }
    }
    return QWidget::eventFilter(watched, event);
}

void RegionGraphPanel::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    if (!m_zoomed)
        fitGraph();
}

} // namespace ui
