#include "engine/background_priority.h"

#include <QThread>

#if defined(Q_OS_LINUX)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace cam {

namespace {
constexpr int kBackgroundNice = 10;
}  // namespace

void runInTheBackground() {
#if defined(Q_OS_LINUX)
    // On Linux a thread id names one thread: its own nice value, not the process's.
    const auto tid = static_cast<id_t>(syscall(SYS_gettid));
    const int current = getpriority(PRIO_PROCESS, tid);
    if (current < kBackgroundNice) setpriority(PRIO_PROCESS, tid, kBackgroundNice);
#else
    QThread::currentThread()->setPriority(QThread::LowPriority);
#endif
}

}  // namespace cam
