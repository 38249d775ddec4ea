// SPDX-License-Identifier: GPL-3.0-or-later
// The brush bar tells the texture sizes strokes really go into: a model whose material has a
// 256² base colour texture says "Texture 256 × 256" (with the material in the tooltip), a raised
// texture shows its new size and Undo the old one; a model whose UVs overlap gets a warning and
// can still be painted over an automatic UV layout.
#include <gtest/gtest.h>

#include <QComboBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "core/document/document.h"
#include "core/paint/targets/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/panels/brush_toolbar.h"
#include "ui/shell/main_window.h"

namespace texture_size_uitest {

using namespace ui_test;

/** Two quads side by side; the second's UVs as given ("1 2 3 4": the first's). */
QByteArray twoQuads(const QByteArray& secondUvs) {
    return "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
           "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0\nvt 0.5 1\n"
           "f 1/1 2/2 3/3 4/4\nf 2/" +
           secondUvs.left(1) + " 5/" + secondUvs.mid(2, 1) + " 6/" + secondUvs.mid(4, 1) + " 3/" +
           secondUvs.mid(6, 1) + "\n";
}

class TextureSizeUiTest : public WindowTest {
protected:
    TextureSizeUiTest() : WindowTest({1260, 720}) {}

    void SetUp() override {
        ASSERT_TRUE(m_dir.isValid());
        // A quad whose material has a 256 × 128 base colour texture.
        write(QStringLiteral("quad.obj"), "mtllib quad.mtl\nusemtl painted\n"
                                          "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\n"
                                          "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                          "f 1/1 2/2 3/3 4/4\n");
        write(QStringLiteral("quad.mtl"), "newmtl painted\nKd 1 1 1\nmap_Kd tex.png\n");
        QImage texture(256, 128, QImage::Format_RGBA8888);
        texture.fill(QColor(200, 120, 40));
        ASSERT_TRUE(texture.save(m_dir.filePath(QStringLiteral("tex.png"))));
        // The second quad's UVs mirror the first's: every place painted twice.
        write(QStringLiteral("mirrored.obj"), twoQuads("2 1 4 3"));
        WindowTest::SetUp();
    }

    void write(const QString& name, const QByteArray& bytes) {
        QFile file(m_dir.filePath(name));
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write(bytes);
    }

    bool open(const QString& name) {
        QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
        m_window->openFile(m_dir.filePath(name));
        return loaded.wait(kLoadTimeoutMs);
    }

    QComboBox* targetBox() const {
        return m_window->brushToolBar()->findChild<QComboBox*>(QStringLiteral("paintTarget"));
    }

    QTemporaryDir m_dir;
};

TEST_F(TextureSizeUiTest, TheBrushBarNamesTheTexturesRealSize) {
    ASSERT_TRUE(open(QStringLiteral("quad.obj")));
    QComboBox* box = targetBox();
    ASSERT_NE(box, nullptr);
    EXPECT_EQ(box->currentText(), QStringLiteral("Texture 256 × 128"));
    EXPECT_TRUE(box->toolTip().contains(QStringLiteral("painted: 256 × 128 (its base colour")))
        << box->toolTip().toStdString();
    // The resolution sizes nothing here: one entry for the model's UVs, then the automatic
    // layouts (offered for a model with UVs too) and vertex colours.
    EXPECT_EQ(box->findText(QStringLiteral("Texture 2048 × 2048")), -1);
    EXPECT_EQ(box->itemText(1), QStringLiteral("Texture 512 × 512, automatic UVs"));
    EXPECT_EQ(box->count(), 7);

    // Raised: the bar says so; Undo and Redo (the Edit menu's stack) bring either size back.
    ASSERT_NE(document().paintTarget(), nullptr);
    const std::uint32_t material = document().mesh().triangleMaterial[0]; // Assimp adds one
    const core::Status raised = document().raiseTextureSize(material, 1024);
    ASSERT_TRUE(raised.ok()) << raised.error();
    undoStack()->undo();
    EXPECT_EQ(box->currentText(), QStringLiteral("Texture 256 × 128"));
    undoStack()->redo();
    EXPECT_EQ(box->currentText(), QStringLiteral("Texture 1024 × 512"));
    const auto* target = dynamic_cast<const core::TextureTarget*>(document().paintTarget());
    ASSERT_NE(target, nullptr);
    EXPECT_EQ(target->page(target->materialPage(material)).width, 1024);
}

TEST_F(TextureSizeUiTest, OverlappingUvsAreNamedAndCanBePaintedApart) {
    ASSERT_TRUE(open(QStringLiteral("mirrored.obj")));
    ASSERT_TRUE(document().mesh().hasUvs()) << "kept";
    auto* note = m_window->findChild<QLabel*>(QStringLiteral("messageBarText"));
    ASSERT_NE(note, nullptr);
    EXPECT_TRUE(note->text().contains(QStringLiteral("paints every overlapping place at once")))
        << note->text().toStdString();

    QComboBox* box = targetBox();
    ASSERT_NE(box, nullptr);
    EXPECT_FALSE(box->currentText().contains(QStringLiteral("automatic"))) << "the default stays";
    const int item = box->findText(QStringLiteral("Texture 1024 × 1024, automatic UVs"));
    ASSERT_GE(item, 0);
    box->setCurrentIndex(item);
    emit box->activated(item);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            return document().hasPaintTarget() &&
                   document().currentPaintTarget()->mesh().uvs != document().mesh().uvs;
        },
        kLoadTimeoutMs));
    EXPECT_EQ(document().paintTarget()->page(0).width, 1024);
    EXPECT_EQ(box->currentText(), QStringLiteral("Texture 1024 × 1024, automatic UVs"));
    // The next model paints its own UVs again.
    ASSERT_TRUE(open(QStringLiteral("quad.obj")));
    EXPECT_FALSE(document().paintTargetOptions().automaticUvs);
    EXPECT_EQ(box->currentText(), QStringLiteral("Texture 256 × 128"));
}

} // namespace texture_size_uitest
