// The machining panel: the times it shows are the core's, computed in the worker, and its edits
// are undoable; a tool that cannot mill the contour is explained, not hidden.

#include <gtest/gtest.h>

#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QPushButton>

#include "app_test_support.h"
#include "document/commands.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "views/machining_panel.h"

namespace cam {
namespace {

const QString kProject = QString::fromStdString(test::dataPath("app/six-lobe-machining.cam.json"));

bool waitForTiming(MainWindow& w) {
    return test::processEventsUntil([&] {
        const auto& t = w.engine()->latestTiming();
        return t && t->generation == w.engine()->latestGeneration();
    });
}

void openPanel(MainWindow& w) {
    w.show();
    w.findChild<QDockWidget*>("machiningDock")->show();
}

TEST(MachiningPanel, ShowsTheThreeTimesTheCoreComputes) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kProject).isEmpty());
    openPanel(window);
    ASSERT_TRUE(waitForTiming(window));
    const auto outcome = window.engine()->latestTiming();
    ASSERT_TRUE(outcome->errors.empty());
    // The same computation done here directly, from the file.
    const Project p = loadProjectFile(kProject.toStdString()).value();
    const ToolPath path =
        toolPathFromContour(Contour::build(p).value(), p.machining->toolRadius).value();
    const MachineLimits lim = limitsFromProject(*p.machining);
    const TimingMethod methods[] = {TimingMethod::Seed, TimingMethod::ExactStop,
                                    TimingMethod::Optimal};
    for (int m = 0; m < 3; ++m) {
        const double expected = machiningTime(path, lim, methods[m]).value().timeS;
        EXPECT_DOUBLE_EQ(outcome->timesS[static_cast<std::size_t>(m)], expected) << m;
        EXPECT_TRUE(
            window.machiningPanel()->timesText().contains(QLocale().toString(expected, 'f', 4)))
            << window.machiningPanel()->timesText().toStdString();
    }
    EXPECT_LT(outcome->timesS[2], outcome->timesS[1]);  // optimal beats exact stop here
    EXPECT_FALSE(outcome->profile.s.empty());
}

TEST(MachiningPanel, EditingTheToolRadiusIsUndoableAndRecomputes) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kProject).isEmpty());
    openPanel(window);
    ASSERT_TRUE(waitForTiming(window));
    const double before = window.engine()->latestTiming()->lengthMm;
    const auto spins = window.machiningPanel()->findChildren<QDoubleSpinBox*>();
    QDoubleSpinBox* tool = nullptr;
    for (auto* s : spins) {
        if (s->toolTip().startsWith("Radius of the tool")) tool = s;
    }
    ASSERT_NE(tool, nullptr);
    tool->setValue(1.0);  // from 2 mm
    EXPECT_DOUBLE_EQ(window.document()->project().machining->toolRadius, 1.0);
    ASSERT_TRUE(waitForTiming(window));
    // The offset path is 2π·(change of radius) shorter.
    EXPECT_NEAR(window.engine()->latestTiming()->lengthMm, before - 2 * M_PI * 1.0, 1e-6);
    window.document()->undoStack()->undo();
    EXPECT_DOUBLE_EQ(window.document()->project().machining->toolRadius, 2.0);
    EXPECT_DOUBLE_EQ(tool->value(), 2.0);
}

TEST(MachiningPanel, AProjectWithoutLimitsOffersToAddThem) {
    MainWindow window;
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::examplePath("six-lobe-arc-cam.cam.json")))
            .isEmpty());
    openPanel(window);
    auto* add = window.machiningPanel()->findChild<QPushButton*>("addMachiningButton");
    ASSERT_NE(add, nullptr);
    EXPECT_TRUE(add->isVisible());
    add->click();
    ASSERT_TRUE(window.document()->project().machining.has_value());
    EXPECT_FALSE(add->isVisible());
    ASSERT_TRUE(waitForTiming(window));
    EXPECT_TRUE(window.engine()->latestTiming()->errors.empty());
    window.document()->undoStack()->undo();
    EXPECT_FALSE(window.document()->project().machining.has_value());
}

TEST(MachiningPanel, ATooWideToolIsExplained) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kProject).isEmpty());
    openPanel(window);
    MachiningSpec wide = *window.document()->project().machining;
    wide.toolRadius = 6.0;  // wider than the 4.84 mm notches
    window.document()->undoStack()->push(new SetMachining(window.document(), wide));
    ASSERT_TRUE(waitForTiming(window));
    ASSERT_FALSE(window.engine()->latestTiming()->errors.empty());
    EXPECT_EQ(window.engine()->latestTiming()->errors.front().location, "contour[0]");
}

}  // namespace
}  // namespace cam
