// SPDX-License-Identifier: GPL-3.0-or-later
// Material channels in the GUI through real Qt events: View ▸ Channel opened with the keyboard
// switches what the viewport shows (and is remembered), and File ▸ Export to glTF writes the
// painted roughness and metallic as the material's metallicRoughnessTexture. Needs a display with
// OpenGL 4.5 (run under xvfb-run; Mesa llvmpipe is enough).
#include <gtest/gtest.h>

#include <algorithm>

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/document/document.h"
#include "core/io/gltf/glb_container.h"
#include "core/io/mesh_io.h"
#include "core/paint/targets/paint_target.h"
#include "tests/ui/ui_test_util.h"
#include "tests/ui/window_test.h"
#include "ui/shell/main_window.h"
#include "ui/shell/project_controller.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace material_uitest {

using namespace ui_test;

constexpr int kExportTimeoutMs = 120000;

class MaterialUiTest : public WindowTest {
protected:
    MaterialUiTest() : WindowTest({1260, 860}) {}

    void SetUp() override {
        WindowTest::SetUp();
        if (HasFatalFailure())
            return;
        openTrefoil();
    }

    core::Document& doc() { return m_window->document(); }

    /** Ctrl+Shift+N (a paint layer), then a stroke painting roughness 0.2 and metal 1 only. */
    void paintMetal() {
        QTest::keyClick(m_window.get(), Qt::Key_N, Qt::ControlModifier | Qt::ShiftModifier);
        core::Brush brush = doc().brush();
        brush.radius = 10.0f;
        brush.hardness = 1.0f;
        brush.paintBaseColor = false;
        brush.paintRoughness = true;
        brush.paintMetallic = true;
        brush.roughness = 0.2f;
        brush.metallic = 1.0f;
        m_window->setBrush(brush);
        const std::optional<QPoint> start = solidPixel();
        ASSERT_TRUE(start.has_value()) << "no patch of the model in the view";
        m_start = *start;
        ui::Viewport* viewport = m_window->viewport();
        QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, *start);
        for (int step = 1; step <= 6; ++step)
            QTest::mouseMove(viewport, *start + QPoint(2 * step, 0));
        QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, *start + QPoint(12, 0));
    }

    /**
     * Opens View with Alt+V, then Channel and the entry with its accelerator keys, as a user
     * does; returns when the menus have closed.
     */
    void chooseChannel(Qt::Key key) {
        QTest::keyClick(m_window.get(), Qt::Key_V, Qt::AltModifier);
        auto* channels = m_window->findChild<QMenu*>(QStringLiteral("menuChannel"));
        ASSERT_NE(channels, nullptr);
        auto* view = qobject_cast<QMenu*>(channels->parentWidget());
        ASSERT_NE(view, nullptr);
        ASSERT_TRUE(QTest::qWaitFor([&] { return view->isVisible(); }));
        QTest::keyClick(view, Qt::Key_C);
        ASSERT_TRUE(QTest::qWaitFor([&] { return channels->isVisible(); }));
        QTest::keyClick(channels, key);
        ASSERT_TRUE(QTest::qWaitFor([&] { return !view->isVisible(); }));
    }

    QImage grabView() { return m_window->viewport()->grabFramebuffer(); }

    /**
     * Whether image's bottom-left corner has a legend: a row going from black to white (grey
     * both) within the first 250 pixels.
     */
    static bool hasLegend(const QImage& image) {
        for (int y = image.height() - 40; y < image.height(); ++y) {
            int black = -1, white = -1;
            for (int x = 0; x < std::min(250, image.width()); ++x) {
                const QRgb p = image.pixel(x, y);
                if (qRed(p) != qGreen(p) || qGreen(p) != qBlue(p))
                    continue;
                if (qRed(p) < 30 && black < 0)
                    black = x;
                if (qRed(p) > 225)
                    white = x;
            }
            if (black >= 0 && white > black + 100)
                return true;
        }
        return false;
    }

    QPoint m_start;
};

TEST_F(MaterialUiTest, ViewChannelMenuSwitchesWhatTheViewShows) {
    paintMetal();
    ui::Viewport* viewport = m_window->viewport();
    EXPECT_EQ(viewport->channel(), render::MaterialChannel::Material);
    const QImage material = grabView();

    chooseChannel(Qt::Key_R);
    EXPECT_EQ(viewport->channel(), render::MaterialChannel::Roughness);
    auto* roughnessAction = m_window->findChild<QAction*>(QStringLiteral("actionChannelRoughness"));
    ASSERT_NE(roughnessAction, nullptr);
    EXPECT_TRUE(roughnessAction->isChecked());
    const QImage roughness = grabView();
    // Grey everywhere on the model; the painted roughness (0.2) where the stroke went.
    const QPoint painted = m_start + QPoint(6, 0); // layer pixels are the view's pixels here
    const QRgb pixel = roughness.pixel(painted);
    EXPECT_EQ(qRed(pixel), qGreen(pixel));
    EXPECT_EQ(qGreen(pixel), qBlue(pixel));
    EXPECT_NEAR(qRed(pixel), 51, 3);
    EXPECT_GT(differingFraction(material, roughness), 0.05);
    // Behind it a blue no grey matches, and a legend from 0 (black) to 1 (white).
    const QRgb corner = roughness.pixel(roughness.width() - 3, 3);
    EXPECT_GT(qBlue(corner) - qRed(corner), 40) << "the background is grey like low values";
    EXPECT_LT(qBlue(material.pixel(material.width() - 3, 3)) -
                  qRed(material.pixel(material.width() - 3, 3)),
              20);
    EXPECT_TRUE(hasLegend(roughness));
    EXPECT_FALSE(hasLegend(material));

    chooseChannel(Qt::Key_E);
    EXPECT_EQ(viewport->channel(), render::MaterialChannel::Metallic);
    EXPECT_NEAR(qRed(grabView().pixel(painted)), 255, 3);
    EXPECT_EQ(QSettings().value(QStringLiteral("view/channel")).toInt(),
              int(render::MaterialChannel::Metallic));

    // Remembered: a new window starts with the channel last chosen.
    m_window.reset();
    ui::MainWindow again;
    EXPECT_EQ(again.viewport()->channel(), render::MaterialChannel::Metallic);
    EXPECT_TRUE(again.findChild<QAction*>(QStringLiteral("actionChannelMetallic"))->isChecked());
}

TEST_F(MaterialUiTest, GlbExportFromTheGuiHasTheMetallicRoughnessComposite) {
    paintMetal();
    const auto* target = dynamic_cast<const core::TextureTarget*>(doc().paintTarget());
    ASSERT_NE(target, nullptr);
    const core::Image& composite = target->metallicRoughnessPage(0);
    ASSERT_FALSE(composite.empty());

    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("metal.glb"));
    ui::ProjectController* project = m_window->projectController();
    QSignalSpy exported(project, &ui::ProjectController::exported);
    ASSERT_TRUE(project->exportTo(core::ExportFormat::Glb, file));
    ASSERT_TRUE(exported.wait(kExportTimeoutMs));

    // The material's metallicRoughnessTexture, found through the file's own JSON.
    QFile glb(file);
    ASSERT_TRUE(glb.open(QIODevice::ReadOnly));
    const QByteArray bytes = glb.readAll();
    const std::span<const std::uint8_t> span(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                             std::size_t(bytes.size()));
    const core::Result<core::glb::Layout> layout = core::glb::readContainer(span);
    ASSERT_TRUE(layout) << layout.error();
    const nlohmann::json json =
        nlohmann::json::parse(bytes.constData() + layout->jsonOffset,
                              bytes.constData() + layout->jsonOffset + layout->jsonLength);
    const nlohmann::json& pbr = json.at("materials").at(0).at("pbrMetallicRoughness");
    ASSERT_TRUE(pbr.contains("metallicRoughnessTexture")) << pbr.dump();
    const int texture = pbr["metallicRoughnessTexture"]["index"].get<int>();
    const int source = json.at("textures").at(texture).at("source").get<int>();
    const int view = json.at("images").at(source).at("bufferView").get<int>();
    const core::Result<std::vector<core::Image>> images =
        core::loadGlbImages(QFile::encodeName(file).toStdString(), {{view}});
    ASSERT_TRUE(images) << images.error();
    ASSERT_EQ(images->size(), 1u);
    EXPECT_EQ((*images)[0].width, composite.width);
    EXPECT_EQ((*images)[0].height, composite.height);
    EXPECT_TRUE((*images)[0].rgba == composite.rgba) << "the exported texture is not the composite";
    // Painted metal is in there.
    bool metal = false;
    for (std::size_t i = 2; i < composite.rgba.size() && !metal; i += 4)
        metal = composite.rgba[i] == 255;
    EXPECT_TRUE(metal);

    // Wide strokes to look at in the Material view: smooth metal down the right loop, rough
    // orange down the left one (where the framed trefoil is in a 1260 × 860 window).
    ui::Viewport* viewport = m_window->viewport();
    const auto wide = [&](QPoint from, float roughness, float metallic, bool color) {
        core::Brush brush = doc().brush();
        brush.radius = 22.0f;
        brush.paintBaseColor = color;
        brush.color = {0.9f, 0.35f, 0.05f, 1.0f};
        brush.roughness = roughness;
        brush.metallic = metallic;
        m_window->setBrush(brush);
        QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, from);
        for (int step = 1; step <= 12; ++step)
            QTest::mouseMove(viewport, from + QPoint(0, 5 * step));
        QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, from + QPoint(0, 60));
    };
    wide(QPoint(482, 260), 0.15f, 1.0f, false);
    wide(QPoint(145, 280), 1.0f, 0.0f, true);
    grabView().save(QDir::current().absoluteFilePath(QStringLiteral("material_uitest.png")));
}

} // namespace material_uitest
