// The contour view and the plots as a user drives them: a project that cannot be computed is
// shown as out of date (edit, undo, redo).

#include <gtest/gtest.h>

#include <QImage>
#include <QLabel>
#include <cmath>

#include "app_test_support.h"
#include "common/angles.h"
#include "document/commands.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "models/arc_table_model.h"
#include "views/contour_view.h"
#include "views/kinematics_plots.h"
#include "views/palette.h"
#include "views/state_readout.h"

#include <qcustomplot.h>

namespace cam {
namespace {

const QString kExample = QString::fromStdString(test::examplePath("six-lobe-arc-cam.cam.json"));

TEST(ContourView, AProjectThatCannotBeComputedIsShownGreyedAndLabelled) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(kExample).isEmpty());
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    ArcTableModel* model = window.tableModel();
    ContourView* view = window.contourView();
    KinematicsPlots* plots = window.plots();
    const QModelIndex radius = model->index(2, ArcTableModel::Radius);
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
        EXPECT_EQ(labelSays(contourLabel, "contour[2].radius"), stale) << when;
        EXPECT_EQ(labelSays(plotsLabel, "contour[2].radius"), stale) << when;
        EXPECT_EQ(view->staleReason().contains("contour[2].radius"), stale) << when;
        EXPECT_EQ(plots->staleReason().contains("contour[2].radius"), stale) << when;
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
    EXPECT_TRUE(contourLabel && contourLabel->text().startsWith("Not computed: contour[2].radius"));
    EXPECT_TRUE(window.findChild<QLabel*>("computeLabel")->text().contains("not computed"));

    window.document()->undoStack()->undo();
    EXPECT_DOUBLE_EQ(model->data(radius, Qt::EditRole).toDouble(), before);
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    expectStale(false, "after undo");
    // What is drawn is the document as it is now: segment 2 on its circle again.
    const SegmentSpec& s = window.document()->project().contour[2];
    int checked = 0;
    for (int i = 0; i < view->plottableCount(); ++i) {
        auto* c = qobject_cast<QCPCurve*>(view->plottable(i));
        if (!c || c->name() != "segment 2") continue;
        for (auto it = c->data()->constBegin(); it != c->data()->constEnd(); ++it) {
            EXPECT_NEAR(std::hypot(it->key - s.center.x(), it->value - s.center.y()), s.radius,
                        1e-9);
            ++checked;
        }
    }
    EXPECT_GT(checked, 100);

    window.document()->undoStack()->redo();
    EXPECT_DOUBLE_EQ(model->data(radius, Qt::EditRole).toDouble(), -1.0);
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    expectStale(true, "after redo");
}

}  // namespace
}  // namespace cam
