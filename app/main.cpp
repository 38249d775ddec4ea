// SPDX-License-Identifier: GPL-3.0-or-later
// The LayerPaint GUI: command line, translations, and the main window.
#include <QApplication>
#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QIcon>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QStringList>
#include <QSurfaceFormat>
#include <QTranslator>

#include "core/base/huge_pages.h"
#include "ui/shell/main_window.h"
#include "ui/shell/project_controller.h"
#include "ui/shell/stall_meter.h"
#include "ui/view/viewport.h"

namespace {

/** The reverse-DNS id: the .desktop file, the AppStream metainfo and the icon are named so. */
const QString kAppId = QStringLiteral("io.github.layerpaint.LayerPaint");
/** The preferred language: "" (the system's), "en", "de", "zh_CN", ... */
const QString kLanguageKey = QStringLiteral("ui/language");

void setApplicationInfo() {
    // Organization and application name are the QSettings location.
    QCoreApplication::setOrganizationName(QStringLiteral("LayerPaint"));
    QCoreApplication::setOrganizationDomain(QStringLiteral("layerpaint.github.io"));
    QCoreApplication::setApplicationName(QStringLiteral("LayerPaint"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LAYERPAINT_VERSION));
}

/**
 * Installs LayerPaint's translation (embedded by qt_add_translations under :/i18n) and Qt's own
 * for the language of the preferences, or the system's. A language without a translation
 * (English) leaves the source strings. Needs setApplicationInfo() first (for the settings).
 */
void installTranslators(QCoreApplication& app) {
    const QString language = QSettings().value(kLanguageKey).toString();
    const QLocale locale = language.isEmpty() ? QLocale::system() : QLocale(language);
    if (!language.isEmpty())
        QLocale::setDefault(locale); // numbers follow the chosen language too
    auto* qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    auto* own = new QTranslator(&app);
    if (own->load(locale, QStringLiteral("layerpaint"), QStringLiteral("_"),
                  QStringLiteral(":/i18n")))
        QCoreApplication::installTranslator(own);
}

void describeOptions(QCommandLineParser& parser) {
    parser.setApplicationDescription(
        QCoreApplication::translate("main", "Layer-aware 3D painting of meshes."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QCoreApplication::translate("main", "file"),
        QCoreApplication::translate("main", "The project or model to open (glTF, OBJ, PLY, STL, "
                                            "OFF, ... or builtin:NAME). Without it the trefoil "
                                            "knot opens."),
        QCoreApplication::translate("main", "[file]"));
    parser.addOption(QCommandLineOption(
        QStringLiteral("connectivity"),
        QCoreApplication::translate("main", "Where pixel connectivity is computed: auto (the "
                                            "faster here), cpu or gpu."),
        QStringLiteral("engine")));
}

} // namespace

int main(int argc, char* argv[]) {
    core::restartWithHugePages(argv); // a large model's arrays fill faster
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments.append(QString::fromLocal8Bit(argv[i]));
    {
        // --help and --version print and exit without needing a display. Qt's own options
        // (-platform, -reverse, ...) are still in argv here: read single-dash words as long
        // options so they are not taken for -v, and leave errors to the full parse below.
        QCommandLineParser probe;
        describeOptions(probe);
        probe.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
        probe.parse(arguments);
        if (probe.isSet(QStringLiteral("help")) || probe.isSet(QStringLiteral("version")) ||
            probe.isSet(QStringLiteral("help-all"))) {
            QCoreApplication textOnly(argc, argv);
            setApplicationInfo();
            installTranslators(textOnly);
            QCommandLineParser parser; // described again, now translated
            describeOptions(parser);
            parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
            parser.process(textOnly); // exits
            return 1;
        }
    }

    // Must precede QApplication so every context, including the one sharing with the
    // QOpenGLWidget, is created as OpenGL 4.5 core.
    QSurfaceFormat::setDefaultFormat(ui::Viewport::requiredFormat());

    ui::MeteredApplication app(argc, argv);
    // LAYERPAINT_STALL_MS=N: every event the window takes N ms or more to handle, on stderr.
    app.setStallThresholdMs(ui::MeteredApplication::thresholdFromEnvironment());
    app.setLogStalls(true);
    setApplicationInfo();
    QApplication::setApplicationDisplayName(QStringLiteral("LayerPaint"));
    QGuiApplication::setDesktopFileName(kAppId);
    QApplication::setWindowIcon(
        QIcon::fromTheme(kAppId, QIcon(QStringLiteral(":/icons/%1.svg").arg(kAppId))));
    installTranslators(app);

    QCommandLineParser parser;
    describeOptions(parser);
    parser.process(app);

    ui::MainWindow window;
    if (parser.isSet(QStringLiteral("connectivity")) &&
        !window.setConnectivityBackend(parser.value(QStringLiteral("connectivity")))) {
        qCritical("layerpaint: --connectivity must be auto, cpu or gpu");
        return 2;
    }
    window.show();
    // After a crash, the autosaved work comes first.
    if (!window.projectController()->offerRecovery())
        window.openFromCommandLine(parser.positionalArguments());
    window.showQuickGuideAtStart(); // a first start opens it once
    return QApplication::exec();
}
