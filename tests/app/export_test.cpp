// File → Export… (issue 10): the dialog's defaults, checks and memory, and the window's exports.
// Every format the app writes is byte for byte what `camwright-cli export` writes with the same
// options (whose files the CLI tests read back with ezdxf, svgelements, rs274 and an independent
// evaluation); failures name the problem and lose nothing; long exports leave the GUI thread.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <qcustomplot.h>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>
#include <filesystem>
#include <fstream>

#include "app_test_support.h"
#include "document/commands.h"
#include "document/project_document.h"
#include "export/export_dialog.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "widgets/number_spin_box.h"

namespace cam {
namespace {

using test::kExampleFile;
const QString kMachining =
    QString::fromStdString(test::dataPath("app/six-lobe-machining.cam.json"));

/// Starts the export and waits for its end; the problem (empty on success).
QString exportAndWait(MainWindow& window, const ExportRequest& request) {
    QSignalSpy finished(&window, &MainWindow::exportFinished);
    window.exportFile(request);
    EXPECT_TRUE(test::processEventsUntil([&] { return finished.count() > 0; }, 60000));
    if (finished.isEmpty()) return "no exportFinished";
    EXPECT_EQ(finished.front().at(0).toString(), request.path);
    return finished.front().at(1).toString();
}

/// Opens the example in a shown 1200×800 window and waits for its plots.
bool showExample(MainWindow& window) {
    if (!window.loadFile(kExampleFile).isEmpty()) return false;
    window.resize(1200, 800);
    window.show();
    return window.waitForCurrentResult(20000);
}

/// Closes the message box an export failure opens (it does not block the event loop).
void closeProblemBox(MainWindow& window) {
    for (auto* box : window.findChildren<QMessageBox*>("exportProblemBox")) box->close();
    QCoreApplication::processEvents();
}

struct FormatCase {
    const char* name;
    std::vector<std::string> cliOptions;
    std::function<void(ExportRequest&)> setUp;
};

/// What one case wrote through the CLI and through the window (files cli-NAME, app-NAME).
struct ExportedBothWays {
    std::string cli, app;
    QString appPath;
};

ExportedBothWays exportBothWays(MainWindow& window, const std::string& project, const FormatCase& c,
                                const test::TempDir& dir) {
    ExportedBothWays out;
    const std::string cliFile = dir.file(std::string("cli-") + c.name);
    std::vector<std::string> args{"export", project};
    args.insert(args.end(), c.cliOptions.begin(), c.cliOptions.end());
    args.insert(args.end(), {"--out", cliFile});
    const auto cli = test::runCli(args);
    EXPECT_EQ(cli.exitCode, 0) << c.name << ": " << cli.err;
    if (cli.exitCode != 0) return out;
    ExportRequest request;
    c.setUp(request);
    request.path = QString::fromStdString(dir.file(std::string("app-") + c.name));
    const QString problem = exportAndWait(window, request);
    EXPECT_TRUE(problem.isEmpty()) << c.name << ": " << problem.toStdString();
    if (!problem.isEmpty()) return out;
    out.cli = test::readFile(cliFile);
    out.app = test::readFile(request.path.toStdString());
    out.appPath = request.path;
    return out;
}

TEST(ExportInWindow, EveryFormatWritesWhatTheCliWrites) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kMachining).isEmpty());
    const std::string title = window.document()->project().name;
    ASSERT_FALSE(title.empty());
    const FormatCase cases[] = {
        {"csv",
         {"--format", "csv", "--points", "720"},
         [](ExportRequest& r) {
             r.format = ExportFormat::Csv;
             r.csvPoints = 720;
         }},
        {"dxf",
         {"--format", "dxf", "--centres", "--tool-radius", "3"},
         [](ExportRequest& r) {
             r.format = ExportFormat::Dxf;
             r.dxf.centres = true;
             r.dxf.toolRadiusMm = 3.0;
         }},
        {"dxf-polyline",
         {"--format", "dxf", "--polyline"},
         [](ExportRequest& r) {
             r.format = ExportFormat::Dxf;
             r.dxf.polyline = true;
         }},
        {"svg",
         {"--format", "svg"},
         [&](ExportRequest& r) {
             r.format = ExportFormat::Svg;
             r.svg.title = title;
         }},
        {"gcode",
         {"--format", "gcode", "--tool-radius", "2", "--depth", "3", "--step-down", "1.5"},
         [&](ExportRequest& r) {
             r.format = ExportFormat::Gcode;
             r.gcode.toolRadiusMm = 2.0;
             r.gcode.depthMm = 3.0;
             r.gcode.stepDownMm = 1.5;
             r.gcode.feedMmMin = window.document()->project().machining->feedMax * 60.0;
             r.gcode.projectName = title;
         }},
        {"camtable",
         {"--format", "camtable", "--points", "720"},
         [&](ExportRequest& r) {
             r.format = ExportFormat::CamTable;
             r.camTable.points = 720;
             r.camTable.name = title;
         }},
        {"codesys",
         {"--format", "camtable", "--dialect", "codesys"},
         [&](ExportRequest& r) {
             r.format = ExportFormat::CamTable;
             r.camTable.dialect = CamTableDialect::Codesys;
             r.camTable.name = title;
         }},
    };
    test::TempDir dir;
    for (const FormatCase& c : cases) {
        ExportedBothWays both;
        ASSERT_NO_FATAL_FAILURE(both = exportBothWays(window, kMachining.toStdString(), c, dir));
        EXPECT_GT(both.app.size(), 200u) << c.name;
        EXPECT_EQ(both.app, both.cli) << c.name;
        EXPECT_TRUE(window.statusBar()->currentMessage().contains(both.appPath))
            << window.statusBar()->currentMessage().toStdString();
    }
}

TEST(ExportInWindow, ADesignsCamTableIsItsLawAsTheCliWritesIt) {
    // Issue 33: a project with a design exports its law by default, in the window as in the
    // CLI, byte for byte, in every dialect.
    test::TempDir dir;
    const std::string project = test::examplePath("synthesised-cycloidal-roller.cam.json");
    MainWindow window;
    ASSERT_TRUE(window.loadFile(QString::fromStdString(project)).isEmpty());
    const std::string title =
        "Synthesised from motion: cycloidal rise, modified-sine return, roller 8 mm";
    const std::pair<const char*, CamTableDialect> dialects[] = {
        {"csv", CamTableDialect::Csv},
        {"codesys", CamTableDialect::Codesys},
        {"beckhoff", CamTableDialect::Beckhoff},
        {"rockwell", CamTableDialect::Rockwell},
        {"kollmorgen", CamTableDialect::Kollmorgen}};
    for (const auto& [name, dialect] : dialects) {
        const FormatCase c{name,
                           {"--format", "camtable", "--dialect", name},
                           [&, dialect = dialect](ExportRequest& r) {
                               r.format = ExportFormat::CamTable;
                               r.camTable.dialect = dialect;
                               r.camTable.name = title;
                           }};
        ExportedBothWays both;
        ASSERT_NO_FATAL_FAILURE(both = exportBothWays(window, project, c, dir));
        EXPECT_GT(both.app.size(), 200u) << name;
        EXPECT_EQ(both.app, both.cli) << name;
    }
    EXPECT_NE(test::readFile(dir.file("app-csv")).find("# source=law\n"), std::string::npos);
}

TEST(ExportInWindow, ADesignNeverSynthesisedIsAPlainElectronicCamInTheWindowToo) {
    // Issue 33: a design without a contour exports its law as a servo table, as the CLI does;
    // its contour is refused with the reason; the dialog states the controller's
    // interpolation error before the export, the very number the CLI reports.
    test::TempDir dir;
    const std::string project = test::dataPath("app/design-roller-no-contour.cam.json");
    MainWindow window;
    ASSERT_TRUE(window.loadFile(QString::fromStdString(project)).isEmpty());
    const std::string title = "A design never synthesised: cycloidal rise and return, roller 8 mm";
    const FormatCase c{"beckhoff",
                       {"--format", "camtable", "--dialect", "beckhoff", "--points", "36"},
                       [&](ExportRequest& r) {
                           r.format = ExportFormat::CamTable;
                           r.camTable.dialect = CamTableDialect::Beckhoff;
                           r.camTable.points = 36;
                           r.camTable.name = title;
                           r.camTableSource = CamTableSource::Law;
                       }};
    ExportedBothWays both;
    ASSERT_NO_FATAL_FAILURE(both = exportBothWays(window, project, c, dir));
    EXPECT_GT(both.app.size(), 200u);
    EXPECT_EQ(both.app, both.cli);
    ExportRequest contour;
    c.setUp(contour);
    contour.camTableSource = CamTableSource::Contour;
    contour.path = QString::fromStdString(dir.file("never"));
    EXPECT_TRUE(exportAndWait(window, contour).contains("no contour yet"));
    closeProblemBox(window);
    EXPECT_FALSE(std::filesystem::exists(dir.file("never")));
    // The dialog: the law by default, the contour not offered, the report the CLI's.
    const auto cli = test::runCli({"export", project, "--format", "camtable", "--dialect",
                                   "beckhoff", "--points", "36", "--out", dir.file("again")});
    ASSERT_EQ(cli.exitCode, 0) << cli.err;
    const double error =
        nlohmann::json::parse(cli.out).at("max_error").at("position").get<double>();
    ExportDialog dialog(window.document()->project(), "design", {});
    dialog.setFormat(ExportFormat::CamTable);
    auto* source = dialog.findChild<QComboBox*>("tableSource");
    ASSERT_NE(source, nullptr);
    EXPECT_EQ(source->currentData().toInt(), static_cast<int>(CamTableSource::Law));
    auto* points = dialog.findChild<QSpinBox*>("tablePoints");
    auto* dialect = dialog.findChild<QComboBox*>("tableDialect");
    dialect->setCurrentIndex(static_cast<int>(CamTableDialect::Beckhoff));
    points->setValue(36);
    auto* report = dialog.findChild<QLabel*>("tableReport");
    ASSERT_NE(report, nullptr);
    const QString expected = QString::number(error, 'g', 3) + " mm";
    EXPECT_TRUE(test::processEventsUntil(
        [&] { return report->text().contains("36 points") && report->text().contains(expected); },
        20000))
        << report->text().toStdString() << " / " << expected.toStdString();
}

TEST(ExportInWindow, AConjugatePairWritesWhatTheCliWrites) {
    // Both plates in the drawings, and the second plate's program: byte for byte the CLI's.
    test::TempDir dir;
    const std::string project = dir.file("pair.cam.json");
    std::ofstream(project) << R"({"format": "camwright", "version": 1, "name": "Pair",
      "motion": {"period_s": 2},
      "contour": [{"type": "arc", "center": [5, 0], "radius": 30, "branch": "outer",
                   "phi_start": 0, "phi_end": 360}],
      "follower": {"type": "roller", "radius": 4, "offset": 3, "closure": "conjugate",
                   "conjugate_distance_mm": 80, "conjugate_radius_mm": 5}})";
    MainWindow window;
    ASSERT_TRUE(window.loadFile(QString::fromStdString(project)).isEmpty());
    const FormatCase cases[] = {
        {"dxf", {"--format", "dxf"}, [](ExportRequest& r) { r.format = ExportFormat::Dxf; }},
        {"svg",
         {"--format", "svg"},
         [](ExportRequest& r) {
             r.format = ExportFormat::Svg;
             r.svg.title = "Pair";
         }},
        {"gcode-plate-2",
         {"--format", "gcode", "--tool-radius", "3", "--depth", "3", "--plate", "2"},
         [](ExportRequest& r) {
             r.format = ExportFormat::Gcode;
             r.gcodePlate = 2;
             r.gcode.toolRadiusMm = 3.0;
             r.gcode.depthMm = 3.0;
             r.gcode.feedMmMin = MachiningSpec{}.feedMax * 60.0;
             r.gcode.projectName = "Pair";
         }},
    };
    for (const FormatCase& c : cases) {
        ExportedBothWays both;
        ASSERT_NO_FATAL_FAILURE(both = exportBothWays(window, project, c, dir));
        EXPECT_EQ(both.app, both.cli) << c.name;
    }
    EXPECT_NE(test::readFile(dir.file("app-dxf")).find("PLATE_2"), std::string::npos);
    EXPECT_NE(test::readFile(dir.file("app-svg")).find("id=\"second-plate\""), std::string::npos);
    // The dialog offers the plate for a conjugate pair only.
    ExportDialog pair(window.document()->project(), "pair", {});
    auto* plate = pair.findChild<QComboBox*>("gcodePlate");
    ASSERT_NE(plate, nullptr);
    plate->setCurrentIndex(1);
    pair.setFormat(ExportFormat::Gcode);
    EXPECT_EQ(pair.request().gcodePlate, 2);
    Project single = window.document()->project();
    single.follower->closure = Closure::Spring;
    ExportDialog one(single, "single", {});
    EXPECT_EQ(one.findChild<QComboBox*>("gcodePlate"), nullptr);
}

TEST(ExportInWindow, ACsvWithForcesWritesWhatTheCliWrites) {
    // A project with dynamics: the forces' columns follow the follower's, from the app as
    // from the CLI (cli_tests CliForces.* check the numbers).
    const std::string disc = test::dataPath("forces/eccentric-disc.cam.json");
    MainWindow window;
    ASSERT_TRUE(window.loadFile(QString::fromStdString(disc)).isEmpty());
    test::TempDir dir;
    const std::string cliFile = dir.file("cli.csv");
    const auto cli =
        test::runCli({"export", disc, "--format", "csv", "--points", "360", "--out", cliFile});
    ASSERT_EQ(cli.exitCode, 0) << cli.err;
    ExportRequest request;
    request.format = ExportFormat::Csv;
    request.csvPoints = 360;
    request.path = QString::fromStdString(dir.file("app.csv"));
    ASSERT_TRUE(exportAndWait(window, request).isEmpty());
    const std::string written = test::readFile(request.path.toStdString());
    EXPECT_NE(written.find(",axial_N,normal_N,lateral_N,torque_Nm,power_W,contact_stress_MPa\n"),
              std::string::npos);
    EXPECT_EQ(written, test::readFile(cliFile));
}

TEST(ExportInWindow, ACsvForAGermanSpreadsheetIsTheSameNumbersWithSemicolonsAndCommas) {
    // Issue 31: an option, clearly labelled and off at every start, that writes ";" between
    // cells and a decimal comma. The numbers are the plain export's: read back with ";" as
    // the separator and "," as the decimal point, every cell equals the plain file's.
    MainWindow window;
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    test::TempDir dir;
    ExportRequest request;
    request.format = ExportFormat::Csv;
    request.csvPoints = 72;
    request.path = QString::fromStdString(dir.file("plain.csv"));
    ASSERT_TRUE(exportAndWait(window, request).isEmpty());
    request.csvGerman = true;
    request.path = QString::fromStdString(dir.file("german.csv"));
    ASSERT_TRUE(exportAndWait(window, request).isEmpty());
    const QStringList plain =
        QString::fromStdString(test::readFile(dir.file("plain.csv"))).split('\n');
    const QStringList german =
        QString::fromStdString(test::readFile(dir.file("german.csv"))).split('\n');
    ASSERT_EQ(plain.size(), german.size());
    ASSERT_EQ(plain.size(), 72 + 2);  // header, 72 rows, the last line end
    EXPECT_EQ(german.front(), QString(plain.front()).replace(',', ';'));
    const QLocale de(QLocale::German, QLocale::Germany);
    for (qsizetype row = 1; row + 1 < plain.size(); ++row) {
        const QStringList a = plain[row].split(','), b = german[row].split(';');
        ASSERT_EQ(a.size(), b.size()) << row;
        ASSERT_FALSE(german[row].contains('.')) << german[row].toStdString();
        for (qsizetype c = 0; c < a.size(); ++c) {
            bool okA = false, okB = false;
            const double x = QLocale::c().toDouble(a[c], &okA), y = de.toDouble(b[c], &okB);
            ASSERT_TRUE(okA && okB) << a[c].toStdString() << " / " << b[c].toStdString();
            EXPECT_EQ(x, y) << row << "," << c;
        }
    }
    // The dialog offers it, labelled, and never starts with it.
    ExportDialog dialog(window.document()->project(), "six-lobe", {});
    auto* option = dialog.findChild<QCheckBox*>("csvGerman");
    ASSERT_NE(option, nullptr);
    EXPECT_TRUE(option->text().contains("German"));
    EXPECT_FALSE(option->isChecked());
    dialog.setFormat(ExportFormat::Csv);
    option->setChecked(true);
    EXPECT_TRUE(dialog.request().csvGerman);
    dialog.accept();
    ExportDialog again(window.document()->project(), "six-lobe", {});
    EXPECT_FALSE(again.findChild<QCheckBox*>("csvGerman")->isChecked());
    QSettings().remove("export");  // what accept() remembered is no other test's start
}

TEST(ExportInWindow, AFailureNamesTheProblemAndLosesNothing) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    test::TempDir dir;
    const std::string kept = dir.file("kept.ngc");
    {
        std::ofstream f(kept);
        f << "the old program";
    }
    // A tool wider than the cam's concave arcs (radius 4.5 mm) cannot cut them.
    ExportRequest request;
    request.format = ExportFormat::Gcode;
    request.gcode.toolRadiusMm = 6.0;
    request.path = QString::fromStdString(kept);
    QString problem = exportAndWait(window, request);
    EXPECT_TRUE(problem.contains("Segment 0: the tool radius 6 mm is not smaller than"))
        << problem.toStdString();
    EXPECT_EQ(test::readFile(kept), "the old program");
    auto* box = window.findChild<QMessageBox*>("exportProblemBox");
    ASSERT_NE(box, nullptr);
    EXPECT_TRUE(box->informativeText().contains("Segment 0: the tool radius 6 mm"))
        << box->informativeText().toStdString();
    closeProblemBox(window);

    // A folder that is not there.
    request.format = ExportFormat::Dxf;
    request.path = QString::fromStdString(dir.file("no/such/cam.dxf"));
    problem = exportAndWait(window, request);
    EXPECT_TRUE(problem.contains("no/such")) << problem.toStdString();
    closeProblemBox(window);

    // A project with a problem is not exported at all.
    window.tableModel()->setData(window.tableModel()->index(0, SegmentTableModel::Radius), -2.0,
                                 Qt::EditRole);
    ASSERT_FALSE(window.document()->diagnostics().empty());
    request.path = QString::fromStdString(kept);
    problem = exportAndWait(window, request);
    // Named as the table shows it (messages/diagnostic_text.h).
    EXPECT_TRUE(problem.contains("Segment 0, Radius [mm]")) << problem.toStdString();
    EXPECT_EQ(test::readFile(kept), "the old program");
    closeProblemBox(window);
    EXPECT_EQ(test::folderEntries(dir.path()), std::vector<std::string>{"kept.ngc"});
}

TEST(ExportInWindow, ALongExportRunsOffTheGuiThread) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    test::TempDir dir;
    ExportRequest request;
    request.format = ExportFormat::Csv;
    request.csvPoints = 400'000;  // about 120 MB of text: far more than a frame
    request.path = QString::fromStdString(dir.file("turn.csv"));
    QSignalSpy finished(&window, &MainWindow::exportFinished);
    window.exportFile(request);
    // exportFile returned at once: nothing written yet, the window says what is under way.
    EXPECT_EQ(finished.count(), 0);
    EXPECT_FALSE(std::filesystem::exists(request.path.toStdString()));
    EXPECT_TRUE(window.statusBar()->currentMessage().contains("Exporting"));
    ASSERT_TRUE(test::processEventsUntil([&] { return finished.count() > 0; }, 120000));
    EXPECT_EQ(finished.front().at(1).toString(), QString());
    // Header and 400 000 rows.
    std::ifstream in(request.path.toStdString());
    std::size_t lines = 0;
    for (std::string line; std::getline(in, line);) ++lines;
    EXPECT_EQ(lines, 400'001u);
}

TEST(ExportInWindow, APlotPictureFromTheWindow) {
    MainWindow window;
    ASSERT_TRUE(showExample(window));
    test::TempDir dir;
    ExportRequest request;
    request.format = ExportFormat::Picture;
    request.plot = PlotKind::Acceleration;
    request.picture = PictureFormat::Pdf;
    request.pictureSize = QSize(700, 400);
    request.path = QString::fromStdString(dir.file("a.pdf"));
    ASSERT_EQ(exportAndWait(window, request), QString());
    const auto check =
        test::run("/usr/bin/python3",
                  {std::string(CAMWRIGHT_SOURCE_DIR) + "/tests/reference/check_picture.py", "pdf",
                   request.path.toStdString(), "--title",
                   "Six-lobe arc cam (seed document, Table 1) — Acceleration", "--size", "700x400",
                   "--text", "Acceleration [mm/s²]", "--text", "φ [°]"});
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
}

/// Answers the next popup menu or modal dialog with `answer` as soon as it appears.
void whenShown(std::function<bool()> answer) {
    auto* timer = new QTimer;
    timer->setInterval(20);
    QObject::connect(timer, &QTimer::timeout, [timer, answer] {
        if (answer()) timer->deleteLater();
    });
    timer->start();
}

TEST(ExportInWindow, RightClickOnAPlotExportsIt) {
    MainWindow window;
    ASSERT_TRUE(showExample(window));
    test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("jerk.svg"));
    QCustomPlot* plot = window.plotWidget(PlotKind::Jerk);
    whenShown([] {
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        if (!menu) return false;
        auto* action = menu->findChild<QAction*>("actionExportPlot");
        if (!action) return false;
        menu->close();
        action->trigger();
        return true;
    });
    whenShown([path] {
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        if (!dialog) return false;
        dialog->selectFile(path);
        QMetaObject::invokeMethod(dialog, "accept");
        return true;
    });
    QSignalSpy finished(&window, &MainWindow::exportFinished);
    emit plot->customContextMenuRequested(QPoint(50, 50));
    ASSERT_TRUE(test::processEventsUntil([&] { return finished.count() > 0; }));
    EXPECT_EQ(finished.front().at(1).toString(), QString());
    const auto check =
        test::run("/usr/bin/python3",
                  {std::string(CAMWRIGHT_SOURCE_DIR) + "/tests/reference/check_picture.py", "svg",
                   path.toStdString(), "--title",
                   "Six-lobe arc cam (seed document, Table 1) — Jerk", "--size",
                   std::to_string(std::max(plot->width(), 640)) + "x" +
                       std::to_string(std::max(plot->height(), 400)),
                   "--text", "Jerk [mm/s³]"});
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
    // The folder is remembered for the next export.
    EXPECT_EQ(QSettings().value("export/folder").toString(),
              QString::fromStdString(dir.path().string()));
}

// The dialog lists the formats and dialects of the core's table (export/export_formats.h), in
// its order, by their titles: a new row is a new choice without a change here.
TEST(ExportDialogTest, ListsEveryFormatAndDialectOfTheTable) {
    Project project;
    ExportDialog dialog(project, "x", {PlotKind::Contour});
    const auto titles = [&](const char* box) {
        QStringList out;
        auto* combo = dialog.findChild<QComboBox*>(box);
        for (int k = 0; combo && k < combo->count(); ++k) out << combo->itemText(k);
        return out;
    };
    QStringList formats, tables, pictures;
    for (const ExportFormatKind& kind : exportFormats()) formats << QString::fromUtf8(kind.title);
    for (const ExportDialectKind& d : exportFormat(ExportFormat::CamTable).dialects) {
        tables << QString::fromUtf8(d.title);
    }
    for (const ExportDialectKind& d : exportFormat(ExportFormat::Picture).dialects) {
        pictures << QString::fromUtf8(d.title);
    }
    EXPECT_EQ(titles("exportFormat"), formats);
    EXPECT_EQ(titles("tableDialect"), tables);
    EXPECT_EQ(titles("pictureFormat"), pictures);
    EXPECT_EQ(formats.size(), 6);
    EXPECT_EQ(tables.size(), 5);
    EXPECT_EQ(pictures.size(), 3);
    // Each picture dialect is the PictureFormat of its place in the table.
    for (int k = 0; k < pictures.size(); ++k) {
        const auto named = pictureFormatNamed(
            QString::fromUtf8(exportFormat(ExportFormat::Picture).dialects[k].name.data()));
        ASSERT_TRUE(named);
        EXPECT_EQ(static_cast<int>(*named), k);
    }
}

TEST(ExportDialogTest, StartsFromTheProjectAndTheLastExport) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kMachining).isEmpty());
    const Project& project = window.document()->project();
    test::TempDir dir;
    QSettings().setValue("export/folder", QString::fromStdString(dir.path().string()));
    QSettings().setValue("export/format", static_cast<int>(ExportFormat::Gcode));
    ExportDialog dialog(project, "six-lobe-machining", {PlotKind::Contour, PlotKind::Velocity});
    // The last format, in the last folder, the file named after the project.
    ExportRequest r = dialog.request();
    EXPECT_EQ(r.format, ExportFormat::Gcode);
    EXPECT_EQ(r.path, QString::fromStdString(dir.file("six-lobe-machining.ngc")));
    EXPECT_EQ(r.gcode.toolRadiusMm, project.machining->toolRadius);
    EXPECT_EQ(r.gcode.feedMmMin, project.machining->feedMax * 60.0);
    EXPECT_EQ(r.gcode.projectName, project.name);
    EXPECT_FALSE(r.gcode.stepDownMm.has_value());
    EXPECT_EQ(r.csvPoints, static_cast<std::size_t>(project.samplesPerTurnOrDefault()));
    EXPECT_EQ(r.camTable.points, 360u);

    // The file's suffix follows the format, the dialect and the plot.
    dialog.setFormat(ExportFormat::CamTable);
    EXPECT_TRUE(dialog.request().path.endsWith("six-lobe-machining.csv"));
    dialog.findChild<QComboBox*>("tableDialect")->setCurrentIndex(1);
    EXPECT_TRUE(dialog.request().path.endsWith("six-lobe-machining.st"));
    dialog.setFormat(ExportFormat::Picture);
    EXPECT_TRUE(dialog.request().path.endsWith("six-lobe-machining-contour.png"));
    dialog.findChild<QComboBox*>("plotKind")->setCurrentIndex(1);
    dialog.findChild<QComboBox*>("pictureFormat")->setCurrentIndex(1);
    r = dialog.request();
    EXPECT_TRUE(r.path.endsWith("six-lobe-machining-velocity.pdf")) << r.path.toStdString();
    EXPECT_EQ(r.plot, PlotKind::Velocity);
    EXPECT_EQ(r.picture, PictureFormat::Pdf);
    EXPECT_EQ(r.pictureSize, QSize(842, 595));

    // Options reach the request.
    dialog.setFormat(ExportFormat::Dxf);
    dialog.findChild<QCheckBox*>("dxfToolPath")->setChecked(true);
    dialog.findChild<NumberSpinBox*>("dxfToolRadius")->setValue(2.5);
    dialog.findChild<QCheckBox*>("dxfSplines")->setChecked(true);
    r = dialog.request();
    EXPECT_EQ(r.dxf.toolRadiusMm, 2.5);
    EXPECT_TRUE(r.dxf.splineEntities);
    EXPECT_FALSE(r.dxf.polyline);

    // A folder that is not there keeps the dialog open and says so.
    dialog.show();
    dialog.setFileName(QString::fromStdString(dir.file("missing/cam.dxf")));
    dialog.accept();
    EXPECT_TRUE(dialog.isVisible());
    auto* problem = dialog.findChild<QLabel*>("exportProblem");
    EXPECT_TRUE(problem->isVisibleTo(&dialog));
    EXPECT_TRUE(problem->text().contains("missing")) << problem->text().toStdString();
    // A good one is taken, and remembered with the format.
    test::TempDir other;
    dialog.setFileName(QString::fromStdString(other.file("cam.dxf")));
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    EXPECT_EQ(QSettings().value("export/folder").toString(),
              QString::fromStdString(other.path().string()));
    EXPECT_EQ(QSettings().value("export/format").toInt(), static_cast<int>(ExportFormat::Dxf));

    // The next dialog starts with the options of this one; what the project gives comes from
    // the project.
    ExportDialog next(project, "six-lobe-machining", {});
    r = next.request();
    EXPECT_EQ(r.format, ExportFormat::Dxf);
    EXPECT_EQ(r.path, QString::fromStdString(other.file("six-lobe-machining.dxf")));
    EXPECT_TRUE(r.dxf.splineEntities);
    EXPECT_EQ(r.dxf.toolRadiusMm, project.machining->toolRadius);  // checked; from the project
    EXPECT_EQ(r.camTable.dialect, CamTableDialect::Codesys);
    EXPECT_EQ(r.picture, PictureFormat::Pdf);
    EXPECT_EQ(r.pictureSize, QSize(842, 595));
}

TEST(ExportDialogTest, AProjectNamedLikeAPlotKeepsItsName) {
    // Seen under Xvfb: "design-roller-no-contour" became "design-roller-no.dxf", the tail
    // taken for a plot's name. Only the plot tail the dialog added is renamed.
    ExportDialog dialog(Project{}, "design-roller-no-contour",
                        {PlotKind::Contour, PlotKind::Velocity});
    // The file's name without its suffix (the suffixes follow the remembered options).
    const auto stem = [&] { return QFileInfo(dialog.request().path).completeBaseName(); };
    dialog.setFormat(ExportFormat::Dxf);
    EXPECT_EQ(stem(), "design-roller-no-contour");
    dialog.setFormat(ExportFormat::Picture);
    dialog.findChild<QComboBox*>("plotKind")->setCurrentIndex(1);
    EXPECT_EQ(stem(), "design-roller-no-contour-velocity");
    dialog.findChild<QComboBox*>("plotKind")->setCurrentIndex(0);
    EXPECT_EQ(stem(), "design-roller-no-contour-contour");
    dialog.setFormat(ExportFormat::CamTable);
    EXPECT_EQ(stem(), "design-roller-no-contour");
}

TEST(ExportDialogTest, TheFeedStartsCautiousIsRememberedAndStaysBelowTheProjectsLimit) {
    // Issue 31, point 6: a project without a machining section went out at 6,000 mm/min, and a
    // typed feed was forgotten by the next export.
    QSettings().remove("export/options");
    const Project plain = test::loadExample();
    ASSERT_FALSE(plain.machining.has_value());
    test::TempDir dir;
    const auto exportWith = [&](const Project& project, const QString& feed) {
        ExportDialog dialog(project, "cam", {});
        dialog.setFormat(ExportFormat::Gcode);
        dialog.show();
        if (!feed.isEmpty()) test::typeInto(dialog.findChild<NumberSpinBox*>("gcodeFeed"), feed);
        const ExportRequest r = dialog.request();
        dialog.setFileName(QString::fromStdString(dir.file("cam.ngc")));
        dialog.accept();
        EXPECT_EQ(dialog.result(), QDialog::Accepted);
        return std::pair{r, dialog.findChild<QLabel*>("gcodePlunge")->text()};
    };
    // A first export of a project with no feed limit: 1,000 mm/min, the plunge at half shown.
    auto [first, plunge] = exportWith(plain, {});
    EXPECT_EQ(first.gcode.feedMmMin, 1000.0);
    EXPECT_EQ(plunge, "500 mm/min (half the feed)");
    // A typed feed is the next export's.
    EXPECT_EQ(exportWith(plain, "2400").first.gcode.feedMmMin, 2400.0);
    EXPECT_EQ(exportWith(plain, {}).first.gcode.feedMmMin, 2400.0);
    // A project with a feed limit (100 mm/s) keeps a remembered feed below it, caps one above,
    // and gives its own tool radius whatever was typed before.
    Project limited = plain;
    limited.machining = MachiningSpec{};
    limited.machining->feedMax = 100.0;
    limited.machining->toolRadius = 2.0;
    auto [below, plungeBelow] = exportWith(limited, {});
    EXPECT_EQ(below.gcode.feedMmMin, 2400.0);
    EXPECT_EQ(plungeBelow, "1200 mm/min (half the feed)");
    EXPECT_EQ(exportWith(plain, "9000").first.gcode.feedMmMin, 9000.0);
    const auto capped = exportWith(limited, {}).first;
    EXPECT_EQ(capped.gcode.feedMmMin, 6000.0);
    EXPECT_EQ(capped.gcode.toolRadiusMm, 2.0);
    // Typed above the limit: the box refuses to go past it.
    EXPECT_EQ(exportWith(limited, "7000").first.gcode.feedMmMin, 6000.0);
    QSettings().remove("export/options");
}

TEST(ExportDialogTest, AProjectsExportGoesBesideItUnlessItWasExportedElsewhere) {
    // Issue 31, point 8: the dialog started in the home folder, not the project's.
    const Project project = test::loadExample();
    test::TempDir lastAny, projectDir, chosen, otherDir;
    QSettings().setValue("export/folder", QString::fromStdString(lastAny.path().string()));
    QSettings().remove("export/project");
    const QString projectFile = QString::fromStdString(projectDir.file("cam.cam.json"));
    const auto folderOf = [&](const QString& file) {
        ExportDialog dialog(project, "cam", {}, nullptr, file);
        return QFileInfo(dialog.request().path).absolutePath();
    };
    const auto dirOf = [](const test::TempDir& d) {
        return QFileInfo(QString::fromStdString(d.path().string())).absoluteFilePath();
    };
    EXPECT_EQ(folderOf(projectFile), dirOf(projectDir));
    EXPECT_EQ(folderOf({}), dirOf(lastAny));  // a project with no file yet: the last folder
    // Exported elsewhere, the project's next export goes there; another project's beside it.
    {
        ExportDialog dialog(project, "cam", {}, nullptr, projectFile);
        dialog.show();
        dialog.setFileName(QString::fromStdString(chosen.file("cam.dxf")));
        dialog.accept();
        ASSERT_EQ(dialog.result(), QDialog::Accepted);
    }
    EXPECT_EQ(folderOf(projectFile), dirOf(chosen));
    EXPECT_EQ(folderOf(QString::fromStdString(otherDir.file("other.cam.json"))), dirOf(otherDir));
}

TEST(ExportDialogTest, FileExportIsInTheMenuWithItsShortcut) {
    MainWindow window;
    auto* action = window.findChild<QAction*>("actionExport");
    ASSERT_NE(action, nullptr);
    EXPECT_EQ(action->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_E));
    EXPECT_FALSE(action->toolTip().isEmpty());
    // Without a machining section the machining plots are not offered; with one, while the
    // Machining panel shows its times, they are.
    ASSERT_TRUE(window.loadFile(kMachining).isEmpty());
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    auto plots = window.drawablePlots();
    EXPECT_EQ(std::count(plots.begin(), plots.end(), PlotKind::Feed), 0);
    window.showMachiningPanel();
    window.show();
    ASSERT_TRUE(test::processEventsUntil([&] {
        const auto p = window.drawablePlots();
        return std::count(p.begin(), p.end(), PlotKind::Feed) == 1;
    }));
}

}  // namespace
}  // namespace cam
