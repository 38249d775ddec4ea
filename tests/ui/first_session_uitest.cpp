// SPDX-License-Identifier: GPL-3.0-or-later
// A new artist's first session through real Qt event delivery: keys as an X keyboard sends them
// (QWindowSystemInterface with native scan codes), typing into the tool bar and panel fields,
// the file dialogs of Export and Save As, recovery after a crash, load warnings and errors,
// models without UVs, the Panels menu and the cursor of every tool. Needs a display with OpenGL
// 4.5 (xvfb-run; llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <QUndoStack>
#include <qpa/qwindowsysteminterface.h>

#include <cmath>
#include <functional>
#include <memory>
#include <ostream>
#include <random>
#include <set>

#include "core/io/mesh_io.h"
#include "core/io/project/project_file.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/panels/brush_toolbar.h"
#include "ui/panels/color_panel.h"
#include "ui/shell/main_window.h"
#include "ui/shell/project_controller.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

// Readable failures: gtest prints a QString as its text.
[[maybe_unused]] static void PrintTo(const QString& text, std::ostream* out) {
    *out << '"' << text.toStdString() << '"';
}

namespace first_session_uitest {

using namespace ui_test;

[[maybe_unused]] constexpr int kSaveTimeoutMs = 60000;

// X11 keycodes (evdev and the older xfree86 set agree on these) and keysyms of a US keyboard.
constexpr quint32 kScanBracketLeft = 34;
constexpr quint32 kScanBracketRight = 35;
constexpr quint32 kShiftMask = 1;

[[maybe_unused]] QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

[[maybe_unused]] bool writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}

[[maybe_unused]] void clickButton(QMessageBox* box, QMessageBox::StandardButton which) {
    QTest::mouseClick(box->button(which), Qt::LeftButton);
}

/** Whether text is fit to show: no control characters, no replacement characters. */
[[maybe_unused]] bool printable(const QString& text) {
    for (const QChar c : text)
        if (c == QChar::ReplacementCharacter || (!c.isPrint() && c != QLatin1Char(' ')))
            return false;
    return true;
}

class FirstSessionTest : public ProjectFilesTest {
protected:
    FirstSessionTest() : ProjectFilesTest({1260, 900}) {}

    QAction* action(const char* name) const {
        return m_window->findChild<QAction*>(QString::fromLatin1(name));
    }
    /** The bar over the viewport that keeps notes about the open model. */
    QWidget* messageBar() const {
        return m_window->findChild<QWidget*>(QStringLiteral("messageBar"));
    }
    QString messageBarText() const {
        QWidget* bar = messageBar();
        auto* label = bar ? bar->findChild<QLabel*>(QStringLiteral("messageBarText")) : nullptr;
        return label ? label->text() : QString();
    }
    QString modelInfo() const {
        const auto* info = m_window->statusBar()->findChild<QLabel*>();
        return info ? info->text() : QString();
    }

    bool open(const QString& source, QString* error = nullptr) {
        QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
        QSignalSpy failed(m_window.get(), &ui::MainWindow::loadFailed);
        m_window->openFile(source);
        if (!QTest::qWaitFor([&] { return !loaded.isEmpty() || !failed.isEmpty(); },
                             kLoadTimeoutMs))
            return false;
        if (error && !failed.isEmpty())
            *error = failed.first().first().toString();
        return !loaded.isEmpty();
    }

    void openAndBuild(const QString& source) {
        QSignalSpy built(m_window->depthLayersBuilder(), &ui::DepthLayersBuilder::depthLayersBuilt);
        ASSERT_TRUE(open(source));
        ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
        ASSERT_NE(document().depthLayers(), nullptr);
    }

    /** A pixel of the view in the middle of the model's surface (logical = device here). */
    QPoint onModel() const {
        const core::DepthStack& stack = document().depthLayers()->stack;
        for (int r = 0; r < stack.width / 2; r += 2)
            for (const QPoint p : {QPoint(r, 0), QPoint(-r, 0), QPoint(0, r), QPoint(0, -r)}) {
                const QPoint at = QPoint(stack.width / 2, stack.height / 2) + p;
                if (showsModelAround(stack, at, 3))
                    return at;
            }
        return {};
    }

    bool saveTo(const QString& file) {
        QSignalSpy saved(m_window->projectController(), &ui::ProjectController::saved);
        QSignalSpy failed(m_window->projectController(), &ui::ProjectController::saveFailed);
        if (!m_window->projectController()->saveTo(file))
            return false;
        EXPECT_TRUE(
            QTest::qWaitFor([&] { return !saved.isEmpty() || !failed.isEmpty(); }, kSaveTimeoutMs));
        return !saved.isEmpty();
    }

    /**
     * A key pressed and released on the keyboard, delivered as the X11 platform plugin delivers
     * it: to the focus widget, shortcuts matched through the keyboard map when scan is given.
     */
    void key(int qtKey, Qt::KeyboardModifiers modifiers = Qt::NoModifier,
             const QString& text = QString(), quint32 scan = 0, quint32 keysym = 0,
             quint32 nativeModifiers = 0) {
        QWindow* window = QApplication::focusWindow();
        ASSERT_NE(window, nullptr);
        for (const QEvent::Type type : {QEvent::KeyPress, QEvent::KeyRelease})
            QWindowSystemInterface::handleExtendedKeyEvent(window, type, qtKey, modifiers, scan,
                                                           keysym, nativeModifiers, text);
        QWindowSystemInterface::flushWindowSystemEvents();
    }
    /** A letter key as typed: E gives Qt::Key_E and the text "e". */
    void letter(char c) {
        key(Qt::Key_A + (QChar::fromLatin1(c).toLower().toLatin1() - 'a'), Qt::NoModifier,
            QString(QChar::fromLatin1(c).toLower()));
    }
    void type(const QString& text) {
        for (const QChar c : text) {
            const char l = c.toLatin1();
            int code = c.toUpper().unicode();
            if (l == '#')
                code = Qt::Key_NumberSign;
            key(code, Qt::NoModifier, QString(c));
        }
    }
    void selectAllText() { key(Qt::Key_A, Qt::ControlModifier, QStringLiteral("\x01")); }
};

// A layer-aware stroke and the pop-ups it caused are one undo step, and undoing back to
// the saved state clears the unsaved mark.
TEST_F(FirstSessionTest, AStrokeAndItsPopUpsAreOneUndoStep) {
    openAndBuild(QStringLiteral("builtin:trefoil"));
    ASSERT_TRUE(saveTo(path(QStringLiteral("knot.glb"))));
    ASSERT_FALSE(m_window->projectController()->isModified());
    const core::DepthLayers& layers = *document().depthLayers();
    const core::DepthStack& stack = layers.stack;
    const core::RegionOrderState initial = document().regionOrder().state();
    QUndoStack* stack0 = m_window->undoStack();
    ASSERT_NE(document().paintTarget(), nullptr);
    const std::vector<std::uint8_t> blank = document().paintedMesh().textures.at(0).rgba;

    // A stroke from a visible surface to where it runs under another one: from a layer-1 pixel
    // of a region linked to a layer-2 region, to a pixel where that region is on layer 2.
    bool poppedUp = false;
    for (int y = stack.height / 4; y < stack.height * 3 / 4 && !poppedUp; y += 9) {
        for (int x = stack.width / 4; x < stack.width * 3 / 4 && !poppedUp; x += 9) {
            const std::size_t p = std::size_t(y) * stack.width + x;
            const std::uint32_t back = stack.fragment(p, 2);
            if (back == core::kNone)
                continue;
            const std::uint32_t region = layers.segmentation.region[back];
            for (const core::RegionLink& link : layers.segmentation.graph.neighborsOf(region)) {
                const core::Region& front = layers.segmentation.graph.regions[link.region];
                if (front.layer != 1 || front.pixels < 400)
                    continue;
                // A start on that front region 30 to 90 px away, the first found on rings.
                QPoint from(-1, -1);
                for (int r = 30; r <= 90 && from.x() < 0; r += 20) {
                    for (int k = 0; k < 16 && from.x() < 0; ++k) {
                        const double angle = k * 3.14159265358979 / 8;
                        const QPoint at(x + int(r * std::cos(angle)), y + int(r * std::sin(angle)));
                        if (at.x() < 0 || at.y() < 0 || at.x() >= stack.width ||
                            at.y() >= stack.height)
                            continue;
                        const std::uint32_t f =
                            stack.fragment(std::size_t(at.y()) * stack.width + at.x(), 1);
                        if (f != core::kNone && layers.segmentation.region[f] == link.region)
                            from = at;
                    }
                }
                if (from.x() < 0)
                    continue;
                const int count = stack0->count();
                const std::uint64_t serial = document().regionOrderSerial();
                QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, from);
                for (int i = 1; i <= 12; ++i)
                    QTest::mouseMove(viewport(), from + (QPoint(x, y) - from) * i / 12);
                QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(x, y));
                if (document().regionOrderSerial() != serial) {
                    poppedUp = true;
                    EXPECT_EQ(stack0->count(), count + 1); // one step, not two
                } else if (stack0->count() > count) {
                    stack0->undo(); // no pop-up: take the stroke back and try elsewhere
                }
                break;
            }
        }
    }
    ASSERT_TRUE(poppedUp) << "no stroke went behind another surface";
    ASSERT_TRUE(m_window->projectController()->isModified());
    EXPECT_TRUE(action("actionUndo")->text().contains(QStringLiteral("Paint Stroke")));
    EXPECT_NE(document().regionOrder().state(), initial);

    key(Qt::Key_Z, Qt::ControlModifier, QStringLiteral("\x1a"));
    EXPECT_EQ(document().regionOrder().state(), initial); // the pop-ups went with the paint
    EXPECT_EQ(document().paintedMesh().textures.at(0).rgba, blank);
    EXPECT_FALSE(m_window->projectController()->isModified()); // back at the saved state
    EXPECT_FALSE(m_window->isWindowModified());
}

// Export proposes another name and never replaces the open project.
TEST_F(FirstSessionTest, ExportNeverReplacesTheOpenProject) {
    openAndBuild(QStringLiteral("builtin:trefoil"));
    const QString project = path(QStringLiteral("p.glb"));
    ASSERT_TRUE(saveTo(project));
    const QByteArray saved = readAll(project);
    ASSERT_FALSE(saved.isEmpty());
    ui::ProjectController* controller = m_window->projectController();
    QSignalSpy exported(controller, &ui::ProjectController::exported);
    QSignalSpy failed(controller, &ui::ProjectController::exportFailed);

    // File ▸ Export ▸ glTF Binary: the dialog proposes a name of its own. The artist types the
    // project's name over it anyway and confirms that the file may be replaced.
    QString proposed;
    onNextModal<QFileDialog>([&](QFileDialog* dialog) {
        proposed = dialog->selectedFiles().value(0);
        auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
        ASSERT_NE(name, nullptr);
        name->selectAll();
        QTest::keyClicks(name, QStringLiteral("p.glb"));
        onNextModal<QMessageBox>([](QMessageBox* box) { clickButton(box, QMessageBox::Yes); });
        QTest::keyClick(name, Qt::Key_Return);
    });
    action("actionExportGlb")->trigger();
    EXPECT_EQ(QFileInfo(proposed).fileName(), QStringLiteral("p-export.glb"));
    EXPECT_EQ(QFileInfo(proposed).absolutePath(), QFileInfo(project).absolutePath());
    QTest::qWait(0);
    controller->waitForTasks();
    QApplication::processEvents();
    EXPECT_TRUE(exported.isEmpty()) << "the open project was replaced by an export";
    ASSERT_EQ(failed.size(), 1);
    EXPECT_TRUE(failed.first().first().toString().contains(QStringLiteral("p.glb")))
        << failed.first().first().toString().toStdString();
    EXPECT_EQ(readAll(project), saved);
    core::Result<core::Project> reopened = core::loadProject(local(project));
    ASSERT_TRUE(reopened.ok());
    EXPECT_TRUE(reopened->state.has_value()) << "the project lost its LayerPaint state";

    // Accepting the proposal exports beside the project, which stays as it was.
    onNextModal<QFileDialog>([&](QFileDialog* dialog) {
        auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
        ASSERT_NE(name, nullptr);
        if (name->text() != QStringLiteral("p-export.glb")) {
            dialog->reject(); // never answer an overwrite question here
            return;
        }
        QTest::keyClick(name, Qt::Key_Return);
    });
    action("actionExportGlb")->trigger();
    EXPECT_TRUE(QTest::qWaitFor([&] { return !exported.isEmpty(); }, kSaveTimeoutMs));
    EXPECT_TRUE(QFileInfo::exists(path(QStringLiteral("p-export.glb"))));
    EXPECT_EQ(readAll(project), saved);
    EXPECT_EQ(controller->filePath(), QFileInfo(project).absoluteFilePath());
}

// Shift+[ and Shift+] as an X keyboard sends them (keys { and } with Shift).
TEST_F(FirstSessionTest, ShiftBracketsFromAKeyboardChangeTheHardness) {
    viewport()->setFocus();
    ASSERT_FLOAT_EQ(document().brush().hardness, 0.5f);
    key(Qt::Key_BraceRight, Qt::ShiftModifier, QStringLiteral("}"), kScanBracketRight, 0x7d,
        kShiftMask);
    EXPECT_FLOAT_EQ(document().brush().hardness, 0.6f);
    key(Qt::Key_BraceLeft, Qt::ShiftModifier, QStringLiteral("{"), kScanBracketLeft, 0x7b,
        kShiftMask);
    key(Qt::Key_BraceLeft, Qt::ShiftModifier, QStringLiteral("{"), kScanBracketLeft, 0x7b,
        kShiftMask);
    EXPECT_FLOAT_EQ(document().brush().hardness, 0.4f);
    // The same keys without Shift still size the brush.
    const float radius = document().brush().radius;
    key(Qt::Key_BracketRight, Qt::NoModifier, QStringLiteral("]"), kScanBracketRight, 0x5d, 0);
    EXPECT_GT(document().brush().radius, radius);
    EXPECT_FLOAT_EQ(document().brush().hardness, 0.4f);
}

// After Enter or Escape in a tool bar or panel field, the tool keys work again.
TEST_F(FirstSessionTest, ToolKeysWorkAfterEnterOrEscapeInAField) {
    openAndBuild(QStringLiteral("builtin:trefoil"));
    auto* opacity = m_window->brushToolBar()->findChild<QSpinBox*>(QStringLiteral("brushOpacity"));
    auto* radius = m_window->brushToolBar()->findChild<QSpinBox*>(QStringLiteral("brushRadius"));
    auto* hex = m_window->colorPanel()->findChild<QLineEdit*>(QStringLiteral("colorHex"));
    ASSERT_TRUE(opacity && radius && hex);
    ASSERT_NE(opacity->value(), 40);

    // Opacity 40, Enter, then E: the eraser.
    QTest::mouseClick(opacity->findChild<QLineEdit*>(), Qt::LeftButton);
    ASSERT_TRUE(opacity->hasFocus());
    selectAllText();
    type(QStringLiteral("40"));
    key(Qt::Key_Return, Qt::NoModifier, QStringLiteral("\r"));
    EXPECT_EQ(opacity->value(), 40);
    EXPECT_FLOAT_EQ(document().brush().opacity, 0.4f);
    EXPECT_TRUE(viewport()->hasFocus());
    letter('e');
    EXPECT_EQ(m_window->tool(), ui::Tool::Eraser);

    // A hex colour, Enter, then G and a click: a fill in that colour.
    QTest::mouseClick(hex, Qt::LeftButton);
    ASSERT_TRUE(hex->hasFocus());
    selectAllText();
    type(QStringLiteral("#20a040"));
    key(Qt::Key_Enter, Qt::KeypadModifier, QStringLiteral("\r"));
    EXPECT_EQ(m_window->colorPanel()->foreground(), QColor(0x20, 0xa0, 0x40));
    EXPECT_TRUE(viewport()->hasFocus());
    letter('g');
    EXPECT_EQ(m_window->tool(), ui::Tool::Fill);
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, onModel());
    ASSERT_EQ(m_window->undoStack()->count(), 1);
    EXPECT_EQ(m_window->undoStack()->text(0), QStringLiteral("Fill"));

    // Escape leaves a field without taking what was typed.
    QTest::mouseClick(radius->findChild<QLineEdit*>(), Qt::LeftButton);
    ASSERT_TRUE(radius->hasFocus());
    selectAllText();
    type(QStringLiteral("77"));
    key(Qt::Key_Escape, Qt::NoModifier, QStringLiteral("\x1b"));
    EXPECT_EQ(radius->value(), 32);
    EXPECT_EQ(radius->cleanText(), QStringLiteral("32"));
    EXPECT_FLOAT_EQ(document().brush().radius, 32.0f);
    EXPECT_TRUE(viewport()->hasFocus());
    letter('b');
    EXPECT_EQ(m_window->tool(), ui::Tool::Brush);

    // Escape in the hex field: the colour in use stays.
    QTest::mouseClick(hex, Qt::LeftButton);
    selectAllText();
    type(QStringLiteral("#ffffff"));
    key(Qt::Key_Escape, Qt::NoModifier, QStringLiteral("\x1b"));
    EXPECT_EQ(m_window->colorPanel()->foreground(), QColor(0x20, 0xa0, 0x40));
    EXPECT_EQ(hex->text().toLower(), QStringLiteral("#20a040"));
    EXPECT_TRUE(viewport()->hasFocus());

    // A click on a number field's arrow edits nothing as text: letters stay tool keys.
    QTest::mouseClick(radius, Qt::LeftButton, Qt::NoModifier, QPoint(radius->width() - 6, 4));
    ASSERT_TRUE(radius->hasFocus());
    EXPECT_EQ(radius->value(), 33);
    letter('i');
    EXPECT_EQ(m_window->tool(), ui::Tool::Eyedropper);
}

// A recovered document keeps its own name and says it was recovered.
TEST_F(FirstSessionTest, RecoveredWorkKeepsItsNameAndSaysSo) {
    QString orphan;
    ASSERT_NO_FATAL_FAILURE(writeCrashedAutosave({}, orphan));
    QSettings().setValue(QStringLiteral("project/directory"), m_dir.path());

    m_window->setErrorDialogsEnabled(true);
    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    onNextModal<QMessageBox>(
        [](QMessageBox* box) {
            QTest::mouseClick(box->findChild<QAbstractButton*>(QStringLiteral("recoverButton")),
                              Qt::LeftButton);
        },
        [](QMessageBox* box) { return box->objectName() == QStringLiteral("recoveryBox"); });
    ASSERT_TRUE(m_window->projectController()->offerRecovery());
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    m_window->setErrorDialogsEnabled(false);
    m_window->activateWindow(); // the question box had the keyboard
    ASSERT_TRUE(QTest::qWaitForWindowActive(m_window.get()));

    EXPECT_EQ(m_window->currentSource(), QStringLiteral("builtin:row"));
    EXPECT_TRUE(modelInfo().startsWith(QStringLiteral("Row of four"))) << modelInfo().toStdString();
    EXPECT_FALSE(shownTitle(*m_window).contains(QStringLiteral("autosave")));
    ASSERT_NE(messageBar(), nullptr);
    EXPECT_TRUE(messageBar()->isVisible());
    EXPECT_TRUE(messageBarText().contains(QStringLiteral("ecovered")))
        << messageBarText().toStdString();

    // Ctrl+S proposes the model's own name; the artist saves there.
    QString proposed;
    onNextModal<QFileDialog>([&](QFileDialog* dialog) {
        proposed = dialog->selectedFiles().value(0);
        auto* name = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"));
        ASSERT_NE(name, nullptr);
        if (name->text() != QStringLiteral("row.glb")) {
            dialog->reject();
            return;
        }
        QTest::keyClick(name, Qt::Key_Return);
    });
    QSignalSpy saved(m_window->projectController(), &ui::ProjectController::saved);
    key(Qt::Key_S, Qt::ControlModifier, QStringLiteral("\x13"));
    EXPECT_EQ(QFileInfo(proposed).fileName(), QStringLiteral("row.glb"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !saved.isEmpty(); }, kSaveTimeoutMs));
    EXPECT_EQ(m_window->projectController()->filePath(), path(QStringLiteral("row.glb")));
    EXPECT_EQ(shownTitle(*m_window), QStringLiteral("row.glb — LayerPaint"));
    EXPECT_FALSE(modelInfo().contains(QStringLiteral("autosave"))) << modelInfo().toStdString();
}

// Load warnings are shown whole, over the viewport, until dismissed.
TEST_F(FirstSessionTest, LoadWarningsStayWholeUntilDismissed) {
    const QString file = path(QStringLiteral("warnings.obj"));
    ASSERT_TRUE(writeFile(file, "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1e39 0 0\nvn 0 0 1\n"
                                "f 1//1 2//2 3//2\nl 1 3\n"));
    ASSERT_TRUE(open(file));
    const std::vector<std::string>& warnings = viewport()->mesh()->warnings;
    ASSERT_EQ(warnings.size(), 2u);
    QWidget* bar = messageBar();
    ASSERT_NE(bar, nullptr);
    EXPECT_TRUE(bar->isVisible());
    EXPECT_TRUE(viewport()->isAncestorOf(bar)) << "the bar is over the viewport";
    for (const std::string& warning : warnings)
        EXPECT_TRUE(messageBarText().contains(QString::fromStdString(warning)))
            << warning << " in " << messageBarText().toStdString();
    // Later messages (a mode change here) do not take its place.
    letter('l');
    EXPECT_TRUE(bar->isVisible());
    EXPECT_TRUE(messageBarText().contains(QString::fromStdString(warnings.front())));
    // The artist dismisses it.
    auto* close = bar->findChild<QAbstractButton*>(QStringLiteral("messageBarClose"));
    ASSERT_NE(close, nullptr);
    QTest::mouseClick(close, Qt::LeftButton);
    EXPECT_FALSE(bar->isVisible());
    // It comes back with the next model that has something to say, not with one that has not.
    ASSERT_TRUE(open(file));
    EXPECT_TRUE(messageBar()->isVisible());
    ASSERT_TRUE(open(QStringLiteral("builtin:trefoil")));
    EXPECT_FALSE(messageBar()->isVisible());
}

// Errors name the file and say what is wrong in the user's words, no raw bytes.
TEST_F(FirstSessionTest, OpenErrorsAreInTheUsersWords) {
    std::mt19937 random(15);
    QByteArray noise(4096, '\0');
    for (char& c : noise)
        c = char(random() & 0xff);
    noise[0] = char(0x9c); // never "glTF" or "{"
    struct Case {
        QString name;
        QByteArray bytes;
        const char* forbidden;
    };
    const Case cases[] = {
        {QStringLiteral("random.glb"), noise, "JSON"},
        {QStringLiteral("notes.glb"), "hello, these are notes\n", "JSON"},
        {QStringLiteral("notes.obj"), "just notes\n", "OBJ-file"},
        {QStringLiteral("random.stl"), noise.left(100), "representation"},
        {QStringLiteral("random.ply"), noise, "magic number"},
    };
    m_window->setErrorDialogsEnabled(true);
    for (const Case& c : cases) {
        const QString file = path(c.name);
        ASSERT_TRUE(writeFile(file, c.bytes));
        QString message;
        QString shown;
        onNextModal<QMessageBox>([&](QMessageBox* box) {
            shown = box->text() + QLatin1Char('\n') + box->informativeText();
            clickButton(box, QMessageBox::Ok);
        });
        EXPECT_FALSE(open(file, &message)) << c.name.toStdString();
        ASSERT_TRUE(QTest::qWaitFor([&] { return !shown.isEmpty(); }, 10000));
        EXPECT_TRUE(shown.contains(c.name)) << shown.toStdString();
        EXPECT_FALSE(shown.contains(QLatin1String(c.forbidden), Qt::CaseInsensitive))
            << shown.toStdString();
        EXPECT_TRUE(printable(message)) << message.toStdString();
        EXPECT_TRUE(message.contains(c.name)) << message.toStdString();
    }
}

// A model without UVs says so, and the Paint into box says why textures are off.
TEST_F(FirstSessionTest, ModelWithoutUvsSaysItGetsAnAutomaticUvLayout) {
    const QString file = path(QStringLiteral("tetra.obj"));
    ASSERT_TRUE(writeFile(file, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"));
    ASSERT_TRUE(open(file));
    ASSERT_FALSE(document().mesh().hasUvs());
    ASSERT_NE(messageBar(), nullptr);
    EXPECT_TRUE(messageBar()->isVisible());
    EXPECT_TRUE(messageBarText().contains(QStringLiteral("texture coordinates")))
        << messageBarText().toStdString();
    // Four vertices are coarse for any brush: a texture over an automatic layout by default.
    EXPECT_TRUE(messageBarText().contains(QStringLiteral("automatic UV layout")));
    auto* target = m_window->brushToolBar()->findChild<QComboBox*>(QStringLiteral("paintTarget"));
    ASSERT_NE(target, nullptr);
    EXPECT_TRUE(target->toolTip().contains(QStringLiteral("no texture coordinates")))
        << target->toolTip().toStdString();
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return target->currentText().contains(QStringLiteral("automatic UVs")); },
        kLoadTimeoutMs));
    // A model with UVs: textures again, and no such note.
    ASSERT_TRUE(open(QStringLiteral("builtin:trefoil")));
    EXPECT_FALSE(target->toolTip().contains(QStringLiteral("no texture coordinates")));
    EXPECT_FALSE(target->currentText().contains(QStringLiteral("automatic UVs")));
    EXPECT_FALSE(messageBar()->isVisible());
}

// View ▸ Panels names every panel and tool bar apart.
TEST_F(FirstSessionTest, PanelsMenuNamesEveryEntryApart) {
    auto* panels = m_window->findChild<QMenu*>(QStringLiteral("panelsMenu"));
    ASSERT_NE(panels, nullptr);
    std::set<QString> names;
    int entries = 0;
    for (const QAction* entry : panels->actions()) {
        if (entry->isSeparator())
            continue;
        ++entries;
        names.insert(entry->text().remove(QLatin1Char('&')));
    }
    EXPECT_EQ(int(names.size()), entries) << "two entries of View ▸ Panels share a name";
    EXPECT_EQ(m_window->findChild<QDockWidget*>(QStringLiteral("brushDock"))->windowTitle(),
              QStringLiteral("Brush"));
}

// Every tool shows its own cursor; the brush outline only where it means something.
TEST_F(FirstSessionTest, EveryToolShowsItsOwnCursor) {
    openAndBuild(QStringLiteral("builtin:trefoil"));
    viewport()->setFocus();
    struct Seen {
        Qt::CursorShape shape;
        QImage image;
        bool outline;
    };
    const auto choose = [&](char c) {
        letter(c);
        QTest::mouseMove(viewport(), viewport()->rect().center() + QPoint(3, 1));
        QTest::mouseMove(viewport(), viewport()->rect().center());
        const QCursor cursor = viewport()->cursor();
        return Seen{cursor.shape(),
                    cursor.shape() == Qt::BitmapCursor ? cursor.pixmap().toImage() : QImage(),
                    viewport()->brushOutlineVisible()};
    };
    const Seen brush = choose('b');
    EXPECT_EQ(m_window->tool(), ui::Tool::Brush);
    EXPECT_TRUE(brush.outline);
    const Seen eraser = choose('e');
    EXPECT_TRUE(eraser.outline);
    const Seen fill = choose('g');
    EXPECT_EQ(m_window->tool(), ui::Tool::Fill);
    EXPECT_FALSE(fill.outline);
    EXPECT_EQ(fill.shape, Qt::BitmapCursor);
    EXPECT_FALSE(fill.image.isNull());
    const Seen picker = choose('i');
    EXPECT_EQ(m_window->tool(), ui::Tool::Eyedropper);
    EXPECT_FALSE(picker.outline);
    EXPECT_EQ(picker.shape, Qt::CrossCursor);
    const Seen popUp = choose('p');
    EXPECT_EQ(m_window->tool(), ui::Tool::PopUp);
    EXPECT_FALSE(popUp.outline);
    EXPECT_EQ(popUp.shape, Qt::PointingHandCursor);
    const Seen hide = choose('h');
    EXPECT_EQ(m_window->tool(), ui::Tool::Hide);
    EXPECT_TRUE(hide.outline) << "paint to hide uses the brush radius";
    // The painting tools' cursor is not the fill bucket, nor the eyedropper's crosshair.
    EXPECT_NE(brush.shape, Qt::CrossCursor);
    EXPECT_TRUE(brush.shape != fill.shape || brush.image != fill.image);
    // Back to the brush: its outline again.
    EXPECT_TRUE(choose('b').outline);
}

// The first window fits the screen: a fixed 1280 × 800 would put the right column and the
// status bar off a 1000 × 700 screen.
TEST(FirstStart, TheWindowFitsTheScreen) {
    QSettings().clear(); // no saved geometry: a first start
    ui::MainWindow window;
    const QScreen* screen = window.screen();
    ASSERT_NE(screen, nullptr);
    const QSize available = screen->availableGeometry().size();
    EXPECT_LE(window.width(), std::min(1280, available.width() * 9 / 10));
    EXPECT_LE(window.height(), std::min(800, available.height() * 9 / 10));
    EXPECT_GE(window.width(), std::min(1280, available.width() * 9 / 10) - 1);
}

} // namespace first_session_uitest
