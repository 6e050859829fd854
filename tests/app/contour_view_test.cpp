// The contour view and the readout as a user drives them: joints that stay marked when zoomed
// in, a project that cannot be computed shown as out of date (edit, undo, redo), and a readout
// that reads every angle and instant within one turn.

#include <gtest/gtest.h>

#include <QImage>
#include <QLabel>
#include <QTest>
#include <QWheelEvent>
#include <cmath>
#include <fstream>
#include <limits>

#include "app_test_support.h"
#include "common/angles.h"
#include "document/commands.h"
#include "engine/compute_engine.h"
#include "io/project_json.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "views/contour_view.h"
#include "views/kinematics_plots.h"
#include "views/palette.h"
#include "views/state_readout.h"

#include <qcustomplot.h>

namespace cam {
namespace {

using test::kExampleFile;

QPointF pixelOf(const ContourView* view, double x, double y) {
    return {view->xAxis->coordToPixel(x), view->yAxis->coordToPixel(y)};
}

/// Turns the mouse wheel over `at` (mm) until the view spans at most `spanMm` across.
void wheelZoom(ContourView* view, const QPointF& at, double spanMm) {
    for (int i = 0; i < 60 && view->xAxis->range().size() > spanMm; ++i) {
        const QPointF pos = pixelOf(view, at.x(), at.y());
        QWheelEvent wheel(pos, view->mapToGlobal(pos), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(view, &wheel);
    }
}

QCPGraph* graphNamed(QCustomPlot* plot, const QString& name) {
    for (int i = 0; i < plot->graphCount(); ++i) {
        if (plot->graph(i)->name() == name) return plot->graph(i);
    }
    return nullptr;
}

TEST(ContourView, ManySegmentsAreDrawnByAFixedSetOfCurves) {
    // At 612d090 every segment was a curve of its own with a legend item: closing a window of
    // 10,000 segments took more than five minutes (QCPLegend::removeItem, one by one). Now the
    // segments share the ten colour curves, separated by gaps, and nothing enters a legend.
    MainWindow small;
    ASSERT_TRUE(small.loadFile(kExampleFile).isEmpty());
    ASSERT_TRUE(small.waitForCurrentResult(10000));
    const int fixed = small.contourView()->plottableCount();

    const test::TempDir dir;
    constexpr int kSegments = 2000;
    Project p = test::loadExample();
    p.contour.clear();
    for (int k = 0; k < kSegments; ++k) {  // the circle about (5, 0) of radius 20, split
        p.contour.push_back(SegmentSpec{Arc{{5.0, 0.0}, 20.0, Branch::Outer}, 360.0 * k / kSegments,
                                        360.0 * (k + 1) / kSegments});
    }
    const std::string path = dir.file("split.cam.json");
    std::ofstream(path, std::ios::binary) << serializeProject(p);
    MainWindow window;
    ASSERT_TRUE(window.loadFile(QString::fromStdString(path)).isEmpty());
    ASSERT_TRUE(window.waitForCurrentResult(60000));
    ContourView* view = window.contourView();
    EXPECT_EQ(view->plottableCount(), fixed);
    EXPECT_EQ(view->legend->itemCount(), 0);
    // Each segment's run of points lies on the circle and spans exactly its window.
    for (int k : {0, 1, 9, 10, 1234, kSegments - 1}) {
        const QCPCurve* curve = view->segmentCurve(k);
        const auto [first, count] = view->segmentRun(k);
        ASSERT_GE(count, 9) << k;
        ASSERT_LE(first + count, curve->data()->size()) << k;
        for (int i = first; i < first + count; ++i) {
            const auto it = curve->data()->at(i);
            EXPECT_NEAR(std::hypot(it->key - 5.0, it->value), 20.0, 1e-9) << k;
        }
        const auto start = curve->data()->at(first);
        const auto end = curve->data()->at(first + count - 1);
        const auto turnsApart = [](double a, double b) { return std::remainder(a - b, kTwoPi); };
        EXPECT_NEAR(
            turnsApart(std::atan2(start->value, start->key), degToRad(360.0 * k / kSegments)), 0.0,
            1e-12)
            << k;
        EXPECT_NEAR(
            turnsApart(std::atan2(end->value, end->key), degToRad(360.0 * (k + 1) / kSegments)),
            0.0, 1e-12)
            << k;
        // A gap (NaN) separates it from the next segment of its colour.
        if (first + count < curve->data()->size()) {
            EXPECT_TRUE(std::isnan(curve->data()->at(first + count)->key)) << k;
        }
    }
}

TEST(ContourView, EveryJointStaysMarkedWhenZoomedInOnIt) {
    const Project project = test::loadExample();
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    ContourView* view = window.contourView();
    QCPGraph* joints = graphNamed(view, "joints");
    ASSERT_NE(joints, nullptr);
    int drawn = 0;
    for (std::size_t k = 0; k < project.contour.size(); ++k) {
        // Where segment k begins: on its arc at its start angle (from the document alone).
        const SegmentSpec& s = project.contour[k];
        const double phi = degToRad(s.phiStartDeg);
        const double r = test::arcOf(s).evaluate(phi).r;
        const QPointF joint(r * std::cos(phi), r * std::sin(phi));
        view->resetZoom();
        view->replot(QCustomPlot::rpImmediateRefresh);
        wheelZoom(view, joint, 2.0);  // a ±1 mm view
        ASSERT_LE(view->xAxis->range().size(), 2.0);
        window.setCursorTime(0.55 * window.engine()->latestResult()->period);  // ray elsewhere
        view->replot(QCustomPlot::rpImmediateRefresh);
        const QPointF pixel = pixelOf(view, joint.x(), joint.y());
        // The graph finds the point among those it draws, and the picture shows its marker: a
        // white dot in a black ring, over the thick coloured contour.
        const double distance = joints->selectTest(pixel, false);
        const QImage image = view->grab().toImage();
        const QColor centre = image.pixelColor(pixel.toPoint());
        int ring = 0;
        for (int a = 0; a < 16; ++a) {
            const QPoint p =
                (pixel + 2.5 * QPointF(std::cos(a * kPi / 8), std::sin(a * kPi / 8))).toPoint();
            const QColor c = image.pixelColor(p);
            ring += c.red() < 90 && c.green() < 90 && c.blue() < 90;
        }
        const bool marked =
            distance >= 0 && distance < 2.0 && centre.lightness() > 230 && ring >= 6;
        EXPECT_TRUE(marked) << "joint " << k << " at (" << joint.x() << ", " << joint.y()
                            << "): distance " << distance << ", centre "
                            << centre.name().toStdString() << ", ring " << ring;
        drawn += marked;
    }
    EXPECT_EQ(drawn, 13);
}

TEST(ContourView, AProjectThatCannotBeComputedIsShownGreyedAndLabelled) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    SegmentTableModel* model = window.tableModel();
    ContourView* view = window.contourView();
    KinematicsPlots* plots = window.plots();
    const QModelIndex radius = model->index(2, SegmentTableModel::Radius);
    const double before = model->data(radius, Qt::EditRole).toDouble();
    auto* contourLabel = view->findChild<QLabel*>("staleLabel");
    auto* plotsLabel = plots->findChild<QLabel*>("staleLabel");

    // Counts pixels of a segment's own colour in the contour view: none when all is grey.
    const auto colouredPixels = [&] {
        view->replot(QCustomPlot::rpImmediateRefresh);
        const QImage image = view->grab().toImage();
        int count = 0;
        for (int y = 0; y < image.height(); y += 2) {
            for (int x = 0; x < image.width(); x += 2) {
                const QColor c = image.pixelColor(x, y);
                for (int k : {1, 2, 3}) {  // orange, green, red
                    const QColor s = segmentColor(k);
                    count += std::abs(c.red() - s.red()) + std::abs(c.green() - s.green()) +
                                 std::abs(c.blue() - s.blue()) <
                             30;
                }
            }
        }
        return count;
    };
    const auto labelSays = [](const QLabel* label, const char* what) {
        return label && label->isVisible() && label->text().contains(what);
    };
    const auto expectStale = [&](bool stale, const char* when) {
        // The picture first: no segment drawn in its own colour while it is out of date.
        EXPECT_EQ(colouredPixels() == 0, stale) << when;
        EXPECT_EQ(labelSays(contourLabel, "Segment 2, Radius [mm]"), stale) << when;
        EXPECT_EQ(labelSays(plotsLabel, "Segment 2, Radius [mm]"), stale) << when;
        EXPECT_EQ(view->staleReason().contains("Segment 2, Radius [mm]"), stale) << when;
        EXPECT_EQ(plots->staleReason().contains("Segment 2, Radius [mm]"), stale) << when;
        // The curves of the plots grey, not their own colours.
        const QColor curve = plots->plot(1)->graph(2)->pen().color();
        const QColor axial = plots->plot(1)->graph(0)->pen().color();
        EXPECT_EQ(axial == curve, stale) << when;  // grey both, or blue and black
        EXPECT_EQ(std::isnan(test::readoutValue(window, "r")), stale) << when;
    };
    expectStale(false, "at first");

    ASSERT_TRUE(model->setData(radius, -1.0, Qt::EditRole));
    EXPECT_DOUBLE_EQ(model->data(radius, Qt::EditRole).toDouble(), -1.0);
    EXPECT_FALSE(window.document()->isValid());
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    EXPECT_FALSE(window.engine()->latestResult()->ok());
    expectStale(true, "after the edit");
    EXPECT_TRUE(contourLabel &&
                contourLabel->text().startsWith("Not computed: Segment 2, Radius [mm]"));
    EXPECT_TRUE(window.findChild<QLabel*>("computeLabel")->text().contains("not computed"));

    window.document()->undoStack()->undo();
    EXPECT_DOUBLE_EQ(model->data(radius, Qt::EditRole).toDouble(), before);
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    expectStale(false, "after undo");
    // What is drawn is the document as it is now: segment 2 on its circle again.
    const SegmentSpec& s = window.document()->project().contour[2];
    int checked = 0;
    const QCPCurve* curve = view->segmentCurve(2);
    const auto [first, count] = view->segmentRun(2);
    ASSERT_LE(first + count, curve->data()->size());
    const Arc& arc = test::arcOf(s);
    double previous = std::numeric_limits<double>::quiet_NaN();
    for (int i = first; i < first + count; ++i) {
        const auto it = curve->data()->at(i);
        EXPECT_NEAR(std::hypot(it->key - arc.center.x(), it->value - arc.center.y()), arc.radius,
                    1e-9);
        // Close enough that the chords stay on the circle: the gap between a chord and its arc
        // (the sagitta, R·(1 − cos(Δθ/2))) is at most 0.01 mm, far below a pixel.
        const double theta = std::atan2(it->value - arc.center.y(), it->key - arc.center.x());
        if (i > first) {
            const double step = std::abs(std::remainder(theta - previous, 2.0 * M_PI));
            EXPECT_LE(arc.radius * (1.0 - std::cos(step / 2.0)), 0.01) << "point " << i - first;
        }
        previous = theta;
        ++checked;
    }
    EXPECT_GE(checked, 9);  // at least the 8 intervals every outline starts from

    window.document()->undoStack()->redo();
    EXPECT_DOUBLE_EQ(model->data(radius, Qt::EditRole).toDouble(), -1.0);
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    expectStale(true, "after redo");
}

TEST(StateReadout, ReadsAnglesAndInstantsWithinOneTurnWhereverTheMouseIs) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    for (const double omega : {15.0, -15.0}) {
        window.document()->undoStack()->push(
            new SetMotion(window.document(), {SpeedUnit::OmegaRadS, omega}));
        ASSERT_TRUE(window.waitForCurrentResult(10000));
        const double period = kTwoPi / 15.0;
        ContourView* view = window.contourView();
        view->replot(QCustomPlot::rpImmediateRefresh);
        // The mouse in the lower half of the contour, at 303.69° (−56.31°).
        const QPointF at = pixelOf(view, 10.0, -15.0);
        QTest::mouseMove(view, at.toPoint());
        QCoreApplication::processEvents();
        const double x = view->xAxis->pixelToCoord(at.toPoint().x());
        const double y = view->yAxis->pixelToCoord(at.toPoint().y());
        const double phi = std::atan2(y, x) + kTwoPi;  // in [0, 2π): the lower half
        // Turning clockwise, the ray reaches 303.69° after 360° − 303.69° of rotation.
        const double t = omega > 0 ? phi / omega : (kTwoPi - phi) / -omega;
        // The readout shows an angle's and a time's significant digits (quantity_format.h).
        const double angleTolerance = test::readoutTolerance(DisplayQuantity::Angle);
        const double timeTolerance = test::readoutTolerance(DisplayQuantity::Time);
        EXPECT_TRUE(test::relClose(test::readoutValue(window, "φ"), radToDeg(phi), angleTolerance))
            << omega;
        EXPECT_TRUE(test::relClose(test::readoutValue(window, "t"), t, timeTolerance)) << omega;
        EXPECT_GE(test::readoutValue(window, "t"), 0.0);
        EXPECT_LT(test::readoutValue(window, "t"), period);

        // Left of the plots' axis, where the axis reads a negative x: still within the turn.
        QCustomPlot* velocity = window.plots()->plot(0);
        const QRect rect = velocity->axisRect()->rect();
        QTest::mouseMove(velocity, QPoint(rect.left() - 20, rect.center().y()));
        QCoreApplication::processEvents();
        const double readT = test::readoutValue(window, "t");
        const double readPhi = test::readoutValue(window, "φ");
        EXPECT_GE(readT, 0.0) << omega;
        EXPECT_LT(readT, period) << omega;
        EXPECT_GE(readPhi, 0.0) << omega;
        EXPECT_LT(readPhi, 360.0) << omega;
        // The angle the mouse points at, a few degrees before the start, read within the turn.
        const double xDeg = velocity->xAxis->pixelToCoord(rect.left() - 20);
        EXPECT_TRUE(test::relClose(readPhi, mod360(xDeg), angleTolerance)) << omega;
    }
}

}  // namespace
}  // namespace cam
