#include "project/validate.h"

#include <cmath>

#include "common/angles.h"
#include "geometry/planar.h"
#include "project/dynamics.h"
#include "project/follower_kind.h"

namespace cam {
namespace {

using Code = DiagnosticCode;

/// The x (0) or y (1) coordinate of the point at `where`: a segment's point or a field's.
Place pointCoordinate(const Place& where, int i) {
    if (const auto* segment = std::get_if<SegmentPlace>(&where)) {
        SegmentPlace p = *segment;
        p.axis = i;
        return p;
    }
    FieldPlace field = std::get<FieldPlace>(where);
    field.index = i;
    return field;
}

class Validator {
public:
    Validator(const Project& project, ValidationOptions options)
        : m_project(project), m_options(options) {}

    Diagnostics run() {
        checkMotion();
        checkContour();
        checkFollower();
        checkSampling();
        checkMachining();
        checkDynamics();
        return std::move(m_out);
    }

private:
    void error(const Place& where, DiagnosticCode code, std::vector<DiagnosticArg> args = {}) {
        m_out.push_back(Diagnostic::make(where, code, std::move(args)));
    }

    /// Finite with |value| <= 1e6 mm; returns false (and reports) otherwise.
    bool checkLength(const Place& where, double value) {
        std::optional<Diagnostic> problem = lengthProblem(where, value);
        if (!problem) return true;
        m_out.push_back(std::move(*problem));
        return false;
    }

    bool checkPoint(const Place& where, const Eigen::Vector2d& p) {
        const bool x = checkLength(pointCoordinate(where, 0), p.x());
        const bool y = checkLength(pointCoordinate(where, 1), p.y());
        return x && y;
    }

    /// Finite and within [lo, hi]; returns false (and reports) otherwise.
    bool checkRange(const Place& where, double value, double lo, double hi, const char* unit) {
        if (!std::isfinite(value)) {
            error(where, Code::NotFinite, {value});
            return false;
        }
        if (!(value >= lo && value <= hi)) {
            error(where, Code::OutOfRange, {lo, hi, std::string(unit), value});
            return false;
        }
        return true;
    }

    /// A radius or step: > 0 (as project-format.md words it), and then at least kMinLengthMm.
    bool checkPositiveLength(const Place& where, double value) {
        if (!checkPositive(where, value, true)) return false;
        if (value < kMinLengthMm) {
            error(where, Code::BelowMinimumLength, {kMinLengthMm, value});
            return false;
        }
        return true;
    }

    bool checkPositive(const Place& where, double value, bool isLength) {
        if (isLength && !checkLength(where, value)) return false;
        if (!std::isfinite(value)) {
            error(where, Code::NotFinite, {value});
            return false;
        }
        if (!(value > 0.0)) {
            error(where, Code::NotPositive, {value});
            return false;
        }
        return true;
    }

    void checkMotion() {
        const MotionSpec& m = m_project.motion;
        const FieldPlace key{m.unit == SpeedUnit::OmegaRadS ? Field::MotionOmega
                             : m.unit == SpeedUnit::Rpm     ? Field::MotionRpm
                                                            : Field::MotionPeriod};
        if (!std::isfinite(m.value)) {
            error(key, Code::NotFinite, {m.value});
        } else if (m.unit == SpeedUnit::PeriodS && !(m.value > 0.0)) {
            error(key, Code::NotPositive, {m.value});
        } else if (m.value == 0.0) {
            error(key, Code::SpeedIsZero);
        } else {
            const ValueRange range = speedRange(m.unit);
            const double lo = range.lo;
            const double hi = range.hi;
            const char* unit = m.unit == SpeedUnit::OmegaRadS ? " rad/s"
                               : m.unit == SpeedUnit::Rpm     ? " rpm"
                                                              : " s";
            if (!(std::abs(m.value) >= lo && std::abs(m.value) <= hi)) {
                error(key, Code::SpeedOutOfRange, {lo, hi, std::string(unit), m.value});
            }
        }
    }

    void checkContour() {
        const auto& segments = m_project.contour;
        if (segments.empty()) {
            // A design whose contour was never synthesised is valid (project-format.md).
            if (!m_project.design) error(FieldPlace{Field::Contour}, Code::NoSegments);
            return;
        }
        bool allShapesValid = true;
        bool windowsValid = true;
        for (std::size_t k = 0; k < segments.size(); ++k) {
            const bool window = checkWindow(k);
            windowsValid = windowsValid && window;
            const bool shape = checkShape(k, window) && (!window || checkFiniteEnds(k));
            allShapesValid = shape && allShapesValid;
        }
        if (!windowsValid) return;
        const bool chainValid = checkContiguity();
        if (allShapesValid && chainValid && m_options.checkJoints) checkJoints();
    }

    bool checkWindow(std::size_t k) {
        const SegmentSpec& s = m_project.contour[k];
        bool ok = true;
        for (auto [part, value] : {std::pair{SegmentPart::PhiStart, s.phiStartDeg},
                                   std::pair{SegmentPart::PhiEnd, s.phiEndDeg}}) {
            if (!std::isfinite(value) || std::abs(value) > 1e6) {
                error(SegmentPlace{k, part}, Code::AngleNotFinite, {value});
                ok = false;
            }
        }
        if (ok && !(s.phiEndDeg > s.phiStartDeg)) {
            error(SegmentPlace{k, SegmentPart::PhiEnd}, Code::WindowNotIncreasing,
                  {SegmentPart::PhiStart, s.phiStartDeg, s.phiEndDeg});
            ok = false;
        }
        return ok;
    }

    /// At both ends of the window the follower ray crosses the curve at an angle of at least
    /// kMinRayAngleRad, and r and its derivatives are finite. A window that reaches the angle
    /// where the ray only grazes the curve (r' infinite, or so large that the jerk overflows) is
    /// not a contour the follower can ride. Inside the window an arc meets the ray more steeply
    /// than at one of its ends; lines and splines have their own checks.
    bool checkFiniteEnds(std::size_t k) {
        const SegmentSpec& s = m_project.contour[k];
        for (double phiDeg : {s.phiStartDeg, s.phiEndDeg}) {
            const PolarDerivatives d = polarOfSegment(s, phiDeg);
            // The angle between the ray and the curve's tangent: tan ψ = r / |r'|.
            const double angle = std::atan2(std::abs(d.r), std::abs(d.dr));
            if (std::isfinite(d.r) && std::isfinite(d.dr) && std::isfinite(d.d2r) &&
                std::isfinite(d.d3r) && angle >= kMinRayAngleRad) {
                continue;
            }
            error(SegmentPlace{k, phiDeg == s.phiStartDeg ? SegmentPart::PhiStart
                                                          : SegmentPart::PhiEnd},
                  Code::RayGrazes, {phiDeg, kMinRayAngleRad});
            return false;
        }
        return true;
    }

    /// The window of a line or spline must be the polar angles of its end points.
    bool checkWindowFollowsEnds(std::size_t k, DiagnosticCode code) {
        const SegmentSpec& s = m_project.contour[k];
        const auto [start, end] = lineWindowDeg(s, s.phiStartDeg);
        if (std::abs(wrapDeg(s.phiStartDeg - start)) > kLineWindowToleranceDeg ||
            std::abs(wrapDeg(s.phiEndDeg - end)) > kLineWindowToleranceDeg ||
            std::abs((s.phiEndDeg - s.phiStartDeg) - (end - start)) > kLineWindowToleranceDeg) {
            error(SegmentPlace{k}, code, {s.phiStartDeg, s.phiEndDeg, start, end});
            return false;
        }
        return true;
    }

    bool checkShape(std::size_t k, bool windowValid) {
        const SegmentSpec& s = m_project.contour[k];
        if (isSpline(s.type())) return checkSpline(k, windowValid);
        if (const auto* arc = s.as<Arc>()) {
            const bool center = checkPoint(SegmentPlace{k, SegmentPart::Center}, arc->center);
            const bool radius =
                checkPositiveLength(SegmentPlace{k, SegmentPart::Radius}, arc->radius);
            if (!(center && radius)) return false;
            return !windowValid || checkArcWindow(k, *arc);
        }
        const Line& line = *s.as<Line>();
        const bool from = checkPoint(SegmentPlace{k, SegmentPart::From}, line.from);
        const bool to = checkPoint(SegmentPlace{k, SegmentPart::To}, line.to);
        if (!(from && to)) return false;
        if ((line.to - line.from).norm() <= kJointToleranceMm) {
            error(SegmentPlace{k, SegmentPart::To}, Code::LineHasNoLength);
            return false;
        }
        if (line.distance() <= kJointToleranceMm) {
            error(SegmentPlace{k}, Code::LineThroughCentre);
            return false;
        }
        if (cross(line.from, line.to) <= 0.0) {
            const double fromDeg = radToDeg(std::atan2(line.from.y(), line.from.x()));
            const double toDeg = radToDeg(std::atan2(line.to.y(), line.to.x()));
            error(SegmentPlace{k}, Code::LineClockwise, {fromDeg, toDeg});
            return false;
        }
        return !windowValid || checkWindowFollowsEnds(k, Code::WindowDisagreesWithLineEnds);
    }

    /// Bézier and Hermite: finite points, the window on the polar angles of the end points, and
    /// the ray meeting the curve exactly once at every angle inside the window.
    bool checkSpline(std::size_t k, bool windowValid) {
        const SegmentSpec& s = m_project.contour[k];
        bool ok = true;
        if (const auto* b = s.as<CubicBezier>()) {
            for (int i = 0; i < 4; ++i) {
                ok = checkPoint(SegmentPlace{k, SegmentPart::Points, i},
                                b->p[static_cast<std::size_t>(i)]) &&
                     ok;
            }
        } else {
            const HermiteCurve& h = *s.as<HermiteCurve>();
            ok = checkPoint(SegmentPlace{k, SegmentPart::P0}, h.p0) && ok;
            ok = checkPoint(SegmentPlace{k, SegmentPart::T0}, h.t0) && ok;
            ok = checkPoint(SegmentPlace{k, SegmentPart::P3}, h.p3) && ok;
            ok = checkPoint(SegmentPlace{k, SegmentPart::T1}, h.t1) && ok;
        }
        if (!ok || !windowValid) return false;
        const auto [from, to] = endPointsOf(s);
        if (from.norm() <= kJointToleranceMm || to.norm() <= kJointToleranceMm) {
            error(SegmentPlace{k}, Code::SplineEndOnCentre);
            return false;
        }
        const auto [start, end] = lineWindowDeg(s, s.phiStartDeg);
        if (!(end > start)) {
            error(SegmentPlace{k}, Code::SplineClockwise, {start, end});
            return false;
        }
        if (!checkWindowFollowsEnds(k, Code::WindowDisagreesWithSplineEnds)) {
            return false;
        }
        const CubicBezier curve = bezierOf(s);
        constexpr int kChecks = 256;
        for (int i = 1; i < kChecks; ++i) {
            const double phiDeg = s.phiStartDeg + (s.phiEndDeg - s.phiStartDeg) * i / kChecks;
            const double phi = degToRad(phiDeg);
            const std::size_t hits = curve.rayParameters(std::cos(phi), std::sin(phi)).size();
            if (hits != 1) {
                error(SegmentPlace{k}, Code::RayMeetsSplineTimes,
                      {static_cast<double>(hits), phiDeg});
                return false;
            }
        }
        return true;
    }

    /// The ray meets the circle with r > 0 across the whole window (math.md §1).
    bool checkArcWindow(std::size_t k, const Arc& arc) {
        const SegmentSpec& s = m_project.contour[k];
        const double dist = arc.center.norm();
        const double rel = (dist - arc.radius) / arc.radius;
        if (arc.branch == Branch::Inner && rel <= 1e-12) {
            error(SegmentPlace{k, SegmentPart::Branch}, Code::InnerBranchBehindCentre);
            return false;
        }
        if (rel < -1e-12) return true;  // centre inside the circle: the outer branch is total
        // Centre outside (or on) the circle: the ray meets it within alpha of the centre's angle.
        const double alphaDeg = rel <= 1e-12 ? 90.0 : radToDeg(std::asin(arc.radius / dist));
        const double centerDeg = radToDeg(std::atan2(arc.center.y(), arc.center.x()));
        const double lo = wrapDeg(s.phiStartDeg - centerDeg);
        const double hi = lo + (s.phiEndDeg - s.phiStartDeg);
        constexpr double kTangentTolDeg = 1e-7;
        if (lo < -alphaDeg - kTangentTolDeg || hi > alphaDeg + kTangentTolDeg) {
            error(SegmentPlace{k}, Code::RayMissesArc,
                  {s.phiStartDeg, s.phiEndDeg, centerDeg - alphaDeg, centerDeg + alphaDeg});
            return false;
        }
        return true;
    }

    bool checkContiguity() {
        const auto& c = m_project.contour;
        bool ok = true;
        for (std::size_t k = 0; k + 1 < c.size(); ++k) {
            const double end = c[k].phiEndDeg;
            const double next = c[k + 1].phiStartDeg;
            const double diff = next - end;
            if (std::abs(diff) > kWindowToleranceDeg) {
                error(JointPlace{k, k + 1}, diff > 0 ? Code::WindowGap : Code::WindowOverlap,
                      {std::abs(diff), SegmentPart::PhiEnd, end, SegmentPart::PhiStart, next});
                ok = false;
            }
        }
        const double span = c.back().phiEndDeg - c.front().phiStartDeg;
        if (std::abs(span - 360.0) > kWindowToleranceDeg) {
            error(TurnPlace{c.size() - 1}, Code::WindowsNotOneTurn,
                  {span, c.front().phiStartDeg, c.back().phiEndDeg});
            ok = false;
        }
        return ok;
    }

    void checkJoints() {
        const auto& c = m_project.contour;
        for (std::size_t k = 0; k < c.size(); ++k) {
            const std::size_t next = (k + 1) % c.size();
            const double angle = c[k].phiEndDeg;
            const Eigen::Vector2d left = pointOnSegment(c[k], angle);
            const Eigen::Vector2d right = pointOnSegment(c[next], c[next].phiStartDeg);
            const double gap = (left - right).norm();
            if (!(gap <= kJointToleranceMm)) {
                error(JointPlace{k, next}, Code::JointGap, {angle, gap});
            }
        }
    }

    /// A groove (closure/groove.h): a roller's, with a clearance of 0 to 1e6 mm, and the land
    /// radii, when given, positive lengths with the inner one below the outer.
    void checkGroove(const FollowerSpec& f) {
        if (f.grooved()) {
            if (f.type != FollowerType::Roller) {
                error(FieldPlace{Field::FollowerClosure}, Code::GrooveNeedsRoller);
            }
            checkRange(FieldPlace{Field::FollowerGrooveClearance}, f.grooveClearance, 0.0,
                       kMaxLengthMm, " mm");
        }
        if (f.conjugate()) {
            if (f.type != FollowerType::Roller) {
                error(FieldPlace{Field::FollowerClosure}, Code::ConjugateNeedsRoller);
            }
            if (f.motion == FollowerMotion::Oscillating) {
                // A bell crank: a second arm on the same pivot, at an angle from the first.
                if (f.conjugateDistance != 0.0) {
                    error(FieldPlace{Field::FollowerConjugateDistance},
                          Code::DynamicsKeyForTranslating);
                }
                checkPositiveLength(FieldPlace{Field::FollowerConjugateArmLength},
                                    f.conjugateArmLength);
                checkRange(FieldPlace{Field::FollowerConjugateAngle}, f.conjugateAngleDeg, -360.0,
                           360.0, "°");
            } else {
                if (f.conjugateAngleDeg != 0.0) {
                    error(FieldPlace{Field::FollowerConjugateAngle}, Code::DynamicsKeyForArm);
                }
                if (f.conjugateArmLength != 0.0) {
                    error(FieldPlace{Field::FollowerConjugateArmLength}, Code::DynamicsKeyForArm);
                }
                checkPositiveLength(FieldPlace{Field::FollowerConjugateDistance},
                                    f.conjugateDistance);
            }
            checkPositiveLength(FieldPlace{Field::FollowerConjugateRadius}, f.conjugateRadius);
        }
        bool landsOk = true;
        if (f.innerLandRadius) {
            landsOk &=
                checkPositiveLength(FieldPlace{Field::FollowerInnerLandRadius}, *f.innerLandRadius);
        }
        if (f.outerLandRadius) {
            landsOk &=
                checkPositiveLength(FieldPlace{Field::FollowerOuterLandRadius}, *f.outerLandRadius);
        }
        if (landsOk && f.innerLandRadius && f.outerLandRadius &&
            !(*f.outerLandRadius > *f.innerLandRadius)) {
            error(FieldPlace{Field::FollowerOuterLandRadius}, Code::LandRadiiCrossed,
                  {*f.innerLandRadius, *f.outerLandRadius});
        }
    }

    void checkFollower() {
        if (!m_project.follower) return;
        const FollowerSpec& f = *m_project.follower;
        checkLength(FieldPlace{Field::FollowerOffset}, f.offset);
        bool radiusOk = true;
        const FollowerKind& kind = followerKind(f.type);
        if (kind.hasRadius)
            radiusOk = checkPositiveLength(FieldPlace{Field::FollowerRadius}, f.radius);
        if (f.maxPressureAngleDeg) {
            checkRange(FieldPlace{Field::FollowerMaxPressureAngle}, *f.maxPressureAngleDeg, 1e-6,
                       89.0, "°");
        }
        if (f.motion == FollowerMotion::Oscillating) {
            if (!kind.canSwing) error(FieldPlace{Field::FollowerType}, Code::FlatFaceOscillating);
            checkPoint(FieldPlace{Field::FollowerPivot}, f.pivot);
            checkPositiveLength(FieldPlace{Field::FollowerArmLength}, f.armLength);
        }
        checkGroove(f);
        // A roller must fit into every concave arc it rides (its pitch circle R − ρ > 0).
        if (!kind.hasRadius || !radiusOk) return;
        for (std::size_t k = 0; k < m_project.contour.size(); ++k) {
            const SegmentSpec& segment = m_project.contour[k];
            const Arc* arc = segment.as<Arc>();
            if (!arc || !(f.radius >= arc->radius)) continue;
            const PolarDerivatives d = polarOfSegment(segment, segment.phiStartDeg);
            const double phi = degToRad(segment.phiStartDeg);
            const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), n(-u.y(), u.x());
            const Eigen::Vector2d point = d.r * u, travel = d.dr * u + d.r * n;
            const Eigen::Vector2d fromCentre = point - arc->center;
            const bool concave = fromCentre.x() * travel.y() - fromCentre.y() * travel.x() < 0.0;
            if (!concave) continue;
            error(FieldPlace{Field::FollowerRadius}, Code::RollerTooLargeForArc,
                  {arc->radius, static_cast<double>(k), f.radius});
        }
    }

    void checkSampling() {
        if (!m_project.samplesPerTurn) return;
        const auto n = *m_project.samplesPerTurn;
        if (n < kMinSamplesPerTurn || n > kMaxSamplesPerTurn) {
            error(FieldPlace{Field::SamplesPerTurn}, Code::SamplesOutOfRange,
                  {static_cast<double>(n)});
        }
    }

    void checkMachining() {
        if (!m_project.machining) return;
        const MachiningSpec& m = *m_project.machining;
        auto checkAxes = [&](Field key, const std::vector<double>& values, double hi,
                             const char* unit) {
            if (values.size() < 2 || values.size() > 3) {
                error(FieldPlace{key}, Code::AxisCount, {static_cast<double>(values.size())});
            }
            for (std::size_t i = 0; i < values.size(); ++i) {
                checkRange(FieldPlace{key, static_cast<int>(i)}, values[i], kMinMachineLimit, hi,
                           unit);
            }
        };
        checkAxes(Field::MachiningAxisAccel, m.axisAccel, kMaxAccelMmS2, " mm/s²");
        if (!m.axisVmax.empty())
            checkAxes(Field::MachiningAxisVmax, m.axisVmax, kMaxSpeedMmS, " mm/s");
        checkRange(FieldPlace{Field::MachiningFeedMax}, m.feedMax, kMinMachineLimit, kMaxSpeedMmS,
                   " mm/s");
        checkRange(FieldPlace{Field::MachiningToolRadius}, m.toolRadius, 0.0, kMaxLengthMm, " mm");
        checkPositiveLength(FieldPlace{Field::MachiningStep}, m.step);
    }

    void checkDynamics() {
        if (!m_project.dynamics) return;
        const FollowerSpec follower = m_project.follower.value_or(FollowerSpec{});
        for (const DynamicsKeyInfo& info : dynamicsKeys()) {
            const std::optional<double>& v = (*m_project.dynamics)[info.key];
            if (!v) continue;
            const DynamicsPlace where{info.key};
            if (!dynamicsKeyApplies(info.key, follower)) {
                error(where, info.follower == DynamicsFollower::Swinging
                                 ? Code::DynamicsKeyForArm
                                 : Code::DynamicsKeyForTranslating);
                continue;
            }
            const std::string unit = *info.unit ? std::string(" ") + info.unit : std::string();
            switch (info.rule) {
                case DynamicsRule::Positive:
                    if (checkPositive(where, *v, false) && *v > kMaxDynamicsValue) {
                        error(where, Code::OutOfRange, {0.0, kMaxDynamicsValue, unit, *v});
                    }
                    break;
                case DynamicsRule::NonNegative:
                    checkRange(where, *v, 0.0, kMaxDynamicsValue, unit.c_str());
                    break;
                case DynamicsRule::Finite:
                    checkRange(where, *v, -kMaxDynamicsValue, kMaxDynamicsValue, unit.c_str());
                    break;
                case DynamicsRule::Poisson:
                    if (!std::isfinite(*v)) {
                        error(where, Code::NotFinite, {*v});
                    } else if (!(*v >= 0.0 && *v < 0.5)) {
                        error(where, Code::PoissonOutOfRange, {*v});
                    }
                    break;
            }
        }
    }

    const Project& m_project;
    ValidationOptions m_options;
    Diagnostics m_out;
};

}  // namespace

std::pair<double, double> lineWindowDeg(const SegmentSpec& segment, double nearDeg) {
    const auto [from, to] = endPointsOf(segment);
    double start = radToDeg(std::atan2(from.y(), from.x()));
    start = nearDeg + wrapDeg(start - nearDeg);
    const double cross = from.x() * to.y() - from.y() * to.x();
    const double dot = from.dot(to);
    const double sweep = radToDeg(std::atan2(cross, dot));
    return {start, start + sweep};
}

std::optional<Diagnostic> jointIndexProblem(std::size_t segmentCount, std::size_t joint,
                                            const char* operation) {
    if (segmentCount < 2) {
        return Diagnostic::make(FieldPlace{Field::Contour}, Code::JointNeedsTwoSegments,
                                {operation, static_cast<double>(segmentCount)});
    }
    if (joint >= segmentCount) {
        return Diagnostic::make(
            FieldPlace{Field::Contour}, Code::NoSuchJoint,
            {static_cast<double>(joint), static_cast<double>(segmentCount - 1)});
    }
    return std::nullopt;
}

std::optional<Diagnostic> lengthProblem(const Place& place, double value) {
    if (!std::isfinite(value)) return Diagnostic::make(place, Code::NotFinite, {value});
    if (std::abs(value) > kMaxLengthMm)
        return Diagnostic::make(place, Code::LengthTooLarge, {value});
    return std::nullopt;
}

Diagnostics validateProject(const Project& project, ValidationOptions options) {
    return Validator(project, options).run();
}

}  // namespace cam
