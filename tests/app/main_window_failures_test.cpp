// The main window when a computation fails or is huge: the failure is a message, the app
// carries on, and a turn of ten million samples fits in bounded memory.

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
#include "models/segment_table_model.h"
#include "views/contour_view.h"
#include "views/kinematics_plots.h"
#include "views/plot_data.h"

namespace cam {
namespace {

using test::kExampleFile;

/// Stands for a computation that runs out of memory in the worker.
class OutOfMemory : public PlotDataPreparer {
public:
    PreparedPlotDataPtr prepare(const ComputeResult&, const std::atomic<bool>&) const override {
        throw std::bad_alloc();
    }
    PreparedPlotDataPtr prepareTiming(const TimingOutcome&) const override { return nullptr; }
};

TEST(MainWindow, AFailedComputationIsReportedAndTheAppCarriesOn) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    auto* computeLabel = window.findChild<QLabel*>("computeLabel");
    ASSERT_NE(computeLabel, nullptr);

    window.engine()->setPlotDataPreparer(std::make_shared<OutOfMemory>());
    SegmentTableModel* model = window.tableModel();
    ASSERT_TRUE(model->setData(model->index(1, SegmentTableModel::Radius), 8.2, Qt::EditRole));
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    EXPECT_TRUE(window.engine()->latestResult()->failed());
    EXPECT_TRUE(computeLabel->text().contains("out of memory"))
        << computeLabel->text().toStdString();
    EXPECT_TRUE(window.plots()->staleReason().contains("out of memory"));
    EXPECT_TRUE(window.contourView()->staleReason().contains("out of memory"));

    // The next computation works again and replaces the message.
    window.engine()->setPlotDataPreparer(std::make_shared<QcpPlotDataPreparer>());
    window.document()->undoStack()->undo();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    EXPECT_TRUE(window.engine()->latestResult()->ok());
    EXPECT_TRUE(computeLabel->text().contains("samples computed"))
        << computeLabel->text().toStdString();
    EXPECT_TRUE(window.plots()->staleReason().isEmpty());
    EXPECT_TRUE(window.contourView()->staleReason().isEmpty());
}

TEST(ScreenshotCommand, ATenMillionSampleTurnFitsInAGigabyteAndAHalf) {
    // Before, the whole turn and its plot data were kept: 2.6 GB at its peak, and std::terminate
    // when an allocation failed. Now big turns are sampled in chunks and only bounded
    // envelopes are kept: the app draws it within an address-space limit of 1.5 GB.
    if (test::kSanitized) GTEST_SKIP() << "AddressSanitizer cannot run under an address limit";
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
