// Help: F1 opens the bundled user guide at the section of what has the focus, in the window's
// language; every link of the guide leads somewhere; every dock explains itself on What's This.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QCursor>
#include <QDockWidget>
#include <QFile>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTableView>
#include <QTest>
#include <QTextBrowser>

#include "app_test_support.h"
#include "dialogs/user_guide.h"
#include "mainwindow.h"
#include "translations.h"
#include "views/contour_view.h"

namespace cam {
namespace {

QString resource(const QString& path) {
    QFile file(path);
    EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << path.toStdString();
    return QString::fromUtf8(file.readAll());
}

const QStringList kSections{"start",  "table",  "construction", "splines", "plots", "followers",
                            "forces", "design", "machining",    "exports", "cli",   "files"};

TEST(UserGuide, BothLanguagesHaveEverySectionAndNoDeadLink) {
    for (const QString& language : {QString("en"), QString("de")}) {
        const QString html = resource(":/help/user-guide." + language + ".html");
        QStringList anchors;
        static const QRegularExpression name(R"re(<a name="([a-z]+)">)re");
        for (auto m = name.globalMatch(html); m.hasNext();) anchors << m.next().captured(1);
        EXPECT_EQ(anchors, kSections) << language.toStdString();
        static const QRegularExpression link(R"re(href="#([a-z]+)")re");
        for (auto m = link.globalMatch(html); m.hasNext();) {
            const QString target = m.next().captured(1);
            EXPECT_TRUE(anchors.contains(target))
                << language.toStdString() << ": #" << target.toStdString();
        }
    }
}

TEST(UserGuide, F1OpensTheGuideAtTheSectionOfTheFocusedDock) {
    MainWindow window;
    window.resize(1400, 860);
    window.show();
    QApplication::setActiveWindow(&window);
    QAction* f1 = window.findChild<QAction*>("actionUserGuide");
    ASSERT_NE(f1, nullptr);
    EXPECT_EQ(f1->shortcut(), QKeySequence(QKeySequence::HelpContents));

    window.findChild<QTableView*>("segmentTable")->setFocus();
    QApplication::processEvents();
    f1->trigger();
    ASSERT_NE(window.userGuide(), nullptr);
    EXPECT_TRUE(window.userGuide()->isVisible());
    QTextBrowser* text = window.userGuide()->browser();
    EXPECT_TRUE(text->toPlainText().contains("Getting started"));
    EXPECT_TRUE(text->toPlainText().contains("Tangent Line to Next Arc"));
    const int atTable = text->verticalScrollBar()->value();

    // The contour view's section lies further down than the table's. (Focus moves back to the
    // main window only on a real display; the mapping from a widget to its section is shown
    // here directly.)
    window.userGuide()->showSection(UserGuide::sectionFor(window.contourView()));
    EXPECT_GT(text->verticalScrollBar()->value(), atTable);
    EXPECT_EQ(UserGuide::sectionFor(window.contourView()), "construction");
    EXPECT_EQ(UserGuide::sectionFor(window.findChild<QDockWidget*>("forcesDock")), "forces");
    EXPECT_EQ(UserGuide::sectionFor(nullptr), "start");
}

TEST(UserGuide, F1OverTheContourViewOpensItsSectionWhateverHasTheFocus) {
    // Issue 31: F1 with the mouse over the contour view opened the guide at the segment table,
    // which had the focus.
    MainWindow window;
    window.resize(1400, 860);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    QApplication::setActiveWindow(&window);
    window.findChild<QTableView*>("segmentTable")->setFocus();
    QWidget* contour = window.contourView();
    QCursor::setPos(contour->mapToGlobal(contour->rect().center()));
    ASSERT_TRUE(contour->isAncestorOf(QApplication::widgetAt(QCursor::pos())) ||
                QApplication::widgetAt(QCursor::pos()) == contour);
    window.findChild<QAction*>("actionUserGuide")->trigger();
    ASSERT_NE(window.userGuide(), nullptr);
    window.userGuide()->showSection("construction");
    const int atConstruction = window.userGuide()->browser()->verticalScrollBar()->value();
    window.userGuide()->showSection("table");
    window.userGuide()->hide();  // offscreen, it opens over the window, under the mouse
    window.findChild<QAction*>("actionUserGuide")->trigger();
    EXPECT_EQ(window.userGuide()->browser()->verticalScrollBar()->value(), atConstruction);
    // The guide names places as the window does, never by a file key.
    for (const QString& language : {QString("en"), QString("de")}) {
        EXPECT_FALSE(resource(":/help/user-guide." + language + ".html").contains("contour["))
            << language.toStdString();
    }
}

TEST(UserGuide, TheGermanWindowShowsTheGermanGuide) {
    const Translations german(QLocale(QLocale::German, QLocale::Germany));
    ASSERT_TRUE(german.appTranslated());
    EXPECT_EQ(UserGuide::source(), ":/help/user-guide.de.html");
    UserGuide guide;
    EXPECT_TRUE(guide.browser()->toPlainText().contains("Erste Schritte"));
}

TEST(WhatsThis, EveryDockAndViewExplainsItself) {
    MainWindow window;
    EXPECT_NE(window.findChild<QAction*>("actionWhatsThis"), nullptr);
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) {
        EXPECT_GT(dock->whatsThis().size(), 40) << dock->objectName().toStdString();
    }
    EXPECT_FALSE(window.contourView()->whatsThis().isEmpty());
}

}  // namespace
}  // namespace cam
