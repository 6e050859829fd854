// Save As and the file's units, driven through the real dialogs: the QFileDialog is filled and
// accepted, the question box answered, as a user would. Opening a big file: the window keeps
// answering, a progress dialog offers Cancel, and cancelling leaves the document as it was.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTimer>
#include <filesystem>
#include <fstream>

#include "app_test_support.h"
#include "io/project_json.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"
#include "test_support.h"

namespace cam {
namespace {

/// Answers the modal dialogs as they appear: the file dialog gets `fileName` typed and accepted,
/// a question box gets `answer` clicked. Returns how many question boxes were seen.
class DialogDriver : public QObject {
public:
    DialogDriver(QString fileName, QMessageBox::StandardButton answer)
        : m_fileName(std::move(fileName)), m_answer(answer) {
        connect(&m_timer, &QTimer::timeout, this, &DialogDriver::poll);
        m_timer.start(10);
    }
    int questions = 0;

private:
    void poll() {
        for (QWidget* w : QApplication::topLevelWidgets()) {
            if (w->isVisible()) answer(w);
        }
    }
    void answer(QWidget* modal) {
        if (auto* dialog = qobject_cast<QFileDialog*>(modal)) {
            // Typed into the file name field, as a user types (selectFile() leaves a focused
            // field alone).
            auto* name = dialog->findChild<QLineEdit*>("fileNameEdit");
            if (!name) return;
            name->setText(m_fileName);
            QMetaObject::invokeMethod(dialog, "accept");  // as the Save button does
        } else if (auto* box = qobject_cast<QMessageBox*>(modal)) {
            ++questions;
            box->button(m_answer)->click();
        }
    }
    QString m_fileName;
    QMessageBox::StandardButton m_answer;
    QTimer m_timer;
};

TEST(SaveAs, ANameWithoutTheSuffixAsksBeforeReplacingTheSuffixedFile) {
    QTemporaryDir dir;
    const QString existing = dir.filePath("cam.cam.json");
    {
        QFile f(existing);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("precious");
    }
    MainWindow window;
    window.show();
    auto* saveAs = window.findChild<QAction*>("actionSaveAs");
    ASSERT_NE(saveAs, nullptr);
    {
        DialogDriver no(dir.filePath("cam"), QMessageBox::No);  // typed without the suffix
        saveAs->trigger();
        EXPECT_EQ(no.questions, 1);
    }
    EXPECT_EQ(test::readFile(existing.toStdString()), "precious");
    EXPECT_TRUE(window.document()->filePath().isEmpty());
    {
        DialogDriver yes(dir.filePath("cam"), QMessageBox::Yes);
        saveAs->trigger();
        EXPECT_EQ(yes.questions, 1);
    }
    EXPECT_EQ(test::readFile(existing.toStdString()),
              serializeProject(window.document()->project()));
    EXPECT_EQ(window.document()->filePath(), QFileInfo(existing).absoluteFilePath());
    // A new name with no file behind it is not asked about.
    {
        DialogDriver fresh(dir.filePath("other"), QMessageBox::No);
        saveAs->trigger();
        EXPECT_EQ(fresh.questions, 0);
    }
    EXPECT_TRUE(QFile::exists(dir.filePath("other.cam.json")));
}

TEST(SaveKeepsUnits, AMetreAndRadianFileStaysSoAndOnlyTheEditedValueChanges) {
    const std::string text = test::readFile(test::dataPath("io/metres-radians.cam.json"));
    // The file as Camwright writes it: loading and saving it untouched must give these bytes.
    const std::string canonical = serializeProject(parseProject(text).value());
    QTemporaryDir dir;
    const QString path = dir.filePath("metric.cam.json");
    {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(canonical.data(), static_cast<qint64>(canonical.size()));
    }
    MainWindow window;
    ASSERT_TRUE(window.loadFile(path).isEmpty());
    ASSERT_TRUE(window.saveFile(path).isEmpty());
    EXPECT_EQ(test::readFile(path.toStdString()), canonical);  // untouched: byte for byte

    // The table shows and takes millimetres; the file keeps metres.
    SegmentTableModel* model = window.tableModel();
    EXPECT_EQ(model->index(0, SegmentTableModel::Radius).data(Qt::EditRole).toDouble(), 20.0);
    ASSERT_TRUE(model->setData(model->index(0, SegmentTableModel::Radius), 21.0, Qt::EditRole));
    ASSERT_TRUE(window.saveFile(path).isEmpty());
    std::string expected = canonical;
    const auto at = expected.find("\"radius\": 0.02");
    ASSERT_NE(at, std::string::npos);
    expected.replace(at, 14, "\"radius\": 0.021");
    EXPECT_EQ(test::readFile(path.toStdString()), expected);
}

/// A circle about (5, 0) of radius 20 split into n arcs: n = 100,000 is an 11 MB file.
std::string writeSplitCircle(const std::string& path, int n) {
    std::string text = R"({"format": "camwright", "version": 1, "motion": {"period_s": 1},
 "contour": [)";
    char line[200];
    for (int k = 0; k < n; ++k) {
        std::snprintf(line, sizeof line,
                      R"(%s{"type": "arc", "center": [5, 0], "radius": 20, "branch": "outer", )"
                      R"("phi_start": %.17g, "phi_end": %.17g})",
                      k == 0 ? "\n" : ",\n", 360.0 * k / n,
                      k + 1 == n ? 360.0 : 360.0 * (k + 1) / n);
        text += line;
    }
    text += "]}\n";
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

/// Watches the GUI thread while a file opens: counts the ticks of a 5 ms timer (they only fire
/// while the GUI thread answers) and notes when the progress dialog is up.
struct LoadWatcher {
    QTimer timer;
    int ticks = 0;
    int ticksWithDialog = 0;
    bool cancelWhenShown = false;
    LoadWatcher() {
        QObject::connect(&timer, &QTimer::timeout, [this] {
            ++ticks;
            for (QWidget* w : QApplication::topLevelWidgets()) {
                auto* progress = qobject_cast<QProgressDialog*>(w);
                if (!progress || !progress->isVisible()) continue;
                ++ticksWithDialog;
                // Clicked as a user clicks it.
                auto* cancel = progress->findChild<QPushButton*>();
                if (cancelWhenShown && cancel) cancel->click();
            }
        });
        timer.start(5);
    }
};

TEST(OpenBigFile, TheWindowKeepsAnsweringAndShowsProgress) {
    // At 612d090 the GUI thread parsed and validated the file itself: the window froze for as
    // long as that took (24 s for 400,000 empty objects).
    const test::TempDir dir;
    const std::string path = writeSplitCircle(dir.file("big.cam.json"), 100'000);
    MainWindow window;
    window.show();
    LoadWatcher watcher;
    const QString problem = window.loadFile(QString::fromStdString(path));
    EXPECT_TRUE(problem.isEmpty()) << problem.toStdString();
    EXPECT_GT(watcher.ticks, 10);  // the event loop ran while the file was read
    EXPECT_GT(watcher.ticksWithDialog, 0);
    EXPECT_EQ(window.document()->project().contour.size(), 100'000u);
    EXPECT_TRUE(window.document()->diagnostics().empty());
    EXPECT_FALSE(window.document()->isModified());
    // Its kinematics take many seconds (100,000 segments' extremes): meanwhile the status bar
    // says so, instead of describing the result of the project that was open before.
    // (Waited for rather than looked at after a fixed time: under the sanitizers one pass of the
    // event loop over the 100,000-row table can outlast the 400 ms after which it says so.)
    const auto* label = window.findChild<QLabel*>("computeLabel");
    ASSERT_NE(label, nullptr);
    EXPECT_TRUE(test::processEventsUntil([&] { return label->text() == "computing…"; }))
        << label->text().toStdString();
}

TEST(OpenBigFile, CancelKeepsTheOpenProject) {
    const test::TempDir dir;
    const std::string path = writeSplitCircle(dir.file("big.cam.json"), 100'000);
    MainWindow window;
    window.show();
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::examplePath("six-lobe-arc-cam.cam.json")))
            .isEmpty());
    const Project before = window.document()->project();
    LoadWatcher watcher;
    watcher.cancelWhenShown = true;
    const QString problem = window.loadFile(QString::fromStdString(path));
    EXPECT_TRUE(problem.contains("cancelled")) << problem.toStdString();
    EXPECT_TRUE(window.document()->project() == before);
    EXPECT_TRUE(window.document()->filePath().endsWith("six-lobe-arc-cam.cam.json"));
}

TEST(OpenBigFile, AFileOverTheSizeLimitIsRefusedWithItsSize) {
    // A sparse file of 64 MiB + 1 byte: refused before it is read, the open project kept.
    const test::TempDir dir;
    const std::string path = dir.file("huge.cam.json");
    std::ofstream(path, std::ios::binary).put('{');
    std::filesystem::resize_file(path, (64u << 20) + 1);
    MainWindow window;
    ASSERT_TRUE(
        window.loadFile(QString::fromStdString(test::examplePath("six-lobe-arc-cam.cam.json")))
            .isEmpty());
    const QString problem = window.loadFile(QString::fromStdString(path));
    EXPECT_TRUE(problem.contains("67108865 bytes")) << problem.toStdString();
    EXPECT_TRUE(problem.contains("64 MiB")) << problem.toStdString();
    EXPECT_TRUE(window.document()->filePath().endsWith("six-lobe-arc-cam.cam.json"));
}

}  // namespace
}  // namespace cam
