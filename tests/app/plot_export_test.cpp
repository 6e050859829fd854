// Pictures of the plots (issue 10): `camwright-cli export --format png|pdf|svg --plot NAME`, which
// has the app draw them headless (`camwright --export-plot`), and the same pictures from the
// window. Each is read back by what a user opens it with: QImage for PNG, poppler (pdfinfo,
// pdftotext, pdftoppm) for PDF, svgelements and rsvg-convert for SVG
// (tests/reference/check_picture.py). For the contour the PDF's tick labels must give one mm
// the same length on both axes.

#include <gtest/gtest.h>

#include <qcustomplot.h>
#include <QImage>
#include <QSignalSpy>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app_test_support.h"
#include "mainwindow.h"
#include "views/contour_view.h"
#include "views/palette.h"

namespace cam {
namespace {

const char* const kPython = "/usr/bin/python3";
using test::kExample;

std::string checker() {
    return std::string(CAMWRIGHT_SOURCE_DIR) + "/tests/reference/check_picture.py";
}

/// Pixels of the colour or of its antialiased blend with the white background: c = w·colour +
/// (1 − w)·white with a weight w of at least a third, within 12 per channel. Only inside the
/// plot, away from title, tick labels and legend: dark grey would also match their text.
int pixelsNear(const QImage& image, const QColor& colour) {
    const QRect inside(130, 50, image.width() - 130 - 140, image.height() - 50 - 60);
    int n = 0;
    for (int y = inside.top(); y <= inside.bottom(); ++y) {
        for (int x = inside.left(); x <= inside.right(); ++x) {
            const QColor c = image.pixelColor(x, y);
            // The weight that explains the channel farthest from white best.
            const double wr = (255.0 - c.red()) / std::max(1, 255 - colour.red());
            const double wg = (255.0 - c.green()) / std::max(1, 255 - colour.green());
            const double wb = (255.0 - c.blue()) / std::max(1, 255 - colour.blue());
            const double w = std::max({wr, wg, wb});
            if (w < 1.0 / 3.0 || w > 1.05) continue;
            const auto blend = [w](int channel) { return 255.0 - w * (255.0 - channel); };
            if (std::abs(blend(colour.red()) - c.red()) <= 12 &&
                std::abs(blend(colour.green()) - c.green()) <= 12 &&
                std::abs(blend(colour.blue()) - c.blue()) <= 12) {
                ++n;
            }
        }
    }
    return n;
}

struct PlotCase {
    const char* plot;
    const char* yLabel;  ///< text the picture must hold
};

/// The label of the plot's vertical axis, which a picture must carry as text.
const PlotCase kPlots[] = {{"contour", "y [mm]"},
                           {"velocity", "Velocity [mm/s]"},
                           {"acceleration", "Acceleration [mm/s²]"},
                           {"jerk", "Jerk [mm/s³]"}};

/// "PROJECT — Plot": the project's name (README), or without one its file's base name.
std::string titleOf(const std::string& project, const std::string& plot) {
    std::string base = nlohmann::json::parse(test::readFile(project)).value("name", "");
    if (base.empty()) {
        base = std::filesystem::path(project).filename().string();
        base = base.substr(0, base.size() - std::string(".cam.json").size());
    }
    std::string name = plot;
    name[0] = static_cast<char>(std::toupper(name[0]));
    return base + " — " + name;
}

/// Every picture format of one plot, of the example and of a cam of lines, arcs and Béziers the
/// other tests never drew.
class PlotPictures : public ::testing::TestWithParam<PlotCase> {};

TEST_P(PlotPictures, ThePngShowsTheCurvesInTheirColours) {
    const PlotCase& c = GetParam();
    for (const std::string& project : {kExample, test::dataPath("reference/spline-mix.cam.json")}) {
        test::TempDir dir;
        const std::string out = dir.file("plot.png");
        const auto r =
            test::runCli({"export", project, "--format", "png", "--plot", c.plot, "--out", out});
        ASSERT_EQ(r.exitCode, 0) << project << " " << c.plot << ": " << r.err;
        const QImage image(QString::fromStdString(out));
        ASSERT_FALSE(image.isNull()) << out;
        EXPECT_EQ(image.size(), QSize(1200, 800));
        if (std::string(c.plot) == "contour") {
            // Each segment in its colour (the spline mix has fewer than six segments).
            const int segments = project == kExample ? 6 : 3;
            for (int k = 0; k < segments; ++k) {
                EXPECT_GT(pixelsNear(image, segmentColor(k)), 150) << project << " segment " << k;
            }
        } else {
            for (int component = 0; component < 3; ++component) {
                EXPECT_GT(pixelsNear(image, componentColor(component)), 300)
                    << project << " " << c.plot << " component " << component;
            }
        }
    }
}

TEST_P(PlotPictures, ThePdfIsAVectorPageWithTitleCreatorAndText) {
    const PlotCase& c = GetParam();
    test::TempDir dir;
    const std::string out = dir.file("plot.pdf");
    const auto r =
        test::runCli({"export", kExample, "--format", "pdf", "--plot", c.plot, "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::vector<std::string> args{
        checker(), "pdf",     out,      "--title", titleOf(kExample, c.plot),
        "--size",  "842x595", "--text", c.yLabel};
    if (std::string(c.plot) == "contour") {
        args.insert(args.end(), {"--text", "x [mm]", "--equal-scales"});
    } else {
        args.insert(args.end(), {"--text", "φ [°]"});
    }
    const auto check = test::run(kPython, args);
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
}

TEST_P(PlotPictures, TheSvgHasItsSizeTitleAndText) {
    const PlotCase& c = GetParam();
    test::TempDir dir;
    const std::string out = dir.file("plot.svg");
    const auto r = test::runCli({"export", kExample, "--format", "svg", "--plot", c.plot, "--size",
                                 "900x700", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto check =
        test::run(kPython, {checker(), "svg", out, "--title", titleOf(kExample, c.plot), "--size",
                            "900x700", "--text", c.yLabel});
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
}

INSTANTIATE_TEST_SUITE_P(Plots, PlotPictures, ::testing::ValuesIn(kPlots), [](const auto& info) {
    std::string n = info.param.plot;
    n[0] = static_cast<char>(std::toupper(n[0]));
    return n;
});

TEST(PlotPictureContour, ASplineCamKeepsEqualScalesInThePdf) {
    test::TempDir dir;
    const std::string project = test::dataPath("reference/spline-offset.cam.json");
    const std::string out = dir.file("contour.pdf");
    const auto r =
        test::runCli({"export", project, "--format", "pdf", "--size", "600x900", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto check =
        test::run(kPython, {checker(), "pdf", out, "--title", titleOf(project, "contour"), "--size",
                            "600x900", "--text", "x [mm]", "--equal-scales"});
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
}

TEST(PlotPictureContour, AFormClosedCamShowsItsSecondCurve) {
    // The contour picture of a conjugate pair draws the second plate, and of a groove the
    // outer flank, as the profile's dark grey beside the coloured profile: far more such
    // pixels than the same disc closed by a spring (whose picture has none but the centres').
    const std::string disc =
        R"({"format": "camwright", "version": 1, "name": "Disc", "motion": {"period_s": 2},
          "contour": [{"type": "arc", "center": [5, 0], "radius": 30, "branch": "outer",
                       "phi_start": 0, "phi_end": 360}],
          "follower": {"type": "roller", "radius": 4, "offset": 3 CLOSURE}})";
    const auto grey = [&](const std::string& closure) {
        test::TempDir dir;
        std::string text = disc;
        text.replace(text.find("CLOSURE"), 7, closure);
        const std::string project = dir.file("disc.cam.json"), out = dir.file("plot.png");
        std::ofstream(project) << text;
        const auto r =
            test::runCli({"export", project, "--format", "png", "--plot", "contour", "--out", out});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        const QImage image(QString::fromStdString(out));
        EXPECT_FALSE(image.isNull());
        return image.isNull() ? 0 : pixelsNear(image, QColor(40, 40, 40));
    };
    const int spring = grey("");
    const int pair = grey(R"(, "closure": "conjugate", "conjugate_distance_mm": 80,
                             "conjugate_radius_mm": 5)");
    const int groove = grey(R"(, "closure": "groove", "groove_clearance_mm": 0.5)");
    EXPECT_GT(pair, spring + 500) << spring << " " << pair;
    EXPECT_GT(groove, spring + 500) << spring << " " << groove;
}

TEST(PlotPictureMachining, FeedAndAxisAccelerationNeedAMachiningSection) {
    test::TempDir dir;
    const std::string out = dir.file("feed.png");
    auto r = test::runCli({"export", kExample, "--format", "png", "--plot", "feed", "--out", out});
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("no machining section"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));

    const std::string machining = test::dataPath("app/six-lobe-machining.cam.json");
    for (const char* plot : {"feed", "axis-acceleration"}) {
        r = test::runCli({"export", machining, "--format", "png", "--plot", plot, "--out", out});
        ASSERT_EQ(r.exitCode, 0) << plot << ": " << r.err;
        const QImage image(QString::fromStdString(out));
        ASSERT_FALSE(image.isNull());
        // The feed curve is drawn dark grey; the axis accelerations in the legend's colours.
        const QColor curve =
            std::string(plot) == "feed" ? QColor(40, 40, 40) : QColor(31, 119, 180);
        EXPECT_GT(pixelsNear(image, curve), 300) << plot;
    }
}

TEST(PlotPictureFollower, ThePressureAngleNeedsAFollowerAndShowsTheLimitCrossed) {
    test::TempDir dir;
    const std::string out = dir.file("pressure.png");
    auto r = test::runCli(
        {"export", kExample, "--format", "png", "--plot", "pressure-angle", "--out", out});
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("no follower"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    // A swinging knife beyond its 45° limit in five ranges: the curve blue, those red.
    const std::string arm = test::dataPath("reference/followers/five-lobe-arm-knife.cam.json");
    r = test::runCli({"export", arm, "--format", "png", "--plot", "pressure-angle", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const QImage image(QString::fromStdString(out));
    ASSERT_FALSE(image.isNull());
    EXPECT_GT(pixelsNear(image, QColor(20, 90, 160)), 300);
    EXPECT_GT(pixelsNear(image, QColor(200, 30, 30)), 50);
}

TEST(PlotPictureFollower, TheMotionSheetIsOnePageOfTheFollowersFourPlots) {
    // A project naming a follower: `--plot motion` stacks its lift, velocity, acceleration
    // and jerk on one page (poppler reads each axis title as text), `--plot lift` draws the
    // lift alone.
    const std::string project = test::examplePath("synthesised-cycloidal-roller.cam.json");
    std::string base = nlohmann::json::parse(test::readFile(project)).value("name", "");
    if (base.empty()) base = "synthesised-cycloidal-roller";
    test::TempDir dir;
    const std::string pdf = dir.file("motion.pdf");
    auto r = test::runCli({"export", project, "--format", "pdf", "--plot", "motion", "--out", pdf});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto check = test::run(
        kPython,
        {checker(), "pdf", pdf, "--title", base + " — Lift, velocity, acceleration, jerk", "--size",
         "842x595", "--text", "Lift s [mm]", "--text", "Velocity v [mm/s]", "--text",
         "Acceleration a [mm/s²]", "--text", "Jerk j [mm/s³]", "--text", "φ [°]"});
    EXPECT_EQ(check.exitCode, 0) << check.out << check.err;
    const std::string png = dir.file("lift.png");
    r = test::runCli({"export", project, "--format", "png", "--plot", "lift", "--out", png});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const QImage image(QString::fromStdString(png));
    ASSERT_FALSE(image.isNull());
    EXPECT_GT(pixelsNear(image, componentColor(0)), 300);
}

TEST(PlotPictureArguments, EveryBadArgumentIsNamedAndNoFileIsLeft) {
    test::TempDir dir;
    const std::string out = dir.file("keep.png");
    {
        std::ofstream f(out);
        f << "the old file";
    }
    struct Case {
        std::vector<std::string> args;
        int exit;
        const char* says;
    };
    const Case cases[] = {
        {{"--format", "png", "--plot", "speed"}, 1, "--plot: unknown plot 'speed'"},
        {{"--format", "pdf", "--size", "10x10"}, 1, "--size"},
        {{"--format", "pdf", "--size", "axb"}, 1, "--size"},
        {{"--format", "png", "--plot", "jerk", "--tolerance", "0.1"}, 1, "--tolerance"},
        {{"--format", "svg", "--size", "800x600"}, 1, "--size: is not an option of --format svg"},
        {{"--format", "png", "--plot", "feed"}, 3, "no machining section"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"export", kExample};
        args.insert(args.end(), c.args.begin(), c.args.end());
        args.insert(args.end(), {"--out", out});
        const auto r = test::runCli(args);
        EXPECT_EQ(r.exitCode, c.exit) << c.says << ": " << r.err;
        EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
        EXPECT_EQ(test::readFile(out), "the old file") << c.says;
    }
    const auto missing = test::runCli(
        {"export", kExample, "--format", "png", "--out", dir.file("no/such/folder.png")});
    EXPECT_EQ(missing.exitCode, 2) << missing.err;
    EXPECT_NE(missing.err.find("no/such/folder.png"), std::string::npos) << missing.err;
    EXPECT_EQ(test::folderEntries(dir.path()).size(), 1u);  // only keep.png: no temporary left
}

TEST(PlotPictureArguments, WithoutTheAppTheCliSaysWhereItLooked) {
    test::TempDir dir;
    const std::string out = dir.file("x.png");
    const auto r = test::run("/usr/bin/env", {"CAMWRIGHT_APP=/nonexistent/camwright", CAMWRIGHT_CLI,
                                              "export", kExample, "--format", "png", "--out", out});
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_NE(r.err.find("/nonexistent/camwright"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(PlotPictureArguments, TheAppAloneRefusesWhatItCannotDraw) {
    test::TempDir dir;
    const std::string out = dir.file("x.png");
    auto r = test::run(CAMWRIGHT_APP, {"--export-plot", "velocity", "--out", out});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("PROJECT"), std::string::npos) << r.err;
    r = test::run(CAMWRIGHT_APP,
                  {"--export-plot", "velocity", "--out", dir.file("x.gif"), kExample});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("--format"), std::string::npos) << r.err;
    r = test::run(CAMWRIGHT_APP, {"--export-plot", "velocity", "--out", out,
                                  test::dataPath("invalid/nope.cam.json")});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_FALSE(std::filesystem::exists(out));
    // Only Qt's own words about the environment are quiet: the run says nothing else.
    r = test::run(CAMWRIGHT_APP, {"--export-plot", "jerk", "--out", out, kExample});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
}

/// The window's own picture of a plot: drawn at another size than on screen, the contour
/// keeps equal scales, and the view on screen is left exactly as it was.
TEST(PlotPictureInWindow, APictureLeavesThePlotOnScreenAsItWas) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(QString::fromStdString(kExample)).isEmpty());
    window.resize(1200, 800);
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    QCustomPlot* contour = window.plotWidget(PlotKind::Contour);
    QCustomPlot* velocity = window.plotWidget(PlotKind::Velocity);
    const QCPRange cx = contour->xAxis->range(), cy = contour->yAxis->range();
    const QRect viewport = contour->viewport();
    const int rows = contour->plotLayout()->rowCount();
    const bool tickLabels = velocity->xAxis->tickLabels();
    const QString label = velocity->xAxis->label();

    QString problem;
    const QByteArray png =
        window.plotPicture(PlotKind::Contour, PictureFormat::Png, QSize(500, 900), &problem);
    ASSERT_FALSE(png.isEmpty()) << problem.toStdString();
    EXPECT_FALSE(
        window.plotPicture(PlotKind::Velocity, PictureFormat::Pdf, {}, &problem).isEmpty());
    EXPECT_EQ(contour->xAxis->range(), cx);
    EXPECT_EQ(contour->yAxis->range(), cy);
    EXPECT_EQ(contour->viewport(), viewport);
    EXPECT_EQ(contour->plotLayout()->rowCount(), rows);
    EXPECT_EQ(velocity->xAxis->tickLabels(), tickLabels);
    EXPECT_EQ(velocity->xAxis->label(), label);
    QImage image;
    ASSERT_TRUE(image.loadFromData(png, "PNG"));
    EXPECT_EQ(image.size(), QSize(500, 900));

    // No machining section: the machining plots cannot be drawn, and say why.
    EXPECT_TRUE(window.plotPicture(PlotKind::Feed, PictureFormat::Png, {}, &problem).isEmpty());
    EXPECT_TRUE(problem.contains("machining section")) << problem.toStdString();
}

}  // namespace
}  // namespace cam
