// The Follower dock: its edits are undo commands that the engine computes in the worker; the
// design checks it lists are the core's analysis of the same project, and a click on one puts
// the cursor at its angle; the contour view draws the follower there.

#include <gtest/gtest.h>

#include <qcustomplot.h>
#include <Eigen/Geometry>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QListWidget>
#include <QTest>
#include <QUndoStack>

#include "app_test_support.h"
#include "common/angles.h"
#include "document/project_document.h"
#include "engine/compute_engine.h"
#include "follower/follower_analysis.h"
#include "mainwindow.h"
#include "views/contour_view.h"
#include "views/follower_panel.h"
#include "views/kinematics_plots.h"
#include "widgets/number_spin_box.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

using test::kExampleFile;

bool waitForResult(MainWindow& w) { return w.waitForCurrentResult(20000); }

/// Opens the bundled example `name`, shows the window and waits for its result.
bool openAndCompute(MainWindow& w, const char* name) {
    if (!w.loadFile(QString::fromStdString(test::examplePath(name))).isEmpty()) return false;
    w.show();
    return waitForResult(w);
}

template <class T>
T* child(const MainWindow& w, const char* name) {
    T* widget = w.followerPanel()->findChild<T*>(name);
    EXPECT_NE(widget, nullptr) << name;
    return widget;
}

TEST(FollowerPanel, ChoosingARollerIsOneUndoableEditComputedInTheWorker) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.show();
    window.findChild<QDockWidget*>("followerDock")->show();
    ASSERT_TRUE(waitForResult(window));
    EXPECT_FALSE(window.document()->project().follower.has_value());
    EXPECT_EQ(window.engine()->latestResult()->follower, nullptr);

    child<QComboBox>(window, "followerTypeComboBox")->setCurrentIndex(1);  // Roller
    ASSERT_TRUE(window.document()->project().follower.has_value());
    EXPECT_EQ(window.document()->project().follower->type, FollowerType::Roller);
    // A first roller fits the cam: under half its smallest arc (4.84 mm).
    EXPECT_EQ(window.document()->project().follower->radius, 2.4);
    ASSERT_TRUE(waitForResult(window));
    EXPECT_TRUE(window.engine()->latestResult()->ok());
    // One of 5 mm does not fit the concave arcs: the project says so, and the panel why.
    auto* radius = child<QDoubleSpinBox>(window, "followerRadiusSpinBox");
    radius->setValue(5.0);
    emit radius->editingFinished();
    ASSERT_TRUE(waitForResult(window));
    EXPECT_FALSE(window.engine()->latestResult()->ok());
    EXPECT_TRUE(window.followerPanel()
                    ->findChild<QLabel*>("designChecksSummary")
                    ->text()
                    .contains("Follower, roller radius"));
    radius->setValue(2.0);
    radius->setValue(2.5);  // one spin-box session: merged with the step before
    emit radius->editingFinished();
    EXPECT_EQ(window.document()->project().follower->radius, 2.5);
    ASSERT_TRUE(waitForResult(window));
    const ComputeResultPtr result = window.engine()->latestResult();
    ASSERT_TRUE(result->ok());
    ASSERT_NE(result->follower, nullptr);
    EXPECT_EQ(result->follower->spec().radius, 2.5);

    // Undo: the radius back to 5 (the two steps were one edit), to 2.4, then no follower.
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project().follower->radius, 5.0);
    EXPECT_EQ(radius->value(), 5.0);
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project().follower->radius, 2.4);
    window.document()->undoStack()->undo();
    EXPECT_FALSE(window.document()->project().follower.has_value());
    EXPECT_EQ(child<QComboBox>(window, "followerTypeComboBox")->currentIndex(), 0);
    for (int i = 0; i < 3; ++i) window.document()->undoStack()->redo();
    EXPECT_EQ(window.document()->project().follower->radius, 2.5);
}

TEST(FollowerPanel, ThePressureCurveIsAOnePixelLineAndOnlyWhatIsBeyondTheLimitIsWider) {
    // Qt strokes a pen wider than one pixel through its general stroker, 15 times the cost of
    // a one-pixel line: the pressure-angle curve, redrawn on every edit, is one pixel wide (at
    // 1.3 px it took 2 to 3 ms of the redraw); only the stretches beyond the limit are wider.
    MainWindow window;
    ASSERT_TRUE(openAndCompute(window, "swinging-arm-cam.cam.json"));
    QCustomPlot* plot = window.followerPanel()->pressurePlot();
    ASSERT_EQ(plot->graphCount(), 2);
    EXPECT_EQ(plot->graph(0)->pen().widthF(), 1.0);
    EXPECT_EQ(plot->graph(0)->dataCount(),
              static_cast<int>(ComputeResult::kFollowerCurvePoints + 1));
    EXPECT_GT(plot->graph(1)->pen().widthF(), 1.0);
    // The wide one holds values only where |angle| exceeds the limit (NaN elsewhere).
    const double limit = window.document()->project().follower->maxPressureAngleOrDefault();
    int beyond = 0;
    for (int k = 0; k < plot->graph(1)->dataCount(); ++k) {
        const double v = plot->graph(1)->data()->at(k)->value;
        const double all = plot->graph(0)->data()->at(k)->value;
        if (std::isnan(v)) {
            EXPECT_LE(std::abs(all), limit) << k;
        } else {
            EXPECT_EQ(v, all) << k;
            EXPECT_GT(std::abs(v), limit) << k;
            ++beyond;
        }
    }
    EXPECT_LT(beyond, plot->graph(1)->dataCount());
}

TEST(FollowerPanel, TheChecksAreTheCoresAndAClickGoesToTheirAngle) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.show();
    window.findChild<QDockWidget*>("followerDock")->show();
    ASSERT_TRUE(waitForResult(window));
    // A swinging roller, set field by field as a user would.
    child<QComboBox>(window, "followerMotionComboBox")->setCurrentIndex(1);
    auto* radius = child<QDoubleSpinBox>(window, "followerRadiusSpinBox");
    radius->setValue(2.0);
    emit radius->editingFinished();
    const auto spec = window.document()->project().follower;
    ASSERT_TRUE(spec.has_value());
    EXPECT_EQ(spec->motion, FollowerMotion::Oscillating);
    EXPECT_EQ(spec->pivot, Eigen::Vector2d(60.0, 0.0));  // the panel's first arm
    EXPECT_EQ(spec->armLength, 50.0);
    ASSERT_TRUE(waitForResult(window));
    const ComputeResultPtr result = window.engine()->latestResult();
    ASSERT_TRUE(result->ok());
    ASSERT_TRUE(result->followerErrors.empty());

    // The same analysis, made here from the file's contour and the spec.
    const Contour contour = Contour::build(*result->project).value();
    const FollowerModel model = FollowerModel::build(contour, *spec).value();
    const FollowerAnalysis a = analyzeFollower(model, result->omega, contour.phiBegin());
    const QStringList lines = window.followerPanel()->checkLines();
    ASSERT_FALSE(lines.isEmpty());
    EXPECT_TRUE(
        lines[0].contains(formatQuantity(DisplayQuantity::Angle, radToDeg(a.pressure.rise->value))))
        << lines[0].toStdString();
    // 45° is the swinging arm's default limit; it is exceeded in 12 ranges on this cam.
    EXPECT_TRUE(lines[0].contains("(limit 45°)")) << lines[0].toStdString();
    EXPECT_EQ(lines.filter("beyond the limit").size(),
              static_cast<qsizetype>(a.pressureExceeded.size()));
    // Each phase whose largest angle is beyond the limit is a failed check, and each range.
    int phases = 0;
    for (const auto& phase : {a.pressure.rise, a.pressure.fall, a.pressure.dwell}) {
        phases += phase && phase->value > a.limitRad ? 1 : 0;
    }
    EXPECT_GE(phases, 2);
    EXPECT_EQ(window.followerPanel()->problemCount(),
              static_cast<int>(a.pressureExceeded.size()) + phases);

    // The pressure-angle plot: the core's angle at every point, the limit as two lines, red
    // exactly where it is beyond.
    QCustomPlot* plot = window.followerPanel()->pressurePlot();
    ASSERT_TRUE(plot->isVisible());
    const auto angles = plot->graph(0)->data();
    const auto beyond = plot->graph(1)->data();
    ASSERT_EQ(angles->size(), static_cast<int>(ComputeResult::kFollowerCurvePoints + 1));
    int red = 0;
    for (int k = 0; k < angles->size(); k += 7) {
        const double t = result->period * k / ComputeResult::kFollowerCurvePoints;
        const double alpha = radToDeg(model.at(result->omega * t, result->omega).pressureAngle);
        EXPECT_NEAR(angles->at(k)->key, radToDeg(result->omega * t), 1e-9);
        // The engine samples the turn in one go (sampleFollowerTurn: φ_k = ω·(k·T/n), cos/sin
        // by the block table), so the angle agrees with at() to rounding, not to the last bit.
        EXPECT_NEAR(angles->at(k)->value, alpha, 1e-9);
        EXPECT_EQ(std::isnan(beyond->at(k)->value), std::abs(alpha) <= 45.0) << k;
        red += std::isnan(beyond->at(k)->value) ? 0 : 1;
    }
    EXPECT_GT(red, 10);
    // It shares the kinematics plots' x axis.
    window.plots()->plot(0)->xAxis->setRange(100.0, 140.0);
    EXPECT_EQ(plot->xAxis->range().lower, 100.0);
    EXPECT_EQ(plot->xAxis->range().upper, 140.0);

    // Click the third line (the first range beyond the limit): the cursor goes to its start.
    auto* list = child<QListWidget>(window, "designChecksList");
    QListWidgetItem* item = list->item(2);
    ASSERT_NE(item, nullptr);
    const QRect rect = list->visualItemRect(item);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, rect.center());
    const double phi = item->data(Qt::UserRole).toDouble();
    EXPECT_NEAR(phi, a.pressureExceeded.front().from, 1e-12);
    const double expected = std::fmod(phi / result->omega + result->period, result->period);
    EXPECT_NEAR(window.cursorTime(), expected, 1e-12);
}

TEST(FollowerPanel, TheDockTellsConvexFromConcaveAndPlotsBothRadiiOverTheTurn) {
    // The seed's six-lobe cam under a 2 mm roller (offset 3 mm): hollows of 4.84070597 mm,
    // convex arcs of 8.10318055 mm (math.md §3); the pitch curve's are 2 mm less and more.
    const QString path = QString::fromStdString(
        test::dataPath("reference/followers/six-lobe-roller-offset.cam.json"));
    MainWindow window;
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    window.show();
    ASSERT_TRUE(waitForResult(window));
    const ComputeResultPtr result = window.engine()->latestResult();
    ASSERT_TRUE(result->ok() && result->follower);
    const QStringList lines = window.followerPanel()->checkLines();
    const auto has = [&](const QString& start, double mm) {
        const QString text = start + formatQuantity(DisplayQuantity::Length, mm);
        return !lines.filter(text).isEmpty();
    };
    EXPECT_TRUE(has("Smallest convex radius of the profile: ", 8.10318055))
        << lines.join('\n').toStdString();
    EXPECT_TRUE(has("Smallest concave radius of the profile: ", 4.84070597));
    EXPECT_TRUE(has("Smallest convex radius of the pitch curve: ", 10.10318055));
    EXPECT_TRUE(has("Smallest concave radius of the pitch curve: ", 2.84070597));
    EXPECT_TRUE(lines.filter("radius of curvature").isEmpty());  // no signed minimum any more
    EXPECT_FALSE(lines.filter("Largest pressure angle on return").isEmpty());
    EXPECT_TRUE(lines.filter("in a dwell").isEmpty());  // this cam has none

    // The plot: the core's signed radii at every point, clipped at twice the cam's largest
    // radius so that both signs read beside a straight stretch's +∞.
    QCustomPlot* plot = window.followerPanel()->curvaturePlot();
    ASSERT_TRUE(plot->isVisible());
    const double clip = window.followerPanel()->curvatureClip();
    EXPECT_GT(clip, 2.0 * 8.10318055);
    const auto profile = plot->graph(0)->data(), pitch = plot->graph(1)->data();
    ASSERT_EQ(profile->size(), static_cast<int>(ComputeResult::kFollowerCurvePoints + 1));
    int convex = 0, concave = 0;
    for (int k = 0; k < profile->size(); k += 11) {
        const double t = result->period * k / ComputeResult::kFollowerCurvePoints;
        const FollowerState st = result->follower->at(result->omega * t, result->omega);
        EXPECT_NEAR(profile->at(k)->value, std::clamp(st.rhoProfile, -clip, clip), 1e-9) << k;
        EXPECT_NEAR(pitch->at(k)->value, std::clamp(st.rhoPitch, -clip, clip), 1e-9) << k;
        convex += profile->at(k)->value > 0 ? 1 : 0;
        concave += profile->at(k)->value < 0 ? 1 : 0;
    }
    EXPECT_GT(convex, 10);
    EXPECT_GT(concave, 10);
    EXPECT_GE(plot->yAxis->range().lower, -1.1 * clip);
    EXPECT_LE(plot->yAxis->range().upper, 1.1 * clip);
}

TEST(FollowerPanel, AnEditsChecksFollowItsFirstPictureAndTheListIsNeverEmptyMeanwhile) {
    // The first picture of an edit carries the pressure-angle curve but not the arm's checks
    // (they take longer than the kinematics): the list keeps the previous checks until the
    // same result comes back with its own.
    MainWindow window;
    ASSERT_TRUE(openAndCompute(window, "swinging-arm-cam.cam.json"));
    const QStringList before = window.followerPanel()->checkLines();
    ASSERT_FALSE(before.isEmpty());
    std::vector<std::pair<bool, QStringList>> seen;  // pending, the list as shown then
    QObject::connect(&window, &MainWindow::resultShown, [&](const ComputeResultPtr& r) {
        seen.emplace_back(r->followerChecksPending, window.followerPanel()->checkLines());
    });
    auto* limit = child<QDoubleSpinBox>(window, "pressureLimitSpinBox");
    ASSERT_NE(limit, nullptr);
    limit->setValue(limit->value() + 5.0);
    emit limit->editingFinished();
    ASSERT_TRUE(waitForResult(window));
    ASSERT_GE(seen.size(), 2u);
    EXPECT_TRUE(seen.front().first);
    EXPECT_EQ(seen.front().second, before);  // the previous checks, not an empty list
    EXPECT_FALSE(seen.back().first);
    // Then the checks of the edit: the core's, with the new limit.
    const ComputeResultPtr result = window.engine()->latestResult();
    const Contour contour = Contour::build(*result->project).value();
    const FollowerModel model = FollowerModel::build(contour, *result->project->follower).value();
    const FollowerAnalysis a = analyzeFollower(model, result->omega, contour.phiBegin());
    const QStringList after = window.followerPanel()->checkLines();
    EXPECT_EQ(seen.back().second, after);
    ASSERT_FALSE(after.isEmpty());
    EXPECT_TRUE(after[0].contains(formatQuantity(DisplayQuantity::Angle, radToDeg(a.limitRad))))
        << after[0].toStdString();
    EXPECT_NE(after, before);
}

TEST(FollowerPanel, CtrlZAfterEnterInADocksBoxUndoesTheEdit) {
    // Issue 31, point 4: after a committed edit in a dock the focus stays in its box, and the
    // window's undo must win there: the Follower dock's roller radius and the Motion dock's
    // speed, with real key events.
    MainWindow window;
    ASSERT_TRUE(openAndCompute(window, "spring-loaded-roller-cam.cam.json"));
    window.findChild<QDockWidget*>("followerDock")->show();
    window.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
    const QKeySequence undo = QKeySequence::keyBindings(QKeySequence::Undo).first();
    auto* radius = child<NumberSpinBox>(window, "followerRadiusSpinBox");
    test::typeInto(radius, "6");
    ASSERT_EQ(window.document()->project().follower->radius, 6.0);
    ASSERT_TRUE(radius->hasFocus());
    QTest::keySequence(radius, undo);
    EXPECT_EQ(window.document()->project().follower->radius, 8.0);
    EXPECT_EQ(radius->value(), 8.0);

    auto* speed = window.findChild<NumberSpinBox*>("speedSpinBox");
    ASSERT_NE(speed, nullptr);
    const double before = window.document()->project().motion.value;
    test::typeInto(speed, "200");
    ASSERT_EQ(window.document()->project().motion.value, 200.0);
    ASSERT_TRUE(speed->hasFocus());
    QTest::keySequence(speed, undo);
    EXPECT_EQ(window.document()->project().motion.value, before);
}

TEST(FollowerPanel, AnArmThatCannotReachTheCamIsListedNotHidden) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.show();
    child<QComboBox>(window, "followerMotionComboBox")->setCurrentIndex(1);
    auto* length = child<QDoubleSpinBox>(window, "armLengthSpinBox");
    length->setValue(20.0);  // from a pivot 60 mm out the cam is at least 31 mm away
    emit length->editingFinished();
    ASSERT_TRUE(waitForResult(window));
    const QStringList lines = window.followerPanel()->checkLines();
    ASSERT_EQ(lines.size(), 1);
    EXPECT_TRUE(lines[0].contains("Follower, arm length: is too short")) << lines[0].toStdString();
    EXPECT_TRUE(lines[0].contains("too short")) << lines[0].toStdString();
    EXPECT_EQ(window.followerPanel()->problemCount(), 1);
    // The kinematics are still shown: only the follower cannot be placed.
    EXPECT_TRUE(window.engine()->latestResult()->ok());
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(Play, TheCursorTurnsAtTheChosenFractionOfTheRealSpeedAndStopsOnPause) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.show();
    ASSERT_TRUE(waitForResult(window));
    auto* speed = window.findChild<QComboBox*>("playSpeedComboBox");
    ASSERT_NE(speed, nullptr);
    speed->setCurrentIndex(speed->findData(0.1));
    EXPECT_EQ(window.playSpeedFactor(), 0.1);
    const double start = window.cursorTime();
    QElapsedTimer clock;
    clock.start();
    window.playAction()->trigger();
    EXPECT_EQ(window.playAction()->text(), "Pause");
    QTest::qWait(400);
    window.playAction()->trigger();  // pause
    const double wall = static_cast<double>(clock.nsecsElapsed()) / 1e9;
    const double moved = window.cursorTime() - start;  // T = 0.4 s: no wrap within 4 s of play
    // At a tenth of the speed the cursor's time ran a tenth of the wall time (the frames that
    // came: at least half of it on a busy machine), never more.
    EXPECT_GT(moved, 0.5 * 0.1 * 0.4);
    EXPECT_LE(moved, 0.1 * wall + 1e-9);
    EXPECT_EQ(window.playAction()->text(), "Play");
    const double paused = window.cursorTime();
    QTest::qWait(100);
    EXPECT_EQ(window.cursorTime(), paused);
}

}  // namespace
}  // namespace cam

namespace cam {
namespace {

TEST(FollowerInContourView, TheArmRollerContactAndNormalAreDrawnWhereTheCoreSays) {
    const QString arm = QString::fromStdString(
        test::dataPath("reference/followers/pear-tangent-arm-roller.cam.json"));
    MainWindow window;
    ASSERT_TRUE(window.loadFile(arm).isEmpty());
    window.show();
    ASSERT_TRUE(waitForResult(window));
    const ComputeResultPtr result = window.engine()->latestResult();
    ASSERT_TRUE(result->ok());
    ASSERT_NE(result->follower, nullptr);
    const FollowerSpec& spec = *result->project->follower;
    for (const double deg : {10.0, 123.4, 271.0}) {
        const double phi = degToRad(deg);
        window.contourView()->setCursorAngle(phi);
        const ContourView::FollowerMarkers m = window.contourView()->followerMarkers();
        ASSERT_TRUE(m.shown);
        ASSERT_TRUE(m.pivotShown);
        // The pivot turned by φ; the roller L from it and ρ from the contact, which lies on the
        // profile along the normal (plane geometry, not the follower's own numbers).
        const Eigen::Vector2d pivot(
            std::cos(phi) * spec.pivot.x() - std::sin(phi) * spec.pivot.y(),
            std::sin(phi) * spec.pivot.x() + std::cos(phi) * spec.pivot.y());
        const Eigen::Vector2d center(m.center.x(), m.center.y()),
            contact(m.contact.x(), m.contact.y());
        EXPECT_NEAR((Eigen::Vector2d(m.pivot.x(), m.pivot.y()) - pivot).norm(), 0.0, 1e-9) << deg;
        EXPECT_NEAR((center - pivot).norm(), spec.armLength, 1e-9) << deg;
        EXPECT_NEAR(m.rollerRadius, spec.radius, 1e-12);
        EXPECT_NEAR((center - contact).norm(), spec.radius, 1e-9) << deg;
        const Eigen::Vector2d tip(m.normalTip.x(), m.normalTip.y());
        const Eigen::Vector2d a = (tip - contact).normalized(), b = (center - contact).normalized();
        EXPECT_NEAR((a - b).norm(), 0.0, 1e-9) << deg;  // the normal points through the centre
    }
    // A project without a follower draws none.
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    ASSERT_TRUE(waitForResult(window));
    window.contourView()->setCursorAngle(0.3);
    EXPECT_FALSE(window.contourView()->followerMarkers().shown);
}

TEST(FollowerPanel, TheGrooveIsOneSettingDrawnCheckedAndUndone) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.show();
    window.findChild<QDockWidget*>("followerDock")->show();
    ASSERT_TRUE(waitForResult(window));
    ContourView* view = window.contourView();
    EXPECT_EQ(view->outerFlankCurve()->dataCount(), 0);

    // One setting: the closure. The knife becomes a roller whose groove fits the notches
    // (radius 4.84 mm): (4.84 − 0.05) / 2 rounded down to 2.3 mm.
    auto* closure = child<QComboBox>(window, "followerClosureComboBox");
    ASSERT_TRUE(closure->isEnabled());  // from any follower, the knife of a new project too
    // Rows a follower does not use are hidden: the lands without a groove, an arm's on a line.
    FollowerPanel* panel = window.followerPanel();
    auto* innerLandBox = child<QDoubleSpinBox>(window, "innerLandSpinBox");
    EXPECT_FALSE(innerLandBox->isVisibleTo(panel));
    EXPECT_FALSE(child<QDoubleSpinBox>(window, "pivotXSpinBox")->isVisibleTo(panel));
    EXPECT_TRUE(child<QDoubleSpinBox>(window, "followerOffsetSpinBox")->isVisibleTo(panel));
    closure->setCurrentIndex(1);
    const auto spec = window.document()->project().follower;
    ASSERT_TRUE(spec.has_value());
    EXPECT_EQ(spec->closure, Closure::Groove);
    EXPECT_EQ(spec->type, FollowerType::Roller);
    EXPECT_EQ(spec->radius, 2.3);
    EXPECT_EQ(spec->grooveClearance, 0.05);
    EXPECT_EQ(window.document()->undoStack()->count(), 1);
    ASSERT_TRUE(waitForResult(window));
    ComputeResultPtr result = window.engine()->latestResult();
    ASSERT_TRUE(result->valid());
    ASSERT_NE(result->groove, nullptr);

    // Drawn: every point of the outer flank is 2ρ + c from the profile and of the dashed
    // pitch curve ρ, measured against r(φ) sampled every 0.005° (to the sampling's 1e-4 mm).
    const Contour contour = Contour::build(*result->project).value();
    std::vector<Eigen::Vector2d> profile;
    for (int k = 0; k < 72000; ++k) {
        const double phi = kTwoPi * k / 72000;
        profile.push_back(contour.evaluate(phi).r * Eigen::Vector2d(std::cos(phi), std::sin(phi)));
    }
    const auto worstOff = [&](const QCPCurve* curve, double offset) {
        double worst = 0.0;
        for (int i = 0; i < curve->dataCount(); i += 13) {
            const Eigen::Vector2d p(curve->data()->at(i)->key, curve->data()->at(i)->value);
            double d = 1e300;
            for (const Eigen::Vector2d& q : profile) d = std::min(d, (p - q).squaredNorm());
            worst = std::max(worst, std::abs(std::sqrt(d) - offset));
        }
        return worst;
    };
    ASSERT_GT(view->outerFlankCurve()->dataCount(), 360);
    ASSERT_GT(view->pitchCurve()->dataCount(), 360);
    EXPECT_LT(worstOff(view->outerFlankCurve(), 2 * 2.3 + 0.05), 1e-3);
    EXPECT_LT(worstOff(view->pitchCurve(), 2.3), 1e-3);
    EXPECT_EQ(view->pitchCurve()->pen().style(), Qt::DashLine);

    // Checked: the groove's lines, and a land the inner flank (down to 20.897 mm) cuts into.
    EXPECT_EQ(window.followerPanel()->checkLines().filter("Groove: ").size(), 1);
    const int before = window.followerPanel()->problemCount();
    auto* innerLand = child<QDoubleSpinBox>(window, "innerLandSpinBox");
    ASSERT_TRUE(innerLand->isEnabled());
    EXPECT_TRUE(innerLand->isVisibleTo(panel));
    innerLand->setValue(22.0);
    emit innerLand->editingFinished();
    EXPECT_EQ(window.document()->project().follower->innerLandRadius, 22.0);
    ASSERT_TRUE(waitForResult(window));
    const QStringList lines = window.followerPanel()->checkLines();
    const QStringList land = lines.filter("Inner flank nearest the centre");
    ASSERT_EQ(land.size(), 1);
    EXPECT_TRUE(land.front().contains("(land to 22 mm)")) << land.front().toStdString();
    EXPECT_EQ(window.followerPanel()->problemCount(), before + 1);

    // A clearance the notches (4.84 mm) cannot hold (2·2.3 + 1 = 5.6 mm): the follower cannot
    // ride it, and no outer flank is drawn.
    auto* clearance = child<QDoubleSpinBox>(window, "grooveClearanceSpinBox");
    clearance->setValue(1.0);
    emit clearance->editingFinished();
    ASSERT_TRUE(waitForResult(window));
    EXPECT_FALSE(window.engine()->latestResult()->valid());
    qsizetype notches = 0;  // one line per concave arc
    for (const SegmentSpec& segment : window.document()->project().contour) {
        notches += segment.as<Arc>() && segment.as<Arc>()->branch == Branch::Inner ? 1 : 0;
    }
    EXPECT_EQ(window.followerPanel()->checkLines().filter("undercuts the groove").size(), notches)
        << window.followerPanel()->checkLines().join("\n").toStdString();
    EXPECT_EQ(view->outerFlankCurve()->dataCount(), 0);

    // Undone step by step, back to the spring-closed knife.
    QUndoStack* undo = window.document()->undoStack();
    ASSERT_EQ(undo->count(), 3);
    undo->undo();
    EXPECT_EQ(window.document()->project().follower->grooveClearance, 0.05);
    undo->undo();
    EXPECT_FALSE(window.document()->project().follower->innerLandRadius);
    EXPECT_EQ(innerLand->value(), 0.0);
    undo->undo();
    EXPECT_FALSE(window.document()->project().follower.has_value());
    EXPECT_EQ(closure->currentIndex(), 0);
    ASSERT_TRUE(waitForResult(window));
    EXPECT_EQ(view->outerFlankCurve()->dataCount(), 0);
}

TEST(FollowerPanel, TurningTheCamTurnsItsGrooveWithIt) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    window.show();
    ASSERT_TRUE(waitForResult(window));
    child<QComboBox>(window, "followerClosureComboBox")->setCurrentIndex(1);
    ASSERT_TRUE(waitForResult(window));
    ContourView* view = window.contourView();
    const auto standing = [&](int i) {
        return Eigen::Vector2d(view->outerFlankCurve()->data()->at(i)->key,
                               view->outerFlankCurve()->data()->at(i)->value);
    };
    std::vector<Eigen::Vector2d> before;
    for (int i = 0; i < view->outerFlankCurve()->dataCount(); i += 50)
        before.push_back(standing(i));
    view->setTurning(true);
    const double phi = degToRad(37.0);
    view->setCursorAngle(phi);
    EXPECT_NEAR(view->turnedBy(), -phi, 1e-15);
    // Every point turned by −φ about the rotation centre, as the profile is.
    const Eigen::Rotation2Dd turn(-phi);
    for (std::size_t k = 0; k < before.size(); ++k) {
        EXPECT_NEAR((standing(static_cast<int>(k) * 50) - turn * before[k]).norm(), 0.0, 1e-12);
    }
    view->setTurning(false);
    EXPECT_NEAR((standing(0) - before[0]).norm(), 0.0, 1e-15);
}

TEST(FollowerPanel, TheConjugatePairIsOneSettingDrawnCheckedAndUndone) {
    // The roller lobe cam (a 5 mm roller, r up to 30 mm): one setting makes it a conjugate
    // pair whose second roller, as large, stands 2·(30 + 5) = 70 mm behind the first.
    MainWindow window;
    ASSERT_TRUE(openAndCompute(window, "roller-lobe-cam.cam.json"));
    window.findChild<QDockWidget*>("followerDock")->show();
    ContourView* view = window.contourView();
    EXPECT_EQ(view->secondPlateCurve()->dataCount(), 0);
    FollowerPanel* panel = window.followerPanel();
    auto* distance = child<QDoubleSpinBox>(window, "conjugateDistanceSpinBox");
    EXPECT_FALSE(distance->isVisibleTo(panel));
    child<QComboBox>(window, "followerClosureComboBox")->setCurrentIndex(2);
    const FollowerSpec spec = *window.document()->project().follower;
    EXPECT_EQ(spec.closure, Closure::Conjugate);
    EXPECT_EQ(spec.conjugateDistance, 70.0);
    EXPECT_EQ(spec.conjugateRadius, 5.0);
    EXPECT_TRUE(distance->isVisibleTo(panel));
    EXPECT_EQ(distance->value(), 70.0);
    ASSERT_TRUE(waitForResult(window));
    const ComputeResultPtr result = window.engine()->latestResult();
    ASSERT_TRUE(result->valid());
    ASSERT_NE(result->conjugate, nullptr)
        << (result->conjugateErrors.empty() ? std::string()
                                            : result->conjugateErrors.front().text());

    // Drawn: every point of the second plate is the second roller's radius from the path its
    // centre runs on, 70 mm behind the first roller's (sampled every 0.01°).
    const FollowerModel& first = *result->follower;
    std::vector<Eigen::Vector2d> centres;
    for (int k = 0; k < 36000; ++k) {
        const double phi = kTwoPi * k / 36000;
        centres.push_back((first.at(phi, 1.0).s - 70.0) *
                          Eigen::Vector2d(std::cos(phi), std::sin(phi)));
    }
    const QCPCurve* plate = view->secondPlateCurve();
    ASSERT_GT(plate->dataCount(), 360);
    double worst = 0.0;
    for (int i = 0; i < plate->dataCount(); i += 7) {
        const Eigen::Vector2d p(plate->data()->at(i)->key, plate->data()->at(i)->value);
        double d = 1e300;
        for (const Eigen::Vector2d& c : centres) d = std::min(d, (p - c).squaredNorm());
        worst = std::max(worst, std::abs(std::sqrt(d) - 5.0));
    }
    // The fit's 0.001 mm, and the centres' spacing (0.007 mm at 40 mm) across a 5 mm roller.
    EXPECT_LT(worst, 1.1e-3);
    // Both rollers drawn at the cursor, the second 70 mm behind the first on its line.
    for (const double deg : {0.0, 90.0, 200.0}) {
        view->setCursorAngle(degToRad(deg));
        const auto m = view->followerMarkers();
        ASSERT_TRUE(m.secondShown);
        EXPECT_EQ(m.secondRadius, 5.0);
        const Eigen::Vector2d a(m.center.x(), m.center.y()),
            b(m.secondCenter.x(), m.secondCenter.y()),
            contact(m.secondContact.x(), m.secondContact.y());
        EXPECT_NEAR((a - b).norm(), 70.0, 1e-9) << deg;
        EXPECT_NEAR((a - b).normalized().dot(
                        Eigen::Vector2d(std::cos(degToRad(deg)), std::sin(degToRad(deg)))),
                    1.0, 1e-12);
        EXPECT_NEAR((contact - b).norm(), 5.0, 1e-9);
    }
    // Turning with Play, the second plate turns with the cam.
    const Eigen::Vector2d before(plate->data()->at(0)->key, plate->data()->at(0)->value);
    view->setTurning(true);
    view->setCursorAngle(degToRad(50.0));
    const Eigen::Vector2d turned(plate->data()->at(0)->key, plate->data()->at(0)->value);
    EXPECT_NEAR((turned - Eigen::Rotation2Dd(degToRad(-50.0)) * before).norm(), 0.0, 1e-12);
    view->setTurning(false);

    // Checked: the play within the tolerance, the second roller's pressure angle, the bends.
    const QStringList lines = panel->checkLines();
    EXPECT_EQ(lines.filter("Second plate: ").size(), 1) << lines.join("\n").toStdString();
    EXPECT_EQ(lines.filter("Largest pressure angle at the second roller").size(), 1);
    EXPECT_EQ(lines.filter("Smallest convex radius of the second plate").size(), 1);
    EXPECT_EQ(panel->problemCount(), 0) << lines.join("\n").toStdString();

    // Too short a yoke: the project is invalid at the distance, and no second plate is drawn.
    distance->setValue(30.0);
    emit distance->editingFinished();
    ASSERT_TRUE(waitForResult(window));
    EXPECT_FALSE(window.engine()->latestResult()->valid());
    EXPECT_EQ(panel->checkLines().filter("beyond the cam centre").size(), 1)
        << panel->checkLines().join("\n").toStdString();
    EXPECT_EQ(view->secondPlateCurve()->dataCount(), 0);

    // Undone step by step, back to the spring.
    QUndoStack* undo = window.document()->undoStack();
    ASSERT_EQ(undo->count(), 2);
    undo->undo();
    EXPECT_EQ(window.document()->project().follower->conjugateDistance, 70.0);
    undo->undo();
    EXPECT_EQ(window.document()->project().follower->closure, Closure::Spring);
    ASSERT_TRUE(waitForResult(window));
    EXPECT_EQ(view->secondPlateCurve()->dataCount(), 0);
    EXPECT_FALSE(view->followerMarkers().secondShown);
}

TEST(FollowerPanel, OnASwingingArmTheConjugatePairIsABellCrank) {
    // The swinging-arm example: the same setting gives the arm a second arm on its pivot, the
    // first mirrored about the line to the cam centre, as long; its roller is drawn that far
    // from the pivot, and the second plate holds it within the tolerance.
    MainWindow window;
    ASSERT_TRUE(openAndCompute(window, "swinging-arm-cam.cam.json"));
    window.findChild<QDockWidget*>("followerDock")->show();
    FollowerPanel* panel = window.followerPanel();
    child<QComboBox>(window, "followerClosureComboBox")->setCurrentIndex(2);
    const FollowerSpec spec = *window.document()->project().follower;
    ASSERT_EQ(spec.closure, Closure::Conjugate);
    EXPECT_EQ(spec.motion, FollowerMotion::Oscillating);
    EXPECT_EQ(spec.conjugateArmLength, spec.armLength);
    EXPECT_NE(spec.conjugateAngleDeg, 0.0);
    EXPECT_EQ(spec.conjugateDistance, 0.0);
    EXPECT_TRUE(child<QDoubleSpinBox>(window, "conjugateAngleSpinBox")->isVisibleTo(panel));
    EXPECT_FALSE(child<QDoubleSpinBox>(window, "conjugateDistanceSpinBox")->isVisibleTo(panel));
    ASSERT_TRUE(waitForResult(window));
    const ComputeResultPtr result = window.engine()->latestResult();
    ASSERT_TRUE(result->valid()) << (result->problems.empty() ? ""
                                                              : result->problems.front().text());
    ASSERT_NE(result->conjugate, nullptr);
    EXPECT_LE(result->conjugate->plate.maxPlay, result->conjugate->toleranceMm);
    EXPECT_GE(result->conjugate->plate.minPlay, -result->conjugate->toleranceMm);
    ContourView* view = window.contourView();
    for (const double deg : {0.0, 100.0, 250.0}) {
        view->setCursorAngle(degToRad(deg));
        const auto m = view->followerMarkers();
        ASSERT_TRUE(m.secondShown && m.pivotShown);
        const Eigen::Vector2d pivot(m.pivot.x(), m.pivot.y());
        EXPECT_NEAR((Eigen::Vector2d(m.secondCenter.x(), m.secondCenter.y()) - pivot).norm(),
                    spec.armLength, 1e-9);
        EXPECT_NEAR((Eigen::Vector2d(m.center.x(), m.center.y()) - pivot).norm(), spec.armLength,
                    1e-9);
    }
    EXPECT_EQ(panel->checkLines().filter("Second plate: ").size(), 1);
    // Back to a line: a yoke again, the distance shown.
    child<QComboBox>(window, "followerMotionComboBox")->setCurrentIndex(0);
    const FollowerSpec line = *window.document()->project().follower;
    EXPECT_GT(line.conjugateDistance, 0.0);
    EXPECT_EQ(line.conjugateArmLength, 0.0);
    EXPECT_TRUE(child<QDoubleSpinBox>(window, "conjugateDistanceSpinBox")->isVisibleTo(panel));
}

}  // namespace
}  // namespace cam
