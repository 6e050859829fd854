// camwright: the desktop application.
//   camwright [PROJECT]
//   camwright --screenshot FILE.png [--size WxH] [PROJECT]   (works without any display)
//   camwright --export-plot NAME [--format png|pdf|svg] --out FILE [--size WxH] PROJECT

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QLocale>
#include <QMessageBox>
#include <QTimer>
#include <cstdio>
#include <cstring>

#include "engine/memory_reuse.h"
#include "files/autosave.h"
#include "files/project_files.h"
#include "mainwindow.h"
#include "screenshot.h"
#include "translations.h"

namespace {

/// With no display QApplication aborts before any argument parsing; a screenshot or --help
/// needs none, and an interactive start without one falls back to offscreen.
void chooseOffscreenWhenThereIsNoDisplay(int argc, char** argv) {
    if (!qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) return;
    bool headless = false;
    for (int i = 1; i < argc; ++i) {
        headless = headless || std::strcmp(argv[i], "--screenshot") == 0 ||
                   std::strcmp(argv[i], "--export-plot") == 0 ||
                   std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "--version") == 0;
    }
    const bool noDisplay =
        qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
    if (headless || noDisplay) qputenv("QT_QPA_PLATFORM", "offscreen");
}

/// Qt's notes about the environment of a headless run (no XDG_RUNTIME_DIR, the offscreen
/// platform's missing size hints) say nothing about the picture: they would bury the one line
/// that matters on stderr. Everything else goes through as before.
QtMessageHandler g_defaultHandler = nullptr;
void quietHeadlessMessages(QtMsgType type, const QMessageLogContext& context,
                           const QString& message) {
    if (type == QtWarningMsg &&
        (message.startsWith("QStandardPaths: XDG_RUNTIME_DIR not set") ||
         message.startsWith("This plugin does not support propagateSizeHints"))) {
        return;
    }
    g_defaultHandler(type, context, message);
}

bool isHeadless(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--screenshot") == 0 || std::strcmp(argv[i], "--export-plot") == 0)
            return true;
    }
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    cam::keepFreedMemoryForReuse();
    if (isHeadless(argc, argv)) g_defaultHandler = qInstallMessageHandler(quietHeadlessMessages);
    chooseOffscreenWhenThereIsNoDisplay(argc, argv);
    QApplication app(argc, argv);
    QApplication::setApplicationName("Camwright");
    QApplication::setOrganizationName("Camwright");
    QApplication::setApplicationVersion(CAMWRIGHT_VERSION);
    // The desktop entry (packaging/linux) and the icon share this id.
    QGuiApplication::setDesktopFileName(QStringLiteral("org.camwright.Camwright"));
    QApplication::setWindowIcon(
        QIcon::fromTheme(QStringLiteral("org.camwright.Camwright"),
                         QIcon(QStringLiteral(":/icons/org.camwright.Camwright.svg"))));

    const cam::Translations translations{QLocale()};

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "Design and inspect cam contours."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        "project", QApplication::translate("main", "A .cam.json project to open."), "[PROJECT]");
    const QCommandLineOption screenshotOption(
        "screenshot",
        QApplication::translate("main", "Render the main window into FILE.png and exit."),
        "FILE.png");
    const QCommandLineOption sizeOption(
        "size", QApplication::translate("main", "Window size for --screenshot."), "WxH");
    const QCommandLineOption exportPlotOption(
        "export-plot",
        QApplication::translate("main",
                                "Draw one plot of PROJECT into --out and exit (contour, velocity, "
                                "acceleration, jerk, feed, axis-acceleration)."),
        "NAME");
    const QCommandLineOption formatOption(
        "format",
        QApplication::translate("main",
                                "Picture format for --export-plot: png, pdf or svg "
                                "(default: the suffix of --out)."),
        "FORMAT");
    const QCommandLineOption outOption(
        "out", QApplication::translate("main", "The file --export-plot writes."), "FILE");
    parser.addOption(screenshotOption);
    parser.addOption(sizeOption);
    parser.addOption(exportPlotOption);
    parser.addOption(formatOption);
    const QCommandLineOption autosaveOption(
        "autosave-interval",
        QApplication::translate("main",
                                "Seconds between recovery copies of unsaved changes (default 30, "
                                "or the settings' autosave/intervalS)."),
        "SECONDS");
    parser.addOption(outOption);
    parser.addOption(autosaveOption);
    parser.process(app);

    cam::MainWindow window;
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1) {
        std::fprintf(stderr, "camwright: give at most one PROJECT\n");
        return 1;
    }
    const bool exportPlot = parser.isSet(exportPlotOption);
    const bool headless = parser.isSet(screenshotOption) || exportPlot;
    // A picture drawn for a script is not a file the user opened.
    if (headless) window.files()->setRemembersRecentFiles(false);
    if (exportPlot && files.isEmpty()) {
        std::fprintf(stderr, "camwright: --export-plot: give the PROJECT to draw\n");
        return 1;
    }
    if (parser.isSet(autosaveOption)) {
        bool ok = false;
        const double seconds = parser.value(autosaveOption).toDouble(&ok);
        if (!ok || !(seconds >= 0.01 && seconds <= 86400.0)) {
            std::fprintf(stderr,
                         "camwright: --autosave-interval: expected seconds between 0.01 and "
                         "86400 (got \"%s\")\n",
                         qPrintable(parser.value(autosaveOption)));
            return 1;
        }
        window.autosave()->setIntervalMs(static_cast<int>(seconds * 1000.0));
    }
    // After a crash the unsaved changes come first; a restored project replaces the one asked
    // for on the command line (which stays one File → Open away).
    const bool restored = !headless && window.offerRecovery();
    if (!files.isEmpty() && !restored) {
        const QString problem = window.loadFile(files.front());
        if (!problem.isEmpty()) {
            if (headless) {
                std::fprintf(stderr, "camwright: %s\n", qPrintable(problem));
                return 2;
            }
            QMessageBox::warning(&window, "Camwright", problem);
        }
    }
    if (exportPlot) {
        return cam::writePlotPicture(window, parser.value(exportPlotOption),
                                     parser.value(formatOption), parser.value(outOption),
                                     parser.value(sizeOption));
    }
    if (headless)
        return cam::writeScreenshot(window, parser.value(screenshotOption),
                                    parser.value(sizeOption));
    window.show();
    return QApplication::exec();
}
