#include "messages/diagnostic_text.h"

#include <QLocale>
#include <QRegularExpression>
#include <cmath>
#include <type_traits>
#include <utility>

#include "common/diagnostic_catalogue.h"
#include "design/motion_law.h"
#include "messages/field_titles.h"
#include "widgets/quantity_format.h"

namespace cam {
// A named namespace, not an anonymous one: the app is a unity build, and helpers named
// columnName or term would meet their namesakes in the same translation unit.
namespace diagnostic_wording {

using Code = DiagnosticCode;

/// The user's number format without group separators: a message may quote what was typed.
QLocale messageLocale() {
    QLocale locale;
    locale.setNumberOptions(locale.numberOptions() | QLocale::OmitGroupSeparator);
    return locale;
}

/// A number in a message: at most kMessageDigits significant digits (as the core's English),
/// the user's decimal separator, no group separators, never "-0". A message does not say what
/// quantity its number is, and often quotes what was typed: it keeps the digits a cell shows
/// a typed value with, and does not round a typed 1e-12 to 0 as the table's display does.
static_assert(quantityFormat(DisplayQuantity::Input).significant == kMessageDigits);
QString messageNumber(double value) {
    if (value == 0.0) return QStringLiteral("0");
    return messageLocale().toString(value, 'g', kMessageDigits);
}

/// A count or a typed whole number (a tool number, a file's bytes) with every digit: unlike
/// the table's Count, never rounded to ten digits, since it may quote what was typed.
QString wholeNumber(double value) {
    return messageLocale().toString(static_cast<qlonglong>(std::llround(value)));
}

/// The header text without its unit: "Radius [mm]" → "Radius", for a column named inside a
/// sentence whose numbers carry their units.
QString columnName(int column) {
    static const QRegularExpression unit(QStringLiteral(R"(\s*\[[^\]]*\]$)"));
    return segmentColumnTitle(column).remove(unit);
}

/// "X", "Y", "Z" for an axis index of the machine.
QString axisName(double i) {
    return i >= 0.0 && i < 3.0 ? QString(QChar('X' + static_cast<int>(i))) : messageNumber(i);
}

/// A motion law by its file name, as the design table names it.
QString lawTitle(const std::string& name) {
    if (const auto law = lawFromName(name)) {
        const QStringList titles = motionLawTitles();
        const auto index = static_cast<qsizetype>(*law);
        if (index < titles.size()) return titles[index];
    }
    return QString::fromStdString(name);
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

/// The table column(s) or the control point a segment place names; `title` gives a column's
/// name (with its unit for a place, without inside a sentence).
QString partName(const SegmentPlace& p, QString (*title)(int)) {
    auto pair = [&](int x, int y) {
        if (p.axis == 0) return title(x);
        if (p.axis == 1) return title(y);
        return title(x) + QStringLiteral(" / ") + title(y);
    };
    switch (p.part) {
        case SegmentPart::Whole:
            return QString();
        case SegmentPart::Type:
            return title(SegmentColumns::Type);
        case SegmentPart::Center:
            return pair(SegmentColumns::CenterX, SegmentColumns::CenterY);
        case SegmentPart::Radius:
            return title(SegmentColumns::Radius);
        case SegmentPart::Branch:
            return title(SegmentColumns::Branch);
        case SegmentPart::From:
            return pair(SegmentColumns::FromX, SegmentColumns::FromY);
        case SegmentPart::To:
            return pair(SegmentColumns::ToX, SegmentColumns::ToY);
        case SegmentPart::PhiStart:
            return title(SegmentColumns::PhiStart);
        case SegmentPart::PhiEnd:
            return title(SegmentColumns::PhiEnd);
        case SegmentPart::Points:
        case SegmentPart::P0:
        case SegmentPart::T0:
        case SegmentPart::P3:
        case SegmentPart::T1:
            return pointPart(p);
    }
    return QString();
}

/// An argument of the kind `kind` (a signature letter, not `r`) as the window words it.
QString argument(char kind, const DiagnosticArg& arg) {
    if (const auto* part = std::get_if<SegmentPart>(&arg)) {
        return partName(SegmentPlace{0, *part}, columnName);
    }
    if (const auto* text = std::get_if<std::string>(&arg)) {
        if (kind == 's') return QCoreApplication::translate(kDiagnosticContext, text->c_str());
        if (kind == 'l') return lawTitle(*text);
        return QString::fromStdString(*text);
    }
    const double value = std::get<double>(arg);
    switch (kind) {
        case 'i':
            return wholeNumber(value);
        case 'd':
            return messageLocale().toString(value, 'f', 1);
        case 'k':
            return DiagnosticText::tr("segment %1").arg(wholeNumber(value));
        case 'a':
            return axisName(value);
        default:
            return messageNumber(value);
    }
}

/// The reasons a message lists, each as its line, "a; b".
QString reasonsText(const Diagnostic& d) {
    QStringList lines;
    for (const Diagnostic& reason : d.reasons) lines << DiagnosticText::line(reason);
    return lines.join(QStringLiteral("; "));
}

/// The template in the window's language: the catalogue's, translated; or, for the few codes
/// whose English names something only the command line has, the window's own.
QString windowTemplate(Code code) {
    // The core's English names the CLI's command that makes the contour; the window has its
    // menu command.
    if (code == Code::ContourNeverSynthesised) {
        return DiagnosticText::tr(
            "is empty: the design's contour was never synthesised (Synthesize Contour, F6, "
            "makes it)");
    }
    return QCoreApplication::translate(kDiagnosticContext, diagnosticTemplate(code));
}

QString translatedMessage(const Diagnostic& d) {
    std::vector<std::string> values;
    std::size_t next = 0;
    for (const char kind : diagnosticCodeSignature(d.code)) {
        const QString value = kind == 'r' ? reasonsText(d) : argument(kind, d.args[next++]);
        values.push_back(value.toStdString());
    }
    return QString::fromStdString(fillPlaceholders(windowTemplate(d.code).toStdString(), values));
}

/// A named field as the panels name it (lupdate reads the names here; tr() at lookup); its
/// key where it is none of them.
QString fieldName(const FieldPlace& p) {
    const int i = p.index;
    switch (p.field) {
        case Field::MachiningAxisAccel:
            if (i >= 0)
                return DiagnosticText::tr("Machining, acceleration of axis %1").arg(axisName(i));
            break;
        case Field::MachiningAxisVmax:
            if (i >= 0)
                return DiagnosticText::tr("Machining, speed limit of axis %1").arg(axisName(i));
            break;
        case Field::FollowerPivot:
            if (i == 0) return DiagnosticText::tr("Follower, pivot x");
            if (i == 1) return DiagnosticText::tr("Follower, pivot y");
            break;
        case Field::Point:
            // The teach-in's points, numbered from 0 as the segments are.
            if (i >= 0) return DiagnosticText::tr("Point %1").arg(i);
            break;
        default:
            break;
    }
    static constexpr std::pair<Field, const char*> kTitles[] = {
        {Field::Contour, QT_TRANSLATE_NOOP("DiagnosticText", "Contour")},
        {Field::Points, QT_TRANSLATE_NOOP("DiagnosticText", "Points")},
        {Field::Bulge, QT_TRANSLATE_NOOP("DiagnosticText", "Bulge factor")},
        {Field::ApproximationError, QT_TRANSLATE_NOOP("DiagnosticText", "Admissible radial error")},
        {Field::MotionOmega, QT_TRANSLATE_NOOP("DiagnosticText", "Motion, ω [rad/s]")},
        {Field::MotionRpm, QT_TRANSLATE_NOOP("DiagnosticText", "Motion, speed [rpm]")},
        {Field::MotionPeriod, QT_TRANSLATE_NOOP("DiagnosticText", "Motion, period [s]")},
        {Field::FollowerOffset, QT_TRANSLATE_NOOP("DiagnosticText", "Follower, offset")},
        {Field::FollowerRadius, QT_TRANSLATE_NOOP("DiagnosticText", "Follower, roller radius")},
        {Field::FollowerMaxPressureAngle,
         QT_TRANSLATE_NOOP("DiagnosticText", "Follower, largest pressure angle")},
        {Field::FollowerType, QT_TRANSLATE_NOOP("DiagnosticText", "Follower, type")},
        {Field::FollowerPivot, QT_TRANSLATE_NOOP("DiagnosticText", "Follower, pivot")},
        {Field::FollowerArmLength, QT_TRANSLATE_NOOP("DiagnosticText", "Follower, arm length")},
        {Field::FollowerClosure, QT_TRANSLATE_NOOP("DiagnosticText", "Follower, closure")},
        {Field::FollowerGrooveClearance,
         QT_TRANSLATE_NOOP("DiagnosticText", "Follower, groove clearance")},
        {Field::FollowerInnerLandRadius,
         QT_TRANSLATE_NOOP("DiagnosticText", "Follower, groove's inner land radius")},
        {Field::FollowerOuterLandRadius,
         QT_TRANSLATE_NOOP("DiagnosticText", "Follower, groove's outer land radius")},
        {Field::FollowerConjugateDistance,
         QT_TRANSLATE_NOOP("DiagnosticText", "Follower, second roller's distance")},
        {Field::FollowerConjugateRadius,
         QT_TRANSLATE_NOOP("DiagnosticText", "Follower, second roller's radius")},
        {Field::FollowerConjugateAngle,
         QT_TRANSLATE_NOOP("DiagnosticText", "Follower, second arm's angle")},
        {Field::FollowerConjugateArmLength,
         QT_TRANSLATE_NOOP("DiagnosticText", "Follower, second arm's length")},
        {Field::SamplesPerTurn, QT_TRANSLATE_NOOP("DiagnosticText", "Samples per turn")},
        {Field::MachiningAxisAccel,
         QT_TRANSLATE_NOOP("DiagnosticText", "Machining, axis accelerations")},
        {Field::MachiningAxisVmax,
         QT_TRANSLATE_NOOP("DiagnosticText", "Machining, axis speed limits")},
        {Field::MachiningFeedMax, QT_TRANSLATE_NOOP("DiagnosticText", "Machining, feed ceiling")},
        {Field::MachiningToolRadius, QT_TRANSLATE_NOOP("DiagnosticText", "Machining, tool radius")},
        {Field::MachiningStep, QT_TRANSLATE_NOOP("DiagnosticText", "Machining, step")},
        {Field::Design, QT_TRANSLATE_NOOP("DiagnosticText", "Motion design")},
        {Field::DesignBaseRadius,
         QT_TRANSLATE_NOOP("DiagnosticText", "Motion design, base radius")},
        {Field::DesignTolerance, QT_TRANSLATE_NOOP("DiagnosticText", "Motion design, tolerance")},
        {Field::DesignSegments, QT_TRANSLATE_NOOP("DiagnosticText", "Motion design, segments")},
    };
    if (i < 0) {
        for (const auto& [field, title] : kTitles) {
            if (field == p.field) return DiagnosticText::tr(title);
        }
    }
    return QString::fromStdString(locationText(p));
}

/// A field of a design segment inside the place's name; empty for the whole segment.
QString designPartName(DesignPart part) {
    switch (part) {
        case DesignPart::Whole:
            return {};
        case DesignPart::Law:
            return DiagnosticText::tr("law");
        case DesignPart::ToDeg:
            return DiagnosticText::tr("end angle");
        case DesignPart::Lift:
            return DiagnosticText::tr("lift");
        default:
            return QString::fromUtf8(designPartKey(part).data(), designPartKey(part).size());
    }
}

QString placeName(std::monostate) { return {}; }

QString placeName(const SegmentPlace& p) {
    const QString part = partName(p, segmentColumnTitle);
    return part.isEmpty()
               ? DiagnosticText::tr("Segment %1").arg(p.segment)
               : DiagnosticText::tr("Segment %1, %2").arg(QString::number(p.segment), part);
}

QString placeName(const JointPlace& p) {
    return DiagnosticText::tr("Joint between segments %1 and %2").arg(p.left).arg(p.right);
}

QString placeName(const TurnPlace&) { return DiagnosticText::tr("Contour"); }

QString placeName(const FieldPlace& p) { return fieldName(p); }

QString placeName(const DesignSegmentPlace& p) {
    const QString part = designPartName(p.part);
    if (part.isEmpty()) return DiagnosticText::tr("Motion design, segment %1").arg(p.segment);
    return DiagnosticText::tr("Motion design, segment %1, %2")
        .arg(QString::number(p.segment), part);
}

QString placeName(const DesignJointPlace& p) {
    return DiagnosticText::tr("Motion design, joint between segments %1 and %2")
        .arg(p.left)
        .arg(p.right);
}

QString placeName(const FilePositionPlace& p) {
    if (p.column == 0) return DiagnosticText::tr("line %1").arg(p.line);
    return DiagnosticText::tr("line %1, column %2").arg(p.line).arg(p.column);
}

/// Keys of a file being read stay the file's own words: the user finds them in the file.
QString placeName(const FileKeyPlace& p) { return QString::fromStdString(p.key); }

QString placeName(const FilePlace& p) { return QString::fromStdString(p.path); }

QString placeName(const DynamicsPlace& p) {
    return DiagnosticText::tr("Dynamics, %1").arg(dynamicsKeyTitle(p.key));
}

QString placeName(const SamplePlace& p) {
    return DiagnosticText::tr("sample %1, %2")
        .arg(QString::number(p.sample), QString::fromStdString(p.quantity));
}

bool translatable(const Diagnostic& d) {
    if (d.code == Code::Unspecified || !argumentsFit(d.code, d.args)) return false;
    for (const Diagnostic& reason : d.reasons) {
        if (!translatable(reason)) return false;
    }
    return true;
}

}  // namespace diagnostic_wording

bool DiagnosticText::translatable(const Diagnostic& diagnostic) {
    return diagnostic_wording::translatable(diagnostic);
}

QString DiagnosticText::location(const Diagnostic& d) {
    if (!translatable(d)) return QString::fromStdString(d.location);
    return std::visit([](const auto& place) { return diagnostic_wording::placeName(place); },
                      d.place);
}

QString DiagnosticText::message(const Diagnostic& d) {
    if (!translatable(d)) return QString::fromStdString(d.message);
    return diagnostic_wording::translatedMessage(d);
}

QString DiagnosticText::line(const Diagnostic& d) {
    if (!translatable(d)) return QString::fromStdString(d.text());
    const QString where = location(d);
    const QString what = message(d);
    return where.isEmpty() ? what : tr("%1: %2").arg(where, what);
}

}  // namespace cam
