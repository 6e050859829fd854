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

class FileWatch;
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
    /// Asks nothing: the questions are save()'s.
    QString save(const QString& path);

    /// @brief File → Open (the dialog unless `path` is given), after the unsaved-changes prompt;
    /// a file another Camwright window has open is opened only when the user says so.
    void open(const QString& path = {});
    /// @brief File → Save: to the project's file, or Save As when it has none. Nothing is
    /// written for a document without unsaved changes whose file is still there. When the file
    /// on disk is no longer what this window read or wrote (another program or window saved
    /// it), the user is asked before it is overwritten; "no" saves nothing.
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
    /// @brief Whether opened and saved files join the recent files in the user's settings (not
    /// in a headless run: `--screenshot`, `--export-plot`, camwright-cli's pictures).
    void setRemembersRecentFiles(bool on) { m_remembersRecentFiles = on; }

    /// @brief The project's file on disk: what changed there, who else has it open.
    [[nodiscard]] FileWatch* watch() const { return m_watch; }

signals:
    /// A transient status-bar message.
    void message(const QString& text, int timeoutMs);

private:
    /// The file changed on disk: offers to reload it (once no other dialog is open).
    void askAboutChangeOnDisk();
    /// Asked before Save overwrites what another program or window wrote; true: overwrite.
    bool mayOverwriteChangedFile();
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();
    void rebuildExamplesMenu();

    ProjectDocument* m_document;
    FileWatch* m_watch;
    bool m_asking = false;  ///< the changed-on-disk question is open
    bool m_loading = false;
    bool m_remembersRecentFiles = true;
    bool m_loadCancelled = false;  ///< the last load() ended by the user's Cancel
    std::vector<QPointer<QThread>> m_abandonedLoaders;
    QWidget* m_window;
    QMenu* m_recentMenu;
    QMenu* m_examplesMenu;
};

}  // namespace cam
