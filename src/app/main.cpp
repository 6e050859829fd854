// camwright: the desktop application. In this first version a minimal window that shows the
// contour and r(phi) of a project; the full editor (arc table, live plots, undo) comes next.

#include <QApplication>
#include <QCommandLineParser>
#include <QMessageBox>
#include <cstdlib>

#include "mainwindow.h"

int main(int argc, char** argv) {
    // With no display QApplication aborts before any argument parsing; fall back to offscreen.
    if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") &&
        qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    QApplication app(argc, argv);
    QApplication::setApplicationName("Camwright");
    QApplication::setOrganizationName("Camwright");
    QApplication::setApplicationVersion(CAMWRIGHT_VERSION);

    QCommandLineParser parser;
    parser.setApplicationDescription("Design and inspect cam contours.");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("project", "A .cam.json project to open.", "[PROJECT]");
    parser.process(app);

    cam::MainWindow window;
    const QStringList files = parser.positionalArguments();
    if (!files.isEmpty()) {
        const QString problem = window.openProject(files.front());
        if (!problem.isEmpty()) {
            QMessageBox::critical(&window, "Camwright", problem);
        }
    }
    window.show();
    return QApplication::exec();
}
