#include "closure/conjugate.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "design/synthesis.h"
#include "geometry/planar.h"

namespace cam {
ConjugatePoint conjugatePoint(const FollowerModel& first, const SecondRoller& yoke, double phi) {
    const FollowerState st = first.at(phi, 1.0);
    return conjugatePointOf(phi, {st.sPhi[0], st.sPhi[1], st.sPhi[2]}, first.spec(), yoke);
}

ConjugatePoint conjugatePointOf(double phi, const std::array<double, 3>& sPhi,
                                const FollowerSpec& first, const SecondRoller& yoke) {
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), n(-u.y(), u.x());
    ConjugatePoint out;
    Eigen::Vector2d d1, d2, leaving;
    if (first.motion == FollowerMotion::Oscillating) {
        // The pivot turns with the follower frame: Q = R(φ)·q, Q' = R(φ)·J·q, Q'' = −Q. The
        // second arm points along θ + β, θ = φ + ψ: P = Q + L₂·a(θ + β), a' = θ'·b, b' = −θ'·a.
        const Eigen::Vector2d q = first.pivot;
        const Eigen::Vector2d pivot = q.x() * u + q.y() * n, pivot1 = q.x() * n - q.y() * u;
        const double theta = phi + sPhi[0] + yoke.armAngleRad, t1 = 1.0 + sPhi[1], t2 = sPhi[2];
        const Eigen::Vector2d along(std::cos(theta), std::sin(theta)),
            across(-along.y(), along.x());
        const double L = yoke.armLengthMm;
        out.centre = pivot + L * along;
        out.behind = std::numeric_limits<double>::infinity();
        d1 = pivot1 + L * t1 * across;
        d2 = -pivot + L * (t2 * across - t1 * t1 * along);
        // The first roller leaves its plate as ψ grows with awaySign; the crank carries the
        // second towards its own then: it leaves it the other way.
        const double away = first.arm == ArmSide::Cw ? -1.0 : 1.0;
        leaving = -away * across;
    } else {
        // P = a·u + e·n with a = s − D; u' = n, n' = −u.
        const double e = first.offset;
        const double a = sPhi[0] - yoke.distanceMm, a1 = sPhi[1], a2 = sPhi[2];
        out.centre = a * u + e * n;
        out.behind = -a;
        d1 = (a1 - e) * u + a * n;
        d2 = (a2 - a) * u + (2.0 * a1 - e) * n;
        leaving = -u;
    }
    out.roundCentre = cross(out.centre, d1);
    const double speed = d1.norm();
    // The path runs counter-clockwise round the cam: its outward normal is d1 turned clockwise,
    // and the plate lies the roller's radius inwards, towards the cam centre.
    const Eigen::Vector2d outward = Eigen::Vector2d(d1.y(), -d1.x()) / speed;
    const double curvature = cross(d1, d2) / (speed * speed * speed);
    out.plate = out.centre - yoke.rollerRadiusMm * outward;
    out.spread = 1.0 - yoke.rollerRadiusMm * curvature;
    out.rhoPlate = curvature != 0.0 ? 1.0 / curvature - yoke.rollerRadiusMm
                                    : std::numeric_limits<double>::infinity();
    out.pressureAngle = std::atan2(cross(leaving, outward), leaving.dot(outward));
    out.plateTangent = out.spread * d1;
    return out;
}

Diagnostics conjugateProblems(const FollowerModel& first, const SecondRoller& yoke) {
    Diagnostics errors;
    const FollowerSpec& spec = first.spec();
    if (spec.type != FollowerType::Roller) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::FollowerClosure},
                                          DiagnosticCode::ConjugateNeedsRoller));
    }
    const bool crank = spec.motion == FollowerMotion::Oscillating;
    const Field carrier =
        crank ? Field::FollowerConjugateArmLength : Field::FollowerConjugateDistance;
    for (const auto& [value, field] :
         {std::pair{crank ? yoke.armLengthMm : yoke.distanceMm, carrier},
          std::pair{yoke.rollerRadiusMm, Field::FollowerConjugateRadius}}) {
        if (!(std::isfinite(value) && value >= kMinLengthMm && value <= kMaxLengthMm)) {
            errors.push_back(
                Diagnostic::make(FieldPlace{field}, DiagnosticCode::OutOfRange,
                                 {kMinLengthMm, kMaxLengthMm, std::string(" mm"), value}));
        }
    }
    if (!errors.empty()) return errors;
    // A yoke's second roller beyond the centre (s − D < 0, with room for its radius), a plate
    // that does not fold and runs round the centre, at every sample.
    for (int k = 0; k < kConjugateCheckSamples; ++k) {
        const double phi = kTwoPi * k / kConjugateCheckSamples;
        const ConjugatePoint p = conjugatePoint(first, yoke, phi);
        if (!(p.behind > yoke.rollerRadiusMm)) {
            return Diagnostics{Diagnostic::make(FieldPlace{Field::FollowerConjugateDistance},
                                                DiagnosticCode::ConjugateRollerNotBeyondCentre,
                                                {radToDeg(phi), p.behind})};
        }
        // The plate is a cam: its roller's centre and the plate itself run counter-clockwise
        // round the centre (a bell crank whose arm swings across it makes none).
        const auto notRound = [&] {
            return Diagnostics{
                Diagnostic::make(FieldPlace{crank ? Field::FollowerConjugateAngle
                                                  : Field::FollowerConjugateDistance},
                                 DiagnosticCode::ConjugatePlateNotRoundCentre, {radToDeg(phi)})};
        };
        if (!(p.roundCentre > 0.0)) return notRound();
        if (!(p.spread > 0.0)) {
            return Diagnostics{Diagnostic::make(FieldPlace{Field::FollowerConjugateRadius},
                                                DiagnosticCode::ConjugatePlateFolds,
                                                {yoke.rollerRadiusMm, radToDeg(phi)})};
        }
        if (!(cross(p.plate, p.plateTangent) > 0.0)) return notRound();
    }
    return errors;
}

Result<ConjugatePlate> conjugatePlate(const FollowerModel& first, const SecondRoller& yoke,
                                      double toleranceMm, int samples,
                                      const std::atomic<bool>* cancel) {
    if (Diagnostics errors = conjugateProblems(first, yoke); !errors.empty()) return errors;
    auto fit = fitArcs(
        [&](double phi) {
            const ConjugatePoint p = conjugatePoint(first, yoke, phi);
            return CurveSample{p.plate, p.plateTangent};
        },
        0.0, toleranceMm, cancel, yoke.rollerRadiusMm);
    if (!fit.ok()) return fit.errors();
    if (cancel && cancel->load()) return Diagnostics{};
    ConjugatePlate plate;
    plate.fit = std::move(fit).value();
    plate.contour = contourOfArcs(plate.fit.arcs);
    for (const FittedArc& arc : plate.fit.arcs) {
        const Eigen::Vector3d from(arc.from.x(), arc.from.y(), 0.0),
            to(arc.to.x(), arc.to.y(), 0.0);
        if (arc.straight) {
            plate.path.segments.push_back(PathSegment::line(from, to));
            continue;
        }
        const Eigen::Vector2d r = arc.from - arc.center;
        PathSegment piece =
            PathSegment::arc(arc.center, arc.radius, std::atan2(r.y(), r.x()), arc.sweep, 0.0);
        piece.start = from;  // exactly where the neighbours meet
        piece.end = to;
        plate.path.segments.push_back(piece);
    }
    for (const FittedArc& arc : plate.fit.arcs) {
        if (arc.straight) continue;
        std::optional<RadialExtreme>& tightest =
            arc.sweep > 0.0 ? plate.bends.minConvex : plate.bends.minConcave;
        if (tightest && !(arc.radius < tightest->radius)) continue;
        const double middle = wrapTwoPi((arc.t0 + arc.t1) / 2.0);
        tightest = RadialExtreme{arc.radius, conjugatePoint(first, yoke, middle).plate, middle};
    }
    plate.maxPlay = -std::numeric_limits<double>::infinity();
    plate.minPlay = std::numeric_limits<double>::infinity();
    // The play: the roller's centre, with the first roller on the first plate, against the arcs.
    for (int k = 0; k < samples; ++k) {
        const double phi = kTwoPi * k / samples;
        const ConjugatePoint point = conjugatePoint(first, yoke, phi);
        const Eigen::Vector2d& centre = point.centre;
        if (std::abs(point.pressureAngle) > std::abs(plate.maxPressureAngle)) {
            plate.maxPressureAngle = point.pressureAngle;
            plate.maxPressureAt = phi;
        }
        double distance = std::numeric_limits<double>::infinity();
        for (const FittedArc& arc : plate.fit.arcs) {
            distance = std::min(distance, distanceToArc(arc, centre));
        }
        const double play = distance - yoke.rollerRadiusMm;
        if (play > plate.maxPlay) {
            plate.maxPlay = play;
            plate.maxPlayAt = phi;
        }
        if (play < plate.minPlay) {
            plate.minPlay = play;
            plate.minPlayAt = phi;
        }
    }
    return plate;
}

Result<std::optional<ConjugatePlate>> secondPlateOf(const Project& project, const Contour& contour,
                                                    const std::atomic<bool>* cancel) {
    const std::optional<SecondRoller> yoke = SecondRoller::of(project);
    if (!yoke) return std::optional<ConjugatePlate>{};
    auto first = FollowerModel::build(contour, *project.follower);
    if (!first.ok()) return first.errors();
    auto plate = conjugatePlate(first.value(), *yoke, conjugateTolerance(project), 7200, cancel);
    if (!plate.ok()) return plate.errors();
    return std::optional<ConjugatePlate>(std::move(plate).value());
}

Result<Contour> plateContour(const ConjugatePlate& plate) {
    Project alone;
    alone.contour = plate.contour;
    return Contour::build(alone);
}

}  // namespace cam
