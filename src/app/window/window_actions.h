#pragma once
/// @file
/// @brief The window's actions, in one catalogue: the File, Edit, View and Help menus' entries
/// that are not made by their own controller (Play, Synthesize, Export), what each does, and
/// the icons and shortcut tooltips of every action.

#include <QObject>
#include <QString>

class QMainWindow;

namespace Ui {
class MainWindow;
}

namespace cam {

class DockLayout;
class ProjectDocument;
class ProjectFiles;
class UserGuide;
struct EditOutcome;

class WindowActions : public QObject {
    Q_OBJECT
public:
    WindowActions(QMainWindow* window, Ui::MainWindow& ui, ProjectDocument* document,
                  ProjectFiles* files, DockLayout& views);

    /// @brief Gives every action and dock toggle its icon, and every tooltip its shortcut.
    /// Called once all actions exist.
    void setUpIcons();

    /// @brief Shows what a contour edit did (status bar, selection) or why not (a message box
    /// titled `title`; none when empty).
    void report(const EditOutcome& outcome, const QString& title = {});
    /// @brief File → Project Name…: renames the project (trimmed) as one undo step.
    void renameProject(const QString& name);
    /// @brief Help → About: version, license, the libraries and their versions.
    [[nodiscard]] QString aboutText() const;
    /// @brief The user guide, once F1 has opened it (else null).
    [[nodiscard]] UserGuide* userGuide() const { return m_guide; }

signals:
    /// A computation with the new view settings is needed (the time axis was switched).
    void viewChanged();

private:
    void setUpActions();
    [[nodiscard]] int selectedRow() const;

    QMainWindow* m_window;
    Ui::MainWindow& m_ui;
    ProjectDocument* m_document;
    ProjectFiles* m_files;
    DockLayout& m_views;
    UserGuide* m_guide = nullptr;  ///< made when first asked for
    int m_pickRow = -1;            ///< the row a tangent arc continues, while a point is picked
};

}  // namespace cam
