// Issue 27: free text in the pictures of the plots and in what camwright-cli writes when the
// project has no name and its file's name stands in. Every title of the hostile-name corpus
// (tests/hostile_names.h) goes into an SVG and a PDF picture; hostile file names go through
// camwright-cli into every export that carries a name. tests/reference/check_free_text.py
// reads them all (expat, rsvg-convert, pdfinfo, Python's csv, the IEC 61131-3 rules, rs274).

#include <gtest/gtest.h>

#include <qcustomplot.h>
#include <QDir>
#include <QFile>
#include <QSettings>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>

#include "app_test_support.h"
#include "export/plot_picture.h"
#include "hostile_names.h"

namespace cam {
namespace {

namespace fs = std::filesystem;
TEST(HostileNames, EveryPlotPictureTitledWithAHostileNameIsValid) {
    QCustomPlot plot;
    plot.addGraph();
    plot.graph(0)->setData({0.0, 1.0, 2.0}, {0.0, 1.0, 0.5});
    plot.rescaleAxes();
    const test::TempDir dir;
    const auto names = test::hostileNames();
    for (std::size_t i = 0; i < names.size(); ++i) {
        SCOPED_TRACE(names[i].kind);
        PictureText text;
        text.title =
            QString::fromUtf8(names[i].text.data(), static_cast<qsizetype>(names[i].text.size())) +
            " — Velocity";
        for (PictureFormat format : {PictureFormat::Svg, PictureFormat::Pdf}) {
            const QByteArray bytes = renderPlotPicture(plot, format, QSize(600, 400), text, {});
            ASSERT_FALSE(bytes.isEmpty());
            QFile file(QString::fromStdString(
                dir.file(std::to_string(i) + "." + pictureSuffix(format).toStdString())));
            ASSERT_TRUE(file.open(QIODevice::WriteOnly));
            file.write(bytes);
        }
    }
    EXPECT_TRUE(test::exportsAreValid(dir.path().string(), 2 * names.size()));
}

TEST(HostileNames, AnAmpersandInTheTitleReadsBackAsItself) {
    // Escaped, not dropped: the title an XML reader gets is the one given.
    QCustomPlot plot;
    PictureText text;
    text.title = "Cams & Co. <1> \"2\"";
    const QByteArray svg = renderPlotPicture(plot, PictureFormat::Svg, QSize(300, 200), text, {});
    EXPECT_TRUE(svg.contains("<title>Cams &amp; Co. &lt;1&gt; &quot;2&quot;</title>"))
        << svg.left(600).toStdString();
    EXPECT_EQ(svg.count("<title>"), 1);
}

/// The six-lobe example without its name, written to `path`: the file's name stands in.
void writeNameless(const std::string& path) {
    nlohmann::json project = nlohmann::json::parse(test::readFile(test::kExample));
    project.erase("name");
    test::writeText(path, project.dump(2));
}

/// Sets an environment variable for the lifetime of this object.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : m_name(name) {
        if (const char* old = std::getenv(name)) m_old = old;
        ::setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (m_old) {
            ::setenv(m_name, m_old->c_str(), 1);
        } else {
            ::unsetenv(m_name);
        }
    }

private:
    const char* m_name;
    std::optional<std::string> m_old;
};

TEST(HostileNames, AFileNameStandingInForTheProjectsNameBreaksNoExport) {
    // The probe's "Cams & Co.cam.json" gave an SVG plot that xmllint, expat and rsvg-convert
    // refuse; a line break in a file name injected rows into the cam table.
    const test::TempDir dir;
    const fs::path out = dir.path() / "out";
    fs::create_directory(out);
    const std::vector<std::string> files{"Cams & Co", "cam\n=1+1,@x\r(M30", "\xff\xfe bad",
                                         "END_VAR"};
    for (std::size_t i = 0; i < files.size(); ++i) {
        const std::string project = dir.file(files[i] + ".cam.json");
        writeNameless(project);
        const std::string stem = (out / std::to_string(i)).string();
        const std::vector<std::vector<std::string>> exports{
            {"--format", "svg", "--plot", "velocity", "--out", stem + ".velocity.svg"},
            {"--format", "pdf", "--plot", "velocity", "--out", stem + ".velocity.pdf"},
            {"--format", "svg", "--out", stem + ".drawing.svg"},
            {"--format", "camtable", "--out", stem + ".camtable.csv"},
            {"--format", "camtable", "--dialect", "codesys", "--out", stem + ".codesys.st"},
            {"--format", "gcode", "--tool-radius", "3", "--out", stem + ".program.ngc"},
        };
        for (const auto& options : exports) {
            std::vector<std::string> args{"export", project};
            args.insert(args.end(), options.begin(), options.end());
            const auto r = test::runCli(args);
            EXPECT_EQ(r.exitCode, 0) << files[i] << " " << options[1] << ": " << r.err;
        }
    }
    // A picture whose own file name is not UTF-8 either lands where it was asked to.
    const std::string odd = (out / "\xff\xfe.velocity.svg").string();
    const auto r = test::runCli({"export", dir.file(files[2] + ".cam.json"), "--format", "svg",
                                 "--plot", "velocity", "--out", odd});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(odd));
    EXPECT_TRUE(test::exportsAreValid(out.string(), 6 * files.size() + 1));
}

TEST(HostileNames, AHeadlessPictureLeavesTheUsersSettingsAlone) {
    // camwright-cli's pictures (and `camwright --export-plot`, `--screenshot`) added the
    // project to the desktop app's recent files.
    const test::TempDir dir;
    const ScopedEnv config("XDG_CONFIG_HOME", dir.file("config"));
    const ScopedEnv data("XDG_DATA_HOME", dir.file("data"));
    for (const char* format : {"png", "pdf", "svg"}) {
        const auto r = test::runCli({"export", test::kExample, "--format", format, "--plot",
                                     "velocity", "--out", dir.file(std::string("v.") + format)});
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    // Nothing written where the app keeps its settings or its recovery copies.
    EXPECT_FALSE(fs::exists(dir.file("config"))) << test::folderEntries(dir.path()).size();
    EXPECT_FALSE(fs::exists(dir.file("data")));
}

}  // namespace
}  // namespace cam
