// The docks keep the plots readable: the Segments dock takes the rows its contour has (a
// two-row project leaves the rest to the plots, a long one gets the height back), and a
// large Samples / turn does not widen the Motion dock.

#include <gtest/gtest.h>

#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QHeaderView>
#include <QSpinBox>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

#include "app_test_support.h"
#include "document/commands.h"
#include "mainwindow.h"
#include "views/kinematics_plots.h"

#include <qcustomplot.h>
#include "models/segment_table_model.h"

namespace cam {
namespace {

/// The window at the size of the development screen, shown.
class DockLayout : public ::testing::Test {
protected:
    void SetUp() override {
        window.resize(1400, 860);
        window.show();
    }
    /// Opens the design without a contour (its Motion Design dock in front) and lets the
    /// layout settle.
    bool openDesignProject() {
        const bool opened = window
                                .loadFile(QString::fromStdString(
                                    test::dataPath("app/design-roller-no-contour.cam.json")))
                                .isEmpty();
        test::processEventsUntil([] { return false; }, 100);
        return opened;
    }
    MainWindow window;
};

TEST_F(DockLayout, TheSegmentsDockTakesTheRowsItsContourHas) {
    QApplication::processEvents();
    auto* dock = window.findChild<QDockWidget*>("segmentsDock");
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    QApplication::processEvents();
    QApplication::processEvents();
    auto* table = window.findChild<QTableView*>("segmentTable");
    const int rowHeight = table->verticalHeader()->defaultSectionSize();
    const int longHeight = dock->height();
    EXPECT_GE(table->viewport()->height(), 6 * rowHeight);  // 13 rows: most of them shown

    window.findChild<QAction*>("actionNew")->trigger();  // two rows, unmodified: no prompt
    ASSERT_EQ(window.document()->project().contour.size(), 2u);
    QApplication::processEvents();
    QApplication::processEvents();
    // Room for four rows, not more: the plots get the rest.
    EXPECT_LE(table->viewport()->height(), 5 * rowHeight);
    EXPECT_GE(table->viewport()->height(), 4 * rowHeight);
    EXPECT_LT(dock->height(), longHeight);

    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    QApplication::processEvents();
    QApplication::processEvents();
    EXPECT_EQ(dock->height(), longHeight);  // the long contour gets its height back
}

TEST_F(DockLayout, TenMillionSamplesDoNotWidenTheMotionDock) {
    QApplication::processEvents();
    auto* motion = window.findChild<QDockWidget*>("motionDock");
    auto* samples = window.findChild<QSpinBox*>("samplesSpinBox");
    ASSERT_NE(samples, nullptr);
    const int width = motion->width();
    samples->setValue(10'000'000);
    QApplication::processEvents();
    EXPECT_EQ(motion->width(), width);
    EXPECT_EQ(samples->text(), "10000000");  // no group separators, as everywhere
}

// The Type and Branch cells' combo editors show their longest choice whole, also where the
// column, sized to the cells' text, is narrower than the editor needs.
TEST_F(DockLayout, ComboEditorsAreNeverClipped) {
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    QApplication::processEvents();
    auto* table = window.findChild<QTableView*>("segmentTable");
    for (int column : {SegmentTableModel::Type, SegmentTableModel::Branch}) {
        const QModelIndex index = window.tableModel()->index(1, column);
        table->setCurrentIndex(index);
        table->edit(index);
        QApplication::processEvents();
        auto* combo = table->findChild<QComboBox*>();
        ASSERT_NE(combo, nullptr) << column;
        EXPECT_GE(combo->width(), combo->sizeHint().width()) << column;
        table->closePersistentEditor(index);
        QTest::keyClick(combo, Qt::Key_Escape);
        QApplication::processEvents();
    }
}

// Opening every right-hand dock (Follower, Motion Design, Machining, Path Study) neither grows
// the window past its size (stacked, they asked for more height than the screen had, and the
// window's bottom went off the screen) nor squeezes the plots: they are tabs of one group, the
// one opened last in front.
TEST_F(DockLayout, TheRightHandDocksAreTabsAndTheWindowKeepsItsSize) {
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    // The layout settles first: the Segments dock takes its rows once the load has been laid
    // out, and the status bar its "computed" text once the plots have drawn the first result;
    // both lay the plots out again (a slow sanitizer build measured before them).
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    test::processEventsUntil([] { return false; }, 100);
    const int heightBefore = window.plots()->plot(0)->height();
    for (const char* name :
         {"followerDock", "forcesDock", "motionDesignDock", "machiningDock", "pathStudyDock"}) {
        auto* dock = window.findChild<QDockWidget*>(name);
        ASSERT_NE(dock, nullptr) << name;
        dock->toggleViewAction()->trigger();
        QApplication::processEvents();
        QApplication::processEvents();
        EXPECT_TRUE(dock->isVisible()) << name;
        EXPECT_FALSE(dock->visibleRegion().isEmpty()) << name << " is not the tab in front";
        EXPECT_EQ(window.height(), 860) << name;
        EXPECT_EQ(window.plots()->plot(0)->height(), heightBefore) << name;
    }
    EXPECT_EQ(window.tabifiedDockWidgets(window.findChild<QDockWidget*>("followerDock")).size(), 4);
}

TEST_F(DockLayout, SavingLeavesTheTabsAndTheFocusWhereTheyWere) {
    // Issue 31, point 7: Save (giving the file a new path) brought the Motion Design tab to
    // the front and the focus went with it; the next click landed on its Delete button.
    QApplication::setActiveWindow(&window);
    ASSERT_TRUE(openDesignProject());
    auto* design = window.findChild<QDockWidget*>("motionDesignDock");
    auto* follower = window.findChild<QDockWidget*>("followerDock");
    ASSERT_NE(design, nullptr);
    ASSERT_NE(follower, nullptr);
    // Opened, the project's design is the tab in front.
    EXPECT_FALSE(design->visibleRegion().isEmpty());
    follower->raise();
    test::processEventsUntil([] { return false; }, 50);
    auto* radius = follower->findChild<QWidget*>("followerRadiusSpinBox");
    ASSERT_NE(radius, nullptr);
    radius->setFocus();
    ASSERT_FALSE(follower->visibleRegion().isEmpty());
    QTemporaryDir dir;
    ASSERT_TRUE(window.saveFile(dir.filePath("saved.cam.json")).isEmpty());
    test::processEventsUntil([] { return false; }, 100);
    EXPECT_FALSE(follower->visibleRegion().isEmpty()) << "the Follower tab left the front";
    EXPECT_TRUE(design->visibleRegion().isEmpty());
    EXPECT_EQ(QApplication::focusWidget(), radius);
}

TEST_F(DockLayout, ASideDockGetsItsWidthBackWhenTheWindowGrowsAgain) {
    // Issue 31, point 7: shrunk and grown again, the window gave all the new room to the
    // centre, and the Motion Design dock stayed too narrow for its table.
    ASSERT_TRUE(openDesignProject());
    auto* design = window.findChild<QDockWidget*>("motionDesignDock");
    auto* motion = window.findChild<QDockWidget*>("motionDock");
    ASSERT_NE(design, nullptr);
    ASSERT_NE(motion, nullptr);
    ASSERT_FALSE(design->visibleRegion().isEmpty());
    // The user drags it wider than it opened.
    window.resizeDocks({design}, {520}, Qt::Horizontal);
    test::processEventsUntil([] { return false; }, 50);
    const int chosen = design->width();
    const int left = motion->width();
    EXPECT_GE(chosen, 500);
    for (int round = 0; round < 2; ++round) {
        window.resize(900, 600);
        test::processEventsUntil([] { return false; }, 50);
        EXPECT_LT(design->width(), chosen) << "the window had to take room from the dock";
        window.resize(1400, 860);
        test::processEventsUntil([] { return false; }, 50);
        EXPECT_EQ(design->width(), chosen) << round;
        EXPECT_EQ(motion->width(), left) << round;
    }
}

TEST_F(DockLayout, NoPlotWritesItsTickLabelsIntoOneAnother) {
    // A project with a roller and a motion design: every right-hand dock has plots, the Motion
    // Design dock four in little room. In each, with each dock in front, every axis leaves a
    // label's height between two labels up its side (and their half widths along the bottom).
    ASSERT_TRUE(window
                    .loadFile(QString::fromStdString(
                        test::examplePath("synthesised-cycloidal-roller.cam.json")))
                    .isEmpty());
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    int axesChecked = 0;
    const auto check = [&](const char* name) {
        auto* dock = window.findChild<QDockWidget*>(name);
        ASSERT_NE(dock, nullptr) << name;
        dock->show();
        dock->raise();
        test::processEventsUntil([] { return false; }, 150);  // laid out and replotted
        for (QCustomPlot* plot : window.findChildren<QCustomPlot*>()) {
            if (!plot->isVisible() || plot->visibleRegion().isEmpty()) continue;
            plot->replot(QCustomPlot::rpImmediateRefresh);
            for (QCPAxis* axis : plot->axisRect()->axes()) {
                if (!axis->visible() || !axis->tickLabels()) continue;
                const QVector<double> ticks = axis->tickVector();
                const QVector<QString> labels = axis->tickVectorLabels();
                const QFontMetricsF font(axis->tickLabelFont());
                for (qsizetype i = 1; i < ticks.size(); ++i) {
                    const double apart =
                        std::abs(axis->coordToPixel(ticks[i]) - axis->coordToPixel(ticks[i - 1]));
                    const double needed = axis->orientation() == Qt::Vertical
                                              ? font.height()
                                              : (font.horizontalAdvance(labels[i]) +
                                                 font.horizontalAdvance(labels[i - 1])) /
                                                    2.0;
                    EXPECT_GE(apart, needed)
                        << name << ": " << plot->objectName().toStdString() << " "
                        << labels[i - 1].toStdString() << " / " << labels[i].toStdString();
                }
                ++axesChecked;
            }
        }
    };
    for (const char* name : {"followerDock", "motionDesignDock", "pathStudyDock"}) check(name);
    // The Forces dock's three plots, on a project with dynamics.
    ASSERT_TRUE(window
                    .loadFile(QString::fromStdString(
                        test::examplePath("spring-loaded-roller-cam.cam.json")))
                    .isEmpty());
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    check("forcesDock");
    EXPECT_GE(axesChecked, 4 * 8);  // each pass: the four kinematics plots' axes and its own
}

}  // namespace
}  // namespace cam
