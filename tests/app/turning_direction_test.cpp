// The turning direction in the window (issue 31, point 3): the Follower dock's Turning picture of
// cam, follower line, offset and turning arrow, which is the setting (a click turns the cam round),
// driven with real keys. The file keeps the direction as the sign of the speed (project-format.md);
// a period has none, so turning the six-lobe cam (period 0.4 s) clockwise writes the same speed as
// −150 rpm.

#include <gtest/gtest.h>

#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QTest>
#include <QUndoStack>

#include "app_test_support.h"
#include "common/angles.h"
#include "document/project_document.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "views/turning_picture.h"

namespace cam {
namespace {

TEST(TurningDirection, ClockwiseIsOneUndoStepAndTheSameSpeedTurnedRound) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    window.show();
    window.findChild<QDockWidget*>("followerDock")->show();
    window.findChild<QDockWidget*>("followerDock")->raise();
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    auto* picture = window.findChild<TurningPicture*>("turningPicture");
    ASSERT_NE(picture, nullptr);
    TurningPicture* direction = picture;
    EXPECT_FALSE(direction->isChecked());
    EXPECT_FALSE(picture->clockwise());
    const int steps = window.document()->undoStack()->count();

    direction->setFocus();
    QTest::keyClick(direction, Qt::Key_Space);
    const MotionSpec& m = window.document()->project().motion;
    EXPECT_EQ(m.unit, SpeedUnit::Rpm);
    EXPECT_NEAR(m.value, -60.0 / 0.4, 1e-12);
    EXPECT_EQ(window.document()->undoStack()->count(), steps + 1);
    EXPECT_TRUE(picture->clockwise());
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    EXPECT_NEAR(window.engine()->latestResult()->omega, -kTwoPi / 0.4, 1e-9);

    // Back counter-clockwise: +150 rpm; undo twice: the period again.
    QTest::mouseClick(direction, Qt::LeftButton);
    EXPECT_NEAR(window.document()->project().motion.value, 150.0, 1e-12);
    EXPECT_FALSE(picture->clockwise());
    window.document()->undoStack()->undo();
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project().motion.unit, SpeedUnit::PeriodS);
    EXPECT_EQ(window.document()->project().motion.value, 0.4);
    EXPECT_FALSE(direction->isChecked());
    EXPECT_TRUE(direction->toolTip().contains("counter-clockwise"));
    EXPECT_TRUE(window.findChild<QLabel*>("turningText")->text().startsWith("counter-clockwise"));
}

TEST(TurningDirection, TheOffsetIsExplainedInWordsAndInThePicture) {
    // A roller offset 6 mm on a cam turning clockwise: the picture's tooltip says which way
    // the offset lies and which phase it helps; the Offset box speaks no spec notation.
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
    EXPECT_TRUE(picture->clockwise());
    EXPECT_TRUE(picture->toolTip().contains("clockwise")) << picture->toolTip().toStdString();
    EXPECT_TRUE(picture->toolTip().contains("to the left")) << picture->toolTip().toStdString();
    EXPECT_FALSE(offset->toolTip().contains("along n")) << offset->toolTip().toStdString();
    EXPECT_TRUE(offset->toolTip().contains("left of its direction"));
}

}  // namespace
}  // namespace cam
