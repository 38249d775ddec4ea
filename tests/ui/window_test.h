// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QPoint>
#include <QSettings>
#include <QSignalSpy>
#include <QSize>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/depth/depth_stack.h"
#include "core/document/document.h"
#include "core/document/project_state.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/paint/targets/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "ui/shell/main_window.h"
#include "ui/shell/project_controller.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace ui_test {

/** A path as the core's file functions take it. */
inline std::string local(const QString& path) {
    return QFile::encodeName(path).toStdString();
}

/**
 * Writes what a crashed session leaves in the recovery folder: an autosave of builtin:row with
 * state, and no lock beside it. path gets the file's path.
 */
inline void writeCrashedAutosave(core::ProjectState state, QString& path) {
    const QString folder = ui::ProjectController::recoveryFolder();
    ASSERT_TRUE(QDir().mkpath(folder));
    path = QDir(folder).filePath(QStringLiteral("autosave-999999-crashed.glb"));
    core::Result<core::Mesh> mesh = core::loadMesh("builtin:row");
    ASSERT_TRUE(mesh.ok());
    state.source = "builtin:row";
    ASSERT_TRUE(core::saveProject(local(path), *mesh, state, {}, false).ok());
}

/** Whether pixel p of stack and the (2 margin + 1)² pixels around it all show the model. */
inline bool showsModelAround(const core::DepthStack& stack, QPoint p, int margin) {
    for (int dy = -margin; dy <= margin; ++dy)
        for (int dx = -margin; dx <= margin; ++dx) {
            const int x = p.x() + dx, y = p.y() + dy;
            if (x < 0 || y < 0 || x >= stack.width || y >= stack.height)
                return false;
            const std::size_t i = std::size_t(y) * std::size_t(stack.width) + std::size_t(x);
            if (stack.offsets[i + 1] == stack.offsets[i])
                return false;
        }
    return true;
}

/**
 * A test with its own main window: settings cleared before and after, the window shown at the
 * fixture's size and active (shortcuts reach the active window only), error dialogs off.
 */
class WindowTest : public ::testing::Test {
protected:
    explicit WindowTest(QSize size) : m_size(size) {}

    void SetUp() override {
        QSettings().clear();
        showWindow();
    }

    void TearDown() override {
        m_window.reset();
        QSettings().clear();
    }

    /** A main window as the tests use one: error dialogs off, at size, shown. */
    static std::unique_ptr<ui::MainWindow> makeWindow(QSize size) {
        auto window = std::make_unique<ui::MainWindow>();
        window->setErrorDialogsEnabled(false);
        window->resize(size);
        window->show();
        return window;
    }

    /** A new window in place of the current one (as a new start of the application). */
    void showWindow() {
        m_window.reset();
        m_window = makeWindow(m_size);
        ASSERT_TRUE(QTest::qWaitForWindowExposed(m_window.get()));
        m_window->activateWindow();
        ASSERT_TRUE(QTest::qWaitForWindowActive(m_window.get()));
    }

    ui::Viewport* viewport() const { return m_window->viewport(); }
    ui::DepthLayersBuilder* builder() const { return m_window->depthLayersBuilder(); }
    core::Document& document() const { return m_window->document(); }
    QUndoStack* undoStack() const { return m_window->undoStack(); }
    QImage grab() const { return viewport()->grabFramebuffer(); }

    /** The first page of the texture target; nothing when painting goes elsewhere. */
    std::vector<std::uint8_t> pageBytes() const {
        const auto* target = dynamic_cast<const core::TextureTarget*>(document().paintTarget());
        return target ? target->page(0).rgba : std::vector<std::uint8_t>{};
    }

    /** A left drag from a to b in steps of 4 px (Manhattan), events handled after each. */
    void drag(QPoint a, QPoint b) {
        QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, a);
        const int steps = std::max(1, (b - a).manhattanLength() / 4);
        for (int i = 1; i <= steps; ++i) {
            QTest::mouseMove(viewport(), a + (b - a) * i / steps);
            QApplication::processEvents();
        }
        QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, b);
        QApplication::processEvents();
    }

    /** Opens the built-in trefoil and waits until its depth layers are built. */
    void openTrefoil() {
        QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
        QSignalSpy built(builder(), &ui::DepthLayersBuilder::depthLayersBuilt);
        m_window->openFile(QStringLiteral("builtin:trefoil"));
        ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
        ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
        ASSERT_NE(document().depthLayers(), nullptr);
    }

    /**
     * A pixel near the middle whose neighbourhood (21 × 21, and 32 px to the right) all shows
     * the model; nothing when none does.
     */
    std::optional<QPoint> solidPixel() {
        const core::DepthStack& layers = document().depthLayers()->stack;
        const auto covered = [&](int x, int y) {
            if (x < 0 || y < 0 || x >= layers.width || y >= layers.height)
                return false;
            const std::size_t i = std::size_t(y) * std::size_t(layers.width) + std::size_t(x);
            return layers.offsets[i + 1] != layers.offsets[i];
        };
        for (int y = layers.height / 4; y < layers.height * 3 / 4; y += 3)
            for (int x = layers.width / 4; x < layers.width * 3 / 4; x += 3) {
                bool inside = true;
                for (int dy = -10; inside && dy <= 10; dy += 2)
                    for (int dx = -10; inside && dx <= 22; dx += 2)
                        inside = covered(x + dx, y + dy);
                if (inside)
                    return QPoint(x, y);
            }
        return std::nullopt;
    }

    std::unique_ptr<ui::MainWindow> m_window;

private:
    QSize m_size;
};

/** A WindowTest with no autosave left over from before, and a folder for the test's files. */
class ProjectFilesTest : public WindowTest {
protected:
    explicit ProjectFilesTest(QSize size) : WindowTest(size) {}

    void SetUp() override {
        QDir(ui::ProjectController::recoveryFolder()).removeRecursively();
        ASSERT_TRUE(m_dir.isValid());
        WindowTest::SetUp();
    }

    void TearDown() override {
        WindowTest::TearDown();
        QDir(ui::ProjectController::recoveryFolder()).removeRecursively();
    }

    /** The path of name in the test's folder. */
    QString path(const QString& name) const { return m_dir.filePath(name); }

    QTemporaryDir m_dir;
};

} // namespace ui_test
