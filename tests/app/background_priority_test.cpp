// The engine's threads yield the processor to the window's thread.

#include <gtest/gtest.h>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QThread>
#include <optional>

#include "app_test_support.h"
#include "engine/background_priority.h"
#include "engine/compute_engine.h"

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace cam {
namespace {

#if defined(__linux__)

int niceOfThisThread() { return getpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid))); }

/// The nice value of this process's thread named `name` (its first 15 characters), from
/// /proc/self/task/*/stat: field 19, counted after the name in parentheses.
std::optional<int> niceOfThreadNamed(const QString& name) {
    const QDir tasks(QStringLiteral("/proc/self/task"));
    for (const QString& tid : tasks.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        QFile comm(tasks.filePath(tid + "/comm"));
        if (!comm.open(QIODevice::ReadOnly)) continue;
        if (QString::fromUtf8(comm.readAll()).trimmed() != name.left(15)) continue;
        QFile stat(tasks.filePath(tid + "/stat"));
        if (!stat.open(QIODevice::ReadOnly)) continue;
        const QByteArray text = stat.readAll();
        const QList<QByteArray> fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
        return fields.size() > 16 ? std::optional<int>(fields[16].toInt()) : std::nullopt;
    }
    return std::nullopt;
}

TEST(BackgroundPriority, AComputeThreadIsNicedAndTheCallerIsNot) {
    const int before = niceOfThisThread();
    int inThread = -100;
    QThread* thread = QThread::create([&] {
        runInTheBackground();
        runInTheBackground();  // again: no further change
        inThread = niceOfThisThread();
    });
    thread->start();
    ASSERT_TRUE(thread->wait(5000));
    delete thread;
    EXPECT_EQ(inThread, std::max(before, 10));
    EXPECT_EQ(niceOfThisThread(), before);  // the window's thread keeps its priority
}

TEST(BackgroundPriority, TheEnginesWorkerRunsInTheBackground) {
    ComputeEngine engine;
    engine.request(test::loadExample(), PlotAxis::Angle);
    QElapsedTimer clock;
    clock.start();
    while (!engine.latestResult() && clock.elapsed() < 10000) QCoreApplication::processEvents();
    ASSERT_TRUE(engine.latestResult());
    const std::optional<int> nice = niceOfThreadNamed(QStringLiteral("cam::ComputeWorker"));
    ASSERT_TRUE(nice.has_value()) << "no thread named after the worker";
    EXPECT_GE(*nice, 10);
}

#endif

}  // namespace
}  // namespace cam
