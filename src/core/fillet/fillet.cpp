#include "fillet/fillet.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "analysis/analysis.h"
#include "common/angles.h"
#include "common/translate_marker.h"
#include "geometry/arc.h"
#include "geometry/line.h"
#include "geometry/planar.h"
#include "project/validate.h"

namespace cam {
namespace {

using Vec = Eigen::Vector2d;

/// As phi grows the ray's far intersection ("outer") moves counter-clockwise about the circle's
/// centre and the near one clockwise, so the branch is the direction of travel.

/// Unit tangent in the direction of travel (growing phi) at a point of the segment.
Vec travelDirection(const SegmentSpec& s, const Vec& p) {
    if (const auto* line = s.as<Line>()) return (line->to - line->from).normalized();
    const Arc& arc = *s.as<Arc>();
    return (arc.sense() * perp(p - arc.center)).normalized();
}

/// Joint K, seen along the direction of travel: `a` ends there, `b` starts there.
struct Corner {
    std::size_t left = 0, right = 0;
    SegmentSpec a, b;
    double phiJoint = 0.0;  ///< deg, the end of a's window; b's window is shifted by `shift`
    double shift = 0.0;     ///< 360 at the wrap-around joint K = 0, else 0
    double widthA = 0.0, widthB = 0.0;
    Vec joint{0.0, 0.0};
    double turn = 0.0;  ///< signed turn of the tangent at the joint, rad, in (-π, π)
    double side = 1.0;  ///< +1: fillet centre left of travel (left turn), -1: right
};

/// Why a radius does not fit.
enum class Failure { None, NoCircle, LeavesLeft, LeavesRight, RayTwice, TooLarge };

/// One fillet circle tangent to both neighbours, and what is wrong with it (if anything).
struct Candidate {
    Vec center{0.0, 0.0}, t1{0.0, 0.0}, t2{0.0, 0.0};
    double d1 = 0.0;  ///< deg from tangent point 1 forward to the joint
    double d2 = 0.0;  ///< deg from the joint forward to tangent point 2
    Failure failure = Failure::NoCircle;
};

/// Locus of fillet centres next to one neighbour: the line shifted by rho towards the fillet
/// side, or the concentric circle whose signed radius R - side·sense·rho is negative when the
/// fillet circle encloses the neighbour's circle.
struct Offset {
    bool isLine = true;
    Vec point{0.0, 0.0}, dir{1.0, 0.0};  // line
    Vec center{0.0, 0.0};                // circle
    double signedRadius = 0.0;
};

Offset offsetOf(const SegmentSpec& s, double side, double rho) {
    Offset o;
    if (const auto* arc = s.as<Arc>()) {
        o.isLine = false;
        o.center = arc->center;
        o.signedRadius = arc->radius - side * arc->sense() * rho;
    } else {
        const Line& line = *s.as<Line>();
        o.dir = (line.to - line.from).normalized();
        o.point = line.from + side * rho * perp(o.dir);
    }
    return o;
}

/// Where the fillet circle about o touches the neighbour whose offset curve o lies on.
Vec tangentPoint(const SegmentSpec& s, const Offset& off, const Vec& o, double side, double rho) {
    if (off.isLine) return o - side * rho * perp(off.dir);
    const Arc& arc = *s.as<Arc>();
    return arc.center + (o - arc.center) * (arc.radius / off.signedRadius);
}

std::vector<Vec> intersect(const Offset& p, const Offset& q) {
    if (p.isLine && q.isLine) {
        const double den = cross(p.dir, q.dir);
        if (std::abs(den) < 1e-15) return {};
        return {p.point + p.dir * (cross(q.point - p.point, q.dir) / den)};
    }
    if (p.isLine != q.isLine) {
        const Offset& line = p.isLine ? p : q;
        const Offset& circle = p.isLine ? q : p;
        const Vec w = line.point - circle.center;
        const double b = line.dir.dot(w);
        const double disc = b * b - (w.squaredNorm() - circle.signedRadius * circle.signedRadius);
        if (disc < 0.0) return {};
        const double s = std::sqrt(disc);
        return {line.point + (-b + s) * line.dir, line.point + (-b - s) * line.dir};
    }
    const double r1 = std::abs(p.signedRadius), r2 = std::abs(q.signedRadius);
    const Vec d = q.center - p.center;
    const double dist = d.norm();
    if (dist < 1e-15) return {};
    const Vec e = d / dist;
    const double a = (dist * dist + r1 * r1 - r2 * r2) / (2.0 * dist);
    const double h2 = r1 * r1 - a * a;
    if (h2 < 0.0) return {};
    const double h = std::sqrt(h2);
    const Vec base = p.center + a * e;
    return {base + h * perp(e), base - h * perp(e)};
}

/// Is p where the ray at phi meets the segment (and not on the circle's other branch)?
bool onSegment(const SegmentSpec& s, double phiDeg, const Vec& p) {
    return (pointOnSegment(s, phiDeg) - p).norm() <= 0.1 * kJointToleranceMm;
}

Candidate check(const Corner& k, const Offset& offA, const Offset& offB, const Vec& o, double rho) {
    Candidate c;
    c.center = o;
    c.t1 = tangentPoint(k.a, offA, o, k.side, rho);
    c.t2 = tangentPoint(k.b, offB, o, k.side, rho);
    c.d1 = mod360(k.phiJoint - polarDeg(c.t1));
    c.d2 = mod360(polarDeg(c.t2) - k.phiJoint);
    if (!(c.d1 > 0.0 && c.d1 < k.widthA) || !onSegment(k.a, k.phiJoint - c.d1, c.t1)) {
        c.failure = Failure::LeavesLeft;
        return c;
    }
    if (!(c.d2 > 0.0 && c.d2 < k.widthB) || !onSegment(k.b, k.phiJoint + c.d2 - k.shift, c.t2)) {
        c.failure = Failure::LeavesRight;
        return c;
    }
    // With both tangent points on their segments and the ray meeting the arc once, the arc
    // replaces the piece T1 .. joint .. T2 by a polar graph over the same window: a valid
    // rounding of this corner. (An outer arc fails here only when it would pass the rotation
    // centre, cutting it off; an inner one cannot fail on a continuous family of radii.)
    const double sweep = sweepRad(c.t1 - o, c.t2 - o, k.side);
    c.failure = arcSweepOnBranch(o, rho, c.t1, sweep, k.side) ? Failure::None : Failure::RayTwice;
    return c;
}

/// The fillet of radius rho: the valid candidate nearest the joint, or else the nearest
/// candidate with the reason it fails.
Candidate solve(const Corner& k, double rho) {
    if (!(rho < kMaxLengthMm)) return Candidate{.failure = Failure::TooLarge};
    const Offset offA = offsetOf(k.a, k.side, rho);
    const Offset offB = offsetOf(k.b, k.side, rho);
    std::optional<Candidate> bestValid, bestAny;
    double validDist = 0.0, anyDist = 0.0;
    for (const Vec& o : intersect(offA, offB)) {
        const Candidate c = check(k, offA, offB, o, rho);
        const double dist = (c.t1 - k.joint).norm() + (c.t2 - k.joint).norm();
        if (!bestAny || dist < anyDist) bestAny = c, anyDist = dist;
        if (c.failure == Failure::None && (!bestValid || dist < validDist)) {
            bestValid = c, validDist = dist;
        }
    }
    if (bestValid) return *bestValid;
    if (bestAny) return *bestAny;
    return Candidate{.failure = Failure::NoCircle};
}

/// Why rho fails, as a reason for a message to list; `atBound` for the radius just beyond the
/// largest that fits.
Diagnostic filletFailure(const Corner& k, Failure f, bool atBound) {
    auto make = [](DiagnosticCode code, std::vector<DiagnosticArg> args = {}) {
        return Diagnostic::make({}, code, std::move(args));
    };
    switch (f) {
        case Failure::LeavesLeft:
            return make(DiagnosticCode::FilletLeavesSegment, {static_cast<double>(k.left)});
        case Failure::LeavesRight:
            return make(DiagnosticCode::FilletLeavesSegment, {static_cast<double>(k.right)});
        case Failure::NoCircle:
            return make(atBound ? DiagnosticCode::FilletNoLargerCircle
                                : DiagnosticCode::FilletNoCircle);
        case Failure::RayTwice:
            return make(DiagnosticCode::FilletRayNotOnce);
        case Failure::TooLarge:
        case Failure::None:
            break;
    }
    return make(DiagnosticCode::FilletRadiusLimit);
}

/// A problem of the corner k, located at its joint.
Diagnostic atCorner(const Corner& k, DiagnosticCode code, std::vector<DiagnosticArg> args = {}) {
    return Diagnostic::make(JointPlace{k.left, k.right}, code, std::move(args));
}

Result<Corner> makeCorner(const std::vector<SegmentSpec>& contour, std::size_t joint) {
    const std::size_t n = contour.size();
    if (auto problem = jointIndexProblem(n, joint, CAM_TRANSLATE_NOOP("Diagnostic", "a fillet"))) {
        return Diagnostics{*problem};
    }
    Corner k;
    k.left = (joint + n - 1) % n;
    k.right = joint;
    // Everything below relies on contiguous windows and closed joints.
    Project project;
    project.contour = contour;
    Diagnostics problems;
    for (Diagnostic& d : validateProject(project)) {
        if (d.severity == Severity::Error) problems.push_back(std::move(d));
    }
    if (!problems.empty()) {
        problems.insert(problems.begin(), atCorner(k, DiagnosticCode::FilletContourInvalid));
        return problems;
    }
    k.a = contour[k.left];
    k.b = contour[k.right];
    for (std::size_t i : {k.left, k.right}) {
        if (isSpline(contour[i].type())) {
            return Diagnostics{
                atCorner(k, DiagnosticCode::FilletNeedsArcsAndLines, {static_cast<double>(i)})};
        }
    }
    k.phiJoint = k.a.phiEndDeg;
    k.shift = joint == 0 ? 360.0 : 0.0;
    k.widthA = k.a.phiEndDeg - k.a.phiStartDeg;
    k.widthB = k.b.phiEndDeg - k.b.phiStartDeg;
    k.joint = pointOnSegment(k.a, k.phiJoint);
    const Vec tA = travelDirection(k.a, k.joint);
    const Vec tB = travelDirection(k.b, pointOnSegment(k.b, k.b.phiStartDeg));
    k.turn = std::atan2(cross(tA, tB), tA.dot(tB));
    k.side = k.turn > 0.0 ? 1.0 : -1.0;
    const double turnDeg = radToDeg(std::abs(k.turn));
    if (turnDeg <= kTangentToleranceDeg) {
        return Diagnostics{
            atCorner(k, DiagnosticCode::FilletAlreadyTangent, {turnDeg, kTangentToleranceDeg})};
    }
    return k;
}

struct Bound {
    double maxRadius = 0.0;  ///< 0 when no radius fits
    Failure why = Failure::None;
};

/// Scan rho upwards from (nearly) the smallest radius a project holds in small geometric steps
/// and bisect the first failure.
Bound largestRadius(const Corner& k) {
    auto fits = [&](double rho) { return solve(k, rho).failure == Failure::None; };
    // Start where the tangent points sit ~1e-9 of the joint's size from it (for two lines they
    // are rho·tan(|turn|/2) away): far above rounding, far below any real bound. But never below
    // kMinLengthMm: feasible radii need not form one interval, and a scan from below it could
    // stop at a gap under it and report a range that ends before it begins.
    const double scale = std::max(k.joint.norm(), 1e-300);
    const double start = 1e-9 * scale / std::tan(0.5 * std::min(std::abs(k.turn), 3.0));
    const double first = std::max(start, kMinLengthMm);
    double lo = 0.0;
    for (double s : {first, std::max(start * 1e-3, kMinLengthMm), kMinLengthMm}) {
        if (fits(s)) {
            lo = s;
            break;
        }
    }
    if (lo == 0.0) return {0.0, solve(k, first).failure};
    constexpr double kStep = 1.02;  // fine enough that a narrow infeasible gap is not skipped
    double hi = lo * kStep;
    while (fits(hi)) {
        lo = hi;
        hi *= kStep;
    }
    while (hi - lo > 1e-13 * hi) {
        const double mid = 0.5 * (lo + hi);
        (fits(mid) ? lo : hi) = mid;
    }
    return {lo, solve(k, hi).failure};
}

/// No range of radii from kMinLengthMm up fits (the scan found none, or only kMinLengthMm
/// itself, which leaves the range [min, max) empty).
bool nothingFits(const Bound& bound) { return bound.maxRadius <= kMinLengthMm; }

/// Why no radius fits, for the message that says so.
Diagnostic nothingFitsReason(const Corner& k, const Bound& bound) {
    return filletFailure(k, bound.why, bound.maxRadius > 0.0);
}

FilletResult build(const Corner& k, const std::vector<SegmentSpec>& contour, std::size_t joint,
                   const Candidate& c, double rho) {
    std::vector<SegmentSpec> out = contour;
    SegmentSpec& a = out[k.left];
    SegmentSpec& b = out[k.right];
    // Lines keep their window tied to their end points; the untouched boundaries stay bit-equal
    // to their neighbours' so the chain stays contiguous.
    if (auto* line = a.as<Line>()) {
        line->to = c.t1;
        const auto [start, end] = lineWindowDeg(a, a.phiStartDeg);
        a.phiEndDeg = a.phiStartDeg + (end - start);
    } else {
        a.phiEndDeg = k.phiJoint - c.d1;
    }
    if (auto* line = b.as<Line>()) {
        line->from = c.t2;
        b.phiStartDeg = lineWindowDeg(b, b.phiStartDeg).first;
    } else {
        b.phiStartDeg = k.phiJoint + c.d2 - k.shift;
    }
    SegmentSpec arc{Arc{c.center, rho, k.side > 0.0 ? Branch::Outer : Branch::Inner}};
    arc.phiStartDeg = a.phiEndDeg;
    arc.phiEndDeg = b.phiStartDeg + k.shift;
    // At K = 0 the arc goes last: its window ends a turn after the first one starts.
    out.insert(joint == 0 ? out.end() : out.begin() + static_cast<std::ptrdiff_t>(joint), arc);
    return {std::move(out), c.center, rho, c.t1, c.t2};
}

}  // namespace

double minimumSwitchRadius(double speed, double accel, double admissibleError) {
    if (!(accel > 0.0) || !(admissibleError > 0.0)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return speed * speed / (admissibleError * accel);
}

Result<FilletRange> filletRange(const std::vector<SegmentSpec>& contour, std::size_t joint) {
    auto corner = makeCorner(contour, joint);
    if (!corner.ok()) return corner.errors();
    const Corner& k = corner.value();
    const Bound bound = largestRadius(k);
    if (nothingFits(bound)) {
        return Diagnostics{atCorner(k, DiagnosticCode::FilletNothingFits, {kMinLengthMm})
                               .because({nothingFitsReason(k, bound)})};
    }
    return FilletRange{kMinLengthMm, bound.maxRadius};
}

Result<FilletResult> filletJoint(const std::vector<SegmentSpec>& contour, std::size_t joint,
                                 double rho) {
    auto corner = makeCorner(contour, joint);
    if (!corner.ok()) {
        Diagnostics errors = corner.errors();
        // Name the radius too, so the message answers "why not this one?".
        if (errors.size() == 1) {
            Diagnostic& d = errors.front();
            std::vector<DiagnosticArg> args{rho};
            args.insert(args.end(), d.args.begin(), d.args.end());
            if (d.code == DiagnosticCode::FilletNeedsArcsAndLines) {
                d = Diagnostic::make(d.place, DiagnosticCode::FilletRadiusNeedsArcsAndLines, args);
            } else if (d.code == DiagnosticCode::FilletAlreadyTangent) {
                d = Diagnostic::make(d.place, DiagnosticCode::FilletRadiusAlreadyTangent, args);
            }
        }
        return errors;
    }
    const Corner& k = corner.value();
    if (std::isfinite(rho) && rho > 0.0 && rho < kMinLengthMm) {
        return Diagnostics{atCorner(k, DiagnosticCode::FilletRadiusTooSmall, {rho, kMinLengthMm})};
    }
    const Candidate c = std::isfinite(rho) && rho > 0.0 ? solve(k, rho) : Candidate{};
    if (c.failure == Failure::None) {
        FilletResult result = build(k, contour, joint, c, rho);
        Project project;
        project.contour = result.contour;
        const Diagnostics problems = validateProject(project);
        // A safety net: every check above should prevent this. It nests the validator's
        // problem, which keeps its own code as the reason.
        if (hasErrors(problems)) {
            return Diagnostics{atCorner(k, DiagnosticCode::FilletRadiusInvalidContour, {rho})
                                   .because({problems.front()})};
        }
        return result;
    }
    const Bound bound = largestRadius(k);
    if (nothingFits(bound)) {
        return Diagnostics{atCorner(k, DiagnosticCode::FilletRadiusNothingFits, {rho, kMinLengthMm})
                               .because({nothingFitsReason(k, bound)})};
    }
    if (!(rho > 0.0) || !std::isfinite(rho)) {
        return Diagnostics{
            atCorner(k, DiagnosticCode::FilletRadiusNotPositive, {rho, bound.maxRadius})};
    }
    if (rho >= bound.maxRadius) {
        return Diagnostics{atCorner(k, DiagnosticCode::FilletRadiusTooLarge, {rho, bound.maxRadius})
                               .because({filletFailure(k, bound.why, true)})};
    }
    // Feasible radii need not form one interval; this one lies in a gap below the bound.
    return Diagnostics{atCorner(k, DiagnosticCode::FilletRadiusInGap, {rho, bound.maxRadius})
                           .because({filletFailure(k, c.failure, false)})};
}

}  // namespace cam
