// SPDX-License-Identifier: GPL-3.0-or-later
// The Region Graph panel on the 2CylinderEngine (thousands of regions, 17 layers) through real Qt
// events: wheel zoom, drag pan, Fit, the size and neighbourhood filters, hover and click.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QApplication>
#include <QCheckBox>
#include <QDockWidget>
#include <QFileInfo>
#include <QGraphicsItem>
#include <QGraphicsScene>
#include <QGraphicsSimpleTextItem>
#include <QGraphicsView>
#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>
#include <QWheelEvent>

#include <memory>
#include <set>

#include "core/document/document.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/panels/region_graph_panel.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace region_graph_uitest {

using namespace ui_test;

QString enginePath() {
    return QStringLiteral(LAYERPAINT_ASSIMP_MODELS
                          "/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
}

class RegionGraphTest : public WindowTest {
protected:
    RegionGraphTest() : WindowTest({1260, 900}) {}

    void SetUp() override {
        WindowTest::SetUp();
        // Its tab to the front (behind Paint Layers at first), as an artist clicks it.
        m_window->findChild<QDockWidget*>(QStringLiteral("regionGraphDock"))->raise();
    }

    ui::RegionGraphPanel* panel() const { return m_window->regionGraphPanel(); }
    QGraphicsView* view() const { return panel()->graphicsView(); }
    const core::RegionGraph& graph() const {
        return m_window->document().depthLayers()->segmentation.graph;
    }

    /** The node items (they carry their region id) that are visible in the view. */
    std::vector<QGraphicsItem*> nodesInView() const {
        std::vector<QGraphicsItem*> nodes;
        for (QGraphicsItem* item : view()->items(view()->viewport()->rect()))
            if (item->data(0).isValid())
                nodes.push_back(item);
        return nodes;
    }
    QPoint onScreen(const QGraphicsItem* item) const {
        return view()->mapFromScene(item->scenePos());
    }
    /** On-screen height of the header of layer 1. */
    double headerHeight() const {
        for (QGraphicsItem* item : view()->scene()->items()) {
            const auto* text = dynamic_cast<const QGraphicsSimpleTextItem*>(item);
            if (text && text->data(1).toUInt() == 1u)
                return text->deviceTransform(view()->viewportTransform())
                    .mapRect(text->boundingRect())
                    .height();
        }
        return 0.0;
    }
    void wheel(QPoint at, int notches) {
        QWheelEvent event(QPointF(at), view()->viewport()->mapToGlobal(QPointF(at)), QPoint(),
                          QPoint(0, 120 * notches), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase,
                          false);
        QApplication::sendEvent(view()->viewport(), &event);
    }
    /** A point of the view with no node near it, nor 60, 36 pixels further. */
    QPoint background() const {
        const auto noNode = [&](QPoint p) {
            for (QGraphicsItem* item : view()->items(QRect(p - QPoint(4, 4), QSize(9, 9))))
                if (item->data(0).isValid())
                    return false;
            return true;
        };
        const QRect rect = view()->viewport()->rect();
        for (int y = 20; y < rect.bottom() - 60; y += 7)
            for (int x = 20; x < rect.right() - 80; x += 7)
                if (noNode({x, y}) && noNode({x + 60, y + 36}))
                    return {x, y};
        return {-1, -1};
    }
};

TEST_F(RegionGraphTest, ZoomPanFitFilterHoverAndClickOnTheEngine) {
    if (!QFileInfo::exists(enginePath()))
        GTEST_SKIP() << "assimp test models not installed: " << enginePath().toStdString();
    QSignalSpy built(m_window->depthLayersBuilder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    m_window->openFromCommandLine({enginePath()});
    ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kLoadTimeoutMs));
    QApplication::processEvents();
    ASSERT_NE(m_window->document().depthLayers(), nullptr);
    std::printf("[ graph   ] %d regions, %d connections, %zu nodes\n", panel()->regionCount(),
                panel()->connectionCount(), panel()->layout().nodes.size());
    ASSERT_GT(panel()->regionCount(), 2000);
    ASSERT_GE(panel()->layout().layerCount, 10u);

    // Whole at first; the headers readable although the graph is scaled far down.
    EXPECT_NEAR(panel()->zoom(), 1.0, 1e-6);
    EXPECT_LT(view()->transform().m11(), 0.6);
    const double header = headerHeight();
    EXPECT_GE(header, 9.0);

    // The wheel zooms in about the pointer: the node there stays under it.
    std::vector<QGraphicsItem*> nodes = nodesInView();
    ASSERT_FALSE(nodes.empty());
    QGraphicsItem* node = nodes.front();
    for (QGraphicsItem* item : nodes) // a large node, away from the view's edges
        if (item->boundingRect().width() > node->boundingRect().width())
            node = item;
    const QPoint at = onScreen(node);
    wheel(at, 4);
    EXPECT_GT(panel()->zoom(), 2.0);
    EXPECT_LE((onScreen(node) - at).manhattanLength(), 3);
    EXPECT_NEAR(headerHeight(), header, 1.0) << "labels keep their size";

    // Hover and click still work zoomed in.
    QSignalSpy hovered(panel(), &ui::RegionGraphPanel::regionHovered);
    QSignalSpy activated(panel(), &ui::RegionGraphPanel::regionActivated);
    const auto region = std::uint32_t(node->data(0).toUInt());
    QTest::mouseMove(view()->viewport(), onScreen(node));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !hovered.isEmpty(); }, 2000));
    EXPECT_EQ(hovered.last().first().value<std::uint32_t>(), region);
    EXPECT_EQ(m_window->viewport()->compositeOptions().highlightRegion, region);
    QTest::mouseClick(view()->viewport(), Qt::LeftButton, Qt::NoModifier, onScreen(node));
    ASSERT_EQ(activated.size(), 1);
    EXPECT_EQ(activated.first().first().value<std::uint32_t>(), region);
    EXPECT_EQ(panel()->selectedRegion(), region);

    // Dragging the background pans: the scene moves with the pointer.
    const QPoint from = background();
    ASSERT_GE(from.x(), 0) << "no empty spot to drag";
    const QPointF sceneAt = view()->mapToScene(from);
    QTest::mousePress(view()->viewport(), Qt::LeftButton, Qt::NoModifier, from);
    for (int i = 1; i <= 6; ++i)
        QTest::mouseMove(view()->viewport(), from + QPoint(10 * i, 6 * i));
    QTest::mouseRelease(view()->viewport(), Qt::LeftButton, Qt::NoModifier, from + QPoint(60, 36));
    EXPECT_LE((view()->mapFromScene(sceneAt) - (from + QPoint(60, 36))).manhattanLength(), 3);
    EXPECT_EQ(activated.size(), 1) << "a drag is no click";

    // F in the graph fits it (and leaves the model's camera alone).
    const float distance = m_window->viewport()->camera().distance;
    wheel(view()->viewport()->rect().center(), 3);
    ASSERT_GT(panel()->zoom(), 1.5);
    view()->setFocus();
    QTest::keyClick(view(), Qt::Key_F);
    EXPECT_NEAR(panel()->zoom(), 1.0, 1e-6);
    EXPECT_EQ(m_window->viewport()->camera().distance, distance);
    // So does the Fit button.
    wheel(view()->viewport()->rect().center(), 5);
    ASSERT_GT(panel()->zoom(), 2.0);
    auto* fit = panel()->findChild<QToolButton*>(QStringLiteral("regionGraphFit"));
    ASSERT_NE(fit, nullptr);
    QTest::mouseClick(fit, Qt::LeftButton);
    EXPECT_NEAR(panel()->zoom(), 1.0, 1e-6);

    // Hide the regions under 500 pixels, typed into the filter box.
    auto* minPixels = panel()->findChild<QSpinBox*>(QStringLiteral("regionGraphMinPixels"));
    ASSERT_NE(minPixels, nullptr);
    minPixels->setFocus();
    minPixels->selectAll();
    QTest::keyClicks(minPixels, QStringLiteral("500"));
    QTest::keyClick(minPixels, Qt::Key_Return);
    EXPECT_EQ(panel()->minimumPixels(), 500u);
    EXPECT_GT(panel()->hiddenRegionCount(), 0);
    EXPECT_EQ(panel()->regionCount(), int(graph().regions.size()));
    std::size_t big = 0;
    for (const core::Region& r : graph().regions)
        big += r.pixels >= 500 ? 1 : 0;
    EXPECT_EQ(std::size_t(panel()->regionCount() - panel()->hiddenRegionCount()), big);
    for (QGraphicsItem* item : view()->scene()->items()) {
        if (item->data(0).isValid()) {
            EXPECT_GE(graph().regions[item->data(0).toUInt()].pixels, 500u);
        }
    }
    EXPECT_TRUE(panel()
                    ->findChild<QLabel*>(QStringLiteral("regionSummary"))
                    ->text()
                    .contains(QStringLiteral("filtered out")));

    // The selected region's neighbourhood only.
    minPixels->selectAll();
    QTest::keyClicks(minPixels, QStringLiteral("0"));
    QTest::keyClick(minPixels, Qt::Key_Return);
    EXPECT_EQ(panel()->hiddenRegionCount(), 0);
    auto* neighbours = panel()->findChild<QCheckBox*>(QStringLiteral("regionGraphNeighbours"));
    ASSERT_NE(neighbours, nullptr);
    QTest::mouseClick(neighbours, Qt::LeftButton, Qt::NoModifier,
                      neighbours->rect().topLeft() + QPoint(6, neighbours->height() / 2));
    ASSERT_TRUE(panel()->neighbourhoodOnly());
    std::set<std::uint32_t> allowed{region};
    for (const core::RegionLink& link : graph().neighborsOf(region))
        allowed.insert(link.region);
    int shown = 0;
    for (QGraphicsItem* item : view()->scene()->items()) {
        if (!item->data(0).isValid())
            continue;
        ++shown;
        EXPECT_TRUE(allowed.count(item->data(0).toUInt())) << item->data(0).toUInt();
    }
    EXPECT_GE(shown, 1);
    EXPECT_EQ(panel()->regionCount() - panel()->hiddenRegionCount(), int(allowed.size()));

    // Clicking a neighbour shows its neighbourhood in turn (after the click, not inside it).
    QGraphicsItem* other = nullptr;
    for (QGraphicsItem* item : nodesInView())
        if (item->data(0).toUInt() != region)
            other = item;
    if (other) {
        const auto next = std::uint32_t(other->data(0).toUInt());
        QTest::mouseClick(view()->viewport(), Qt::LeftButton, Qt::NoModifier, onScreen(other));
        ASSERT_EQ(activated.size(), 2);
        EXPECT_EQ(activated.last().first().value<std::uint32_t>(), next);
        ASSERT_TRUE(QTest::qWaitFor(
            [&] {
                return panel()->regionCount() - panel()->hiddenRegionCount() ==
                       int(graph().neighborsOf(next).size() + 1);
            },
            2000));
    }
}

} // namespace region_graph_uitest
