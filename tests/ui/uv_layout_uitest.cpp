// SPDX-License-Identifier: GPL-3.0-or-later
// A model without UVs in the GUI: the note over the view says so, the automatic UV layout (the
// default for a coarse mesh) is made in the background and painted into with real mouse events,
// the note's button switches to vertex colours as an undoable step, and the Paint into box
// brings the texture back.
#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>
#include <QUndoStack>

#include <memory>
#include <vector>

#include "core/document/document.h"
#include "core/paint/targets/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace uv_layout_uitest {

using namespace ui_test;

class UvLayoutUiTest : public WindowTest {
protected:
    UvLayoutUiTest() : WindowTest({1260, 720}) {}

    void SetUp() override {
        ASSERT_TRUE(m_dir.isValid());
        // A box of eight vertices without texture coordinates: vertex colours would be coarse.
        QFile obj(m_dir.filePath(QStringLiteral("box.obj")));
        ASSERT_TRUE(obj.open(QIODevice::WriteOnly));
        obj.write("v -1 -1 -1\nv 1 -1 -1\nv -1 1 -1\nv 1 1 -1\n"
                  "v -1 -1 1\nv 1 -1 1\nv -1 1 1\nv 1 1 1\n"
                  "f 5 6 8\nf 5 8 7\nf 2 1 3\nf 2 3 4\nf 1 5 7\nf 1 7 3\n"
                  "f 6 2 4\nf 6 4 8\nf 7 8 4\nf 7 4 3\nf 1 2 6\nf 1 6 5\n");
        obj.close();
        WindowTest::SetUp();
    }

    const core::TextureTarget* texture() const {
        return document().hasPaintTarget()
                   ? dynamic_cast<const core::TextureTarget*>(document().paintTarget())
                   : nullptr;
    }

    QTemporaryDir m_dir;
};

TEST_F(UvLayoutUiTest, ModelWithoutUvsGetsAnAutomaticLayoutAndTheChoiceIsUndoable) {
    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    QSignalSpy built(m_window->depthLayersBuilder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    m_window->openFile(m_dir.filePath(QStringLiteral("box.obj")));
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));

    // The note over the view says so, without a dialog, and offers the other choice.
    auto* note = m_window->findChild<QLabel*>(QStringLiteral("messageBarText"));
    ASSERT_NE(note, nullptr);
    EXPECT_TRUE(note->isVisible());
    EXPECT_TRUE(note->text().contains(QStringLiteral("automatic UV layout")))
        << qPrintable(note->text());
    auto* button = m_window->findChild<QToolButton*>(QStringLiteral("messageBarButton"));
    ASSERT_NE(button, nullptr);
    EXPECT_TRUE(button->isVisible());

    // The layout is made in the background; then the target is a texture over the layout's UVs.
    ASSERT_TRUE(QTest::qWaitFor([&] { return texture() != nullptr; }, kLoadTimeoutMs));
    EXPECT_TRUE(texture()->mesh().hasUvs());
    EXPECT_FALSE(document().mesh().hasUvs());
    EXPECT_FALSE(m_window->undoStack()->canUndo()) << "the default is not a step";
    auto* combo = m_window->findChild<QComboBox*>(QStringLiteral("paintTarget"));
    ASSERT_NE(combo, nullptr);
    EXPECT_NE(combo->currentIndex(), combo->count() - 1) << "the box shows the texture";
    EXPECT_TRUE(combo->currentText().contains(QStringLiteral("automatic UVs")));

    // A real drag paints the layout's texture.
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return document().depthLayers() != nullptr; }, kBuildTimeoutMs));
    const std::vector<std::uint8_t> before = texture()->page(0).rgba;
    const QPoint centre = viewport()->rect().center();
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, centre - QPoint(40, 0));
    for (int i = 1; i <= 20; ++i)
        QTest::mouseMove(viewport(), centre - QPoint(40, 0) + QPoint(4 * i, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, centre + QPoint(40, 0));
    EXPECT_NE(texture()->page(0).rgba, before);

    // The note's button: vertex colours, as one undoable step.
    QTest::mouseClick(button, Qt::LeftButton);
    ASSERT_EQ(document().paintTarget()->kind(), core::PaintTargetKind::VertexColors);
    EXPECT_EQ(combo->currentIndex(), combo->count() - 1);
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    ASSERT_NE(texture(), nullptr);
    EXPECT_NE(texture()->page(0).rgba, before) << "the painted layout comes back";

    // Vertex colours again through the box, then a texture of another size: a new layout.
    combo->setCurrentIndex(combo->count() - 1);
    emit combo->activated(combo->count() - 1);
    ASSERT_EQ(document().paintTarget()->kind(), core::PaintTargetKind::VertexColors);
    int item = 0;
    while (item + 1 < combo->count() && combo->itemData(item).toInt() != 1024)
        ++item;
    ASSERT_EQ(combo->itemData(item).toInt(), 1024);
    combo->setCurrentIndex(item);
    emit combo->activated(item);
    ASSERT_TRUE(QTest::qWaitFor([&] { return texture() != nullptr; }, kLoadTimeoutMs));
    EXPECT_EQ(texture()->page(0).width, 1024);
    EXPECT_TRUE(texture()->mesh().hasUvs());
}

} // namespace uv_layout_uitest
