// The main window when a computation is huge: a turn of ten million samples fits in bounded
// memory.

#include <gtest/gtest.h>

#include <QDir>
#include <QImage>
#include <QLabel>
#include <QTemporaryDir>
#include <fstream>
#include <new>

#include "app_test_support.h"
#include "engine/compute_engine.h"
#include "io/project_json.h"
#include "mainwindow.h"
#include "models/arc_table_model.h"
#include "views/contour_view.h"
#include "views/kinematics_plots.h"

namespace cam {
namespace {

const QString kExample = QString::fromStdString(test::examplePath("six-lobe-arc-cam.cam.json"));

TEST(ScreenshotCommand, ATenMillionSampleTurnFitsInAGigabyteAndAHalf) {
    // Before, the whole turn and its plot data were kept: 2.6 GB at its peak, and std::terminate
    // when an allocation failed. Now big turns are sampled in chunks and only bounded
    // envelopes are kept: the app draws it within an address-space limit of 1.5 GB.
    QTemporaryDir dir;
    Project p = test::loadExample();
    p.samplesPerTurn = kMaxSamplesPerTurn;
    const std::string project = dir.filePath("big.cam.json").toStdString();
    std::ofstream(project) << serializeProject(p);
    const QString png = dir.filePath("big.png");
    const auto run = test::run("/usr/bin/prlimit",
                               {"--as=1500000000", "--", CAMWRIGHT_APP, "--screenshot",
                                png.toStdString(), "--size", "900x600", project},
                               120);
    EXPECT_EQ(run.signal, 0) << run.err;
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(QImage(png).size(), QSize(900, 600));
}

}  // namespace
}  // namespace cam
