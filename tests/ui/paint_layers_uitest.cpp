// SPDX-License-Identifier: GPL-3.0-or-later
// The Paint Layers panel through real Qt events: a new layer (Ctrl+Shift+N), a stroke on the
// trefoil, multiply in the blend combo, the eye, and Ctrl+Z back through each step, with the
// document's stack and the painted bytes checked after every one. Needs a display with OpenGL 4.5
// (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QApplication>
#include <QColorDialog>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>
#include <QTreeWidget>
#include <QUndoStack>

#include <memory>
#include <optional>
#include <vector>

#include "core/document/document.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/panels/brush_panel.h"
#include "ui/panels/paint_layers_panel.h"
#include "ui/shell/main_window.h"
#include "ui/view/layer_builder.h"
#include "ui/view/viewport.h"

namespace {

using namespace ui_test;
using Panel = ui::PaintLayersPanel;

class PaintLayersUiTest : public WindowTest {
protected:
    PaintLayersUiTest() : WindowTest({1260, 860}) {}

    void SetUp() override {
        WindowTest::SetUp();
        if (HasFatalFailure())
            return;
        QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
        QSignalSpy built(m_window->layerBuilder(), &ui::LayerBuilder::layersBuilt);
        m_window->openFile(QStringLiteral("builtin:trefoil"));
        ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
        ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
        ASSERT_NE(doc().layers(), nullptr);
        // The panel shares its place with the Depth Layers: its tab to the front.
        auto* dock = m_window->findChild<QDockWidget*>(QStringLiteral("paintLayersDock"));
        ASSERT_NE(dock, nullptr);
        dock->raise();
        QApplication::processEvents();
    }

    core::Document& doc() { return m_window->document(); }
    Panel& panel() { return *m_window->paintLayersPanel(); }
    const core::TextureTarget* texture() {
        return doc().hasPaintTarget()
                   ? dynamic_cast<const core::TextureTarget*>(doc().paintTarget())
                   : nullptr;
    }
    /** The composite the view shows. */
    std::vector<std::uint8_t> composite() {
        const core::TextureTarget* target = texture();
        return target ? target->page(0).rgba : std::vector<std::uint8_t>{};
    }
    const core::PaintLayerStack& stack() { return texture()->layerStack(); }
    /** Every written tile of the layer's base colour plane, in order. */
    std::vector<std::uint8_t> layerColorBytes(std::size_t index) {
        std::vector<std::uint8_t> out;
        const core::TiledPlane* plane =
            stack().layer(index).channels[std::size_t(core::PaintChannel::BaseColor)].get();
        if (!plane)
            return out;
        for (const core::TileKey key : plane->writtenTiles()) {
            const core::TileRect rect = plane->tileRect(key.page, key.tile);
            const std::uint8_t* texels = plane->tile(key.page, key.tile);
            out.insert(out.end(), texels,
                       texels + std::size_t(rect.width) * std::size_t(rect.height) *
                                    std::size_t(plane->texelBytes()));
        }
        return out;
    }
    QImage thumbnailOf(QTreeWidgetItem* item) {
        return item->icon(Panel::ThumbnailColumn).pixmap(32, 32).toImage();
    }
    void undo() { QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier); }
};

TEST_F(PaintLayersUiTest, AddPaintMultiplyHideAndUndoEachStep) {
    ASSERT_TRUE(panel().disabledReason().isEmpty()) << panel().disabledReason().toStdString();
    QTreeWidget* list = panel().list();
    ASSERT_EQ(list->topLevelItemCount(), 1) << "only Base before any paint layer";
    QUndoStack* undoStack = m_window->undoStack();
    const int steps = undoStack->count();

    // 1. Ctrl+Shift+N: a paint layer on top of Base, selected.
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_NE(texture(), nullptr);
    ASSERT_EQ(stack().size(), 1u);
    const std::uint64_t id = stack().layer(0).id;
    EXPECT_EQ(texture()->selection(), (core::PaintSelection{id, false}));
    EXPECT_EQ(undoStack->count(), steps + 1);
    ASSERT_EQ(list->topLevelItemCount(), 2);
    EXPECT_EQ(list->topLevelItem(0)->data(0, Qt::UserRole).toULongLong(), id);
    EXPECT_EQ(list->topLevelItem(1)->text(Panel::NameColumn), QStringLiteral("Base"));
    const std::vector<std::uint8_t> original = composite();
    const std::vector<std::uint8_t> base = stack().baseColor(0);
    ASSERT_FALSE(original.empty());
    const QImage emptyThumbnail = thumbnailOf(panel().rowOf(id));

    // 2. A stroke on the trefoil paints the layer, not the base.
    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value()) << "no patch of the model in the view";
    core::Brush brush = doc().brush();
    brush.radius = 8.0f;
    brush.hardness = 1.0f;
    brush.color = {0.1f, 0.6f, 0.9f, 1.0f};
    m_window->setBrush(brush);
    ui::Viewport* viewport = m_window->viewport();
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, *start);
    for (int step = 1; step <= 6; ++step)
        QTest::mouseMove(viewport, *start + QPoint(2 * step, 0));
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, *start + QPoint(12, 0));
    EXPECT_EQ(undoStack->count(), steps + 2);
    const std::vector<std::uint8_t> layerPaint = layerColorBytes(0);
    EXPECT_FALSE(layerPaint.empty()) << "the stroke did not paint the layer";
    EXPECT_EQ(stack().baseColor(0), base) << "the stroke painted the base";
    const std::vector<std::uint8_t> painted = composite();
    EXPECT_NE(painted, original);
    EXPECT_NE(thumbnailOf(panel().rowOf(id)), emptyThumbnail) << "thumbnail not updated";

    // 3. Multiply, chosen in the combo with the keyboard (Normal is first, Multiply next).
    auto* blend = panel().findChild<QComboBox*>(QStringLiteral("paintLayerBlend"));
    ASSERT_NE(blend, nullptr);
    ASSERT_TRUE(blend->isEnabled());
    blend->setFocus();
    QTest::keyClick(blend, Qt::Key_Down);
    EXPECT_EQ(stack().layer(0).settings.blend, core::BlendMode::Multiply);
    EXPECT_EQ(undoStack->count(), steps + 3);
    const std::vector<std::uint8_t> multiplied = composite();
    EXPECT_NE(multiplied, painted);
    EXPECT_NE(multiplied, original);
    EXPECT_EQ(layerColorBytes(0), layerPaint) << "a blend mode changed the layer's texels";

    // 4. The eye hides it: the composite is the base's again, byte for byte.
    QTreeWidgetItem* row = panel().rowOf(id);
    ASSERT_NE(row, nullptr);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(row).topLeft() +
                          QPoint(list->columnViewportPosition(Panel::EyeColumn) +
                                     list->columnWidth(Panel::EyeColumn) / 2,
                                 list->visualItemRect(row).height() / 2));
    EXPECT_FALSE(stack().layer(0).settings.visible);
    EXPECT_EQ(undoStack->count(), steps + 4);
    EXPECT_EQ(composite(), original);

    // Selecting Base and the layer again (clicks on the names) adds no undo step.
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(panel().rowOf(0)).center());
    EXPECT_EQ(texture()->selection(), (core::PaintSelection{0, false}));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(panel().rowOf(id)).center());
    EXPECT_EQ(texture()->selection(), (core::PaintSelection{id, false}));
    EXPECT_EQ(undoStack->count(), steps + 4);

    // The window with the panel, to look at.
    const QString shot =
        QDir::current().absoluteFilePath(QStringLiteral("paint_layers_uitest.png"));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(panel().rowOf(id)).topLeft() +
                          QPoint(list->columnViewportPosition(Panel::EyeColumn) +
                                     list->columnWidth(Panel::EyeColumn) / 2,
                                 list->visualItemRect(panel().rowOf(id)).height() / 2));
    EXPECT_TRUE(stack().layer(0).settings.visible);
    EXPECT_TRUE(m_window->grab().save(shot));
    undo(); // the eye again
    EXPECT_FALSE(stack().layer(0).settings.visible);

    // 5. Ctrl+Z back through each step.
    undo(); // shown again
    EXPECT_TRUE(stack().layer(0).settings.visible);
    EXPECT_EQ(composite(), multiplied);
    undo(); // normal again
    EXPECT_EQ(stack().layer(0).settings.blend, core::BlendMode::Normal);
    EXPECT_EQ(composite(), painted);
    EXPECT_EQ(blend->currentIndex(), 0) << "the combo still shows the undone mode";
    undo(); // the stroke
    ASSERT_EQ(stack().size(), 1u);
    EXPECT_TRUE(layerColorBytes(0).empty());
    EXPECT_EQ(composite(), original);
    EXPECT_EQ(thumbnailOf(panel().rowOf(id)), emptyThumbnail);
    undo(); // the layer
    EXPECT_EQ(stack().size(), 0u);
    EXPECT_EQ(texture()->selection(), (core::PaintSelection{0, false}));
    EXPECT_EQ(composite(), original);
    EXPECT_EQ(stack().baseColor(0), base);
    EXPECT_EQ(list->topLevelItemCount(), 1);
    EXPECT_EQ(undoStack->index(), steps);
}

TEST_F(PaintLayersUiTest, AFillLayersValuesAreSetInThePanelOneUndoStepEach) {
    QUndoStack* undoStack = m_window->undoStack();
    auto* roughness = panel().findChild<QSpinBox*>(QStringLiteral("paintLayerFillRoughness"));
    auto* metallic = panel().findChild<QSpinBox*>(QStringLiteral("paintLayerFillMetallic"));
    auto* colorButton = panel().findChild<QToolButton*>(QStringLiteral("paintLayerFillColor"));
    ASSERT_TRUE(roughness && metallic && colorButton);
    // A paint layer has no fill values: the rows are hidden.
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_FALSE(roughness->isVisible());
    EXPECT_FALSE(colorButton->isVisible());

    // New Fill Layer, by its button in the panel.
    QToolButton* fillButton = nullptr;
    for (QToolButton* button : panel().findChildren<QToolButton*>())
        if (button->defaultAction() == panel().newFillLayerAction())
            fillButton = button;
    ASSERT_NE(fillButton, nullptr);
    core::Brush brush = doc().brush();
    brush.paintBaseColor = true;
    brush.paintRoughness = false;
    brush.paintMetallic = false;
    m_window->setBrush(brush);
    QTest::mouseClick(fillButton, Qt::LeftButton);
    ASSERT_EQ(stack().size(), 2u);
    const core::PaintLayer& fill = stack().layer(1);
    ASSERT_EQ(fill.settings.kind, core::PaintLayerKind::Fill);
    ASSERT_EQ(texture()->selection().layer, fill.id);
    ASSERT_TRUE(roughness->isVisible());
    ASSERT_TRUE(colorButton->isVisible());
    EXPECT_EQ(roughness->text(), roughness->specialValueText()) << "roughness is off";
    const int steps = undoStack->count();
    const std::vector<std::uint8_t> mrBefore = texture()->metallicRoughnessPage(0).rgba;
    const std::vector<std::uint8_t> colorBefore = composite();

    // Roughness 40 %, typed: one undo step, the composite's roughness changes.
    QTest::mouseDClick(roughness, Qt::LeftButton);
    QTest::keyClick(roughness, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(roughness, QStringLiteral("40"));
    QTest::keyClick(roughness, Qt::Key_Return);
    ASSERT_TRUE(stack().layer(1).settings.fill.roughness.has_value());
    EXPECT_FLOAT_EQ(*stack().layer(1).settings.fill.roughness, 0.4f);
    EXPECT_FALSE(stack().layer(1).settings.fill.metallic.has_value());
    EXPECT_EQ(undoStack->count(), steps + 1);
    const std::vector<std::uint8_t> mrRough = texture()->metallicRoughnessPage(0).rgba;
    EXPECT_NE(mrRough, mrBefore);

    // The colour button opens a colour dialog; Return takes its colour.
    QTest::mouseClick(colorButton, Qt::LeftButton);
    QColorDialog* dialog = nullptr;
    ASSERT_TRUE(QTest::qWaitFor([&] {
        dialog = panel().findChild<QColorDialog*>(QStringLiteral("paintLayerFillColorDialog"));
        return dialog != nullptr && dialog->isVisible();
    }));
    dialog->setCurrentColor(QColor(255, 0, 0));
    QTest::keyClick(dialog, Qt::Key_Return);
    ASSERT_TRUE(stack().layer(1).settings.fill.baseColor.has_value());
    EXPECT_EQ(*stack().layer(1).settings.fill.baseColor, glm::vec3(1.0f, 0.0f, 0.0f));
    EXPECT_EQ(undoStack->count(), steps + 2);
    const std::vector<std::uint8_t> red = composite();
    EXPECT_NE(red, colorBefore);

    // Ctrl+Z undoes each: the colour, then the roughness; the fields follow.
    undo();
    EXPECT_EQ(composite(), colorBefore);
    EXPECT_EQ(texture()->metallicRoughnessPage(0).rgba, mrRough);
    undo();
    EXPECT_FALSE(stack().layer(1).settings.fill.roughness.has_value());
    EXPECT_EQ(texture()->metallicRoughnessPage(0).rgba, mrBefore);
    EXPECT_EQ(roughness->value(), roughness->minimum());
}

TEST_F(PaintLayersUiTest, VertexColoursDisableThePanelAndTheMaterialChannels) {
    core::PaintTargetOptions options = doc().paintTargetOptions();
    options.kind = core::PaintTargetKind::VertexColors;
    ASSERT_TRUE(doc().setPaintTarget(options).ok());
    m_window->showDocumentState();
    EXPECT_FALSE(panel().disabledReason().isEmpty());
    EXPECT_FALSE(panel().list()->isEnabled());
    EXPECT_FALSE(panel().newLayerAction()->isEnabled());
    auto* roughness =
        m_window->brushPanel()->findChild<QWidget*>(QStringLiteral("brushPanelPaintRoughness"));
    ASSERT_NE(roughness, nullptr);
    EXPECT_FALSE(roughness->isEnabled());
    // Ctrl+Shift+N does nothing there.
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_EQ(texture(), nullptr);
}

} // namespace
