// The window as a desktop application: every menu and toolbar action has an icon (ours where the
// desktop theme has none, as on the offscreen platform here), every action with a shortcut says
// it in its tooltip, Help → Keyboard Shortcuts lists them, and Help → About names the version,
// the license and the libraries.

#include <gtest/gtest.h>

#include <QAction>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QTableWidget>
#include <QToolBar>
#include <QWidgetAction>
#include <functional>

#include "app_test_support.h"
#include "dialogs/shortcuts_dialog.h"
#include "mainwindow.h"

namespace cam {
namespace {

/// Every action a user can reach from the menus (submenus included) and the toolbars.
QList<QAction*> reachableActions(const MainWindow& window) {
    QList<QAction*> out;
    std::function<void(QMenu*)> walk = [&](QMenu* menu) {
        for (QAction* a : menu->actions()) {
            if (a->isSeparator()) continue;
            if (a->menu()) {
                if (a->menu()->objectName() == "menuRecent" ||
                    a->menu()->objectName() == "menuExamples") {
                    out << a;  // the submenu itself; its entries are file names
                    continue;
                }
                walk(a->menu());
            } else {
                out << a;
            }
        }
    };
    for (QAction* top : window.menuBar()->actions()) {
        if (top->menu()) walk(top->menu());
    }
    for (QToolBar* bar : window.findChildren<QToolBar*>()) {
        for (QAction* a : bar->actions()) {
            if (!a->isSeparator() && !qobject_cast<QWidgetAction*>(a)) out << a;
        }
    }
    return out;
}

TEST(DesktopManners, EveryMenuAndToolbarActionHasAnIconAndItsShortcutInItsTooltip) {
    MainWindow window;
    const QList<QAction*> actions = reachableActions(window);
    ASSERT_GT(actions.size(), 30);
    for (QAction* a : actions) {
        EXPECT_FALSE(a->icon().isNull()) << a->text().toStdString() << " has no icon";
        EXPECT_FALSE(a->icon().pixmap(24, 24).isNull()) << a->text().toStdString();
        if (!a->shortcut().isEmpty()) {
            const QString keys = a->shortcut().toString(QKeySequence::NativeText);
            EXPECT_TRUE(a->toolTip().contains(keys))
                << a->text().toStdString() << ": \"" << a->toolTip().toStdString()
                << "\" does not name " << keys.toStdString();
        }
    }
    // The toolbar shows icons, the tooltips the names.
    auto* bar = window.findChild<QToolBar*>("mainToolBar");
    ASSERT_NE(bar, nullptr);
    EXPECT_EQ(bar->toolButtonStyle(), Qt::ToolButtonIconOnly);
    // Play shows pause while it plays.
    QAction* play = window.playAction();
    const qint64 playing = play->icon().cacheKey();
    play->setChecked(true);
    EXPECT_NE(play->icon().cacheKey(), playing);
    play->setChecked(false);
}

TEST(DesktopManners, KeyboardShortcutsListsEveryShortcut) {
    MainWindow window;
    ShortcutsDialog dialog(&window);
    QStringList keys;
    for (int r = 0; r < dialog.table()->rowCount(); ++r) keys << dialog.table()->item(r, 1)->text();
    for (const QKeySequence& k :
         {QKeySequence(QKeySequence::Save), QKeySequence(QKeySequence::Undo),
          QKeySequence(Qt::Key_F6), QKeySequence(Qt::Key_F5), QKeySequence(Qt::CTRL | Qt::Key_D),
          QKeySequence(Qt::CTRL | Qt::Key_L), QKeySequence(Qt::CTRL | Qt::Key_M)}) {
        EXPECT_TRUE(keys.contains(k.toString(QKeySequence::NativeText)))
            << k.toString().toStdString() << " missing from " << keys.join(", ").toStdString();
    }
    EXPECT_TRUE(window.findChild<QAction*>("actionKeyboardShortcuts"));
}

TEST(DesktopManners, KeyboardShortcutsNamesActionsNotTheirLiveText) {
    // Issue 31, point 9: after an edit and its undo the list showed "Redo Insert segment" (the
    // redo action's live text) as an action; while playing, "Pause".
    MainWindow window;
    window.findChild<QAction*>("actionInsertSegment")->trigger();
    window.findChild<QAction*>("actionUndo")->trigger();
    ASSERT_TRUE(window.findChild<QAction*>("actionRedo")->text().remove('&').startsWith("Redo "))
        << window.findChild<QAction*>("actionRedo")->text().toStdString();
    window.playAction()->setChecked(true);
    ShortcutsDialog dialog(&window);
    window.playAction()->setChecked(false);
    QStringList names;
    for (int r = 0; r < dialog.table()->rowCount(); ++r)
        names << dialog.table()->item(r, 0)->text();
    for (const char* name : {"Undo", "Redo", "Play / Pause"}) {
        EXPECT_TRUE(names.contains(name))
            << name << " missing from " << names.join(", ").toStdString();
    }
    for (const QString& name : names) {
        EXPECT_FALSE(name.startsWith("Undo ") || name.startsWith("Redo ") || name == "Pause")
            << name.toStdString();
    }
}

TEST(DesktopManners, AboutNamesTheVersionLicenseAndLibraries) {
    MainWindow window;
    const QString about = window.aboutText();
    for (const char* word :
         {"GPL-3.0-or-later", "Qt ", "QCustomPlot 2.", "Eigen 3.", "nlohmann-json) 3."}) {
        EXPECT_TRUE(about.contains(QLatin1String(word)))
            << word << " not in " << about.toStdString();
    }
    EXPECT_TRUE(about.contains(QString::fromLatin1(qVersion())));
}

}  // namespace
}  // namespace cam
