// The segment table's number editors driven as a user drives them: keys typed into the real
// cell editor of the real table view. Each test checks the document and the table, undoes,
// checks, redoes, checks (the LabPlot manner).

#include <gtest/gtest.h>

#include <QAbstractItemModelTester>
#include <QApplication>
#include <QStatusBar>
#include <QTableView>
#include <QTest>

#include "app_test_support.h"
#include "io/project_json.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "widgets/number_spin_box.h"

namespace cam {
namespace {

using test::kExampleFile;

class TableEditing : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
        window.resize(1400, 860);
        window.show();
        QApplication::setActiveWindow(&window);
        table = window.findChild<QTableView*>("segmentTable");
        ASSERT_NE(table, nullptr);
        tester = std::make_unique<QAbstractItemModelTester>(
            window.tableModel(), QAbstractItemModelTester::FailureReportingMode::Fatal);
        original = window.document()->project();
    }

    /// Selects the cell and types into it as a user does: the first key opens the editor.
    void typeInto(int row, int column, const QString& text) {
        const QModelIndex index = window.tableModel()->index(row, column);
        table->setFocus();
        table->setCurrentIndex(index);
        for (const QChar c : text) {
            QWidget* target = QApplication::focusWidget() ? QApplication::focusWidget() : table;
            QTest::keyClick(target, c.toLatin1());
        }
    }
    void press(Qt::Key key) {
        QWidget* target = QApplication::focusWidget() ? QApplication::focusWidget() : table;
        QTest::keyClick(target, key);
    }
    NumberSpinBox* openEditor() {
        return table->findChild<NumberSpinBox*>(QString(), Qt::FindChildrenRecursively);
    }
    const Arc& arc(int row) { return test::arcOf(window.document()->project().contour[row]); }
    int steps() { return window.document()->undoStack()->count(); }

    MainWindow window;
    QTableView* table = nullptr;
    std::unique_ptr<QAbstractItemModelTester> tester;
    Project original;
};

TEST_F(TableEditing, TypedDecimalsAreStoredAsTyped) {
    typeInto(1, SegmentTableModel::Radius, "12.5");
    // Nothing reaches the document while typing: "1" or "12" was never stored on the way.
    EXPECT_EQ(arc(1).radius, original.contour[1].as<Arc>()->radius);
    EXPECT_EQ(steps(), 0);
    press(Qt::Key_Return);
    EXPECT_EQ(arc(1).radius, 12.5);
    EXPECT_EQ(window.tableModel()->index(1, SegmentTableModel::Radius).data().toString(), "12.5");
    EXPECT_EQ(steps(), 1);
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project(), original);
    EXPECT_EQ(window.tableModel()->index(1, SegmentTableModel::Radius).data().toString(),
              "8.10318055");
    window.document()->undoStack()->redo();
    EXPECT_EQ(arc(1).radius, 12.5);

    typeInto(2, SegmentTableModel::CenterX, "144.31");
    press(Qt::Key_Tab);  // Tab commits too, and moves on
    EXPECT_EQ(arc(2).center.x(), 144.31);
    EXPECT_EQ(steps(), 2);
}

TEST_F(TableEditing, AKeyOrATextThatIsNoNumberIsRefusedWithAWordThatNamesTheCell) {
    // Issue 31, point 7: letters and 1e400 were refused without a word.
    QStatusBar* bar = window.statusBar();
    typeInto(1, SegmentTableModel::Radius, "12x");
    NumberSpinBox* editor = openEditor();
    ASSERT_NE(editor, nullptr);
    EXPECT_EQ(editor->cleanText(), "12");  // the x never entered
    EXPECT_TRUE(editor->lastRefusal().contains("“x”")) << editor->lastRefusal().toStdString();
    EXPECT_TRUE(bar->currentMessage().startsWith("Radius [mm], row 1: “x” cannot be"))
        << bar->currentMessage().toStdString();
    press(Qt::Key_Escape);
    EXPECT_EQ(window.document()->project(), original);
    // A number beyond any double, taken by Tab: refused, the cell keeps its value, and the
    // status bar says so with the cell's name.
    bar->clearMessage();
    typeInto(1, SegmentTableModel::Radius, "1e400");
    press(Qt::Key_Tab);
    EXPECT_EQ(window.document()->project(), original);
    EXPECT_EQ(steps(), 0);
    EXPECT_EQ(bar->currentMessage().toStdString(),
              "Radius [mm], row 1: 1e400 is beyond the largest number there is (about 1.8E308); "
              "it stays 8.10318055 mm.");
    // The same taken by Enter.
    bar->clearMessage();
    typeInto(1, SegmentTableModel::Radius, "-2e999");
    press(Qt::Key_Return);
    EXPECT_EQ(window.document()->project(), original);
    EXPECT_TRUE(bar->currentMessage().contains("-2e999 is beyond"))
        << bar->currentMessage().toStdString();
    // Escape cancels an unfinished number without a word.
    bar->clearMessage();
    typeInto(1, SegmentTableModel::Radius, "1e");
    press(Qt::Key_Escape);
    EXPECT_EQ(bar->currentMessage().toStdString(), "");
    EXPECT_EQ(arc(1).radius, original.contour[1].as<Arc>()->radius);
    EXPECT_EQ(window.document()->project(), original);
}

TEST_F(TableEditing, TabPassesOverTheFieldsASegmentDoesNotHave) {
    // Issue 31, point 7: Tab after an arc's Branch went into its greyed end-point cells, and
    // what was typed there was lost.
    table->setFocus();
    table->setCurrentIndex(window.tableModel()->index(1, SegmentTableModel::Branch));
    press(Qt::Key_Tab);
    EXPECT_EQ(table->currentIndex(), window.tableModel()->index(1, SegmentTableModel::PhiStart));
    press(Qt::Key_Backtab);
    EXPECT_EQ(table->currentIndex(), window.tableModel()->index(1, SegmentTableModel::Branch));
    // Typed into the cell after Branch (φ start), the text lands there and is taken.
    press(Qt::Key_Tab);
    for (const QChar c : QStringLiteral("9.5")) {
        QTest::keyClick(QApplication::focusWidget(), c.toLatin1());
    }
    press(Qt::Key_Return);
    EXPECT_EQ(steps(), 1);
    EXPECT_NE(window.document()->project(), original);
    // A click cannot make such a cell current either.
    const QModelIndex from = window.tableModel()->index(1, SegmentTableModel::FromX);
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, table->visualRect(from).center());
    EXPECT_NE(table->currentIndex(), from);
}

TEST_F(TableEditing, EscapeCancelsTypingAndSteppingAlike) {
    typeInto(3, SegmentTableModel::Radius, "99");
    press(Qt::Key_Escape);
    EXPECT_EQ(window.document()->project(), original);
    EXPECT_EQ(steps(), 0);
    // Arrow steps are live (the plots follow), and Escape takes all of them back.
    table->setCurrentIndex(window.tableModel()->index(3, SegmentTableModel::Radius));
    table->edit(table->currentIndex());
    ASSERT_NE(openEditor(), nullptr);
    openEditor()->setFocus();
    for (int i = 0; i < 3; ++i) press(Qt::Key_Up);
    EXPECT_NEAR(arc(3).radius, original.contour[3].as<Arc>()->radius + 0.3, 1e-12);
    EXPECT_EQ(steps(), 1);  // three steps, one gesture
    press(Qt::Key_Escape);
    EXPECT_EQ(window.document()->project(), original);
    EXPECT_EQ(steps(), 0);  // the step vanished from the history, it was never made
}

TEST_F(TableEditing, OpeningAndLeavingEveryCellUnchangedChangesNothing) {
    // φ end of row 1 is 50.308589201268575: an editor with six decimals stored 50.308589 and
    // opened a 2e-7° gap. Every numeric cell is opened and committed with Enter here.
    const std::string before = serializeProject(original);
    int opened = 0;
    for (int row = 0; row < window.tableModel()->rowCount(); ++row) {
        for (int c = SegmentTableModel::CenterX; c < SegmentTableModel::ColumnCount; ++c) {
            const QModelIndex index = window.tableModel()->index(row, c);
            if (c == SegmentTableModel::Branch ||
                !(window.tableModel()->flags(index) & Qt::ItemIsEditable)) {
                continue;
            }
            table->setCurrentIndex(index);
            table->edit(index);
            NumberSpinBox* editor = openEditor();
            ASSERT_NE(editor, nullptr) << row << " " << c;
            editor->setFocus();
            press(Qt::Key_Return);
            ++opened;
        }
    }
    EXPECT_EQ(opened, 13 * 5);
    EXPECT_EQ(steps(), 0);
    EXPECT_TRUE(window.document()->isValid());
    EXPECT_EQ(serializeProject(window.document()->project()), before);
}

TEST_F(TableEditing, TheEditorShowsReadableDigitsButKeepsTheExactValue) {
    const QModelIndex index = window.tableModel()->index(1, SegmentTableModel::PhiEnd);
    table->setCurrentIndex(index);
    table->edit(index);
    NumberSpinBox* editor = openEditor();
    ASSERT_NE(editor, nullptr);
    EXPECT_EQ(editor->text(), "50.3085892 °");
    EXPECT_EQ(editor->value(), 50.308589201268575);
    editor->setFocus();
    press(Qt::Key_Up);  // a real step is a real change, of exactly the step
    EXPECT_EQ(window.document()->project().contour[1].phiEndDeg, 50.308589201268575 + 0.5);
}

TEST(TableEditingGerman, ACommaIsTheDecimalSeparator) {
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    {
        MainWindow window;
        ASSERT_TRUE(window.loadFile(kExampleFile).isEmpty());
        window.show();
        QApplication::setActiveWindow(&window);
        auto* table = window.findChild<QTableView*>("segmentTable");
        table->setFocus();
        table->setCurrentIndex(window.tableModel()->index(1, SegmentTableModel::Radius));
        for (const char c : std::string("12,5")) {
            QTest::keyClick(QApplication::focusWidget(), c);
        }
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
        EXPECT_EQ(test::arcOf(window.document()->project().contour[1]).radius, 12.5);
        EXPECT_EQ(window.tableModel()->index(1, SegmentTableModel::Radius).data().toString(),
                  "12,5");
        // A dot is understood too (never as a group separator).
        table->setCurrentIndex(window.tableModel()->index(1, SegmentTableModel::CenterY));
        for (const char c : std::string("10.75")) {
            QTest::keyClick(QApplication::focusWidget(), c);
        }
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Return);
        EXPECT_EQ(test::arcOf(window.document()->project().contour[1]).center.y(), 10.75);
    }
    QLocale::setDefault(QLocale::c());
}

}  // namespace
}  // namespace cam
