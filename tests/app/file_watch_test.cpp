// Issue 27, point 2: saving never silently undoes someone else's save. Two windows on one file
// (as two processes would be: each window marks its file with its own lock and keeps the digest
// of what it read or wrote), a file replaced on disk behind the window's back, Save of an
// unmodified document, and a file another window already has open.

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <QAbstractButton>
#include <QApplication>
#include <QFile>
#include <QMessageBox>
#include <QProcess>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>

#include "app_test_support.h"
#include "document/commands.h"
#include "document/project_document.h"
#include "files/autosave.h"
#include "files/file_watch.h"
#include "files/project_files.h"
#include "io/project_json.h"
#include "mainwindow.h"

namespace cam {
namespace {

/// Answers the message box named `name` with the button labelled `button` once it is shown,
/// and remembers what it said.
class Answer {
public:
    Answer(const char* name, QString button) : m_name(name), m_button(std::move(button)) {
        m_timer.setInterval(10);
        QObject::connect(&m_timer, &QTimer::timeout, [this] { look(); });
        m_timer.start();
    }
    [[nodiscard]] bool given() const { return m_given; }
    [[nodiscard]] const QString& said() const { return m_said; }

private:
    void look() {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box || box->objectName() != m_name) return;
        for (QAbstractButton* b : box->buttons()) {
            if (b->text().remove('&') != m_button) continue;
            m_said = box->text() + "\n" + box->informativeText();
            m_given = true;
            m_timer.stop();
            b->click();
            return;
        }
        ADD_FAILURE() << "no button " << m_button.toStdString() << " in " << m_name.toStdString();
        box->reject();
    }

    QString m_name, m_button, m_said;
    QTimer m_timer;
    bool m_given = false;
};

/// The speed a project file holds (NaN when it cannot be read).
double rpmIn(const QString& path) {
    auto p = loadProjectStructure(QFile::encodeName(path).toStdString());
    return p.ok() ? p.value().motion.value : std::nan("");
}

void setRpm(MainWindow& window, double rpm) {
    window.document()->undoStack()->push(new SetMotion(window.document(), {SpeedUnit::Rpm, rpm}));
}

/// Replaces `path` as another program saving atomically would: a new file renamed over it.
void replaceOnDisk(const QString& path, double rpm) {
    Project p = test::loadExample();
    p.motion = {SpeedUnit::Rpm, rpm};
    QFile f(path + ".other");
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(QByteArray::fromStdString(serializeProject(p)));
    f.close();
    ASSERT_EQ(std::rename(QFile::encodeName(path + ".other").constData(),
                          QFile::encodeName(path).constData()),
              0);
}

class FileWatchTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(m_dir.isValid());
        m_path = m_dir.filePath("cam.cam.json");
        ASSERT_TRUE(QFile::copy(test::kExampleFile, m_path));
        QFile::setPermissions(m_path, QFile::ReadOwner | QFile::WriteOwner);
    }
    QTemporaryDir m_dir;
    QString m_path;
};

TEST_F(FileWatchTest, ASaveAfterAnotherWindowSavedAsksBeforeItOverwrites) {
    MainWindow a, b;
    ASSERT_TRUE(a.loadFile(m_path).isEmpty());
    ASSERT_TRUE(b.loadFile(m_path).isEmpty());
    EXPECT_TRUE(b.statusBar()->currentMessage().contains("open in another Camwright window"))
        << b.statusBar()->currentMessage().toStdString();
    setRpm(a, 100);
    ASSERT_TRUE(a.files()->save());
    ASSERT_EQ(rpmIn(m_path), 100);
    // B hears of it and keeps its version.
    {
        Answer keep("changedOnDiskBox", "Keep This Version");
        ASSERT_TRUE(test::processEventsUntil([&] { return keep.given(); }));
        EXPECT_TRUE(keep.said().contains("changed on disk")) << keep.said().toStdString();
    }
    // B's edit and Ctrl+S: asked first; No keeps A's save.
    setRpm(b, 200);
    {
        Answer no("overwriteChangedBox", "Cancel");
        EXPECT_FALSE(b.files()->save());
        EXPECT_TRUE(no.given());
    }
    EXPECT_EQ(rpmIn(m_path), 100);
    EXPECT_TRUE(b.document()->isModified());
    {
        Answer yes("overwriteChangedBox", "Overwrite");
        EXPECT_TRUE(b.files()->save());
        EXPECT_TRUE(yes.given());
    }
    EXPECT_EQ(rpmIn(m_path), 200);
    // Now A is the one behind: its next save asks too (whether or not it has seen B's yet).
    setRpm(a, 300);
    {
        Answer no("overwriteChangedBox", "Cancel");
        EXPECT_FALSE(a.files()->save());
        EXPECT_TRUE(no.given());
    }
    EXPECT_EQ(rpmIn(m_path), 200);
}

TEST_F(FileWatchTest, AFileReplacedOnDiskIsNotOverwrittenWithoutAQuestion) {
    // Without a turn of the event loop in between: the check at Save does not depend on the
    // watcher having seen the change.
    MainWindow window;
    ASSERT_TRUE(window.loadFile(m_path).isEmpty());
    setRpm(window, 100);
    replaceOnDisk(m_path, 77);
    {
        Answer no("overwriteChangedBox", "Cancel");
        EXPECT_FALSE(window.files()->save());
        EXPECT_TRUE(no.given());
        EXPECT_TRUE(no.said().contains("changed on disk")) << no.said().toStdString();
    }
    EXPECT_EQ(rpmIn(m_path), 77);
    EXPECT_TRUE(window.document()->isModified());
}

TEST_F(FileWatchTest, AnUnmodifiedWindowOffersToReloadAFileReplacedOnDisk) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(m_path).isEmpty());
    ASSERT_NE(window.document()->project().motion.value, 77);
    replaceOnDisk(m_path, 77);
    Answer reload("changedOnDiskBox", "Reload");
    ASSERT_TRUE(test::processEventsUntil([&] { return reload.given(); }));
    EXPECT_TRUE(
        test::processEventsUntil([&] { return window.document()->project().motion.value == 77; }));
    EXPECT_FALSE(window.document()->isModified());
    EXPECT_EQ(window.document()->filePath(), m_path);
    // Reloaded: this window knows the new content, and a save of a new edit asks nothing.
    setRpm(window, 78);
    EXPECT_TRUE(window.files()->save());
    EXPECT_EQ(rpmIn(m_path), 78);
}

TEST_F(FileWatchTest, SaveOfAnUnmodifiedDocumentWritesNothing) {
    MainWindow window;
    ASSERT_TRUE(window.loadFile(m_path).isEmpty());
    struct stat before {
    }, after{};
    ASSERT_EQ(::stat(QFile::encodeName(m_path).constData(), &before), 0);
    EXPECT_TRUE(window.files()->save());
    ASSERT_EQ(::stat(QFile::encodeName(m_path).constData(), &after), 0);
    EXPECT_EQ(after.st_ino, before.st_ino);  // an atomic save is a new file
    EXPECT_EQ(after.st_mtim.tv_nsec, before.st_mtim.tv_nsec);
    EXPECT_EQ(after.st_mtim.tv_sec, before.st_mtim.tv_sec);
    EXPECT_TRUE(window.statusBar()->currentMessage().startsWith("Nothing to save"))
        << window.statusBar()->currentMessage().toStdString();
    // Changed by someone else and nothing unsaved here: still nothing written.
    replaceOnDisk(m_path, 77);
    EXPECT_TRUE(window.files()->save());
    EXPECT_EQ(rpmIn(m_path), 77);
    // Deleted: Save writes it again.
    ASSERT_TRUE(QFile::remove(m_path));
    EXPECT_TRUE(window.files()->save());
    EXPECT_EQ(rpmIn(m_path), window.document()->project().motion.value);
}

TEST_F(FileWatchTest, OpeningAFileAnotherWindowHasOpenAsksFirst) {
    MainWindow a, b;
    ASSERT_TRUE(a.loadFile(m_path).isEmpty());
    {
        Answer cancel("openElsewhereBox", "Cancel");
        b.files()->open(m_path);
        EXPECT_TRUE(cancel.given());
        EXPECT_TRUE(cancel.said().contains("already open in another Camwright window"))
            << cancel.said().toStdString();
    }
    EXPECT_TRUE(b.document()->filePath().isEmpty());
    {
        Answer open("openElsewhereBox", "Open");
        b.files()->open(m_path);
        EXPECT_TRUE(open.given());
    }
    EXPECT_EQ(b.document()->filePath(), m_path);
    // A window's own file is not "elsewhere"; once the other window has closed it, neither.
    EXPECT_TRUE(b.files()->watch()->isOpenElsewhere(m_path));
    ASSERT_TRUE(a.loadFile(test::kExampleFile).isEmpty());
    EXPECT_FALSE(b.files()->watch()->isOpenElsewhere(m_path));
}

TEST_F(FileWatchTest, AFileOpenInAnotherProcessIsSeenAsOpenElsewhere) {
    // What a window holds is a shared flock on its file; another process's window holds the
    // same (here util-linux's flock stands in for it).
    MainWindow window;
    EXPECT_FALSE(window.files()->watch()->isOpenElsewhere(m_path));
    QProcess holder;
    holder.start("flock", {"--shared", "--no-fork", m_path, "sleep", "30"});
    ASSERT_TRUE(holder.waitForStarted(5000));
    EXPECT_TRUE(test::processEventsUntil(
        [&] { return window.files()->watch()->isOpenElsewhere(m_path); }, 5000));
    holder.kill();
    holder.waitForFinished(5000);
    EXPECT_FALSE(window.files()->watch()->isOpenElsewhere(m_path));
}

TEST_F(FileWatchTest, ARestoredProjectStillNoticesWhatWasSavedOverItsFileMeanwhile) {
    // The recovery note keeps the digest of the file as the killed session knew it: a file
    // changed between the crash and the restore is not overwritten without a question.
    QTemporaryDir recovery;
    QString copy;
    {
        ProjectDocument crashed;
        crashed.reset(test::loadExample(), m_path, {}, FileWatch::digestOfFile(m_path));
        crashed.undoStack()->push(new SetMotion(&crashed, {SpeedUnit::Rpm, 100}));
        Autosave autosave(&crashed, recovery.path());
        ASSERT_TRUE(autosave.writeNow().isEmpty());
        copy = autosave.recoveryPath();
        // Killed: the copy, its note and its lock stay (a clean end would remove them).
        QFile::copy(copy, copy + ".kept");
        QFile::copy(autosave.notePath(), autosave.notePath() + ".kept");
        crashed.markSaved(m_path, crashed.fileDigest());
    }
    ASSERT_TRUE(QFile::rename(copy + ".kept", copy));
    ASSERT_TRUE(QFile::rename(QString(copy).replace(".cam.json", ".json") + ".kept",
                              QString(copy).replace(".cam.json", ".json")));
    replaceOnDisk(m_path, 77);  // another program saved meanwhile
    MainWindow window;
    Autosave next(window.document(), recovery.path());
    const std::vector<Autosave::Orphan> orphans = next.orphans();
    ASSERT_EQ(orphans.size(), 1u);
    QString problem;
    ASSERT_TRUE(next.adopt(orphans.front(), &problem)) << problem.toStdString();
    EXPECT_EQ(window.document()->project().motion.value, 100);
    EXPECT_EQ(window.files()->watch()->check(), DiskState::Changed);
    {
        Answer no("overwriteChangedBox", "Cancel");
        EXPECT_FALSE(window.files()->save());
        EXPECT_TRUE(no.given());
    }
    EXPECT_EQ(rpmIn(m_path), 77);
}

}  // namespace
}  // namespace cam
