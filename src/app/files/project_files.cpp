#include "files/project_files.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QEventLoop>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QThread>
#include <QTimer>
#include <atomic>
#include <memory>
#include <optional>

#include "document/project_document.h"
#include "evaluation/evaluation.h"
#include "files/file_watch.h"
#include "io/atomic_file.h"
#include "io/project_json.h"
#include "messages/diagnostic_text.h"
#include "widgets/icons.h"

namespace cam {
namespace {

constexpr int kMaxRecentFiles = 8;
/// A load that takes longer than this shows its progress dialog.
constexpr int kProgressAfterMs = 300;
constexpr const char* kSuffix = ".cam.json";
/// The bundled example projects, embedded in the binary (src/app/CMakeLists.txt).
constexpr const char* kExamplesFolder = ":/examples";

int errorCount(const Diagnostics& diagnostics) {
    int n = 0;
    for (const Diagnostic& d : diagnostics) n += d.severity == Severity::Error ? 1 : 0;
    return n;
}

}  // namespace

ProjectFiles::ProjectFiles(ProjectDocument* document, QWidget* window, QMenu* recentMenu,
                           QMenu* examplesMenu)
    : QObject(window),
      m_document(document),
      m_window(window),
      m_recentMenu(recentMenu),
      m_examplesMenu(examplesMenu) {
    m_watch = new FileWatch(document, this);
    connect(m_watch, &FileWatch::changedOnDisk, this, &ProjectFiles::askAboutChangeOnDisk);
    rebuildRecentMenu();
    rebuildExamplesMenu();
}

ProjectFiles::~ProjectFiles() {
    // A load the user cancelled may still be reading: it writes only into its own shared
    // state, but the thread object must outlive it.
    for (const QPointer<QThread>& loader : m_abandonedLoaders) {
        if (loader) loader->wait();
    }
}

QString ProjectFiles::load(const QString& path) {
    if (m_loading) return tr("%1 cannot be opened: another file is being opened").arg(path);
    const QString shown = QDir::toNativeSeparators(path);
    // Reading, parsing and validating happen in a worker thread: the window keeps drawing and
    // a big file shows its progress with a Cancel button (application modal, so nothing else
    // can change the document meanwhile).
    struct Outcome {
        std::atomic<bool> done{false};
        std::optional<Result<Project>> project;
        Diagnostics diagnostics;
        QByteArray digest;  ///< of the very bytes parsed: what a later save compares with
    };
    auto outcome = std::make_shared<Outcome>();
    QThread* worker = QThread::create([file = QFile::encodeName(path).toStdString(), outcome] {
        auto text = readTextFile(file);
        if (!text.ok()) {
            outcome->project.emplace(text.errors());
        } else {
            outcome->digest = FileWatch::digest(QByteArray::fromStdString(text.value()));
            auto loaded = parseProjectStructure(text.value());
            if (loaded.ok()) outcome->diagnostics = projectProblems(loaded.value());
            outcome->project.emplace(std::move(loaded));
        }
        outcome->done = true;
    });
    worker->setObjectName("projectLoader");
    m_loading = true;
    QEventLoop loop;
    connect(worker, &QThread::finished, &loop, &QEventLoop::quit);
    QProgressDialog progress(m_window);
    progress.setObjectName("openProgress");
    progress.setWindowTitle(tr("Opening"));
    const qint64 bytes = QFileInfo(path).size();
    progress.setLabelText(
        bytes > 0 ? tr("Reading %1 (%2)…")
                        .arg(QFileInfo(path).fileName(), QLocale().formattedDataSize(bytes))
                  : tr("Reading %1…").arg(QFileInfo(path).fileName()));
    progress.setRange(0, 0);  // busy: the parser reports no fraction
    progress.setWindowModality(Qt::ApplicationModal);
    progress.setMinimumDuration(kProgressAfterMs);
    progress.setValue(0);  // starts the clock of minimumDuration
    bool cancelled = false;
    connect(&progress, &QProgressDialog::canceled, &loop, [&] {
        cancelled = true;
        loop.quit();
    });
    QTimer tick;
    tick.setInterval(20);
    connect(&tick, &QTimer::timeout, &loop, &QEventLoop::quit);
    tick.start();
    worker->start();
    // Until the dialog shows, the user's input waits (it must not reach the window while its
    // document is about to be replaced); once it shows, only the dialog takes input.
    while (!outcome->done && !cancelled && !progress.wasCanceled()) {
        loop.exec(progress.isVisible() ? QEventLoop::AllEvents
                                       : QEventLoop::ExcludeUserInputEvents);
    }
    m_loading = false;
    cancelled = cancelled || progress.wasCanceled();
    m_loadCancelled = cancelled;
    progress.reset();
    if (cancelled) {
        if (worker->isFinished()) {
            delete worker;
        } else {
            connect(worker, &QThread::finished, worker, &QObject::deleteLater);
            m_abandonedLoaders.push_back(worker);
        }
        emit message(tr("Opening %1 cancelled").arg(shown), 4000);
        return tr("Opening %1 was cancelled").arg(shown);
    }
    worker->wait();
    delete worker;
    Result<Project>& loaded = *outcome->project;
    if (!loaded.ok()) {
        return tr("%1 cannot be opened:\n%2").arg(shown, diagnosticsText(loaded.errors()));
    }
    const QString absolute = QFileInfo(path).absoluteFilePath();
    const bool elsewhere = absolute != m_document->filePath() && m_watch->isOpenElsewhere(absolute);
    m_document->reset(std::move(loaded).value(), absolute, std::move(outcome->diagnostics),
                      outcome->digest);
    addRecentFile(absolute);
    const int problems = errorCount(m_document->diagnostics());
    if (elsewhere) {
        emit message(tr("%1 is open in another Camwright window too: a save in either asks "
                        "before it overwrites the other's")
                         .arg(shown),
                     10000);
        return {};
    }
    emit message(problems == 0
                     ? tr("Opened %1").arg(shown)
                     : tr("Opened %1 with %n problem(s): listed in the status bar, marked in the "
                          "table",
                          "", problems)
                           .arg(shown),
                 problems == 0 ? 4000 : 10000);
    return {};
}

QString ProjectFiles::save(const QString& path) {
    // Geometric problems are saved as they are (an unfinished design); a number a file cannot
    // hold is not.
    const Diagnostics unwritable = nonFiniteValues(m_document->project());
    if (!unwritable.empty()) {
        return tr("%1 cannot be saved:\n%2")
            .arg(QDir::toNativeSeparators(path), diagnosticsText(unwritable));
    }
    // The core's writer, as the CLI's --out: mode, owner and symlinks kept, non-files refused.
    const std::string text = serializeProject(m_document->project());
    const Diagnostics problems = writeFileAtomically(QFile::encodeName(path).toStdString(), text);
    if (!problems.empty()) {
        return tr("%1 could not be written: %2")
            .arg(QDir::toNativeSeparators(path), DiagnosticText::message(problems.front()));
    }
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_document->markSaved(absolute, FileWatch::digest(QByteArray::fromStdString(text)));
    addRecentFile(absolute);
    const int open = errorCount(m_document->diagnostics());
    emit message(open == 0 ? tr("Saved %1").arg(QDir::toNativeSeparators(path))
                           : tr("Saved %1 with %n problem(s) still to solve", "", open)
                                 .arg(QDir::toNativeSeparators(path)),
                 open == 0 ? 4000 : 8000);
    return {};
}

void ProjectFiles::open(const QString& givenPath) {
    if (!maybeSave()) return;
    QString path = givenPath;
    if (path.isEmpty()) {
        path = QFileDialog::getOpenFileName(m_window, tr("Open Project"),
                                            QSettings().value("files/lastDir").toString(),
                                            tr("Camwright projects (*.cam.json)"));
        if (path.isEmpty()) return;
    }
    QSettings().setValue("files/lastDir", QFileInfo(path).absolutePath());
    const QString absolute = QFileInfo(path).absoluteFilePath();
    if (absolute != m_document->filePath() && m_watch->isOpenElsewhere(absolute)) {
        QMessageBox box(QMessageBox::Warning, tr("Open Project"),
                        tr("%1 is already open in another Camwright window.")
                            .arg(QDir::toNativeSeparators(absolute)),
                        QMessageBox::Open | QMessageBox::Cancel, m_window);
        box.setObjectName("openElsewhereBox");
        box.setInformativeText(
            tr("Open it here too? Whichever window saves second is asked before it overwrites "
               "the other's changes."));
        box.setDefaultButton(QMessageBox::Cancel);
        if (box.exec() != QMessageBox::Open) return;
    }
    const QString problem = load(path);
    // A cancelled open needs no box: the user asked for it, the status bar says it.
    if (!problem.isEmpty() && !m_loadCancelled) {
        QMessageBox::warning(m_window, tr("Open Project"), problem);
    }
}

bool ProjectFiles::save() {
    if (m_document->filePath().isEmpty()) return saveAs();
    const QString shown = QDir::toNativeSeparators(m_document->filePath());
    const DiskState disk = m_watch->check();
    // Nothing unsaved: nothing is written (a file someone else changed stays theirs); only a
    // file that is gone is written again.
    if (!m_document->isModified() && disk != DiskState::Removed) {
        emit message(disk == DiskState::Same
                         ? tr("Nothing to save: %1 holds this project as it is").arg(shown)
                         : tr("Nothing to save here; %1 was changed on disk by another "
                              "program or window")
                               .arg(shown),
                     6000);
        return true;
    }
    if (disk == DiskState::Changed && !mayOverwriteChangedFile()) return false;
    const QString problem = save(m_document->filePath());
    if (!problem.isEmpty()) QMessageBox::warning(m_window, tr("Save Project"), problem);
    return problem.isEmpty();
}

bool ProjectFiles::saveAs() {
    const QString start = m_document->filePath().isEmpty()
                              ? QSettings().value("files/lastDir").toString()
                              : m_document->filePath();
    QString path = QFileDialog::getSaveFileName(m_window, tr("Save Project As"), start,
                                                tr("Camwright projects (*.cam.json)"));
    if (path.isEmpty()) return false;
    if (!path.endsWith(kSuffix)) {
        path += kSuffix;
        // The dialog asked about the name as typed; the file written is another one.
        if (QFileInfo::exists(path) &&
            QMessageBox::question(m_window, tr("Save Project As"),
                                  tr("%1 already exists.\nDo you want to replace it?")
                                      .arg(QDir::toNativeSeparators(path)),
                                  QMessageBox::Yes | QMessageBox::No,
                                  QMessageBox::No) != QMessageBox::Yes) {
            return false;
        }
    }
    QSettings().setValue("files/lastDir", QFileInfo(path).absolutePath());
    // Save As onto the project's own file is a Save: the same question about changes on disk.
    if (QFileInfo(path).absoluteFilePath() == m_document->filePath() &&
        m_watch->check() == DiskState::Changed && !mayOverwriteChangedFile()) {
        return false;
    }
    const QString problem = save(path);
    if (!problem.isEmpty()) QMessageBox::warning(m_window, tr("Save Project"), problem);
    return problem.isEmpty();
}

bool ProjectFiles::mayOverwriteChangedFile() {
    QMessageBox box(QMessageBox::Warning, tr("Save Project"),
                    tr("%1 has been changed on disk since this window opened or saved it.")
                        .arg(QDir::toNativeSeparators(m_document->filePath())),
                    QMessageBox::NoButton, m_window);
    box.setObjectName("overwriteChangedBox");
    box.setInformativeText(
        tr("Another program or Camwright window has written it. Overwrite "
           "its changes with this window's project?"));
    QPushButton* overwrite = box.addButton(tr("&Overwrite"), QMessageBox::DestructiveRole);
    box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(QMessageBox::Cancel);
    box.exec();
    if (box.clickedButton() == overwrite) return true;
    emit message(tr("Not saved: %1 keeps the changes made on disk")
                     .arg(QDir::toNativeSeparators(m_document->filePath())),
                 8000);
    return false;
}

void ProjectFiles::askAboutChangeOnDisk() {
    if (m_asking) return;
    // Not over another dialog or while a file opens: asked once those are done.
    if (m_loading || QApplication::activeModalWidget() || QApplication::activePopupWidget()) {
        QTimer::singleShot(300, this, &ProjectFiles::askAboutChangeOnDisk);
        return;
    }
    const QString path = m_document->filePath();
    const QString shown = QDir::toNativeSeparators(path);
    const DiskState state = m_watch->check();
    if (state == DiskState::Same) return;
    if (state == DiskState::Removed) {
        emit message(tr("%1 was deleted or moved away on disk; Save writes it again").arg(shown),
                     10000);
        return;
    }
    QMessageBox box(QMessageBox::Question, tr("File Changed on Disk"),
                    tr("%1 has been changed on disk by another program or window.").arg(shown),
                    QMessageBox::NoButton, m_window);
    box.setObjectName("changedOnDiskBox");
    box.setInformativeText(m_document->isModified()
                               ? tr("Reload it and discard the unsaved changes made here? Keep "
                                    "them, and Save asks before it overwrites the file.")
                               : tr("Reload it? Keep this window's version, and Save asks "
                                    "before it overwrites the file."));
    QPushButton* reload =
        box.addButton(tr("&Reload"), m_document->isModified() ? QMessageBox::DestructiveRole
                                                              : QMessageBox::AcceptRole);
    QPushButton* keep = box.addButton(tr("&Keep This Version"), QMessageBox::RejectRole);
    box.setDefaultButton(m_document->isModified() ? keep : reload);
    m_asking = true;
    box.exec();
    m_asking = false;
    if (box.clickedButton() != reload || m_document->filePath() != path) return;
    const QString problem = load(path);
    if (!problem.isEmpty() && !m_loadCancelled) {
        QMessageBox::warning(m_window, tr("File Changed on Disk"), problem);
    }
}

bool ProjectFiles::maybeSave() {
    if (!m_document->isModified()) return true;
    const auto answer = QMessageBox::warning(
        m_window, tr("Unsaved Changes"),
        tr("%1 has unsaved changes. Save them?").arg(m_document->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void ProjectFiles::openExample(const QString& resourcePath) {
    if (!maybeSave()) return;
    QFile file(resourcePath);
    auto loaded = file.open(QIODevice::ReadOnly)
                      ? parseProjectStructure(file.readAll().toStdString())
                      : Result<Project>(Diagnostics{{resourcePath.toStdString(), "cannot open"}});
    if (!loaded.ok()) {
        QMessageBox::warning(m_window, tr("Open Example"), diagnosticsText(loaded.errors()));
        return;
    }
    // An example opens as an untitled copy: Save asks where, never over the example.
    m_document->reset(std::move(loaded).value(), {});
}

void ProjectFiles::addRecentFile(const QString& path) {
    if (!m_remembersRecentFiles) return;
    QSettings settings;
    QStringList files = settings.value("files/recent").toStringList();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    settings.setValue("files/recent", files);
    rebuildRecentMenu();
}

void ProjectFiles::openRecent(const QString& path) {
    if (!QFileInfo::exists(path)) {
        // Moved or deleted since: it goes from the list, and the user is told once, here.
        QSettings settings;
        QStringList files = settings.value("files/recent").toStringList();
        files.removeAll(path);
        settings.setValue("files/recent", files);
        rebuildRecentMenu();
        QMessageBox box(QMessageBox::Information, tr("Open Recent"),
                        tr("%1 no longer exists; it has been removed from the recent files.")
                            .arg(QDir::toNativeSeparators(path)),
                        QMessageBox::Ok, m_window);
        box.setObjectName("recentFileGoneBox");
        box.exec();
        return;
    }
    open(path);
}

void ProjectFiles::clearRecentFiles() {
    QSettings().remove("files/recent");
    rebuildRecentMenu();
    emit message(tr("Recent files cleared"), 4000);
}

void ProjectFiles::rebuildRecentMenu() {
    m_recentMenu->clear();
    const QStringList files = QSettings().value("files/recent").toStringList();
    for (const QString& f : files) {
        QAction* entry = m_recentMenu->addAction(QDir::toNativeSeparators(f), this,
                                                 [this, f] { openRecent(f); });
        entry->setToolTip(QDir::toNativeSeparators(f));
    }
    if (!files.isEmpty()) {
        m_recentMenu->addSeparator();
        QAction* clear =
            m_recentMenu->addAction(actionIcon("edit-clear-history"), tr("&Clear Menu"), this,
                                    &ProjectFiles::clearRecentFiles);
        clear->setObjectName("actionClearRecent");
        clear->setToolTip(tr("Forget the recent files (the files stay where they are)"));
    }
    m_recentMenu->setEnabled(!files.isEmpty());
}

void ProjectFiles::rebuildExamplesMenu() {
    m_examplesMenu->clear();
    const auto entries =
        QDir(kExamplesFolder)
            .entryInfoList({QStringLiteral("*.cam.json")}, QDir::Files, QDir::Name);
    for (const QFileInfo& f : entries) {
        const QString path = f.absoluteFilePath();
        m_examplesMenu->addAction(f.fileName().chopped(9), this,
                                  [this, path] { openExample(path); });
    }
    m_examplesMenu->setEnabled(!m_examplesMenu->isEmpty());
}

}  // namespace cam
