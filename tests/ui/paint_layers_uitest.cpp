// SPDX-License-Identifier: GPL-3.0-or-later
// The Paint Layers panel through real Qt events: a new layer (Ctrl+Shift+N), a stroke on the
// trefoil, multiply in the blend combo, the eye, and Ctrl+Z back through each step, with the
// document's stack and the painted bytes checked after every one. Needs a display with OpenGL 4.5
// (run under xvfb-run; Mesa llvmpipe is enough). Also: File ▸ Export with "each paint layer as
// images" writes the files `layerpaint-cli export --per-layer` writes for the same project.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDrag>
#include <QFileDialog>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QTreeWidget>
#include <QUndoStack>
#include <QWindow>

#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/document/document.h"
#include "core/io/paint_layers_export.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/panels/brush_panel.h"
#include "ui/panels/paint_layers_panel.h"
#include "ui/shell/main_window.h"
#include "ui/shell/project_controller.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace paint_layers_uitest {

using namespace ui_test;
using Panel = ui::PaintLayersPanel;

constexpr int kSaveTimeoutMs = 120000;
constexpr int kCliTimeoutMs = 300000;

/** The pixels of an image file (RGBA8), empty if it cannot be read. */
QImage pixelsOf(const QString& file) {
    return QImage(file).convertToFormat(QImage::Format_RGBA8888);
}

class PaintLayersUiTest : public WindowTest {
protected:
    PaintLayersUiTest() : WindowTest({1260, 860}) {}

    void SetUp() override {
        WindowTest::SetUp();
        if (HasFatalFailure())
            return;
        QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
        QSignalSpy built(m_window->depthLayersBuilder(), &ui::DepthLayersBuilder::depthLayersBuilt);
        m_window->openFile(QStringLiteral("builtin:trefoil"));
        ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
        ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
        ASSERT_NE(doc().depthLayers(), nullptr);
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
    const core::PaintLayerStack& stack() { return texture()->paintLayerStack(); }
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
    /** The panel's New Fill Layer button. */
    QToolButton* fillButton() {
        for (QToolButton* button : panel().findChildren<QToolButton*>())
            if (button->defaultAction() == panel().newFillLayerAction())
                return button;
        return nullptr;
    }
    QImage thumbnailOf(QTreeWidgetItem* item) {
        return item->icon(Panel::ThumbnailColumn).pixmap(32, 32).toImage();
    }
    void undo() { QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier); }
    /** A short horizontal stroke of colour from start with the mouse. */
    void stroke(QPoint start, glm::vec4 color) {
        core::Brush brush = doc().brush();
        brush.radius = 8.0f;
        brush.hardness = 1.0f;
        brush.color = color;
        m_window->setBrush(brush);
        ui::Viewport* viewport = m_window->viewport();
        QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, start);
        for (int step = 1; step <= 6; ++step)
            QTest::mouseMove(viewport, start + QPoint(2 * step, 0));
        QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, start + QPoint(12, 0));
    }
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

TEST_F(PaintLayersUiTest, WhatStrokesPaintIsFramedInAmberAndSaidInTheStatusBar) {
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_NE(texture(), nullptr);
    const std::uint64_t id = stack().layer(0).id;
    const QString name = QString::fromStdString(stack().layer(0).settings.name);
    panel().addMaskAction()->trigger();
    ASSERT_TRUE(stack().layer(0).mask);
    auto* info = m_window->findChild<QLabel*>(QStringLiteral("paintIntoInfo"));
    ASSERT_NE(info, nullptr);
    QTreeWidget* list = panel().list();
    const auto columnPoint = [&](int column) {
        const QRect row = list->visualItemRect(panel().rowOf(id));
        return QPoint(list->columnViewportPosition(column) + list->columnWidth(column) / 2,
                      row.center().y());
    };
    // The amber frame's corner, on the thumbnail painted and not on the other.
    const auto amber = [&](int column) {
        const QImage icon = panel().rowOf(id)->icon(column).pixmap(32, 32).toImage();
        const QColor corner = icon.pixelColor(1, 1);
        return corner.red() > 200 && corner.green() > 120 && corner.green() < 190 &&
               corner.blue() < 60;
    };

    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      columnPoint(Panel::MaskColumn));
    ASSERT_EQ(texture()->selection(), (core::PaintSelection{id, true}));
    EXPECT_EQ(info->text(), QStringLiteral("Painting the mask of “%1”").arg(name));
    EXPECT_TRUE(amber(Panel::MaskColumn));
    EXPECT_FALSE(amber(Panel::ThumbnailColumn));

    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      columnPoint(Panel::NameColumn));
    ASSERT_EQ(texture()->selection(), (core::PaintSelection{id, false}));
    EXPECT_EQ(info->text(), QStringLiteral("Painting “%1”").arg(name));
    EXPECT_TRUE(amber(Panel::ThumbnailColumn));
    EXPECT_FALSE(amber(Panel::MaskColumn));

    // Base: nothing to say.
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(panel().rowOf(0)).center());
    EXPECT_TRUE(info->text().isEmpty());
}

TEST_F(PaintLayersUiTest, AltClickOnAMaskShowsItAloneAndAStrokeOnItShowsAsItGoes) {
    // A red fill layer with a mask, a black stroke on the mask hiding the red there.
    core::Brush red = doc().brush();
    red.color = {1.0f, 0.0f, 0.0f, 1.0f};
    m_window->setBrush(red);
    QTest::mouseClick(fillButton(), Qt::LeftButton);
    ASSERT_EQ(stack().size(), 1u);
    const std::uint64_t id = stack().layer(0).id;
    panel().addMaskAction()->trigger();
    ASSERT_TRUE(stack().layer(0).mask);
    QTreeWidget* list = panel().list();
    const auto maskPoint = [&] {
        const QRect row = list->visualItemRect(panel().rowOf(id));
        return QPoint(list->columnViewportPosition(Panel::MaskColumn) +
                          list->columnWidth(Panel::MaskColumn) / 2,
                      row.center().y());
    };
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier, maskPoint());
    ASSERT_EQ(texture()->selection(), (core::PaintSelection{id, true}));
    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value());
    const QPoint middle = *start + QPoint(6, 0);
    stroke(*start, {0.0f, 0.0f, 0.0f, 1.0f});
    ui::Viewport* viewport = m_window->viewport();
    const auto frame = [&] {
        QApplication::processEvents();
        return grab().convertToFormat(QImage::Format_RGB888);
    };
    const auto redPixels = [](const QImage& image) {
        int n = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                n += c.red() > c.green() + 60;
            }
        return n;
    };
    const auto grey = [](QColor c) {
        return std::abs(c.red() - c.green()) <= 2 && std::abs(c.green() - c.blue()) <= 2;
    };
    QImage shown = frame();
    EXPECT_GT(redPixels(shown), 1000) << "the red fill layer does not show";

    // Alt+click on the mask: the mask alone, unlit grey: black under the stroke, white elsewhere.
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::AltModifier, maskPoint());
    EXPECT_EQ(viewport->maskView(), id);
    EXPECT_EQ(texture()->selection(), (core::PaintSelection{id, true})) << "still painting it";
    shown = frame();
    EXPECT_EQ(redPixels(shown), 0) << "the mask view shows the paint layers' colour";
    QColor c = shown.pixelColor(middle);
    EXPECT_TRUE(grey(c) && c.red() < 40) << c.name().toStdString();
    int white = 0;
    for (int y = 0; y < shown.height(); ++y)
        for (int x = 0; x < shown.width(); ++x)
            white += grey(shown.pixelColor(x, y)) && shown.pixelColor(x, y).red() > 235;
    EXPECT_GT(white, 1000) << "the unpainted mask does not show white";
    EXPECT_TRUE(m_window->statusBar()->currentMessage().contains(QStringLiteral("Alt+click")));

    // A white stroke on the mask shows in the mask view as it is painted.
    stroke(*start, {1.0f, 1.0f, 1.0f, 1.0f});
    c = frame().pixelColor(middle);
    EXPECT_TRUE(grey(c) && c.red() > 235) << c.name().toStdString();

    // Alt+click again: the paint layers, the red back where the mask is white again.
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::AltModifier, maskPoint());
    EXPECT_EQ(viewport->maskView(), 0u);
    shown = frame();
    EXPECT_GT(redPixels(shown), 1000);
    c = shown.pixelColor(middle);
    EXPECT_GT(c.red(), c.green() + 60) << c.name().toStdString();

    // The view ends by itself when the mask goes (here: deleted while shown).
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::AltModifier, maskPoint());
    ASSERT_EQ(viewport->maskView(), id);
    panel().deleteMaskAction()->trigger();
    EXPECT_TRUE(QTest::qWaitFor([&] {
        frame();
        return viewport->maskView() == 0;
    }));
    EXPECT_GT(redPixels(frame()), 1000);
}

TEST_F(PaintLayersUiTest, TheTextureSetBoxChoosesWhichSetsPaintTheThumbnailsShow) {
    auto* box = panel().findChild<QComboBox*>(QStringLiteral("textureSetBox"));
    ASSERT_NE(box, nullptr);
    EXPECT_FALSE(box->isVisibleTo(&panel())) << "one texture set: no box";

    // Two materials with textures of their own: two texture sets, named by their materials.
    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    QSignalSpy built(m_window->depthLayersBuilder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    m_window->openFile(QStringLiteral(LAYERPAINT_TEST_DATA) +
                       QStringLiteral("/material/materials.glb"));
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
    ASSERT_NE(texture(), nullptr);
    ASSERT_EQ(texture()->pageCount(), 2u);
    EXPECT_TRUE(box->isVisibleTo(&panel()));
    ASSERT_EQ(box->count(), 2);
    const core::Mesh& mesh = doc().mesh();
    for (std::size_t m = 0; m < mesh.materials.size(); ++m)
        EXPECT_TRUE(box->itemText(int(texture()->materialPage(m)))
                        .contains(QString::fromStdString(mesh.materials[m].name)))
            << box->itemText(int(texture()->materialPage(m))).toStdString();

    // A stroke on one quad paints one set; the thumbnail shows it for that set only.
    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value());
    const QImage before = thumbnailOf(panel().rowOf(stack().layer(0).id));
    stroke(*start, {0.1f, 0.9f, 0.2f, 1.0f});
    const core::TiledPlane* plane = stack().layer(0).channels[0].get();
    ASSERT_NE(plane, nullptr);
    const std::uint32_t painted = plane->anyTile(0) ? 0 : 1;
    ASSERT_TRUE(plane->anyTile(painted));
    ASSERT_FALSE(plane->anyTile(1 - painted));
    const auto shown = [&] { return thumbnailOf(panel().rowOf(stack().layer(0).id)); };
    box->setFocus();
    while (box->currentIndex() != int(painted))
        QTest::keyClick(box, box->currentIndex() < int(painted) ? Qt::Key_Down : Qt::Key_Up);
    EXPECT_NE(shown(), before) << "the painted set's thumbnail shows no paint";
    QTest::keyClick(box, painted == 0 ? Qt::Key_Down : Qt::Key_Up);
    EXPECT_EQ(box->currentIndex(), int(1 - painted));
    EXPECT_EQ(shown(), before) << "the other set's thumbnail shows paint it does not have";
}

TEST_F(PaintLayersUiTest, AStrokeOnAFillLayerSaysWhyAndOffersItsMaskOrAPaintLayer) {
    QTest::mouseClick(fillButton(), Qt::LeftButton);
    ASSERT_EQ(stack().size(), 1u);
    const std::uint64_t fill = stack().layer(0).id;
    ASSERT_EQ(stack().layer(0).settings.kind, core::PaintLayerKind::Fill);
    QUndoStack* undoStack = m_window->undoStack();
    const int steps = undoStack->count();
    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value());

    // The stroke paints nothing and makes no step, but says why and offers a way on.
    stroke(*start, {0.9f, 0.1f, 0.1f, 1.0f});
    EXPECT_EQ(undoStack->count(), steps);
    EXPECT_TRUE(m_window->statusBar()->currentMessage().contains(QStringLiteral("fill layer")))
        << m_window->statusBar()->currentMessage().toStdString();
    QMessageBox* offer = nullptr;
    ASSERT_TRUE(QTest::qWaitFor([&] {
        offer = m_window->findChild<QMessageBox*>(QStringLiteral("fillLayerOffer"));
        return offer != nullptr && offer->isVisible();
    }));
    auto* above = offer->findChild<QPushButton*>(QStringLiteral("fillLayerOfferPaintLayer"));
    ASSERT_NE(above, nullptr);
    QTest::mouseClick(above, Qt::LeftButton);
    ASSERT_EQ(stack().size(), 2u);
    EXPECT_EQ(stack().layer(0).id, fill);
    EXPECT_EQ(texture()->selection(), (core::PaintSelection{stack().layer(1).id, false}));
    stroke(*start, {0.9f, 0.1f, 0.1f, 1.0f});
    EXPECT_FALSE(layerColorBytes(1).empty()) << "the paint layer above was not painted";

    // Back on the fill layer, the other choice: a mask, made and selected.
    ASSERT_TRUE(doc().selectPaint({fill, false}).ok());
    stroke(*start, {0.9f, 0.1f, 0.1f, 1.0f});
    ASSERT_TRUE(QTest::qWaitFor([&] {
        offer = m_window->findChild<QMessageBox*>(QStringLiteral("fillLayerOffer"));
        return offer != nullptr && offer->isVisible();
    }));
    QTest::mouseClick(offer->findChild<QPushButton*>(QStringLiteral("fillLayerOfferMask")),
                      Qt::LeftButton);
    ASSERT_NE(stack().layer(0).mask, nullptr);
    EXPECT_EQ(texture()->selection(), (core::PaintSelection{fill, true}));
}

TEST_F(PaintLayersUiTest, AFillLayersValuesAreSetInThePanelOneUndoStepEach) {
    QUndoStack* undoStack = m_window->undoStack();
    auto* roughness = panel().findChild<QDoubleSpinBox*>(QStringLiteral("paintLayerFillRoughness"));
    auto* metallic = panel().findChild<QDoubleSpinBox*>(QStringLiteral("paintLayerFillMetallic"));
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

    // Roughness 0.4 (0..1, as the Brush panel and glTF give it), typed: one undo step, the
    // composite's roughness changes.
    QTest::mouseDClick(roughness, Qt::LeftButton);
    QTest::keyClick(roughness, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(roughness, QStringLiteral("0.4"));
    QTest::keyClick(roughness, Qt::Key_Return);
    ASSERT_TRUE(stack().layer(1).settings.fill.roughness.has_value());
    EXPECT_FLOAT_EQ(*stack().layer(1).settings.fill.roughness, 0.4f);
    EXPECT_FALSE(stack().layer(1).settings.fill.metallic.has_value());
    EXPECT_EQ(undoStack->count(), steps + 1);
    // A value typed as a percentage is read as one: 40 is 0.40 (no change, no step).
    QTest::keyClick(roughness, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(roughness, QStringLiteral("40"));
    QTest::keyClick(roughness, Qt::Key_Return);
    EXPECT_FLOAT_EQ(*stack().layer(1).settings.fill.roughness, 0.4f);
    EXPECT_EQ(roughness->text(), roughness->textFromValue(0.4));
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

// A real drag: the mouse pressed on a row, moved past the drag distance (QDrag::exec() runs its
// own loop from there, on the X11 platform plugin's drag), moved over the upper row and
// released. Events go in through QWindowSystemInterface, as the platform plugin delivers them.
TEST_F(PaintLayersUiTest, DraggingARowReordersThePaintLayersOneUndoStep) {
    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value()) << "no patch of the model in the view";
    // Two layers painted over the same spot: the upper one's blue covers the lower one's red.
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
    stroke(*start, {0.9f, 0.1f, 0.1f, 1.0f});
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
    stroke(*start, {0.1f, 0.2f, 0.9f, 1.0f});
    ASSERT_EQ(stack().size(), 2u);
    const std::uint64_t red = stack().layer(0).id;
    const std::uint64_t blue = stack().layer(1).id;
    const std::vector<std::uint8_t> blueOnTop = composite();
    QUndoStack* undoStack = m_window->undoStack();
    const int steps = undoStack->count();

    QTreeWidget* list = panel().list();
    ASSERT_EQ(list->topLevelItemCount(), 3); // blue, red, Base
    ASSERT_EQ(panel().rowOf(blue), list->topLevelItem(0));
    QWindow* window = m_window->windowHandle();
    ASSERT_NE(window, nullptr);
    const auto inWindow = [&](QPoint inViewport) {
        return window->mapFromGlobal(list->viewport()->mapToGlobal(inViewport));
    };
    const QRect redRow = list->visualItemRect(panel().rowOf(red));
    const QRect blueRow = list->visualItemRect(panel().rowOf(blue));
    const int nameX = list->columnViewportPosition(Panel::NameColumn) + 10;
    const QPoint from(nameX, redRow.center().y());
    const QPoint over(nameX, blueRow.top() + 2); // the upper edge: above the blue row
    QCursor::setPos(list->viewport()->mapToGlobal(from));

    // Once the drag runs its loop (the list owns its QDrag then; a tick before that, say while
    // a loaded machine still delivers the first moves, waits for the next): over the blue row in
    // steps, then the release. A guard ends a drag that never ends (Escape cancels it) so the
    // test fails instead of hanging.
    bool dragLoopRan = false;
    QTimer steer;
    QObject::connect(&steer, &QTimer::timeout, [&] {
        if (!list->findChild<QDrag*>())
            return;
        steer.stop();
        dragLoopRan = true;
        for (int i = 1; i <= 4; ++i)
            QTest::mouseMove(window, inWindow(from + (over - from) * i / 4));
        QTest::mouseRelease(window, Qt::LeftButton, Qt::NoModifier, inWindow(over));
    });
    QTimer guard;
    guard.setSingleShot(true);
    QObject::connect(&guard, &QTimer::timeout, [&] {
        if (QGuiApplication::focusWindow())
            QTest::keyClick(QGuiApplication::focusWindow(), Qt::Key_Escape);
    });
    QTest::mousePress(window, Qt::LeftButton, Qt::NoModifier, inWindow(from));
    ASSERT_EQ(list->currentItem(), panel().rowOf(red));
    steer.start(50);
    guard.start(20000);
    const int distance = QApplication::startDragDistance() + 4;
    for (int i = 1; i <= 3; ++i) // the move that starts the drag returns when it has ended
        QTest::mouseMove(window, inWindow(from - QPoint(0, distance * i / 3)));
    guard.stop();
    if (!dragLoopRan) // no drag started: release the button anyway
        QTest::mouseRelease(window, Qt::LeftButton, Qt::NoModifier, inWindow(over));
    ASSERT_TRUE(dragLoopRan) << "no drag started";
    // The move is applied once the drag has ended.
    ASSERT_TRUE(QTest::qWaitFor([&] { return stack().layer(1).id == red; }, 5000))
        << "the drop did not reorder the paint layers";

    EXPECT_EQ(stack().layer(0).id, blue);
    EXPECT_EQ(undoStack->count(), steps + 1);
    EXPECT_EQ(list->topLevelItem(0)->data(0, Qt::UserRole).toULongLong(), red);
    EXPECT_EQ(list->topLevelItem(1)->data(0, Qt::UserRole).toULongLong(), blue);
    const std::vector<std::uint8_t> redOnTop = composite();
    ASSERT_EQ(redOnTop.size(), blueOnTop.size());
    // Where both painted, red now covers blue; nowhere else does anything change colour.
    int redder = 0;
    for (std::size_t i = 0; i + 3 < redOnTop.size(); i += 4)
        redder += redOnTop[i] > blueOnTop[i] + 100 && redOnTop[i + 2] + 100 < blueOnTop[i + 2];
    EXPECT_GT(redder, 0) << "the composite does not show the red layer on top";

    // One Ctrl+Z puts the order and the composite back.
    undo();
    EXPECT_EQ(stack().layer(0).id, red);
    EXPECT_EQ(stack().layer(1).id, blue);
    EXPECT_EQ(composite(), blueOnTop);
    EXPECT_EQ(undoStack->index(), steps);
    EXPECT_EQ(list->topLevelItem(0)->data(0, Qt::UserRole).toULongLong(), blue);
}

TEST_F(PaintLayersUiTest, ExportWritesEachPaintLayerAsTheCommandLineDoes) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    // Two paint layers, each with a stroke of its own colour; the upper one gets a mask too.
    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value()) << "no patch of the model in the view";
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
    stroke(*start, {0.9f, 0.2f, 0.1f, 1.0f});
    QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
    stroke(*start + QPoint(0, 6), {0.1f, 0.3f, 0.9f, 1.0f});
    ASSERT_EQ(stack().size(), 2u);
    ASSERT_FALSE(layerColorBytes(0).empty());
    ASSERT_FALSE(layerColorBytes(1).empty());

    ui::ProjectController* project = m_window->projectController();
    ASSERT_TRUE(project->hasPaintLayers());
    const QString projectFile = dir.filePath(QStringLiteral("layers.glb"));
    QSignalSpy saved(project, &ui::ProjectController::saved);
    ASSERT_TRUE(project->saveTo(projectFile));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !saved.isEmpty(); }, kSaveTimeoutMs));

    // File ▸ Export ▸ PNG: the box is off at first; the artist ticks it, names the file and
    // presses Return.
    QSignalSpy exported(project, &ui::ProjectController::exported);
    QSignalSpy failed(project, &ui::ProjectController::exportFailed);
    auto* exportPng = m_window->findChild<QAction*>(QStringLiteral("actionExportPng8"));
    ASSERT_NE(exportPng, nullptr);
    bool wasChecked = true;
    bool enabled = false;
    onNextModal<QFileDialog>([&](QFileDialog* dialog) {
        auto* box = dialog->findChild<QCheckBox*>(QStringLiteral("exportPerPaintLayer"));
        auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
        if (!box || !name) {
            dialog->reject();
            return;
        }
        wasChecked = box->isChecked();
        enabled = box->isEnabled();
        QTest::mouseClick(box, Qt::LeftButton, Qt::NoModifier, QPoint(8, box->height() / 2));
        name->setFocus();
        name->selectAll();
        QTest::keyClicks(name, dir.filePath(QStringLiteral("gui.png")));
        // The dialog with the box ticked, to look at.
        dialog->grab().save(QDir::current().absoluteFilePath(QStringLiteral("export_dialog.png")));
        QTest::keyClick(name, Qt::Key_Return);
    });
    exportPng->trigger();
    EXPECT_FALSE(wasChecked) << "the box starts ticked";
    ASSERT_TRUE(enabled) << "the box is disabled with paint layers";
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return !exported.isEmpty() || !failed.isEmpty(); }, kSaveTimeoutMs));
    ASSERT_TRUE(failed.isEmpty()) << failed.first().first().toString().toStdString();
    const QStringList guiFiles = exported.first().first().toStringList();
    EXPECT_TRUE(QSettings().value(QStringLiteral("export/perPaintLayer")).toBool())
        << "the choice is not remembered";

    // The same project through the headless tool.
    QProcess cli;
    cli.start(QStringLiteral(LAYERPAINT_CLI),
              {QStringLiteral("export"), projectFile, QStringLiteral("--out"),
               dir.filePath(QStringLiteral("cli.png")), QStringLiteral("--per-layer")});
    ASSERT_TRUE(cli.waitForFinished(kCliTimeoutMs));
    ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();
    const nlohmann::json report = nlohmann::json::parse(cli.readAllStandardOutput().toStdString());
    QStringList cliFiles;
    for (const auto& file : report["files"])
        cliFiles.append(QString::fromStdString(file.get<std::string>()));

    // The same files (but for the stem) with the same pixels, per paint layer at least its
    // base colour; the lower layer's is its red stroke.
    ASSERT_EQ(guiFiles.size(), cliFiles.size());
    int layerFiles = 0;
    for (int i = 0; i < guiFiles.size(); ++i) {
        const QString gui = QFileInfo(guiFiles[i]).fileName();
        const QString headless = QFileInfo(cliFiles[i]).fileName();
        EXPECT_EQ(gui.mid(3), headless.mid(3)); // "gui…" and "cli…"
        ASSERT_TRUE(QFileInfo::exists(guiFiles[i])) << guiFiles[i].toStdString();
        const QImage a = pixelsOf(guiFiles[i]);
        ASSERT_FALSE(a.isNull()) << gui.toStdString();
        EXPECT_TRUE(a == pixelsOf(cliFiles[i])) << gui.toStdString() << " differs from the CLI's";
        if (gui.contains(QStringLiteral("_layer-")))
            ++layerFiles;
    }
    const QString lower = dir.filePath(
        QStringLiteral("gui_layer-1-") +
        QString::fromStdString(core::sanitizeLayerName(stack().layer(0).settings.name)) +
        QStringLiteral("_basecolor.png"));
    ASSERT_TRUE(guiFiles.contains(lower)) << lower.toStdString();
    EXPECT_TRUE(guiFiles.contains(
        QString(lower)
            .replace(QStringLiteral("layer-1-"), QStringLiteral("layer-2-"))
            .replace(
                QString::fromStdString(core::sanitizeLayerName(stack().layer(0).settings.name)),
                QString::fromStdString(core::sanitizeLayerName(stack().layer(1).settings.name)))));
    EXPECT_GE(layerFiles, 2);
    const QImage image = pixelsOf(lower);
    const core::TiledPlane* plane =
        stack().layer(0).channels[std::size_t(core::PaintChannel::BaseColor)].get();
    ASSERT_NE(plane, nullptr);
    ASSERT_EQ(image.width(), plane->pages()[0].width);
    int covered = 0;
    int same = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const std::uint8_t* t = plane->texel(0, x, y);
            if (t[3] == 0)
                continue;
            ++covered;
            const QRgb p = image.pixel(x, y);
            same += qRed(p) == t[0] && qGreen(p) == t[1] && qBlue(p) == t[2] && qAlpha(p) == t[3];
        }
    EXPECT_GT(covered, 0);
    EXPECT_EQ(same, covered) << "the file is not the layer's texels";

    // The next export dialog starts with the box ticked.
    onNextModal<QFileDialog>([&](QFileDialog* dialog) {
        auto* box = dialog->findChild<QCheckBox*>(QStringLiteral("exportPerPaintLayer"));
        wasChecked = box && box->isChecked();
        dialog->reject();
    });
    exportPng->trigger();
    EXPECT_TRUE(wasChecked) << "the box forgot it was ticked";
}

} // namespace paint_layers_uitest
