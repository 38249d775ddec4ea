// SPDX-License-Identifier: GPL-3.0-or-later
// The viewer through real Qt event delivery: opening models, camera input, errors, settings.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDropEvent>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>
#include <QTimer>
#include <QUrl>
#include <QWheelEvent>
#include <qpa/qwindowsysteminterface.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

#include <glm/geometric.hpp>

#include "core/model/builtin_models.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/shell/model_loader.h"
#include "ui/shell/recent_files.h"
#include "ui/shell/stall_meter.h"
#include "ui/view/viewport.h"

namespace viewer_uitest {

using namespace ui_test;

QString boxPath() {
    return QStringLiteral(LAYERPAINT_ASSIMP_MODELS
                          "/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb");
}

/** Fraction of pixels that differ from the top-left (background) pixel. */
double foregroundFraction(const QImage& image) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    const QRgb background = rgb.pixel(0, 0);
    qint64 count = 0;
    for (int y = 0; y < rgb.height(); ++y)
        for (int x = 0; x < rgb.width(); ++x)
            count += channelDifference(rgb.pixel(x, y), background) > 8 ? 1 : 0;
    return double(count) / double(qint64(rgb.width()) * rgb.height());
}

constexpr QSize kWindowSize(800, 600);

class ViewerTest : public WindowTest {
protected:
    ViewerTest() : WindowTest(kWindowSize) {}

    /** Opens as the command line does and waits; true if modelLoaded() came. */
    static bool openAndWait(ui::MainWindow& window, const QStringList& arguments) {
        QSignalSpy loaded(&window, &ui::MainWindow::modelLoaded);
        QSignalSpy failed(&window, &ui::MainWindow::loadFailed);
        window.openFromCommandLine(arguments);
        const bool done =
            QTest::qWaitFor([&] { return !loaded.isEmpty() || !failed.isEmpty(); }, kLoadTimeoutMs);
        return done && loaded.size() == 1 && failed.isEmpty();
    }

    QPoint center() const { return viewport()->rect().center(); }

    void middleDrag(Qt::KeyboardModifiers modifiers, QPoint delta,
                    Qt::MouseButton button = Qt::MiddleButton) {
        const QPoint start = center();
        QTest::mousePress(viewport(), button, modifiers, start);
        constexpr int kSteps = 10;
        for (int i = 1; i <= kSteps; ++i)
            QTest::mouseMove(viewport(), start + delta * i / kSteps);
        QTest::mouseRelease(viewport(), button, modifiers, start + delta);
    }
};

TEST_F(ViewerTest, OpensFileFromCommandLineAndDrawsIt) {
    if (!QFileInfo::exists(boxPath()))
        GTEST_SKIP() << "assimp test models not installed: " << boxPath().toStdString();
    ASSERT_TRUE(openAndWait(*m_window, {boxPath()}));

    EXPECT_EQ(m_window->currentSource(), QFileInfo(boxPath()).absoluteFilePath());
    EXPECT_EQ(shownTitle(*m_window), QStringLiteral("BoxTextured.glb — LayerPaint"));
    ASSERT_TRUE(viewport()->mesh());
    EXPECT_EQ(viewport()->mesh()->triangleCount(), 12u);
    EXPECT_EQ(viewport()->mesh()->vertexCount(), 24u);
    EXPECT_FALSE(m_window->isLoading());

    const QImage image = grab();
    const qreal ratio = viewport()->devicePixelRatioF();
    EXPECT_EQ(image.width(), qRound(viewport()->width() * ratio));
    EXPECT_EQ(image.height(), qRound(viewport()->height() * ratio));
    // A framed cube seen face-on covers a good part of the view but not all of it.
    const double covered = foregroundFraction(image);
    EXPECT_GT(covered, 0.05);
    EXPECT_LT(covered, 0.9);

    const auto* info = m_window->statusBar()->findChild<QLabel*>();
    ASSERT_NE(info, nullptr);
    EXPECT_TRUE(info->text().contains(QStringLiteral("24 vertices"))) << info->text().toStdString();
    EXPECT_TRUE(info->text().contains(QStringLiteral("12 triangles")));
}

TEST_F(ViewerTest, RelativeCommandLinePathIsResolved) {
    if (!QFileInfo::exists(boxPath()))
        GTEST_SKIP() << "assimp test models not installed";
    const QString previous = QDir::currentPath();
    ASSERT_TRUE(QDir::setCurrent(QFileInfo(boxPath()).absolutePath()));
    const bool opened = openAndWait(*m_window, {QStringLiteral("BoxTextured.glb")});
    QDir::setCurrent(previous);
    ASSERT_TRUE(opened);
    EXPECT_EQ(m_window->currentSource(), QFileInfo(boxPath()).absoluteFilePath());
}

TEST_F(ViewerTest, LoadWarningsShowOverTheView) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("with line.obj"));
    {
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        file.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 3\n");
    }
    ASSERT_TRUE(openAndWait(*m_window, {path}));
    ASSERT_TRUE(viewport()->mesh());
    ASSERT_FALSE(viewport()->mesh()->warnings.empty());
    EXPECT_EQ(viewport()->mesh()->triangleCount(), 1u);
    const QString first = QString::fromStdString(viewport()->mesh()->warnings.front());
    auto* bar = m_window->findChild<QLabel*>(QStringLiteral("messageBarText"));
    ASSERT_NE(bar, nullptr);
    EXPECT_TRUE(bar->isVisible());
    EXPECT_TRUE(bar->text().contains(first)) << bar->text().toStdString();
    EXPECT_FALSE(m_window->statusBar()->currentMessage().isEmpty()); // a hint to look there
    const auto* info = m_window->statusBar()->findChild<QLabel*>();
    ASSERT_NE(info, nullptr);
    EXPECT_TRUE(info->toolTip().contains(first));
}

TEST_F(ViewerTest, WithoutArgumentsOpensTheTrefoil) {
    ASSERT_TRUE(openAndWait(*m_window, {}));
    EXPECT_EQ(m_window->currentSource(), QString::fromLatin1(core::kDefaultModel));
    EXPECT_EQ(shownTitle(*m_window), QStringLiteral("Trefoil knot — LayerPaint"));
    ASSERT_TRUE(viewport()->mesh());
    EXPECT_EQ(viewport()->mesh()->vertexCount(), 144000u);
    // The recent list only holds files.
    EXPECT_TRUE(m_window->recentFiles().isEmpty());

    const double covered = foregroundFraction(grab());
    EXPECT_GT(covered, 0.05);
    EXPECT_LT(covered, 0.9);

    // Framed: the camera looks at the bounds' centre.
    const core::Bounds bounds = viewport()->mesh()->bounds();
    EXPECT_LT(glm::length(viewport()->camera().target - bounds.center()), 1e-5f);
}

TEST_F(ViewerTest, BuiltinMenuOpensModels) {
    auto* action = m_window->findChild<QAction*>(QStringLiteral("actionBuiltin_hexring"));
    ASSERT_NE(action, nullptr);
    EXPECT_EQ(action->text(), QStringLiteral("Hexagonal ring"));
    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    action->trigger();
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    EXPECT_EQ(loaded.first().first().toString(), QStringLiteral("builtin:hexring"));
    EXPECT_EQ(shownTitle(*m_window), QStringLiteral("Hexagonal ring — LayerPaint"));
}

TEST_F(ViewerTest, MiddleDragOrbitsTheCamera) {
    ASSERT_TRUE(openAndWait(*m_window, {QStringLiteral("builtin:trefoil")}));
    const QImage before = grab();
    const core::Camera camera = viewport()->camera();

    middleDrag(Qt::NoModifier, QPoint(100, 0));

    // 0.4° per pixel; dragging right turns the model right, i.e. the eye moves to -yaw.
    EXPECT_NEAR(viewport()->camera().yawDegrees, camera.yawDegrees - 40.0f, 1e-3f);
    EXPECT_NEAR(viewport()->camera().pitchDegrees, camera.pitchDegrees, 1e-5f);
    EXPECT_FLOAT_EQ(viewport()->camera().distance, camera.distance);
    const QImage after = grab();
    EXPECT_GT(differingFraction(before, after), 0.02);
    EXPECT_GT(foregroundFraction(after), 0.05);

    middleDrag(Qt::NoModifier, QPoint(0, 50));
    EXPECT_NEAR(viewport()->camera().pitchDegrees, camera.pitchDegrees + 20.0f, 1e-3f);
}

TEST_F(ViewerTest, ShiftMiddleDragPans) {
    ASSERT_TRUE(openAndWait(*m_window, {QStringLiteral("builtin:trefoil")}));
    const core::Camera camera = viewport()->camera();
    const QImage before = grab();

    middleDrag(Qt::ShiftModifier, QPoint(80, 0));

    EXPECT_FLOAT_EQ(viewport()->camera().yawDegrees, camera.yawDegrees);
    // The model follows the cursor: a point at the old target moves 80 px to the right.
    const core::View view = viewport()->view();
    const glm::vec3 moved = view.project(camera.target);
    const qreal ratio = viewport()->devicePixelRatioF();
    const core::View old = camera.view(view.width, view.height);
    const glm::vec3 was = old.project(camera.target);
    EXPECT_NEAR(moved.x - was.x, 80.0 * ratio, 0.5);
    EXPECT_NEAR(moved.y - was.y, 0.0, 0.5);
    EXPECT_GT(differingFraction(before, grab()), 0.02);
}

TEST_F(ViewerTest, WheelAndAltRightDragZoom) {
    ASSERT_TRUE(openAndWait(*m_window, {QStringLiteral("builtin:trefoil")}));
    const float distance = viewport()->camera().distance;

    const QPointF pos = center();
    QWheelEvent wheel(pos, viewport()->mapToGlobal(pos), QPoint(), QPoint(0, 120), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &wheel);
    EXPECT_TRUE(wheel.isAccepted());
    EXPECT_NEAR(viewport()->camera().distance, distance * 0.85f, distance * 1e-5f);

    // Alt+right drag to the right moves closer.
    middleDrag(Qt::AltModifier, QPoint(100, 0), Qt::RightButton);
    EXPECT_NEAR(viewport()->camera().distance, distance * 0.85f * std::exp(-0.5f),
                distance * 1e-4f);
}

TEST_F(ViewerTest, AltButtonsNavigateForTablets) {
    ASSERT_TRUE(openAndWait(*m_window, {QStringLiteral("builtin:trefoil")}));
    const core::Camera camera = viewport()->camera();

    middleDrag(Qt::AltModifier, QPoint(50, 0), Qt::LeftButton);
    EXPECT_NEAR(viewport()->camera().yawDegrees, camera.yawDegrees - 20.0f, 1e-3f);

    const glm::vec3 target = viewport()->camera().target;
    middleDrag(Qt::AltModifier, QPoint(0, 40), Qt::MiddleButton);
    EXPECT_GT(glm::length(viewport()->camera().target - target), 1e-4f);
}

TEST_F(ViewerTest, LeftButtonIsLeftForPainting) {
    ASSERT_TRUE(openAndWait(*m_window, {QStringLiteral("builtin:trefoil")}));
    const core::Camera camera = viewport()->camera();
    QSignalSpy pressed(viewport(), &ui::Viewport::paintPressed);
    QSignalSpy moved(viewport(), &ui::Viewport::paintMoved);
    QSignalSpy released(viewport(), &ui::Viewport::paintReleased);

    middleDrag(Qt::NoModifier, QPoint(30, 20), Qt::LeftButton);

    EXPECT_FLOAT_EQ(viewport()->camera().yawDegrees, camera.yawDegrees);
    EXPECT_FLOAT_EQ(viewport()->camera().distance, camera.distance);
    ASSERT_EQ(pressed.size(), 1);
    EXPECT_EQ(moved.size(), 10);
    ASSERT_EQ(released.size(), 1);
    // Device pixels, origin top-left.
    const qreal ratio = viewport()->devicePixelRatioF();
    EXPECT_EQ(pressed.first().first().toPointF(), QPointF(center()) * ratio);
    EXPECT_EQ(released.first().first().toPointF(), QPointF(center() + QPoint(30, 20)) * ratio);
}

TEST_F(ViewerTest, KeysToggleOrthographicAndFrameAll) {
    ASSERT_TRUE(openAndWait(*m_window, {QStringLiteral("builtin:trefoil")}));
    auto* ortho = m_window->findChild<QAction*>(QStringLiteral("actionOrthographic"));
    ASSERT_NE(ortho, nullptr);
    const QImage perspective = grab();

    QTest::keyClick(m_window.get(), Qt::Key_O);
    EXPECT_TRUE(viewport()->isOrthographic());
    EXPECT_TRUE(ortho->isChecked());
    EXPECT_GT(differingFraction(perspective, grab()), 0.005);
    QTest::keyClick(m_window.get(), Qt::Key_5);
    EXPECT_FALSE(viewport()->isOrthographic());
    EXPECT_FALSE(ortho->isChecked());

    const glm::vec3 framed = viewport()->camera().target;
    const float distance = viewport()->camera().distance;
    middleDrag(Qt::ShiftModifier, QPoint(60, 30));
    QWheelEvent wheel(QPointF(center()), viewport()->mapToGlobal(QPointF(center())), QPoint(),
                      QPoint(0, -240), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &wheel);
    ASSERT_GT(glm::length(viewport()->camera().target - framed), 1e-4f);

    QTest::keyClick(m_window.get(), Qt::Key_F);
    EXPECT_LT(glm::length(viewport()->camera().target - framed), 1e-6f);
    EXPECT_FLOAT_EQ(viewport()->camera().distance, distance);

    middleDrag(Qt::ShiftModifier, QPoint(60, 30));
    QTest::keyClick(m_window.get(), Qt::Key_Home);
    EXPECT_LT(glm::length(viewport()->camera().target - framed), 1e-6f);
}

TEST_F(ViewerTest, FailedOpenKeepsTheCurrentModel) {
    ASSERT_TRUE(openAndWait(*m_window, {QStringLiteral("builtin:trefoil")}));
    const auto mesh = viewport()->mesh();
    const QString title = m_window->windowTitle();
    const QImage before = grab();

    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString missing = dir.filePath(QStringLiteral("missing.glb"));
    const QString empty = dir.filePath(QStringLiteral("empty.obj"));
    {
        QFile file(empty);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
    }

    for (const QString& path : {missing, empty}) {
        QSignalSpy failed(m_window.get(), &ui::MainWindow::loadFailed);
        QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
        m_window->openFile(path);
        ASSERT_TRUE(failed.wait(kLoadTimeoutMs)) << path.toStdString();
        EXPECT_TRUE(loaded.isEmpty());
        const QString message = failed.first().first().toString();
        EXPECT_TRUE(message.contains(QFileInfo(path).fileName())) << message.toStdString();

        EXPECT_EQ(viewport()->mesh(), mesh);
        EXPECT_EQ(m_window->currentSource(), QStringLiteral("builtin:trefoil"));
        EXPECT_EQ(m_window->windowTitle(), title);
        EXPECT_TRUE(m_window->recentFiles().isEmpty());
        EXPECT_TRUE(m_window->statusBar()->currentMessage().contains(QFileInfo(path).fileName()));
        EXPECT_LT(differingFraction(before, grab()), 0.001);
    }
}

TEST_F(ViewerTest, CancellingTheProgressDialogKeepsTheCurrentModel) {
    ASSERT_TRUE(openAndWait(*m_window, {QStringLiteral("builtin:hexring")}));
    const auto mesh = viewport()->mesh();

    // A grid OBJ big enough to take well over the dialog's delay to load.
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("big grid.obj"));
    {
        constexpr int n = 700;
        QByteArray text;
        text.reserve(40 << 20);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                text += "v " + QByteArray::number(i) + ' ' + QByteArray::number(j) + " 0\n";
        for (int j = 0; j + 1 < n; ++j) {
            for (int i = 0; i + 1 < n; ++i) {
                const QByteArray a = QByteArray::number(j * n + i + 1);
                const QByteArray b = QByteArray::number(j * n + i + 2);
                const QByteArray c = QByteArray::number((j + 1) * n + i + 1);
                const QByteArray d = QByteArray::number((j + 1) * n + i + 2);
                text += "f " + a + ' ' + b + ' ' + c + "\nf " + b + ' ' + d + ' ' + c + '\n';
            }
        }
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        ASSERT_EQ(file.write(text), text.size());
    }

    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    QSignalSpy failed(m_window.get(), &ui::MainWindow::loadFailed);
    m_window->openFile(path);
    EXPECT_TRUE(m_window->isLoading());
    // The event loop keeps running while the file loads: the view still repaints.
    EXPECT_GT(foregroundFraction(grab()), 0.01);

    QProgressDialog* progress = nullptr;
    const bool shown = QTest::qWaitFor(
        [&] {
            progress = m_window->findChild<QProgressDialog*>();
            return (progress && progress->isVisible()) || !m_window->isLoading();
        },
        kLoadTimeoutMs);
    ASSERT_TRUE(shown);
    if (!m_window->isLoading())
        GTEST_SKIP() << "the file loaded before the progress dialog appeared";
    EXPECT_TRUE(progress->labelText().contains(QStringLiteral("big grid.obj")));
    auto* cancel = progress->findChild<QPushButton*>();
    ASSERT_NE(cancel, nullptr);
    QTest::mouseClick(cancel, Qt::LeftButton);

    ASSERT_TRUE(QTest::qWaitFor([&] { return !m_window->isLoading(); }, kLoadTimeoutMs));
    EXPECT_TRUE(loaded.isEmpty());
    EXPECT_TRUE(failed.isEmpty());
    EXPECT_EQ(viewport()->mesh(), mesh);
    EXPECT_EQ(m_window->currentSource(), QStringLiteral("builtin:hexring"));
    EXPECT_TRUE(m_window->statusBar()->currentMessage().contains(QStringLiteral("cancelled")));
    EXPECT_TRUE(QTest::qWaitFor([&] { return !m_window->findChild<QProgressDialog*>(); }));
}

TEST_F(ViewerTest, FailedOpenShowsAnErrorDialog) {
    m_window->setErrorDialogsEnabled(true);
    QTemporaryDir dir;
    const QString missing = dir.filePath(QStringLiteral("nowhere.ply"));
    QSignalSpy failed(m_window.get(), &ui::MainWindow::loadFailed);
    m_window->openFile(missing);
    ASSERT_TRUE(failed.wait(kLoadTimeoutMs));

    QMessageBox* box = nullptr;
    ASSERT_TRUE(QTest::qWaitFor([&] {
        box = m_window->findChild<QMessageBox*>();
        return box && box->isVisible();
    }));
    EXPECT_TRUE(box->text().contains(QStringLiteral("nowhere.ply")));
    EXPECT_EQ(box->informativeText(), failed.first().first().toString());
    box->accept();
    EXPECT_TRUE(QTest::qWaitFor([&] { return !m_window->findChild<QMessageBox*>(); }));
}

TEST_F(ViewerTest, RecentFilesPersistAndForgetDeletedFiles) {
    if (!QFileInfo::exists(boxPath()))
        GTEST_SKIP() << "assimp test models not installed";
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString copy = dir.filePath(QStringLiteral("box copy.glb"));
    ASSERT_TRUE(QFile::copy(boxPath(), copy));
    const QString canonical = QFileInfo(copy).canonicalFilePath();

    ASSERT_TRUE(openAndWait(*m_window, {boxPath()}));
    ASSERT_TRUE(openAndWait(*m_window, {copy}));
    EXPECT_EQ(m_window->recentFiles(),
              QStringList({canonical, QFileInfo(boxPath()).canonicalFilePath()}));

    // A new window (as after a restart) reads the list back from QSettings.
    m_window.reset();
    auto window = makeWindow(kWindowSize);
    EXPECT_EQ(window->recentFiles().value(0), canonical);
    auto* menu = window->findChild<QMenu*>(QStringLiteral("recentMenu"));
    ASSERT_NE(menu, nullptr);
    ASSERT_FALSE(menu->actions().isEmpty());
    QAction* first = menu->actions().first();
    EXPECT_EQ(first->data().toString(), canonical);
    EXPECT_EQ(first->text(), QStringLiteral("&1 box copy.glb"));

    // Triggering the entry opens the file.
    QSignalSpy loaded(window.get(), &ui::MainWindow::modelLoaded);
    first->trigger();
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    EXPECT_EQ(QFileInfo(window->currentSource()).canonicalFilePath(), canonical);

    // A deleted file disappears from the list and from the stored settings.
    ASSERT_TRUE(QFile::remove(copy));
    EXPECT_EQ(window->recentFiles(), QStringList({QFileInfo(boxPath()).canonicalFilePath()}));
    EXPECT_EQ(QSettings().value(QStringLiteral("recentFiles")).toStringList().size(), 1);
}

TEST(RecentFilesTest, KeepsTheTenMostRecent) {
    QSettings().clear();
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const ui::RecentFiles recent;
    QStringList paths;
    for (int i = 0; i < 12; ++i) {
        const QString path = dir.filePath(QStringLiteral("model%1.obj").arg(i));
        QFile file(path);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        paths.prepend(QFileInfo(path).canonicalFilePath());
        recent.add(path);
    }
    recent.add(dir.filePath(QStringLiteral("model5.obj"))); // again: moves to the front
    const QStringList files = recent.files();
    ASSERT_EQ(files.size(), ui::RecentFiles::kMaxEntries);
    EXPECT_EQ(files.first(), paths.at(6));
    EXPECT_EQ(files.at(1), paths.at(0));
    EXPECT_EQ(files.count(paths.at(6)), 1);
    QSettings().clear();
}

TEST_F(ViewerTest, DroppingAFileOpensIt) {
    if (!QFileInfo::exists(boxPath()))
        GTEST_SKIP() << "assimp test models not installed";
    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(boxPath())});
    const QPoint pos = m_window->rect().center();

    QDragEnterEvent enter(pos, Qt::CopyAction, &mime, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(m_window.get(), &enter);
    EXPECT_TRUE(enter.isAccepted());

    QSignalSpy loaded(m_window.get(), &ui::MainWindow::modelLoaded);
    QDropEvent drop(QPointF(pos), Qt::CopyAction, &mime, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(m_window.get(), &drop);
    ASSERT_TRUE(loaded.wait(kLoadTimeoutMs));
    EXPECT_EQ(m_window->currentSource(), QFileInfo(boxPath()).absoluteFilePath());

    QMimeData text;
    text.setText(QStringLiteral("not a file"));
    QDragEnterEvent rejected(pos, Qt::CopyAction, &text, Qt::NoButton, Qt::NoModifier);
    rejected.setAccepted(false);
    QApplication::sendEvent(m_window.get(), &rejected);
    EXPECT_FALSE(rejected.isAccepted());
}

TEST_F(ViewerTest, WindowGeometryIsRemembered) {
    // Above the smallest size (the panels beside a view of usable width).
    m_window->resize(1100, 700);
    ASSERT_TRUE(QTest::qWaitFor([&] { return m_window->size() == QSize(1100, 700); }));
    m_window->close();
    m_window.reset();

    auto window = std::make_unique<ui::MainWindow>();
    EXPECT_EQ(window->size(), QSize(1100, 700));
}

/** An object whose handling of any event takes busyMs, running a loop that waits waitMs first. */
class SlowReceiver : public QObject {
public:
    SlowReceiver(int busyMs, int waitMs) : m_busyMs(busyMs), m_waitMs(waitMs) {
        setObjectName(QStringLiteral("slow"));
    }
    bool event(QEvent* event) override {
        if (event->type() != QEvent::User)
            return QObject::event(event);
        if (m_waitMs > 0) {
            // A nested loop (as a dialog runs) waiting: not this event's own time.
            QEventLoop loop;
            QTimer::singleShot(m_waitMs, &loop, &QEventLoop::quit);
            loop.exec();
        }
        QThread::msleep(std::uint64_t(m_busyMs));
        return true;
    }

private:
    int m_busyMs, m_waitMs;
};

TEST(StallMeterTest, AnEventHandledSlowlyIsAStallNamingItsReceiverAndWaitingIsNot) {
    auto* app = dynamic_cast<ui::MeteredApplication*>(QCoreApplication::instance());
    ASSERT_NE(app, nullptr);
    app->setStallThresholdMs(100.0);
    app->clearStalls();
    SlowReceiver slow(160, 0), waiting(10, 400);
    QCoreApplication::postEvent(&slow, new QEvent(QEvent::User));
    QCoreApplication::postEvent(&waiting, new QEvent(QEvent::User));
    QTest::qWait(700);
    app->setStallThresholdMs(-1.0);
    std::vector<ui::Stall> stalls;
    for (const ui::Stall& s : app->stalls())
        if (s.event == QStringLiteral("User"))
            stalls.push_back(s);
    ASSERT_EQ(stalls.size(), 1u);
    EXPECT_GE(stalls[0].ms, 150.0);
    EXPECT_EQ(stalls[0].receiver, QStringLiteral("QObject (slow)"));
    EXPECT_EQ(ui::MeteredApplication::thresholdFromEnvironment(), -1.0);
    qputenv("LAYERPAINT_STALL_MS", "250");
    EXPECT_EQ(ui::MeteredApplication::thresholdFromEnvironment(), 250.0);
    qunsetenv("LAYERPAINT_STALL_MS");
}

/** A widget that keeps the mouse events it is given. */
class InputRecorder : public QWidget {
public:
    std::vector<QEvent::Type> events;

protected:
    void mousePressEvent(QMouseEvent* e) override { events.push_back(e->type()); }
    void mouseMoveEvent(QMouseEvent* e) override { events.push_back(e->type()); }
    void mouseReleaseEvent(QMouseEvent* e) override { events.push_back(e->type()); }
};

/** A mouse event as the window system gives it: at p of the widget, with the buttons held after. */
struct QueuedMouse {
    QEvent::Type type;
    QPoint p;
    Qt::MouseButton button = Qt::LeftButton; // NoButton for a move
    Qt::MouseButtons held = Qt::LeftButton;
};

/** Queues events for widget from another thread, as the window system's reader does. */
void queueFromAnotherThread(QWidget& widget, const std::vector<QueuedMouse>& events) {
    QWindow* window = widget.window()->windowHandle();
    std::vector<std::pair<QPointF, QPointF>> points; // in the window, on the screen
    for (const QueuedMouse& e : events)
        points.emplace_back(widget.mapTo(widget.window(), QPointF(e.p)),
                            widget.mapToGlobal(QPointF(e.p)));
    std::thread reader([&] {
        using Input = QWindowSystemInterface;
        for (std::size_t i = 0; i < events.size(); ++i)
            Input::handleMouseEvent<Input::AsynchronousDelivery>(window, points[i].first,
                                                                 points[i].second, events[i].held,
                                                                 events[i].button, events[i].type);
    });
    reader.join();
}

/**
 * Queues left-button events for widget from another thread: a press at p, a move 10 px right
 * (a move in place is no event), a release there.
 */
void queueMouseFromAnotherThread(QWidget& widget, const std::vector<QEvent::Type>& types,
                                 QPoint p) {
    std::vector<QueuedMouse> events;
    for (const QEvent::Type type : types) {
        const bool press = type == QEvent::MouseButtonPress;
        const bool release = type == QEvent::MouseButtonRelease;
        events.push_back({type, press ? p : p + QPoint(10, 0),
                          type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton,
                          release ? Qt::NoButton : Qt::LeftButton});
    }
    queueFromAnotherThread(widget, events);
}

/** An object that, given a User event, runs its work and then keeps the GUI thread busyMs. */
class BusyReceiver : public QObject {
public:
    BusyReceiver(int busyMs, std::function<void()> work)
        : m_busyMs(busyMs), m_work(std::move(work)) {}
    bool event(QEvent* event) override {
        if (event->type() != QEvent::User)
            return QObject::event(event);
        m_work();
        QThread::msleep(std::uint64_t(m_busyMs));
        return true;
    }

private:
    int m_busyMs;
    std::function<void()> m_work;
};

TEST(StallMeterTest, APressGivenWhileFrozenIsDroppedWithItsDragAndAStrokeBegunBeforeGoesOn) {
    const BusyInputMs fence(200.0);
    ASSERT_NE(fence.app(), nullptr);
    InputRecorder widget;
    widget.resize(200, 200);
    widget.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&widget));
    fence.app()->guardFromQueuedInput(&widget);
    using E = QEvent;
    const auto freezeWhileGiving = [&](int busyMs, std::vector<E::Type> types, QPoint p) {
        BusyReceiver busy(busyMs, [&] { queueMouseFromAnotherThread(widget, types, p); });
        QCoreApplication::postEvent(&busy, new QEvent(QEvent::User));
        QTest::qWait(busyMs + 100);
    };

    // A click and drag given during a freeze: dropped whole.
    const std::size_t dropped = fence.app()->droppedInputEvents();
    freezeWhileGiving(300, {E::MouseButtonPress, E::MouseMove, E::MouseButtonRelease}, {20, 20});
    EXPECT_TRUE(widget.events.empty());
    EXPECT_EQ(fence.app()->droppedInputEvents(), dropped + 3);
    // The same given during a short wait arrives.
    freezeWhileGiving(50, {E::MouseButtonPress, E::MouseMove, E::MouseButtonRelease}, {70, 70});
    EXPECT_EQ(widget.events,
              (std::vector<E::Type>{E::MouseButtonPress, E::MouseMove, E::MouseButtonRelease}));
    // A drag begun before a freeze goes on with what was given meanwhile.
    widget.events.clear();
    queueMouseFromAnotherThread(widget, {E::MouseButtonPress}, {120, 120});
    QTest::qWait(50);
    freezeWhileGiving(300, {E::MouseMove, E::MouseButtonRelease}, {120, 120});
    EXPECT_EQ(widget.events,
              (std::vector<E::Type>{E::MouseButtonPress, E::MouseMove, E::MouseButtonRelease}));
    // Another button pressed during a freeze while such a drag goes on belongs to the drag:
    // its press, its release and the drag's release all arrive, nothing is left held.
    widget.events.clear();
    queueMouseFromAnotherThread(widget, {E::MouseButtonPress}, {150, 40});
    QTest::qWait(50);
    const Qt::MouseButtons both = Qt::LeftButton | Qt::RightButton;
    BusyReceiver busy(300, [&] {
        queueFromAnotherThread(widget,
                               {{E::MouseButtonPress, {150, 40}, Qt::RightButton, both},
                                {E::MouseButtonRelease, {150, 40}, Qt::RightButton, Qt::LeftButton},
                                {E::MouseButtonRelease, {150, 40}, Qt::LeftButton, Qt::NoButton}});
    });
    QCoreApplication::postEvent(&busy, new QEvent(QEvent::User));
    QTest::qWait(400);
    EXPECT_EQ(widget.events, (std::vector<E::Type>{E::MouseButtonPress, E::MouseButtonPress,
                                                   E::MouseButtonRelease, E::MouseButtonRelease}));
    // A hover move after a dropped press whose release went elsewhere arrives again.
    widget.setMouseTracking(true);
    freezeWhileGiving(300, {E::MouseButtonPress}, {30, 150});
    widget.events.clear();
    queueFromAnotherThread(widget, {{E::MouseMove, {40, 160}, Qt::NoButton, Qt::NoButton}});
    QTest::qWait(50);
    EXPECT_EQ(widget.events, (std::vector<E::Type>{E::MouseMove}));
    // The window system's button state back to none for the tests that follow.
    queueFromAnotherThread(widget,
                           {{E::MouseButtonRelease, {40, 160}, Qt::LeftButton, Qt::NoButton}});
    QTest::qWait(50);
}

TEST(ModelLoaderTest, CancelAndSupersede) {
    ui::ModelLoader loader;
    QSignalSpy loaded(&loader, &ui::ModelLoader::loaded);
    QSignalSpy failed(&loader, &ui::ModelLoader::failed);
    QSignalSpy cancelled(&loader, &ui::ModelLoader::cancelled);

    loader.load(QStringLiteral("builtin:trefoil"));
    EXPECT_TRUE(loader.isLoading());
    loader.cancel();
    ASSERT_EQ(cancelled.size(), 1) << "said before cancel() returns";
    EXPECT_EQ(cancelled.first().first().toString(), QStringLiteral("builtin:trefoil"));
    EXPECT_TRUE(loaded.isEmpty());
    EXPECT_FALSE(loader.isLoading());

    // A second load replaces the first: only its result arrives.
    loader.load(QStringLiteral("builtin:trefoil"));
    loader.load(QStringLiteral("builtin:hexring"));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !loader.isLoading(); }, kLoadTimeoutMs));
    QTest::qWait(50); // let a stray result of the first load show up if there were one
    ASSERT_EQ(loaded.size(), 1);
    EXPECT_EQ(loaded.first().first().toString(), QStringLiteral("builtin:hexring"));
    // The topology and the paint target were made in the background too, of the mesh delivered.
    const auto model = loaded.first().at(1).value<std::shared_ptr<ui::LoadedModel>>();
    ASSERT_TRUE(model && model->mesh && model->topology);
    EXPECT_EQ(model->topology->planes.size(), model->mesh->triangleCount());
    ASSERT_NE(model->paintTarget, nullptr) << "the hex ring has UVs: a texture target";
    EXPECT_EQ(&model->paintTarget->mesh(), model->mesh.get());
    EXPECT_EQ(model->paintTarget->kind(), core::PaintTargetKind::Texture);
    EXPECT_TRUE(failed.isEmpty());
    EXPECT_EQ(cancelled.size(), 1);
    ASSERT_TRUE(QTest::qWaitFor([&] { return loader.runningJobs() == 0; }, kLoadTimeoutMs));
    EXPECT_EQ(loaded.size(), 1) << "the cancelled load delivered nothing";

    // Destroying the loader mid-load must not crash or deliver anything.
    {
        ui::ModelLoader shortLived;
        shortLived.load(QStringLiteral("builtin:trefoil"));
    }
    QTest::qWait(50);
}

} // namespace viewer_uitest
