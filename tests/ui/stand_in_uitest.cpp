// SPDX-License-Identifier: GPL-3.0-or-later
// The stand-in through real Qt event delivery: with a low threshold the built-in trefoil gets a
// simplified stand-in in the background; an orbit drag and the wheel draw it, the settled view
// draws the full mesh, and painting after the orbit works on the full mesh's depth layers. On a
// model painted metal through a fill layer, the stand-in shows what the settled view (the depth
// layers' composite) shows, in the lit material and in each channel view.
// Needs a display with OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <QApplication>
#include <QDir>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>
#include <QWheelEvent>

#include <cmath>
#include <set>
#include <vector>

#include "core/document/document.h"
#include "core/paint/targets/paint_target.h"
#include "render/material_channel.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/panels/paint_layers_panel.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace stand_in_uitest {

using namespace ui_test;

constexpr std::size_t kStandInTriangles = 20000;

/**
 * The mean colour difference (0-255 per channel, averaged over R, G and B) of the pixels that
 * show the model in both pictures (not the background colour at either).
 */
double meanModelDifference(const QImage& a, const QImage& b, QRgb background) {
    const QImage ra = a.convertToFormat(QImage::Format_RGB32);
    const QImage rb = b.convertToFormat(QImage::Format_RGB32);
    if (ra.size() != rb.size())
        return 255.0;
    double sum = 0.0;
    qint64 count = 0;
    for (int y = 0; y < ra.height(); ++y)
        for (int x = 0; x < ra.width(); ++x) {
            const QRgb p = ra.pixel(x, y), q = rb.pixel(x, y);
            if (channelDifference(p, background) <= 2 || channelDifference(q, background) <= 2)
                continue;
            sum += (std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) +
                    std::abs(qBlue(p) - qBlue(q))) /
                   3.0;
            ++count;
        }
    return count > 0 ? sum / double(count) : 255.0;
}

class StandInTest : public WindowTest {
protected:
    StandInTest() : WindowTest({1000, 700}) {}

    /** Opens the trefoil with a low stand-in threshold and waits for its stand-in. */
    void openWithStandIn() {
        viewport()->setStandInTriangles(kStandInTriangles);
        openTrefoil();
        if (HasFatalFailure())
            return;
        ASSERT_TRUE(QTest::qWaitFor([&] { return viewport()->hasStandIn(); }, kBuildTimeoutMs));
    }

    std::size_t fullTriangles() const { return document().mesh().triangleCount(); }

    /** Distinct triangles with a fragment in the document's depth layers. */
    std::size_t capturedTriangles() const {
        const core::DepthStack& stack = document().depthLayers()->stack;
        const std::set<std::uint32_t> triangles(stack.triangle.begin(), stack.triangle.end());
        return triangles.size();
    }
};

TEST_F(StandInTest, OrbitDrawsTheStandInAndTheSettledViewTheFullMesh) {
    openWithStandIn();
    if (HasFatalFailure())
        return;
    const std::size_t full = fullTriangles();
    ASSERT_GT(full, kStandInTriangles * 3 / 2);
    // The layers show: no triangles drawn by the mesh renderer.
    grab();
    EXPECT_EQ(viewport()->lastFrameTriangles(), 0u);

    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value());
    const float yaw = document().camera().yawDegrees;
    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, *start);
    QImage during;
    for (int i = 1; i <= 5; ++i) {
        QTest::mouseMove(viewport(), *start + QPoint(8 * i, 2 * i));
        during = grab();
        const std::size_t drawn = viewport()->lastFrameTriangles();
        EXPECT_GT(drawn, 0u);
        EXPECT_LE(drawn, kStandInTriangles);
    }
    EXPECT_NE(document().camera().yawDegrees, yaw);
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, *start + QPoint(40, 10));
    // Settled, before the new layers are there: the full mesh, from the same camera.
    const QImage settled = grab();
    ASSERT_FALSE(viewport()->isShowingDepthLayers());
    EXPECT_EQ(viewport()->lastFrameTriangles(), full);
    // The stand-in looked like the model: a few pixels along the outline differ, not the shape
    // or its colours.
    const double differing = differingFraction(during, settled);
    EXPECT_GT(differing, 0.0);
    EXPECT_LT(differing, 0.05);
}

TEST_F(StandInTest, WheelDrawsTheStandInUntilItRests) {
    openWithStandIn();
    if (HasFatalFailure())
        return;
    const QPointF middle = QPointF(viewport()->rect().center());
    QWheelEvent wheel(middle, viewport()->mapToGlobal(middle), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(viewport(), &wheel);
    ASSERT_TRUE(viewport()->isCameraMoving());
    grab();
    EXPECT_LE(viewport()->lastFrameTriangles(), kStandInTriangles);
    EXPECT_GT(viewport()->lastFrameTriangles(), 0u);
    ASSERT_TRUE(QTest::qWaitFor([&] { return !viewport()->isCameraMoving(); }, kBuildTimeoutMs));
    grab();
    // The full mesh, or already the layers of the settled view.
    if (!viewport()->isShowingDepthLayers()) {
        EXPECT_EQ(viewport()->lastFrameTriangles(), fullTriangles());
    }
}

TEST_F(StandInTest, PaintingAfterAnOrbitUsesTheFullMesh) {
    openWithStandIn();
    if (HasFatalFailure())
        return;
    const std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value());
    QSignalSpy built(builder(), &ui::DepthLayersBuilder::depthLayersBuilt);
    QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, *start);
    for (int i = 1; i <= 4; ++i) {
        QTest::mouseMove(viewport(), *start + QPoint(6 * i, 0));
        grab();
        EXPECT_LE(viewport()->lastFrameTriangles(), kStandInTriangles);
    }
    QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, *start + QPoint(24, 0));
    ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
    ASSERT_NE(document().depthLayers(), nullptr);
    // Captured from the full mesh: far more triangles than the stand-in has.
    EXPECT_GT(capturedTriangles(), kStandInTriangles);

    const auto* target = dynamic_cast<const core::TextureTarget*>(document().paintTarget());
    ASSERT_NE(target, nullptr);
    const std::vector<std::uint8_t> before = target->page(0).rgba;
    const std::optional<QPoint> p = solidPixel();
    ASSERT_TRUE(p.has_value());
    QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, *p);
    for (int i = 1; i <= 5; ++i)
        QTest::mouseMove(viewport(), *p + QPoint(4 * i, 0));
    QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, *p + QPoint(20, 0));
    target = dynamic_cast<const core::TextureTarget*>(document().paintTarget());
    ASSERT_NE(target, nullptr);
    EXPECT_NE(target->page(0).rgba, before);
}

// The colours of the view do not change when an orbit starts or stops: a stand-in frame
// against the full view (the depth layers' composite) from the same camera, on the trefoil
// painted gold metal by a fill layer, for the lit material and each channel alone.
TEST_F(StandInTest, TheStandInShowsThePaintLayersAndMaterialAsTheSettledView) {
    openWithStandIn();
    if (HasFatalFailure())
        return;
    // New Fill Layer (the panel's button) with the brush's colour, roughness and metallic.
    core::Brush brush = document().brush();
    brush.color = {0.95f, 0.7f, 0.2f, 1.0f};
    brush.paintBaseColor = brush.paintRoughness = brush.paintMetallic = true;
    brush.roughness = 0.3f;
    brush.metallic = 1.0f;
    m_window->setBrush(brush);
    ui::PaintLayersPanel* panel = m_window->paintLayersPanel();
    QToolButton* fillButton = nullptr;
    for (QToolButton* button : panel->findChildren<QToolButton*>())
        if (button->defaultAction() == panel->newFillLayerAction())
            fillButton = button;
    ASSERT_NE(fillButton, nullptr);
    const QImage plain = grab();
    QTest::mouseClick(fillButton, Qt::LeftButton);
    const auto* target = dynamic_cast<const core::TextureTarget*>(document().paintTarget());
    ASSERT_NE(target, nullptr);
    ASSERT_EQ(target->paintLayerStack().size(), 1u);
    ASSERT_TRUE(target->paintLayerStack().layer(0).settings.fill.metallic.has_value());
    const QImage filled = grab();
    const QRgb background = filled.pixel(2, 2);
    // The gold metal changes the picture far more than the stand-in may.
    EXPECT_GT(meanModelDifference(plain, filled, background), 20.0);

    std::optional<QPoint> start = solidPixel();
    ASSERT_TRUE(start.has_value());
    for (const render::MaterialChannel channel :
         {render::MaterialChannel::Material, render::MaterialChannel::BaseColor,
          render::MaterialChannel::Roughness, render::MaterialChannel::Metallic}) {
        SCOPED_TRACE(int(channel));
        viewport()->setChannel(channel);
        QSignalSpy built(builder(), &ui::DepthLayersBuilder::depthLayersBuilt);
        // An orbit: the last frame while the mouse is down is the stand-in's.
        QTest::mousePress(viewport(), Qt::MiddleButton, Qt::NoModifier, *start);
        QImage moving;
        for (int i = 1; i <= 3; ++i) {
            QTest::mouseMove(viewport(), *start + QPoint(6 * i, 2 * i));
            moving = grab();
        }
        ASSERT_GT(viewport()->lastFrameTriangles(), 0u);
        ASSERT_LE(viewport()->lastFrameTriangles(), kStandInTriangles);
        QTest::mouseRelease(viewport(), Qt::MiddleButton, Qt::NoModifier, *start + QPoint(18, 6));
        // Settled: the depth layers of the same camera, composited.
        ASSERT_TRUE(QTest::qWaitFor([&] { return !built.isEmpty(); }, kBuildTimeoutMs));
        ASSERT_TRUE(
            QTest::qWaitFor([&] { return viewport()->isShowingDepthLayers(); }, kBuildTimeoutMs));
        const QImage settled = grab();
        ASSERT_EQ(viewport()->lastFrameTriangles(), 0u) << "not the composite";
        if (channel == render::MaterialChannel::Material) {
            const QString shot = QDir::current().absoluteFilePath(QStringLiteral("stand_in_"));
            EXPECT_TRUE(moving.save(shot + QStringLiteral("orbit.png")));
            EXPECT_TRUE(settled.save(shot + QStringLiteral("settled.png")));
        }
        // The outline moves by a pixel here and there, the simplified surface a little: 3 of
        // 255 levels on average is far under what any shading mismatch makes.
        const double difference = meanModelDifference(moving, settled, background);
        std::printf("[ stand-in ] channel %d: mean colour difference %.2f of 255\n", int(channel),
                    difference);
        EXPECT_LT(difference, 3.0);
        start = solidPixel();
        ASSERT_TRUE(start.has_value());
    }
}

} // namespace stand_in_uitest
