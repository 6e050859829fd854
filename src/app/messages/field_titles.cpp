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

QStringList motionLawSummaries() {
    QStringList summaries;
    for (const MotionLawKind& law : motionLaws()) {
        summaries << QCoreApplication::translate("MotionLaw", law.summary);
    }
    return summaries;
}

QString dynamicsKeyTitle(DynamicsKey key) {
    using K = DynamicsKey;
    static constexpr std::pair<DynamicsKey, const char*> kTitles[] = {
        {K::MassKg, QT_TRANSLATE_NOOP("DynamicsKey", "Moving mass [kg]")},
        {K::SpringRateNPerMm, QT_TRANSLATE_NOOP("DynamicsKey", "Spring rate [N/mm]")},
        {K::SpringPreloadN, QT_TRANSLATE_NOOP("DynamicsKey", "Spring preload [N]")},
        {K::ExternalForceN, QT_TRANSLATE_NOOP("DynamicsKey", "External force [N]")},
        {K::DampingNsPerM, QT_TRANSLATE_NOOP("DynamicsKey", "Damping [N·s/m]")},
        {K::InertiaKgM2, QT_TRANSLATE_NOOP("DynamicsKey", "Arm inertia [kg·m²]")},
        {K::SpringRateNmPerRad, QT_TRANSLATE_NOOP("DynamicsKey", "Spring rate [N·m/rad]")},
        {K::SpringPreloadNm, QT_TRANSLATE_NOOP("DynamicsKey", "Spring preload [N·m]")},
        {K::ExternalMomentNm, QT_TRANSLATE_NOOP("DynamicsKey", "External moment [N·m]")},
        {K::DampingNmsPerRad, QT_TRANSLATE_NOOP("DynamicsKey", "Damping [N·m·s/rad]")},
        {K::ContactWidthMm, QT_TRANSLATE_NOOP("DynamicsKey", "Contact width [mm]")},
        {K::CamModulusMpa, QT_TRANSLATE_NOOP("DynamicsKey", "Cam material, E [MPa]")},
        {K::CamPoisson, QT_TRANSLATE_NOOP("DynamicsKey", "Cam material, Poisson's ratio")},
        {K::FollowerModulusMpa, QT_TRANSLATE_NOOP("DynamicsKey", "Follower material, E [MPa]")},
        {K::FollowerPoisson,
         QT_TRANSLATE_NOOP("DynamicsKey", "Follower material, Poisson's ratio")},
        {K::AllowableContactStressMpa,
         QT_TRANSLATE_NOOP("DynamicsKey", "Allowable contact stress [MPa]")},
        {K::SpringSafetyFactor, QT_TRANSLATE_NOOP("DynamicsKey", "Spring safety factor")},
    };
    static_assert(std::size(kTitles) == kDynamicsKeyCount);
    for (const auto& [k, title] : kTitles) {
        if (k == key) return QCoreApplication::translate("DynamicsKey", title);
    }
    return {};
}

}  // namespace cam
