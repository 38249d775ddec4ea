// SPDX-License-Identifier: GPL-3.0-or-later
// Projects in the GUI through real Qt event delivery: save → reopen in a new window gives the
// same paint and settings; the unsaved-changes mark and prompts; autosave and recovery after a
// simulated crash; refusal of corrupted projects with the open document untouched; exports
// running off the GUI thread. Needs a display with OpenGL 4.5 (xvfb-run; llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

#include "core/document/document.h"
#include "core/io/gltf/gltf_export.h"
#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "core/paint/targets/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/shell/model_loader.h"
#include "ui/shell/project_controller.h"
#include "ui/shell/texture_export_dialog.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace project_uitest {

using namespace ui_test;

constexpr int kSaveTimeoutMs = 60000;

std::vector<std::vector<std::uint8_t>> pagesOf(core::Document& doc) {
    std::vector<std::vector<std::uint8_t>> pages;
    if (const auto* t = dynamic_cast<const core::TextureTarget*>(doc.paintTarget()))
        for (std::size_t i = 0; i < t->pageCount(); ++i)
            pages.push_back(t->page(i).rgba);
    return pages;
}

/**
 * Answers the next modal message box called name with a real click on the button pick chooses,
 * as soon as it shows (the box runs its own event loop, so this polls from a timer).
 */
void answerNextBox(const QString& name, std::function<QAbstractButton*(QMessageBox*)> pick) {
    auto* timer = new QTimer(qApp);
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, name, pick] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box || box->objectName() != name || !box->isVisible() || !box->windowHandle() ||
            !box->windowHandle()->isExposed())
            return;
        timer->stop();
        timer->deleteLater();
        QTest::mouseClick(pick(box), Qt::LeftButton);
    });
    timer->start();
}

std::function<QAbstractButton*(QMessageBox*)> standard(QMessageBox::StandardButton which) {
    return [which](QMessageBox* box) { return box->button(which); };
}

std::function<QAbstractButton*(QMessageBox*)> named(const QString& objectName) {
    return [objectName](QMessageBox* box) { return box->findChild<QAbstractButton*>(objectName); };
}

constexpr QSize kWindowSize(1100, 720);

class ProjectTest : public ProjectFilesTest {
protected:
    ProjectTest() : ProjectFilesTest(kWindowSize) {}

    static void openAndBuild(ui::MainWindow& window, const QString& source) {
        QSignalSpy loaded(&window, &ui::MainWindow::modelLoaded);
        QSignalSpy built(window.depthLayersBuilder(), &ui::DepthLayersBuilder::depthLayersBuilt);
        window.openFile(source);
        ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
        ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
        ASSERT_NE(window.document().depthLayers(), nullptr);
    }

    /** A horizontal run across the model near the middle of the view. */
    static std::pair<QPoint, QPoint> pathAcross(ui::MainWindow& window, int skipRows = 0) {
        const core::DepthStack& stack = window.document().depthLayers()->stack;
        int found = 0;
        for (int k = 0; k < stack.height / 2; k += 7)
            for (int y : {stack.height / 2 - k, stack.height / 2 + k}) {
                int start = -1;
                for (int x = 0; x <= stack.width; ++x) {
                    const bool inside = x < stack.width && showsModelAround(stack, {x, y}, 4);
                    if (inside && start < 0)
                        start = x;
                    if (!inside && start >= 0) {
                        if (x - start >= 60 && found++ == skipRows)
                            return {{start + 5, y}, {x - 6, y}};
                        start = -1;
                    }
                }
            }
        return {};
    }

    static void drag(ui::MainWindow& window, QPoint a, QPoint b) {
        ui::Viewport* viewport = window.viewport();
        QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, a);
        const int steps = std::max(1, int(std::hypot(b.x() - a.x(), b.y() - a.y()) / 4));
        for (int i = 1; i <= steps; ++i)
            QTest::mouseMove(viewport, a + (b - a) * i / steps);
        QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, b);
        QEvent leave(QEvent::Leave); // the brush outline goes: pictures compare the model only
        QApplication::sendEvent(viewport, &leave);
    }

    /** Saves through the controller and waits; true on success. */
    static bool saveTo(ui::MainWindow& window, const QString& path) {
        QSignalSpy saved(window.projectController(), &ui::ProjectController::saved);
        QSignalSpy failed(window.projectController(), &ui::ProjectController::saveFailed);
        if (!window.projectController()->saveTo(path))
            return false;
        EXPECT_TRUE(
            QTest::qWaitFor([&] { return !saved.isEmpty() || !failed.isEmpty(); }, kSaveTimeoutMs));
        if (!failed.isEmpty())
            ADD_FAILURE() << failed.first().first().toString().toStdString();
        return !saved.isEmpty();
    }
};

TEST_F(ProjectTest, SaveAndReopenInANewWindowGivesTheSamePaintAndSettings) {
    openAndBuild(*m_window, QStringLiteral("builtin:trefoil"));
    EXPECT_FALSE(m_window->isWindowModified());
    EXPECT_EQ(shownTitle(*m_window), QStringLiteral("Trefoil knot — LayerPaint"));

    // Settings through the widgets: radius typed into its box, layer-aware off with L.
    auto* radius = m_window->findChild<QSpinBox*>(QStringLiteral("brushRadius"));
    ASSERT_NE(radius, nullptr);
    radius->setFocus();
    radius->selectAll();
    QTest::keyClicks(radius, QStringLiteral("19"));
    QTest::keyClick(radius, Qt::Key_Return);
    ASSERT_EQ(m_window->document().brush().radius, 19.0f);
    EXPECT_TRUE(m_window->isWindowModified()) << "a settings change is unsaved";
    m_window->activateWindow();
    m_window->setFocus();
    QTest::keyClick(m_window.get(), Qt::Key_L);
    ASSERT_FALSE(m_window->document().layerAware());

    const QString file = path(QStringLiteral("knot.glb"));
    ASSERT_TRUE(saveTo(*m_window, file));
    EXPECT_FALSE(m_window->isWindowModified());
    EXPECT_EQ(shownTitle(*m_window), QStringLiteral("knot.glb — LayerPaint"));

    // A stroke: the mark appears; Ctrl+S saves to the same file and it goes.
    const auto [a, b] = pathAcross(*m_window);
    ASSERT_GT(b.x() - a.x(), 50);
    drag(*m_window, a, b);
    ASSERT_EQ(m_window->undoStack()->count(), 1);
    EXPECT_TRUE(m_window->isWindowModified());
    EXPECT_EQ(shownTitle(*m_window), QStringLiteral("knot.glb* — LayerPaint"));
    QSignalSpy saved(m_window->projectController(), &ui::ProjectController::saved);
    QTest::keyClick(m_window.get(), Qt::Key_S, Qt::ControlModifier);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !saved.isEmpty(); }, kSaveTimeoutMs));
    EXPECT_EQ(saved.first().first().toString(), QFileInfo(file).absoluteFilePath());
    EXPECT_FALSE(m_window->isWindowModified());
    EXPECT_TRUE(QFileInfo::exists(file + QStringLiteral(".bak")));
    // Undo makes it modified again, redo returns to the saved state.
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier);
    EXPECT_TRUE(m_window->isWindowModified());
    QTest::keyClick(m_window.get(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_FALSE(m_window->isWindowModified());

    const std::vector<std::vector<std::uint8_t>> painted = pagesOf(m_window->document());
    ASSERT_EQ(painted.size(), 1u);
    const core::Camera camera = m_window->document().camera();
    QApplication::processEvents();
    const QImage picture = m_window->viewport()->grabFramebuffer();

    auto second = makeWindow(kWindowSize);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(second.get()));
    openAndBuild(*second, file);
    EXPECT_EQ(pagesOf(second->document()), painted) << "the paint target differs";
    EXPECT_EQ(second->document().brush().radius, 19.0f);
    EXPECT_EQ(second->findChild<QSpinBox*>(QStringLiteral("brushRadius"))->value(), 19);
    EXPECT_FALSE(second->document().layerAware());
    EXPECT_FALSE(second->findChild<QAction*>(QStringLiteral("actionLayerAware"))->isChecked());
    EXPECT_EQ(second->document().camera().yawDegrees, camera.yawDegrees);
    EXPECT_EQ(second->document().camera().pitchDegrees, camera.pitchDegrees);
    EXPECT_EQ(second->document().camera().distance, camera.distance);
    EXPECT_EQ(second->document().camera().target, camera.target);
    EXPECT_FALSE(second->isWindowModified());
    EXPECT_EQ(shownTitle(*second), QStringLiteral("knot.glb — LayerPaint"));
    EXPECT_EQ(second->projectController()->filePath(), QFileInfo(file).absoluteFilePath());
    // The same picture (both windows are laid out alike).
    ASSERT_EQ(second->viewport()->size(), m_window->viewport()->size());
    QApplication::processEvents();
    EXPECT_LT(differingFraction(picture, second->viewport()->grabFramebuffer()), 0.002);
}

TEST_F(ProjectTest, UnsavedChangesArePromptedOnCloseAndOpen) {
    m_window->setErrorDialogsEnabled(true);
    openAndBuild(*m_window, QStringLiteral("builtin:trefoil"));
    const auto [a, b] = pathAcross(*m_window);
    ASSERT_GT(b.x() - a.x(), 50);
    drag(*m_window, a, b);
    ASSERT_TRUE(m_window->isWindowModified());

    // Close → Cancel: the window stays, with its changes.
    answerNextBox(QStringLiteral("unsavedChangesBox"), standard(QMessageBox::Cancel));
    EXPECT_FALSE(m_window->close());
    EXPECT_TRUE(m_window->isVisible());
    EXPECT_TRUE(m_window->isWindowModified());

    // Open another model → Cancel: nothing is loaded.
    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    answerNextBox(QStringLiteral("unsavedChangesBox"), standard(QMessageBox::Cancel));
    m_window->openFile(QStringLiteral("builtin:row"));
    EXPECT_FALSE(m_window->isLoading());
    EXPECT_EQ(m_window->currentSource(), QStringLiteral("builtin:trefoil"));

    // Save first (a project file exists), then paint again and open → Save: saved, then opened.
    m_window->setErrorDialogsEnabled(false);
    const QString file = path(QStringLiteral("first.glb"));
    ASSERT_TRUE(saveTo(*m_window, file));
    m_window->setErrorDialogsEnabled(true);
    const auto [c, d] = pathAcross(*m_window, 2);
    drag(*m_window, c, d);
    ASSERT_TRUE(m_window->isWindowModified());
    const std::vector<std::vector<std::uint8_t>> painted = pagesOf(m_window->document());
    answerNextBox(QStringLiteral("unsavedChangesBox"), standard(QMessageBox::Save));
    m_window->openFile(QStringLiteral("builtin:row"));
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    EXPECT_EQ(m_window->currentSource(), QStringLiteral("builtin:row"));
    EXPECT_FALSE(m_window->isWindowModified());
    core::Result<core::Project> onDisk = core::loadProject(local(file));
    ASSERT_TRUE(onDisk.ok()) << onDisk.error();
    ASSERT_EQ(onDisk->mesh.textures.size(), 1u);
    EXPECT_TRUE(onDisk->mesh.textures[0].rgba == painted[0]) << "the prompt's save missed paint";

    // Close → Discard: the window closes, and no recovery file is left.
    ASSERT_TRUE(QTest::qWaitFor([&] { return m_window->document().depthLayers() != nullptr; },
                                kBuildTimeoutMs));
    const auto [e, f] = pathAcross(*m_window);
    ASSERT_GT(f.x() - e.x(), 50);
    drag(*m_window, e, f);
    ASSERT_TRUE(m_window->isWindowModified());
    ASSERT_TRUE(m_window->projectController()->autosaveNow());
    QSignalSpy autosaved(m_window->projectController(), &ui::ProjectController::autosaved);
    ASSERT_TRUE(autosaved.wait(kSaveTimeoutMs));
    ASSERT_TRUE(QFileInfo::exists(m_window->projectController()->autosavePath()));
    answerNextBox(QStringLiteral("unsavedChangesBox"), standard(QMessageBox::Discard));
    EXPECT_TRUE(m_window->close());
    EXPECT_FALSE(QFileInfo::exists(m_window->projectController()->autosavePath()));
}

TEST_F(ProjectTest, AutosaveIsRecoveredAfterACrash) {
    openAndBuild(*m_window, QStringLiteral("builtin:trefoil"));
    const QString file = path(QStringLiteral("knot.glb"));
    ASSERT_TRUE(saveTo(*m_window, file));
    const auto [a, b] = pathAcross(*m_window);
    ASSERT_GT(b.x() - a.x(), 50);
    drag(*m_window, a, b);
    ASSERT_TRUE(m_window->isWindowModified());
    const std::vector<std::vector<std::uint8_t>> painted = pagesOf(m_window->document());

    // The timer autosaves (a short interval, as the Preferences would set it).
    QSettings().setValue(QStringLiteral("autosave/intervalMinutes"), 0.005);
    m_window->projectController()->reloadAutosaveInterval();
    QSignalSpy autosaved(m_window->projectController(), &ui::ProjectController::autosaved);
    ASSERT_TRUE(autosaved.wait(kSaveTimeoutMs));
    const QString autosave = m_window->projectController()->autosavePath();
    ASSERT_TRUE(QFileInfo::exists(autosave));
    QSettings().setValue(QStringLiteral("autosave/intervalMinutes"), 0);
    m_window->projectController()->reloadAutosaveInterval();

    // A second session while the first runs: its autosave is not offered (the lock is live).
    auto other = makeWindow(kWindowSize);
    other->setErrorDialogsEnabled(true);
    EXPECT_FALSE(other->projectController()->offerRecovery());
    other.reset();

    // The crash: the window goes without closing (the file stays, the lock is released).
    m_window.reset();
    ASSERT_TRUE(QFileInfo::exists(autosave));

    m_window = makeWindow(kWindowSize);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(m_window.get()));
    m_window->setErrorDialogsEnabled(true);
    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    answerNextBox(QStringLiteral("recoveryBox"), named(QStringLiteral("recoverButton")));
    ASSERT_TRUE(m_window->projectController()->offerRecovery());
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    EXPECT_EQ(pagesOf(m_window->document()), painted) << "the recovered paint differs";
    // It belongs to knot.glb again, unsaved; the old session's file is now this one's autosave.
    EXPECT_EQ(m_window->projectController()->filePath(), QFileInfo(file).absoluteFilePath());
    EXPECT_TRUE(m_window->isWindowModified());
    EXPECT_EQ(shownTitle(*m_window), QStringLiteral("knot.glb* — LayerPaint"));
    EXPECT_FALSE(QFileInfo::exists(autosave));
    EXPECT_TRUE(QFileInfo::exists(m_window->projectController()->autosavePath()));
    EXPECT_FALSE(m_window->recentFiles().contains(m_window->projectController()->autosavePath()));

    // Saving puts it where it belongs and leaves nothing to recover.
    m_window->setErrorDialogsEnabled(false);
    ASSERT_TRUE(saveTo(*m_window, m_window->projectController()->filePath()));
    EXPECT_FALSE(QFileInfo::exists(m_window->projectController()->autosavePath()));
    core::Result<core::Project> onDisk = core::loadProject(local(file));
    ASSERT_TRUE(onDisk.ok());
    EXPECT_TRUE(onDisk->mesh.textures[0].rgba == painted[0]);
}

TEST_F(ProjectTest, RecoveryFileLeftByACrashCanBeKeptOrDiscarded) {
    // A crashed session's autosave, as written by core: no lock beside it.
    core::ProjectState state;
    state.brush.radius = 42.0f;
    QString orphan;
    ASSERT_NO_FATAL_FAILURE(writeCrashedAutosave(state, orphan));

    m_window->setErrorDialogsEnabled(true);
    answerNextBox(QStringLiteral("recoveryBox"), named(QStringLiteral("notNowButton")));
    EXPECT_FALSE(m_window->projectController()->offerRecovery());
    EXPECT_TRUE(QFileInfo::exists(orphan)) << "Not Now keeps it for the next start";

    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    answerNextBox(QStringLiteral("recoveryBox"), named(QStringLiteral("recoverButton")));
    ASSERT_TRUE(m_window->projectController()->offerRecovery());
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    EXPECT_EQ(m_window->document().brush().radius, 42.0f);
    EXPECT_TRUE(m_window->projectController()->filePath().isEmpty()) << "never saved: untitled";
    EXPECT_EQ(shownTitle(*m_window), QStringLiteral("Row of four* — LayerPaint"));
    EXPECT_TRUE(m_window->isWindowModified());

    // Discard removes one.
    ASSERT_NO_FATAL_FAILURE(writeCrashedAutosave(state, orphan));
    auto second = makeWindow(kWindowSize);
    second->setErrorDialogsEnabled(true);
    answerNextBox(QStringLiteral("recoveryBox"), named(QStringLiteral("discardButton")));
    EXPECT_FALSE(second->projectController()->offerRecovery());
    EXPECT_FALSE(QFileInfo::exists(orphan));
}

TEST_F(ProjectTest, CorruptedOrNewerProjectIsRefusedAndTheDocumentStays) {
    openAndBuild(*m_window, QStringLiteral("builtin:trefoil"));
    const QString good = path(QStringLiteral("good.glb"));
    ASSERT_TRUE(saveTo(*m_window, good));
    const auto [a, b] = pathAcross(*m_window);
    drag(*m_window, a, b);
    ASSERT_TRUE(m_window->isWindowModified());
    const std::vector<std::vector<std::uint8_t>> painted = pagesOf(m_window->document());
    const std::uint64_t serial = m_window->document().meshSerial();
    const QString title = m_window->windowTitle();

    QFile in(good);
    ASSERT_TRUE(in.open(QIODevice::ReadOnly));
    const QByteArray bytes = in.readAll();
    const QString truncated = path(QStringLiteral("truncated.glb"));
    {
        QFile out(truncated);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(bytes.left(bytes.size() / 2));
    }
    core::ProjectState future;
    future.formatVersion = 99;
    nlohmann::json futureJson = core::projectStateToJson(future);
    futureJson["version"] = 99;
    const QString newer = path(QStringLiteral("newer.glb"));
    ASSERT_TRUE(core::saveGlb(local(newer), core::loadMesh("builtin:row").value(),
                              {{"layerpaint", futureJson}})
                    .ok());

    for (const auto& [file, expected] : {std::pair{truncated, QStringLiteral("truncated")},
                                         std::pair{newer, QStringLiteral("newer LayerPaint")}}) {
        QSignalSpy failed(m_window.get(), &ui::MainWindow::loadFailed);
        m_window->openFile(file);
        ASSERT_TRUE(failed.wait(kLoadTimeoutMs));
        const QString message = failed.first().first().toString();
        EXPECT_TRUE(message.startsWith(QFileInfo(file).absoluteFilePath()))
            << message.toStdString();
        EXPECT_TRUE(message.contains(expected)) << message.toStdString();
        EXPECT_EQ(m_window->document().meshSerial(), serial);
        EXPECT_EQ(pagesOf(m_window->document()), painted);
        EXPECT_TRUE(m_window->isWindowModified());
        EXPECT_EQ(m_window->windowTitle(), title);
        EXPECT_EQ(m_window->projectController()->filePath(), QFileInfo(good).absoluteFilePath());
    }
}

TEST_F(ProjectTest, ExportsRunOffTheGuiThreadWithProgress) {
    openAndBuild(*m_window, QStringLiteral("builtin:trefoil"));
    // A 4096² paint texture makes the 16-bit PNG take a while.
    auto* combo = m_window->findChild<QComboBox*>(QStringLiteral("paintTarget"));
    ASSERT_NE(combo, nullptr);
    const int item = combo->findData(4096);
    ASSERT_GE(item, 0);
    combo->setCurrentIndex(item);
    emit combo->activated(item);
    ASSERT_TRUE(QTest::qWaitFor([&] { return m_window->document().depthLayers() != nullptr; },
                                kBuildTimeoutMs));
    const auto [a, b] = pathAcross(*m_window);
    drag(*m_window, a, b);
    const std::vector<std::vector<std::uint8_t>> painted = pagesOf(m_window->document());
    ASSERT_EQ(painted.size(), 1u);
    ASSERT_EQ(painted[0].size(), std::size_t(4096) * 4096 * 4);

    ui::ProjectController* project = m_window->projectController();
    QSignalSpy exported(project, &ui::ProjectController::exported);
    const QString png = path(QStringLiteral("paint.png"));
    bool eventLoopRan = false, progressShown = false;
    ASSERT_TRUE(project->exportTo(core::ExportFormat::Png16, png));
    ASSERT_TRUE(project->isBusy()) << "the export finished inside the call";
    QTimer::singleShot(0, [&] { eventLoopRan = project->isBusy(); });
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            if (auto* p = m_window->findChild<QProgressDialog*>(QStringLiteral("projectProgress")))
                progressShown = progressShown || p->isVisible();
            return !exported.isEmpty();
        },
        kSaveTimeoutMs));
    EXPECT_TRUE(eventLoopRan) << "the event loop was blocked during the export";
    std::printf("[ export  ] progress dialog %s during the 4096² 16-bit PNG export\n",
                progressShown ? "shown" : "not shown (finished within its delay)");
    // The base colour, then the material channels beside it (as the headless export writes).
    const QString folder = QFileInfo(png).absolutePath();
    EXPECT_EQ(exported.first().first().toStringList(),
              (QStringList{QFileInfo(png).absoluteFilePath(),
                           QDir(folder).filePath(QStringLiteral("paint_roughness.png")),
                           QDir(folder).filePath(QStringLiteral("paint_metallic.png"))}));

    // The model formats, read back.
    for (const auto format : {core::ExportFormat::Obj, core::ExportFormat::Glb}) {
        QSignalSpy done(project, &ui::ProjectController::exported);
        const QString file =
            path(QStringLiteral("model") + QString::fromLatin1(core::exportExtension(format)));
        ASSERT_TRUE(project->exportTo(format, file));
        ASSERT_TRUE(done.wait(kSaveTimeoutMs));
        core::Result<core::Mesh> back = core::loadMesh(local(file));
        ASSERT_TRUE(back.ok()) << back.error();
        ASSERT_EQ(back->textures.size(), 1u);
        EXPECT_TRUE(back->textures[0].rgba == painted[0]);
    }
    EXPECT_TRUE(m_window->isWindowModified()) << "an export is not a save";

    // Vertex colours have no texture: the texture entries are disabled.
    combo->setCurrentIndex(combo->count() - 1); // vertex colours
    emit combo->activated(combo->count() - 1);
    ASSERT_FALSE(project->canExportTexture());
    auto* menu = m_window->findChild<QMenu*>(QStringLiteral("exportMenu"));
    ASSERT_NE(menu, nullptr);
    emit menu->aboutToShow();
    EXPECT_FALSE(m_window->findChild<QAction*>(QStringLiteral("actionExportPng8"))->isEnabled());
    EXPECT_TRUE(m_window->findChild<QAction*>(QStringLiteral("actionExportPly"))->isEnabled());
    QSignalSpy refused(project, &ui::ProjectController::exportFailed);
    EXPECT_FALSE(project->exportTo(core::ExportFormat::Png8, path(QStringLiteral("none.png"))));
    EXPECT_EQ(refused.size(), 1);
}

TEST_F(ProjectTest, ExportTexturesWritesThePresetsMapsChosenInItsDialog) {
    openAndBuild(*m_window, QStringLiteral("builtin:trefoil"));
    const auto [a, b] = pathAcross(*m_window);
    drag(*m_window, a, b);
    const std::vector<std::vector<std::uint8_t>> painted = pagesOf(m_window->document());
    ASSERT_EQ(painted.size(), 1u);
    const int side = int(std::lround(std::sqrt(double(painted[0].size() / 4))));

    // File ▸ Export Textures…: the Unreal Engine preset chosen with the keyboard, a folder typed.
    const QString folder = path(QStringLiteral("unreal"));
    QStringList listed;
    onNextModal<ui::TextureExportDialog>([&](ui::TextureExportDialog* dialog) {
        auto* preset = dialog->findChild<QComboBox*>(QStringLiteral("textureExportPreset"));
        preset->setFocus();
        while (preset->currentData().toString() != QStringLiteral("unreal") &&
               preset->currentIndex() < preset->count() - 2)
            QTest::keyClick(preset, Qt::Key_Down);
        auto* edit = dialog->findChild<QLineEdit*>(QStringLiteral("textureExportFolder"));
        edit->setFocus();
        QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(edit, folder);
        listed = dialog->fileNames();
        QTest::mouseClick(dialog->findChild<QPushButton*>(QStringLiteral("textureExportButton")),
                          Qt::LeftButton);
    });
    ui::ProjectController* project = m_window->projectController();
    QSignalSpy exported(project, &ui::ProjectController::exported);
    auto* action = m_window->findChild<QAction*>(QStringLiteral("actionExportTextures"));
    ASSERT_NE(action, nullptr);
    action->trigger();
    ASSERT_TRUE(QTest::qWaitFor([&] { return !exported.isEmpty(); }, kSaveTimeoutMs));
    const QStringList stems = {
        QStringLiteral("BaseColor"), QStringLiteral("OcclusionRoughnessMetallic"),
        QStringLiteral("Normal"), QStringLiteral("Emissive"), QStringLiteral("Opacity")};
    ASSERT_EQ(listed.size(), stems.size());
    const QStringList files = exported.first().first().toStringList();
    ASSERT_EQ(files.size(), stems.size());
    for (int i = 0; i < stems.size(); ++i) {
        // $mesh the document's name, $textureSet its material's.
        EXPECT_TRUE(listed[i].startsWith(QStringLiteral("Trefoil-knot_trefoil_")))
            << listed[i].toStdString();
        EXPECT_TRUE(listed[i].endsWith(QStringLiteral("_") + stems[i] + QStringLiteral(".png")))
            << listed[i].toStdString();
        EXPECT_EQ(QFileInfo(files[i]).fileName(), listed[i]);
    }
    // The base colour as painted under the charts (the padding fills only the texels outside).
    const auto* target =
        dynamic_cast<const core::TextureTarget*>(m_window->document().paintTarget());
    ASSERT_NE(target, nullptr);
    const std::vector<std::uint8_t>& coverage = target->coverage(0);
    const QImage base = QImage(files[0]).convertToFormat(QImage::Format_RGBA8888);
    ASSERT_EQ(base.width(), side);
    const QImage normal = QImage(files[2]).convertToFormat(QImage::Format_RGBA8888);
    std::size_t same = 0, flat = 0, covered = 0;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const std::uint8_t* p = &painted[0][(std::size_t(y) * std::size_t(side) + x) * 4];
            const QRgb q = base.pixel(x, y);
            if (coverage[std::size_t(y) * std::size_t(side) + std::size_t(x)] != 1)
                continue;
            ++covered;
            same += qRed(q) == p[0] && qGreen(q) == p[1] && qBlue(q) == p[2];
            flat += qGreen(normal.pixel(x, y)) == 128 && qBlue(normal.pixel(x, y)) == 255;
        }
    ASSERT_GT(covered, 0u);
    EXPECT_GT(double(same) / double(covered), 0.99);
    EXPECT_GT(double(flat) / double(covered), 0.99) << "the trefoil has no normal map: flat";
    EXPECT_TRUE(m_window->isWindowModified()) << "an export is not a save";
}

TEST_F(ProjectTest, CancelWhileOpeningKeepsTheOpenModelAndDropsTheLoad) {
    openAndBuild(*m_window, QStringLiteral("builtin:trefoil"));
    const std::uint64_t serial = m_window->document().meshSerial();
    const QString title = m_window->windowTitle();
    auto* loader = m_window->findChild<ui::ModelLoader*>();
    ASSERT_NE(loader, nullptr);
    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    // Cancel while the file is read, then while its topology is made (the last 15 %).
    for (const double stage : {0.0, 0.86}) {
        SCOPED_TRACE(stage);
        m_window->openFile(QStringLiteral("builtin:knot?triangles=3000000"));
        QProgressDialog* dialog = nullptr;
        ASSERT_TRUE(QTest::qWaitFor(
            [&] {
                dialog = m_window->findChild<QProgressDialog*>(QStringLiteral("loadProgress"));
                return dialog && dialog->isVisible() && loader->progress() >= stage;
            },
            kLoadTimeoutMs))
            << "the load ended before its progress dialog showed";
        auto* cancel = dialog->findChild<QPushButton*>();
        ASSERT_NE(cancel, nullptr);
        QTest::mouseClick(cancel, Qt::LeftButton);
        // At once, not when the worker notices: the dialog is gone, the old model stays.
        EXPECT_FALSE(loader->isLoading());
        const auto* left = m_window->findChild<QProgressDialog*>(QStringLiteral("loadProgress"));
        EXPECT_TRUE(left == nullptr || !left->isVisible());
        EXPECT_EQ(m_window->document().meshSerial(), serial);
        // The worker stops in the background and nothing of it arrives.
        ASSERT_TRUE(QTest::qWaitFor([&] { return loader->runningJobs() == 0; }, kLoadTimeoutMs));
        QTest::qWait(50);
        EXPECT_TRUE(loaded.isEmpty());
        EXPECT_EQ(m_window->document().meshSerial(), serial);
        EXPECT_EQ(m_window->windowTitle(), title);
    }
}

} // namespace project_uitest
