// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <gtest/gtest.h>

#include <QImage>
#include <QPoint>
#include <QSettings>
#include <QSignalSpy>
#include <QSize>
#include <QTest>
#include <QUndoStack>

#include <memory>
#include <optional>

#include "core/depth/depth_stack.h"
#include "core/document/document.h"
#include "tests/ui/ui_test_util.h"
#include "ui/shell/main_window.h"
#include "ui/view/depth_layers_builder.h"
#include "ui/view/viewport.h"

namespace ui_test {

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

    /** A new window in place of the current one (as a new start of the application). */
    void showWindow() {
        m_window.reset();
        m_window = std::make_unique<ui::MainWindow>();
        m_window->setErrorDialogsEnabled(false);
        m_window->resize(m_size);
        m_window->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(m_window.get()));
        m_window->activateWindow();
        ASSERT_TRUE(QTest::qWaitForWindowActive(m_window.get()));
    }

    ui::Viewport* viewport() const { return m_window->viewport(); }
    ui::DepthLayersBuilder* builder() const { return m_window->depthLayersBuilder(); }
    core::Document& document() const { return m_window->document(); }
    QUndoStack* undoStack() const { return m_window->undoStack(); }
    QImage grab() const { return viewport()->grabFramebuffer(); }

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

} // namespace ui_test
