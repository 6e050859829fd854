// Fit Windows in the window (issue 29, point 5): the seed's Table 1 typed with its two typos
// fixed becomes valid with one Fit Windows, one undo step, every change listed; while a project
// has problems its plots are greyed as not computed, never drawn as the cam's, and the contour
// view still draws the contour.

#include <gtest/gtest.h>

#include <QAction>
#include <QLabel>
#include <QMessageBox>
#include <QUndoStack>

#include "app_test_support.h"
#include "contour/fit_windows.h"
#include "document/contour_edits.h"
#include "document/project_document.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "views/contour_view.h"
#include "views/follower_panel.h"
#include "views/kinematics_plots.h"
#include "views/stale_label.h"
#include "views/state_readout.h"

#include <qcustomplot.h>

namespace cam {
namespace {

using test::kExampleFile;

const QString kTyped =
    QString::fromStdString(test::dataPath("seed-table/table1-typos-fixed.cam.json"));

void closeDetailsBoxes(MainWindow& window) {
    for (auto* box : window.findChildren<QMessageBox*>("editDetailsBox")) box->close();
    QCoreApplication::processEvents();
}

TEST(FitWindowsInWindow, TheSeedTableBecomesValidInOneUndoStepWithEveryChangeListed) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kTyped).isEmpty());
    ProjectDocument* document = window.document();
    const Project typed = document->project();
    ASSERT_FALSE(document->isValid());
    // What the core makes of it, to compare the window with.
    const auto core = fitWindows(typed.contour);
    ASSERT_TRUE(core.ok());
    ASSERT_FALSE(core.value().moves.empty());

    QUndoStack* stack = document->undoStack();
    const int steps = stack->count();
    auto* fit = window.findChild<QAction*>("actionFitWindows");
    ASSERT_NE(fit, nullptr);
    fit->trigger();
    EXPECT_TRUE(document->isValid()) << diagnosticsText(document->diagnostics()).toStdString();
    EXPECT_EQ(stack->count(), steps + 1);  // windows and moved circles: one step
    EXPECT_EQ(document->project().contour, core.value().contour);

    // Every change listed, one line each, in the window's words.
    auto* box = window.findChild<QMessageBox*>("editDetailsBox");
    ASSERT_NE(box, nullptr);
    const QStringList lines = box->informativeText().split('\n');
    ASSERT_EQ(lines.size(), static_cast<int>(core.value().moves.size()))
        << box->informativeText().toStdString();
    for (int i = 0; i < lines.size(); ++i) {
        const SegmentMove& m = core.value().moves[static_cast<std::size_t>(i)];
        EXPECT_TRUE(lines[i].startsWith(QStringLiteral("Segment %1").arg(m.segment)))
            << lines[i].toStdString();
        EXPECT_TRUE(lines[i].contains("typing tolerance")) << lines[i].toStdString();
    }
    EXPECT_TRUE(box->text().contains(QStringLiteral("%1 segment").arg(core.value().moves.size())))
        << box->text().toStdString();
    closeDetailsBoxes(window);

    stack->undo();
    EXPECT_EQ(document->project().contour, typed.contour);
    EXPECT_FALSE(document->isValid());
    stack->redo();
    EXPECT_TRUE(document->isValid());
    // Fitted once, nothing is left to fit.
    fit->trigger();
    EXPECT_EQ(stack->count(), steps + 1);
    EXPECT_EQ(window.findChild<QMessageBox*>("editDetailsBox"), nullptr);
}

TEST(FitWindowsInWindow, JointsThatCannotBeFittedAreNamedWithTheirGapAndNothingChanges) {
    MainWindow window;
    ASSERT_TRUE(window
                    .loadFile(QString::fromStdString(
                        test::dataPath("seed-table/table1-as-printed.cam.json")))
                    .isEmpty());
    ProjectDocument* document = window.document();
    const Project printed = document->project();
    const int steps = document->undoStack()->count();
    const EditOutcome outcome = ContourEdits::fitWindows(*document);
    ASSERT_FALSE(outcome.ok());
    // Lobe 3 at (−18.1, −18.1) misses notch 3 by |c4 − c5| − (R4 + R5), from the file's numbers.
    const Arc& a = *printed.contour[4].as<Arc>();
    const Arc& b = *printed.contour[5].as<Arc>();
    const double gap = (b.center - a.center).norm() - (a.radius + b.radius);
    EXPECT_NEAR(gap, 27.77966807, 1e-8);
    EXPECT_TRUE(outcome.problem.contains("Joint between segments 4 and 5"))
        << outcome.problem.toStdString();
    EXPECT_TRUE(outcome.problem.contains("27.77966807 mm")) << outcome.problem.toStdString();
    EXPECT_TRUE(outcome.problem.contains("Joint between segments 0 and 1"))
        << outcome.problem.toStdString();
    EXPECT_EQ(document->undoStack()->count(), steps);
    EXPECT_EQ(document->project(), printed);
}

TEST(FitWindowsInWindow, APlainFitListsNothingAndSaysSo) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
    SegmentTableModel* model = window.tableModel();
    model->setData(model->index(1, SegmentTableModel::PhiEnd), 51.0, Qt::EditRole);
    model->setData(model->index(2, SegmentTableModel::PhiStart), 51.0, Qt::EditRole);
    window.findChild<QAction*>("actionFitWindows")->trigger();
    EXPECT_TRUE(window.document()->isValid());
    // Only windows moved: no list to read.
    EXPECT_EQ(window.findChild<QMessageBox*>("editDetailsBox"), nullptr);
}

TEST(FitWindowsInWindow, WhileTheProjectHasProblemsThePlotsAreGreyedAsNotComputed) {
    MainWindow window;
    window.resize(1400, 860);
    window.show();
    // A project opened with open joints: its plots show nothing as the cam's.
    ASSERT_TRUE(window.loadFile(kTyped).isEmpty());
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    KinematicsPlots* plots = window.plots();
    ContourView* view = window.contourView();
    const auto plotsLabel = [&] { return plots->findChild<QLabel*>("staleLabel"); };
    EXPECT_TRUE(plots->staleReason().startsWith("Not computed: "))
        << plots->staleReason().toStdString();
    EXPECT_TRUE(plots->staleReason().contains("do not meet")) << plots->staleReason().toStdString();
    EXPECT_TRUE(plotsLabel()->isVisible());
    // What they still hold is the new window's own cam, grey.
    EXPECT_EQ(plots->plot(1)->graph(0)->pen().color(), staleColor());
    // The contour view still draws the contour, not greyed.
    EXPECT_TRUE(view->staleReason().isEmpty()) << view->staleReason().toStdString();
    // The follower's checks are not made on it, its curves not drawn.
    auto* summary = window.followerPanel()->findChild<QLabel*>("designChecksSummary");
    ASSERT_NE(summary, nullptr);
    EXPECT_TRUE(summary->text().startsWith("No design checks: ")) << summary->text().toStdString();
    EXPECT_FALSE(window.followerPanel()->findChild<QWidget*>("pressureAnglePlot")->isVisible());
    // Nor is a state read out at the cursor, wherever it is put.
    window.contourView()->cursorAngleChanged(0.5);
    EXPECT_TRUE(window.readout()->text().startsWith("t —"))
        << window.readout()->text().toStdString();

    // Fitted: valid, drawn in colour.
    window.findChild<QAction*>("actionFitWindows")->trigger();
    closeDetailsBoxes(window);
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    EXPECT_TRUE(plots->staleReason().isEmpty()) << plots->staleReason().toStdString();
    EXPECT_FALSE(plotsLabel()->isVisible());
    EXPECT_GT(plots->plot(1)->graph(0)->dataCount(), 0);
    EXPECT_NE(plots->plot(1)->graph(0)->pen().color(), staleColor());
    window.contourView()->cursorAngleChanged(0.5);
    EXPECT_TRUE(window.readout()->text().startsWith("t 0.0318"))
        << window.readout()->text().toStdString();

    // A joint opened by an edit: the last valid curves stay, grey, under the reason.
    SegmentTableModel* model = window.tableModel();
    model->setData(model->index(1, SegmentTableModel::PhiEnd), 51.0, Qt::EditRole);
    model->setData(model->index(2, SegmentTableModel::PhiStart), 51.0, Qt::EditRole);
    ASSERT_FALSE(window.document()->isValid());
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    EXPECT_TRUE(plots->staleReason().startsWith("Not computed: "))
        << plots->staleReason().toStdString();
    EXPECT_TRUE(plots->staleReason().contains("segments 1 and 2"))
        << plots->staleReason().toStdString();
    EXPECT_EQ(plots->plot(1)->graph(0)->pen().color(), staleColor());
    EXPECT_GT(plots->plot(1)->graph(0)->dataCount(), 0);
    EXPECT_TRUE(view->staleReason().isEmpty()) << view->staleReason().toStdString();
    EXPECT_TRUE(window.readout()->text().startsWith("t —"))
        << window.readout()->text().toStdString();

    // Undone: valid again, in colour.
    window.document()->undoStack()->undo();
    window.document()->undoStack()->undo();
    ASSERT_TRUE(window.document()->isValid());
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    EXPECT_TRUE(plots->staleReason().isEmpty()) << plots->staleReason().toStdString();
    EXPECT_NE(plots->plot(1)->graph(0)->pen().color(), staleColor());
}

}  // namespace
}  // namespace cam
