// Autosave and crash recovery, the way a user meets them: the real application runs as its own
// process on a real X display (Xvfb), an edit is typed into the segment table (xdotool), the
// recovery copy appears, the process is killed with SIGKILL, and the next start offers the
// copy; Restore and Ctrl+S put the edit into the project file, and a clean quit leaves no copy.
// Skipped (with the reason) where Xvfb or xdotool are missing; packaging/install-deps.sh
// installs both.

#include <gtest/gtest.h>

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QThread>
#include <functional>
#include <limits>

#include "document/commands.h"
#include "document/project_document.h"
#include "files/autosave.h"
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

    QTemporaryDir m_home;
    VirtualDisplay m_display{m_home.path()};
    QString m_project, m_recovery;
};

TEST_F(CrashRecovery, AKilledSessionsEditComesBackOnTheNextStart) {
    ASSERT_FALSE(m_display.name().isEmpty()) << "Xvfb did not start";
    const QString before = readAll(m_project);
    ASSERT_EQ(firstCentreX(m_project), 25.73752542);
    {
        QProcess app;
        start(app, {m_project});
        ASSERT_TRUE(waitForWindow("cam.cam.json")) << appLog();
        QThread::msleep(2000);  // laid out and computed
        // The window opens at 1400×860 in the top-left corner (no window manager); row 0's
        // "Centre x" cell of the Segments dock is at (121, 647). Type 26.5 into it.
        xdotool({"mousemove", "121", "647", "click", "--repeat", "2", "1"});
        QThread::msleep(400);
        xdotool({"key", "ctrl+a"});
        xdotool({"type", "26.5"});
        xdotool({"key", "Return"});
        // The recovery copy holds the edit within a few autosave intervals.
        ASSERT_TRUE(waitFor(
            [&] {
                const QStringList copies = recoveryCopies();
                return copies.size() == 1 &&
                       firstCentreX(QDir(m_recovery).filePath(copies.front())) == 26.5;
            },
            10000))
            << "no recovery copy with the edit in " << m_recovery.toStdString() << ": "
            << recoveryCopies().join(", ").toStdString();
        app.kill();  // SIGKILL: no chance to clean up
        ASSERT_TRUE(app.waitForFinished(5000));
    }
    EXPECT_EQ(readAll(m_project), before);  // the project file was never touched
    ASSERT_EQ(recoveryCopies().size(), 1u);
    {
        QProcess app;
        start(app, {});
        ASSERT_TRUE(waitForWindow("Recover Unsaved Changes")) << appLog();
        // Return answers Restore, the default button, once the box takes input (on a busy
        // machine it may not yet when it first appears: then press again).
        bool restored = false;
        for (int attempt = 0; attempt < 10 && !restored; ++attempt) {
            const QString box =
                xdotool({"search", "--onlyvisible", "--name", "Recover Unsaved Changes"})
                    .split('\n')
                    .front();
            if (!box.isEmpty()) {
                QThread::msleep(300);
                xdotool({"mousemove", "--window", box, "20", "20"});
                xdotool({"key", "Return"});
            }
            restored = waitFor(
                [&] {
                    return !xdotool({"search", "--name", "cam.cam.json"}).isEmpty();
                },
                2000);
        }
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

}  // namespace
}  // namespace cam
