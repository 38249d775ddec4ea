// SPDX-License-Identifier: GPL-3.0-or-later
// Multi-layer segmentation in the GUI through real Qt event delivery: layers built when the view
// settles, the view modes, the Depth Layers and Region Graph panels and the threshold slider.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QGraphicsItem>
#include <QGraphicsView>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QStatusBar>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>
#include <QWheelEvent>

#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <set>

#include "core/document/document.h"
#include "render/depth_compositor.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/panels/depth_layers_panel.h"
#include "ui/panels/region_graph_panel.h"
#include "ui/panels/segmentation_controls.h"
#include "ui/shell/main_window.h"
#include "ui/tools/tool.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace segmentation_uitest {

using namespace ui_test;

QRgb backgroundRgb() {
    const glm::vec4 c = render::CompositeOptions{}.background;
    return qRgb(qRound(c.r * 255.0f), qRound(c.g * 255.0f), qRound(c.b * 255.0f));
}

/** Hues (degrees) of clearly coloured pixels, in 10° buckets with their pixel counts. */
std::map<int, qint64> hueHistogram(const QImage& image) {
    std::map<int, qint64> buckets;
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    for (int y = 0; y < rgb.height(); ++y) {
        for (int x = 0; x < rgb.width(); ++x) {
            const QColor color = QColor::fromRgb(rgb.pixel(x, y));
            if (color.hsvSaturation() > 90 && color.value() > 60)
                ++buckets[color.hsvHue() / 10];
        }
    }
    return buckets;
}

int hueOf(std::uint32_t region) {
    const glm::vec4 c = render::regionColor(region);
    return QColor::fromRgbF(c.r, c.g, c.b).hsvHue();
}

class SegmentationTest : public WindowTest {
protected:
    // The size gives the view of the trefoil whose region counts the tests below rely on.
    SegmentationTest() : WindowTest({1100, 754}) {}

    void SetUp() override {
        WindowTest::SetUp();
        if (HasFatalFailure())
            return;
        // Every adopted build must describe the view on screen at that moment.
        QObject::connect(builder(), &ui::DepthLayersBuilder::depthLayersBuilt, [this] {
            const core::DepthLayers* layers = document().depthLayers();
            ASSERT_NE(layers, nullptr);
            const core::View view = viewport()->view();
            EXPECT_EQ(layers->view.view, view.view);
            EXPECT_EQ(layers->view.proj, view.proj);
            EXPECT_EQ(layers->view.width, view.width);
            EXPECT_EQ(layers->view.height, view.height);
        });
    }

    ui::RegionGraphPanel* graph() const { return m_window->regionGraphPanel(); }

    /** Opens the trefoil and waits until the layers of its first view are shown. */
    void openTrefoil() {
        WindowTest::openTrefoil();
        if (HasFatalFailure())
            return;
        ASSERT_TRUE(viewport()->isShowingDepthLayers());
    }

    void orbitDrag(QPoint delta) {
        const QPoint start = viewport()->rect().center();
        QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, start);
        for (int i = 1; i <= 5; ++i)
            QTest::mouseMove(viewport(), start + delta * i / 5);
        QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, start + delta);
    }
};

TEST_F(SegmentationTest, BuildsLayersWhenTheViewSettles) {
    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    QSignalSpy built(builder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    m_window->openFile(QStringLiteral("builtin:trefoil"));
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    // Until the view has settled the mesh renderer draws.
    EXPECT_EQ(document().depthLayers(), nullptr);
    EXPECT_FALSE(viewport()->isShowingDepthLayers());
    EXPECT_TRUE(builder()->isBuilding());
    const QImage fromMesh = grab();

    ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
    const core::DepthLayers* layers = document().depthLayers();
    ASSERT_NE(layers, nullptr);
    EXPECT_GE(layers->stack.maxLayers(), 2u);
    EXPECT_GT(layers->segmentation.graph.regions.size(), 1u);
    EXPECT_EQ(builder()->captureCount(), 1);
    EXPECT_FALSE(builder()->isBuilding());
    EXPECT_GT(builder()->lastBuildMs(), 0.0);

    // Shaded from the layers looks like shaded from the mesh.
    ASSERT_TRUE(viewport()->isShowingDepthLayers());
    EXPECT_LT(differingFraction(fromMesh, grab()), 0.001);

    // The status bar and the panels report the build.
    auto* info = m_window->statusBar()->findChild<QLabel*>(QStringLiteral("layerInfo"));
    ASSERT_NE(info, nullptr);
    EXPECT_TRUE(info->text().contains(
        QStringLiteral("Regions: %1").arg(layers->segmentation.graph.regions.size())))
        << info->text().toStdString();
    EXPECT_TRUE(info->text().contains(QStringLiteral(" ms"))) << info->text().toStdString();
    EXPECT_EQ(m_window->depthLayersPanel()->layerCount(), int(layers->stack.maxLayers()));
    EXPECT_EQ(graph()->regionCount(), int(layers->segmentation.graph.regions.size()));
}

TEST_F(SegmentationTest, SegmentationViewThroughTheMenuShortcut) {
    openTrefoil();
    auto* action = m_window->findChild<QAction*>(QStringLiteral("actionDisplaySegmentation"));
    ASSERT_NE(action, nullptr);
    EXPECT_FALSE(action->isChecked());
    const QImage shaded = grab();
    EXPECT_LT(hueHistogram(shaded).size(), 2u); // the default material is grey

    QTest::keyClick(m_window.get(), Qt::Key_3, Qt::ControlModifier);
    EXPECT_TRUE(action->isChecked());
    EXPECT_EQ(viewport()->display(), render::DepthLayerDisplay::Segmentation);

    const QImage map = grab();
    EXPECT_GT(differingFraction(shaded, map), 0.05);
    // The front layer's regions show in their own colours.
    const std::map<int, qint64> hues = hueHistogram(map);
    const core::RegionGraph& regions = document().depthLayers()->segmentation.graph;
    std::set<int> found;
    for (const core::Region& region : regions.regions) {
        if (region.layer != 1 || region.pixels < 500)
            continue;
        const int bucket = hueOf(region.id) / 10;
        for (int b : {bucket - 1, bucket, bucket + 1}) {
            const auto it = hues.find((b + 36) % 36);
            if (it != hues.end() && it->second > 100)
                found.insert(region.id);
        }
    }
    EXPECT_GE(found.size(), 3u);

    // Ctrl+1 goes back to shaded; Ctrl+4 toggles the boundary overlay.
    QTest::keyClick(m_window.get(), Qt::Key_1, Qt::ControlModifier);
    EXPECT_EQ(viewport()->display(), render::DepthLayerDisplay::Composite);
    QTest::keyClick(m_window.get(), Qt::Key_4, Qt::ControlModifier);
    EXPECT_TRUE(viewport()->compositeOptions().boundaries);
    EXPECT_GT(differingFraction(shaded, grab()), 0.0005);
    QTest::keyClick(m_window.get(), Qt::Key_4, Qt::ControlModifier);
    EXPECT_FALSE(viewport()->compositeOptions().boundaries);
}

TEST_F(SegmentationTest, ThresholdSliderResegmentsWithoutCapturing) {
    openTrefoil();
    const int captures = builder()->captureCount();
    const int before = graph()->regionCount();
    auto* summary = graph()->findChild<QLabel*>(QStringLiteral("regionSummary"));
    ASSERT_NE(summary, nullptr);
    EXPECT_TRUE(summary->text().contains(QString::number(before))) << summary->text().toStdString();
    QSignalSpy resegmented(builder(), &ui::DepthLayersBuilder::segmentationChanged);

    // The paper's plain depth test, chosen with the keyboard.
    auto* test = m_window->findChild<QComboBox*>(QStringLiteral("connectionTest"));
    ASSERT_NE(test, nullptr);
    test->setFocus();
    QTest::keyClick(test, Qt::Key_Down);
    EXPECT_EQ(document().depthLayerOptions().test, core::ConnectionTest::Plain);

    // The smallest threshold: a plain depth test breaks the tube into many small pieces.
    auto* slider = m_window->findChild<QSlider*>(QStringLiteral("thresholdSlider"));
    ASSERT_NE(slider, nullptr);
    slider->setFocus();
    QTest::keyClick(slider, Qt::Key_Home);
    EXPECT_NEAR(document().depthLayerOptions().threshold, 1e-5f, 1e-9f);
    auto* value = m_window->findChild<QLabel*>(QStringLiteral("thresholdValue"));
    ASSERT_NE(value, nullptr);
    EXPECT_EQ(value->text(), QStringLiteral("0.000010"));
    ASSERT_NE(document().depthLayers(), nullptr);
    const int fine = graph()->regionCount();
    EXPECT_GT(fine, 10 * before);
    EXPECT_EQ(fine, int(document().depthLayers()->segmentation.graph.regions.size()));
    EXPECT_TRUE(summary->text().contains(QLocale().toString(fine)))
        << summary->text().toStdString();

    // Back up a few steps at a time: fewer regions again. Each step re-segments at once.
    for (int i = 0; i < 6; ++i)
        QTest::keyClick(slider, Qt::Key_PageUp);
    EXPECT_GT(document().depthLayerOptions().threshold, 1e-4f);
    EXPECT_LT(graph()->regionCount(), fine);

    // The largest threshold joins everything that touches.
    QTest::keyClick(slider, Qt::Key_End);
    EXPECT_NEAR(document().depthLayerOptions().threshold, 0.1f, 1e-6f);
    EXPECT_LE(graph()->regionCount(), before);

    EXPECT_GE(resegmented.size(), 4);
    EXPECT_EQ(builder()->captureCount(), captures); // no new capture
    EXPECT_FALSE(builder()->isBuilding());
    ASSERT_NE(document().depthLayers(), nullptr);
    EXPECT_TRUE(viewport()->isShowingDepthLayers());
}

TEST_F(SegmentationTest, TwoSidedCaptureRecaptures) {
    openTrefoil();
    const int captures = builder()->captureCount();
    const std::size_t fragments = document().depthLayers()->stack.fragmentCount();
    QSignalSpy built(builder(), &ui::DepthLayersBuilder::depthLayersBuilt);

    auto* twoSided = m_window->findChild<QCheckBox*>(QStringLiteral("twoSidedCapture"));
    ASSERT_NE(twoSided, nullptr);
    QTest::mouseClick(twoSided, Qt::LeftButton, Qt::NoModifier, QPoint(8, twoSided->height() / 2));
    EXPECT_FALSE(document().depthLayerOptions().cullBackFaces);
    EXPECT_EQ(document().depthLayers(), nullptr); // dropped at once

    ASSERT_TRUE(built.wait(kBuildTimeoutMs));
    EXPECT_EQ(builder()->captureCount(), captures + 1);
    ASSERT_NE(document().depthLayers(), nullptr);
    EXPECT_FALSE(document().depthLayers()->options.cullBackFaces);
    // A closed tube seen from both sides: each pixel meets it twice as often.
    EXPECT_GT(document().depthLayers()->stack.fragmentCount(), fragments * 3 / 2);
}

TEST_F(SegmentationTest, LayerRowShowsThatLayerAlone) {
    openTrefoil();
    auto* list = m_window->depthLayersPanel()->findChild<QListWidget*>(QStringLiteral("layerList"));
    ASSERT_NE(list, nullptr);
    const core::DepthLayers& layers = *document().depthLayers();
    ASSERT_EQ(list->count(), int(layers.stack.maxLayers()) + 1); // "All depth layers" first
    EXPECT_EQ(m_window->depthLayersPanel()->layerCount(), int(layers.stack.maxLayers()));
    const QImage all = grab();

    QListWidgetItem* second = list->item(2);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(second).center());
    EXPECT_EQ(viewport()->display(), render::DepthLayerDisplay::SingleLayer);
    EXPECT_EQ(viewport()->displayLayer(), 2u);
    auto* action = m_window->findChild<QAction*>(QStringLiteral("actionDisplaySingleLayer"));
    ASSERT_NE(action, nullptr);
    EXPECT_TRUE(action->isChecked());

    const QImage image = grab().convertToFormat(QImage::Format_RGB32);
    ASSERT_EQ(image.width(), layers.stack.width);
    ASSERT_EQ(image.height(), layers.stack.height);
    EXPECT_GT(differingFraction(all, image), 0.05);
    // Pixels without a second fragment show the background; most others do not.
    const QRgb background = backgroundRgb();
    qint64 without = 0, withoutBackground = 0, with = 0, withForeground = 0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const std::size_t pixel = std::size_t(y) * std::size_t(image.width()) + std::size_t(x);
            const bool isBackground = channelDifference(image.pixel(x, y), background) <= 3;
            if (layers.stack.layerCount(pixel) < 2) {
                ++without;
                withoutBackground += isBackground ? 1 : 0;
            } else {
                ++with;
                withForeground += isBackground ? 0 : 1;
            }
        }
    }
    ASSERT_GT(with, 1000);
    EXPECT_GE(double(withoutBackground), 0.999 * double(without));
    EXPECT_GE(double(withForeground), 0.95 * double(with));

    // "All depth layers" goes back.
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(list->item(0)).center());
    EXPECT_EQ(viewport()->display(), render::DepthLayerDisplay::Composite);
    EXPECT_LT(differingFraction(all, grab()), 0.001);
}

TEST_F(SegmentationTest, HoveringAGraphNodeHighlightsItsRegion) {
    openTrefoil();
    // Its tab to the front (behind Paint Layers at first), as an artist clicks it.
    m_window->findChild<QDockWidget*>(QStringLiteral("regionGraphDock"))->raise();
    QApplication::processEvents();
    QGraphicsView* view = graph()->graphicsView();
    ASSERT_NE(view, nullptr);
    // The largest region's node.
    QGraphicsItem* node = nullptr;
    std::uint32_t region = core::kNone;
    std::uint32_t largest = 0;
    for (QGraphicsItem* item : view->scene()->items()) {
        if (!item->data(0).isValid())
            continue;
        const auto id = std::uint32_t(item->data(0).toUInt());
        const std::uint32_t pixels =
            document().depthLayers()->segmentation.graph.regions[id].pixels;
        if (pixels > largest) {
            largest = pixels;
            node = item;
            region = id;
        }
    }
    ASSERT_NE(node, nullptr);
    EXPECT_EQ(viewport()->compositeOptions().highlightRegion, core::kNone);
    const QImage plain = grab();

    const QPoint centre = view->mapFromScene(node->scenePos());
    QTest::mouseMove(view->viewport(), centre);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return viewport()->compositeOptions().highlightRegion == region; }, 2000));
    EXPECT_GT(differingFraction(plain, grab()), 0.01);

    QSignalSpy activated(m_window.get(), &ui::MainWindow::regionActivated);
    QSignalSpy panelActivated(graph(), &ui::RegionGraphPanel::regionActivated);
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, centre);
    ASSERT_EQ(panelActivated.size(), 1);
    EXPECT_EQ(panelActivated.first().first().value<std::uint32_t>(), region);
    ASSERT_EQ(activated.size(), 1);
    EXPECT_EQ(graph()->selectedRegion(), region);
    // The click popped the region up (with its neighbours), as one undoable step.
    EXPECT_EQ(document().regionOrder().order().front(), region);
    EXPECT_EQ(m_window->undoStack()->count(), 1);

    // Leaving the node ends the highlight.
    QTest::mouseMove(view->viewport(), QPoint(2, 2));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return viewport()->compositeOptions().highlightRegion == core::kNone; }, 2000));
}

TEST_F(SegmentationTest, CameraChangeDropsTheLayersAndRebuildsAfterSettling) {
    openTrefoil();
    const int captures = builder()->captureCount();
    QSignalSpy built(builder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    QSignalSpy cleared(builder(), &ui::DepthLayersBuilder::depthLayersCleared);
    const std::uint64_t serial = viewport()->viewSerial();

    const QPoint start = viewport()->rect().center();
    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, start);
    QTest::mouseMove(viewport(), start + QPoint(20, 0));
    // Dropped at the first move: painting never sees layers of another view.
    EXPECT_EQ(document().depthLayers(), nullptr);
    EXPECT_FALSE(viewport()->isShowingDepthLayers());
    EXPECT_EQ(cleared.size(), 1);
    EXPECT_GT(viewport()->viewSerial(), serial);
    EXPECT_TRUE(builder()->isBuilding());
    // Held still mid-drag for longer than the settle delay: no capture under the cursor.
    QTest::qWait(builder()->settleDelay() * 2);
    EXPECT_EQ(builder()->captureCount(), captures);
    for (int i = 2; i <= 6; ++i)
        QTest::mouseMove(viewport(), start + QPoint(20 * i, 0));
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, start + QPoint(120, 0));
    EXPECT_EQ(builder()->captureCount(), captures);

    ASSERT_TRUE(built.wait(kBuildTimeoutMs));
    EXPECT_EQ(builder()->captureCount(), captures + 1);
    ASSERT_NE(document().depthLayers(), nullptr);
    EXPECT_TRUE(viewport()->isShowingDepthLayers());
    EXPECT_FALSE(builder()->isBuilding());
}

TEST_F(SegmentationTest, ResultOfAViewThatMovedOnIsDropped) {
    openTrefoil();
    QSignalSpy built(builder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    // Orbit, then wait for the capture (the worker then finishes it for ~50 ms) and zoom at once.
    orbitDrag(QPoint(60, 0));
    const int captures = builder()->captureCount();
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return builder()->captureCount() > captures; }, kBuildTimeoutMs));
    if (!built.isEmpty())
        GTEST_SKIP() << "the worker finished before the test could move the view";
    const QPointF pos = viewport()->rect().center();
    QWheelEvent wheel(pos, viewport()->mapToGlobal(pos), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &wheel);

    // The stale result is not adopted; the one after the zoom is (the fixture checks its view).
    ASSERT_TRUE(built.wait(kBuildTimeoutMs));
    EXPECT_EQ(built.size(), 1);
    EXPECT_EQ(builder()->captureCount(), captures + 2);
}

TEST_F(SegmentationTest, ViewMenuListsModesAndPanels) {
    for (const char* name : {"actionDisplayShaded", "actionDisplaySingleLayer",
                             "actionDisplaySegmentation", "actionShowBoundaries"}) {
        auto* action = m_window->findChild<QAction*>(QString::fromLatin1(name));
        ASSERT_NE(action, nullptr) << name;
        EXPECT_TRUE(action->isCheckable());
        EXPECT_FALSE(action->shortcut().isEmpty()) << name;
    }
    auto* panels = m_window->findChild<QMenu*>(QStringLiteral("panelsMenu"));
    ASSERT_NE(panels, nullptr);
    // Every panel and tool bar, and nothing else.
    const QList<QDockWidget*> docks = m_window->findChildren<QDockWidget*>();
    const QList<QToolBar*> bars = m_window->findChildren<QToolBar*>();
    qsizetype entries = 0;
    for (const QAction* action : panels->actions())
        entries += action->isSeparator() ? 0 : 1;
    EXPECT_EQ(entries, docks.size() + bars.size());
    for (QDockWidget* dock : docks)
        EXPECT_TRUE(panels->actions().contains(dock->toggleViewAction()))
            << dock->objectName().toStdString();
    for (QToolBar* bar : bars)
        EXPECT_TRUE(panels->actions().contains(bar->toggleViewAction()))
            << bar->objectName().toStdString();
    for (const char* name :
         {"segmentationDock", "layersDock", "regionGraphDock", "hiddenRegionsDock", "fillDock"}) {
        auto* dock = m_window->findChild<QDockWidget*>(QString::fromLatin1(name));
        ASSERT_NE(dock, nullptr) << name;
        EXPECT_FALSE(dock->isHidden()) << name; // paint-to-hide and fill are tabs behind
    }
    // The Fill and Paint to Hide tools' panels are tabs behind Segmentation until their tool is
    // chosen (a tab behind stays "visible", moved out of sight).
    auto* fillDock = m_window->findChild<QDockWidget*>(QStringLiteral("fillDock"));
    auto* hiddenDock = m_window->findChild<QDockWidget*>(QStringLiteral("hiddenRegionsDock"));
    auto* segmentation = m_window->findChild<QDockWidget*>(QStringLiteral("segmentationDock"));
    EXPECT_TRUE(m_window->tabifiedDockWidgets(segmentation).contains(fillDock));
    EXPECT_TRUE(m_window->tabifiedDockWidgets(segmentation).contains(hiddenDock));
    QApplication::processEvents();
    EXPECT_TRUE(fillDock->visibleRegion().isEmpty());
    EXPECT_FALSE(segmentation->visibleRegion().isEmpty());
    m_window->setTool(ui::Tool::Fill);
    QApplication::processEvents();
    EXPECT_FALSE(fillDock->visibleRegion().isEmpty());
    m_window->setTool(ui::Tool::Hide);
    QApplication::processEvents();
    EXPECT_FALSE(hiddenDock->visibleRegion().isEmpty());
    EXPECT_TRUE(fillDock->visibleRegion().isEmpty());

    // A closed panel stays closed in the next session.
    auto* graphDock = m_window->findChild<QDockWidget*>(QStringLiteral("regionGraphDock"));
    graphDock->toggleViewAction()->trigger();
    EXPECT_FALSE(graphDock->isVisible());
    m_window->close();
    m_window.reset();
    ui::MainWindow window;
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    EXPECT_FALSE(window.findChild<QDockWidget*>(QStringLiteral("regionGraphDock"))->isVisible());
    EXPECT_TRUE(window.findChild<QDockWidget*>(QStringLiteral("layersDock"))->isVisible());
}

TEST_F(SegmentationTest, ThresholdSliderIsLogarithmic) {
    using Controls = ui::SegmentationControls;
    EXPECT_NEAR(Controls::thresholdAt(0), 1e-5f, 1e-10f);
    EXPECT_NEAR(Controls::thresholdAt(Controls::sliderPositionFor(0.001f)), 0.001f, 1e-7f);
    EXPECT_NEAR(Controls::thresholdAt(4 * Controls::kStepsPerDecade), 0.1f, 1e-6f);
    EXPECT_EQ(Controls::sliderPositionFor(1.0f), 4 * Controls::kStepsPerDecade); // clamped
    EXPECT_EQ(Controls::formatThreshold(0.001f), QLocale().toString(0.001, 'f', 4));
    // The default shows at start.
    auto* value = m_window->findChild<QLabel*>(QStringLiteral("thresholdValue"));
    ASSERT_NE(value, nullptr);
    EXPECT_EQ(value->text(), Controls::formatThreshold(0.001f));
}

TEST_F(SegmentationTest, ConnectivityEngineChoiceGivesTheSameRegions) {
    openTrefoil();
    // On a software renderer Automatic means the C++ path.
    EXPECT_EQ(viewport()->connectivityBackend(), render::ConnectivityBackend::Cpu);
    const std::vector<std::uint8_t> cpuLinks = document().depthLayers()->connectivity.links;
    const std::size_t cpuRegions = document().depthLayers()->segmentation.graph.regions.size();

    auto* choice = m_window->findChild<QComboBox*>(QStringLiteral("connectivityBackend"));
    ASSERT_NE(choice, nullptr);
    QSignalSpy built(builder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    choice->setFocus();
    QTest::keyClick(choice, Qt::Key_End); // "Compute shader (graphics card)"
    EXPECT_EQ(choice->currentIndex(), 2);
    ASSERT_TRUE(built.wait(kBuildTimeoutMs));
    ASSERT_NE(document().depthLayers(), nullptr);
    EXPECT_EQ(viewport()->connectivityBackend(), render::ConnectivityBackend::Gpu);
    EXPECT_EQ(document().depthLayers()->connectivity.links, cpuLinks);
    EXPECT_EQ(document().depthLayers()->segmentation.graph.regions.size(), cpuRegions);
    EXPECT_EQ(QSettings().value(QStringLiteral("layers/connectivity")).toString(),
              QStringLiteral("gpu"));
}

} // namespace segmentation_uitest
