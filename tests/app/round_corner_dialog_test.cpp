// Round Corner (issue 31, point 5), driven as a designer drives it: Ctrl+R on the segment after
// the corner opens the dialog, which shows what bounds the radius before it is chosen. On a
// polygon cam with a notch (a concave corner) and a 3 mm cutter, a 3 mm switch arc is refused
// in the dialog (it named the cutter only after the Machining dock failed, before); the seed's
// speed-based radius rho_min = V² / (vae · ACv) is written out here: V = 20 mm/s,
// ACv = 500 mm/s², vae = 0.1 give 400 / 50 = 8 mm.

#include <gtest/gtest.h>

#include <qcustomplot.h>
#include <QAction>
#include <QApplication>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QTableView>
#include <QTest>
#include <QTimer>
#include <QUndoStack>
#include <fstream>

#include "app_test_support.h"
#include "dialogs/round_corner_dialog.h"
#include "document/project_document.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "views/machining_panel.h"
#include "views/stale_label.h"
#include "widgets/number_spin_box.h"

namespace cam {
namespace {

/// Counter-clockwise round the centre; the corner at (−8, 0) (joint 3) is concave.
constexpr const char* kNotched = R"({"format": "camwright", "version": 1,
  "motion": {"period_s": 1},
  "machining": {"axis_accel": [500, 800, 200], "feed_max": 20, "tool_radius": 3},
  "contour": [{"type": "line", "from": [20, -15], "to": [20, 15]},
              {"type": "line", "from": [20, 15], "to": [-20, 15]},
              {"type": "line", "from": [-20, 15], "to": [-8, 0]},
              {"type": "line", "from": [-8, 0], "to": [-20, -15]},
              {"type": "line", "from": [-20, -15], "to": [20, -15]}]})";

struct Opened {
    test::TempDir dir;
    std::string path = dir.file("notched.cam.json");
};

/// Writes the notched cam to `file`, opens it in `window` and shows the window.
bool openNotched(MainWindow& window, const Opened& file) {
    std::ofstream(file.path) << kNotched;
    if (!window.loadFile(QString::fromStdString(file.path)).isEmpty()) return false;
    window.show();
    return QTest::qWaitForWindowExposed(&window);
}

/// Types `text` over a box's value without Enter (Enter is the dialog's OK).
void typeOver(NumberSpinBox* box, const QString& text) {
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, text);
    box->interpretText();
}

/// Selects `row`, presses Ctrl+R and runs `drive` on the dialog once it is open.
void roundCornerAt(MainWindow& window, int row,
                   const std::function<void(RoundCornerDialog&)>& drive) {
    auto* table = window.findChild<QTableView*>("segmentTable");
    table->setFocus();
    table->selectRow(row);
    bool driven = false;
    QTimer::singleShot(0, [&] {
        auto* dialog = qobject_cast<RoundCornerDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(dialog, nullptr);
        drive(*dialog);
        driven = true;
        if (dialog->isVisible()) dialog->reject();
    });
    QTest::keyClick(table, Qt::Key_R, Qt::ControlModifier);
    EXPECT_TRUE(driven);
}

TEST(RoundCornerDialogTest, TheCutterBoundsAConcaveArcAndTheSpeedGivesTheSeedsRadius) {
    Opened file;
    MainWindow window;
    ASSERT_TRUE(openNotched(window, file));
    const int steps = window.document()->undoStack()->count();
    roundCornerAt(window, 3, [](RoundCornerDialog& d) {
        EXPECT_EQ(d.cutterBound(), 3.0);
        ASSERT_NE(d.findChild<QLabel*>("cutterLabel"), nullptr);
        EXPECT_TRUE(d.findChild<QLabel*>("cutterLabel")->text().contains("3 mm"));
        auto* radius = d.findChild<NumberSpinBox*>("radiusSpinBox");
        QPushButton* ok = d.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
        typeOver(radius, "3");
        EXPECT_FALSE(ok->isEnabled());
        EXPECT_TRUE(d.findChild<QLabel*>("verdictLabel")->text().contains("cutter"));
        typeOver(radius, "3.5");
        EXPECT_TRUE(ok->isEnabled());
        // The seed's radius from the speed: started from the project (feed 20 mm/s, the
        // smaller of x and y 500 mm/s²), vae 0.1.
        EXPECT_EQ(d.findChild<NumberSpinBox*>("speedSpinBox")->value(), 20.0);
        EXPECT_EQ(d.findChild<NumberSpinBox*>("accelSpinBox")->value(), 500.0);
        typeOver(d.findChild<NumberSpinBox*>("vaeSpinBox"), "0.1");
        EXPECT_NEAR(d.speedRadius(), 8.0, 1e-12);
        EXPECT_TRUE(d.findChild<QLabel*>("speedRadiusLabel")->text().endsWith("= 8 mm"))
            << d.findChild<QLabel*>("speedRadiusLabel")->text().toStdString();
        QTest::mouseClick(d.findChild<QPushButton*>("useSpeedRadius"), Qt::LeftButton);
        EXPECT_EQ(radius->value(), 8.0);
        QTest::mouseClick(ok, Qt::LeftButton);
    });
    const Project& p = window.document()->project();
    ASSERT_EQ(p.contour.size(), 6u);
    const Arc* arc = p.contour[3].as<Arc>();
    ASSERT_NE(arc, nullptr);
    EXPECT_EQ(arc->radius, 8.0);
    EXPECT_EQ(arc->branch, Branch::Inner);  // the concave corner's
    EXPECT_EQ(window.document()->undoStack()->count(), steps + 1);
}

TEST(RoundCornerDialogTest, AConvexCornerHasNoCutterBoundAndTooLargeIsRefusedInTheDialog) {
    Opened file;
    MainWindow window;
    ASSERT_TRUE(openNotched(window, file));
    roundCornerAt(window, 1, [](RoundCornerDialog& d) {
        EXPECT_FALSE(d.cutterBound().has_value());
        EXPECT_EQ(d.findChild<QLabel*>("cutterLabel"), nullptr);
        auto* radius = d.findChild<NumberSpinBox*>("radiusSpinBox");
        QPushButton* ok = d.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
        typeOver(radius, "1");
        EXPECT_EQ(radius->value(), 1.0);
        EXPECT_TRUE(ok->isEnabled());
        EXPECT_TRUE(d.findChild<QLabel*>("fitsLabel")->text().startsWith("Below "));
        // At the bound itself: refused with the bound named.
        radius->setValue(radius->maximum());
        EXPECT_FALSE(ok->isEnabled());
        EXPECT_TRUE(d.findChild<QLabel*>("verdictLabel")->text().contains("does not fit"));
    });
    EXPECT_EQ(window.document()->project().contour.size(), 5u);  // cancelled
}

TEST(RoundCornerDialogTest, AFilletTheCutterCannotFollowLeavesNoMachiningPlotInColour) {
    // Rounded by the window's test entry (no dialog) to 3 mm with the 3 mm cutter: the
    // Machining dock has no time for that path, and its plots must not keep the last path's
    // curves as if they were this one's.
    Opened file;
    MainWindow window;
    ASSERT_TRUE(openNotched(window, file));
    window.findChild<QDockWidget*>("machiningDock")->show();
    const auto timed = [&] {
        return test::processEventsUntil([&] {
            const auto& t = window.engine()->latestTiming();
            return t && t->generation == window.engine()->latestGeneration();
        });
    };
    ASSERT_TRUE(timed());
    QCustomPlot* feed = window.machiningPanel()->feedPlot();
    ASSERT_GT(feed->graph(0)->dataCount(), 0);
    EXPECT_TRUE(window.roundCorner(3, 3.0).isEmpty());
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    test::processEventsUntil([] { return false; }, 300);
    const bool timedAgain =
        window.engine()->latestTiming() &&
        window.engine()->latestTiming()->generation == window.engine()->latestGeneration();
    const bool shownInColour =
        feed->graph(0)->dataCount() > 0 && feed->graph(0)->pen().color() != staleColor();
    EXPECT_FALSE(shownInColour && !(timedAgain && window.engine()->latestTiming()->errors.empty()))
        << "the feed plot shows an earlier path's curve in colour";
}

}  // namespace
}  // namespace cam
