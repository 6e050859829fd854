// One table of digits and units for every number the window shows (widgets/quantity_format.h):
// the table itself, its strings in English and German, and the views that show them — the
// readout, the Joints tab and the follower checks — each with the table's digits, not its own.
// Expected strings are written by hand from the rule (significant digits, %g, whole from
// 10^digits up, round-off as 0) and the core's values (math.md §3, camwright-cli analyze).

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDockWidget>
#include <QEvent>
#include <QLabel>
#include <QLocale>
#include <QVBoxLayout>
#include <limits>

#include "app_test_support.h"
#include "common/angles.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "translations.h"
#include "views/follower_panel.h"
#include "views/joints_panel.h"
#include "views/state_readout.h"
#include "widgets/quantity_format.h"

namespace cam {
namespace {

using Q = DisplayQuantity;

/// The window's language and number format for one test, restored after it.
struct ShownLanguage {
    explicit ShownLanguage(const QLocale& locale) : translations(locale) {
        QLocale::setDefault(locale);
    }
    ~ShownLanguage() { QLocale::setDefault(QLocale::c()); }
    Translations translations;
};

const QLocale kEnglishQuantities(QLocale::English, QLocale::UnitedStates);
const QLocale kGermanQuantities(QLocale::German, QLocale::Germany);

/// The significant digits of a number as shown ("-0.001230" has 4; "407473000" has 9).
int significantDigits(const QString& number) {
    QString digits;
    for (const QChar c : number) {
        if (c.isDigit()) digits += c;
    }
    while (digits.startsWith('0')) digits.remove(0, 1);
    return static_cast<int>(digits.size());
}

/// The readout's value of the row `name`, without its unit ("r 26.21882 mm" → "26.21882").
QString readoutNumber(const StateReadout& readout, const QString& name) {
    for (const QString& line : readout.text().split('\n')) {
        const QStringList parts = line.split(' ');
        if (parts.size() >= 2 && parts[0] == name) return QString(parts[1]).remove(QChar(u'°'));
    }
    return {};
}

TEST(QuantityFormat, EveryQuantityHasItsDigitsAndAUnitUnlessItIsAPureNumber) {
    ASSERT_EQ(kQuantityFormats.size(), kQuantityCount);
    for (std::size_t i = 0; i < kQuantityCount; ++i) {
        const QuantityFormat& f = kQuantityFormats[i];
        EXPECT_EQ(f.quantity, static_cast<DisplayQuantity>(i)) << i;
        EXPECT_GE(f.significant, 3) << i;
        EXPECT_LE(f.significant, 10) << i;
        const bool pureNumber = f.quantity == Q::Ratio || f.quantity == Q::RelativeError ||
                                f.quantity == Q::Count || f.quantity == Q::Input;
        EXPECT_EQ(QString(f.unit).isEmpty(), pureNumber) << i;
    }
    // The digits a machine designer reads (the table's comments say why).
    EXPECT_EQ(quantityFormat(Q::Length).significant, 7);
    EXPECT_EQ(quantityFormat(Q::Angle).significant, 7);
    EXPECT_EQ(quantityFormat(Q::Jerk).significant, 6);
    EXPECT_EQ(quantityFormat(Q::Ratio).significant, 4);
    EXPECT_EQ(quantityFormat(Q::Input).significant, 10);
}

TEST(QuantityFormat, EnglishStringsByTheRule) {
    const ShownLanguage english(kEnglishQuantities);
    EXPECT_EQ(formatQuantity(Q::Length, 123.456789), "123.4568 mm");
    EXPECT_EQ(formatQuantity(Q::Length, -25.737525423), "-25.73753 mm");
    EXPECT_EQ(formatQuantity(Q::Length, 1e-15), "0 mm");  // round-off of an exact 0
    EXPECT_EQ(formatQuantity(Q::Length, -0.0), "0 mm");
    EXPECT_EQ(formatQuantity(Q::Length, 5.999999999999989), "6 mm");
    EXPECT_EQ(formatQuantity(Q::Length, 1234.5), "1234.5 mm");  // no thousands separator
    EXPECT_EQ(formatQuantity(Q::Angle, 359.99994), "359.9999°");
    EXPECT_EQ(formatQuantity(Q::Angle, 45.00000000000001), "45°");
    EXPECT_EQ(formatQuantity(Q::Angle, -0.0), "0°");
    EXPECT_EQ(formatQuantity(Q::Velocity, 411.844327435), "411.844 mm/s");
    EXPECT_EQ(formatQuantity(Q::Velocity, 999999.7), "1000000 mm/s");  // not 1E+06
    EXPECT_EQ(formatQuantity(Q::Acceleration, -40298.5214382), "-40298.5 mm/s²");
    // From 10⁶ up, whole and rounded to six digits, never 4.07473E+08.
    EXPECT_EQ(formatQuantity(Q::Jerk, 407472740.79828817), "407473000 mm/s³");
    EXPECT_EQ(formatQuantity(Q::Jerk, -123456789012.0), "-123457000000 mm/s³");
    EXPECT_EQ(formatQuantity(Q::Time, 0.05), "0.05 s");
    EXPECT_EQ(formatQuantity(Q::Time, 12.3456789), "12.3457 s");
    EXPECT_EQ(formatQuantity(Q::Duration, 12.345), "12.3 ms");
    EXPECT_EQ(formatQuantity(Q::Duration, 0.41234), "0.412 ms");
    EXPECT_EQ(formatQuantity(Q::Duration, 1234.5), "1230 ms");
    EXPECT_EQ(formatQuantity(Q::AngularSpeed, 157.07963267948966), "157.08 rad/s");  // 50π
    EXPECT_EQ(formatQuantity(Q::RotationSpeed, 1500.0), "1500 rpm");
    EXPECT_EQ(formatQuantity(Q::Ratio, 6.283185307), "6.283");
    EXPECT_EQ(formatQuantity(Q::Ratio, 0.99987), "0.9999");
    EXPECT_EQ(formatQuantity(Q::LengthError, 0.00123456), "0.00123 mm");
    EXPECT_EQ(formatQuantity(Q::LengthError, 2.5e-5), "2.5E-05 mm");  // below 10⁻⁴: %g's form
    EXPECT_EQ(formatQuantity(Q::AngleError, 0.0123456), "0.0123°");
    EXPECT_EQ(formatQuantity(Q::AngularVelocityError, 1.23456), "1.23 °/s");
    EXPECT_EQ(formatQuantity(Q::AccelerationError, 98765.4), "98800 mm/s²");
    EXPECT_EQ(formatQuantity(Q::RelativeError, 0.012345), "0.0123");
    EXPECT_EQ(formatQuantity(Q::Count, 10000000.0), "10000000");
    EXPECT_EQ(formatQuantity(Q::Count, 2.6), "3");
    EXPECT_EQ(formatQuantity(Q::Input, 215.60000000000002), "215.6");
    EXPECT_EQ(formatQuantity(Q::Input, -25.737525422714), "-25.73752542");
    EXPECT_EQ(formatQuantityValue(Q::Length, 123.456789), "123.4568");
    EXPECT_EQ(formatQuantityValue(Q::Angle, 50.308589201268575), "50.30859");
    EXPECT_EQ(formatQuantity(Q::Length, std::numeric_limits<double>::infinity()), "∞ mm");
    EXPECT_EQ(formatPoint(12.5, -3.0), "(12.5, -3)");
    EXPECT_EQ(formatPoint(-18.0970001, 1e-16), "(-18.097, 0)");
}

TEST(QuantityFormat, GermanStringsByTheRule) {
    const ShownLanguage german(kGermanQuantities);
    ASSERT_TRUE(german.translations.appTranslated());
    EXPECT_EQ(formatQuantity(Q::Length, 123.456789), "123,4568 mm");
    EXPECT_EQ(formatQuantity(Q::Length, 1e-15), "0 mm");
    EXPECT_EQ(formatQuantity(Q::Length, -1234.5), "-1234,5 mm");  // de_DE would write -1.234,5
    EXPECT_EQ(formatQuantity(Q::Angle, 359.99994), "359,9999°");
    EXPECT_EQ(formatQuantity(Q::Acceleration, -40298.5214382), "-40298,5 mm/s²");
    EXPECT_EQ(formatQuantity(Q::Jerk, 407472740.79828817), "407473000 mm/s³");
    EXPECT_EQ(formatQuantity(Q::Time, 0.05), "0,05 s");
    EXPECT_EQ(formatQuantity(Q::AngularSpeed, 157.07963267948966), "157,08 rad/s");
    EXPECT_EQ(formatQuantity(Q::RotationSpeed, 1500.0), "1500 U/min");  // a word, translated
    EXPECT_EQ(formatQuantity(Q::Ratio, 6.283185307), "6,283");
    EXPECT_EQ(formatQuantity(Q::Duration, 12.345), "12,3 ms");
    EXPECT_EQ(formatQuantity(Q::Input, -25.737525422714), "-25,73752542");
    // A comma between the coordinates would read as a decimal one.
    EXPECT_EQ(formatPoint(12.5, -3.0), "(12,5; -3)");
}

TEST(QuantityFormat, TheReadoutShowsEachRowWithItsQuantitysDigitsAndUnit) {
    KinematicState s;
    s.t = 0.05;
    s.phi = -kPi / 4.0;  // clockwise: 315° on the cam
    s.segment = 1;
    s.polar.r = 123.456789;
    s.motion =
        PolarMotion{-369.148280152, 411.844327435,      553.0638, -40298.5214382, -11597.1352501,
                    41934.0567,     407472740.79828817, -1.5e-12, 123456789012.0};
    StateReadout readout;
    readout.setState(s);
    EXPECT_EQ(readout.text(), QStringLiteral("t 0.05 s\n"
                                             "φ 315°\n"
                                             "segment 1\n"
                                             "r 123.4568 mm\n"
                                             "v_r -369.148 mm/s\n"
                                             "v_φ 411.844 mm/s\n"
                                             "|v| 553.064 mm/s\n"
                                             "a_r -40298.5 mm/s²\n"
                                             "a_φ -11597.1 mm/s²\n"
                                             "|a| 41934.1 mm/s²\n"
                                             "j_r 407473000 mm/s³\n"
                                             "j_φ 0 mm/s³\n"
                                             "|j| 123457000000 mm/s³"));
    // The readout's own 8 digits of before would show r as 123.45679.
    EXPECT_EQ(significantDigits(readoutNumber(readout, "r")),
              quantityFormat(Q::Length).significant);
    EXPECT_EQ(significantDigits(readoutNumber(readout, "v_φ")),
              quantityFormat(Q::Velocity).significant);
    // Its column is as wide as a long value of the table: nothing jumps as the cursor moves.
    s.polar.r = -0.000888888888;
    readout.setState(s);
    const QString widest = readout.text().split('\n')[3].mid(2);
    EXPECT_EQ(widest, "-0.0008888889 mm");
    for (const QLabel* value : readout.findChildren<QLabel*>()) {
        if (value->text() != widest) continue;
        EXPECT_GE(value->minimumWidth(), value->fontMetrics().horizontalAdvance(widest));
    }
}

TEST(QuantityFormat, ANewStateAsksForNoLayoutPassAndAWiderValueWidensItsLabel) {
    const ShownLanguage english(kEnglishQuantities);
    QWidget dock;
    auto* readout = new StateReadout(&dock);
    auto* layout = new QVBoxLayout(&dock);
    layout->addWidget(readout);
    dock.show();
    QCoreApplication::processEvents();
    // Layout passes the readout asks for while states come in (one per edit and cursor move).
    struct LayoutRequests : QObject {
        int count = 0;
        bool eventFilter(QObject*, QEvent* event) override {
            if (event->type() == QEvent::LayoutRequest) ++count;
            return false;
        }
    } requests;
    readout->installEventFilter(&requests);
    KinematicState s;
    for (int k = 0; k < 20; ++k) {
        s.t = 0.001 * k;
        s.polar.r = 20.0 + 0.37 * k;
        s.motion = PolarMotion{-369.1 * k, 411.8,  553.06,     -40298.5 * k, -11597.1,
                               41934.0,    4.07e8, -1.5e3 * k, 1.2e9};
        readout->setState(s);
        QCoreApplication::processEvents();
    }
    EXPECT_EQ(requests.count, 0);
    // A value wider than any the column was made for: its label widens, nothing is cut off.
    s.motion.j = -1.234567e15;
    readout->setState(s);
    QCoreApplication::processEvents();
    for (const QLabel* value : readout->findChildren<QLabel*>()) {
        EXPECT_GE(value->width(), value->fontMetrics().horizontalAdvance(value->text()))
            << value->text().toStdString();
    }
    EXPECT_TRUE(readout->text().endsWith("|j| -1234570000000000 mm/s³"))
        << readout->text().toStdString();
}

TEST(QuantityFormat, TheWindowReadsTheSixLobeCamWithTheTablesDigits) {
    // math.md §3: at t = 0.05 s r = 26.218824198 mm, v_φ = 411.844327435 mm/s,
    // a_r = -40298.5214382 mm/s²; the joint between lobe 0 and notch 1 at 9.691410798731°.
    const ShownLanguage english(kEnglishQuantities);
    MainWindow window;
    ASSERT_TRUE(window.loadFile(test::kExampleFile).isEmpty());
    window.show();
    ASSERT_TRUE(window.waitForCurrentResult(10000));
    window.setCursorTime(0.05);
    const QStringList lines = window.readout()->text().split('\n');
    EXPECT_TRUE(lines.contains("r 26.21882 mm")) << lines.join(" | ").toStdString();
    EXPECT_TRUE(lines.contains("v_φ 411.844 mm/s")) << lines.join(" | ").toStdString();
    EXPECT_TRUE(lines.contains("a_r -40298.5 mm/s²")) << lines.join(" | ").toStdString();
    EXPECT_TRUE(lines.contains("φ 45°")) << lines.join(" | ").toStdString();

    // The Joints tab: units in the headers, the table's digits in the cells (camwright-cli
    // analyze: φ 9.691410798731425°, Δa_r -494616.2731753 mm/s², relative jump 1.38732764).
    JointsPanel* joints = window.jointsPanel();
    ASSERT_GE(joints->rowCount(), 2);
    EXPECT_EQ(joints->item(0, 0)->text(), "0 | 1");
    EXPECT_EQ(joints->item(0, 1)->text(), "9.691411");
    EXPECT_EQ(joints->item(0, 5)->text(), "-494616");
    EXPECT_EQ(joints->item(0, 6)->text(), "1.387");
    EXPECT_EQ(joints->item(1, 1)->text(), "50.30859");
    EXPECT_EQ(significantDigits(joints->item(1, 1)->text()), quantityFormat(Q::Angle).significant);
}

TEST(QuantityFormat, TheFollowerChecksShowAnglesAndRadiiWithTheTablesDigits) {
    // camwright-cli analyze of the roller example: the largest pressure angle on rise is
    // 37.945095446524455° at 73.63043015917653°, limit 40°; the smallest radius of curvature
    // of the profile 5.999999999999989 mm at 90.16466528734792°, of the pitch curve
    // 10.99999999999999 mm there.
    const ShownLanguage english(kEnglishQuantities);
    MainWindow window;
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::examplePath("roller-lobe-cam.cam.json")))
            .isEmpty());
    window.show();
    window.findChild<QDockWidget*>("followerDock")->show();
    ASSERT_TRUE(window.waitForCurrentResult(20000));
    ASSERT_TRUE(test::processEventsUntil([&] {
        const auto& r = window.engine()->latestResult();
        return r && !r->followerChecksPending;
    }));
    const QStringList lines = window.followerPanel()->checkLines();
    ASSERT_GE(lines.size(), 3);
    EXPECT_EQ(lines[0], "Largest pressure angle on rise: 37.9451° at 73.63043° (limit 40°)");
    // A magnitude per phase (issue 29), not the signed minimum.
    EXPECT_EQ(lines[1], "Largest pressure angle on return: 37.9451° at 106.3696° (limit 40°)");
    EXPECT_TRUE(lines.contains("Smallest convex radius of the profile: 6 mm at 90.16467°"))
        << lines.join(" | ").toStdString();
    EXPECT_TRUE(
        lines.contains("Smallest convex radius of the pitch curve: 11 mm at 90.16467° (roller "
                       "radius 5 mm)"))
        << lines.join(" | ").toStdString();
}

}  // namespace
}  // namespace cam
