#pragma once
// Helpers for the app tests: loading projects, waiting for the engine.

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QLocale>
#include <QStringList>
#include <QThread>
#include <limits>

#include "io/project_json.h"
#include "test_support.h"

namespace cam::test {

inline const Arc& arcOf(const SegmentSpec& s) { return std::get<Arc>(s.shape); }
inline const Line& lineOf(const SegmentSpec& s) { return std::get<Line>(s.shape); }

/// The bundled six-lobe arc cam's path.
inline const QString kExampleFile = QString::fromStdString(kExample);

inline Project loadExample() {
    auto p = loadProjectFile(examplePath("six-lobe-arc-cam.cam.json"));
    EXPECT_TRUE(p.ok());
    return std::move(p).value();
}

/// Processes events until `done()` or the timeout; returns done().
template <class Predicate>
bool processEventsUntil(Predicate done, int timeoutMs = kSanitized ? 60000 : 10000) {
    QElapsedTimer timer;
    timer.start();
    while (!done() && timer.elapsed() < timeoutMs) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        QThread::msleep(1);
    }
    return done();
}

/// The number a row of the State-at-Cursor readout shows ("φ 45 °" → 45); NaN if absent.
template <class Window>
double readoutValue(const Window& window, const QString& name) {
    for (const QString& line : window.readout()->text().split('\n')) {
        const QStringList parts = line.split(' ');
        if (parts.size() >= 2 && parts[0] == name) {
            bool ok = false;
            const double value = QLocale::c().toDouble(QString(parts[1]).remove(','), &ok);
            if (ok) return value;
        }
    }
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace cam::test
