// How the window writes numbers: the user's decimal separator, no thousands separators, and
// round-off of an exact zero as 0 — in the policy itself and where a user reads it.

#include <gtest/gtest.h>

#include <QLabel>
#include <QLocale>
#include <cmath>
#include <limits>
#include <tuple>

#include "app_test_support.h"
#include "document/commands.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "widgets/number_format.h"
#include "widgets/number_spin_box.h"

namespace cam {
namespace {

/// The default locale for one test, restored after it.
struct DefaultLocale {
    explicit DefaultLocale(const QLocale& locale) { QLocale::setDefault(locale); }
    ~DefaultLocale() { QLocale::setDefault(QLocale::c()); }
};

TEST(NumberFormat, RoundOffIsZeroAndNoThousandsSeparators) {
    const DefaultLocale english(QLocale(QLocale::English, QLocale::UnitedStates));
    EXPECT_EQ(formatNumber(1.279561153e-15, 10), "0");
    EXPECT_EQ(formatNumber(-3.151937812e-15, 10), "0");
    EXPECT_EQ(formatNumber(-0.0, 10), "0");
    EXPECT_EQ(formatNumber(-40298.521, 8), "-40298.521");  // en_US would group: -40,298.521
    EXPECT_EQ(formatNumber(215.60000000000002, 10), "215.6");
    EXPECT_EQ(formatNumber(2e-9, 3), "2E-09");  // above round-off: a value, shown as one
    EXPECT_EQ(formatNumber(12345.678, 7), "12345.68");
}

TEST(NumberFormat, ALargeValueIsWrittenWholeNeverWithAnExponent) {
    // %g would write 4.07473E+08: from 10^digits up the rounded value is written whole.
    const DefaultLocale english(QLocale(QLocale::English, QLocale::UnitedStates));
    EXPECT_EQ(formatNumber(407472740.8, 6), "407473000");
    EXPECT_EQ(formatNumber(-407472740.8, 6), "-407473000");
    EXPECT_EQ(formatNumber(999999.7, 6), "1000000");  // rounds up to 10^6: whole too
    EXPECT_EQ(formatNumber(999999.4, 6), "999999");
    EXPECT_EQ(formatNumber(123456.4, 6), "123456");
    EXPECT_EQ(formatNumber(std::numeric_limits<double>::infinity(), 6), "∞");
    EXPECT_EQ(formatNumber(-std::numeric_limits<double>::infinity(), 6), "-∞");
}

TEST(NumberFormat, GermanHasADecimalCommaAndStillNoGroups) {
    const DefaultLocale german(QLocale(QLocale::German, QLocale::Germany));
    EXPECT_EQ(formatNumber(-40298.521, 8), "-40298,521");  // de_DE would group: -40.298,521
    EXPECT_EQ(formatNumber(1.279561153e-15, 10), "0");
    EXPECT_EQ(formatNumber(1234.5, 6), "1234,5");
    EXPECT_EQ(formatNumber(123456789.0, 6), "123457000");  // whole, and still no groups
}

TEST(NumberFormat, AnExponentIsWrittenTheSameWayInEveryLanguage) {
    // Issue 31: English boxes (the C locale) wrote 1e-06, German ones 1E-06.
    for (const QLocale& locale : {QLocale::c(), QLocale(QLocale::English, QLocale::UnitedStates),
                                  QLocale(QLocale::German, QLocale::Germany)}) {
        const DefaultLocale chosen(locale);
        const QString decimal = locale.decimalPoint();
        EXPECT_EQ(formatNumber(1e-6, 6), "1E-06") << locale.name().toStdString();
        EXPECT_EQ(formatNumber(-2.5e-5, 6), "-2" + decimal + "5E-05")
            << locale.name().toStdString();
        NumberSpinBox box;
        box.setLocale(locale);
        box.setRange(-1.0, 1.0);
        box.setValue(1e-6);
        EXPECT_EQ(box.text(), "1E-06") << locale.name().toStdString();
        // And it reads back what it shows, and what a file or the other form writes.
        EXPECT_EQ(box.valueFromText("1E-06"), 1e-6);
        EXPECT_EQ(box.valueFromText("1e-06"), 1e-6);
    }
    EXPECT_EQ(withCapitalExponent("nan", std::nan("")), "nan");
}

TEST(NumberFormat, TheTableShowsRoundOffAsZeroButKeepsTheExactValue) {
    const DefaultLocale english(QLocale(QLocale::English, QLocale::UnitedStates));
    MainWindow window;
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::examplePath("six-lobe-arc-cam.cam.json")))
            .isEmpty());
    const SegmentTableModel* model = window.tableModel();
    // Lobe 3's centre is on the y axis, lobe 6's on the x axis, as computed by the seed.
    const QModelIndex x3 = model->index(3, SegmentTableModel::CenterX);
    const QModelIndex y6 = model->index(6, SegmentTableModel::CenterY);
    EXPECT_EQ(x3.data(Qt::DisplayRole).toString(), "0");
    EXPECT_EQ(y6.data(Qt::DisplayRole).toString(), "0");
    EXPECT_EQ(x3.data(Qt::EditRole).toDouble(),
              window.document()->project().contour[3].as<Arc>()->center.x());
    EXPECT_NE(x3.data(Qt::EditRole).toDouble(), 0.0);  // only the display rounds
    EXPECT_EQ(model->index(6, SegmentTableModel::CenterX).data(Qt::DisplayRole).toString(),
              "-25.73752542");
}

TEST(NumberFormat, TheMotionSummaryHasNoThousandsSeparatorsInEitherLanguage) {
    // 1,500 rpm is 157.08 rad/s and a period of 0.04 s: the summary beside the speed once
    // wrote "1,500 rpm" in English and "1.500 rpm" in German.
    for (const auto& [locale, rpm, omega, period] :
         {std::tuple{QLocale(QLocale::English, QLocale::UnitedStates), "· 1500 ", "157.08 rad/s",
                     "T = 0.04 s"},
          std::tuple{QLocale(QLocale::German, QLocale::Germany), "· 1500 ", "157,08 rad/s",
                     "T = 0,04 s"}}) {
        const DefaultLocale shown(locale);
        MainWindow window;
        ASSERT_TRUE(
            window.loadFile(QString::fromStdString(test::examplePath("six-lobe-arc-cam.cam.json")))
                .isEmpty());
        window.document()->undoStack()->push(
            new SetMotion(window.document(), MotionSpec{SpeedUnit::Rpm, 1500.0}));
        const auto* summary = window.findChild<QLabel*>("motionSummary");
        ASSERT_NE(summary, nullptr);
        const QString text = summary->text();
        EXPECT_TRUE(text.contains(rpm)) << text.toStdString();
        EXPECT_TRUE(text.contains(omega)) << text.toStdString();  // 50π = 157.0796…
        EXPECT_TRUE(text.contains(period)) << text.toStdString();
    }
}

}  // namespace
}  // namespace cam
