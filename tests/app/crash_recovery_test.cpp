// Autosave and crash recovery, the way a user meets them: the real application runs as its own
// process on a real X display (Xvfb), an edit is typed into the segment table (xdotool), the
// recovery copy appears, the process is killed with SIGKILL, and the next start offers the
// copy; Restore and Ctrl+S put the edit into the project file, and a clean quit leaves no copy.
// Skipped (with the reason) where Xvfb or xdotool are missing; packaging/install-deps.sh
// installs both.

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStandardPaths>
#include <QSysInfo>
#include <QTemporaryDir>
#include <QThread>
#include <atomic>
#include <functional>
#include <set>
#include <thread>

#include <unistd.h>
#include <limits>

#include "document/commands.h"
#include "document/project_document.h"
#include "files/autosave.h"
#include "files/session_lock.h"
#include "io/project_json.h"
#include "test_support.h"

namespace cam {
namespace {

bool waitFor(const std::function<bool()>& done, int timeoutMs) {
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > timeoutMs) return false;
        QThread::msleep(50);
    }
    return true;
}

QString readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

/// contour[0].center[0] of a project file (NaN when it cannot be read).
double firstCentreX(const QString& path) {
    const QJsonArray contour =
        QJsonDocument::fromJson(readAll(path).toUtf8()).object().value("contour").toArray();
    if (contour.isEmpty()) return std::numeric_limits<double>::quiet_NaN();
    return contour.first().toObject().value("center").toArray().first().toDouble(
        std::numeric_limits<double>::quiet_NaN());
}

/// An X server of our own on a free display, gone with this object. The server picks the
/// display itself and says which (-displayfd): two tests starting at once (ctest -j2) cannot
/// both take the one that looked free, as they could when the test chose it. What it prints
/// goes to files (a pipe nobody reads while the test sleeps could fill and stall it).
class VirtualDisplay {
public:
    explicit VirtualDisplay(const QString& folder) : m_log(folder + "/xvfb.log") {
        const QString said = folder + "/xvfb.display";
        m_server.setStandardOutputFile(said);
        m_server.setStandardErrorFile(m_log);
        m_server.start("Xvfb", {"-displayfd", "1", "-screen", "0", "1600x1000x24", "-nolisten",
                                "tcp", "-noreset"});
        if (!m_server.waitForStarted(5000)) return;
        const bool told = waitFor(
            [&] {
                QFile f(said);
                return f.open(QIODevice::ReadOnly) && f.readAll().contains('\n');
            },
            30000);
        QFile f(said);
        bool isNumber = false;
        const int n = f.open(QIODevice::ReadOnly) ? f.readAll().trimmed().toInt(&isNumber) : -1;
        if (!told || !isNumber) return;
        // Up when a client can ask it something.
        const QString name = QStringLiteral(":%1").arg(n);
        const auto answers = [&name] {
            QProcess probe;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert("DISPLAY", name);
            probe.setProcessEnvironment(env);
            probe.start("xdotool", {"getdisplaygeometry"});
            return probe.waitForFinished(5000) && probe.exitCode() == 0;
        };
        if (waitFor(answers, 30000)) m_name = name;
    }
    /// What the server said, and whether it still runs: for a failure's message.
    [[nodiscard]] std::string state() const {
        QFile f(m_log);
        const QString log = f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : "";
        return (m_server.state() == QProcess::Running ? "Xvfb runs; " : "Xvfb has ended; ") +
               log.right(2000).toStdString();
    }
    ~VirtualDisplay() {
        m_server.terminate();
        m_server.waitForFinished(5000);
    }
    [[nodiscard]] const QString& name() const { return m_name; }

private:
    QString m_log;
    QProcess m_server;
    QString m_name;
};

class CrashRecovery : public ::testing::Test {
protected:
    void SetUp() override {
        if (QStandardPaths::findExecutable("Xvfb").isEmpty() ||
            QStandardPaths::findExecutable("xdotool").isEmpty()) {
            GTEST_SKIP() << "needs Xvfb and xdotool (apt install xvfb xdotool)";
        }
        ASSERT_TRUE(m_home.isValid());
        m_project = m_home.filePath("cam.cam.json");
        ASSERT_TRUE(QFile::copy(
            QString::fromStdString(test::examplePath("six-lobe-arc-cam.cam.json")), m_project));
        QFile::setPermissions(m_project, QFile::ReadOwner | QFile::WriteOwner);
        m_recovery = m_home.filePath("data/Camwright/Camwright/recovery");
    }

    /// The application on the virtual display, with settings and data in the test's folder.
    void start(QProcess& app, const QStringList& args) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("DISPLAY", m_display.name());
        env.insert("QT_QPA_PLATFORM", "xcb");
        env.insert("XDG_DATA_HOME", m_home.filePath("data"));
        env.insert("XDG_CONFIG_HOME", m_home.filePath("config"));
        env.insert("LANG", "C.UTF-8");
        env.insert("LC_ALL", "C.UTF-8");
        // In a sanitizer build: libdbus's own leak at exit is not ours (tests/sanitizers).
        env.insert("LSAN_OPTIONS",
                   "suppressions=" CAMWRIGHT_SOURCE_DIR "/tests/sanitizers/lsan.supp");
        app.setProcessEnvironment(env);
        app.setProcessChannelMode(QProcess::MergedChannels);
        app.setStandardOutputFile(m_home.filePath("app.log"), QIODevice::Append);
        app.start(QStringLiteral(CAMWRIGHT_APP), QStringList{"--autosave-interval", "0.2"} + args);
        ASSERT_TRUE(app.waitForStarted(10000));
    }

    /// Runs xdotool on the virtual display; its standard output.
    QString xdotool(const QStringList& args) {
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("DISPLAY", m_display.name());
        p.setProcessEnvironment(env);
        p.start("xdotool", args);
        p.waitForFinished(10000);
        return QString::fromUtf8(p.readAllStandardOutput()).trimmed();
    }

    /// What the application printed (all its runs).
    [[nodiscard]] std::string appLog() const {
        return readAll(m_home.filePath("app.log")).toStdString();
    }

    bool waitForWindow(const QString& title, int timeoutMs = 60000) {
        const bool found = waitFor(
            [&] {
                return !xdotool({"search", "--name", title}).isEmpty();
            },
            timeoutMs);
        if (!found) {
            ADD_FAILURE() << "no window \"" << title.toStdString() << "\" on "
                          << m_display.name().toStdString()
                          << "; windows: " << xdotool({"search", "--name", "."}).toStdString()
                          << "; " << m_display.state();
        }
        return found;
    }

    /// The titles of the windows on the display that are shown, for a failure's message.
    QString visibleWindowNames() {
        QStringList names;
        for (const QString& id :
             xdotool({"search", "--onlyvisible", "--name", "."}).split('\n', Qt::SkipEmptyParts))
            names << '"' + xdotool({"getwindowname", id}) + '"';
        return names.join(", ");
    }

    QStringList recoveryCopies() const {
        return QDir(m_recovery).entryList({"session-*.cam.json"}, QDir::Files);
    }

    /// Presses `key` in the recovery question once it takes input (on a busy machine it may
    /// not yet when it first appears: then again) until `answered()`.
    bool answerRecoveryBox(const char* key, const std::function<bool()>& answered) {
        for (int attempt = 0; attempt < 10; ++attempt) {
            const QString box =
                xdotool({"search", "--onlyvisible", "--name", "Recover Unsaved Changes"})
                    .split('\n')
                    .front();
            if (!box.isEmpty()) {
                QThread::msleep(300);
                xdotool({"mousemove", "--window", box, "20", "20"});
                xdotool({"key", key});
            }
            if (waitFor(answered, 2000)) return true;
        }
        return false;
    }

    /// Opens the project, types 26.5 into row 0's "Centre x" cell, waits for the recovery copy
    /// to hold it and kills the application with SIGKILL; its process id.
    qint64 killAfterAnEdit() {
        QProcess app;
        start(app, {m_project});
        if (!waitForWindow("cam.cam.json")) {
            ADD_FAILURE() << appLog();
            return 0;
        }
        QThread::msleep(2000);  // laid out and computed
        // The window opens at 1400×860 in the top-left corner (no window manager); row 0's
        // "Centre x" cell of the Segments dock is at (121, 647). Type 26.5 into it.
        xdotool({"mousemove", "121", "647", "click", "--repeat", "2", "1"});
        QThread::msleep(400);
        xdotool({"key", "ctrl+a"});
        xdotool({"type", "26.5"});
        xdotool({"key", "Return"});
        // The recovery copy holds the edit within a few autosave intervals.
        const bool copied = waitFor(
            [&] {
                const QStringList copies = recoveryCopies();
                return copies.size() == 1 &&
                       firstCentreX(QDir(m_recovery).filePath(copies.front())) == 26.5;
            },
            10000);
        EXPECT_TRUE(copied) << "no recovery copy with the edit in " << m_recovery.toStdString()
                            << ": " << recoveryCopies().join(", ").toStdString();
        const qint64 pid = app.processId();
        app.kill();  // SIGKILL: no chance to clean up
        EXPECT_TRUE(app.waitForFinished(5000));
        return pid;
    }

    QTemporaryDir m_home;
    VirtualDisplay m_display{m_home.path()};
    QString m_project, m_recovery;
};

TEST_F(CrashRecovery, AKilledSessionsEditComesBackOnTheNextStart) {
    ASSERT_FALSE(m_display.name().isEmpty()) << "Xvfb did not start";
    const QString before = readAll(m_project);
    ASSERT_EQ(firstCentreX(m_project), 25.73752542);
    killAfterAnEdit();
    EXPECT_EQ(readAll(m_project), before);  // the project file was never touched
    ASSERT_EQ(recoveryCopies().size(), 1u);
    {
        QProcess app;
        start(app, {});
        ASSERT_TRUE(waitForWindow("Recover Unsaved Changes")) << appLog();
        // Return answers Restore, the default button.
        const bool restored = answerRecoveryBox("Return", [&] {
            return !xdotool({"search", "--name", "cam.cam.json"}).isEmpty();
        });
        ASSERT_TRUE(restored) << "windows shown: " << visibleWindowNames().toStdString()
                              << "; log: " << appLog();
        QThread::msleep(1000);
        // The restored project is the file's, unsaved: Ctrl+S writes the edit into it.
        xdotool({"mousemove", "300", "849", "click", "1"});  // the status bar: activates the window
        QThread::msleep(300);
        xdotool({"key", "ctrl+s"});
        ASSERT_TRUE(waitFor([&] { return firstCentreX(m_project) == 26.5; }, 10000))
            << readAll(m_project).left(400).toStdString();
        // Saved: no copy; a clean quit leaves nothing behind.
        EXPECT_TRUE(waitFor([&] { return recoveryCopies().isEmpty(); }, 5000));
        xdotool({"key", "ctrl+q"});
        ASSERT_TRUE(app.waitForFinished(10000)) << "the app did not quit";
        EXPECT_EQ(app.exitStatus(), QProcess::NormalExit);
        EXPECT_EQ(app.exitCode(), 0);
    }
    EXPECT_TRUE(recoveryCopies().isEmpty());
    EXPECT_TRUE(QDir(m_recovery).entryList({"session-*"}, QDir::Files).isEmpty());
}

TEST_F(CrashRecovery, TheNextSessionOffersTheCopyEvenWithTheKilledOnesProcessId) {
    // The probe's data loss, as it happens where the application always gets the same process
    // id (containers, systemd): the next session took the copy for its own, did not offer it
    // and deleted it at its clean end. The kernel is asked for the killed session's id.
    ASSERT_FALSE(m_display.name().isEmpty()) << "Xvfb did not start";
    const qint64 killed = killAfterAnEdit();
    ASSERT_GT(killed, 1);
    ASSERT_EQ(recoveryCopies().size(), 1u);
    QProcess app;
    for (int attempt = 0; attempt < 20; ++attempt) {
        QFile last("/proc/sys/kernel/ns_last_pid");
        if (!last.open(QIODevice::WriteOnly) || last.write(QByteArray::number(killed - 1)) <= 0 ||
            !last.flush()) {
            GTEST_SKIP() << "cannot choose the next process id here (/proc/sys/kernel/"
                            "ns_last_pid needs root); Autosave.AnEndedSessionsCopyIsOffered"
                            "WhateverProcessIdItsLockNames covers it in-process";
        }
        last.close();
        start(app, {});
        if (app.processId() == killed) break;
        app.kill();
        app.waitForFinished(5000);
    }
    if (app.processId() != killed) {
        GTEST_SKIP() << "another process took id " << killed << " each time";
    }
    ASSERT_TRUE(waitForWindow("Recover Unsaved Changes")) << appLog();
    // Escape answers Later: the copy stays for the next start; then a clean quit.
    const bool answered = answerRecoveryBox("Escape", [&] {
        return xdotool({"search", "--onlyvisible", "--name", "Recover Unsaved Changes"}).isEmpty();
    });
    ASSERT_TRUE(answered) << visibleWindowNames().toStdString();
    ASSERT_TRUE(waitForWindow("Camwright")) << appLog();
    QThread::msleep(1000);
    xdotool({"mousemove", "300", "849", "click", "1"});
    QThread::msleep(300);
    xdotool({"key", "ctrl+q"});
    ASSERT_TRUE(app.waitForFinished(10000)) << "the app did not quit";
    EXPECT_EQ(app.exitCode(), 0);
    const QStringList copies = recoveryCopies();
    ASSERT_EQ(copies.size(), 1u);
    EXPECT_EQ(firstCentreX(QDir(m_recovery).filePath(copies.front())), 26.5);
}

/// The six-lobe example in `doc`, as if opened from `path`.
bool openSixLobe(ProjectDocument& doc, const QString& path) {
    auto project = loadProjectFile(test::examplePath("six-lobe-arc-cam.cam.json"));
    if (!project.ok()) return false;
    doc.reset(project.value(), path);
    return true;
}

/// An edit of the first arc's centre x, as the table makes it.
void moveFirstCentreX(ProjectDocument& doc, double x) {
    SegmentSpec moved = doc.project().contour.front();
    std::get<Arc>(moved.shape).center.x() = x;
    doc.undoStack()->push(new EditSegment(&doc, 0, moved, EditedField::CenterX, "edit"));
}

TEST(Autosave, ACopyIsWrittenOnlyWhileThereAreUnsavedChangesAndSavingRemovesIt) {
    QTemporaryDir folder;
    ProjectDocument doc;
    ASSERT_TRUE(openSixLobe(doc, folder.filePath("cam.cam.json")));
    {
        Autosave autosave(&doc, folder.filePath("recovery"));
        const QString copy = autosave.recoveryPath();
        EXPECT_TRUE(autosave.writeNow().isEmpty());
        EXPECT_FALSE(QFile::exists(copy));  // nothing unsaved: no copy
        moveFirstCentreX(doc, 26.5);
        EXPECT_TRUE(autosave.writeNow().isEmpty());
        ASSERT_TRUE(QFile::exists(copy));
        EXPECT_EQ(firstCentreX(copy), 26.5);
        // The copy reads back as the document, and names the file it belongs to.
        auto back = loadProjectStructure(QFile::encodeName(copy).toStdString());
        ASSERT_TRUE(back.ok());
        EXPECT_EQ(back.value(), doc.project());
        EXPECT_TRUE(readAll(autosave.notePath()).contains("cam.cam.json"));
        // This session is alive: its copy is nobody's orphan.
        EXPECT_TRUE(autosave.orphans().empty());
        doc.markSaved(doc.filePath());
        EXPECT_FALSE(QFile::exists(copy));  // saved: nothing to recover
        doc.undoStack()->undo();            // unsaved again
        EXPECT_TRUE(autosave.writeNow().isEmpty());
        EXPECT_EQ(firstCentreX(copy), 25.73752542);
    }
    // A clean end removes it.
    EXPECT_TRUE(QDir(folder.filePath("recovery")).entryList({"session-*"}, QDir::Files).isEmpty());
}

TEST(Autosave, NoCopyExistsWithoutTheNoteOfItsFile) {
    // A session killed between writing the copy and its note left a copy that restored as
    // an untitled project. The note comes first: when it cannot be written, neither is the copy.
    QTemporaryDir folder;
    ProjectDocument doc;
    ASSERT_TRUE(openSixLobe(doc, folder.filePath("cam.cam.json")));
    Autosave autosave(&doc, folder.filePath("recovery"));
    const QString copy = autosave.recoveryPath();
    const QString note = autosave.notePath();
    ASSERT_TRUE(QDir().mkpath(note));  // a folder where the note goes: it cannot be written
    moveFirstCentreX(doc, 26.5);
    EXPECT_FALSE(autosave.writeNow().isEmpty());
    EXPECT_FALSE(QFile::exists(copy));
    ASSERT_TRUE(QDir().rmdir(note));
    EXPECT_TRUE(autosave.writeNow().isEmpty());
    EXPECT_EQ(firstCentreX(copy), 26.5);
    EXPECT_TRUE(readAll(note).contains("cam.cam.json"));
}

/// What a session that ended without cleaning up leaves in `folder` as `<base>.*`: the six-lobe
/// project with its first centre at `x` as the copy, a note naming `original`, and a lock file
/// nobody holds whose text (what QLockFile writes: process id, program, host) is `lockText`.
void leaveEndedSession(const QString& folder, const QString& base, double x,
                       const QString& original, const QByteArray& lockText) {
    QDir().mkpath(folder);
    ProjectDocument doc;
    ASSERT_TRUE(openSixLobe(doc, original));
    moveFirstCentreX(doc, x);
    QFile copy(folder + "/" + base + ".cam.json");
    ASSERT_TRUE(copy.open(QIODevice::WriteOnly));
    copy.write(QByteArray::fromStdString(serializeProject(doc.project())));
    QFile note(folder + "/" + base + ".json");
    ASSERT_TRUE(note.open(QIODevice::WriteOnly));
    note.write(
        QJsonDocument(QJsonObject{{"original", original}, {"saved", "2026-11-27T10:00:00.000Z"}})
            .toJson());
    QFile lock(folder + "/" + base + ".lock");
    ASSERT_TRUE(lock.open(QIODevice::WriteOnly));
    lock.write(lockText);
}

/// The lock text QLockFile writes for process (or thread) `id` of the program running here:
/// to QLockFile such a lock belongs to a live session.
QByteArray lockTextOf(qint64 id) {
    const QString program = QFileInfo(QFile::symLinkTarget("/proc/self/exe")).fileName();
    return QByteArray::number(id) + '\n' + program.toUtf8() + '\n' +
           QSysInfo::machineHostName().toUtf8() + '\n';
}

QStringList filesIn(const QString& folder) {
    return QDir(folder).entryList(QDir::Files | QDir::Hidden, QDir::Name);
}

TEST(Autosave, AnEndedSessionsCopyIsOfferedWhateverProcessIdItsLockNames) {
    // The probe's data loss: the next session was given the dead one's process id, skipped its
    // copy as its own and deleted it. Here the dead sessions' locks name this very process (as
    // a session with the reused id would find) and a live thread of it: neither may hide a
    // copy, and none of them is deleted unseen.
    QTemporaryDir home;
    const QString folder = home.filePath("recovery");
    const qint64 pid = QCoreApplication::applicationPid();
    std::atomic<qint64> threadId{0};
    std::atomic<bool> stop{false};
    std::thread live([&] {
        threadId = static_cast<qint64>(::gettid());
        while (!stop) QThread::msleep(5);
    });
    while (threadId == 0) QThread::msleep(1);
    // The name this process would have had under the old naming, the old naming with another
    // id, and the current naming.
    leaveEndedSession(folder, QStringLiteral("session-%1-1").arg(pid), 26.5, "/p/a.cam.json",
                      lockTextOf(pid));
    leaveEndedSession(folder, QStringLiteral("session-%1-1").arg(threadId.load()), 27.5,
                      "/p/b.cam.json", lockTextOf(threadId));
    leaveEndedSession(folder, "session-0123456789abcdef0123456789abcdef", 28.5, "/p/c.cam.json",
                      lockTextOf(pid));
    {
        ProjectDocument doc;
        ASSERT_TRUE(openSixLobe(doc, home.filePath("mine.cam.json")));
        Autosave autosave(&doc, folder);
        const std::vector<Autosave::Orphan> orphans = autosave.orphans();
        std::set<double> offered;
        for (const Autosave::Orphan& o : orphans) offered.insert(firstCentreX(o.project));
        EXPECT_EQ(offered, (std::set<double>{26.5, 27.5, 28.5}));
        // This session's own name is none of theirs, and it ends (saved, then cleanly) without
        // touching them.
        EXPECT_FALSE(autosave.recoveryPath().contains(QString::number(pid)));
        moveFirstCentreX(doc, 30.0);
        EXPECT_TRUE(autosave.writeNow().isEmpty());
        doc.markSaved(doc.filePath());
    }
    stop = true;
    live.join();
    EXPECT_EQ(QDir(folder).entryList({"session-*.cam.json"}, QDir::Files).size(), 3u)
        << filesIn(folder).join(", ").toStdString();
}

TEST(Autosave, ALiveSessionsCopyIsNobodysOrphanAndAnOfferedCopyIsClaimed) {
    QTemporaryDir home;
    const QString folder = home.filePath("recovery");
    ProjectDocument first, second, third;
    ASSERT_TRUE(openSixLobe(first, home.filePath("a.cam.json")));
    ASSERT_TRUE(openSixLobe(second, home.filePath("b.cam.json")));
    ASSERT_TRUE(openSixLobe(third, home.filePath("c.cam.json")));
    Autosave a(&first, folder), b(&second, folder);
    moveFirstCentreX(first, 26.5);
    ASSERT_TRUE(a.writeNow().isEmpty());
    // Another window of the same process, alive: not offered.
    EXPECT_TRUE(b.orphans().empty());
    leaveEndedSession(folder, "session-dead", 27.5, "/p/dead.cam.json", lockTextOf(1));
    {
        // While one starting session offers the ended one's copy, another does not.
        const std::vector<Autosave::Orphan> offered = b.orphans();
        ASSERT_EQ(offered.size(), 1u);
        EXPECT_EQ(firstCentreX(offered.front().project), 27.5);
        Autosave c(&third, folder);
        EXPECT_TRUE(c.orphans().empty());
    }
    // Once it is no longer offered ("Later"), it is offered again.
    ASSERT_EQ(b.orphans().size(), 1u);
}

TEST(Autosave, NoSessionDeletesACopyItDidNotWrite) {
    QTemporaryDir home;
    const QString folder = home.filePath("recovery");
    ProjectDocument doc;
    ASSERT_TRUE(openSixLobe(doc, home.filePath("a.cam.json")));
    Autosave autosave(&doc, folder);
    // A file at this session's own name that it never wrote (whatever put it there).
    ASSERT_TRUE(QDir().mkpath(folder));
    {
        QFile foreign(autosave.recoveryPath());
        ASSERT_TRUE(foreign.open(QIODevice::WriteOnly));
        foreign.write("{}");
    }
    moveFirstCentreX(doc, 26.5);
    doc.markSaved(doc.filePath());  // saved: this session's copy would go
    doc.reset(doc.project(), home.filePath("b.cam.json"));
    EXPECT_TRUE(QFile::exists(autosave.recoveryPath()));
}

TEST(Autosave, EndedSessionsWithoutACopyLeaveNothingBehind) {
    // The probe found 119 lock files of killed sessions that nothing removed.
    QTemporaryDir home;
    const QString folder = home.filePath("recovery");
    QDir().mkpath(folder);
    const auto touch = [&](const QString& name) {
        QFile f(folder + "/" + name);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("1\ncamwright\nhost\n");
    };
    touch("session-4242-1.lock");           // an older version's, killed while saved
    touch("session-aaaa.lock");             // killed before it had a copy …
    touch("session-aaaa.json");             // … but after its note
    touch("session-bbbb.lock");             // killed while writing its copy:
    touch("session-bbbb.cam.json.k2Xq9a");  // QSaveFile's temporary
    // A live session without a copy yet keeps its lock.
    auto live = SessionLock::create(folder + "/session-cccc.lock");
    ASSERT_TRUE(live);
    ProjectDocument doc;
    ASSERT_TRUE(openSixLobe(doc, home.filePath("a.cam.json")));
    Autosave autosave(&doc, folder);
    EXPECT_TRUE(autosave.orphans().empty());
    EXPECT_EQ(filesIn(folder), QStringList{"session-cccc.lock"});
    // This session has no copy, so no files at all (a headless run leaves nothing).
    EXPECT_FALSE(QFile::exists(autosave.lockPath()));
}

/// A session that ended leaving the six-lobe project (first centre at 27.5) as a copy of
/// cam.cam.json, and this session's document and autosave in the same folder.
class Restore : public ::testing::Test {
protected:
    void SetUp() override {
        leaveEndedSession(m_folder, "session-dead", 27.5, m_home.filePath("cam.cam.json"),
                          lockTextOf(1));
    }
    QTemporaryDir m_home;
    QString m_folder = m_home.filePath("recovery");
    ProjectDocument m_doc;
    Autosave m_autosave{&m_doc, m_folder};
};

TEST_F(Restore, ThisSessionsCopyIsWrittenBeforeTheOldOneGoes) {
    std::vector<Autosave::Orphan> orphans = m_autosave.orphans();
    ASSERT_EQ(orphans.size(), 1u);
    QString problem;
    ASSERT_TRUE(m_autosave.adopt(orphans.front(), &problem)) << problem.toStdString();
    EXPECT_TRUE(problem.isEmpty()) << problem.toStdString();
    EXPECT_EQ(m_doc.filePath(), m_home.filePath("cam.cam.json"));
    EXPECT_TRUE(m_doc.isModified());
    // The edit is safe in this session's copy, and the ended session's files are gone.
    EXPECT_EQ(firstCentreX(m_autosave.recoveryPath()), 27.5);
    EXPECT_FALSE(QFile::exists(orphans.front().project));
    EXPECT_FALSE(QFile::exists(orphans.front().meta));
    EXPECT_FALSE(QFile::exists(orphans.front().lock));
}

TEST_F(Restore, ARestoreThatCannotWriteItsOwnCopyKeepsTheOldOne) {
    ASSERT_TRUE(QDir().mkpath(m_autosave.notePath()));  // a folder where the note goes
    std::vector<Autosave::Orphan> orphans = m_autosave.orphans();
    ASSERT_EQ(orphans.size(), 1u);
    QString problem;
    EXPECT_TRUE(m_autosave.adopt(orphans.front(), &problem));
    EXPECT_TRUE(problem.contains("kept")) << problem.toStdString();
    EXPECT_EQ(firstCentreX(orphans.front().project), 27.5);
}

}  // namespace
}  // namespace cam
