#include "files/project_files.h"

#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QSettings>

#include "document/project_document.h"
#include "io/atomic_file.h"
#include "io/project_json.h"

namespace cam {
namespace {

constexpr int kMaxRecentFiles = 8;
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
    rebuildRecentMenu();
    rebuildExamplesMenu();
}

QString ProjectFiles::load(const QString& path) {
    auto loaded = loadProjectStructure(QFile::encodeName(path).toStdString());
    if (!loaded.ok()) {
        return tr("%1 cannot be opened:\n%2")
            .arg(QDir::toNativeSeparators(path), diagnosticsText(loaded.errors()));
    }
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_document->reset(std::move(loaded).value(), absolute);
    addRecentFile(absolute);
    const int problems = errorCount(m_document->diagnostics());
    emit message(problems == 0
                     ? tr("Opened %1").arg(QDir::toNativeSeparators(path))
                     : tr("Opened %1 with %n problem(s): listed in the status bar, marked in the "
                          "table",
                          "", problems)
                           .arg(QDir::toNativeSeparators(path)),
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
    const Diagnostics problems = writeFileAtomically(QFile::encodeName(path).toStdString(),
                                                     serializeProject(m_document->project()));
    if (!problems.empty()) {
        return tr("%1 could not be written: %2")
            .arg(QDir::toNativeSeparators(path), QString::fromStdString(problems.front().message));
    }
    const QString absolute = QFileInfo(path).absoluteFilePath();
    m_document->markSaved(absolute);
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
    const QString problem = load(path);
    if (!problem.isEmpty()) QMessageBox::warning(m_window, tr("Open Project"), problem);
}

bool ProjectFiles::save() {
    if (m_document->filePath().isEmpty()) return saveAs();
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
    const QString problem = save(path);
    if (!problem.isEmpty()) QMessageBox::warning(m_window, tr("Save Project"), problem);
    return problem.isEmpty();
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
    QSettings settings;
    QStringList files = settings.value("files/recent").toStringList();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > kMaxRecentFiles) files.removeLast();
    settings.setValue("files/recent", files);
    rebuildRecentMenu();
}

void ProjectFiles::rebuildRecentMenu() {
    m_recentMenu->clear();
    const QStringList files = QSettings().value("files/recent").toStringList();
    for (const QString& f : files) {
        m_recentMenu->addAction(QDir::toNativeSeparators(f), this, [this, f] { open(f); });
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
