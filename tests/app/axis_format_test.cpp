// Every plot axis of the window writes its tick labels by one policy (views/axis_format.h):
// the user's decimal separator and a power of ten as "·10⁶" in English and German alike, never
// QCustomPlot's German "7,5E+06". The expected labels are written by hand from the policy.

#include <gtest/gtest.h>

#include <qcustomplot.h>

#include "mainwindow.h"
#include "translations.h"
#include "views/axis_format.h"

namespace cam {
namespace {

const QLocale kGermanAxes(QLocale::German, QLocale::Germany);
const QLocale kEnglishAxes(QLocale::English, QLocale::UnitedStates);

/// The window's language and number format for one test, restored after it.
struct AxisLanguage {
    explicit AxisLanguage(const QLocale& locale) : translations(locale) {
        QLocale::setDefault(locale);
    }
    ~AxisLanguage() { QLocale::setDefault(QLocale::c()); }
    Translations translations;
};

TEST(AxisFormat, TickLabelsFollowOnePolicyInBothLanguages) {
    EXPECT_EQ(axisTickLabel(7.5e6, kGermanAxes), QStringLiteral("7,5·10⁶"));
    EXPECT_EQ(axisTickLabel(7.5e6, kEnglishAxes), QStringLiteral("7.5·10⁶"));
    EXPECT_EQ(axisTickLabel(0.25, kGermanAxes), QStringLiteral("0,25"));
    EXPECT_EQ(axisTickLabel(0.25, kEnglishAxes), QStringLiteral("0.25"));
    EXPECT_EQ(axisTickLabel(-2.5e-5, kGermanAxes), QStringLiteral("-2,5·10⁻⁵"));
    EXPECT_EQ(axisTickLabel(120000, kGermanAxes), QStringLiteral("120000"));  // no "120.000"
    EXPECT_EQ(axisTickLabel(1e6, kEnglishAxes), QStringLiteral("1·10⁶"));
    EXPECT_EQ(axisTickLabel(999999.7, kEnglishAxes), QStringLiteral("1·10⁶"));
    EXPECT_EQ(axisTickLabel(0.0, kGermanAxes), QStringLiteral("0"));
}

TEST(AxisFormat, EveryPlotOfTheWindowWritesItsTicksByThePolicy) {
    for (const QLocale& locale : {kGermanAxes, kEnglishAxes}) {
        const AxisLanguage language(locale);
        MainWindow window;
        const auto plots = window.findChildren<QCustomPlot*>();
        ASSERT_GE(plots.size(), 8);
        const QString separator = locale == kGermanAxes ? QStringLiteral(",") : QStringLiteral(".");
        for (QCustomPlot* plot : plots) {
            plot->resize(500, 300);
            QCPAxis* axis = plot->yAxis;
            axis->setTickLabels(true);
            axis->setRange(0, 1.5e7);
            plot->replot();
            const QStringList big = axis->tickVectorLabels().toList();
            axis->setRange(0, 1);
            plot->replot();
            const QStringList small = axis->tickVectorLabels().toList();
            const std::string name = plot->objectName().toStdString();
            ASSERT_FALSE(big.isEmpty()) << name;
            for (const QString& tick : big + small) {
                EXPECT_FALSE(tick.contains('E') || tick.contains('e'))
                    << name << ": " << tick.toStdString();
            }
            EXPECT_TRUE(big.join(' ').contains(QStringLiteral("·10⁶")))
                << name << ": " << big.join(' ').toStdString();
            EXPECT_TRUE(small.join(' ').contains(QStringLiteral("0") + separator))
                << name << ": " << small.join(' ').toStdString();
        }
    }
}

}  // namespace
}  // namespace cam
