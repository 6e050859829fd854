#include "messages/diagnostic_text.h"

#include <QLocale>
#include <QRegularExpression>
#include <cmath>
#include <utility>

#include "design/motion_law.h"
#include "fillet/fillet.h"
#include "messages/field_titles.h"
#include "widgets/quantity_format.h"

namespace cam {
// A named namespace, not an anonymous one: the app is a unity build, and helpers named
// columnName or term would meet their namesakes in the same translation unit.
namespace diagnostic_wording {

using Code = DiagnosticCode;

/// A number in a message: at most kMessageDigits significant digits (as the core's English),
/// the user's decimal separator, no group separators, never "-0". A message does not say what
/// quantity its number is, and often quotes what was typed: it keeps the digits a cell shows
/// a typed value with, and does not round a typed 1e-12 to 0 as the table's display does.
static_assert(quantityFormat(DisplayQuantity::Input).significant == kMessageDigits);
QString messageNumber(double value) {
    if (value == 0.0) return QStringLiteral("0");
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    return locale.toString(value, 'g', kMessageDigits);
}

/// A count or a typed whole number (a tool number, a file's bytes) with every digit: unlike
/// the table's Count, never rounded to ten digits, since it may quote what was typed.
QString wholeNumber(double value) {
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    return locale.toString(static_cast<qlonglong>(std::llround(value)));
}

/// The header text without its unit: "Radius [mm]" → "Radius", for a column named inside a
/// sentence whose numbers carry their units.
QString columnName(int column) {
    static const QRegularExpression unit(QStringLiteral(R"(\s*\[[^\]]*\]$)"));
    return segmentColumnTitle(column).remove(unit);
}

/// The arguments' signature letters and types agree with the code's.
bool argumentsFit(const Diagnostic& d) {
    if (static_cast<std::size_t>(d.code) >= kDiagnosticCodeCount) return false;
    if (d.code == Code::Unspecified) return false;
    const std::string_view signature = diagnosticCodeSignature(d.code);
    if (signature.size() != d.args.size()) return false;
    for (std::size_t i = 0; i < signature.size(); ++i) {
        const bool isName = std::holds_alternative<std::string>(d.args[i]);
        if (isName != (signature[i] == 's')) return false;
    }
    for (const Diagnostic& reason : d.reasons) {
        if (!argumentsFit(reason)) return false;
    }
    return true;
}

/// The messages whose place is a line of a text (file) and part of their arguments.
bool placedByArguments(Code code) {
    switch (code) {
        case Code::JsonNumberTooLarge:
        case Code::JsonSyntax:
        case Code::JsonNulByte:
        case Code::RowValueCount:
        case Code::RowValueNotFinite:
            return true;
        default:
            return false;
    }
}

/// A name the core passes as an argument, in the window's words where it is one of the core's
/// terms; anything else (a unit, text from a file) as it is.
QString term(const std::string& name) {
    if (name == "a number") return DiagnosticText::tr("a number");
    if (name == "a string") return DiagnosticText::tr("a string");
    if (name == "a boolean") return DiagnosticText::tr("a boolean");
    if (name == "an array") return DiagnosticText::tr("an array");
    if (name == "an object") return DiagnosticText::tr("an object");
    if (name == "true or false") return DiagnosticText::tr("true or false");
    if (name == "an array [x, y] of two numbers")
        return DiagnosticText::tr("an array [x, y] of two numbers");
    if (name == "an array of numbers") return DiagnosticText::tr("an array of numbers");
    if (name == "an array of segments") return DiagnosticText::tr("an array of segments");
    if (name == "a whole number") return DiagnosticText::tr("a whole number");
    if (name == "fillet") return DiagnosticText::tr("a fillet");
    if (name == "tangent line") return DiagnosticText::tr("a tangent line");
    if (name == "the roller") return DiagnosticText::tr("the roller");
    if (name == "the tip") return DiagnosticText::tr("the tip");
    if (name == "an arc") return DiagnosticText::tr("an arc");
    if (name == "a line") return DiagnosticText::tr("a line");
    if (name == "a Bézier spline") return DiagnosticText::tr("a Bézier spline");
    if (name == "a Hermite spline") return DiagnosticText::tr("a Hermite spline");
    if (name == "a folder") return DiagnosticText::tr("a folder");
    if (name == "a FIFO") return DiagnosticText::tr("a FIFO");
    if (name == "a character device") return DiagnosticText::tr("a character device");
    if (name == "a block device") return DiagnosticText::tr("a block device");
    if (name == "a socket") return DiagnosticText::tr("a socket");
    if (name == "a special file") return DiagnosticText::tr("a special file");
    if (name == "the depth") return DiagnosticText::tr("the depth");
    if (name == "the safe height") return DiagnosticText::tr("the safe height");
    if (name == "the step-down") return DiagnosticText::tr("the step-down");
    if (const auto law = lawFromName(name)) {
        const QStringList names = motionLawTitles();
        const auto index = static_cast<qsizetype>(*law);
        if (index < names.size()) return names[index];
    }
    return QString::fromStdString(name);
}

/// Why a fillet radius fails (a name of fillet_reason); the neighbour it leaves is one of the
/// joint's two segments, the diagnostic's places.
QString filletReason(const Diagnostic& d, std::size_t i) {
    const std::string& name = std::get<std::string>(d.args[i]);
    const bool joint = d.places.size() == 2;
    if (name == fillet_reason::kLeavesLeft && joint) {
        return DiagnosticText::tr("the tangent point would leave segment %1")
            .arg(d.places[0].segment);
    }
    if (name == fillet_reason::kLeavesRight && joint) {
        return DiagnosticText::tr("the tangent point would leave segment %1")
            .arg(d.places[1].segment);
    }
    if (name == fillet_reason::kNoCircle)
        return DiagnosticText::tr(
            "no circle of that radius touches both neighbours inside the corner");
    if (name == fillet_reason::kNoLargerCircle)
        return DiagnosticText::tr("no larger circle touches both neighbours inside the corner");
    if (name == fillet_reason::kRayNotOnce) {
        return DiagnosticText::tr(
            "the follower ray would not meet the fillet arc exactly once: it would pass the "
            "rotation centre or turn back as seen from it");
    }
    if (name == fillet_reason::kRadiusLimit)
        return DiagnosticText::tr("radii are limited to 10⁶ mm");
    return QString::fromStdString(name);
}

QString argument(const Diagnostic& d, std::size_t i);

/// "the outer tangent from (1, 2) on segment 3 to (4, 5) on segment 6": the seven arguments
/// from `first` on (the kind, a point, a segment, a point, a segment).
QString tangentName(const Diagnostic& d, std::size_t first) {
    auto a = [&](std::size_t i) { return argument(d, first + i); };
    const std::string& kind = std::get<std::string>(d.args[first]);
    if (kind == "outer") {
        return DiagnosticText::tr(
                   "the outer tangent from (%1, %2) on segment %3 to (%4, %5) on "
                   "segment %6")
            .arg(a(1), a(2), a(3), a(4), a(5), a(6));
    }
    if (kind == "inner") {
        return DiagnosticText::tr(
                   "the inner tangent from (%1, %2) on segment %3 to (%4, %5) on "
                   "segment %6")
            .arg(a(1), a(2), a(3), a(4), a(5), a(6));
    }
    return DiagnosticText::tr(
               "the tangent “%1” from (%2, %3) on segment %4 to (%5, %6) on "
               "segment %7")
        .arg(a(0), a(1), a(2), a(3), a(4), a(5), a(6));
}

QString translatedMessage(const Diagnostic& d);

QString argument(const Diagnostic& d, std::size_t i) {
    const char kind = diagnosticCodeSignature(d.code)[i];
    if (kind == 's') return term(std::get<std::string>(d.args[i]));
    const double value = std::get<double>(d.args[i]);
    return kind == 'n' ? messageNumber(value) : wholeNumber(value);
}

QString pointPart(const SegmentPlace& p) {
    QString name;
    switch (p.part) {
        case SegmentPart::Points:
            name = p.point >= 0 ? DiagnosticText::tr("control point P%1").arg(p.point)
                                : DiagnosticText::tr("control points");
            break;
        case SegmentPart::P0:
            name = DiagnosticText::tr("start point");
            break;
        case SegmentPart::T0:
            name = DiagnosticText::tr("start tangent");
            break;
        case SegmentPart::P3:
            name = DiagnosticText::tr("end point");
            break;
        default:
            name = DiagnosticText::tr("end tangent");
            break;
    }
    if (p.axis == 0) return DiagnosticText::tr("%1, x").arg(name);
    if (p.axis == 1) return DiagnosticText::tr("%1, y").arg(name);
    return name;
}

/// The table column(s) or the control point a segment place names.
QString partName(const SegmentPlace& p) {
    auto pair = [&](int x, int y) {
        if (p.axis == 0) return segmentColumnTitle(x);
        if (p.axis == 1) return segmentColumnTitle(y);
        return segmentColumnTitle(x) + QStringLiteral(" / ") + segmentColumnTitle(y);
    };
    switch (p.part) {
        case SegmentPart::Whole:
            return {};
        case SegmentPart::Type:
            return segmentColumnTitle(SegmentColumns::Type);
        case SegmentPart::Center:
            return pair(SegmentColumns::CenterX, SegmentColumns::CenterY);
        case SegmentPart::Radius:
            return segmentColumnTitle(SegmentColumns::Radius);
        case SegmentPart::Branch:
            return segmentColumnTitle(SegmentColumns::Branch);
        case SegmentPart::From:
            return pair(SegmentColumns::FromX, SegmentColumns::FromY);
        case SegmentPart::To:
            return pair(SegmentColumns::ToX, SegmentColumns::ToY);
        case SegmentPart::PhiStart:
            return segmentColumnTitle(SegmentColumns::PhiStart);
        case SegmentPart::PhiEnd:
            return segmentColumnTitle(SegmentColumns::PhiEnd);
        case SegmentPart::Points:
        case SegmentPart::P0:
        case SegmentPart::T0:
        case SegmentPart::P3:
        case SegmentPart::T1:
            return pointPart(p);
    }
    return {};
}

/// "X", "Y", "Z" for an axis index of the machining lists.
QString axisName(int i) { return i >= 0 && i < 3 ? QString(QChar('X' + i)) : QString::number(i); }

/// A project field by its key, as the panels name it; the key itself where it is none of them.
QString fieldName(const std::string& location) {
    const QString key = QString::fromStdString(location);
    static const QRegularExpression indexed(QStringLiteral(R"(^([a-z_.]+)\[(\d+)\]$)"));
    static const QRegularExpression designSegment(
        QStringLiteral(R"(^design\.segments\[(\d+)\](?:\.(\w+))?$)"));
    if (const auto m = designSegment.match(key); m.hasMatch()) {
        const QString row = m.captured(1);
        const QString field = m.captured(2);
        QString name;
        if (field == QLatin1String("law")) name = DiagnosticText::tr("law");
        if (field == QLatin1String("to_deg")) name = DiagnosticText::tr("end angle");
        if (field == QLatin1String("lift")) name = DiagnosticText::tr("lift");
        if (field == QLatin1String("v0") || field == QLatin1String("a0") ||
            field == QLatin1String("v1") || field == QLatin1String("a1")) {
            name = field;
        }
        if (field.isEmpty()) return DiagnosticText::tr("Motion design, segment %1").arg(row);
        if (name.isEmpty()) return key;
        return DiagnosticText::tr("Motion design, segment %1, %2").arg(row, name);
    }
    static const QRegularExpression designJoint(
        QStringLiteral(R"(^design\.segments\[(\d+)\]/design\.segments\[(\d+)\]$)"));
    if (const auto m = designJoint.match(key); m.hasMatch()) {
        return DiagnosticText::tr("Motion design, joint between segments %1 and %2")
            .arg(m.captured(1), m.captured(2));
    }
    if (const auto m = indexed.match(key); m.hasMatch()) {
        const int i = m.captured(2).toInt();
        const QString base = m.captured(1);
        if (base == QLatin1String("machining.axis_accel"))
            return DiagnosticText::tr("Machining, acceleration of axis %1").arg(axisName(i));
        if (base == QLatin1String("machining.axis_vmax"))
            return DiagnosticText::tr("Machining, speed limit of axis %1").arg(axisName(i));
        if (base == QLatin1String("follower.pivot"))
            return i == 0 ? DiagnosticText::tr("Follower, pivot x")
                          : DiagnosticText::tr("Follower, pivot y");
        if (base == QLatin1String("contour")) return DiagnosticText::tr("Segment %1").arg(i);
        // The teach-in's points, numbered from 0 as the segments are.
        if (base == QLatin1String("point")) return DiagnosticText::tr("Point %1").arg(i);
        return key;
    }
    // The project's fields by their keys (lupdate reads the names here; tr() at lookup).
    static constexpr std::pair<const char*, const char*> kFields[] = {
        {"contour", QT_TRANSLATE_NOOP("DiagnosticText", "Contour")},
        {"points", QT_TRANSLATE_NOOP("DiagnosticText", "Points")},
        {"bulge", QT_TRANSLATE_NOOP("DiagnosticText", "Bulge factor")},
        {"error", QT_TRANSLATE_NOOP("DiagnosticText", "Admissible radial error")},
        {"motion.omega_rad_s", QT_TRANSLATE_NOOP("DiagnosticText", "Motion, ω [rad/s]")},
        {"motion.rpm", QT_TRANSLATE_NOOP("DiagnosticText", "Motion, speed [rpm]")},
        {"motion.period_s", QT_TRANSLATE_NOOP("DiagnosticText", "Motion, period [s]")},
        {"follower.offset", QT_TRANSLATE_NOOP("DiagnosticText", "Follower, offset")},
        {"follower.radius", QT_TRANSLATE_NOOP("DiagnosticText", "Follower, roller radius")},
        {"follower.max_pressure_angle_deg",
         QT_TRANSLATE_NOOP("DiagnosticText", "Follower, largest pressure angle")},
        {"follower.type", QT_TRANSLATE_NOOP("DiagnosticText", "Follower, type")},
        {"follower.pivot", QT_TRANSLATE_NOOP("DiagnosticText", "Follower, pivot")},
        {"follower.arm_length", QT_TRANSLATE_NOOP("DiagnosticText", "Follower, arm length")},
        {"sampling.samples_per_turn", QT_TRANSLATE_NOOP("DiagnosticText", "Samples per turn")},
        {"machining.axis_accel",
         QT_TRANSLATE_NOOP("DiagnosticText", "Machining, axis accelerations")},
        {"machining.axis_vmax",
         QT_TRANSLATE_NOOP("DiagnosticText", "Machining, axis speed limits")},
        {"machining.feed_max", QT_TRANSLATE_NOOP("DiagnosticText", "Machining, feed ceiling")},
        {"machining.tool_radius", QT_TRANSLATE_NOOP("DiagnosticText", "Machining, tool radius")},
        {"machining.step", QT_TRANSLATE_NOOP("DiagnosticText", "Machining, step")},
        {"design", QT_TRANSLATE_NOOP("DiagnosticText", "Motion design")},
        {"design.base_radius", QT_TRANSLATE_NOOP("DiagnosticText", "Motion design, base radius")},
        {"design.tolerance", QT_TRANSLATE_NOOP("DiagnosticText", "Motion design, tolerance")},
        {"design.segments", QT_TRANSLATE_NOOP("DiagnosticText", "Motion design, segments")},
    };
    for (const auto& [field, name] : kFields) {
        if (key == QLatin1String(field)) return DiagnosticText::tr(name);
    }
    return key;
}

/// Codes the project reader makes: their place is where the file has the problem, named by
/// the file's own keys (the user finds it in the file with them), so it stays as it is.
bool placedInFile(Code code) {
    switch (code) {
        case Code::Missing:
        case Code::UnknownKey:
        case Code::WrongType:
        case Code::PointShape:
        case Code::NotOneOf:
        case Code::UnknownSegmentType:
        case Code::UnknownLaw:
        case Code::SpeedNotExactlyOne:
        case Code::NotWholeSampleCount:
        case Code::NewerFormatVersion:
        case Code::NotFormatVersion1:
        case Code::BezierPointCount:
        case Code::JsonDuplicatedKey:
        case Code::JsonTooDeep:
        case Code::JsonInvalid:
            return true;
        default:
            return false;
    }
}

QString translatedMessage(const Diagnostic& d) {
    auto a = [&](std::size_t i) { return argument(d, i); };
    const QString tangent =
        diagnosticCodeSignature(d.code).starts_with("snnknnk") ? tangentName(d, 0) : QString();
    const QString phiStart = columnName(SegmentColumns::PhiStart);
    const QString phiEnd = columnName(SegmentColumns::PhiEnd);
    switch (d.code) {
        case Code::Unspecified:
            return {};
        case Code::NotFinite:
            return DiagnosticText::tr("must be a finite number (got %1)").arg(a(0));
        case Code::LengthTooLarge:
            return DiagnosticText::tr("magnitude must be at most 10⁶ mm (got %1)").arg(a(0));
        case Code::OutOfRange:
            return DiagnosticText::tr("must be between %1 and %2%3 (got %4)")
                .arg(a(0), a(1), a(2), a(3));
        case Code::BelowMinimumLength:
            return DiagnosticText::tr(
                       "must be at least %1 mm (got %2): a smaller circle or step is below the "
                       "precision of the joints")
                .arg(a(0), a(1));
        case Code::NotPositive:
            return DiagnosticText::tr("must be > 0 (got %1)").arg(a(0));
        case Code::SpeedIsZero:
            return DiagnosticText::tr("must not be 0 (its sign gives the turning direction)");
        case Code::SpeedOutOfRange:
            return DiagnosticText::tr("magnitude must be between %1 and %2%3 (got %4)")
                .arg(a(0), a(1), a(2), a(3));
        case Code::NoSegments:
            return DiagnosticText::tr("must have at least one segment");
        case Code::AngleNotFinite:
            return DiagnosticText::tr("must be a finite angle of magnitude at most 10⁶° (got %1)")
                .arg(a(0));
        case Code::WindowNotIncreasing:
            return DiagnosticText::tr("must be greater than %1 %2° (got %3°)")
                .arg(phiStart, a(0), a(1));
        case Code::RayGrazes:
            return DiagnosticText::tr(
                       "at %1° the follower ray only grazes the curve (it must cross it at an "
                       "angle of at least %2 rad, or the follower would need an unbounded "
                       "speed); the window must end before it")
                .arg(a(0), a(1));
        case Code::WindowDisagreesWithLineEnds:
            return DiagnosticText::tr(
                       "window %1° .. %2° disagrees with the polar angles of the line's end "
                       "points (%3° .. %4°)")
                .arg(a(0), a(1), a(2), a(3));
        case Code::WindowDisagreesWithSplineEnds:
            return DiagnosticText::tr(
                       "window %1° .. %2° disagrees with the polar angles of the curve's end "
                       "points (%3° .. %4°)")
                .arg(a(0), a(1), a(2), a(3));
        case Code::LineHasNoLength:
            return DiagnosticText::tr(
                "the end point must differ from the start point (the line has no length)");
        case Code::LineThroughCentre:
            return DiagnosticText::tr(
                "the line passes through the rotation centre, so the follower ray meets it at "
                "no angle or at every point");
        case Code::LineClockwise:
            return DiagnosticText::tr(
                       "the line runs clockwise around the rotation centre (from %1° to %2°); "
                       "swap its start and end points")
                .arg(a(0), a(1));
        case Code::SplineEndOnCentre:
            return DiagnosticText::tr("an end point lies on the rotation centre");
        case Code::SplineClockwise:
            return DiagnosticText::tr(
                       "the curve runs clockwise around the rotation centre (from %1° to %2°); "
                       "reverse its points")
                .arg(a(0), a(1));
        case Code::RayMeetsSplineTimes:
            return DiagnosticText::tr(
                       "the follower ray meets the curve %1 times at %2°; inside its window it "
                       "must meet it exactly once")
                .arg(a(0), a(1));
        case Code::InnerBranchBehindCentre:
            return DiagnosticText::tr(
                "the rotation centre lies inside this circle, so the inner intersection is "
                "behind the follower (r ≤ 0); choose the outer branch");
        case Code::RayMissesArc:
            return DiagnosticText::tr(
                       "the follower ray misses the circle inside the window %1° .. %2°; it "
                       "meets it only for φ in %3° .. %4°")
                .arg(a(0), a(1), a(2), a(3));
        case Code::WindowGap:
            return DiagnosticText::tr("gap of %1° between %2 %3° and %4 %5°")
                .arg(a(0), phiEnd, a(1), phiStart, a(2));
        case Code::WindowOverlap:
            return DiagnosticText::tr("overlap of %1° between %2 %3° and %4 %5°")
                .arg(a(0), phiEnd, a(1), phiStart, a(2));
        case Code::WindowsNotOneTurn:
            return DiagnosticText::tr(
                       "the windows cover %1° (from %2° to %3°); they must cover exactly one "
                       "turn, 360°")
                .arg(a(0), a(1), a(2));
        case Code::JointGap:
            return DiagnosticText::tr(
                       "the segments do not meet at %1°: gap of %2 mm (at most 10⁻⁶ mm allowed)")
                .arg(a(0), a(1));
        case Code::FlatFaceOscillating:
            return DiagnosticText::tr(
                "a flat face moves only translating; use a knife edge or a roller on a "
                "swinging arm");
        case Code::RollerTooLargeForArc:
            return DiagnosticText::tr(
                       "must be smaller than the radius %1 mm of the concave arc in segment %2 "
                       "(got %3 mm): the roller cannot enter it")
                .arg(a(0), a(1), a(2));
        case Code::SamplesOutOfRange:
            return DiagnosticText::tr("must be between 16 and 10000000 (got %1)").arg(a(0));
        case Code::AxisCount:
            return DiagnosticText::tr("must list 2 or 3 axes (got %1)").arg(a(0));
        case Code::JointNeedsTwoSegments:
            return DiagnosticText::tr("%1 needs a joint between two segments (the contour has %2)")
                .arg(a(0), a(1));
        case Code::NoSuchJoint:
            return DiagnosticText::tr("there is no joint %1: joints are numbered 0 .. %2")
                .arg(a(0), a(1));
        case Code::DesignEndNotAfterStart:
            return DiagnosticText::tr("must be after %1°, where this segment starts (got %2°)")
                .arg(a(0), a(1));
        case Code::DesignEndBeyondTurn:
            return DiagnosticText::tr("must be at most 360° (got %1°)").arg(a(0));
        case Code::DwellLiftChanges:
            return DiagnosticText::tr("a dwell keeps the lift it starts with (%1), got %2")
                .arg(a(0), a(1));
        case Code::LiftUnchanged:
            return DiagnosticText::tr(
                       "must differ from the lift it starts with (%1) for %2; a stretch without "
                       "motion is a dwell")
                .arg(a(0), a(1));
        case Code::DesignLastNot360:
            return DiagnosticText::tr("the last segment must end at 360° (got %1°)").arg(a(0));
        case Code::DesignNotReturning:
            return DiagnosticText::tr(
                       "the motion must return to the start: the last lift must be 0 (got %1)")
                .arg(a(0));
        case Code::DesignVelocityJump:
            return DiagnosticText::tr("the velocity jumps from %1 to %2 per degree")
                .arg(a(0), a(1));
        case Code::DesignAccelerationJump:
            return DiagnosticText::tr("the acceleration jumps from %1 to %2 per degree²")
                .arg(a(0), a(1));
        case Code::DesignVelocityAndAccelerationJump:
            return DiagnosticText::tr(
                       "the velocity jumps from %1 to %2 per degree; the acceleration jumps "
                       "from %3 to %4 per degree²")
                .arg(a(0), a(1), a(2), a(3));
        case Code::Missing:
            return DiagnosticText::tr("missing");
        case Code::UnknownKey:
            return DiagnosticText::tr("unknown key");
        case Code::WrongType:
            return DiagnosticText::tr("must be %1 (got %2)").arg(a(0), a(1));
        case Code::PointShape:
            return DiagnosticText::tr("must be an array [x, y] of two numbers (got %1 elements)")
                .arg(a(0));
        case Code::NotOneOf:
            return DiagnosticText::tr("must be one of %1 (got “%2”)").arg(a(0), a(1));
        case Code::UnknownSegmentType:
            return DiagnosticText::tr(
                       "unknown segment type “%1” (expected “arc”, “line”, “bezier” or "
                       "“hermite”)")
                .arg(a(0));
        case Code::UnknownLaw:
            return DiagnosticText::tr("unknown law “%1” (expected one of %2)").arg(a(0), a(1));
        case Code::SpeedNotExactlyOne:
            return DiagnosticText::tr(
                       "must give exactly one of omega_rad_s, rpm, period_s (got %1)")
                .arg(a(0));
        case Code::NotWholeSampleCount:
            return DiagnosticText::tr("must be a whole number between 16 and 10000000 (got %1)")
                .arg(a(0));
        case Code::NewerFormatVersion:
            return DiagnosticText::tr(
                       "this file has format version %1; this Camwright reads version 1 only — "
                       "open it with a newer Camwright")
                .arg(a(0));
        case Code::NotFormatVersion1:
            return DiagnosticText::tr("must be 1 (got %1)").arg(a(0));
        case Code::BezierPointCount:
            return DiagnosticText::tr("must be an array of four points [x, y]");
        case Code::JsonDuplicatedKey:
            return DiagnosticText::tr("duplicated key");
        case Code::JsonNumberTooLarge:
            return DiagnosticText::tr("line %1, column %2: number %3 is too large for a double")
                .arg(a(0), a(1), a(2));
        case Code::JsonSyntax:
            return DiagnosticText::tr("line %1, column %2: not valid JSON: %3")
                .arg(a(0), a(1), a(2));
        case Code::JsonTooDeep:
            return DiagnosticText::tr("nesting deeper than %1 levels").arg(a(0));
        case Code::JsonNulByte:
            return DiagnosticText::tr(
                       "line %1, column %2: a NUL byte (at byte offset %3): a project file is "
                       "text")
                .arg(a(0), a(1), a(2));
        case Code::JsonInvalid:
            return DiagnosticText::tr("not valid JSON");
        case Code::RowValueCount:
            if (std::get<std::string>(d.args[1]) == std::get<std::string>(d.args[2])) {
                return DiagnosticText::tr("line %1: expected %2 (got %3 values)")
                    .arg(a(0), a(1), a(3));
            }
            return DiagnosticText::tr("line %1: expected %2 or %3 (got %4 values)")
                .arg(a(0), a(1), a(2), a(3));
        case Code::RowValueNotFinite:
            return DiagnosticText::tr("line %1: %2 must be a finite number (got “%3”)")
                .arg(a(0), a(1), a(2));
        case Code::FilletContourInvalid:
            return DiagnosticText::tr("the contour is not valid, so the joint cannot be rounded");
        case Code::FilletNeedsArcsAndLines:
            return DiagnosticText::tr("fillets join arcs and lines; segment %1 is neither")
                .arg(a(0));
        case Code::FilletAlreadyTangent:
            return DiagnosticText::tr(
                       "the segments already meet tangentially (their tangents differ by %1°, at "
                       "most %2° counts as tangent); there is no corner to round")
                .arg(a(0), a(1));
        case Code::FilletRadiusNeedsArcsAndLines:
            return DiagnosticText::tr(
                       "radius %1 mm does not fit: fillets join arcs and lines; segment %2 is "
                       "neither")
                .arg(a(0), a(1));
        case Code::FilletRadiusAlreadyTangent:
            return DiagnosticText::tr(
                       "radius %1 mm does not fit: the segments already meet tangentially (their "
                       "tangents differ by %2°, at most %3° counts as tangent); there is no "
                       "corner to round")
                .arg(a(0), a(1), a(2));
        case Code::FilletNothingFits:
            return DiagnosticText::tr("no fillet radius of at least %1 mm fits at this joint (%2)")
                .arg(a(0), filletReason(d, 1));
        case Code::FilletRadiusNothingFits:
            return DiagnosticText::tr(
                       "radius %1 mm does not fit: no fillet radius of at least %2 mm fits at "
                       "this joint (%3)")
                .arg(a(0), a(1), filletReason(d, 2));
        case Code::FilletRadiusTooSmall:
            return DiagnosticText::tr(
                       "radius %1 mm is too small: a fillet radius is at least %2 mm, the "
                       "smallest radius a project holds")
                .arg(a(0), a(1));
        case Code::FilletRadiusNotPositive:
            return DiagnosticText::tr("radius %1 mm must be a number > 0: radii below %2 mm fit")
                .arg(a(0), a(1));
        case Code::FilletRadiusTooLarge:
            return DiagnosticText::tr("radius %1 mm is too large: only radii below %2 mm fit (%3)")
                .arg(a(0), a(1), filletReason(d, 2));
        case Code::FilletRadiusInGap:
            return DiagnosticText::tr(
                       "radius %1 mm does not fit (%2), although most radii below %3 mm do")
                .arg(a(0), filletReason(d, 1), a(2));
        case Code::RollerNotSmallerThanArc:
            return DiagnosticText::tr(
                       "the roller radius %1 mm is not smaller than this concave arc's radius %2 "
                       "mm: the roller cannot follow it")
                .arg(a(0), a(1));
        case Code::PivotInsideCam:
            return DiagnosticText::tr(
                       "is inside the cam: the pivot turns on a circle of radius %1 mm round the "
                       "cam centre, but the profile reaches %2 mm at %3°; move it farther out")
                .arg(a(0), a(1), a(2));
        case Code::ArmTooShort:
            return DiagnosticText::tr(
                       "is too short: at %1° the cam is %2 mm from the pivot, and %3 reaches "
                       "only %4 mm")
                .arg(a(0), a(1), a(2), a(3));
        case Code::ArmTooLong:
            return DiagnosticText::tr(
                       "is too long: at %1° %2 passes beyond the whole cam (at most %3 mm from "
                       "the pivot)")
                .arg(a(0), a(1), a(2));
        case Code::ArmNoContact:
            return DiagnosticText::tr(
                       "does not let %1 touch the cam at %2° (no contact on the chosen side of "
                       "the arm)")
                .arg(a(0), a(1));
        case Code::ToolAboveCurveRadius:
            return DiagnosticText::tr(
                       "the tool radius %1 mm is larger than this curve's tightest concave radius "
                       "%2 mm: the offset path degenerates")
                .arg(a(0), a(1));
        case Code::ToolNotBelowArcRadius:
            return DiagnosticText::tr(
                       "the tool radius %1 mm is not smaller than the radius %2 mm of this "
                       "concave arc: the offset path degenerates")
                .arg(a(0), a(1));
        case Code::OffsetCornerUnmet:
            return DiagnosticText::tr("the offset segments do not meet at this corner");
        case Code::ToolTrimsSegment:
            return DiagnosticText::tr(
                       "the tool radius %1 mm is too large here: at its concave corners the "
                       "offset of this segment would have to be trimmed beyond its ends")
                .arg(a(0));
        case Code::SeedStepTooSmall:
            return DiagnosticText::tr("must be a finite length of at least %1 mm (got %2)")
                .arg(a(0), a(1));
        case Code::SeedStepTooMany:
            return DiagnosticText::tr(
                       "%1 mm makes %2 steps on this %3 mm path; the seed method takes at most "
                       "%4: a step of at least %5 mm")
                .arg(a(0), a(1), a(2), a(3), a(4));
        case Code::AccelerationLimitMissing:
            return DiagnosticText::tr(
                       "no acceleration limit for the %1 axis, along which the path moves "
                       "(segment %2): without one its speed would be unbounded and its time 0")
                .arg(axisName(static_cast<int>(std::get<double>(d.args[0]))), a(1));
        case Code::PathEmpty:
            return DiagnosticText::tr("is empty");
        case Code::PathPointInvalid:
            return DiagnosticText::tr(
                "coordinates must be finite, at most 10⁶ mm, and the bulge finite");
        case Code::PathTooFewPoints:
            return DiagnosticText::tr("a path needs at least two points");
        case Code::PathPointRepeated:
            return DiagnosticText::tr("repeats the previous point");
        case Code::PathArcChangesHeight:
            return DiagnosticText::tr(
                       "an arc (bulge %1) must keep its height, but z goes from %2 to %3")
                .arg(a(0), a(1), a(2));
        case Code::PathArcNoChord:
            return DiagnosticText::tr("an arc needs two distinct points in the XY plane");
        case Code::PathArcTooFar:
            return DiagnosticText::tr(
                       "the arc (bulge %1) reaches %2 mm from the origin; a path must stay "
                       "within %3 mm")
                .arg(a(0), a(1), a(2));
        case Code::TangentNeedsArcs:
            return DiagnosticText::tr("a tangent line joins two arcs; segment %1 is %2")
                .arg(a(0), a(1));
        case Code::TangentNotCircle:
            return DiagnosticText::tr(
                       "segment %1 is not a circle (its radius must be a finite number > 0, its "
                       "centre finite)")
                .arg(a(0));
        case Code::TangentSameCircle:
            return DiagnosticText::tr(
                "both arcs lie on the same circle, so they already meet tangentially: no line "
                "fits between them");
        case Code::TangentCircleInside:
            return DiagnosticText::tr(
                       "the circle of segment %1 lies inside that of segment %2, so the two "
                       "circles have no common tangent")
                .arg(a(0), a(1));
        case Code::TangentNoneFits: {
            QStringList reasons;
            for (const Diagnostic& reason : d.reasons) reasons << translatedMessage(reason);
            return DiagnosticText::tr("no tangent line fits: %1")
                .arg(reasons.join(QStringLiteral("; ")));
        }
        case Code::TangentTouch:
            return DiagnosticText::tr(
                       "the circles touch at (%1, %2): the arcs can meet there directly, without "
                       "a line")
                .arg(a(0), a(1));
        case Code::TangentClockwise:
            return DiagnosticText::tr(
                       "%1 runs clockwise around the rotation centre (its polar angle would not "
                       "grow from segment %2 to segment %3)")
                .arg(tangent, a(3), a(6));
        case Code::TangentOnNearSide:
            return DiagnosticText::tr(
                       "%1 touches segment %2 on the near side of its circle, but the arc "
                       "follows the far side (outer branch)")
                .arg(tangent, a(7));
        case Code::TangentOnFarSide:
            return DiagnosticText::tr(
                       "%1 touches segment %2 on the far side of its circle, but the arc follows "
                       "the near side (inner branch)")
                .arg(tangent, a(7));
        case Code::TangentEmptiesLeft:
            return DiagnosticText::tr(
                       "with %1 the window of segment %2 would be empty: its end would move onto "
                       "its start %3°")
                .arg(tangent, a(3), a(7));
        case Code::TangentReversesRight:
            return DiagnosticText::tr(
                       "with %1 the window of segment %2 would be empty or reversed: its start "
                       "would move to %3°, not before its end %4°")
                .arg(tangent, a(6), a(7), a(8));
        case Code::ArcNoSegment:
            return DiagnosticText::tr("has no segment to continue");
        case Code::ArcNoSuchRow:
            return DiagnosticText::tr("there is no segment %1: rows are 0 .. %2").arg(a(0), a(1));
        case Code::ArcSingleNotCircle:
            return DiagnosticText::tr("a contour of one segment must be a circle; segment %1 is %2")
                .arg(a(0), a(1));
        case Code::ArcRowNotCircle:
            return DiagnosticText::tr("segment %1 is not a circle").arg(a(0));
        case Code::ArcRayMissesEnd:
            return DiagnosticText::tr(
                       "the follower ray at the end %1° of segment %2 misses its circle, so it "
                       "has no end point")
                .arg(a(0), a(1));
        case Code::ArcNoEndDirection:
            return DiagnosticText::tr("segment %1 has no direction at its end point").arg(a(0));
        case Code::ArcEndClockwise:
            return DiagnosticText::tr(
                       "segment %1 does not run counter-clockwise around the rotation centre at "
                       "its end point (%2, %3) (its polar angle does not grow there)")
                .arg(a(0), a(1), a(2));
        case Code::ArcPointNotFinite:
            return DiagnosticText::tr("the point must be finite (got (%1, %2))").arg(a(0), a(1));
        case Code::ArcPointAtCentre:
            return DiagnosticText::tr(
                "the point is the rotation centre, which no arc of the contour can reach");
        case Code::ArcPointIsEnd:
            return DiagnosticText::tr(
                       "the point is the end point (%1, %2) of segment %3: an arc needs a second "
                       "point")
                .arg(a(0), a(1), a(2));
        case Code::ArcPointOnTangent:
            return DiagnosticText::tr(
                "the point is on the tangent: use a line (an arc through it would need a radius "
                "or centre beyond 10⁶ mm, the largest length a project holds)");
        case Code::ArcRadiusTooSmall:
            return DiagnosticText::tr(
                       "the arc's radius would be %1 mm, below %2 mm, the smallest a project "
                       "holds")
                .arg(a(0), a(1));
        case Code::ArcEndOffOuter:
            return DiagnosticText::tr(
                       "the end point of segment %1 is not on the outer branch of the circle "
                       "(centre (%2, %3), radius %4 mm)")
                .arg(a(0), a(1), a(2), a(3));
        case Code::ArcEndOffInner:
            return DiagnosticText::tr(
                       "the end point of segment %1 is not on the inner branch of the circle "
                       "(centre (%2, %3), radius %4 mm)")
                .arg(a(0), a(1), a(2), a(3));
        case Code::ArcPointOnNearSide:
            return DiagnosticText::tr(
                       "the point lies on the near side of the circle (centre (%1, %2), radius "
                       "%3 mm) as seen from the rotation centre, but the arc leaves segment %4 "
                       "on its far side (outer branch): the follower ray would not meet the arc "
                       "at the point")
                .arg(a(0), a(1), a(2), a(3));
        case Code::ArcPointOnFarSide:
            return DiagnosticText::tr(
                       "the point lies on the far side of the circle (centre (%1, %2), radius "
                       "%3 mm) as seen from the rotation centre, but the arc leaves segment %4 "
                       "on its near side (inner branch): the follower ray would not meet the arc "
                       "at the point")
                .arg(a(0), a(1), a(2), a(3));
        case Code::ArcRunsBackNear:
            return DiagnosticText::tr(
                       "the point lies behind the end point of segment %1 as seen from the "
                       "rotation centre: the arc along the circle (centre (%2, %3), radius %4 mm) "
                       "would pass to its near side and run back before reaching it")
                .arg(a(0), a(1), a(2), a(3));
        case Code::ArcRunsBackFar:
            return DiagnosticText::tr(
                       "the point lies behind the end point of segment %1 as seen from the "
                       "rotation centre: the arc along the circle (centre (%2, %3), radius %4 mm) "
                       "would pass to its far side and run back before reaching it")
                .arg(a(0), a(1), a(2), a(3));
        case Code::ArcPointOnEndRay:
            return DiagnosticText::tr(
                       "the point lies on the follower ray at the end %1° of segment %2: the "
                       "arc's window would be empty")
                .arg(a(0), a(1));
        case Code::ArcEndsAfterNext:
            return DiagnosticText::tr(
                       "the arc would end at %1° (the polar angle of the point), not before the "
                       "end %2° of segment %3, whose window would be empty or reversed")
                .arg(a(0), a(1), a(2));
        case Code::ArcPointIsNextEnd:
            return DiagnosticText::tr(
                       "the point is the end point of segment %1, which would have no length "
                       "left")
                .arg(a(0));
        case Code::ArcNextClockwise:
            return DiagnosticText::tr(
                       "with its start point moved to the point, segment %1 would no longer run "
                       "counter-clockwise from %2° to its end %3°")
                .arg(a(0), a(1), a(2));
        case Code::ExportToleranceOutOfRange:
            return DiagnosticText::tr("the tolerance must be between %1 and %2 mm, not %3")
                .arg(a(0), a(1), a(2));
        case Code::ExportToolRadiusOutOfRange:
            return DiagnosticText::tr("the tool radius must be above 0 and at most %1 mm, not %2")
                .arg(a(0), a(1));
        case Code::GcodeCompensationCutsPart:
            return DiagnosticText::tr(
                "with cutter compensation the tool would have to reach past the next programmed "
                "arc at a concave corner of this segment, which a controller offsetting one move "
                "at a time turns into a cut through the part; export the tool-centre path "
                "(without --compensation) or use a coarser --tolerance");
        case Code::GcodeLengthOutOfRange:
            return DiagnosticText::tr("%1 must be above 0 and at most %2 mm, not %3")
                .arg(a(0), a(1), a(2));
        case Code::GcodeFeedOutOfRange:
            return DiagnosticText::tr("the feed must be above 0 and at most %1 mm/min, not %2")
                .arg(a(0), a(1));
        case Code::GcodeToolNumber:
            return DiagnosticText::tr("the tool number must be from 1 to 99999, not %1").arg(a(0));
        case Code::GcodeTooManyPasses:
            return DiagnosticText::tr(
                       "a step-down of %1 mm makes %2 passes for a depth of %3 mm; at most %4 "
                       "are made")
                .arg(a(0), a(1), a(2), a(3));
        case Code::CamTablePoints:
            return DiagnosticText::tr("a cam table has from %1 to %2 points, not %3")
                .arg(a(0), a(1), a(2));
        case Code::SampleNotFinite:
            return DiagnosticText::tr(
                       "is not a finite number (%1): the result is beyond what a double can hold")
                .arg(a(0));
        case Code::NoPoints:
            return DiagnosticText::tr("must be at least 1 (got 0)");
        case Code::NotFiniteForFile:
            return DiagnosticText::tr("is not a finite number, which a file cannot hold");
        case Code::FileCannotOpen:
            return DiagnosticText::tr("cannot open: %1").arg(a(0));
        case Code::FileCannotExamineOpen:
            return DiagnosticText::tr("cannot examine: %1").arg(a(0));
        case Code::FileCannotRead:
            return DiagnosticText::tr("cannot read: %1").arg(a(0));
        case Code::FileNotRegularToRead:
            return DiagnosticText::tr("is %1, not a regular file: not read").arg(a(0));
        case Code::FileTooLargeToRead:
            return DiagnosticText::tr("is %1 MiB (%2 bytes): files larger than %3 MiB are not read")
                .arg(a(0), a(1), a(2));
        case Code::FileGrewTooLarge:
            return DiagnosticText::tr(
                       "grew past %1 MiB while it was read: larger files are not read")
                .arg(a(0));
        case Code::FileNoName:
            return DiagnosticText::tr("no file name given");
        case Code::FileCannotExamine:
            return DiagnosticText::tr("cannot examine %1: %2").arg(a(0), a(1));
        case Code::FileLinkLoop:
            return DiagnosticText::tr("cannot follow its symbolic links: %1").arg(a(0));
        case Code::FileCannotReadLink:
            return DiagnosticText::tr("cannot read the symbolic link %1: %2").arg(a(0), a(1));
        case Code::FileIsDescriptorLink:
            return DiagnosticText::tr(
                "is a link to an open file descriptor, not a file: not replaced");
        case Code::FileLinkTargetIsDescriptorLink:
            return DiagnosticText::tr(
                       "%1 is a link to an open file descriptor, not a file: not replaced")
                .arg(a(0));
        case Code::FileNotRegular:
            return DiagnosticText::tr("is %1, not a regular file: not replaced").arg(a(0));
        case Code::FileLinkTargetNotRegular:
            return DiagnosticText::tr("%1 is %2, not a regular file: not replaced").arg(a(0), a(1));
        case Code::FileCannotWrite:
            return DiagnosticText::tr("cannot write %1: %2").arg(a(0), a(1));
        case Code::FileNamesFolder:
            return DiagnosticText::tr("names a folder, not a file");
        case Code::FileCannotCreateTemporary:
            return DiagnosticText::tr("cannot create a temporary file in %1: %2").arg(a(0), a(1));
        case Code::FileCannotCopyOwner:
            return DiagnosticText::tr("cannot give the new file the owner of %1: %2")
                .arg(a(0), a(1));
        case Code::FileCannotCopyPermissions:
            return DiagnosticText::tr("cannot give the new file the permissions of %1: %2")
                .arg(a(0), a(1));
        case Code::FileCannotFlush:
            return DiagnosticText::tr("cannot flush %1 to disk: %2").arg(a(0), a(1));
        case Code::FileBecameOther:
            return DiagnosticText::tr("%1 became %2 while it was written: not replaced")
                .arg(a(0), a(1));
        case Code::FileCannotReplace:
            return DiagnosticText::tr("cannot replace %1: %2").arg(a(0), a(1));
        case Code::FileReplacedCannotClose:
            return DiagnosticText::tr("replaced, but cannot close %1: %2").arg(a(0), a(1));
        case Code::FileReplacedCannotFlushFolder:
            return DiagnosticText::tr("replaced, but cannot flush the folder %1 to disk: %2")
                .arg(a(0), a(1));
        case Code::NoSuchSegment:
            return DiagnosticText::tr("there is no such segment");
        case Code::NotAnArc:
            return DiagnosticText::tr("is not an arc");
        case Code::RadialErrorNotPositive:
            return DiagnosticText::tr("the admissible radial error must be > 0 mm");
        case Code::ApproximationStartMissesArc:
            return DiagnosticText::tr(
                "the follower ray at the start of the window does not meet the arc");
        case Code::ApproximationEndMissesArc:
            return DiagnosticText::tr(
                "the follower ray at the end of the window does not meet the arc");
        case Code::SplineTooFewPoints:
            return DiagnosticText::tr("a spline needs at least two points");
        case Code::ClosedSplineTooFewPoints:
            return DiagnosticText::tr("a closed spline needs at least three points");
        case Code::BulgeNotPositive:
            return DiagnosticText::tr("must be a finite factor > 0 (got %1)").arg(a(0));
        case Code::WindowsSegmentsDoNotMeet:
            return DiagnosticText::tr(
                "the neighbouring segments do not meet, so there is no boundary to fit the "
                "windows to");
        case Code::ContourNeverSynthesised:
            return DiagnosticText::tr(
                "is empty: the design's contour was never synthesised (Synthesize Contour, F6, "
                "makes it)");
        case Code::NoDesign:
            return DiagnosticText::tr(
                "the project has no motion design to synthesise a contour "
                "from");
        case Code::SynthesisedContourInvalid:
            return DiagnosticText::tr("the synthesised arc table is not a valid contour: %1")
                .arg(d.reasons.empty() ? QString() : DiagnosticText::line(d.reasons[0]));
        case Code::SynthesisedArcInvalid:
            return DiagnosticText::tr(
                       "the synthesised arc table is not a valid contour: segment %1, made for "
                       "the cam angles %2° to %3° of design segment %4 (%5)")
                .arg(a(0), a(1), a(2), a(3),
                     d.reasons.empty() ? QString() : DiagnosticText::line(d.reasons[0]));
        case Code::ToleranceCannotBeMet:
            return DiagnosticText::tr(
                       "cannot be met near %1°: no arcs come within it even on pieces of 2^-%2 "
                       "of the profile's sampling step (the profile has a corner or a cusp "
                       "there)")
                .arg(a(0), a(1));
        case Code::ToleranceBelowPrecision:
            return DiagnosticText::tr(
                       "%1 mm is below what double precision can certify for this cam: at least "
                       "%2 mm, for a profile reaching %3 mm from the centre")
                .arg(a(0), a(1), a(2));
        case Code::ToleranceNotReached:
            return DiagnosticText::tr(
                       "cannot be met: the closest arc table found lies %2 mm from the exact "
                       "profile (at %3° of cam angle), more than the %1 mm asked for")
                .arg(a(0), a(1), a(2));
        case Code::OffsetOutsideBaseCircle:
            return DiagnosticText::tr(
                       "the follower's line (offset %1 mm) passes outside the base circle of "
                       "radius %2 mm: make the base radius larger than the offset")
                .arg(a(0), a(1));
        case Code::OffsetOutsidePitchBaseCircle:
            return DiagnosticText::tr(
                       "the follower's line (offset %1 mm) passes outside the base circle of "
                       "radius %2 mm (base radius + roller radius): make the base radius larger "
                       "than the offset")
                .arg(a(0), a(1));
        case Code::ArmMissesBaseCircle:
            return DiagnosticText::tr(
                       "an arm of %1 mm from a pivot %2 mm from the cam centre cannot touch the "
                       "base circle of radius %3 mm")
                .arg(a(0), a(1), a(2));
        case Code::ArmMissesPitchBaseCircle:
            return DiagnosticText::tr(
                       "an arm of %1 mm from a pivot %2 mm from the cam centre cannot touch the "
                       "base circle of radius %3 mm (base radius + roller radius)")
                .arg(a(0), a(1), a(2));
        case Code::UndercutRoller:
            return DiagnosticText::tr(
                       "undercut: from %2° to %3° the pitch curve bends tighter than the roller "
                       "radius %1 mm")
                .arg(a(0), a(1), a(2));
        case Code::UndercutFlatFace:
            return DiagnosticText::tr(
                       "undercut: from %1° to %2° the envelope of the flat face folds back "
                       "(h + h'' < 0)")
                .arg(a(0), a(1));
        case Code::PressureAngleExceeded:
            return DiagnosticText::tr("from %2° to %3° the pressure angle exceeds %1°")
                .arg(a(0), a(1), a(2));
        case Code::FilletRadiusInvalidContour:
            return DiagnosticText::tr("radius %1 mm gives a contour that does not validate (%2)")
                .arg(a(0), d.reasons.empty() ? QString() : DiagnosticText::line(d.reasons[0]));
        case Code::Cancelled:
            return DiagnosticText::tr("cancelled");
    }
    return {};
}

}  // namespace diagnostic_wording

bool DiagnosticText::translatable(const Diagnostic& diagnostic) {
    return diagnostic_wording::argumentsFit(diagnostic);
}

QString DiagnosticText::location(const Diagnostic& d) {
    using namespace diagnostic_wording;
    if (!argumentsFit(d)) return QString::fromStdString(d.location);
    if (placedByArguments(d.code)) return {};
    if (placedInFile(d.code)) return QString::fromStdString(d.location);
    if (d.code == Code::WindowsNotOneTurn) return tr("Contour");
    if (d.places.size() == 2 && d.places[0].segment != d.places[1].segment) {
        return tr("Joint between segments %1 and %2")
            .arg(d.places[0].segment)
            .arg(d.places[1].segment);
    }
    if (d.places.size() == 1) {
        const SegmentPlace& p = d.places.front();
        const QString part = partName(p);
        return part.isEmpty() ? tr("Segment %1").arg(p.segment)
                              : tr("Segment %1, %2").arg(QString::number(p.segment), part);
    }
    // A joint whose location the core names without places (a fillet of joint K, the motion
    // design's contour[k]/contour[k+1] text) is left as the core wrote it.
    return fieldName(d.location);
}

QString DiagnosticText::message(const Diagnostic& d) {
    using namespace diagnostic_wording;
    if (!argumentsFit(d)) return QString::fromStdString(d.message);
    return translatedMessage(d);
}

QString DiagnosticText::line(const Diagnostic& d) {
    using namespace diagnostic_wording;
    if (!argumentsFit(d)) return QString::fromStdString(d.text());
    const QString where = location(d);
    const QString what = translatedMessage(d);
    return where.isEmpty() ? what : tr("%1: %2").arg(where, what);
}

}  // namespace cam
