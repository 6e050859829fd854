// The Forces dock, driven as a designer drives it: typing the mass into its box is one undo
// step computed in the worker; the plots show the forces of the edited project, each point
// checked here against math.md §9 written out from the follower's own state (load = m·ä + c·v̇
// + k·s + F0, F_n = load / cos α, the Hertz stress in the textbook's arrangement); a speed
// beyond the jump speed shades the lift-off ranges and turns the lines red; a click goes to an
// angle; the material picker sets E and ν in one step; the State at Cursor shows the forces.

#include <gtest/gtest.h>

#include <qcustomplot.h>
#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTest>
#include <cmath>

#include "app_test_support.h"
#include "common/angles.h"
#include "document/commands.h"
#include "document/project_document.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "project/dynamics.h"
#include "views/contour_view.h"
#include "views/forces_panel.h"
#include "views/kinematics_plots.h"
#include "views/state_readout.h"
#include "views/stress_overlay.h"
#include "widgets/number_spin_box.h"

namespace cam {
namespace {

constexpr const char* kSpringCam = "spring-loaded-roller-cam.cam.json";

bool openWithForces(MainWindow& w, const char* name) {
    if (!w.loadFile(QString::fromStdString(test::examplePath(name))).isEmpty()) return false;
    w.show();
    w.findChild<QDockWidget*>("forcesDock")->show();
    return w.waitForCurrentResult(20000);
}

/// The spring-loaded example at 1.05 times its jump speed, computed: where it leaves the cam.
std::vector<std::array<double, 2>> springCamBeyondItsJumpSpeed(MainWindow& window) {
    EXPECT_TRUE(openWithForces(window, kSpringCam));
    const double jump = window.engine()->latestResult()->forces->summary.jumpSpeed;
    window.document()->undoStack()->push(
        new SetMotion(window.document(), MotionSpec{SpeedUnit::OmegaRadS, 1.05 * jump}));
    EXPECT_TRUE(window.waitForCurrentResult(20000));
    const auto liftOff = window.engine()->latestResult()->forces->summary.liftOff;
    EXPECT_FALSE(liftOff.empty());
    return liftOff;
}

/// math.md §9 for the example's translating roller (c 5 N·s/m, k 3 N/mm, F0 40 N, no external
/// force), from the follower's state: s in mm from its lowest, v in mm/s, a in mm/s².
double loadOf(const FollowerState& f, double mass, double lowest) {
    return mass * f.a * 1e-3 + 5.0 * f.v * 1e-3 + 3.0 * (f.s - lowest) + 40.0;
}

TEST(ForcesPanel, TypingAMassIsOneUndoStepAndThePlotsShowItsForces) {
    MainWindow window;
    ASSERT_TRUE(openWithForces(window, kSpringCam));
    ForcesPanel* panel = window.forcesPanel();
    ASSERT_TRUE(window.findChild<QDockWidget*>("forcesDock")->isVisible());
    NumberSpinBox* mass = panel->valueBox(DynamicsKey::MassKg);
    ASSERT_EQ(mass->value(), 0.8);
    const int steps = window.document()->undoStack()->count();

    test::typeInto(mass, "1.6");
    ASSERT_EQ(window.document()->project().dynamics->values[0], 1.6);
    EXPECT_EQ(window.document()->undoStack()->count(), steps + 1);
    EXPECT_EQ(window.document()->undoStack()->undoText(), "Change dynamics");
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    const ComputeResultPtr r = window.engine()->latestResult();
    ASSERT_TRUE(r->valid());
    ASSERT_NE(r->forces, nullptr);
    EXPECT_EQ(r->forces->model.mass, 1.6);

    // Every 9th point of the plots against math.md §9 from the follower's state there.
    const FollowerModel& follower = *r->follower;
    const std::size_t n = ComputeResult::kFollowerCurvePoints;
    double lowest = 1e300;
    for (std::size_t k = 0; k < n; ++k) {
        lowest = std::min(lowest, follower.at(kTwoPi * k / n, r->omega).s);
    }
    const auto load = panel->forcePlot()->graph(2)->data();
    const auto normal = panel->forcePlot()->graph(0)->data();
    const auto torque = panel->torquePlot()->graph(0)->data();
    const auto stress = panel->stressPlot()->graph(0)->data();
    ASSERT_EQ(normal->size(), static_cast<int>(n + 1));
    ASSERT_EQ(panel->forcePlot()->graph(1)->dataCount(), static_cast<int>(n + 1));  // the law's
    // 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2: nodular cast iron and steel.
    const double soft = (1.0 - 0.275 * 0.275) / 169000.0 + (1.0 - 0.09) / 210000.0;
    for (std::size_t k = 0; k < n; k += 9) {
        const double phi = r->omega * r->period * static_cast<double>(k) / n;
        const FollowerState f = follower.at(phi, r->omega);
        const double expected = loadOf(f, 1.6, lowest);
        const auto i = static_cast<int>(k);
        EXPECT_NEAR(normal->at(i)->key, radToDeg(phi), 1e-9);
        EXPECT_NEAR(load->at(i)->value, expected, 1e-6) << k;
        const double fn = expected / std::cos(f.pressureAngle);
        EXPECT_NEAR(normal->at(i)->value, fn, 1e-6) << k;
        // The power balance: T·ω = load · v.
        EXPECT_NEAR(torque->at(i)->value * r->omega, expected * f.v * 1e-3, 1e-6) << k;
        const double curvature = 1.0 / f.rhoProfile + 1.0 / 8.0;
        EXPECT_NEAR(stress->at(i)->value, std::sqrt(fn * curvature / (kPi * 10.0 * soft)), 1e-6)
            << k;
    }
    // The allowable stress, dashed, where the file has it.
    EXPECT_TRUE(panel->allowableLine()->visible());
    EXPECT_EQ(panel->allowableLine()->point1->coords().y(), 900.0);
    EXPECT_EQ(panel->allowableLine()->pen().style(), Qt::DashLine);
    // It shares the kinematics plots' x axis.
    window.plots()->plot(0)->xAxis->setRange(100.0, 140.0);
    EXPECT_EQ(panel->torquePlot()->xAxis->range().lower, 100.0);
    EXPECT_EQ(panel->stressPlot()->xAxis->range().upper, 140.0);

    // Undo: 0.8 kg again, in the document and in the box.
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project().dynamics->values[0], 0.8);
    EXPECT_EQ(mass->value(), 0.8);
    window.document()->undoStack()->redo();
    EXPECT_EQ(mass->value(), 1.6);
}

TEST(ForcesPanel, BeyondTheJumpSpeedTheLiftOffIsShadedRedAndAClickGoesThere) {
    MainWindow window;
    ASSERT_TRUE(openWithForces(window, kSpringCam));
    ForcesPanel* panel = window.forcesPanel();
    EXPECT_EQ(panel->problemCount(), 0);
    EXPECT_TRUE(panel->liftOffShades().empty());
    const QStringList calm = panel->resultLines();
    ASSERT_FALSE(calm.isEmpty());
    EXPECT_TRUE(calm[0].contains("stays on the cam")) << calm[0].toStdString();
    // The jump speed the panel names: at 1.05 times it the follower leaves the cam.
    const double jump = window.engine()->latestResult()->forces->summary.jumpSpeed;
    ASSERT_TRUE(std::isfinite(jump));
    window.document()->undoStack()->push(
        new SetMotion(window.document(), MotionSpec{SpeedUnit::OmegaRadS, 1.05 * jump}));
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    const ComputeResultPtr r = window.engine()->latestResult();
    ASSERT_TRUE(r->valid());
    const ForceSummary& s = r->forces->summary;
    ASSERT_FALSE(s.liftOff.empty());
    ASSERT_EQ(panel->liftOffShades().size(), s.liftOff.size());
    // Where the first range is shaded, the load (math.md §9 from the follower's own state) is
    // negative inside and positive just outside.
    const FollowerModel& follower = *r->follower;
    double lowest = 1e300;
    for (int k = 0; k < 3600; ++k) lowest = std::min(lowest, follower.at(kTwoPi * k / 3600, 1).s);
    const auto [from, to] = s.liftOff.front();
    QCPItemRect* shade = panel->liftOffShades().front();
    EXPECT_NEAR(shade->topLeft->coords().x(), radToDeg(from), 1e-9);
    EXPECT_NEAR(shade->bottomRight->coords().x(), radToDeg(to), 1e-9);
    EXPECT_LT(loadOf(follower.at(0.5 * (from + to), r->omega), 0.8, lowest), 0.0);
    EXPECT_GT(loadOf(follower.at(from - 1e-3, r->omega), 0.8, lowest), 0.0);
    EXPECT_GT(loadOf(follower.at(to + 1e-3, r->omega), 0.8, lowest), 0.0);
    // Each range, the jump speed and the preload (which no longer holds the follower) are
    // failures, in red.
    const QStringList lines = panel->resultLines();
    EXPECT_EQ(lines.filter("leaves the cam").size(), static_cast<qsizetype>(s.liftOff.size()));
    EXPECT_EQ(panel->problemCount(), static_cast<int>(s.liftOff.size()) + 2);
    EXPECT_GT(s.minPreload, 40.0);
    auto* list = panel->findChild<QListWidget*>("forceResultsList");
    EXPECT_EQ(list->item(0)->foreground().color(), QColor(180, 0, 0));
    // A click on the first range puts the cursor at its start.
    window.findChild<QDockWidget*>("forcesDock")->raise();
    QTest::qWait(50);
    const QRect rect = list->visualItemRect(list->item(0));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, rect.center());
    EXPECT_NEAR(window.cursorTime(), from / r->omega, 1e-9);
    // The State at Cursor shows the forces there: where the follower just leaves the cam the
    // load has come down to nothing.
    const QString readout = window.readout()->text();
    EXPECT_TRUE(readout.contains("F_n 0 N")) << readout.toStdString();
    EXPECT_TRUE(readout.contains("N·m")) << readout.toStdString();
}

TEST(ForcesPanel, TheMaterialPickerSetsBothValuesInOneStep) {
    MainWindow window;
    ASSERT_TRUE(openWithForces(window, kSpringCam));
    ForcesPanel* panel = window.forcesPanel();
    QComboBox* follower = panel->materialBox(1);
    EXPECT_EQ(follower->currentText(), "Steel");
    const int pa6 = follower->findData("pa6");
    ASSERT_GT(pa6, 0);
    const int steps = window.document()->undoStack()->count();
    follower->setCurrentIndex(pa6);
    emit follower->activated(pa6);
    const DynamicsSpec& d = *window.document()->project().dynamics;
    EXPECT_EQ(d[DynamicsKey::FollowerModulusMpa], 3000.0);
    EXPECT_EQ(d[DynamicsKey::FollowerPoisson], 0.39);
    EXPECT_EQ(window.document()->undoStack()->count(), steps + 1);
    EXPECT_EQ(panel->valueBox(DynamicsKey::FollowerModulusMpa)->value(), 3000.0);
    window.document()->undoStack()->undo();
    EXPECT_EQ((*window.document()->project().dynamics)[DynamicsKey::FollowerModulusMpa], 210000.0);
    EXPECT_EQ(follower->currentText(), "Steel");
    // Typing a value of no material names none.
    test::typeInto(panel->valueBox(DynamicsKey::FollowerModulusMpa), "205000");
    EXPECT_EQ(follower->currentIndex(), 0);
    // Remove Dynamics takes the section out; undo brings it back whole.
    const DynamicsSpec before = *window.document()->project().dynamics;
    panel->findChild<QPushButton*>("removeDynamicsButton")->click();
    EXPECT_FALSE(window.document()->project().dynamics.has_value());
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    EXPECT_EQ(window.engine()->latestResult()->forces, nullptr);
    EXPECT_FALSE(panel->forcePlot()->isVisible());
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project().dynamics, before);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(ForcesPanel, TheContourIsColouredByContactStressOnDemand) {
    MainWindow window;
    ASSERT_TRUE(openWithForces(window, kSpringCam));
    auto* action = window.findChild<QAction*>("actionStressColours");
    ASSERT_NE(action, nullptr);
    action->setChecked(false);
    const StressOverlay& overlay = window.contourView()->stressOverlay();
    for (int i = 0; i < StressOverlay::kBands; ++i) EXPECT_FALSE(overlay.band(i)->visible());
    action->setChecked(true);
    // The scale runs up to the allowable 900 MPa; the largest stress, 181.5 MPa (the CLI's
    // max_contact_stress_MPa), falls in band ⌊181.5 / 900 · 12⌋ = 2, so bands 3 and up stay
    // empty, and every step of the turn is drawn in one of bands 0–2.
    EXPECT_EQ(overlay.top(), 900.0);
    EXPECT_TRUE(overlay.label().contains("900 MPa")) << overlay.label().toStdString();
    const ComputeResultPtr r = window.engine()->latestResult();
    const ForceCurves& f = *r->forces;
    int drawn = 0;
    for (int i = 0; i < StressOverlay::kBands; ++i) {
        EXPECT_TRUE(overlay.band(i)->visible());
        if (i >= 3) {
            EXPECT_EQ(overlay.band(i)->dataCount(), 0) << i;
        }
        for (int k = 0; k < overlay.band(i)->dataCount(); ++k) {
            drawn += std::isnan(overlay.band(i)->data()->at(k)->key) ? 0 : 1;
        }
    }
    EXPECT_GE(drawn, static_cast<int>(ComputeResult::kFollowerCurvePoints));
    // The coloured points are where the roller touches the profile: 8 mm from its centre, on
    // the line from the centre towards the cam (FollowerModel::at, not the overlay's data).
    const std::size_t n = ComputeResult::kFollowerCurvePoints;
    for (std::size_t k = 0; k < n; k += 97) {
        const double phi = r->omega * r->period * static_cast<double>(k) / n;
        const Eigen::Vector2d centre = r->follower->at(phi, r->omega).center;
        const Eigen::Vector2d contact(f.contactX[k], f.contactY[k]);
        EXPECT_NEAR((contact - centre).norm(), 8.0, 1e-9) << k;
        EXPECT_LT(contact.norm(), centre.norm()) << k;
    }
    action->setChecked(false);
    for (int i = 0; i < StressOverlay::kBands; ++i) EXPECT_FALSE(overlay.band(i)->visible());
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(ForcesPanel, CtrlZInTheBoxJustCommittedUndoesTheEditNotTheTyping) {
    // Under Xvfb: the mass typed and taken with Enter, the focus still in the box, Ctrl+Z went
    // to the line edit (which had nothing left to undo) instead of the window's Undo.
    MainWindow window;
    ASSERT_TRUE(openWithForces(window, kSpringCam));
    window.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
    NumberSpinBox* mass = window.forcesPanel()->valueBox(DynamicsKey::MassKg);
    test::typeInto(mass, "1.6");
    ASSERT_EQ(window.document()->project().dynamics->values[0], 1.6);
    ASSERT_TRUE(mass->hasFocus());
    QTest::keySequence(mass, QKeySequence::keyBindings(QKeySequence::Undo).first());
    EXPECT_EQ(window.document()->project().dynamics->values[0], 0.8);
    EXPECT_EQ(mass->value(), 0.8);
    QTest::keySequence(mass, QKeySequence::keyBindings(QKeySequence::Redo).first());
    EXPECT_EQ(window.document()->project().dynamics->values[0], 1.6);
    // While a text is typed and not taken, Ctrl+Z undoes the typing in the box alone.
    mass->selectAll();
    QTest::keyClicks(mass, "2");
    QTest::keySequence(mass, QKeySequence::keyBindings(QKeySequence::Undo).first());
    EXPECT_EQ(window.document()->project().dynamics->values[0], 1.6);
}

TEST(ForcesPanel, InAGrooveBeyondTheJumpSpeedTheRollerCrossesToTheOuterFlank) {
    // The spring-loaded example beyond its jump speed leaves the cam; the same cam grooved
    // never does: the outer flank takes the load in the same ranges (to the clearance's
    // effect, neglected), and the dock names the crossovers and the outer flank's stress.
    MainWindow window;
    std::vector<std::array<double, 2>> liftOff;
    ASSERT_NO_FATAL_FAILURE(liftOff = springCamBeyondItsJumpSpeed(window));
    FollowerSpec grooved = *window.document()->project().follower;
    grooved.closure = Closure::Groove;
    grooved.grooveClearance = 0.05;
    window.document()->undoStack()->push(new SetFollower(window.document(), grooved));
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    const ComputeResultPtr r = window.engine()->latestResult();
    ASSERT_TRUE(r->valid()) << (r->problems.empty() ? "" : r->problems.front().text());
    const ForceSummary& s = r->forces->summary;
    ASSERT_EQ(s.liftOff.size(), liftOff.size());
    for (std::size_t k = 0; k < liftOff.size(); ++k) {
        EXPECT_EQ(s.liftOff[k], liftOff[k]);  // the same motion and load: the same crossings
    }
    ForcesPanel* panel = window.forcesPanel();
    const QStringList lines = panel->resultLines();
    EXPECT_EQ(lines.filter("crosses to the outer flank").size(),
              static_cast<qsizetype>(liftOff.size()));
    EXPECT_EQ(lines.filter("leaves the cam").size(), 0);
    EXPECT_EQ(lines.filter("Jump speed").size(), 0);
    EXPECT_EQ(lines.filter("Least preload").size(), 0);
    ASSERT_TRUE(s.maxStressSecond && s.maxNormalSecond);
    EXPECT_EQ(lines.filter("Largest contact stress on the outer flank").size(), 1);
    EXPECT_EQ(lines.filter("Largest normal force on the inner flank").size(), 1);
    // Crossing is no failure: nothing is red unless a stress is beyond the allowable.
    EXPECT_EQ(panel->problemCount(), 0);
}

TEST(ForcesPanel, OnAConjugatePairBeyondTheJumpSpeedTheSecondRollerTakesTheLoad) {
    // The same cam as a conjugate pair: the second roller takes the load over in the ranges
    // the spring would lose it, and the dock names the handovers and the second plate's
    // stress, each roller's own.
    MainWindow window;
    std::vector<std::array<double, 2>> liftOff;
    ASSERT_NO_FATAL_FAILURE(liftOff = springCamBeyondItsJumpSpeed(window));
    FollowerSpec pair = *window.document()->project().follower;
    pair.closure = Closure::Conjugate;
    pair.conjugateDistance = 150.0;
    pair.conjugateRadius = pair.radius;
    window.document()->undoStack()->push(new SetFollower(window.document(), pair));
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    const ComputeResultPtr r = window.engine()->latestResult();
    ASSERT_TRUE(r->valid()) << (r->problems.empty() ? "" : r->problems.front().text());
    const ForceSummary& s = r->forces->summary;
    ASSERT_EQ(s.liftOff.size(), liftOff.size());
    for (std::size_t k = 0; k < liftOff.size(); ++k) EXPECT_EQ(s.liftOff[k], liftOff[k]);
    ForcesPanel* panel = window.forcesPanel();
    const QStringList lines = panel->resultLines();
    EXPECT_EQ(lines.filter("The second roller takes the load over").size(),
              static_cast<qsizetype>(liftOff.size()))
        << lines.join("\n").toStdString();
    EXPECT_EQ(lines.filter("leaves the cam").size(), 0);
    EXPECT_EQ(lines.filter("Jump speed").size(), 0);
    ASSERT_TRUE(s.maxNormalSecond);
    EXPECT_EQ(lines.filter("Largest normal force on the second roller").size(), 1);
    EXPECT_EQ(lines.filter("Largest normal force on the first roller").size(), 1);
    if (s.maxStressSecond) {
        EXPECT_EQ(lines.filter("Largest contact stress on the second plate").size(), 1);
    }
    // The second roller's normal force where it carries most is the load over its own
    // pressure angle (the core's ConjugatePoint), not the first roller's.
    const FollowerModel& first = *r->follower;
    const double at = *s.maxNormalSecondAt;
    const ConjugatePoint second = conjugatePoint(first, {150.0, pair.radius}, at);
    const ForcePoint f =
        forceAt(r->forces->model, forceMotion(first, first.at(at, r->omega)), r->omega);
    EXPECT_LT(f.load, 0.0);
    EXPECT_NEAR(*s.maxNormalSecond, -f.load / std::cos(second.pressureAngle),
                1e-9 * *s.maxNormalSecond);
    EXPECT_EQ(panel->problemCount(), 0);
    // Coloured by stress, the profile shows it where it acts: on the second plate, the second
    // roller's radius from its centre, while that roller carries; and no stroke jumps across
    // from one plate to the other (the steps are 0.1° apart: under a millimetre each).
    const ForceCurves& curves = *r->forces;
    const std::size_t n = ComputeResult::kFollowerCurvePoints;
    int onSecond = 0;
    for (std::size_t k = 0; k < n; k += 7) {
        const double phi = r->omega * r->period * static_cast<double>(k) / n;
        const Eigen::Vector2d contact(curves.contactX[k], curves.contactY[k]);
        const bool carries = curves.curves.normal[k] < 0.0;
        const Eigen::Vector2d centre = carries
                                           ? conjugatePoint(first, {150.0, pair.radius}, phi).centre
                                           : first.at(phi, r->omega).center;
        EXPECT_NEAR((contact - centre).norm(), pair.radius, 1e-9) << k;
        onSecond += carries ? 1 : 0;
    }
    EXPECT_GT(onSecond, 0);
    auto* action = window.findChild<QAction*>("actionStressColours");
    ASSERT_NE(action, nullptr);
    action->setChecked(true);
    const StressOverlay& overlay = window.contourView()->stressOverlay();
    double longest = 0.0;
    for (int i = 0; i < StressOverlay::kBands; ++i) {
        const QCPCurve* band = overlay.band(i);
        for (int k = 1; k < band->dataCount(); ++k) {
            const auto a = band->data()->at(k - 1);
            const auto b = band->data()->at(k);
            if (std::isnan(a->key) || std::isnan(b->key)) continue;
            longest = std::max(longest, std::hypot(b->key - a->key, b->value - a->value));
        }
    }
    EXPECT_LT(longest, 1.0);
}

}  // namespace
}  // namespace cam
