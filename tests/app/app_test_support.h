#pragma once
// Helpers for the app tests: loading projects, waiting for the engine.

#include <QAbstractSpinBox>
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QLocale>
#include <QStringList>
#include <QTest>
#include <QThread>
#include <cmath>
#include <limits>

#include "io/project_json.h"
#include "test_support.h"
#include "widgets/quantity_format.h"

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

/// Types `text` into a spin box as a user does: focus, select all, type, Enter.
inline void typeInto(QAbstractSpinBox* box, const QString& text) {
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
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

/// The number a row of the State-at-Cursor readout shows ("φ 45°" → 45, "r 26.21882 mm" →
/// 26.21882); NaN if absent.
template <class Window>
double readoutValue(const Window& window, const QString& name) {
    for (const QString& line : window.readout()->text().split('\n')) {
        const QStringList parts = line.split(' ');
        if (parts.size() >= 2 && parts[0] == name) {
            bool ok = false;
            const QString number = QString(parts[1]).remove(',').remove(QChar(u'°'));
            const double value = QLocale::c().toDouble(number, &ok);
            if (ok) return value;
        }
    }
    return std::numeric_limits<double>::quiet_NaN();
}

/// How close a readout's number of `quantity` is to the value it shows, relative: its
/// significant digits round to half a unit of the last, 0.5·10^(1 − digits) at worst.
inline double readoutTolerance(DisplayQuantity quantity) {
    return std::pow(10.0, 1 - quantityFormat(quantity).significant);
}

}  // namespace cam::test
