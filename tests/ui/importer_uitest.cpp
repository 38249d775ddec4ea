// SPDX-License-Identifier: GPL-3.0-or-later
// A file that crashes the parser, opened the way a user does (File ▸ Open, the file dialog, the
// unsaved-changes question) over a painted model: the importer process stops, one error dialog
// names the file, and the model, its paint and its undo history are as they were.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QLineEdit>
#include <QMessageBox>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "core/document/document.h"
#include "core/paint/targets/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace importer_uitest {

using namespace ui_test;

const QString kCrasher =
    QStringLiteral(LAYERPAINT_TEST_DATA) + QStringLiteral("/crashers/off-assimp-segv.off");

class ImporterTest : public WindowTest {
protected:
    ImporterTest() : WindowTest({1100, 720}) {}

    /** A horizontal run of pixels that all show the model, near the middle of the view. */
    std::pair<QPoint, QPoint> pathAcrossTheModel() const {
        const core::DepthStack& stack = document().depthLayers()->stack;
        auto covered = [&](int x, int y) {
            const std::size_t i = std::size_t(y) * stack.width + x;
            return stack.offsets[i + 1] != stack.offsets[i];
        };
        for (int k = 0; k < stack.height / 2; k += 5)
            for (int y : {stack.height / 2 - k, stack.height / 2 + k}) {
                int start = -1;
                for (int x = 0; x <= stack.width; ++x) {
                    const bool inside = x < stack.width && covered(x, y) &&
                                        covered(x, std::max(0, y - 4)) &&
                                        covered(x, std::min(stack.height - 1, y + 4));
                    if (inside && start < 0)
                        start = x;
                    if (!inside && start >= 0) {
                        if (x - start >= 60)
                            return {{start + 5, y}, {x - 6, y}};
                        start = -1;
                    }
                }
            }
        return {};
    }
};

/**
 * Plays the user through the modal dialogs that File ▸ Open brings up, with real key and mouse
 * events as soon as each shows: the file dialog (types path, Enter), then the unsaved-changes
 * question (Discard). The dialogs run their own event loops, so this polls from a timer.
 */
class DialogPlayer : public QObject {
public:
    explicit DialogPlayer(const QString& path) : m_path(path) {
        connect(&m_timer, &QTimer::timeout, this, &DialogPlayer::step);
        m_timer.start(20);
    }
    bool choseFile() const { return m_choseFile; }
    bool discarded() const { return m_discarded; }

private:
    void step() {
        QWidget* modal = QApplication::activeModalWidget();
        if (!modal || !modal->isVisible() || !modal->windowHandle() ||
            !modal->windowHandle()->isExposed())
            return;
        if (auto* dialog = qobject_cast<QFileDialog*>(modal)) {
            auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
            if (!name)
                return;
            // The path is set, not typed: typed, it pops up the file-name completer, which can
            // take the Return meant for the dialog when its folder listing arrives late. Return
            // is pressed again on every tick the dialog stays open.
            m_choseFile = true;
            name->setFocus();
            name->setText(m_path);
            QTest::keyClick(name, Qt::Key_Return);
        } else if (auto* box = qobject_cast<QMessageBox*>(modal);
                   box && box->objectName() == QLatin1String("unsavedChangesBox")) {
            m_discarded = true;
            QTest::mouseClick(box->button(QMessageBox::Discard), Qt::LeftButton);
        }
    }

    QString m_path;
    QTimer m_timer;
    bool m_choseFile = false;
    bool m_discarded = false;
};

TEST_F(ImporterTest, AFileThatCrashesTheParserLeavesThePaintedModelAsItWas) {
    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    QSignalSpy built(m_window->depthLayersBuilder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    m_window->openFile(QStringLiteral("builtin:trefoil"));
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));

    // Paint a stroke across the knot.
    const auto [a, b] = pathAcrossTheModel();
    ASSERT_GT(b.x() - a.x(), 40) << "no run across the knot";
    const std::vector<std::uint8_t> original = pageBytes();
    ASSERT_FALSE(original.empty());
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, a);
    for (int i = 1; i <= 16; ++i)
        QTest::mouseMove(viewport(), a + (b - a) * i / 16);
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, b);
    QEvent leave(QEvent::Leave);
    QApplication::sendEvent(viewport(), &leave);
    const std::vector<std::uint8_t> painted = pageBytes();
    ASSERT_NE(painted, original);
    ASSERT_EQ(m_window->undoStack()->count(), 1);
    QApplication::processEvents();
    const QImage before = grab();
    const auto mesh = viewport()->mesh();

    // File ▸ Open (Ctrl+O), the crashing OFF file, Discard: the importer process crashes.
    m_window->setErrorDialogsEnabled(true);
    QSignalSpy failed(m_window.get(), &ui::MainWindow::loadFailed);
    {
        DialogPlayer player(kCrasher);
        QTest::keyClick(m_window.get(), Qt::Key_O, Qt::ControlModifier);
        EXPECT_TRUE(player.choseFile());
        EXPECT_TRUE(player.discarded());
    }
    ASSERT_TRUE(QTest::qWaitFor([&] { return !failed.isEmpty(); }, kLoadTimeoutMs));
    EXPECT_TRUE(loaded.size() == 1) << "a model was loaded";
    const QString message = failed.first().first().toString();
    EXPECT_TRUE(message.startsWith(QFileInfo(kCrasher).absoluteFilePath() +
                                   QStringLiteral(": the importer stopped: ")))
        << message.toStdString();

    QMessageBox* box = nullptr;
    ASSERT_TRUE(QTest::qWaitFor([&] {
        box = m_window->findChild<QMessageBox*>();
        return box && box->isVisible();
    }));
    EXPECT_TRUE(box->text().contains(QStringLiteral("off-assimp-segv.off")))
        << box->text().toStdString();
    EXPECT_EQ(box->informativeText(), message);
    QTest::mouseClick(box->button(QMessageBox::Ok), Qt::LeftButton);
    EXPECT_TRUE(QTest::qWaitFor([&] { return !m_window->findChild<QMessageBox*>(); }));

    // The model, its paint, its picture and its undo history are untouched.
    EXPECT_EQ(viewport()->mesh(), mesh);
    EXPECT_EQ(m_window->currentSource(), QStringLiteral("builtin:trefoil"));
    EXPECT_EQ(pageBytes(), painted);
    QApplication::processEvents();
    EXPECT_LT(differingFraction(before, grab()), 0.001);
    ASSERT_EQ(m_window->undoStack()->count(), 1);
    m_window->activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(m_window.get()));
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(m_window->undoStack()->index(), 0);
    EXPECT_EQ(pageBytes(), original);
}

} // namespace importer_uitest
