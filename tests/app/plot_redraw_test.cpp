// Plots replot one per pass of the event loop; what waits for them (whenReplotsDone) comes
// after the last, and an edit's plots are drawn before the rest of the window takes its result.

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QLabel>
#include <QStringList>
#include <QTimer>
#include <memory>

#include "app_test_support.h"
#include "engine/compute_engine.h"
#include "engine/compute_result.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "views/contour_view.h"
#include "views/kinematics_plots.h"
#include "views/plot_redraw.h"
#include "views/state_readout.h"

#include <qcustomplot.h>

namespace cam {
namespace {

/// Processes events until `done` or two seconds passed.
template <typename Done>
void processUntil(Done done) {
    QElapsedTimer clock;
    clock.start();
    while (!done() && clock.elapsed() < 2000) QCoreApplication::processEvents();
}

/// Lets QCustomPlot's own first replots happen before a test counts any.
void settle() {
    for (int i = 0; i < 3; ++i) QCoreApplication::processEvents();
}

TEST(PlotRedraw, WhatWaitsForThePlotsComesAfterTheLastOfThemInOrder) {
    QCustomPlot a, b;
    settle();
    QStringList events;
    QObject::connect(&a, &QCustomPlot::afterReplot, [&] { events << "a"; });
    QObject::connect(&b, &QCustomPlot::afterReplot, [&] { events << "b"; });
    QObject context;
    queueReplot(&a);
    queueReplot(&b);
    whenReplotsDone(&context, [&] { events << "first"; });
    whenReplotsDone(&context, [&] { events << "second"; });
    // Nothing yet: all of it waits for the event loop.
    EXPECT_TRUE(events.isEmpty());
    processUntil([&] { return events.size() == 4; });
    EXPECT_EQ(events, (QStringList{"a", "b", "first", "second"}));
}

TEST(PlotRedraw, AGoneContextIsNotCalledAndReplotQueuedNowCallsTheRest) {
    QCustomPlot a;
    settle();
    QStringList events;
    QObject::connect(&a, &QCustomPlot::afterReplot, [&] { events << "a"; });
    auto gone = std::make_unique<QObject>();
    QObject kept;
    queueReplot(&a);
    whenReplotsDone(gone.get(), [&] { events << "gone"; });
    whenReplotsDone(&kept, [&] { events << "kept"; });
    gone.reset();
    replotQueuedNow();  // at once, without the event loop
    EXPECT_EQ(events, (QStringList{"a", "kept"}));
    QCoreApplication::processEvents();  // the pass posted meanwhile finds nothing left
    EXPECT_EQ(events, (QStringList{"a", "kept"}));
}

TEST(PlotRedraw, PlotsQueuedLaterNeverHoldBackWhatWaitsForEarlierOnes) {
    QCustomPlot a, b;
    settle();
    QStringList events;
    int bReplots = 0;
    // b is queued again after each of its replots, ten times: a stream of replots, as while
    // edits stream in.
    QObject::connect(&a, &QCustomPlot::afterReplot, [&] {
        events << "a";
        queueReplot(&b);
    });
    QObject::connect(&b, &QCustomPlot::afterReplot, [&] {
        events << "b";
        if (++bReplots < 10) queueReplot(&b);
    });
    QObject context;
    queueReplot(&a);
    whenReplotsDone(&context, [&] { events << "waited for a"; });
    processUntil([&] { return bReplots == 10; });
    ASSERT_GE(events.size(), 3);
    EXPECT_EQ(events.mid(0, 3), (QStringList{"a", "waited for a", "b"}));
}

TEST(PlotRedraw, WhatTheWaitingCallsChangedIsPaintedInAPassBeforeTheNextReplot) {
    // A waiting call (the readout, the contour view's new result) changes labels and queues a
    // replot: the window paints those labels in the next pass, and the replot, which repaints
    // the window again, comes in the pass after. In one pass together they held the window for
    // 7 to 8 ms. What was posted in the pass of the call (the paint, input) comes before it.
    QCustomPlot first, second;
    settle();
    std::vector<std::string> order;
    QObject::connect(&second, &QCustomPlot::afterReplot, [&] { order.push_back("replot"); });
    queueReplot(&first);
    whenReplotsDone(&first, [&] {
        order.push_back("call");
        queueReplot(&second);
        QMetaObject::invokeMethod(
            &first, [&] { order.push_back("posted in the call's pass"); }, Qt::QueuedConnection);
    });
    processUntil([&] { return order.size() == 3; });
    EXPECT_EQ(order, (std::vector<std::string>{"call", "posted in the call's pass", "replot"}));
}

TEST(PlotRedraw, ATimerDueBetweenTwoReplotsFiresBetweenThem) {
    // Input and timers get their turn between two replots: a pass is a zero timer, not a
    // posted event (Qt delivered a chain of posted passes two at a time before any timer, and
    // a probe timer saw the window held for both).
    QCustomPlot first, second;
    settle();
    std::vector<std::string> order;
    QTimer due;
    due.setSingleShot(true);
    QObject::connect(&due, &QTimer::timeout, [&] { order.push_back("timer"); });
    QObject::connect(&first, &QCustomPlot::afterReplot, [&] {
        order.push_back("first");
        due.start(0);
    });
    QObject::connect(&second, &QCustomPlot::afterReplot, [&] { order.push_back("second"); });
    queueReplot(&first);
    queueReplot(&second);
    processUntil([&] { return order.size() == 3; });
    EXPECT_EQ(order, (std::vector<std::string>{"first", "timer", "second"}));
}

TEST(PlotRedraw, AResultThatCannotBeComputedIsNotOverwrittenByTheOneBefore) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    // As soon as an edit's result reaches the plots (the rest of the window still waiting for
    // them), a newer request's result arrives that could not be computed.
    bool failedSent = false;
    QObject::connect(&window, &MainWindow::resultShown, [&](const ComputeResultPtr& shown) {
        if (failedSent || !shown->ok()) return;
        failedSent = true;
        ComputeRequest newer;
        newer.generation = shown->generation + 1;
        newer.project = shown->project;
        emit window.engine()->resultReady(failedResult(newer, "the test's failure"));
    });
    window.tableModel()->setData(window.tableModel()->index(0, SegmentTableModel::Type), 1,
                                 Qt::EditRole);
    processUntil([&] { return failedSent; });
    ASSERT_TRUE(failedSent);
    replotQueuedNow();
    for (int i = 0; i < 5; ++i) QCoreApplication::processEvents();
    // The window says what the newest result says: not computed, no state at the cursor.
    const auto* computeLabel = window.findChild<QLabel*>("computeLabel");
    ASSERT_TRUE(computeLabel);
    EXPECT_TRUE(computeLabel->text().contains("not computed"))
        << computeLabel->text().toStdString();
    EXPECT_TRUE(window.readout()->text().startsWith("t —"))
        << window.readout()->text().toStdString();
}

TEST(PlotRedraw, AnEditsPlotsAreDrawnBeforeTheReadoutAndTheContourViewTakeItsResult) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    window.setCursorTime(0.001);  // on segment 0, which the edit turns into a line
    const QString readoutBefore = window.readout()->text();
    std::vector<QCustomPlot*> plots;
    for (int p = 0; p < KinematicsPlots::kPlotCount; ++p) plots.push_back(window.plots()->plot(p));
    // When the last kinematics plot has replotted with the edit's result: the readout and the
    // contour view still show the previous one.
    int replotted = 0;
    QString readoutThen;
    int contourReplotsThen = -1;
    int contourReplots = 0;
    bool edited = false;
    QObject::connect(window.contourView(), &QCustomPlot::afterReplot, [&] { ++contourReplots; });
    for (QCustomPlot* plot : plots) {
        QObject::connect(plot, &QCustomPlot::afterReplot, [&] {
            if (edited && ++replotted == static_cast<int>(plots.size())) {
                readoutThen = window.readout()->text();
                contourReplotsThen = contourReplots;
            }
        });
    }
    edited = true;
    window.tableModel()->setData(window.tableModel()->index(0, SegmentTableModel::Type), 1,
                                 Qt::EditRole);
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    processUntil([&] { return window.readout()->text() != readoutBefore; });
    ASSERT_EQ(replotted, static_cast<int>(plots.size()));
    EXPECT_EQ(readoutThen, readoutBefore);
    EXPECT_EQ(contourReplotsThen, 0);
    // And then they do: the readout reads the line, the contour view is redrawn.
    EXPECT_NE(window.readout()->text(), readoutBefore);
    EXPECT_GE(contourReplots, 1);
}

}  // namespace
}  // namespace cam
