// Save As and the file's units, driven through the real dialogs: the QFileDialog is filled and
// accepted, the question box answered, as a user would.

#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTimer>

#include "app_test_support.h"
#include "io/project_json.h"
#include "mainwindow.h"
#include "models/segment_table_model.h"

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

}  // namespace
}  // namespace cam
