// SPDX-License-Identifier: GPL-3.0-or-later
// One history, one script runner: a session driven with real Qt events (layer-aware strokes,
// Ctrl+Shift+click pop-ups, paint-to-hide, undo and redo) is copied as a script; the headless tool
// replays it and saves the same picture byte for byte, and File ▸ Run Script replays it in the
// window as one undo step. Needs a display with OpenGL 4.5 (xvfb-run; llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QFile>
#include <QProcess>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <memory>

#include "core/document/document.h"
#include "core/io/project/project_file.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/shell/project_controller.h"
#include "ui/shell/script_actions.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace script_uitest {

using namespace ui_test;

constexpr int kSaveTimeoutMs = 60000;
constexpr int kCliTimeoutMs = 300000;

class ScriptSessionTest : public WindowTest {
protected:
    ScriptSessionTest() : WindowTest({1260, 900}) {}

    void SetUp() override {
        ASSERT_TRUE(m_dir.isValid());
        WindowTest::SetUp();
        if (HasFatalFailure())
            return;
        open();
    }

    void open() {
        QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
        QSignalSpy built(m_window->depthLayersBuilder(), &ui::DepthLayersBuilder::depthLayersBuilt);
        m_window->openFile(QStringLiteral("builtin:trefoil"));
        ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
        ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
        ASSERT_NE(document().depthLayers(), nullptr);
        ASSERT_EQ(viewport()->devicePixelRatioF(), 1.0);
    }

    const core::DepthStack& stack() const { return document().depthLayers()->stack; }
    QString path(const QString& name) const { return m_dir.filePath(name); }

    /** A horizontal run of pixels on the model (layer 1 everywhere), at least length long. */
    std::pair<QPoint, QPoint> run(int length, int skipRows = 0) const {
        const core::DepthStack& s = stack();
        int found = 0;
        for (int y = s.height / 4; y < s.height * 3 / 4; y += 7) {
            int start = -1;
            for (int x = 0; x < s.width; ++x) {
                const bool on = s.layerCount(std::size_t(y) * s.width + x) >= 2;
                if (on && start < 0)
                    start = x;
                if (!on && start >= 0) {
                    if (x - start >= length && found++ >= skipRows)
                        return {{start + 4, y}, {start + length - 4, y}};
                    start = -1;
                }
            }
        }
        return {{-1, -1}, {-1, -1}};
    }

    void drag(QPoint a, QPoint b) {
        QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, a);
        const int steps = std::max(1, (std::abs(b.x() - a.x()) + std::abs(b.y() - a.y())) / 5);
        for (int i = 1; i <= steps; ++i)
            QTest::mouseMove(viewport(), a + (b - a) * i / steps);
        QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, b);
    }
    void key(Qt::Key k, Qt::KeyboardModifiers modifiers = Qt::NoModifier) {
        QTest::keyClick(m_window.get(), k, modifiers);
    }

    bool saveTo(const QString& file) {
        QSignalSpy saved(m_window->projectController(), &ui::ProjectController::saved);
        if (!m_window->projectController()->saveTo(file))
            return false;
        return QTest::qWaitFor([&] { return !saved.isEmpty(); }, kSaveTimeoutMs);
    }

    static std::vector<std::vector<std::uint8_t>> pages(const core::Mesh& mesh) {
        std::vector<std::vector<std::uint8_t>> out;
        for (const core::Image& image : mesh.textures)
            out.push_back(image.rgba);
        return out;
    }

    QTemporaryDir m_dir;
};

TEST_F(ScriptSessionTest, TheHeadlessToolReplaysAGuiSessionToTheSameProject) {
    const auto [a, b] = run(80);
    ASSERT_GE(a.x(), 0) << "no long run of two-layer pixels";
    const auto [c, d] = run(50, 3);
    ASSERT_GE(c.x(), 0);
    const QPoint middle = (a + b) / 2;

    drag(a, b); // layer-aware
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ControlModifier | Qt::ShiftModifier,
                      middle);                // pop-up
    drag(c, d);                               // another stroke ...
    key(Qt::Key_Z, Qt::ControlModifier);      // ... undone
    drag(c + QPoint(0, 3), d + QPoint(0, 3)); // and one in its place
    key(Qt::Key_H);                           // paint-to-hide over the pop-up
    drag(middle, middle + QPoint(6, 0));
    key(Qt::Key_B);
    key(Qt::Key_Z, Qt::ControlModifier);                     // the hiding undone
    key(Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier); // and redone
    std::string steps;
    for (std::size_t i = 0; i < document().history().size(); ++i)
        steps += std::string(core::stepKindName(document().history().kindAt(i))) + " ";
    ASSERT_EQ(document().history().undoCount(), 4u) << steps;

    const QString guiFile = path(QStringLiteral("gui.glb"));
    ASSERT_TRUE(saveTo(guiFile));
    m_window->scriptActions()->copySessionAction()->trigger();
    const QString script = QApplication::clipboard()->text();
    ASSERT_FALSE(script.isEmpty());
    QFile scriptFile(path(QStringLiteral("session.json")));
    ASSERT_TRUE(scriptFile.open(QIODevice::WriteOnly));
    scriptFile.write(script.toUtf8());
    scriptFile.close();

    const QString cliFile = path(QStringLiteral("cli.glb"));
    QProcess cli;
    cli.start(QStringLiteral(LAYERPAINT_CLI),
              {QStringLiteral("paint"), QStringLiteral("builtin:trefoil"),
               QStringLiteral("--script"), scriptFile.fileName(), QStringLiteral("--out"),
               cliFile});
    ASSERT_TRUE(cli.waitForFinished(kCliTimeoutMs));
    ASSERT_EQ(cli.exitCode(), 0) << cli.readAllStandardError().toStdString();

    const core::Result<core::Project> gui = core::loadProject(guiFile.toStdString());
    const core::Result<core::Project> headless = core::loadProject(cliFile.toStdString());
    ASSERT_TRUE(gui.ok()) << gui.error();
    ASSERT_TRUE(headless.ok()) << headless.error();
    ASSERT_FALSE(gui->mesh.textures.empty());
    EXPECT_TRUE(pages(gui->mesh) == pages(headless->mesh)) << "the painted textures differ";
    ASSERT_TRUE(gui->state && headless->state);
    EXPECT_EQ(gui->state->brush, headless->state->brush);
    EXPECT_EQ(gui->state->layerAware, headless->state->layerAware);

    // File ▸ Run Script on the model opened afresh: the same picture, one undo step.
    open();
    ASSERT_NE(document().paintTarget(), nullptr);
    const std::vector<std::uint8_t> blank = document().paintedMesh().textures.at(0).rgba;
    core::Result<core::Script> parsed = core::readScript(scriptFile.fileName().toStdString());
    ASSERT_TRUE(parsed.ok()) << parsed.error();
    QSignalSpy finished(m_window->scriptActions(), &ui::ScriptActions::finished);
    m_window->scriptActions()->run(*parsed, true);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !finished.isEmpty(); }, kCliTimeoutMs));
    EXPECT_EQ(finished.first().first().toString(), QString());
    EXPECT_TRUE(pages(document().paintedMesh()) == pages(gui->mesh));
    EXPECT_EQ(m_window->undoStack()->count(), 1);
    ASSERT_TRUE(QTest::qWaitForWindowActive(m_window.get())); // the progress dialog is gone
    key(Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(document().paintedMesh().textures.at(0).rgba, blank);
    EXPECT_FALSE(document().history().canUndo());
}

} // namespace script_uitest
