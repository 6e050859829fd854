#include "files/autosave.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QSettings>
#include <QStandardPaths>
#include <QUuid>
#include <algorithm>
#include <map>

#include "document/project_document.h"
#include "files/file_watch.h"
#include "io/project_json.h"

namespace cam {
namespace {

constexpr int kDefaultIntervalS = 30;
constexpr QLatin1StringView kCopySuffix(".cam.json");
constexpr QLatin1StringView kNoteSuffix(".json");
constexpr QLatin1StringView kLockSuffix(".lock");

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

/// The session a file of the recovery folder belongs to: its name up to the first dot
/// ("session-<id>" of "session-<id>.cam.json", or of QSaveFile's "session-<id>.json.XyZ123").
QString sessionOf(const QString& fileName) { return fileName.section(QLatin1Char('.'), 0, 0); }

}  // namespace

Autosave::Autosave(ProjectDocument* document, QString folder, QObject* parent)
    : QObject(parent),
      m_document(document),
      m_folder(folder.isEmpty() ? defaultFolder() : std::move(folder)) {
    // A random id, never the process id: the next session may get this one's id again.
    const QString base =
        m_folder + QStringLiteral("/session-") + QUuid::createUuid().toString(QUuid::Id128);
    m_projectPath = base + kCopySuffix;
    m_metaPath = base + kNoteSuffix;
    m_lockPath = base + kLockSuffix;
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
    if (m_lock) {
        m_lock->removeFile();
        m_lock.reset();
    }
}

void Autosave::setIntervalMs(int ms) { m_timer.setInterval(std::max(ms, 10)); }

QString Autosave::writeNow() {
    if (!m_document->isModified() || (m_hasCopy && m_writtenAt == m_changes)) return {};
    QString problem;
    if (!m_lock) {
        QDir().mkpath(m_folder);
        // Taken with the first copy and held until the end: a copy whose lock is free belongs
        // to a session that ended. No copy without it (the next start would take a copy nobody
        // guards for an ended session's); a session that never has one leaves no file at all.
        m_lock = SessionLock::create(m_lockPath, &problem);
        if (!m_lock) {
            emit written(m_projectPath, problem);
            return problem;
        }
    }
    // The note of the original file first: a session killed between the two writes leaves a
    // copy that still names its file (the other order left the first copy nameless).
    // With the digest of what the session knew its file held: after a restore, a Save still
    // notices that another program wrote the file meanwhile.
    const QJsonObject meta{
        {"original", m_document->filePath()},
        {"original_sha256", QString::fromLatin1(m_document->fileDigest().toHex())},
        {"saved", QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs)}};
    problem = writeWhole(m_metaPath, QJsonDocument(meta).toJson());
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
    // Only what this session wrote: its name is its own, but a file it did not write is
    // never its to delete.
    if (!m_hasCopy) return;
    QFile::remove(m_projectPath);
    QFile::remove(m_metaPath);
    m_hasCopy = false;
}

std::vector<Autosave::Orphan> Autosave::orphans() const {
    const QDir dir(m_folder);
    const QString own = sessionOf(QFileInfo(m_lockPath).fileName());
    // Every file of the folder by its session.
    std::map<QString, QStringList> sessions;
    for (const QString& name :
         dir.entryList({QStringLiteral("session-*")}, QDir::Files, QDir::Name)) {
        const QString session = sessionOf(name);
        if (session != own) sessions[session] << name;
    }
    std::vector<Orphan> out;
    for (const auto& [session, names] : sessions) {
        const QString base = dir.filePath(session);
        Orphan o{base + kCopySuffix, base + kNoteSuffix, base + kLockSuffix, {}, {}, {}, nullptr};
        const bool hasLock = names.contains(session + kLockSuffix);
        if (hasLock) {
            o.claim = SessionLock::claim(o.lock);
            if (!o.claim) continue;  // its session runs, or another start has claimed it
        }
        if (!names.contains(session + kCopySuffix)) {
            // An ended session without a copy (it was saved, or killed before it had one, or
            // mid-write): what it left goes, its lock last, while it is held.
            for (const QString& name : names) {
                if (name != session + kLockSuffix) QFile::remove(dir.filePath(name));
            }
            if (o.claim) o.claim->removeFile();
            continue;
        }
        QFile meta(o.meta);
        if (meta.open(QIODevice::ReadOnly)) {
            const QJsonObject m = QJsonDocument::fromJson(meta.readAll()).object();
            o.original = m.value("original").toString();
            o.originalDigest =
                QByteArray::fromHex(m.value("original_sha256").toString().toLatin1());
            o.saved = QDateTime::fromString(m.value("saved").toString(), Qt::ISODateWithMs);
        }
        if (!o.saved.isValid()) o.saved = QFileInfo(o.project).lastModified();
        out.push_back(std::move(o));
    }
    std::sort(out.begin(), out.end(),
              [](const Orphan& a, const Orphan& b) { return a.saved > b.saved; });
    return out;
}

void Autosave::discard(const Orphan& orphan) {
    QFile::remove(orphan.project);
    QFile::remove(orphan.meta);
    if (orphan.claim) {
        orphan.claim->removeFile();
    } else {
        QFile::remove(orphan.lock);
    }
}

bool Autosave::adopt(const Orphan& orphan, QString* problem) {
    auto loaded = loadProjectStructure(QFile::encodeName(orphan.project).toStdString());
    if (!loaded.ok()) {
        *problem =
            tr("The recovery copy %1 cannot be read:\n%2")
                .arg(QDir::toNativeSeparators(orphan.project), diagnosticsText(loaded.errors()));
        return false;
    }
    m_document->reset(std::move(loaded).value(), orphan.original);
    // What the ended session knew its file held; a note without it (an older version's): what
    // the file holds now.
    m_document->setFileDigest(!orphan.originalDigest.isEmpty() || orphan.original.isEmpty()
                                  ? orphan.originalDigest
                                  : FileWatch::digestOfFile(orphan.original));
    m_document->markUnsaved();
    // This session's copy takes over before the orphan goes: a crash in between loses nothing.
    const QString written = writeNow();
    if (!written.isEmpty()) {
        *problem = tr("The unsaved changes were restored, but their new recovery copy could not "
                      "be written (%1); the old copy %2 is kept.")
                       .arg(written, QDir::toNativeSeparators(orphan.project));
        return true;
    }
    problem->clear();
    discard(orphan);
    return true;
}

}  // namespace cam
