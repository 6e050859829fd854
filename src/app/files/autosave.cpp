#include "files/autosave.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>
#include <algorithm>

#include "document/project_document.h"
#include "io/project_json.h"

namespace cam {
namespace {

constexpr int kDefaultIntervalS = 30;

QString defaultFolder() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
           QStringLiteral("/recovery");
}

/// Writes `bytes` to `path` through QSaveFile: the old copy stays whole until the new one is.
QString writeWhole(const QString& path, const QByteArray& bytes) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return file.errorString();
    if (file.write(bytes) != bytes.size()) return file.errorString();
    if (!file.commit()) return file.errorString();
    return {};
}

}  // namespace

Autosave::Autosave(ProjectDocument* document, QString folder, QObject* parent)
    : QObject(parent),
      m_document(document),
      m_folder(folder.isEmpty() ? defaultFolder() : std::move(folder)) {
    QDir().mkpath(m_folder);
    // One copy per window: the process id, and a count for a second window of one process.
    static int windows = 0;
    const QString base =
        m_folder +
        QStringLiteral("/session-%1-%2").arg(QCoreApplication::applicationPid()).arg(++windows);
    m_projectPath = base + QStringLiteral(".cam.json");
    m_metaPath = base + QStringLiteral(".json");
    // Held while this session runs: a copy whose lock is free belongs to a session that died.
    m_lock = std::make_unique<QLockFile>(base + QStringLiteral(".lock"));
    m_lock->setStaleLockTime(0);
    m_lock->tryLock(0);
    const int seconds =
        std::max(1, QSettings().value("autosave/intervalS", kDefaultIntervalS).toInt());
    m_timer.setInterval(seconds * 1000);
    connect(&m_timer, &QTimer::timeout, this, [this] { writeNow(); });
    m_timer.start();
    connect(document, &ProjectDocument::changed, this, [this] { ++m_changes; });
    // Saved, or another project: nothing unsaved to recover.
    connect(document, &ProjectDocument::modifiedChanged, this, [this](bool modified) {
        if (!modified) removeOwnCopy();
    });
    connect(document, &ProjectDocument::filePathChanged, this, [this] {
        if (!m_document->isModified()) removeOwnCopy();
    });
}

Autosave::~Autosave() {
    removeOwnCopy();
    if (m_lock) m_lock->unlock();
}

void Autosave::setIntervalMs(int ms) { m_timer.setInterval(std::max(ms, 10)); }

QString Autosave::writeNow() {
    if (!m_document->isModified() || (m_hasCopy && m_writtenAt == m_changes)) return {};
    // The note of the original file first: a session killed between the two writes leaves a
    // copy that still names its file (the other order left the first copy nameless).
    const QJsonObject meta{{"original", m_document->filePath()},
                           {"saved", QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs)}};
    QString problem = writeWhole(m_metaPath, QJsonDocument(meta).toJson());
    if (problem.isEmpty()) {
        const std::string text = serializeProject(m_document->project());
        problem = writeWhole(m_projectPath, QByteArray::fromStdString(text));
    }
    if (problem.isEmpty()) {
        m_hasCopy = true;
        m_writtenAt = m_changes;
    }
    emit written(m_projectPath, problem);
    return problem;
}

void Autosave::removeOwnCopy() {
    if (!m_hasCopy && !QFile::exists(m_projectPath)) return;
    QFile::remove(m_projectPath);
    QFile::remove(m_metaPath);
    m_hasCopy = false;
}

std::vector<Autosave::Orphan> Autosave::orphans() const {
    std::vector<Orphan> out;
    const QDir dir(m_folder);
    for (const QString& name :
         dir.entryList({QStringLiteral("session-*.cam.json")}, QDir::Files, QDir::Name)) {
        const QString project = dir.filePath(name);
        if (project == m_projectPath) continue;
        const QString base = project.chopped(int(QStringLiteral(".cam.json").size()));
        Orphan o{project, base + QStringLiteral(".json"), base + QStringLiteral(".lock"), {}, {}};
        // Its session still runs (another window): not an orphan.
        QLockFile lock(o.lock);
        lock.setStaleLockTime(0);
        if (!lock.tryLock(0)) continue;
        lock.unlock();
        QFile meta(o.meta);
        if (meta.open(QIODevice::ReadOnly)) {
            const QJsonObject m = QJsonDocument::fromJson(meta.readAll()).object();
            o.original = m.value("original").toString();
            o.saved = QDateTime::fromString(m.value("saved").toString(), Qt::ISODateWithMs);
        }
        if (!o.saved.isValid()) o.saved = QFileInfo(project).lastModified();
        out.push_back(o);
    }
    std::sort(out.begin(), out.end(),
              [](const Orphan& a, const Orphan& b) { return a.saved > b.saved; });
    return out;
}

void Autosave::discard(const Orphan& orphan) {
    QFile::remove(orphan.project);
    QFile::remove(orphan.meta);
    QFile::remove(orphan.lock);
}

}  // namespace cam
