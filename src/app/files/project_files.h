#pragma once
/// @file
/// @brief Opening and saving projects for the main window: file dialogs, the unsaved-changes
/// prompt, recent files and the bundled examples.

#include <QObject>
#include <QPointer>
#include <QString>
#include <QThread>
#include <vector>

class QMenu;
class QWidget;

namespace cam {

class ProjectDocument;

/// @brief File handling of one window. A file that is sound JSON of a known format and version,
/// with every value of the right type, opens even when its geometry has problems (an unfinished
/// design): they are listed and marked, and such a project saves again. Only a file that is not
/// a Camwright project at all is refused, with every problem located, and then the open project
/// stays exactly as it was.
class ProjectFiles : public QObject {
    Q_OBJECT
public:
    /// @brief `window` parents the dialogs; the menus are kept up to date (recent, examples).
    ProjectFiles(ProjectDocument* document, QWidget* window, QMenu* recentMenu,
                 QMenu* examplesMenu);
    ~ProjectFiles() override;

    /// @brief Opens without asking anything; on failure returns the located problems and leaves
    /// the open document untouched. The file is read, parsed and validated in a worker thread
    /// while the window keeps answering; after 300 ms a progress dialog offers Cancel (then the
    /// document stays as it was and the message says so). Files over 64 MB are refused with
    /// their size (io/project_json.h).
    QString load(const QString& path);
    /// @brief Saves to `path` atomically (see io/atomic_file.h); returns the problem, or empty.
    QString save(const QString& path);

    /// @brief File → Open (the dialog unless `path` is given), after the unsaved-changes prompt.
    void open(const QString& path = {});
    /// @brief File → Save: to the project's file, or Save As when it has none.
    bool save();
    /// @brief File → Save As. A name typed without ".cam.json" gets it, and if that file
    /// exists the user is asked before it is replaced (the dialog asked about the typed name).
    bool saveAs();
    /// @brief The unsaved-changes prompt: true when the caller may go on.
    bool maybeSave();
    /// @brief Opens an example (a `:/examples` resource) as an untitled copy.
    void openExample(const QString& resourcePath);
    /// @brief File → Open Recent → a file: opened, or, when it no longer exists, removed from
    /// the list with a message saying so.
    void openRecent(const QString& path);
    /// @brief File → Open Recent → Clear Menu.
    void clearRecentFiles();

signals:
    /// A transient status-bar message.
    void message(const QString& text, int timeoutMs);

private:
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();
    void rebuildExamplesMenu();

    ProjectDocument* m_document;
    bool m_loading = false;
    bool m_loadCancelled = false;  ///< the last load() ended by the user's Cancel
    std::vector<QPointer<QThread>> m_abandonedLoaders;
    QWidget* m_window;
    QMenu* m_recentMenu;
    QMenu* m_examplesMenu;
};

}  // namespace cam
