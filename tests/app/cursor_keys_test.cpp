// The cursor goes where the designer tells it (issue 31, point 2): a time or an angle typed into
// the State at Cursor readout, Left/Right by one sample of the turn, Shift+Left/Right to the
// previous or next joint, Home and End — with real key events in the real window. The expected
// instants are written out from the project file: the six-lobe cam turns once in T = 0.4 s, so
// angle φ is at t = φ/360°·T (turning counter-clockwise) or (360° − φ)/360°·T (clockwise),
// and its joints are the phi_start of its segments.

#include <gtest/gtest.h>

#include <qcustomplot.h>
#include <QFile>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <vector>

#include "app_test_support.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "views/kinematics_plots.h"
#include "views/state_readout.h"
#include "widgets/number_spin_box.h"

namespace cam {
namespace {

constexpr double kPeriod = 0.4;

/// The six-lobe cam's joints (deg): the phi_start of every segment but the first (0°, the
/// joint of the last segment with the first, is one too).
std::vector<double> jointAngles() {
    std::vector<double> angles;
    for (const SegmentSpec& s : test::loadExample().contour) angles.push_back(s.phiStartDeg);
    std::sort(angles.begin(), angles.end());
    return angles;
}

bool openExample(MainWindow& w, const QString& path) {
    if (!w.loadFile(path).isEmpty()) return false;
    w.show();
    return w.waitForCurrentResult(20000) && QTest::qWaitForWindowExposed(&w);
}

TEST(CursorKeys, ATypedTimeOrAngleIsWhereTheCursorGoes) {
    MainWindow window;
    ASSERT_TRUE(openExample(window, test::kExampleFile));
    window.setCursorTime(0.0);
    StateReadout* readout = window.readout();
    ASSERT_TRUE(readout->timeBox()->isEnabled());

    test::typeInto(readout->timeBox(), "0.05");
    EXPECT_NEAR(window.cursorTime(), 0.05, 1e-12);
    EXPECT_NEAR(test::readoutValue(window, "φ"), 360.0 * 0.05 / kPeriod, 1e-6);

    test::typeInto(readout->angleBox(), "100");
    EXPECT_NEAR(window.cursorTime(), 100.0 / 360.0 * kPeriod, 1e-12);
    EXPECT_NEAR(test::readoutValue(window, "t"), 100.0 / 360.0 * kPeriod, 1e-6);
    EXPECT_NEAR(readout->timeBox()->value(), 100.0 / 360.0 * kPeriod, 1e-9);

    // Past a turn wraps round; letters are refused by the box (the cursor stays).
    test::typeInto(readout->angleBox(), "370");
    EXPECT_NEAR(window.cursorTime(), 10.0 / 360.0 * kPeriod, 1e-12);
    test::typeInto(readout->timeBox(), "abc");
    EXPECT_NEAR(window.cursorTime(), 10.0 / 360.0 * kPeriod, 1e-12);
}

TEST(CursorKeys, ATypedAngleOnAClockwiseCamIsTheCamsOwnAngle) {
    // The same cam turning clockwise at 150 rpm (T = 0.4 s): φ on the cam is reached at
    // (360° − φ)/360°·T.
    QFile file(test::kExampleFile);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    QByteArray text = file.readAll();
    ASSERT_TRUE(text.contains("\"period_s\": 0.4"));
    text.replace("\"period_s\": 0.4", "\"rpm\": -150");
    QTemporaryDir dir;
    const QString path = dir.filePath("clockwise.cam.json");
    QFile out(path);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(text);
    out.close();
    MainWindow window;
    ASSERT_TRUE(openExample(window, path));
    test::typeInto(window.readout()->angleBox(), "90");
    EXPECT_NEAR(window.cursorTime(), 270.0 / 360.0 * kPeriod, 1e-12);
    EXPECT_NEAR(test::readoutValue(window, "φ"), 90.0, 1e-6);
}

TEST(CursorKeys, ArrowKeysInAPlotStepBySamplesAndJointsHomeAndEndGoToTheTurnsEnds) {
    MainWindow window;
    ASSERT_TRUE(openExample(window, test::kExampleFile));
    const ComputeResultPtr r = window.engine()->latestResult();
    ASSERT_GT(r->sampleCount, 0u);
    const double dt = kPeriod / static_cast<double>(r->sampleCount);
    QCustomPlot* plot = window.plots()->plot(0);
    QTest::mouseClick(plot, Qt::LeftButton, {}, plot->rect().center());
    ASSERT_TRUE(plot->hasFocus());

    QTest::keyClick(plot, Qt::Key_Home);
    EXPECT_NEAR(window.cursorTime(), 0.0, 1e-12);
    QTest::keyClick(plot, Qt::Key_Right);
    QTest::keyClick(plot, Qt::Key_Right);
    EXPECT_NEAR(window.cursorTime(), 2.0 * dt, 1e-12);
    for (int i = 0; i < 3; ++i) QTest::keyClick(plot, Qt::Key_Left);
    EXPECT_NEAR(window.cursorTime(), kPeriod - dt, 1e-12);  // round the turn's start
    QTest::keyClick(plot, Qt::Key_Home);
    QTest::keyClick(plot, Qt::Key_End);
    EXPECT_NEAR(window.cursorTime(), kPeriod - dt, 1e-12);

    // Shift+Right from the start visits every joint in order, then the start again.
    const std::vector<double> joints = jointAngles();
    ASSERT_GE(joints.size(), 3u);
    QTest::keyClick(plot, Qt::Key_Home);
    for (std::size_t k = 1; k <= joints.size(); ++k) {
        QTest::keyClick(plot, Qt::Key_Right, Qt::ShiftModifier);
        const double expected = k < joints.size() ? joints[k] / 360.0 * kPeriod : 0.0;
        EXPECT_NEAR(window.cursorTime(), expected, 1e-9) << "joint " << k;
    }
    QTest::keyClick(plot, Qt::Key_Left, Qt::ShiftModifier);
    EXPECT_NEAR(window.cursorTime(), joints.back() / 360.0 * kPeriod, 1e-9);
    // From between two joints, Shift+Left goes to the one before.
    window.setCursorTime(0.5 * (joints[1] + joints[2]) / 360.0 * kPeriod);
    QTest::keyClick(plot, Qt::Key_Left, Qt::ShiftModifier);
    EXPECT_NEAR(window.cursorTime(), joints[1] / 360.0 * kPeriod, 1e-9);
}

TEST(CursorKeys, TheSegmentTableKeepsItsArrowKeys) {
    MainWindow window;
    ASSERT_TRUE(openExample(window, test::kExampleFile));
    window.setCursorTime(0.1);
    auto* table = window.findChild<QTableView*>("segmentTable");
    ASSERT_NE(table, nullptr);
    table->setFocus();
    table->setCurrentIndex(table->model()->index(0, 1));
    QTest::keyClick(table, Qt::Key_Right);
    QTest::keyClick(table, Qt::Key_Home);
    EXPECT_NEAR(window.cursorTime(), 0.1, 1e-12);
    EXPECT_EQ(table->currentIndex().row(), 0);
}

}  // namespace
}  // namespace cam
