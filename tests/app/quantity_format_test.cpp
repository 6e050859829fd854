// One table of digits and units for every number the window shows (widgets/quantity_format.h):
// the table itself and its strings in English and German. Expected strings are written by
// hand from the rule (significant digits, %g, whole from 10^digits up, round-off as 0).

#include <gtest/gtest.h>

#include <QLocale>
#include <limits>

#include "translations.h"
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

const QLocale kEnglish(QLocale::English, QLocale::UnitedStates);
const QLocale kGerman(QLocale::German, QLocale::Germany);

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
    const ShownLanguage english(kEnglish);
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
    const ShownLanguage german(kGerman);
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

}  // namespace
}  // namespace cam
