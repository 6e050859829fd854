// German: every string the window shows must be one the translation file knows. A string that
// lupdate never extracted (built without tr(), or tr() in a place lupdate cannot see) stays
// English in the German window; this walks every visible text of the real window and fails on
// any that no German translation explains.

#include <gtest/gtest.h>

#include <qcustomplot.h>
#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QRegularExpression>
#include <QSet>
#include <QTabBar>
#include <QTableView>
#include <QTimer>
#include <QTranslator>
#include <QXmlStreamReader>

#include "app_test_support.h"
#include "document/commands.h"
#include "engine/compute_engine.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "translations.h"

namespace cam {
namespace {

QString withoutAccelerators(QString s) {
    s.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
    s.remove('&');
    s.replace(QChar(1), QChar('&'));
    return s.trimmed();
}

/// What the German translation file can explain: every translation as a pattern (%1, %n, %L1 …
/// stand for any text), and every word any translation uses (for texts the window composes
/// from translated parts, numbers and units, such as "Genauhalt\n4,5949 s").
struct German {
    std::vector<QRegularExpression> patterns;
    QSet<QString> words;

    explicit German(const QString& tsPath) {
        QFile file(tsPath);
        EXPECT_TRUE(file.open(QIODevice::ReadOnly)) << tsPath.toStdString();
        QXmlStreamReader xml(&file);
        static const QRegularExpression placeholder(R"(%L?[0-9n])");
        static const QRegularExpression word(R"([A-Za-zÄÖÜäöüßé]{3,})");
        while (!xml.atEnd()) {
            xml.readNext();
            if (!xml.isStartElement()) continue;
            if (xml.name() != QLatin1String("translation") &&
                xml.name() != QLatin1String("numerusform")) {
                continue;
            }
            const QString text =
                withoutAccelerators(xml.readElementText(QXmlStreamReader::IncludeChildElements));
            if (text.isEmpty()) continue;
            QStringList pieces;
            for (const QString& piece : text.split(placeholder)) {
                pieces << QRegularExpression::escape(piece);
            }
            patterns.emplace_back(
                QRegularExpression::anchoredPattern(pieces.join(QStringLiteral("[\\s\\S]*"))));
            for (auto it = word.globalMatch(text); it.hasNext();)
                words.insert(it.next().captured());
        }
    }

    [[nodiscard]] bool explains(const QString& shown) const {
        for (const auto& p : patterns) {
            if (p.match(shown).hasMatch()) return true;
        }
        static const QRegularExpression word(R"([A-Za-zÄÖÜäöüßé]{3,})");
        for (auto it = word.globalMatch(shown); it.hasNext();) {
            if (!words.contains(it.next().captured())) return false;
        }
        return true;
    }
};

/// Worth checking: holds a word of three or more Latin letters (symbols such as v_r, |v|, φ,
/// units such as mm/s², numbers and paths of the test's own files are not words).
bool hasWords(const QString& s) {
    static const QRegularExpression word(R"([A-Za-zÄÖÜäöüß]{3,})");
    return word.match(s).hasMatch();
}

TEST(GermanWindow, EveryVisibleStringIsATranslationTheFileKnows) {
    QTranslator german;
    ASSERT_TRUE(
        german.load(QLocale(QLocale::German, QLocale::Germany), "camwright", "_", ":/i18n"));
    QCoreApplication::installTranslator(&german);
    QLocale::setDefault(QLocale(QLocale::German, QLocale::Germany));
    const German german_(QString::fromUtf8(CAMWRIGHT_SOURCE_DIR) +
                         "/resources/translations/camwright_de.ts");
    ASSERT_GT(german_.patterns.size(), 200u);

    QStringList offending;
    int checked = 0;
    {
        MainWindow window;
        const QString project =
            QString::fromStdString(test::dataPath("app/six-lobe-machining.cam.json"));
        ASSERT_TRUE(window.loadFile(project).isEmpty());
        window.resize(1400, 860);
        window.show();
        for (auto* dock : window.findChildren<QDockWidget*>()) dock->show();
        ASSERT_TRUE(window.waitForCurrentResult(20000));
        ASSERT_TRUE(test::processEventsUntil([&] {
            const auto& t = window.engine()->latestTiming();
            return t && t->generation == window.engine()->latestGeneration();
        }));
        QCoreApplication::processEvents();

        QStringList shown;
        auto add = [&](const QString& s) { shown << withoutAccelerators(s); };
        add(window.windowTitle());
        // File names are data, not text: the recent files and the examples' names.
        QList<QAction*> named = window.findChild<QMenu*>("menuRecent")->actions();
        named += window.findChild<QMenu*>("menuExamples")->actions();
        for (auto* a : window.findChildren<QAction*>()) {
            if (a->isSeparator() || named.contains(a)) continue;
            add(a->text());
            add(a->toolTip());
            add(a->statusTip());
        }
        for (auto* m : window.findChildren<QMenu*>()) add(m->title());
        for (auto* d : window.findChildren<QDockWidget*>()) add(d->windowTitle());
        for (auto* w : window.findChildren<QWidget*>()) {
            if (!w->isVisible()) continue;
            add(w->toolTip());
            add(w->whatsThis());
            if (auto* l = qobject_cast<QLabel*>(w)) add(l->text());
            if (auto* b = qobject_cast<QAbstractButton*>(w)) add(b->text());
            if (auto* g = qobject_cast<QGroupBox*>(w)) add(g->title());
            if (auto* c = qobject_cast<QComboBox*>(w)) {
                for (int i = 0; i < c->count(); ++i) add(c->itemText(i));
            }
            if (auto* t = qobject_cast<QTabBar*>(w)) {
                for (int i = 0; i < t->count(); ++i) add(t->tabText(i));
            }
            if (auto* p = qobject_cast<QCustomPlot*>(w)) {
                for (QCPAxis* axis : p->axisRect()->axes()) add(axis->label());
                // A curve's name is shown in the legend, if the plot has one.
                for (int i = 0; i < p->plottableCount(); ++i) {
                    if (p->legend->visible() && p->legend->hasItemWithPlottable(p->plottable(i))) {
                        add(p->plottable(i)->name());
                    }
                }
            }
        }
        SegmentTableModel* model = window.tableModel();
        for (int c = 0; c < model->columnCount(); ++c) {
            add(model->headerData(c, Qt::Horizontal, Qt::DisplayRole).toString());
            add(model->headerData(c, Qt::Horizontal, Qt::ToolTipRole).toString());
            for (int r = 0; r < model->rowCount(); ++r) {
                add(model->index(r, c).data(Qt::DisplayRole).toString());
                add(model->index(r, c).data(Qt::ToolTipRole).toString());
            }
        }
        for (const QString& s : shown) {
            if (!hasWords(s) || s.contains(project)) continue;
            ++checked;
            if (!german_.explains(s) && !offending.contains(s)) offending << s;
        }
    }
    QLocale::setDefault(QLocale::c());
    QCoreApplication::removeTranslator(&german);
    EXPECT_GT(checked, 150);
    EXPECT_TRUE(offending.isEmpty()) << "shown in the German window but not translated:\n  "
                                     << offending.join("\n  ").toStdString();
}

TEST(GermanWindow, QtsOwnButtonsAndKeyNamesAreGermanToo) {
    // As main() installs them: Qt's translations (qt6-translations-l10n) and ours.
    const Translations german(QLocale(QLocale::German, QLocale::Germany));
    ASSERT_TRUE(german.appTranslated());
    ASSERT_TRUE(german.qtTranslated())
        << "Qt's German is missing: apt install qt6-translations-l10n";
    MainWindow window;
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::examplePath("six-lobe-arc-cam.cam.json")))
            .isEmpty());
    window.document()->undoStack()->push(new SetMotion(window.document(), {SpeedUnit::Rpm, 90.0}));
    // The unsaved-changes prompt of File → New: its buttons are Qt's.
    QStringList buttons;
    QTimer::singleShot(0, [&] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) return;
        for (QAbstractButton* b : box->buttons()) buttons << withoutAccelerators(b->text());
        box->button(QMessageBox::Cancel)->click();
    });
    window.findChild<QAction*>("actionNew")->trigger();
    buttons.sort();
    EXPECT_EQ(buttons.join(", ").toStdString(), "Abbrechen, Speichern, Verwerfen");
    EXPECT_EQ(window.document()->project().motion.value, 90.0);  // Cancel kept the edit
    // Key names as a German keyboard labels them, in tooltips and the shortcuts list.
    EXPECT_EQ(QKeySequence(QKeySequence::Save).toString(QKeySequence::NativeText), "Strg+S");
    EXPECT_EQ(QKeySequence(Qt::Key_Delete).toString(QKeySequence::NativeText), "Entf");
    EXPECT_TRUE(window.findChild<QAction*>("actionSave")->toolTip().contains("Strg+S"))
        << window.findChild<QAction*>("actionSave")->toolTip().toStdString();
}

// A dock must not read like a menu: "Bearbeitung" (machining) beside "Bearbeiten" (the Edit
// menu) sent users to the wrong place. No menu of the menu bar shares the stem of its first word
// (its first seven letters) with a dock's title.
TEST(GermanWindow, NoDockIsNamedLikeAMenu) {
    const Translations german(QLocale(QLocale::German, QLocale::Germany));
    ASSERT_TRUE(german.appTranslated());
    MainWindow window;
    QStringList menus, docks;
    for (QAction* menu : window.menuBar()->actions()) menus << withoutAccelerators(menu->text());
    for (QDockWidget* dock : window.findChildren<QDockWidget*>()) docks << dock->windowTitle();
    ASSERT_TRUE(menus.contains("Bearbeiten"));
    const auto stem = [](const QString& title) {
        return title.section(' ', 0, 0).left(7).toLower();
    };
    for (const QString& menu : menus) {
        for (const QString& dock : docks) {
            EXPECT_NE(stem(menu), stem(dock)) << menu.toStdString() << " / " << dock.toStdString();
        }
    }
}

}  // namespace
}  // namespace cam
