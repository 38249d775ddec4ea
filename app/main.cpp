// SPDX-License-Identifier: GPL-3.0-or-later
// The LayerPaint GUI: command line, translations, and the main window.
#include <QApplication>
#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QStringList>
#include <QSurfaceFormat>
#include <QTranslator>

#include "ui/main_window.h"
#include "ui/viewport.h"

namespace {

void setApplicationInfo() {
    // Organization and application name are the QSettings location.
    QCoreApplication::setOrganizationName(QStringLiteral("LayerPaint"));
    QCoreApplication::setOrganizationDomain(QStringLiteral("layerpaint.org"));
    QCoreApplication::setApplicationName(QStringLiteral("LayerPaint"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LAYERPAINT_VERSION));
}

void describeOptions(QCommandLineParser& parser) {
    parser.setApplicationDescription(
        QCoreApplication::translate("main", "Layer-aware 3D painting of meshes."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QCoreApplication::translate("main", "file"),
        QCoreApplication::translate("main", "The model to open (glTF, OBJ, PLY, STL, OFF, ... or "
                                            "builtin:NAME). Without it the trefoil knot opens."),
        QCoreApplication::translate("main", "[file]"));
    parser.addOption(QCommandLineOption(
        QStringLiteral("connectivity"),
        QCoreApplication::translate("main", "Where pixel connectivity is computed: auto (the "
                                            "faster here), cpu or gpu."),
        QStringLiteral("engine")));
}

} // namespace

int main(int argc, char* argv[]) {
    QStringList arguments;
    for (int i = 0; i < argc; ++i)
        arguments.append(QString::fromLocal8Bit(argv[i]));
    {
        // --help and --version print and exit without needing a display. Qt's own options
        // (-platform, -reverse, ...) are still in argv here: read single-dash words as long
        // options so they are not taken for -v, and leave errors to the full parse below.
        QCommandLineParser parser;
        describeOptions(parser);
        parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
        parser.parse(arguments);
        if (parser.isSet(QStringLiteral("help")) || parser.isSet(QStringLiteral("version")) ||
            parser.isSet(QStringLiteral("help-all"))) {
            QCoreApplication textOnly(argc, argv);
            setApplicationInfo();
            parser.process(textOnly); // exits
            return 1;
        }
    }

    // Must precede QApplication so every context, including the one sharing with the
    // QOpenGLWidget, is created as OpenGL 4.5 core.
    QSurfaceFormat::setDefaultFormat(ui::Viewport::requiredFormat());

    QApplication app(argc, argv);
    setApplicationInfo();
    QApplication::setApplicationDisplayName(QStringLiteral("LayerPaint"));

    QTranslator qtTranslator;
    if (qtTranslator.load(QLocale(), QStringLiteral("qtbase"), QStringLiteral("_"),
                          QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QApplication::installTranslator(&qtTranslator);
    QTranslator appTranslator;
    if (appTranslator.load(QLocale(), QStringLiteral("layerpaint"), QStringLiteral("_"),
                           QStringLiteral(":/i18n")))
        QApplication::installTranslator(&appTranslator);

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
    window.openFromCommandLine(parser.positionalArguments());
    return QApplication::exec();
}
