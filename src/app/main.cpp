// camwright: the desktop application.
//   camwright [PROJECT]
//   camwright --screenshot FILE.png [--size WxH] [PROJECT]   (works without any display)

#include <QApplication>
#include <QCommandLineParser>
#include <QLibraryInfo>
#include <QLocale>
#include <QMessageBox>
#include <QTimer>
#include <QTranslator>
#include <cstdio>
#include <cstring>

#include "mainwindow.h"
#include "screenshot.h"

namespace {

/// With no display QApplication aborts before any argument parsing; a screenshot or --help
/// needs none, and an interactive start without one falls back to offscreen.
void chooseOffscreenWhenThereIsNoDisplay(int argc, char** argv) {
    if (!qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) return;
    bool headless = false;
    for (int i = 1; i < argc; ++i) {
        headless = headless || std::strcmp(argv[i], "--screenshot") == 0 ||
                   std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "--version") == 0;
    }
    const bool noDisplay =
        qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY");
    if (headless || noDisplay) qputenv("QT_QPA_PLATFORM", "offscreen");
}

}  // namespace

int main(int argc, char** argv) {
    chooseOffscreenWhenThereIsNoDisplay(argc, argv);
    QApplication app(argc, argv);
    QApplication::setApplicationName("Camwright");
    QApplication::setOrganizationName("Camwright");
    QApplication::setApplicationVersion(CAMWRIGHT_VERSION);

    QTranslator qtTranslator, appTranslator;
    if (qtTranslator.load(QLocale(), "qtbase", "_",
                          QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QApplication::installTranslator(&qtTranslator);
    }
    if (appTranslator.load(QLocale(), "camwright", "_", ":/i18n")) {
        QApplication::installTranslator(&appTranslator);
    }

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
    parser.addOption(screenshotOption);
    parser.addOption(sizeOption);
    parser.process(app);

    cam::MainWindow window;
    const QStringList files = parser.positionalArguments();
    if (files.size() > 1) {
        std::fprintf(stderr, "camwright: give at most one PROJECT\n");
        return 1;
    }
    const bool headless = parser.isSet(screenshotOption);
    if (!files.isEmpty()) {
        const QString problem = window.loadFile(files.front());
        if (!problem.isEmpty()) {
            if (headless) {
                std::fprintf(stderr, "camwright: %s\n", qPrintable(problem));
                return 2;
            }
            QMessageBox::warning(&window, "Camwright", problem);
        }
    }
    if (headless)
        return cam::writeScreenshot(window, parser.value(screenshotOption),
                                    parser.value(sizeOption));
    window.show();
    return QApplication::exec();
}
