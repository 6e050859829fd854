#include "messages/field_titles.h"

#include <QCoreApplication>

#include "design/motion_law.h"

namespace cam {

QString segmentColumnTitle(int column) {
    static constexpr const char* kTitles[SegmentColumns::ColumnCount] = {
        QT_TRANSLATE_NOOP("SegmentColumn", "Type"),
        QT_TRANSLATE_NOOP("SegmentColumn", "Centre x [mm]"),
        QT_TRANSLATE_NOOP("SegmentColumn", "Centre y [mm]"),
        QT_TRANSLATE_NOOP("SegmentColumn", "Radius [mm]"),
        QT_TRANSLATE_NOOP("SegmentColumn", "Branch"),
        QT_TRANSLATE_NOOP("SegmentColumn", "From x [mm]"),
        QT_TRANSLATE_NOOP("SegmentColumn", "From y [mm]"),
        QT_TRANSLATE_NOOP("SegmentColumn", "To x [mm]"),
        QT_TRANSLATE_NOOP("SegmentColumn", "To y [mm]"),
        QT_TRANSLATE_NOOP("SegmentColumn", "φ start [°]"),
        QT_TRANSLATE_NOOP("SegmentColumn", "φ end [°]"),
    };
    if (column < 0 || column >= SegmentColumns::ColumnCount) return {};
    return QCoreApplication::translate("SegmentColumn", kTitles[column]);
}

QStringList motionLawTitles() {
    QStringList titles;
    for (const MotionLawKind& law : motionLaws()) {
        titles << QCoreApplication::translate("MotionLaw", law.title);
    }
    return titles;
}

}  // namespace cam
