#include "export/gcode.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "common/angles.h"
#include "common/translate_marker.h"
#include "export/export_checks.h"
#include "export/number_text.h"
#include "geometry/planar.h"
#include "toolpath/tool_path.h"

namespace cam {
namespace {

using Vec2 = Eigen::Vector2d;

constexpr int kDecimals = 6;
/// An arc that leaves its chord by at most this is written as a line (mm): far below the
/// printed resolution, and it keeps tiny arcs (a corner turned by 1e-7 rad) from printing a start
/// equal to their end, which G2/G3 would read as a full circle.
constexpr double kStraightSagittaMm = 1e-6;
/// The tool centre's lead arcs have this radius at least, mm (else the tool radius).
constexpr double kMinLeadRadiusMm = 1.0;

/// `value` as the program prints it: 6 decimals, read back. Printing the result gives the same
/// text, so what is computed from it (I/J) matches the file exactly.
double printed(double value) {
    std::string text;
    appendFixed(text, value, kDecimals);
    double back = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    return back;
}

Vec2 xy(const Eigen::Vector3d& v) { return v.head<2>(); }

/// One move of the loop in the plane: a line, or an arc round `center` with `radius`
/// (counter-clockwise if `sweep` > 0) from the previous move's end to `end`.
struct Move {
    bool arc = false;
    Vec2 end{0, 0};
    Vec2 center{0, 0};
    double radius = 0.0;
    double sweep = 0.0;
};

PathSegment reversed(const PathSegment& s) {
    PathSegment r = s;
    std::swap(r.start, r.end);
    if (s.kind == PathSegment::Kind::Arc) {
        r.startAngle = s.startAngle + s.sweep;
        r.sweep = -s.sweep;
    }
    return r;
}

/// A closed path of contour offsets (counter-clockwise round the part: increasing polar angle)
/// in the order the cutter goes: climb milling goes the other way.
std::vector<PathSegment> inTravelOrder(std::vector<PathSegment> pieces,
                                       MillingDirection direction) {
    if (direction == MillingDirection::Climb) {
        std::reverse(pieces.begin(), pieces.end());
        for (PathSegment& s : pieces) s = reversed(s);
    }
    return pieces;
}

/// The part of arc `s` between the angles `from` and `to` along it (rad, in its sweep's
/// direction, 0 at its start).
PathSegment arcPart(const PathSegment& s, double from, double to) {
    const double sign = s.sweep >= 0 ? 1.0 : -1.0;
    return PathSegment::arc(s.center, s.radius, s.startAngle + sign * from, sign * (to - from),
                            0.0);
}

/// A point of a closed path: its piece, and the angle along that piece from its start (rad; 0
/// on lines).
struct PathPlace {
    std::size_t piece = 0;
    double along = 0.0;
};

/// Where on the closed path the tool is farthest from the rotation centre.
PathPlace farthestPoint(const std::vector<PathSegment>& pieces) {
    PathPlace best;
    double farthest = -1.0;
    auto take = [&](std::size_t i, double along, const Vec2& p) {
        if (p.norm() > farthest) best = {i, along}, farthest = p.norm();
    };
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const PathSegment& s = pieces[i];
        take(i, 0.0, xy(s.start));
        if (s.kind != PathSegment::Kind::Arc || s.center.norm() < 1e-12) continue;
        // On a circle the farthest point lies in the direction of its centre.
        const double toward = std::atan2(s.center.y(), s.center.x());
        double along =
            std::remainder(s.sweep >= 0 ? toward - s.startAngle : s.startAngle - toward, kTwoPi);
        if (along < 0) along += kTwoPi;
        if (along < std::abs(s.sweep)) {
            take(i, along, s.center + s.radius * s.center.normalized());
        }
    }
    return best;
}

/// The closed path rotated (and its piece split) so that it starts at `at`.
std::vector<PathSegment> startingAt(const std::vector<PathSegment>& pieces, const PathPlace& at) {
    const PathSegment& s = pieces[at.piece];
    if (pieces.size() == 1 && s.kind == PathSegment::Kind::Arc) {
        // A full circle: the same circle from the new start.
        const double sign = s.sweep >= 0 ? 1.0 : -1.0;
        return {PathSegment::arc(s.center, s.radius, s.startAngle + sign * at.along, s.sweep, 0.0)};
    }
    std::vector<PathSegment> loop;
    std::optional<PathSegment> head, tail;
    if (at.along * s.radius <= 1e-9) {
        head = s;  // lines, and an arc's start (to 1e-9 mm)
    } else if ((std::abs(s.sweep) - at.along) * s.radius <= 1e-9) {
        tail = s;  // the arc's end: start with the next piece
    } else {
        head = arcPart(s, at.along, std::abs(s.sweep));
        tail = arcPart(s, 0.0, at.along);
        head->end = s.end;
        tail->start = s.start;
        tail->end = head->start;
    }
    if (head) loop.push_back(*head);
    for (std::size_t k = 1; k < pieces.size(); ++k)
        loop.push_back(pieces[(at.piece + k) % pieces.size()]);
    if (tail) loop.push_back(*tail);
    return loop;
}

std::vector<Move> movesOf(const std::vector<PathSegment>& loop) {
    std::vector<Move> moves;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const PathSegment& s = loop[i];
        // Each piece ends exactly where the next begins (the first piece's start closes the loop).
        const Vec2 end = xy(loop[(i + 1) % loop.size()].start);
        if (s.kind == PathSegment::Kind::Line) {
            moves.push_back({false, end});
            continue;
        }
        // Half a turn at most per move: a full circle is two, and no controller has to decide
        // which way round a move with start = end goes.
        const int parts = std::max(1, static_cast<int>(std::ceil(std::abs(s.sweep) / kPi - 1e-9)));
        for (int k = 0; k < parts; ++k) {
            const PathSegment part = PathSegment::arc(
                s.center, s.radius, s.startAngle + k * s.sweep / parts, s.sweep / parts, 0.0);
            moves.push_back(
                {true, k + 1 == parts ? end : xy(part.end), s.center, s.radius, s.sweep / parts});
        }
    }
    return moves;
}

/// The part contour as the loop of a program with cutter compensation, starting at `contact`
/// (the profile point the tool-centre loop starts rho away from). `centre` is the tool-centre
/// path, whose pieces per segment tell where compensation would go wrong.
Result<std::vector<Move>> compensatedLoop(const Contour& contour, const ContourOffset& centre,
                                          double toleranceMm, const Vec2& contact,
                                          MillingDirection direction) {
    auto profile = offsetContour(contour, 0.0, toleranceMm);
    if (!profile.ok()) return profile.errors();
    // A controller offsets one programmed move at a time. Where the tool-centre path had to drop
    // whole arcs of a spline at a concave corner, the crossing lies beyond the next move; LinuxCNC
    // then turns the short arc into an almost full circle through the part.
    Diagnostics errors;
    for (std::size_t k = 0; k < contour.size(); ++k) {
        auto piecesOf = [k](const std::vector<std::size_t>& origin) {
            return std::count(origin.begin(), origin.end(), k);
        };
        if (piecesOf(centre.origin) != piecesOf(profile.value().origin)) {
            errors.push_back(
                Diagnostic::make(SegmentPlace{k}, DiagnosticCode::GcodeCompensationCutsPart));
        }
    }
    if (!errors.empty()) return errors;
    std::vector<PathSegment> pieces = inTravelOrder(profile.value().path.segments, direction);
    // The profile point nearest to the contact (on a profile corner, which the tool-centre path
    // rolls round, the corner itself).
    PathPlace at;
    double nearestDistance = std::numeric_limits<double>::infinity();
    double lineSplit = 0.0;  // where a line is split, as a fraction of it
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const PathSegment& s = pieces[i];
        double along = 0.0, fraction = 0.0;
        Vec2 nearest = xy(s.start);
        if (s.kind == PathSegment::Kind::Line) {
            const Vec2 d = xy(s.end - s.start);
            fraction = std::clamp((contact - xy(s.start)).dot(d) / d.squaredNorm(), 0.0, 1.0);
            if (fraction >= 1.0) continue;  // the next piece's start
            nearest = xy(s.start) + fraction * d;
        } else {
            const Vec2 w = contact - s.center;
            const double toward = std::atan2(w.y(), w.x());
            double a = std::remainder(s.sweep >= 0 ? toward - s.startAngle : s.startAngle - toward,
                                      kTwoPi);
            if (a < 0) a += kTwoPi;
            if (a < std::abs(s.sweep)) {
                along = a;
                nearest = xy(arcPart(s, 0.0, a).end);
            }
        }
        const double d = (contact - nearest).norm();
        if (d < nearestDistance) at = {i, along}, nearestDistance = d, lineSplit = fraction;
    }
    if (lineSplit > 0.0) {
        // The loop starts inside a line: its two parts become pieces of their own.
        PathSegment& s = pieces[at.piece];
        const Eigen::Vector3d p = s.start + lineSplit * (s.end - s.start);
        const PathSegment first = PathSegment::line(s.start, p);
        s = PathSegment::line(p, s.end);
        pieces.insert(pieces.begin() + static_cast<std::ptrdiff_t>(at.piece), first);
        ++at.piece;
    }
    return movesOf(startingAt(pieces, at));
}

/// The program text and the position it has printed last.
class Program {
public:
    void line(const std::string& text) {
        m_text += text;
        m_text += '\n';
    }
    /// A comment line; the text loses what would end or break a comment.
    void comment(const std::string& text) {
        m_text += '(';
        for (const char c : text) {
            m_text += c == '(' ? '[' : c == ')' ? ']' : c;
        }
        m_text += ")\n";
    }
    void rapidZ(double z) {
        m_text += "G0 Z";
        appendFixed(m_text, z, kDecimals);
        m_text += '\n';
    }
    void rapidXY(const Vec2& p) {
        m_at = {printed(p.x()), printed(p.y())};
        m_text += "G0 X";
        appendFixed(m_text, m_at.x(), kDecimals);
        m_text += " Y";
        appendFixed(m_text, m_at.y(), kDecimals);
        m_text += '\n';
    }
    void feedZ(double z, double feed) {
        m_text += "G1 Z";
        appendFixed(m_text, z, kDecimals);
        appendFeed(feed);
        m_text += '\n';
    }
    /// A cutting move from the last printed point; `feed` is written when it changes.
    void move(const Move& m, double feed) {
        const Vec2 end(printed(m.end.x()), printed(m.end.y()));
        if (end == m_at) return;  // shorter than the printed resolution
        const double sagitta = m.radius * (1.0 - std::cos(m.sweep / 2.0));
        if (!m.arc || !(sagitta > kStraightSagittaMm)) {
            m_text += "G1";
        } else {
            m_text += m.sweep > 0 ? "G3" : "G2";
        }
        m_text += " X";
        appendFixed(m_text, end.x(), kDecimals);
        m_text += " Y";
        appendFixed(m_text, end.y(), kDecimals);
        if (m.arc && sagitta > kStraightSagittaMm) {
            // Incremental centre from the printed start: the printed radii at both ends agree to
            // the rounding of the end point and of I/J (about 1e-6 mm).
            m_text += " I";
            appendFixed(m_text, printed(m.center.x() - m_at.x()), kDecimals);
            m_text += " J";
            appendFixed(m_text, printed(m.center.y() - m_at.y()), kDecimals);
        }
        appendFeed(feed);
        m_text += '\n';
        m_at = end;
    }
    [[nodiscard]] std::string take() { return std::move(m_text); }

private:
    void appendFeed(double feed) {
        if (feed == m_feed) return;
        m_feed = feed;
        m_text += " F";
        appendFixed(m_text, feed, 3);
    }

    std::string m_text;
    Vec2 m_at{0, 0};
    double m_feed = -1.0;
};

std::string fixed(double value, int decimals = kDecimals) {
    std::string text;
    appendFixed(text, value, decimals);
    return text;
}

/// The project's name for a comment: printable ASCII (another character becomes '?'), at most
/// 80 characters.
std::string commentSafe(const std::string& name) {
    std::string out;
    for (std::size_t i = 0; i < name.size() && out.size() < 80; ++i) {
        const auto c = static_cast<unsigned char>(name[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else if (c < 0x80 || c >= 0xc0) {  // one '?' per UTF-8 character, not per byte
            out += '?';
        }
    }
    return out;
}

/// `what` is a term of the diagnostic catalogue ("the depth").
void checkLength(double value, Field field, const char* what, Diagnostics& errors) {
    if (!(value > 0.0 && value <= kMaxLengthMm)) {
        errors.push_back(Diagnostic::make(FieldPlace{field}, DiagnosticCode::GcodeLengthOutOfRange,
                                          {std::string(what), kMaxLengthMm, value}));
    }
}

/// The place on a closed path nearest to `target`.
PathPlace nearestPlace(const std::vector<PathSegment>& pieces, const Vec2& target) {
    PathPlace best;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const PathSegment& s = pieces[i];
        if (s.kind == PathSegment::Kind::Line) {
            // A loop starts on a line only at its start (startingAt splits arcs alone): a
            // target across the groove from a line's start is that start.
            const double d = (xy(s.start) - target).norm();
            if (d < nearest) best = {i, 0.0}, nearest = d;
            continue;
        }
        const Vec2 w = target - s.center;
        double along = std::remainder(s.sweep >= 0 ? std::atan2(w.y(), w.x()) - s.startAngle
                                                   : s.startAngle - std::atan2(w.y(), w.x()),
                                      kTwoPi);
        if (along < 0) along += kTwoPi;
        along = std::min(along, std::abs(s.sweep));
        const double sign = s.sweep >= 0 ? 1.0 : -1.0;
        const Vec2 p = s.center + s.radius * Vec2(std::cos(s.startAngle + sign * along),
                                                  std::sin(s.startAngle + sign * along));
        const double d = (p - target).norm();
        if (d < nearest) best = {i, along}, nearest = d;
    }
    return best;
}

/// One closed tool-centre loop of a groove: the contour offset by `offset`, in the travel order
/// of `direction`, starting nearest to `near`.
struct GrooveLoop {
    std::string what;
    std::vector<Move> moves;
    Vec2 start{0, 0};
};

Result<GrooveLoop> grooveLoop(const Contour& contour, double offset, MillingDirection direction,
                              double tolerance, const std::optional<Vec2>& near, std::string what) {
    auto path = offsetContour(contour, offset, tolerance);
    if (!path.ok()) return path.errors();
    const std::vector<PathSegment> pieces = inTravelOrder(path.value().path.segments, direction);
    const PathPlace at = near ? nearestPlace(pieces, *near) : farthestPoint(pieces);
    const std::vector<PathSegment> loop = startingAt(pieces, at);
    return GrooveLoop{std::move(what), movesOf(loop), xy(loop.front().start)};
}

/// The groove's program (GcodeOptions::groove): per depth a plunge on the centre line, the
/// centre loop, and with a narrower tool a move sideways onto each flank's loop and back.
Result<std::string> grooveProgram(const Contour& contour, const GcodeOptions& options,
                                  long long passes) {
    const GrooveSize& g = *options.groove;
    const double width = g.width(), half = width / 2.0, rho = options.toolRadiusMm;
    Diagnostics errors;
    if (options.compensation) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::CompensationOption},
                                          DiagnosticCode::GrooveNoCompensation));
    }
    // A tool of half the width to rounding cuts the slot in one pass.
    const bool slot = std::abs(rho - half) <= 1e-9 * std::max(1.0, half);
    if (!slot && rho > half) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::ToolRadiusOption},
                                          DiagnosticCode::GrooveToolTooWide, {rho, half}));
    } else if (!slot && rho < width / 6.0) {
        // The centre pass clears [ρ + c/2 − r, ρ + c/2 + r] from the inner flank, the flank
        // passes [0, 2r] and [w − 2r, w]: they meet when 3r ≥ w/2.
        errors.push_back(Diagnostic::make(FieldPlace{Field::ToolRadiusOption},
                                          DiagnosticCode::GrooveToolTooNarrow, {rho, width / 6.0}));
    }
    if (!errors.empty()) return errors;

    // The centre line starts farthest from the rotation centre: there its normal is radial, and
    // the flanks' loops start across the groove on the same normal.
    auto centre = grooveLoop(contour, half, MillingDirection::Climb, options.toleranceMm,
                             std::nullopt, "the groove's centre line");
    if (!centre.ok()) return centre.errors();
    std::vector<GrooveLoop> loops{std::move(centre).value()};
    if (!slot) {
        const Vec2 start = loops.front().start, out = start.normalized();
        auto inner = grooveLoop(contour, rho, MillingDirection::Climb, options.toleranceMm,
                                Vec2(start - (half - rho) * out),
                                "finishing the inner flank, climbing: clockwise");
        if (!inner.ok()) return inner.errors();
        auto outer = grooveLoop(contour, width - rho, MillingDirection::Conventional,
                                options.toleranceMm, Vec2(start + (half - rho) * out),
                                "finishing the outer flank, climbing: counter-clockwise");
        if (!outer.ok()) return outer.errors();
        loops.push_back(std::move(inner).value());
        loops.push_back(std::move(outer).value());
    }

    const double feed = options.feedMmMin, plungeFeed = options.feedMmMin / 2.0;
    Program program;
    program.line("%");
    program.comment("Camwright G-code: " + commentSafe(options.projectName));
    program.comment("origin: X0 Y0 the cam's rotation centre, Z0 the top of the stock; mm");
    program.comment("the groove of a grooved cam: inner flank the contour, outer flank " +
                    fixed(width) + " mm beyond it (roller " + fixed(g.rollerRadiusMm) +
                    " mm, clearance " + fixed(g.clearanceMm) + " mm)");
    if (slot) {
        program.comment("one slot pass on the groove's centre line (the contour offset by " +
                        fixed(half) + " mm) with a tool of radius " + fixed(rho) + " mm");
    } else {
        program.comment("tool radius " + fixed(rho) + " mm: roughing on the centre line (offset " +
                        fixed(half) + " mm), then finishing the inner flank (offset " + fixed(rho) +
                        " mm) and the outer flank (offset " + fixed(width - rho) + " mm)");
    }
    program.comment(
        "every pass plunges on the centre line, inside the groove; spindle clockwise "
        "M3; start the spindle before running");
    program.comment("splines as arcs within " + fixed(options.toleranceMm) + " mm");
    program.comment("depth " + fixed(options.depthMm) + " mm in " + std::to_string(passes) +
                    (passes == 1 ? " pass" : " passes") + "; safe Z " + fixed(options.safeZMm) +
                    " mm");
    program.comment("feed " + fixed(feed, 3) + " mm/min, plunge " + fixed(plungeFeed, 3) +
                    " mm/min");
    program.line("G21 G90 G91.1 G17 G94 G40");
    program.rapidZ(options.safeZMm);
    const Vec2 plungeAt = loops.front().start;
    for (long long k = 1; k <= passes; ++k) {
        const double depth =
            k == passes ? options.depthMm : static_cast<double>(k) * *options.stepDownMm;
        program.comment("pass " + std::to_string(k) + " of " + std::to_string(passes) + ": Z" +
                        fixed(-depth));
        program.rapidXY(plungeAt);
        program.feedZ(-depth, plungeFeed);
        for (const GrooveLoop& loop : loops) {
            program.comment(loop.what);
            program.move({false, loop.start}, feed);
            for (const Move& m : loop.moves) program.move(m, feed);
        }
        program.move({false, plungeAt}, feed);
        program.rapidZ(options.safeZMm);
    }
    program.line("M30");
    program.line("%");
    return program.take();
}

}  // namespace

Result<std::string> gcodeProgram(const Contour& contour, const GcodeOptions& options) {
    Diagnostics errors;
    checkToolRadius(options.toolRadiusMm, errors);
    checkTolerance(options.toleranceMm, errors);
    checkLength(options.depthMm, Field::DepthOption, CAM_TRANSLATE_NOOP("Diagnostic", "the depth"),
                errors);
    checkLength(options.safeZMm, Field::GcodeSafeZ,
                CAM_TRANSLATE_NOOP("Diagnostic", "the safe height"), errors);
    if (!(options.feedMmMin > 0.0 && options.feedMmMin <= kMaxSpeedMmS * 60.0)) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::GcodeFeed},
                                          DiagnosticCode::GcodeFeedOutOfRange,
                                          {kMaxSpeedMmS * 60.0, options.feedMmMin}));
    }
    if (!(options.toolNumber >= 1 && options.toolNumber <= 99999)) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::GcodeToolNumber},
                                          DiagnosticCode::GcodeToolNumber,
                                          {static_cast<double>(options.toolNumber)}));
    }
    long long passes = 1;
    if (options.stepDownMm) {
        checkLength(*options.stepDownMm, Field::StepDownOption,
                    CAM_TRANSLATE_NOOP("Diagnostic", "the step-down"), errors);
        const double count = std::ceil(options.depthMm / *options.stepDownMm - 1e-9);
        if (errors.empty() && count > static_cast<double>(kMaxGcodePasses)) {
            errors.push_back(Diagnostic::make(FieldPlace{Field::StepDownOption},
                                              DiagnosticCode::GcodeTooManyPasses,
                                              {*options.stepDownMm, count, options.depthMm,
                                               static_cast<double>(kMaxGcodePasses)}));
        }
        if (errors.empty()) passes = std::max(1LL, static_cast<long long>(count));
    }
    if (!errors.empty()) return errors;
    if (options.groove) return grooveProgram(contour, options, passes);

    const double rho = options.toolRadiusMm;
    // The tool-centre path; it also refuses a tool too wide for a concave arc or corner, which
    // cutter compensation could not mill either.
    auto centre = offsetContour(contour, rho, options.toleranceMm);
    if (!centre.ok()) return centre.errors();
    const bool climb = options.direction == MillingDirection::Climb;
    const std::vector<PathSegment> centrePieces =
        inTravelOrder(centre.value().path.segments, options.direction);
    // Farthest from the rotation centre, the path's tangent line has the whole part (and the tool
    // on its path) on one side: the lead arcs on the other side touch nothing.
    const std::vector<PathSegment> centreLoop =
        startingAt(centrePieces, farthestPoint(centrePieces));
    const Vec2 entry = xy(centreLoop.front().start);
    const Vec2 tIn = xy(centreLoop.front().tangent(0.0));
    const Vec2 tOut = xy(centreLoop.back().tangent(centreLoop.back().length()));
    // The side of the tool away from the part: left of travel when climbing, else right.
    auto outward = [&](const Vec2& t) { return climb ? perp(t) : Vec2(-perp(t)); };
    const Vec2 nIn = outward(tIn), nOut = outward(tOut);
    const double leadSign = climb ? 1.0 : -1.0;  // the lead arcs turn against the loop
    const double lead = std::max(rho, kMinLeadRadiusMm);
    const Vec2 inCentre = entry + lead * nIn, outCentre = entry + lead * nOut;

    // The loop the program follows, and its lead arcs' radius: the tool-centre path, or the part
    // contour (the same loop offset by -rho) under compensation.
    std::vector<Move> loop;
    double leadRadius = lead;
    if (!options.compensation) {
        loop = movesOf(centreLoop);
    } else {
        auto contourLoop = compensatedLoop(contour, centre.value(), options.toleranceMm,
                                           entry - rho * nIn, options.direction);
        if (!contourLoop.ok()) return contourLoop.errors();
        loop = std::move(contourLoop).value();
        leadRadius = lead + rho;
    }
    // The lead-in arc ends where the loop starts, tangent to it; the lead-out leaves from there.
    const Vec2 loopStart = inCentre - leadRadius * nIn;
    const Vec2 inStart = inCentre - leadRadius * tIn;
    const Vec2 outEnd = outCentre + leadRadius * tOut;
    const Move leadIn{true, loopStart, inCentre, leadRadius, leadSign * kPi / 2.0};
    const Move leadOut{true, outEnd, outCentre, leadRadius, leadSign * kPi / 2.0};
    // Under compensation a straight move out from the lead arcs switches it on and off.
    const double approach = lead + rho;
    const Vec2 plungeAt = options.compensation ? Vec2(inStart + approach * nIn) : inStart;
    const Vec2 retreatTo = outEnd + approach * nOut;

    const double feed = options.feedMmMin, plungeFeed = options.feedMmMin / 2.0;
    const std::string side = climb ? "G41" : "G42";
    Program program;
    program.line("%");
    program.comment("Camwright G-code: " + commentSafe(options.projectName));
    program.comment("origin: X0 Y0 the cam's rotation centre, Z0 the top of the stock; mm");
    if (options.compensation) {
        program.comment("the part contour with cutter compensation " + side + " D" +
                        std::to_string(options.toolNumber) + ": the radius of tool " +
                        std::to_string(options.toolNumber) +
                        " in the tool table is used; leads planned for a tool radius of " +
                        fixed(rho) + " mm");
    } else {
        program.comment("the tool-centre path: the profile offset outwards by the tool radius " +
                        fixed(rho) + " mm");
    }
    program.comment(std::string(climb ? "climb milling: clockwise round the part"
                                      : "conventional milling: counter-clockwise round the part") +
                    ", spindle clockwise M3; start the spindle before running");
    program.comment("splines as arcs within " + fixed(options.toleranceMm) + " mm");
    program.comment("depth " + fixed(options.depthMm) + " mm in " + std::to_string(passes) +
                    (passes == 1 ? " pass" : " passes") + "; safe Z " + fixed(options.safeZMm) +
                    " mm");
    program.comment("feed " + fixed(feed, 3) + " mm/min, plunge " + fixed(plungeFeed, 3) +
                    " mm/min");
    program.line("G21 G90 G91.1 G17 G94 G40");
    program.rapidZ(options.safeZMm);
    for (long long k = 1; k <= passes; ++k) {
        const double depth =
            k == passes ? options.depthMm : static_cast<double>(k) * *options.stepDownMm;
        program.comment("pass " + std::to_string(k) + " of " + std::to_string(passes) + ": Z" +
                        fixed(-depth));
        program.rapidXY(plungeAt);
        program.feedZ(-depth, plungeFeed);
        if (options.compensation) {
            program.line(side + " D" + std::to_string(options.toolNumber));
            program.move({false, inStart}, feed);
        }
        program.move(leadIn, feed);
        for (const Move& m : loop) program.move(m, feed);
        program.move(leadOut, feed);
        if (options.compensation) {
            program.line("G40");
            program.move({false, retreatTo}, feed);
        }
        program.rapidZ(options.safeZMm);
    }
    program.line("M30");
    program.line("%");
    return program.take();
}

}  // namespace cam
