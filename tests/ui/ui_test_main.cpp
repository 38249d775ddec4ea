// SPDX-License-Identifier: GPL-3.0-or-later
// GoogleTest main for the widget tests: a QApplication must exist before any QWidget.
#include <gtest/gtest.h>

#include <QApplication>
#include <QSettings>
#include <QStandardPaths>
#include <QSurfaceFormat>
#include <QTemporaryDir>

#include "ui/shell/stall_meter.h"
#include "ui/view/viewport.h"

int main(int argc, char* argv[]) {
    ::testing::InitGoogleTest(&argc, argv);
    // Listing tests (ctest's discovery) must work without a display.
    if (GTEST_FLAG_GET(list_tests))
        return RUN_ALL_TESTS();

    QSurfaceFormat::setDefaultFormat(ui::Viewport::requiredFormat());
    // Settings go to a test location, never the user's real configuration; a folder per
    // process keeps tests that ctest runs in parallel from sharing one settings file.
    QStandardPaths::setTestModeEnabled(true);
    ui::MeteredApplication app(argc, argv); // measures stalls when a test asks it to
    // Dropping input queued during a freeze is for the tests that ask for it: a slow frame of
    // a sanitizer build must not drop a test's queued pen stroke.
    app.setBusyInputMs(1e9);
    const QTemporaryDir settingsDir;
    if (!settingsDir.isValid())
        return 1;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
    QApplication::setOrganizationName(QStringLiteral("LayerPaintTest"));
    QApplication::setApplicationName(QStringLiteral("ui_uitests"));
    return RUN_ALL_TESTS();
}
