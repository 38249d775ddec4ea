// SPDX-License-Identifier: GPL-3.0-or-later
// Painting in the Single Layer display through real Qt events: the layer shown is the one painted.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QListWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>

#include <memory>
#include <optional>
#include <vector>

#include "core/document/document.h"
#include "tests/core/captured_scenes.h"
#include "tests/ui/ui_test_util.h"
#include "ui/panels/depth_layers_panel.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace single_layer_uitest {

using namespace ui_test;

TEST(SingleLayerTest, AStrokeInTheLayerTwoViewPaintsLayerTwoNotTheFrontStrand) {
    QSettings().clear();
    auto window = std::make_unique<ui::MainWindow>();
    window->setErrorDialogsEnabled(false);
    window->resize(1260, 760);
    window->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(window.get()));
    ui::Viewport* viewport = window->viewport();
    core::Document& doc = window->document();
    {
        QSignalSpy loaded(window.get(), &ui::MainWindow::modelLoaded);
        QSignalSpy built(window->depthLayersBuilder(), &ui::DepthLayersBuilder::depthLayersBuilt);
        window->openFile(QStringLiteral("builtin:trefoil"));
        ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
        ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
    }
    ASSERT_NE(doc.depthLayers(), nullptr);
    ASSERT_EQ(viewport->devicePixelRatioF(), 1.0);

    // Layer 2 alone, chosen with a click in the Depth Layers panel.
    auto* list = window->depthLayersPanel()->findChild<QListWidget*>(QStringLiteral("layerList"));
    ASSERT_NE(list, nullptr);
    QListWidgetItem* second = nullptr;
    for (int row = 0; row < list->count(); ++row)
        if (list->item(row)->text().contains(QStringLiteral("2")))
            second = list->item(row);
    ASSERT_NE(second, nullptr);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(second).center());
    ASSERT_EQ(viewport->display(), render::DepthLayerDisplay::SingleLayer);
    ASSERT_EQ(viewport->displayLayer(), 2u);
    EXPECT_EQ(doc.shownLayer(), 2u);

    // A crossing: the front strand on layer 1 well in front of the strand on layer 2.
    const core::DepthStack& stack = doc.depthLayers()->stack;
    const auto index = [&](int x, int y) {
        return std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
    };
    const auto crossing = [&](int x, int y) { return core_test::isCrossing(stack, x, y); };
    constexpr int kRadius = 6;
    std::optional<QPoint> start;
    for (int y = 0; y < stack.height && !start; y += 2)
        for (int x = 0; x < stack.width && !start; x += 2) {
            bool inside = true;
            for (int dy = -2 * kRadius; inside && dy <= 2 * kRadius + 8; dy += 2)
                for (int dx = -2 * kRadius; inside && dx <= 2 * kRadius; dx += 2)
                    inside = crossing(x + dx, y + dy);
            if (inside)
                start = QPoint(x, y);
        }
    ASSERT_TRUE(start.has_value()) << "no crossing in the view";
    core::Brush brush = doc.brush();
    brush.radius = float(kRadius);
    brush.hardness = 1.0f;
    window->setBrush(brush);

    // What each strand looks like around the stroke (the eyedropper on each layer).
    const auto colors = [&](std::uint32_t layer) {
        const std::uint32_t shown = doc.shownLayer();
        doc.setShownLayer(layer);
        std::vector<glm::vec4> result;
        for (int dy = -3 * kRadius; dy <= 3 * kRadius + 8; ++dy)
            for (int dx = -3 * kRadius; dx <= 3 * kRadius; ++dx)
                if (crossing(start->x() + dx, start->y() + dy))
                    result.push_back(doc.pickColor(index(start->x() + dx, start->y() + dy))
                                         .value_or(glm::vec4(-1.0f)));
        doc.setShownLayer(shown);
        return result;
    };
    const std::vector<glm::vec4> frontBefore = colors(1), backBefore = colors(2);

    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, *start);
    for (int step = 1; step <= 4; ++step)
        QTest::mouseMove(viewport, *start + QPoint(0, 2 * step));
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, *start + QPoint(0, 8));

    const std::vector<glm::vec4> frontAfter = colors(1), backAfter = colors(2);
    std::size_t frontChanged = 0, backChanged = 0;
    for (std::size_t i = 0; i < frontBefore.size(); ++i) {
        frontChanged += frontAfter[i] != frontBefore[i];
        backChanged += backAfter[i] != backBefore[i];
    }
    EXPECT_GT(backChanged, 20u) << "the stroke did not paint the layer shown";
    EXPECT_EQ(frontChanged, 0u) << "the stroke painted the front strand";

    // Back to the whole picture: what is drawn in front is painted again.
    window->findChild<QAction*>(QStringLiteral("actionDisplayShaded"))->trigger();
    EXPECT_EQ(doc.shownLayer(), 0u);
    window.reset();
    QSettings().clear();
}

} // namespace single_layer_uitest
