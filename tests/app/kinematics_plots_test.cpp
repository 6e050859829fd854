// The kinematics plots as a user sees them: the time axis, the peaks of every lobe at any window
// size, breaks only where a quantity jumps, and a cursor that redraws only itself. Expected
// values come from the core (the sampled turn, the segments' one-sided limits, the analysis),
// never from the plotting path.

#include <gtest/gtest.h>

#include <QAction>
#include <QDockWidget>
#include <QImage>
#include <QScopeGuard>
#include <QSettings>
#include <QTest>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

#include "app_test_support.h"
#include "common/angles.h"
#include "document/commands.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "views/contour_view.h"
#include "views/kinematics_plots.h"
#include "views/state_readout.h"

#include <qcustomplot.h>

namespace cam {
namespace {

using test::kExampleFile;

/// The example's contour and speed, built from the file by the core alone.
struct Reference {
    Project project = test::loadExample();
    Contour contour = Contour::build(project).value();
    double omega = project.motion.omegaRadS();
    double period = kTwoPi / std::abs(omega);
};

std::vector<QCPGraphData> dataOf(const QCPGraph* graph) {
    return {graph->data()->constBegin(), graph->data()->constEnd()};
}

TEST(KinematicsPlots, TimeAxisActionPlotsTheCurvesOverTime) {
    const Reference ref;  // period 0.4 s
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    auto* action = window.findChild<QAction*>("actionAxisTime");
    ASSERT_NE(action, nullptr);
    ASSERT_FALSE(action->isChecked());

    const auto expectAxis = [&](double upper, double sampleStep, const char* what) {
        for (int p = 0; p < 3; ++p) {
            QCustomPlot* plot = window.plots()->plot(p);
            EXPECT_NEAR(plot->xAxis->range().lower, 0.0, 1e-12 * upper) << what << p;
            EXPECT_NEAR(plot->xAxis->range().upper, upper, 1e-12 * upper) << what << p;
            for (int c = 0; c < 3; ++c) {
                const auto data = dataOf(plot->graph(c));
                ASSERT_GT(data.size(), 3000u) << what << p << c;  // the whole turn, 3600 samples
                EXPECT_NEAR(data.front().key, 0.0, 1e-12 * upper) << what << p << c;
                EXPECT_NEAR(data.back().key, upper, 1e-12 * upper) << what << p << c;
                for (const QCPGraphData& d : data) {
                    ASSERT_GE(d.key, -1e-12 * upper) << what << p << c;
                    ASSERT_LE(d.key, upper * (1 + 1e-12)) << what << p << c;
                }
            }
        }
        // Not flat: |v| and v_r over the axis are the core's own states at those instants.
        const auto speed = dataOf(window.plots()->plot(0)->graph(2));
        const auto radial = dataOf(window.plots()->plot(0)->graph(0));
        double lo = 1e300, hi = -1e300;
        int compared = 0;
        for (std::size_t i = 0; i < speed.size(); ++i) {
            if (std::isnan(speed[i].value)) continue;
            lo = std::min(lo, speed[i].value);
            hi = std::max(hi, speed[i].value);
            // Points at a sample instant (not the exact joint points between them).
            const double k = speed[i].key / sampleStep;
            if (std::abs(k - std::round(k)) > 1e-6 || static_cast<long>(std::round(k)) % 37) {
                continue;
            }
            const double t = upper == 360.0 ? degToRad(speed[i].key) / ref.omega : speed[i].key;
            const KinematicState s = stateAt(ref.contour, ref.omega, t);
            EXPECT_NEAR(speed[i].value, s.motion.v, 1e-9 * s.motion.v) << what << " t=" << t;
            ++compared;
        }
        EXPECT_GT(compared, 50) << what;
        EXPECT_GT(hi - lo, 400.0) << what;               // |v| runs from 328 to 818 mm/s
        EXPECT_EQ(radial.size(), speed.size()) << what;  // no breaks: both are continuous
    };

    action->trigger();  // Ctrl+T
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    QCoreApplication::processEvents();
    EXPECT_EQ(window.engine()->latestResult()->axis, PlotAxis::Time);
    expectAxis(ref.period, ref.period / 3600, "time axis, plot ");

    action->trigger();  // and back
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    QCoreApplication::processEvents();
    EXPECT_EQ(window.engine()->latestResult()->axis, PlotAxis::Angle);
    expectAxis(360.0, 0.1, "angle axis, plot ");
}

/// The topmost row, in a column range of an image, with a pixel of the |a| curve: dark grey
/// (40, 40, 40), antialiased to a lighter grey where a 1-px line straddles two columns; the
/// grid (200, 200, 200) and the blue, red and orange lines are not neutral dark greys.
int topOfDarkCurve(const QImage& image, int x0, int x1, int y0, int y1) {
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const QColor c = image.pixelColor(x, y);
            const int mx = std::max({c.red(), c.green(), c.blue()});
            const int mn = std::min({c.red(), c.green(), c.blue()});
            if (mx < 185 && mx - mn < 30) return y;
        }
    }
    return -1;
}

TEST(KinematicsPlots, TheLiftPlotDrawsTheRadiusOfTheContourAboveTheOthers) {
    const Reference ref;
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    QAction* action = window.findChild<QAction*>("actionLiftPlot");
    ASSERT_NE(action, nullptr);
    EXPECT_TRUE(action->isChecked());  // shown by default
    QCustomPlot* lift = window.plots()->plot(KinematicsPlots::kLiftPlot);
    for (const int samples : {3600, 100'000}) {
        window.document()->undoStack()->push(new SetSamplesPerTurn(window.document(), samples));
        ASSERT_TRUE(window.waitForCurrentResult(10000));
        // Every point drawn, (φ, r) taken back to the plane, lies on the circle of one of the
        // six-lobe cam's arcs (its centres and radii from the file, not from the engine).
        const auto points = dataOf(lift->graph(0));
        ASSERT_GT(points.size(), 1000u);
        double lo = 1e300, hi = -1e300;
        for (const QCPGraphData& d : points) {
            if (std::isnan(d.value)) continue;
            const double phi = degToRad(d.key);
            const Eigen::Vector2d p(d.value * std::cos(phi), d.value * std::sin(phi));
            double off = 1e300;
            for (const SegmentSpec& s : ref.project.contour) {
                const Arc& arc = test::arcOf(s);
                off = std::min(off, std::abs((p - arc.center).norm() - arc.radius));
            }
            ASSERT_LT(off, 1e-9) << samples << " samples, at " << d.key << "°";
            lo = std::min(lo, d.value);
            hi = std::max(hi, d.value);
        }
        // It spans the contour: from the notches to the lobes' tips. The tips are on circles
        // of radius 8.10318055 about centres 20.89681945 from the origin: 29 mm, reached
        // within a sample step; the notches at 25.73752542 − 4.84070597 = 20.89681945 mm.
        EXPECT_NEAR(hi, 20.89681945 + 8.10318055, 1e-3) << samples;
        EXPECT_NEAR(lo, 25.73752542 - 4.84070597, 1e-3) << samples;
        EXPECT_LE(lift->yAxis->range().lower, lo);
        EXPECT_GE(lift->yAxis->range().upper, hi);
    }
    // Drawn above the velocity, on the same x axis.
    EXPECT_LT(lift->y(), window.plots()->plot(0)->y());
    window.plots()->plot(0)->xAxis->setRange(40.0, 80.0);
    EXPECT_EQ(lift->xAxis->range(), QCPRange(40.0, 80.0));
    // The View menu hides it, and the choice is kept for the next window.
    action->setChecked(false);
    EXPECT_FALSE(lift->isVisible());
    EXPECT_FALSE(QSettings().value("view/liftPlot", true).toBool());
    {
        MainWindow next;
        EXPECT_FALSE(next.findChild<QAction*>("actionLiftPlot")->isChecked());
        EXPECT_TRUE(next.plots()->plot(KinematicsPlots::kLiftPlot)->isHidden());
    }
    action->setChecked(true);
    EXPECT_TRUE(lift->isVisible());
}

TEST(KinematicsPlots, EveryLobeReachesItsPeakAtEveryWindowSize) {
    // The six lobes are identical: each peaks where it meets a notch, at both ends, at the
    // one-sided limit of |a| at the joint (356,524 mm/s²); the nearest of 3600 samples reaches
    // 318,853. What the acceleration plot draws must reach both at every peak, whatever its
    // width, from the samples themselves (3600) or from an envelope of them (100,000).
    const Reference ref;
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    // The acceleration plot at the height it has without the lift plot: shorter, a peak's
    // last pixel is a faint antialiased tip this test's colour threshold does not see.
    QAction* lift = window.findChild<QAction*>("actionLiftPlot");
    lift->setChecked(false);
    const auto shownAgain = qScopeGuard([lift] { lift->setChecked(true); });  // a setting
    window.show();
    for (const int samples : {3600, 100'000}) {
        window.document()->undoStack()->push(new SetSamplesPerTurn(window.document(), samples));
        SampledTurn turn;
        ASSERT_TRUE(sampleTurn(ref.contour, ref.omega, static_cast<std::size_t>(samples), turn));
        for (const QSize size : {QSize(900, 600), QSize(1150, 700), QSize(1400, 860),
                                 QSize(1600, 1000), QSize(1920, 1080)}) {
            window.resize(size);
            ASSERT_TRUE(window.waitForCurrentResult(10000));
            test::processEventsUntil([] { return false; }, 50);
            window.setCursorTime(0.0);  // the cursor line sits on the left edge, out of the way
            QCustomPlot* plot = window.plots()->plot(1);
            plot->replot(QCustomPlot::rpImmediateRefresh);
            const QImage image = plot->grab().toImage();
            const QRect rect = plot->axisRect()->rect();
            const double pixel = plot->yAxis->range().size() / rect.height();
            // Each lobe rises to a peak at both of its ends: every joint but the one inside
            // the first notch (at 0°, where the two halves of the notch meet).
            int peaks = 0;
            for (std::size_t k = 1; k < ref.contour.size(); ++k) {
                const double phi = ref.contour.segment(k).phiStart;
                const double from = radToDeg(phi) - 4.0, to = radToDeg(phi) + 4.0;
                double sampled = 0.0;
                for (std::size_t i = 0; i < turn.size(); ++i) {
                    const double deg = radToDeg(turn.phi[i]);
                    if (deg >= from && deg <= to) sampled = std::max(sampled, turn.a[i]);
                }
                // The segments' own values at the joint, from either side.
                double limit = sampled;
                for (std::size_t side : {k - 1, k}) {
                    const auto d = ref.contour.segment(side).evaluate(phi);
                    limit = std::max(limit, polarMotion(d, ref.omega).a);
                }
                const int x0 = static_cast<int>(plot->xAxis->coordToPixel(from));
                const int x1 = static_cast<int>(plot->xAxis->coordToPixel(to));
                const int top = topOfDarkCurve(image, x0, x1, rect.top() + 2, rect.bottom() - 2);
                ASSERT_GE(top, 0) << size.width() << " joint " << k;
                const double drawn = plot->yAxis->pixelToCoord(top);
                const std::string where =
                    std::to_string(samples) + " samples, " + std::to_string(size.width()) + "x" +
                    std::to_string(size.height()) + ", peak at " + std::to_string(radToDeg(phi));
                EXPECT_GE(drawn, sampled - 2.5 * pixel) << where << "°: drawn " << drawn;
                EXPECT_NEAR(drawn, limit, 2.5 * pixel) << where << "°";
                ++peaks;
            }
            EXPECT_EQ(peaks, 12);
        }
    }
}

TEST(KinematicsPlots, LinesBreakOnlyWhereAQuantityJumpsAndExactlyAtTheJoint) {
    const Reference ref;
    const ContourAnalysis analysis = analyzeContour(ref.contour, ref.omega);
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    // Every joint of this cam is C1, and a_r jumps at all but the one inside the first notch.
    int jumps = 0;
    for (const JointAnalysis& j : analysis.joints) {
        ASSERT_NE(j.continuity, Continuity::C0);
        jumps += j.continuity != Continuity::C2;
    }
    ASSERT_EQ(jumps, 12);
    for (const int samples : {3600, 100'000}) {  // the samples, and an envelope of them
        window.document()->undoStack()->push(new SetSamplesPerTurn(window.document(), samples));
        ASSERT_TRUE(window.waitForCurrentResult(10000));
        const auto velocity = dataOf(window.plots()->plot(0)->graph(2));
        const auto radial = dataOf(window.plots()->plot(1)->graph(0));
        // The speed is continuous all around: no break at all.
        for (const QCPGraphData& d : velocity) {
            ASSERT_FALSE(std::isnan(d.value)) << samples << " samples: a break at " << d.key;
        }
        // a_r: a break exactly at the joint's angle, between the two one-sided values, which
        // differ by the jump the analysis finds.
        int breaks = 0;
        for (std::size_t i = 0; i < radial.size(); ++i) {
            if (!std::isnan(radial[i].value)) continue;
            ++breaks;
            ASSERT_GT(i, 0u);
            ASSERT_LT(i + 1, radial.size());
            const auto joint = std::find_if(
                analysis.joints.begin(), analysis.joints.end(), [&](const JointAnalysis& j) {
                    return std::abs(mod360(radToDeg(j.phi)) - radial[i].key) < 1e-9;
                });
            ASSERT_NE(joint, analysis.joints.end())
                << samples << " samples: a break away from every joint at " << radial[i].key;
            EXPECT_NE(joint->continuity, Continuity::C2);
            EXPECT_EQ(radial[i - 1].key, radial[i].key);
            EXPECT_EQ(radial[i + 1].key, radial[i].key);
            EXPECT_NEAR(radial[i + 1].value - radial[i - 1].value, joint->jumpAR,
                        1e-9 * std::abs(joint->jumpAR));
        }
        EXPECT_EQ(breaks, jumps) << samples << " samples";
    }
}

TEST(KinematicsPlots, ZoomingInDrawsFinerDataButNeverMoreThanAFewPointsPerPixel) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    window.document()->undoStack()->push(new SetSamplesPerTurn(window.document(), 1'000'000));
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    const ComputeResultPtr result = window.engine()->latestResult();
    QCustomPlot* plot = window.plots()->plot(1);
    const auto pointsInView = [&] {
        int count = 0;
        for (const QCPGraphData& d : dataOf(plot->graph(2))) {
            count += plot->xAxis->range().contains(d.key);
        }
        return count;
    };
    const double width = plot->axisRect()->width();
    std::vector<std::size_t> levels;
    // The mouse wheel over the joint at 9.69°, zooming in step by step to a tenth of a degree.
    while (plot->xAxis->range().size() > 0.1) {
        const QPointF pos(plot->xAxis->coordToPixel(9.6914), plot->axisRect()->center().y());
        QWheelEvent wheel(pos, plot->mapToGlobal(pos), QPoint(), QPoint(0, 240), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(plot, &wheel);
        const std::size_t level = window.plots()->shownLevel();
        const std::size_t perBucket = result->curves.levels.at(level).samplesPerBucket;
        const double samplesPerPixel =
            plot->xAxis->range().size() / 360.0 * 1e6 / std::max(1.0, width);
        // Buckets of at most a pixel (or the finest there is), at most 8 points a pixel.
        EXPECT_TRUE(perBucket <= samplesPerPixel || level == 0) << plot->xAxis->range().size();
        EXPECT_LE(pointsInView(), 8 * width + 16) << plot->xAxis->range().size();
        levels.push_back(level);
    }
    EXPECT_EQ(levels.back(), 0u);  // the finest at last
    EXPECT_GT(levels.front(), 0u);
    EXPECT_TRUE(std::is_sorted(levels.rbegin(), levels.rend()));
}

TEST(KinematicsPlots, CursorMovesRedrawOnlyTheCursorLayer) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    test::processEventsUntil([] { return false; }, 100);  // queued replots are done
    std::vector<QCustomPlot*> views = {window.plots()->plot(0), window.plots()->plot(1),
                                       window.plots()->plot(2), window.contourView()};
    std::vector<int> fullReplots(views.size(), 0);
    for (std::size_t i = 0; i < views.size(); ++i) {
        QObject::connect(views[i], &QCustomPlot::afterReplot,
                         [&fullReplots, i] { ++fullReplots[i]; });
        QCPLayer* layer = views[i]->layer("cursor");
        ASSERT_NE(layer, nullptr) << i;
        EXPECT_EQ(layer->mode(), QCPLayer::lmBuffered) << i;
        EXPECT_FALSE(layer->children().isEmpty()) << i;
    }
    QCustomPlot* velocity = window.plots()->plot(0);
    const QRect rect = velocity->axisRect()->rect();
    int column = 0;
    for (int step = 1; step <= 5; ++step) {
        column = rect.left() + rect.width() * step / 6;
        QTest::mouseMove(velocity, QPoint(column, rect.center().y()));
        test::processEventsUntil([] { return false; }, 20);
    }
    for (std::size_t i = 0; i < views.size(); ++i) EXPECT_EQ(fullReplots[i], 0) << i;
    // The cursor did move: the readout and the dashed line are at the mouse's angle.
    const double x = velocity->xAxis->pixelToCoord(column);
    EXPECT_TRUE(test::relClose(test::readoutValue(window, "φ"), x,
                               test::readoutTolerance(DisplayQuantity::Angle)));
    const QImage image = velocity->grab().toImage();
    int dark = 0;
    for (int y = rect.top() + 2; y < rect.bottom() - 2; ++y) {
        const QColor c = image.pixelColor(column, y);
        dark += c.red() < 120 && c.green() < 120 && c.blue() < 120;
    }
    EXPECT_GT(dark, rect.height() / 4);  // a dashed line: about half of the column
}

TEST(KinematicsPlots, CursorMovesRedrawOnlyTheCursorLayersOfThePressureAndDesignPlots) {
    // A project with a roller and a motion design: the Follower dock's pressure-angle plot and
    // the Motion Design dock's four plots have cursors too. A move of the cursor (a mouse move,
    // a frame of Play) redraws their cursor layers only; a full replot of each took 0.3 to
    // 1.5 ms, and a new result redrew the pressure plot twice.
    MainWindow window;
    ASSERT_TRUE(window
                    .loadFile(QString::fromStdString(
                        test::examplePath("synthesised-cycloidal-roller.cam.json")))
                    .isEmpty());
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    const std::pair<const char*, std::vector<const char*>> docks[] = {
        {"followerDock", {"pressureAnglePlot"}},
        {"motionDesignDock",
         {"designLiftPlot", "designVelocityPlot", "designAccelerationPlot", "designJerkPlot"}}};
    for (const auto& [dockName, plotNames] : docks) {
        auto* dock = window.findChild<QDockWidget*>(dockName);
        ASSERT_NE(dock, nullptr) << dockName;
        dock->show();
        dock->raise();  // the right-hand docks are tabs: this one in front
        test::processEventsUntil([] { return false; }, 100);  // queued replots are done
        std::vector<QCustomPlot*> views;
        for (const char* name : plotNames) {
            auto* plot = window.findChild<QCustomPlot*>(name);
            ASSERT_NE(plot, nullptr) << name;
            ASSERT_TRUE(plot->isVisible()) << name;
            QCPLayer* layer = plot->layer("cursor");
            ASSERT_NE(layer, nullptr) << name;
            EXPECT_EQ(layer->mode(), QCPLayer::lmBuffered) << name;
            EXPECT_FALSE(layer->children().isEmpty()) << name;
            views.push_back(plot);
        }
        std::vector<int> fullReplots(views.size(), 0);
        std::vector<QMetaObject::Connection> connections;
        for (std::size_t i = 0; i < views.size(); ++i) {
            connections.push_back(QObject::connect(views[i], &QCustomPlot::afterReplot,
                                                   [&fullReplots, i] { ++fullReplots[i]; }));
        }
        const double period = window.engine()->latestResult()->period;
        for (int step = 1; step <= 5; ++step) {
            window.setCursorTime(period * step / 7.0);
            test::processEventsUntil([] { return false; }, 20);
        }
        for (const auto& c : connections) QObject::disconnect(c);
        for (std::size_t i = 0; i < views.size(); ++i) {
            EXPECT_EQ(fullReplots[i], 0) << plotNames[i];
        }
        // The cursor did move: its line is at the last instant's angle (the x axis in degrees).
        const double phi = radToDeg(window.engine()->latestResult()->omega * period * 5.0 / 7.0);
        for (std::size_t i = 0; i < views.size(); ++i) {
            const auto* line =
                qobject_cast<QCPItemStraightLine*>(views[i]->layer("cursor")->children().front());
            ASSERT_NE(line, nullptr) << plotNames[i];
            EXPECT_NEAR(line->point1->coords().x(), std::fmod(phi, 360.0), 1e-9) << plotNames[i];
        }
    }
}

}  // namespace
}  // namespace cam
