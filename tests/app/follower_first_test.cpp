// The follower first (issue 31, point 1): when the project names a follower, the four big plots
// are its lift, velocity, acceleration and jerk (an arm's swing in degrees), the State at Cursor
// reads out its state, and the contour's polar kinematics are one choice away (View ▸ Polar
// Kinematics, Ctrl+Shift+P, pressed here as a real key). The numbers are checked without the
// follower's code:
// - the synthesised cycloidal roller's rise (h = 10 mm over 120° at 60 rpm: T_r = 1/3 s) is the
//   cycloidal law's closed form s = h(x − sin 2πx / 2π), v = h/T_r (1 − cos 2πx), x = t/T_r,
//   to the arcs' fitting tolerance (1 µm) and what it costs the velocity;
// - each plotted velocity, acceleration and jerk is the slope of the plotted curve above it
//   (central differences of the plotted points), so a unit (rad for °) or a sign wrong fails;
// - the readout's lift and velocity at a typed instant are the closed form there.

#include <gtest/gtest.h>

#include <qcustomplot.h>
#include <QAction>
#include <QBuffer>
#include <QImage>
#include <QSettings>
#include <QTest>
#include <cmath>

#include "app_test_support.h"
#include "common/angles.h"
#include "engine/compute_engine.h"
#include "export/plot_picture.h"
#include "mainwindow.h"
#include "views/kinematics_plots.h"
#include "views/state_readout.h"
#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

constexpr const char* kCycloidal = "synthesised-cycloidal-roller.cam.json";
constexpr const char* kArm = "swinging-arm-cam.cam.json";

bool openExample(MainWindow& w, const char* name) {
    if (!w.loadFile(QString::fromStdString(test::examplePath(name))).isEmpty()) return false;
    w.show();
    return w.waitForCurrentResult(20000) && QTest::qWaitForWindowExposed(&w);
}

/// The cycloidal rise of the example: lift (mm) and velocity (mm/s) at t (s) within the rise.
struct Cycloidal {
    static constexpr double h = 10.0, rise = 1.0 / 3.0;
    static double s(double t) {
        const double x = t / rise;
        return h * (x - std::sin(kTwoPi * x) / kTwoPi);
    }
    static double v(double t) { return h / rise * (1.0 - std::cos(kTwoPi * t / rise)); }
};

/// The value of a graph's curve at x, linearly between its points.
double valueAt(const QCPGraph* graph, double x) {
    const auto data = graph->data();
    auto it = data->findBegin(x, false);
    if (it == data->constEnd() || it == data->constBegin()) return std::nan("");
    const auto before = it - 1;
    const double f = (x - before->key) / (it->key - before->key);
    return before->value + f * (it->value - before->value);
}

/// The plotted `derivative` against the slope of the plotted `curve` (x in seconds) inside
/// (lo, hi), at every point where the curve is smooth: its slopes to the left and to the right
/// agree within 2 % (an arc table's acceleration jumps at every joint, so its velocity has a
/// kink there and its jerk no finite value). The largest difference, relative to the largest
/// magnitude of the derivative; `compared` counts the points checked.
double slopeMismatch(const QCPGraph* curve, const QCPGraph* derivative, double lo, double hi,
                     int* compared = nullptr) {
    double worst = 0.0, largest = 0.0;
    int count = 0;
    const auto c = curve->data();
    for (auto it = c->constBegin() + 1; it + 1 != c->constEnd(); ++it) {
        largest = std::max(largest, std::abs(valueAt(derivative, it->key)));
        if (it->key <= lo || it->key >= hi) continue;
        const auto before = it - 1, after = it + 1;
        const double left = (it->value - before->value) / (it->key - before->key);
        const double right = (after->value - it->value) / (after->key - it->key);
        if (std::abs(left - right) > 0.02 * std::max(std::abs(left), std::abs(right))) continue;
        worst = std::max(worst, std::abs(0.5 * (left + right) - valueAt(derivative, it->key)));
        ++count;
    }
    if (compared) *compared = count;
    return worst / largest;
}

QAction* polarAction(MainWindow& w) { return w.findChild<QAction*>("actionPolarKinematics"); }

TEST(FollowerFirst, TheMainPlotsAreTheFollowersLiftVelocityAccelerationAndJerk) {
    QSettings().remove("view/polarKinematics");
    MainWindow window;
    ASSERT_TRUE(openExample(window, kCycloidal));
    window.findChild<QAction*>("actionAxisTime")->setChecked(true);  // x in seconds
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    KinematicsPlots* plots = window.plots();
    ASSERT_TRUE(plots->showsFollower());
    const QCPGraph* lift =
        plots->plot(KinematicsPlots::kLiftPlot)->graph(KinematicsPlots::kFollowerGraph);
    const QCPGraph* velocity = plots->plot(0)->graph(KinematicsPlots::kFollowerGraph);
    const QCPGraph* acceleration = plots->plot(1)->graph(KinematicsPlots::kFollowerGraph);
    const QCPGraph* jerk = plots->plot(2)->graph(KinematicsPlots::kFollowerGraph);
    EXPECT_EQ(plots->plot(KinematicsPlots::kLiftPlot)->yAxis->label(), "Lift s [mm]");
    EXPECT_EQ(plots->plot(0)->yAxis->label(), "Velocity v [mm/s]");
    // The polar curves are gone from the plots and their legends.
    EXPECT_EQ(plots->plot(0)->graph(0)->dataCount(), 0);
    EXPECT_FALSE(plots->plot(0)->legend->hasItemWithPlottable(plots->plot(0)->graph(0)));
    EXPECT_TRUE(plots->plot(0)->legend->hasItemWithPlottable(velocity));
    EXPECT_EQ(qobject_cast<QCPPlottableLegendItem*>(plots->plot(0)->legend->item(0))->plottable(),
              velocity);  // v before the law

    // The rise against the cycloidal law's closed form.
    double liftError = 0.0, velocityError = 0.0;
    for (double t = 0.01; t < Cycloidal::rise - 0.005; t += 0.01) {
        liftError = std::max(liftError, std::abs(valueAt(lift, t) - Cycloidal::s(t)));
        velocityError = std::max(velocityError, std::abs(valueAt(velocity, t) - Cycloidal::v(t)));
    }
    // Linear interpolation between 3601 points over the turn: (Δt)²/8 · |s''| ≤ 4e-5 mm; the
    // arcs within 1 µm of the profile.
    EXPECT_LT(liftError, 5e-3);
    EXPECT_GT(liftError, 0.0);
    EXPECT_LT(velocityError, 0.01 * 2.0 * Cycloidal::h / Cycloidal::rise);
    // The dwell at 10 mm from 120° to 180°, back to 0 after 300°.
    EXPECT_NEAR(valueAt(lift, 0.45), 10.0, 5e-3);
    EXPECT_NEAR(valueAt(lift, 0.9), 0.0, 5e-3);

    // Each curve is the slope of the one above it, in the rise and in the return.
    for (auto [lo, hi] : {std::pair{0.005, 0.33}, std::pair{0.505, 0.83}}) {
        int compared[3] = {};
        EXPECT_LT(slopeMismatch(lift, velocity, lo, hi, &compared[0]), 2e-3) << lo;
        EXPECT_LT(slopeMismatch(velocity, acceleration, lo, hi, &compared[1]), 2e-2) << lo;
        EXPECT_LT(slopeMismatch(acceleration, jerk, lo, hi, &compared[2]), 5e-2) << lo;
        for (int c : compared) EXPECT_GT(c, 300) << lo;  // of some 1,000 points in the range
    }

    // The readout: the follower's state at a typed instant.
    window.setCursorTime(0.0);
    test::typeInto(window.readout()->timeBox(), "0.1");
    EXPECT_NEAR(test::readoutValue(window, "s"), Cycloidal::s(0.1), 5e-3);
    EXPECT_NEAR(test::readoutValue(window, "v"), Cycloidal::v(0.1), 0.01 * Cycloidal::v(0.1));
    EXPECT_TRUE(std::isfinite(test::readoutValue(window, "α")));
    EXPECT_TRUE(std::isnan(test::readoutValue(window, "v_r")));
    window.findChild<QAction*>("actionAxisTime")->setChecked(false);
}

TEST(FollowerFirst, RoundOffReadsZeroAndAStraightStretchAnInfiniteRadius) {
    // A velocity of −2.3·10⁻⁶ mm/s beside 500 mm/s in the turn (4.6·10⁻⁹ of it) is the
    // round-off of a dwell; −2.3·10⁻⁶ where the turn's largest is 10⁻⁵ is a velocity.
    StateReadout readout;
    KinematicState s;
    s.t = 0.1;
    s.phi = 0.5;
    FollowerState f;
    f.pressureAngle = 0.1;
    f.rhoProfile = std::numeric_limits<double>::infinity();
    const auto row = [&](const QString& name) {
        for (const QString& line : readout.text().split('\n')) {
            if (line.startsWith(name + " ")) return line.mid(name.size() + 1);
        }
        return QString();
    };
    readout.setFollowerState(s, f, {3.0, -2.3e-6, 1e-3, 5.0}, false, {10.0, 500.0, 1e4, 1e6});
    EXPECT_EQ(row("v"), "0 mm/s");
    EXPECT_EQ(row("s"), "3 mm");
    EXPECT_EQ(row("ρ"), "∞ (straight)");
    readout.setFollowerState(s, f, {3.0, -2.3e-6, 1e-3, 5.0}, false, {10.0, 1e-5, 1e4, 1e6});
    EXPECT_EQ(row("v"), formatQuantity(DisplayQuantity::Velocity, -2.3e-6));
    EXPECT_NE(row("v"), "0 mm/s");
}

TEST(FollowerFirst, CtrlShiftPShowsThePolarKinematicsAndBackAndIsRemembered) {
    QSettings().remove("view/polarKinematics");
    MainWindow window;
    ASSERT_TRUE(openExample(window, kCycloidal));
    KinematicsPlots* plots = window.plots();
    ASSERT_TRUE(plots->showsFollower());
    window.setCursorTime(0.1);
    ASSERT_FALSE(std::isnan(test::readoutValue(window, "s")));

    plots->plot(0)->setFocus();
    QTest::keyClick(window.windowHandle(), Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_TRUE(polarAction(window)->isChecked());
    EXPECT_FALSE(plots->showsFollower());
    EXPECT_EQ(plots->plot(KinematicsPlots::kLiftPlot)->yAxis->label(), "Radius r [mm]");
    EXPECT_GT(plots->plot(0)->graph(0)->dataCount(), 0);
    EXPECT_EQ(plots->plot(0)->graph(KinematicsPlots::kFollowerGraph)->dataCount(), 0);
    // The readout follows: r and v_r along the ray, no lift.
    const ComputeResultPtr r = window.engine()->latestResult();
    const KinematicState state = stateAt(*r->contour, r->omega, window.cursorTime());
    EXPECT_NEAR(test::readoutValue(window, "r"), state.polar.r, 1e-6 * state.polar.r);
    EXPECT_TRUE(std::isnan(test::readoutValue(window, "s")));
    EXPECT_TRUE(QSettings().value("view/polarKinematics").toBool());
    // The legend reads v_r, v_φ, |v| first, then the design's law, whatever was shown before.
    QCPLegend* legend = plots->plot(0)->legend;
    ASSERT_GE(legend->itemCount(), 4);
    EXPECT_EQ(qobject_cast<QCPPlottableLegendItem*>(legend->item(0))->plottable(),
              plots->plot(0)->graph(0));
    EXPECT_EQ(qobject_cast<QCPPlottableLegendItem*>(legend->item(3))->plottable(),
              plots->plot(0)->graph(KinematicsPlots::kCurvesPerPlot));

    {
        // A new window starts in the polar view the user chose.
        MainWindow second;
        ASSERT_TRUE(openExample(second, kCycloidal));
        EXPECT_FALSE(second.plots()->showsFollower());
    }
    window.activateWindow();
    plots->plot(0)->setFocus();
    QTest::keyClick(window.windowHandle(), Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
    EXPECT_FALSE(polarAction(window)->isChecked());
    EXPECT_TRUE(plots->showsFollower());
    EXPECT_FALSE(std::isnan(test::readoutValue(window, "s")));
    QSettings().remove("view/polarKinematics");
}

TEST(FollowerFirst, AProjectWithoutAFollowerShowsThePolarKinematics) {
    QSettings().remove("view/polarKinematics");
    MainWindow window;
    ASSERT_TRUE(openExample(window, "six-lobe-arc-cam.cam.json"));
    EXPECT_FALSE(window.plots()->showsFollower());
    EXPECT_EQ(window.plots()->plot(0)->yAxis->label(), "Velocity [mm/s]");
    window.setCursorTime(0.05);
    EXPECT_FALSE(std::isnan(test::readoutValue(window, "v_r")));
}

TEST(FollowerFirst, AnArmsSwingIsPlottedInDegreesAndItsSpeedIsTheSlope) {
    // The example's arm swings 15° away from the cam in a cycloidal rise over 120° at 60 rpm.
    QSettings().remove("view/polarKinematics");
    MainWindow window;
    ASSERT_TRUE(openExample(window, kArm));
    window.findChild<QAction*>("actionAxisTime")->setChecked(true);
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    KinematicsPlots* plots = window.plots();
    ASSERT_TRUE(plots->showsFollower());
    EXPECT_EQ(plots->plot(KinematicsPlots::kLiftPlot)->yAxis->label(), "Arm swing ψ [°]");
    EXPECT_EQ(plots->plot(0)->yAxis->label(), "Arm speed ψ' [°/s]");
    const QCPGraph* swing =
        plots->plot(KinematicsPlots::kLiftPlot)->graph(KinematicsPlots::kFollowerGraph);
    const QCPGraph* speed = plots->plot(0)->graph(KinematicsPlots::kFollowerGraph);
    const double h = 15.0, rise = 1.0 / 3.0;
    for (double t = 0.05; t < 0.33; t += 0.05) {
        const double x = t / rise;
        EXPECT_NEAR(valueAt(swing, t), h * (x - std::sin(kTwoPi * x) / kTwoPi), 0.01) << t;
        EXPECT_NEAR(valueAt(speed, t), h / rise * (1.0 - std::cos(kTwoPi * x)), 0.5) << t;
    }
    EXPECT_LT(slopeMismatch(swing, speed, 0.005, 0.33), 2e-3);
    window.setCursorTime(0.1);
    const double x = 0.1 / rise;
    EXPECT_NEAR(test::readoutValue(window, "ψ"), h * (x - std::sin(kTwoPi * x) / kTwoPi), 0.01);
    window.findChild<QAction*>("actionAxisTime")->setChecked(false);
}

TEST(FollowerFirst, TheMotionSheetStacksTheFourPlotsWithoutTheCursor) {
    QSettings().remove("view/polarKinematics");
    MainWindow window;
    ASSERT_TRUE(openExample(window, kCycloidal));
    window.setCursorTime(0.2);
    QString problem;
    const QByteArray svg =
        window.plotPicture(PlotKind::Motion, PictureFormat::Svg, QSize(800, 1000), &problem);
    ASSERT_FALSE(svg.isEmpty()) << problem.toStdString();
    // Each plot's title, once.
    for (const char* title :
         {"Lift s [mm]", "Velocity v [mm/s]", "Acceleration a [mm/s²]", "Jerk j [mm/s³]"}) {
        EXPECT_EQ(QString::fromUtf8(svg).count(QString::fromUtf8(title)), 1) << title;
    }
    // The cursor line (dashed, grey 60, 60, 60) is for the screen only.
    EXPECT_FALSE(svg.contains("#3c3c3c")) << "the cursor line is in the picture";
    // On screen it is still there afterwards.
    int cursors = 0;
    for (int i = 0; i < window.plots()->plot(0)->itemCount(); ++i) {
        cursors += window.plots()->plot(0)->item(i)->visible() &&
                   window.plots()->plot(0)->item(i)->property(kNotInPictures).toBool();
    }
    EXPECT_GE(cursors, 1);

    const QByteArray png =
        window.plotPicture(PlotKind::Motion, PictureFormat::Png, QSize(800, 1000), &problem);
    QImage image;
    ASSERT_TRUE(image.loadFromData(png, "PNG"));
    EXPECT_EQ(image.size(), QSize(800, 1000));
    // Four plots down the sheet, sharing its height 2 : 3 : 3 : 3 (the window's): in each
    // band some pixels are the follower's line.
    const QColor line =
        window.plots()->plot(0)->graph(KinematicsPlots::kFollowerGraph)->pen().color();
    const int tops[] = {0, 181, 453, 725, 1000};
    for (int band = 0; band < 4; ++band) {
        int hits = 0;
        for (int y = tops[band] + 20; y < tops[band + 1] - 20; ++y) {
            for (int x = 0; x < 800; ++x) hits += image.pixelColor(x, y) == line;
        }
        EXPECT_GT(hits, 50) << "band " << band;
    }
}

}  // namespace
}  // namespace cam
