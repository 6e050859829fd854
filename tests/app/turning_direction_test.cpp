// The turning direction in the window (issue 31, point 3): the Follower dock's Turning picture of
// cam, follower line, offset and turning arrow, which is the setting (a click turns the cam round),
// driven with real keys. The file keeps the direction as the sign of the speed (project-format.md).
// The follower assembly turns by φ = ω·t in the cam's frame (math.md §7): for ω > 0 it goes
// counter-clockwise round the drawing, so under a follower that stands still the cam turns
// clockwise (turned clockwise by θ, the cam brings its point at angle θ under a follower on +x).
// A period has no sign and turns clockwise, so turning the six-lobe cam (period 0.4 s)
// counter-clockwise writes the same speed as −150 rpm.

#include <gtest/gtest.h>

#include <qcustomplot.h>
#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QTest>
#include <QUndoStack>
#include <cmath>

#include "app_test_support.h"
#include "common/angles.h"
#include "document/commands.h"
#include "document/project_document.h"
#include "engine/compute_engine.h"
#include "follower/follower.h"
#include "mainwindow.h"
#include "views/contour_view.h"
#include "views/turning_picture.h"

namespace cam {
namespace {

TEST(TurningDirection, TurningRoundIsOneUndoStepAndTheSameSpeedTurnedRound) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    window.show();
    window.findChild<QDockWidget*>("followerDock")->show();
    window.findChild<QDockWidget*>("followerDock")->raise();
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    auto* picture = window.findChild<TurningPicture*>("turningPicture");
    ASSERT_NE(picture, nullptr);
    TurningPicture* direction = picture;
    EXPECT_TRUE(direction->isChecked());
    EXPECT_TRUE(picture->clockwise());
    const int steps = window.document()->undoStack()->count();

    direction->setFocus();
    QTest::keyClick(direction, Qt::Key_Space);
    const MotionSpec& m = window.document()->project().motion;
    EXPECT_EQ(m.unit, SpeedUnit::Rpm);
    EXPECT_NEAR(m.value, -60.0 / 0.4, 1e-12);
    EXPECT_EQ(window.document()->undoStack()->count(), steps + 1);
    EXPECT_FALSE(picture->clockwise());
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    EXPECT_NEAR(window.engine()->latestResult()->omega, -kTwoPi / 0.4, 1e-9);

    EXPECT_TRUE(direction->toolTip().startsWith("The cam turns counter-clockwise"));
    EXPECT_TRUE(window.findChild<QLabel*>("turningText")->text().startsWith("counter-clockwise"));

    // Back clockwise: +150 rpm; undo twice: the period again.
    QTest::mouseClick(direction, Qt::LeftButton);
    EXPECT_NEAR(window.document()->project().motion.value, 150.0, 1e-12);
    EXPECT_TRUE(picture->clockwise());
    window.document()->undoStack()->undo();
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project().motion.unit, SpeedUnit::PeriodS);
    EXPECT_EQ(window.document()->project().motion.value, 0.4);
    EXPECT_TRUE(direction->isChecked());
    EXPECT_TRUE(direction->toolTip().startsWith("The cam turns clockwise"));
    EXPECT_TRUE(window.findChild<QLabel*>("turningText")->text().startsWith("clockwise"));
}

TEST(TurningDirection, TheOffsetIsExplainedInWordsAndInThePicture) {
    // A roller offset 6 mm on a cam turning counter-clockwise (a negative speed): the picture's
    // tooltip says which way the offset lies and which phase it helps; the Offset box speaks
    // no spec notation.
    MainWindow window;
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::examplePath("roller-lobe-cam.cam.json")))
            .isEmpty());
    window.show();
    auto* speed = window.findChild<QDoubleSpinBox*>("speedSpinBox");
    test::typeInto(speed, "-120");
    auto* offset = window.findChild<QDoubleSpinBox*>("followerOffsetSpinBox");
    ASSERT_NE(offset, nullptr);
    test::typeInto(offset, "6");
    EXPECT_EQ(window.document()->project().follower->offset, 6.0);
    auto* picture = window.findChild<TurningPicture*>("turningPicture");
    EXPECT_FALSE(picture->clockwise());
    EXPECT_TRUE(picture->toolTip().contains(
        "lowers the pressure angle of the rise when the cam turns clockwise and raises it when "
        "it turns counter-clockwise"))
        << picture->toolTip().toStdString();
    EXPECT_TRUE(picture->toolTip().contains("to the left")) << picture->toolTip().toStdString();
    EXPECT_FALSE(offset->toolTip().contains("along n")) << offset->toolTip().toStdString();
    EXPECT_TRUE(offset->toolTip().contains("left of its direction"));
}

TEST(TurningDirection, PlayTurnsTheCamUnderAFollowerThatStandsStill) {
    // Issue 31, point 3: Play turns the cam under the follower, as MechDesigner and DYNACAM
    // do; Play Turns the Cam off gives back the inversion (the follower goes round the cam).
    MainWindow window;
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::examplePath("roller-lobe-cam.cam.json")))
            .isEmpty());
    FollowerSpec offset = *window.document()->project().follower;
    offset.offset = 6.0;
    window.document()->undoStack()->push(new SetFollower(window.document(), offset));
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    auto* turnCam = window.findChild<QAction*>("actionPlayTurnsCam");
    ASSERT_NE(turnCam, nullptr);
    turnCam->setChecked(true);
    ContourView* view = window.contourView();
    const ComputeResultPtr result = window.engine()->latestResult();
    ASSERT_TRUE(result && result->follower);
    const double omega = result->omega;
    ASSERT_GT(omega, 0.0);
    const QCPRange xBefore = view->xAxis->range(), yBefore = view->yAxis->range();
    window.playAction()->trigger();
    EXPECT_TRUE(view->turning());
    // The turning cam stays in view: its farthest point, turned anywhere.
    double far = 0.0;
    for (int k = 0; k < static_cast<int>(window.document()->project().contour.size()); ++k) {
        const auto [first, count] = view->segmentRun(k);
        for (int i = first; i < first + count; ++i) {
            const auto p = view->segmentCurve(k)->data()->at(i);
            far = std::max(far, std::hypot(p->key, p->value));
        }
    }
    EXPECT_GT(far, 29.0);  // the lobe's top (r = 30 mm)
    EXPECT_TRUE(view->xAxis->range().contains(-far) && view->xAxis->range().contains(far));
    EXPECT_TRUE(view->yAxis->range().contains(-far) && view->yAxis->range().contains(far));
    window.playAction()->trigger();  // paused: the cam stands still, drawn as the file has it
    EXPECT_FALSE(view->turning());
    window.playAction()->trigger();
    ASSERT_TRUE(view->turning());
    for (const double deg : {30.0, 75.0, 200.0}) {
        const double phi = degToRad(deg);
        window.setCursorTime(phi / omega);
        // The cam is turned by −φ (clockwise for ω > 0): its point at φ is under the
        // follower, which stands on its line at φ = 0 — y = e, x = s (math.md §7: the
        // follower point is e·n + s·u, turned by φ in the cam's frame).
        EXPECT_NEAR(view->turnedBy(), -phi, 1e-9) << deg;
        const FollowerState st = result->follower->at(phi, omega);
        const ContourView::FollowerMarkers m = view->followerMarkers();
        ASSERT_TRUE(m.shown) << deg;
        EXPECT_NEAR(m.center.y(), 6.0, 1e-9) << deg;
        EXPECT_NEAR(m.center.x(), st.s, 1e-9) << deg;
        // The contact on the turned cam is the profile's point turned by −φ.
        EXPECT_NEAR(m.contact.x(),
                    std::cos(-phi) * st.contact.x() - std::sin(-phi) * st.contact.y(), 1e-9);
        EXPECT_NEAR(m.contact.y(),
                    std::sin(-phi) * st.contact.x() + std::cos(-phi) * st.contact.y(), 1e-9);
        // The drawn profile turned with it: segment 0's first point.
        const auto [first, count] = view->segmentRun(0);
        ASSERT_GT(count, 0);
        const auto p = view->segmentCurve(0)->data()->at(first);
        const double r0 =
            result->contour->evaluate(degToRad(window.document()->project().contour[0].phiStartDeg))
                .r;
        const double a0 = degToRad(window.document()->project().contour[0].phiStartDeg) - phi;
        EXPECT_NEAR(p->key, r0 * std::cos(a0), 1e-6) << deg;
        EXPECT_NEAR(p->value, r0 * std::sin(a0), 1e-6) << deg;
    }
    // The inversion, one choice away: the cam stands, the follower goes round it.
    turnCam->setChecked(false);
    EXPECT_FALSE(view->turning());
    EXPECT_EQ(view->turnedBy(), 0.0);
    const double phi = degToRad(200.0);
    const FollowerState st = result->follower->at(phi, omega);
    EXPECT_NEAR(view->followerMarkers().center.x(), st.center.x(), 1e-9);
    EXPECT_NEAR(view->followerMarkers().center.y(), st.center.y(), 1e-9);
    window.playAction()->trigger();
    // Stopped, the view is where it was before Play.
    EXPECT_NEAR(view->xAxis->range().lower, xBefore.lower, 1e-9);
    EXPECT_NEAR(view->xAxis->range().upper, xBefore.upper, 1e-9);
    EXPECT_NEAR(view->yAxis->range().lower, yBefore.lower, 1e-9);
    EXPECT_NEAR(view->yAxis->range().upper, yBefore.upper, 1e-9);
}

}  // namespace
}  // namespace cam
