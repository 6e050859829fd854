#include "window/cursor_actions.h"

#include <QAction>
#include <QMenu>
#include <QWidget>
#include <functional>

#include "window/cursor_model.h"

namespace cam {

CursorActions::CursorActions(CursorModel* cursor, QWidget* where, QMenu* menu) : QObject(where) {
    struct Row {
        const char* name;
        QString text;
        QKeySequence key;
        std::function<void()> go;
    };
    const Row rows[] = {
        {"actionCursorPreviousSample", tr("Previous Sample"), QKeySequence(Qt::Key_Left),
         [cursor] { cursor->stepSamples(-1); }},
        {"actionCursorNextSample", tr("Next Sample"), QKeySequence(Qt::Key_Right),
         [cursor] { cursor->stepSamples(1); }},
        {"actionCursorPreviousJoint", tr("Previous Joint"), QKeySequence(Qt::SHIFT | Qt::Key_Left),
         [cursor] { cursor->stepJoints(-1); }},
        {"actionCursorNextJoint", tr("Next Joint"), QKeySequence(Qt::SHIFT | Qt::Key_Right),
         [cursor] { cursor->stepJoints(1); }},
        {"actionCursorTurnStart", tr("Start of the Turn"), QKeySequence(Qt::Key_Home),
         [cursor] { cursor->toTurnStart(); }},
        {"actionCursorTurnEnd", tr("End of the Turn"), QKeySequence(Qt::Key_End),
         [cursor] { cursor->toTurnEnd(); }},
    };
    QMenu* sub = menu->addMenu(tr("&Cursor"));
    sub->setObjectName("menuCursor");
    sub->setToolTipsVisible(true);
    for (const Row& row : rows) {
        auto* action = new QAction(row.text, where);
        action->setObjectName(row.name);
        action->setShortcut(row.key);
        // Only with the focus in the contour view or the plots: elsewhere the keys are the
        // table's or the box's own.
        action->setShortcutContext(Qt::WidgetWithChildrenShortcut);
        action->setToolTip(tr("%1 (with the focus in the contour view or a plot)").arg(row.text));
        where->addAction(action);
        sub->addAction(action);
        connect(action, &QAction::triggered, this, row.go);
    }
}

}  // namespace cam
