#include "closure/conjugate.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "design/synthesis.h"
#include "geometry/planar.h"

namespace cam {
ConjugatePoint conjugatePoint(const FollowerModel& first, const ConjugateYoke& yoke, double phi) {
    const FollowerState st = first.at(phi, 1.0);
    return conjugatePointOf(phi, {st.sPhi[0], st.sPhi[1], st.sPhi[2]}, first.spec().offset, yoke);
}

ConjugatePoint conjugatePointOf(double phi, const std::array<double, 3>& sPhi, double offset,
                                const ConjugateYoke& yoke) {
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), n(-u.y(), u.x());
    const double e = offset;
    // P = a·u + e·n with a = s − D; u' = n, n' = −u.
    const double a = sPhi[0] - yoke.distanceMm, a1 = sPhi[1], a2 = sPhi[2];
    ConjugatePoint out;
    out.centre = a * u + e * n;
    out.behind = -a;
    const Eigen::Vector2d d1 = (a1 - e) * u + a * n;
    const Eigen::Vector2d d2 = (a2 - a) * u + (2.0 * a1 - e) * n;
    const double speed = d1.norm();
    // The path runs counter-clockwise round the cam: its outward normal is d1 turned clockwise,
    // and the plate lies the roller's radius inwards, towards the cam centre.
    const Eigen::Vector2d outward = Eigen::Vector2d(d1.y(), -d1.x()) / speed;
    const double curvature = cross(d1, d2) / (speed * speed * speed);
    out.plate = out.centre - yoke.rollerRadiusMm * outward;
    out.spread = 1.0 - yoke.rollerRadiusMm * curvature;
    out.rhoPlate = curvature != 0.0 ? 1.0 / curvature - yoke.rollerRadiusMm
                                    : std::numeric_limits<double>::infinity();
    out.pressureAngle = std::atan2(cross(-u, outward), (-u).dot(outward));
    out.plateTangent = out.spread * d1;
    return out;
}

Diagnostics conjugateProblems(const FollowerModel& first, const ConjugateYoke& yoke) {
    Diagnostics errors;
    const FollowerSpec& spec = first.spec();
    if (spec.type != FollowerType::Roller || spec.motion != FollowerMotion::Translating) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::FollowerClosure},
                                          DiagnosticCode::ConjugateNeedsTranslatingRoller));
    }
    for (const auto& [value, field] :
         {std::pair{yoke.distanceMm, Field::FollowerConjugateDistance},
          std::pair{yoke.rollerRadiusMm, Field::FollowerConjugateRadius}}) {
        if (!(std::isfinite(value) && value >= kMinLengthMm && value <= kMaxLengthMm)) {
            errors.push_back(
                Diagnostic::make(FieldPlace{field}, DiagnosticCode::OutOfRange,
                                 {kMinLengthMm, kMaxLengthMm, std::string(" mm"), value}));
        }
    }
    if (!errors.empty()) return errors;
    // The second roller beyond the centre (s − D < 0, with room for its radius) and a plate
    // that does not fold, at every sample.
    for (int k = 0; k < kConjugateCheckSamples; ++k) {
        const double phi = kTwoPi * k / kConjugateCheckSamples;
        const ConjugatePoint p = conjugatePoint(first, yoke, phi);
        if (!(p.behind > yoke.rollerRadiusMm)) {
            return Diagnostics{Diagnostic::make(FieldPlace{Field::FollowerConjugateDistance},
                                                DiagnosticCode::ConjugateRollerNotBeyondCentre,
                                                {radToDeg(phi), p.behind})};
        }
        if (!(p.spread > 0.0)) {
            return Diagnostics{Diagnostic::make(FieldPlace{Field::FollowerConjugateRadius},
                                                DiagnosticCode::ConjugatePlateFolds,
                                                {yoke.rollerRadiusMm, radToDeg(phi)})};
        }
    }
    return errors;
}

Result<ConjugatePlate> conjugatePlate(const FollowerModel& first, const ConjugateYoke& yoke,
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
    const std::optional<ConjugateYoke> yoke = ConjugateYoke::of(project);
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
