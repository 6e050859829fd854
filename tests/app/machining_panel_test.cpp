// The machining panel: the times it shows are the core's, computed in the worker, and its edits
// are undoable; a tool that cannot mill the contour is explained, not hidden.

#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QTest>
#include <cmath>

#include "app_test_support.h"
#include "document/commands.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "timing_reference.h"
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
        // A time has 6 significant digits (widgets/quantity_format.h).
        EXPECT_TRUE(window.machiningPanel()->timesText().contains(
            QLocale().toString(expected, 'g', 6) + " s"))
            << window.machiningPanel()->timesText().toStdString();
    }
    // And independently: the offset path built from the arcs' data and timed by the reference
    // of timing_reference.h (a phase-plane integration and the seed from math.md's wording).
    const std::vector<test::RefPiece> pieces =
        test::offsetArcContour(Contour::build(p).value(), p.machining->toolRadius);
    std::vector<bool> tangent(pieces.size(), true);
    tangent[0] = false;  // the path starts and ends at rest at φ = 0
    double length = 0.0;
    for (const test::RefPiece& piece : pieces) length += piece.length();
    EXPECT_NEAR(outcome->lengthMm, length, 1e-9);
    EXPECT_TRUE(test::relClose(outcome->timesS[0], test::seedReference(pieces, lim), 1e-9));
    EXPECT_TRUE(
        test::relClose(outcome->timesS[1], test::referenceExactStop(pieces, lim, 1e-3), 1e-5));
    EXPECT_TRUE(test::relClose(outcome->timesS[2],
                               test::referenceOptimal(pieces, tangent, lim, 1e-3), 1e-5));
    EXPECT_LT(outcome->timesS[2], outcome->timesS[1]);  // optimal beats exact stop here
    // The plotted profile (optimal) runs over the whole path and ends at rest.
    ASSERT_FALSE(outcome->profile.s.empty());
    EXPECT_NEAR(outcome->profile.s.back(), length, 1e-9);
    EXPECT_EQ(outcome->profile.speed.back(), 0.0);
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

// A tool too large for the notch's dwell arc (tests/data/timing/notch-dwell.cam.json: its
// concave corners would trim away all of the arc's offset; tool_path_test.cpp works out the
// limit, 1.374 mm): the panel names the segment and shows no times.
TEST(MachiningPanel, AnArcTrimmedAwayAtItsConcaveCornersIsExplained) {
    MainWindow window;
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::dataPath("timing/notch-dwell.cam.json")))
            .isEmpty());
    openPanel(window);
    ASSERT_TRUE(waitForTiming(window));
    const auto outcome = window.engine()->latestTiming();
    ASSERT_EQ(outcome->errors.size(), 1u);
    EXPECT_EQ(outcome->errors.front().location, "contour[2]");
    QStringList shown;
    for (const QLabel* label : window.machiningPanel()->findChildren<QLabel*>()) {
        if (label->text().startsWith("No machining time")) shown << label->text();
    }
    ASSERT_EQ(shown.size(), 1) << shown.join(" | ").toStdString();
    EXPECT_TRUE(shown.front().contains("Segment 2: the tool radius 3 mm is too large here"))
        << shown.front().toStdString();
    EXPECT_EQ(window.machiningPanel()->timesText(), "— · — · —");
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

/// The example with limits whose digits a 1- or 3-decimal editor would round away.
Project fineLimits() {
    Project p = loadProjectFile(kProject.toStdString()).value();
    p.machining->axisAccel = {500.25, 499.75, 200.0};
    p.machining->axisVmax = {123.456, 98.7654, 50.0};
    p.machining->feedMax = 12.345;
    p.machining->step = 0.0005;
    p.machining->toolRadius = 2.0;
    return p;
}

void typeAndEnter(QWidget* spin, const QString& text) {
    spin->setFocus();
    QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(spin, text);
    QTest::keyClick(spin, Qt::Key_Return);
}

TEST(MachiningPanelFields, AnEditChangesOnlyItsOwnField) {
    MainWindow window;
    const Project original = fineLimits();
    window.document()->reset(original, {});
    openPanel(window);
    QApplication::setActiveWindow(&window);
    auto* tool = window.machiningPanel()->findChild<QDoubleSpinBox*>("toolRadiusSpinBox");
    ASSERT_NE(tool, nullptr);
    typeAndEnter(tool, "2.5");
    MachiningSpec expected = *original.machining;
    expected.toolRadius = 2.5;
    EXPECT_EQ(*window.document()->project().machining, expected);  // 500.25, 12.345, 0.0005 kept
    EXPECT_EQ(window.document()->undoStack()->count(), 1);
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project(), original);
    EXPECT_EQ(tool->value(), 2.0);
    window.document()->undoStack()->redo();
    EXPECT_EQ(*window.document()->project().machining, expected);

    // The Z acceleration to "none" removes only that axis; the velocity limits stay as they are.
    auto* z = window.machiningPanel()->findChild<QDoubleSpinBox*>("accelZSpinBox");
    ASSERT_NE(z, nullptr);
    typeAndEnter(z, "0");
    expected.axisAccel = {500.25, 499.75};
    EXPECT_EQ(*window.document()->project().machining, expected);
    EXPECT_EQ(z->text(), "none");
}

// Issue 27 point 7: the panel's Z "none" leaves z unlimited. The panel times the contour offset
// by the tool, a path in the plane, so z's limit cannot matter: every time equals the one the
// core gives with the slowest z limit there is (1e-6 mm/s²), finite and positive, and the
// plotted profile of every method is finite. (A path that moved along z would be refused by the
// core, checked in core_tests TimingHostile.AnAxisThePathMovesAlong….)
TEST(MachiningPanelFields, WithoutAZLimitEveryTimeAndProfileIsFinite) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kProject).isEmpty());
    openPanel(window);
    QApplication::setActiveWindow(&window);
    auto* z = window.machiningPanel()->findChild<QDoubleSpinBox*>("accelZSpinBox");
    ASSERT_NE(z, nullptr);
    typeAndEnter(z, "0");
    ASSERT_EQ(z->text(), "none");
    ASSERT_EQ(window.document()->project().machining->axisAccel.size(), 2u);
    const Project p = loadProjectFile(kProject.toStdString()).value();
    const ToolPath path =
        toolPathFromContour(Contour::build(p).value(), p.machining->toolRadius).value();
    MachineLimits slowest = limitsFromProject(*p.machining);
    slowest.accel[2] = 1e-6;
    const TimingMethod methods[] = {TimingMethod::Seed, TimingMethod::ExactStop,
                                    TimingMethod::Optimal};
    auto* plotted = window.machiningPanel()->findChild<QComboBox*>("plotMethodComboBox");
    ASSERT_NE(plotted, nullptr);
    for (int m = 0; m < 3; ++m) {
        SCOPED_TRACE(m);
        plotted->setCurrentIndex(m);
        ASSERT_TRUE(waitForTiming(window));
        const auto outcome = window.engine()->latestTiming();
        ASSERT_TRUE(outcome->errors.empty()) << diagnosticsText(outcome->errors).toStdString();
        EXPECT_TRUE(std::isinf(outcome->limits.accel[2]));
        for (int k = 0; k < 3; ++k) {
            const double t = outcome->timesS[static_cast<std::size_t>(k)];
            EXPECT_TRUE(std::isfinite(t) && t > 0.0) << t;
            EXPECT_EQ(t, machiningTime(path, slowest, methods[k]).value().timeS) << k;
        }
        const TimingProfile& profile = outcome->profile;
        ASSERT_FALSE(profile.s.empty());
        for (std::size_t k = 0; k < profile.s.size(); ++k) {
            ASSERT_TRUE(std::isfinite(profile.s[k]) && std::isfinite(profile.speed[k]) &&
                        profile.accel[k].allFinite())
                << k;
        }
    }
}

TEST(MachiningPanelFields, EnterOnEveryUnchangedFieldChangesNothing) {
    MainWindow window;
    const Project original = fineLimits();
    window.document()->reset(original, {});
    openPanel(window);
    QApplication::setActiveWindow(&window);
    const std::string before = serializeProject(original);
    int fields = 0;
    for (auto* spin : window.machiningPanel()->findChildren<QDoubleSpinBox*>()) {
        spin->setFocus();
        QTest::keyClick(spin, Qt::Key_Return);
        spin->clearFocus();
        ++fields;
    }
    EXPECT_EQ(fields, 9);
    EXPECT_EQ(window.document()->undoStack()->count(), 0);
    EXPECT_EQ(serializeProject(window.document()->project()), before);
    // What the fields show: readable, and the value behind each is exact.
    auto* feed = window.machiningPanel()->findChild<QDoubleSpinBox*>("feedSpinBox");
    EXPECT_EQ(feed->text(), "12.345 mm/s");
    EXPECT_EQ(window.machiningPanel()->findChild<QDoubleSpinBox*>("seedStepSpinBox")->text(),
              "0.0005 mm");
}

}  // namespace
}  // namespace cam
