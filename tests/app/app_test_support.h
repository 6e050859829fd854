#pragma once
// Helpers for the app tests: loading projects, waiting for the engine.

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QThread>

#include "io/project_json.h"
#include "test_support.h"

namespace cam::test {

inline const Arc& arcOf(const SegmentSpec& s) { return std::get<Arc>(s.shape); }
inline const Line& lineOf(const SegmentSpec& s) { return std::get<Line>(s.shape); }

inline Project loadExample() {
    auto p = loadProjectFile(examplePath("six-lobe-arc-cam.cam.json"));
    EXPECT_TRUE(p.ok());
    return std::move(p).value();
}

/// Processes events until `done()` or the timeout; returns done().
template <class Predicate>
bool processEventsUntil(Predicate done, int timeoutMs = 10000) {
    QElapsedTimer timer;
    timer.start();
    while (!done() && timer.elapsed() < timeoutMs) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        QThread::msleep(1);
    }
    return done();
}

}  // namespace cam::test
