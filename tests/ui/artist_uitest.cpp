// SPDX-License-Identifier: GPL-3.0-or-later
// The artist's workflow through real Qt event delivery: pen input queued as a platform plugin
// would (QWindowSystemInterface) with pressure, the eraser end and proximity; the eyedropper
// (tool and Ctrl+click); the painters' keys; the Brush and Colour panels; the dock layout across
// a restart; the Preferences round trip. Needs a display with OpenGL 4.5 (xvfb-run, llvmpipe).
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QPointingDevice>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>
#include <QWheelEvent>
#include <qpa/qwindowsysteminterface.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

#include "core/document/document.h"
#include "core/paint/targets/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/panels/brush_panel.h"
#include "ui/panels/brush_toolbar.h"
#include "ui/panels/color_panel.h"
#include "ui/shell/main_window.h"
#include "ui/shell/preferences.h"
#include "ui/shell/project_controller.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace artist_uitest {

using namespace ui_test;

/** A pen and its eraser end, known to Qt as a platform plugin would register them. */
struct TabletDevices {
    QPointingDevice* pen = nullptr;
    QPointingDevice* eraser = nullptr;

    static const TabletDevices& get() {
        static const TabletDevices devices = [] {
            TabletDevices d;
            const auto caps = QInputDevice::Capability::Position |
                              QInputDevice::Capability::Pressure | QInputDevice::Capability::XTilt |
                              QInputDevice::Capability::YTilt;
            const auto id = QPointingDeviceUniqueId::fromNumericId(0x6a);
            d.pen = new QPointingDevice(
                QStringLiteral("test pen"), 0x6a01, QInputDevice::DeviceType::Stylus,
                QPointingDevice::PointerType::Pen, caps, 1, 3, QString(), id, qApp);
            d.eraser = new QPointingDevice(
                QStringLiteral("test pen eraser"), 0x6a02, QInputDevice::DeviceType::Stylus,
                QPointingDevice::PointerType::Eraser, caps, 1, 3, QString(), id, qApp);
            QWindowSystemInterface::registerInputDevice(d.pen);
            QWindowSystemInterface::registerInputDevice(d.eraser);
            return d;
        }();
        return devices;
    }
};

/** Counts the mouse events a widget receives (Qt synthesizes them from unaccepted pen events). */
class MouseCounter : public QObject {
public:
    int count = 0;
    bool eventFilter(QObject*, QEvent* event) override {
        switch (event->type()) {
        case QEvent::MouseButtonPress:
        case QEvent::MouseMove:
        case QEvent::MouseButtonRelease:
            ++count;
            break;
        default:
            break;
        }
        return false;
    }
};

class ArtistTest : public WindowTest {
protected:
    ArtistTest() : WindowTest({1180, 760}) {}

    const core::TextureTarget* texture() {
        return dynamic_cast<const core::TextureTarget*>(document().paintTarget());
    }
    std::vector<std::uint8_t> pageBytes() {
        const core::TextureTarget* target = texture();
        return target ? target->page(0).rgba : std::vector<std::uint8_t>{};
    }

    bool covered(int x, int y) const {
        const core::DepthStack& stack = document().depthLayers()->stack;
        if (x < 0 || y < 0 || x >= stack.width || y >= stack.height)
            return false;
        const std::size_t i = std::size_t(y) * stack.width + x;
        return stack.offsets[i + 1] != stack.offsets[i];
    }

    /**
     * A horizontal run of at least minLength pixels (device = logical here) with the model under
     * every pixel within halfHeight above and below: a stroke there paints its full width.
     */
    std::pair<QPoint, QPoint> solidRun(int minLength, int halfHeight) const {
        const core::DepthStack& stack = document().depthLayers()->stack;
        for (int k = 0; k < stack.height / 2; k += 3) {
            for (int y : {stack.height / 2 - k, stack.height / 2 + k}) {
                int runStart = -1;
                for (int x = 0; x <= stack.width; ++x) {
                    bool inside = x < stack.width;
                    for (int dy = -halfHeight; inside && dy <= halfHeight; dy += 2)
                        inside = covered(x, y + dy);
                    if (inside && runStart < 0)
                        runStart = x;
                    if (!inside && runStart >= 0) {
                        if (x - runStart >= minLength)
                            return {{runStart + 4, y}, {runStart + minLength - 4, y}};
                        runStart = -1;
                    }
                }
            }
        }
        return {};
    }

    /** Whether the surface at pixel (x, y) has exactly colour (the eyedropper's answer). */
    bool hasColor(int x, int y, const QColor& color) {
        const core::DepthStack& stack = document().depthLayers()->stack;
        const auto picked = document().pickColor(std::size_t(y) * stack.width + x);
        return picked && ui::BrushToolBar::toQColor(*picked) == color;
    }

    /** The painted run of pixels in column x through row y (contiguous, in colour). */
    int paintedHeight(int x, int y, const QColor& color, int limit) {
        if (!hasColor(x, y, color))
            return 0;
        int up = 0, down = 0;
        while (up < limit && hasColor(x, y - up - 1, color))
            ++up;
        while (down < limit && hasColor(x, y + down + 1, color))
            ++down;
        return up + down + 1;
    }

    /** Queues a pen sample at viewport position p (logical), as the platform would. */
    void queueTablet(const QPointingDevice* device, QPointF p, Qt::MouseButtons buttons,
                     qreal pressure) {
        QWindow* window = m_window->windowHandle();
        const QPointF local = viewport()->mapTo(m_window.get(), p);
        const QPointF global = viewport()->mapToGlobal(p);
        QWindowSystemInterface::handleTabletEvent(window, device, local, global, buttons, pressure,
                                                  25, -10, 0.0, 0.0, 0);
    }
    void flush() { QWindowSystemInterface::flushWindowSystemEvents(); }

    /**
     * A pen stroke from a to b in 1-pixel samples, pressure from p0 to p1, all queued before
     * Qt sees any (a burst, as a fast tablet delivers them), then delivered. Returns the samples.
     */
    int penStroke(const QPointingDevice* device, QPoint a, QPoint b, qreal p0, qreal p1) {
        const int steps = std::max(1, int(std::hypot(b.x() - a.x(), b.y() - a.y())));
        queueTablet(device, a, Qt::NoButton, 0.0); // hover in
        queueTablet(device, a, Qt::LeftButton, p0);
        for (int i = 1; i <= steps; ++i)
            queueTablet(device, QPointF(a) + QPointF(b - a) * (double(i) / steps), Qt::LeftButton,
                        p0 + (p1 - p0) * double(i) / steps);
        queueTablet(device, b, Qt::NoButton, 0.0);
        flush();
        return steps;
    }

    QAction* action(const char* name) const {
        return m_window->findChild<QAction*>(QString::fromLatin1(name));
    }
};

TEST_F(ArtistTest, PenPressureWidensTheStrokeAndTheEraserEndErasesIt) {
    openTrefoil();
    ASSERT_FALSE(QCoreApplication::testAttribute(Qt::AA_CompressTabletEvents));
    const TabletDevices& tablet = TabletDevices::get();
    // Conventional painting (the study's check box): what the stroke paints is what shows.
    auto* check = m_window->findChild<QCheckBox*>(QStringLiteral("layerAwareCheckBox"));
    ASSERT_NE(check, nullptr);
    check->click();
    EXPECT_FALSE(document().layerAware());
    // A hard brush of radius 20 from the Brush panel, so painted pixels are exactly the colour.
    auto* panelRadius =
        m_window->brushPanel()->findChild<QSpinBox*>(QStringLiteral("brushPanelRadius"));
    auto* panelHardness =
        m_window->brushPanel()->findChild<QSpinBox*>(QStringLiteral("brushPanelHardness"));
    ASSERT_TRUE(panelRadius && panelHardness);
    panelRadius->setValue(20);
    panelHardness->setValue(100);
    EXPECT_EQ(document().brush().radius, 20.0f);
    EXPECT_EQ(document().brush().hardness, 1.0f);
    EXPECT_TRUE(document().brush().pressureRadius);
    const QColor color = m_window->colorPanel()->foreground();

    // Two wheel notches closer: the tube is wide enough for the widest stroke.
    QSignalSpy built(m_window->depthLayersBuilder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    const QPointF middle = QPointF(viewport()->rect().center());
    QWheelEvent wheel(middle, viewport()->mapToGlobal(middle), QPoint(), QPoint(0, 240),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &wheel);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
    const auto [a, b] = solidRun(170, 24);
    ASSERT_GT(b.x() - a.x(), 150) << "no wide run across the knot";
    ASSERT_NE(texture(), nullptr);
    const std::vector<std::uint8_t> original = pageBytes();

    MouseCounter mice;
    viewport()->installEventFilter(&mice);
    const int samples = penStroke(tablet.pen, a, b, 0.1, 1.0);
    viewport()->removeEventFilter(&mice);
    EXPECT_EQ(mice.count, 0) << "mouse events were synthesized from accepted pen events";
    // Every sample reached the stroke (none merged), and it is one undo step.
    EXPECT_EQ(m_window->lastStrokeStats().moves, samples);
    EXPECT_EQ(m_window->undoStack()->count(), 1);
    EXPECT_EQ(viewport()->pressPointer(), ui::PointerKind::Pen);
    EXPECT_EQ(viewport()->penTilt(), QPointF(25, -10)); // read, unused
    EXPECT_NE(pageBytes(), original);

    // Rising pressure, rising width: measured on the paint target through the eyedropper.
    const int length = b.x() - a.x();
    std::vector<int> widths;
    for (const double t : {0.15, 0.5, 0.95})
        widths.push_back(paintedHeight(a.x() + int(t * length), a.y(), color, 30));
    std::printf("[ pen     ] %d samples; painted width %d, %d, %d px along the stroke\n", samples,
                widths[0], widths[1], widths[2]);
    EXPECT_GE(widths[0], 2);
    EXPECT_GT(widths[1], widths[0] + 6) << widths[0] << " " << widths[1] << " " << widths[2];
    EXPECT_GT(widths[2], widths[1] + 6) << widths[0] << " " << widths[1] << " " << widths[2];
    EXPECT_NEAR(widths[2], 39, 5); // about 2 × 20 × 0.95 at the end

    // The eraser end, a little wider and past both ends, brings back the original colours.
    QTest::keyClick(m_window.get(), Qt::Key_BracketRight); // 20 → 23
    EXPECT_EQ(document().brush().radius, 23.0f);
    penStroke(tablet.eraser, a - QPoint(12, 0), b + QPoint(12, 0), 1.0, 1.0);
    EXPECT_EQ(viewport()->pressPointer(), ui::PointerKind::Eraser);
    EXPECT_EQ(m_window->undoStack()->count(), 2);
    EXPECT_EQ(pageBytes(), original);
    EXPECT_EQ(m_window->tool(), ui::Tool::Brush); // the tool stays; only that stroke erased
}

TEST_F(ArtistTest, TheMouseIsAPenAtFullPressure) {
    openTrefoil();
    m_window->findChild<QCheckBox*>(QStringLiteral("layerAwareCheckBox"))->click();
    core::Brush brush = document().brush();
    brush.radius = 12.0f;
    brush.hardness = 1.0f;
    m_window->setBrush(brush);
    const QColor color = m_window->colorPanel()->foreground();
    const auto [a, b] = solidRun(120, 16);
    ASSERT_GT(b.x() - a.x(), 100);
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, a);
    for (int x = a.x() + 4; x <= b.x(); x += 4)
        QTest::mouseMove(viewport(), QPoint(x, a.y()));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, b);
    EXPECT_EQ(viewport()->pressPointer(), ui::PointerKind::Mouse);
    const int length = b.x() - a.x();
    const int first = paintedHeight(a.x() + length / 5, a.y(), color, 20);
    const int last = paintedHeight(a.x() + length * 4 / 5, a.y(), color, 20);
    EXPECT_NEAR(first, 23, 3);
    EXPECT_NEAR(last, first, 2);
}

TEST_F(ArtistTest, PenProximityShowsAndHidesTheBrushOutline) {
    openTrefoil();
    const TabletDevices& tablet = TabletDevices::get();
    const QPoint p = viewport()->rect().center();
    queueTablet(tablet.pen, p, Qt::NoButton, 0.0); // hovering
    flush();
    EXPECT_TRUE(viewport()->penInProximity());
    EXPECT_TRUE(viewport()->brushOutlineVisible());
    EXPECT_EQ(viewport()->cursorPosition(), QPointF(p) * viewport()->devicePixelRatioF());
    QWindowSystemInterface::handleTabletEnterLeaveProximityEvent(m_window->windowHandle(),
                                                                 tablet.pen, false);
    flush();
    EXPECT_FALSE(viewport()->penInProximity());
    EXPECT_FALSE(viewport()->brushOutlineVisible());
    QWindowSystemInterface::handleTabletEnterLeaveProximityEvent(m_window->windowHandle(),
                                                                 tablet.pen, true);
    flush();
    EXPECT_TRUE(viewport()->penInProximity());
    queueTablet(tablet.pen, p + QPoint(10, 5), Qt::NoButton, 0.0);
    flush();
    EXPECT_TRUE(viewport()->brushOutlineVisible());
    EXPECT_EQ(viewport()->cursorPosition(),
              QPointF(p + QPoint(10, 5)) * viewport()->devicePixelRatioF());
    // Hovering paints nothing.
    EXPECT_EQ(m_window->undoStack()->count(), 0);
}

TEST_F(ArtistTest, EyedropperPicksTheColourJustPainted) {
    openTrefoil();
    ui::ColorPanel* colors = m_window->colorPanel();
    auto* hex = colors->findChild<QLineEdit*>(QStringLiteral("colorHex"));
    ASSERT_NE(hex, nullptr);
    // Red from the hex entry becomes the brush colour.
    hex->setFocus();
    hex->selectAll();
    QTest::keyClicks(hex, QStringLiteral("#d02818"));
    QTest::keyClick(hex, Qt::Key_Return);
    const QColor red(0xd0, 0x28, 0x18);
    EXPECT_EQ(colors->foreground(), red);
    EXPECT_EQ(ui::BrushToolBar::toQColor(document().brush().color), red);
    viewport()->setFocus(); // the keys below are shortcuts, not hex digits
    const auto chooseBlue = [&] {
        colors->setForeground(Qt::blue);
        emit colors->foregroundChanged(QColor(Qt::blue)); // as the picker does
        ASSERT_EQ(ui::BrushToolBar::toQColor(document().brush().color), QColor(Qt::blue));
    };

    m_window->findChild<QCheckBox*>(QStringLiteral("layerAwareCheckBox"))->click();
    const auto [a, b] = solidRun(60, 12);
    ASSERT_GT(b.x() - a.x(), 40);
    const QPoint middle = (a + b) / 2;
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, a);
    QTest::mouseMove(viewport(), middle);
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, b);
    ASSERT_EQ(m_window->undoStack()->count(), 1);
    // The colour was used: it leads the recent colours.
    ASSERT_FALSE(colors->recentColors().isEmpty());
    EXPECT_EQ(colors->recentColors().first(), red);
    const std::vector<std::uint8_t> painted = pageBytes();

    // Another colour, then the eyedropper (I) on the stroke.
    chooseBlue();
    QAction* eyedropper = action("actionToolEyedropper");
    ASSERT_NE(eyedropper, nullptr);
    EXPECT_TRUE(eyedropper->isEnabled());
    QTest::keyClick(m_window.get(), Qt::Key_I);
    EXPECT_EQ(m_window->tool(), ui::Tool::Eyedropper);
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, middle);
    EXPECT_EQ(ui::BrushToolBar::toQColor(document().brush().color), red);
    EXPECT_EQ(colors->foreground(), red);
    EXPECT_EQ(pageBytes(), painted); // picking paints nothing
    EXPECT_EQ(m_window->undoStack()->count(), 1);

    // Ctrl+click picks with any tool, here the brush (B), and paints nothing either.
    chooseBlue();
    QTest::keyClick(m_window.get(), Qt::Key_B);
    EXPECT_EQ(m_window->tool(), ui::Tool::Brush);
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ControlModifier, middle);
    EXPECT_EQ(ui::BrushToolBar::toQColor(document().brush().color), red);
    EXPECT_EQ(pageBytes(), painted);
    EXPECT_EQ(m_window->undoStack()->count(), 1);

    // Off the model there is nothing to pick: the colour stays.
    chooseBlue();
    QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ControlModifier, QPoint(2, 2));
    EXPECT_EQ(ui::BrushToolBar::toQColor(document().brush().color), QColor(Qt::blue));
}

TEST_F(ArtistTest, PaintersKeysChangeTheBrushAndSwapColours) {
    auto* barRadius = m_window->brushToolBar()->findChild<QSpinBox*>(QStringLiteral("brushRadius"));
    auto* panelRadius =
        m_window->brushPanel()->findChild<QSpinBox*>(QStringLiteral("brushPanelRadius"));
    auto* status = m_window->findChild<QLabel*>(QStringLiteral("brushInfo"));
    ASSERT_TRUE(barRadius && panelRadius && status);
    EXPECT_EQ(document().brush().radius, 32.0f);
    QTest::keyClick(m_window.get(), Qt::Key_BracketRight);
    EXPECT_EQ(document().brush().radius, 37.0f);
    EXPECT_EQ(barRadius->value(), 37);
    EXPECT_EQ(panelRadius->value(), 37);
    EXPECT_EQ(viewport()->brushRadius(), 37.0f);
    EXPECT_TRUE(status->text().contains(QStringLiteral("37"))) << status->text().toStdString();
    QTest::keyClick(m_window.get(), Qt::Key_BracketLeft); // back where it was
    EXPECT_EQ(document().brush().radius, 32.0f);
    QTest::keyClick(m_window.get(), Qt::Key_BracketLeft);
    EXPECT_EQ(document().brush().radius, 28.0f);
    for (int i = 0; i < 40; ++i)
        QTest::keyClick(m_window.get(), Qt::Key_BracketLeft);
    EXPECT_EQ(document().brush().radius, 1.0f);

    EXPECT_FLOAT_EQ(document().brush().hardness, 0.5f);
    QTest::keyClick(m_window.get(), Qt::Key_BracketRight, Qt::ShiftModifier);
    EXPECT_FLOAT_EQ(document().brush().hardness, 0.6f);
    // (Shift+[ as an X keyboard reports it, { with Shift: FirstSessionTest.)
    QTest::keyClick(m_window.get(), Qt::Key_BracketLeft, Qt::ShiftModifier);
    QTest::keyClick(m_window.get(), Qt::Key_BracketLeft, Qt::ShiftModifier);
    EXPECT_FLOAT_EQ(document().brush().hardness, 0.4f);
    EXPECT_EQ(
        m_window->brushPanel()->findChild<QSpinBox*>(QStringLiteral("brushPanelHardness"))->value(),
        40);

    // X swaps foreground and background; the brush paints with the foreground.
    ui::ColorPanel* colors = m_window->colorPanel();
    const QColor foreground = colors->foreground(), background = colors->background();
    ASSERT_NE(foreground, background);
    QTest::keyClick(m_window.get(), Qt::Key_X);
    EXPECT_EQ(colors->foreground(), background);
    EXPECT_EQ(colors->background(), foreground);
    EXPECT_EQ(ui::BrushToolBar::toQColor(document().brush().color), background);
    QTest::keyClick(m_window.get(), Qt::Key_X);
    EXPECT_EQ(ui::BrushToolBar::toQColor(document().brush().color), foreground);

    // The keys show in menus (shortcuts) and tooltips.
    const std::pair<const char*, const char*> keys[] = {
        {"actionBrushSmaller", "["},      {"actionBrushLarger", "]"},
        {"actionBrushSofter", "Shift+["}, {"actionBrushHarder", "Shift+]"},
        {"actionSwapColors", "X"},        {"actionToolEyedropper", "I"},
        {"actionToolBrush", "B"},         {"actionToolEraser", "E"},
        {"actionLayerAware", "L"},        {"actionFrameAll", "F"},
        {"actionUndo", "Ctrl+Z"},         {"actionRedo", "Ctrl+Shift+Z"},
        {"actionOpen", "Ctrl+O"}};
    for (const auto& [name, key] : keys) {
        QAction* a = action(name);
        ASSERT_NE(a, nullptr) << name;
        EXPECT_EQ(a->shortcut().toString(), QString::fromLatin1(key)) << name;
    }
    for (const char* name : {"actionBrushSmaller", "actionBrushHarder", "actionSwapColors",
                             "actionToolEyedropper", "actionLayerAware"}) {
        const QString key = action(name)->shortcut().toString(QKeySequence::NativeText);
        EXPECT_TRUE(action(name)->toolTip().contains(key)) << name;
    }
    EXPECT_TRUE(m_window->findChild<QCheckBox*>(QStringLiteral("layerAwareCheckBox"))
                    ->toolTip()
                    .contains(QStringLiteral("(L)")));
    EXPECT_TRUE(barRadius->toolTip().contains(QStringLiteral("[")));
}

TEST_F(ArtistTest, TheBrushPanelSetsEveryBrushSetting) {
    ui::BrushPanel* panel = m_window->brushPanel();
    const auto spin = [&](const char* name) {
        return panel->findChild<QSpinBox*>(QString::fromLatin1(name));
    };
    spin("brushPanelOpacity")->setValue(70);
    spin("brushPanelFlow")->setValue(40);
    spin("brushPanelSpacing")->setValue(25);
    spin("brushPanelTrackRadius")->setValue(150);
    panel->findChild<QCheckBox*>(QStringLiteral("brushPanelPressureRadius"))->click();
    panel->findChild<QCheckBox*>(QStringLiteral("brushPanelPressureOpacity"))->click();
    const core::Brush& brush = document().brush();
    EXPECT_FLOAT_EQ(brush.opacity, 0.7f);
    EXPECT_FLOAT_EQ(brush.flow, 0.4f);
    EXPECT_FLOAT_EQ(brush.spacing, 0.25f);
    EXPECT_FLOAT_EQ(brush.trackRadius, 150.0f);
    EXPECT_FALSE(brush.pressureRadius);
    EXPECT_TRUE(brush.pressureOpacity);
    // The brush bar shows the same brush.
    EXPECT_EQ(
        m_window->brushToolBar()->findChild<QSpinBox*>(QStringLiteral("brushOpacity"))->value(),
        70);
    EXPECT_FLOAT_EQ(m_window->brushToolBar()->brush().flow, 0.4f);
    // R_max 0 is automatic: max(4R, 64).
    spin("brushPanelTrackRadius")->setValue(0);
    EXPECT_EQ(brush.trackRadius, 0.0f);
    EXPECT_TRUE(spin("brushPanelTrackRadius")->text().contains(QStringLiteral("128")));
    // The pressure curve slider: to the right, a firmer press is needed.
    auto* curve = panel->findChild<QSlider*>(QStringLiteral("brushPanelPressureCurve"));
    ASSERT_NE(curve, nullptr);
    curve->setValue(curve->maximum());
    EXPECT_FLOAT_EQ(m_window->pressureCurve().gamma, core::PressureCurve::kMaxGamma);
    EXPECT_NEAR(QSettings().value(QStringLiteral("paint/pressureGamma")).toDouble(),
                core::PressureCurve::kMaxGamma, 1e-6);
}

TEST_F(ArtistTest, TheLayerAwareCheckBoxFollowsTheKey) {
    auto* check = m_window->findChild<QCheckBox*>(QStringLiteral("layerAwareCheckBox"));
    ASSERT_NE(check, nullptr);
    EXPECT_TRUE(check->isVisible());
    EXPECT_TRUE(check->isChecked());
    QTest::keyClick(m_window.get(), Qt::Key_L);
    EXPECT_FALSE(check->isChecked());
    EXPECT_FALSE(document().layerAware());
    check->click();
    EXPECT_TRUE(document().layerAware());
    EXPECT_TRUE(action("actionLayerAware")->isChecked());
}

TEST_F(ArtistTest, DockLayoutSurvivesARestart) {
    auto* brushDock = m_window->findChild<QDockWidget*>(QStringLiteral("brushDock"));
    auto* colorDock = m_window->findChild<QDockWidget*>(QStringLiteral("colorDock"));
    auto* graphDock = m_window->findChild<QDockWidget*>(QStringLiteral("regionGraphDock"));
    auto* tools = m_window->findChild<QToolBar*>(QStringLiteral("toolsToolBar"));
    ASSERT_TRUE(brushDock && colorDock && graphDock && tools);
    // Every dock and tool bar has a name, or saveState() could not keep it.
    for (QDockWidget* dock : m_window->findChildren<QDockWidget*>())
        EXPECT_FALSE(dock->objectName().isEmpty()) << dock->windowTitle().toStdString();
    for (QToolBar* bar : m_window->findChildren<QToolBar*>())
        EXPECT_FALSE(bar->objectName().isEmpty()) << bar->windowTitle().toStdString();
    EXPECT_EQ(m_window->dockWidgetArea(brushDock), Qt::LeftDockWidgetArea);
    EXPECT_TRUE(brushDock->isVisible() && colorDock->isVisible() && graphDock->isVisible());

    m_window->addDockWidget(Qt::BottomDockWidgetArea, brushDock);
    colorDock->setFloating(true);
    graphDock->hide();
    tools->hide();
    ASSERT_TRUE(m_window->close()); // saves the layout, as quitting does
    m_window.reset();

    showWindow();
    brushDock = m_window->findChild<QDockWidget*>(QStringLiteral("brushDock"));
    colorDock = m_window->findChild<QDockWidget*>(QStringLiteral("colorDock"));
    graphDock = m_window->findChild<QDockWidget*>(QStringLiteral("regionGraphDock"));
    tools = m_window->findChild<QToolBar*>(QStringLiteral("toolsToolBar"));
    EXPECT_EQ(m_window->dockWidgetArea(brushDock), Qt::BottomDockWidgetArea);
    EXPECT_TRUE(brushDock->isVisible());
    EXPECT_TRUE(colorDock->isFloating());
    EXPECT_FALSE(graphDock->isVisible());
    EXPECT_FALSE(tools->isVisible());
    EXPECT_TRUE(m_window->findChild<QDockWidget*>(QStringLiteral("layersDock"))->isVisible());
}

TEST_F(ArtistTest, PreferencesRoundTrip) {
    QAction* preferences = action("actionPreferences");
    ASSERT_NE(preferences, nullptr);
    EXPECT_EQ(preferences->shortcut(), QKeySequence(QKeySequence::Preferences));
    // The defaults: both camera mappings, the current budget and texture size.
    EXPECT_EQ(m_window->preferences(), ui::Preferences());
    EXPECT_EQ(viewport()->cameraMapping(), ui::CameraMapping::Both);

    preferences->trigger();
    QPointer<ui::PreferencesDialog> dialog = m_window->findChild<ui::PreferencesDialog*>();
    ASSERT_NE(dialog, nullptr);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
    const auto select = [&](const char* name, const QVariant& data) {
        auto* combo = dialog->findChild<QComboBox*>(QString::fromLatin1(name));
        ASSERT_NE(combo, nullptr) << name;
        const int index = combo->findData(data);
        ASSERT_GE(index, 0) << name;
        combo->setCurrentIndex(index);
    };
    dialog->findChild<QSpinBox*>(QStringLiteral("undoBudget"))->setValue(64);
    select("textureSize", 1024);
    dialog->findChild<QDoubleSpinBox*>(QStringLiteral("pressureGamma"))->setValue(2.0);
    select("cameraMapping", int(ui::CameraMapping::Blender));
    select("language", QStringLiteral("zh_CN"));
    dialog->findChild<QSpinBox*>(QStringLiteral("autosaveMinutes"))->setValue(0);
    dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
    EXPECT_TRUE(QTest::qWaitFor([&] { return dialog.isNull(); }, 5000)) << "dialog not closed";

    // Stored ...
    const QSettings settings;
    EXPECT_EQ(settings.value(QStringLiteral("paint/undoBudgetMiB")).toInt(), 64);
    EXPECT_EQ(settings.value(QStringLiteral("paint/textureSize")).toInt(), 1024);
    EXPECT_DOUBLE_EQ(settings.value(QStringLiteral("paint/pressureGamma")).toDouble(), 2.0);
    EXPECT_EQ(settings.value(QStringLiteral("view/cameraMapping")).toString(),
              QStringLiteral("blender"));
    EXPECT_EQ(settings.value(QStringLiteral("ui/language")).toString(), QStringLiteral("zh_CN"));
    EXPECT_EQ(settings.value(QStringLiteral("autosave/intervalMinutes")).toInt(), 0);
    // ... and applied.
    EXPECT_EQ(document().history().budget(), std::size_t(64) << 20);
    EXPECT_FLOAT_EQ(m_window->pressureCurve().gamma, 2.0f);
    EXPECT_FLOAT_EQ(m_window->brushPanel()->pressureCurve().gamma, 2.0f);
    EXPECT_EQ(viewport()->cameraMapping(), ui::CameraMapping::Blender);

    // The next model gets a texture of the preferred size.
    openTrefoil();
    ASSERT_NE(texture(), nullptr);
    EXPECT_EQ(texture()->page(0).width, 1024);
    // Blender-like: Alt+left neither orbits nor paints any more; the middle button orbits.
    const float yaw = document().camera().yawDegrees;
    const QPoint c = viewport()->rect().center();
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::AltModifier, c);
    QTest::mouseMove(viewport(), c + QPoint(60, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::AltModifier, c + QPoint(60, 0));
    EXPECT_EQ(document().camera().yawDegrees, yaw);
    EXPECT_EQ(m_window->undoStack()->count(), 0);
    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, c);
    QTest::mouseMove(viewport(), c + QPoint(60, 0));
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, c + QPoint(60, 0));
    EXPECT_NE(document().camera().yawDegrees, yaw);

    // A new window starts with them, and the dialog shows them again.
    m_window.reset();
    showWindow();
    EXPECT_EQ(m_window->preferences().undoBudgetMiB, 64);
    EXPECT_EQ(m_window->preferences().language, QStringLiteral("zh_CN"));
    EXPECT_EQ(viewport()->cameraMapping(), ui::CameraMapping::Blender);
    EXPECT_FLOAT_EQ(m_window->pressureCurve().gamma, 2.0f);
    ui::PreferencesDialog again(m_window->preferences());
    EXPECT_EQ(again.preferences(), m_window->preferences());
}

TEST_F(ArtistTest, AChangedAutosaveIntervalAppliesAtOnce) {
    ui::ProjectController& project = *m_window->projectController();
    EXPECT_GT(project.autosaveDueInMs(), 4 * 60'000) << "the default interval is 5 minutes";
    action("actionPreferences")->trigger();
    QPointer<ui::PreferencesDialog> dialog = m_window->findChild<ui::PreferencesDialog*>();
    ASSERT_NE(dialog, nullptr);
    ASSERT_TRUE(QTest::qWaitForWindowExposed(dialog));
    auto* minutes = dialog->findChild<QSpinBox*>(QStringLiteral("autosaveMinutes"));
    ASSERT_NE(minutes, nullptr);
    minutes->setFocus();
    minutes->selectAll();
    QTest::keyClicks(minutes, QStringLiteral("1"));
    QTest::mouseClick(dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok),
                      Qt::LeftButton);
    EXPECT_TRUE(QTest::qWaitFor([&] { return dialog.isNull(); }, 5000)) << "dialog not closed";
    EXPECT_EQ(QSettings().value(QStringLiteral("autosave/intervalMinutes")).toInt(), 1);
    // A coarse timer may wake up to 5 % late.
    EXPECT_LE(project.autosaveDueInMs(), 63'000)
        << "the next autosave still waits the old interval";
    EXPECT_GT(project.autosaveDueInMs(), 50'000);
}

TEST_F(ArtistTest, AltBasedMappingLeavesTheMiddleButtonAlone) {
    ui::Preferences p = m_window->preferences();
    p.cameraMapping = ui::CameraMapping::AltBased;
    m_window->setPreferences(p);
    openTrefoil();
    const float yaw = document().camera().yawDegrees;
    const QPoint c = viewport()->rect().center();
    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, c);
    QTest::mouseMove(viewport(), c + QPoint(60, 0));
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, c + QPoint(60, 0));
    EXPECT_EQ(document().camera().yawDegrees, yaw);
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::AltModifier, c);
    QTest::mouseMove(viewport(), c + QPoint(60, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::AltModifier, c + QPoint(60, 0));
    EXPECT_NE(document().camera().yawDegrees, yaw);
}

TEST_F(ArtistTest, RecentColoursArePersisted) {
    ui::ColorPanel* colors = m_window->colorPanel();
    colors->addRecent(QColor(10, 20, 30));
    colors->addRecent(QColor(200, 100, 0));
    colors->addRecent(QColor(10, 20, 30)); // moves to the front, once
    EXPECT_EQ(colors->recentColors(), (QList<QColor>{QColor(10, 20, 30), QColor(200, 100, 0)}));
    for (int i = 0; i < 20; ++i)
        colors->addRecent(QColor(i, i, i));
    EXPECT_EQ(colors->recentColors().size(), ui::ColorPanel::kMaxRecent);
    const QList<QColor> recent = colors->recentColors();
    m_window.reset();
    showWindow();
    EXPECT_EQ(m_window->colorPanel()->recentColors(), recent);
    // A click on one makes it the brush colour.
    auto* button = m_window->colorPanel()->findChild<QToolButton*>(QStringLiteral("recentColor1"));
    ASSERT_NE(button, nullptr);
    button->click();
    EXPECT_EQ(ui::BrushToolBar::toQColor(document().brush().color), recent.at(1));
}

} // namespace artist_uitest
