#include "closure/groove.h"

#include <cmath>

#include "common/angles.h"

namespace cam {

Result<GrooveFlanks> grooveFlanks(const Contour& contour, double rollerRadius, double clearance,
                                  double splineToleranceMm) {
    Diagnostics errors;
    if (!(std::isfinite(rollerRadius) && rollerRadius > 0.0)) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::FollowerRadius},
                                          DiagnosticCode::NotPositive, {rollerRadius}));
    }
    if (!(std::isfinite(clearance) && clearance >= 0.0)) {
        errors.push_back(Diagnostic::make(FieldPlace{Field::FollowerGrooveClearance},
                                          DiagnosticCode::OutOfRange,
                                          {0.0, kMaxLengthMm, std::string(" mm"), clearance}));
    }
    if (!errors.empty()) return errors;
    auto pitch = offsetContour(contour, rollerRadius, splineToleranceMm);
    if (!pitch.ok()) return pitch.errors();
    // The outer flank is the inner one offset by 2ρ + c: where that offset degenerates, the
    // pitch curve's concave stretch is tighter than ρ + c and the outer flank folds over.
    auto outer = offsetContour(contour, 2.0 * rollerRadius + clearance, splineToleranceMm);
    if (!outer.ok()) {
        for (const Diagnostic& d : outer.errors()) {
            const bool undercut = d.code == DiagnosticCode::ToolNotBelowArcRadius ||
                                  d.code == DiagnosticCode::ToolAboveCurveRadius;
            if (!undercut) {
                errors.push_back(d);
                continue;
            }
            // The arguments of both: the tool radius, then the inner flank's concave radius.
            const double radius = std::get<double>(d.args.at(1));
            errors.push_back(Diagnostic::make(d.place, DiagnosticCode::GrooveOuterFlankUndercut,
                                              {rollerRadius, clearance, radius}));
        }
        return errors;
    }
    auto inner = offsetContour(contour, 0.0, splineToleranceMm);
    if (!inner.ok()) return inner.errors();
    return GrooveFlanks{std::move(inner).value().path, std::move(pitch).value().path,
                        std::move(outer).value().path};
}

Result<std::optional<GrooveFlanks>> grooveFlanksIf(const Contour& contour,
                                                   const std::optional<GrooveSize>& size,
                                                   double splineToleranceMm) {
    if (!size) return std::optional<GrooveFlanks>{};
    auto flanks = grooveFlanks(contour, size->rollerRadiusMm, size->clearanceMm, splineToleranceMm);
    if (!flanks.ok()) return flanks.errors();
    return std::optional<GrooveFlanks>{std::move(flanks).value()};
}

namespace {

/// Whether polar angle `a` about an arc's centre lies within the arc (its start plus a sweep of
/// either sign).
bool withinSweep(const PathSegment& arc, double a) {
    const double from = arc.sweep >= 0.0 ? arc.startAngle : arc.startAngle + arc.sweep;
    return wrapTwoPi(a - from) <= std::abs(arc.sweep);
}

/// The points of `piece` where its distance from the origin can be extreme.
template <typename Visit>
void radialCandidates(const PathSegment& piece, Visit&& visit) {
    const Eigen::Vector2d a = piece.start.head<2>(), b = piece.end.head<2>();
    visit(a);
    visit(b);
    if (piece.kind == PathSegment::Kind::Line) {
        const Eigen::Vector2d d = b - a;
        const double t = d.squaredNorm() > 0.0 ? -a.dot(d) / d.squaredNorm() : 0.0;
        if (t > 0.0 && t < 1.0) visit(Eigen::Vector2d(a + t * d));
        return;
    }
    const double c = piece.center.norm();
    if (!(c > 0.0)) return;  // centred on the origin: every point is as far, the ends say it
    const Eigen::Vector2d u = piece.center / c;
    for (const Eigen::Vector2d& p : {Eigen::Vector2d(piece.center - piece.radius * u),
                                     Eigen::Vector2d(piece.center + piece.radius * u)}) {
        const Eigen::Vector2d r = p - piece.center;
        if (withinSweep(piece, std::atan2(r.y(), r.x()))) visit(p);
    }
}

template <typename Better>
RadialExtreme radialExtreme(const ToolPath& path, Better better) {
    RadialExtreme best;
    bool any = false;
    for (const PathSegment& piece : path.segments) {
        radialCandidates(piece, [&](const Eigen::Vector2d& p) {
            const double r = p.norm();
            if (any && !better(r, best.radius)) return;
            best = {r, p, wrapTwoPi(std::atan2(p.y(), p.x()))};
            any = true;
        });
    }
    return best;
}

}  // namespace

RadialExtreme nearestToCentre(const ToolPath& path) {
    return radialExtreme(path, [](double r, double best) { return r < best; });
}

RadialExtreme farthestFromCentre(const ToolPath& path) {
    return radialExtreme(path, [](double r, double best) { return r > best; });
}

PathBends pathBends(const ToolPath& path) {
    PathBends bends;
    for (const PathSegment& piece : path.segments) {
        if (piece.kind != PathSegment::Kind::Arc) continue;
        std::optional<RadialExtreme>& tightest =
            piece.sweep > 0.0 ? bends.minConvex : bends.minConcave;
        if (tightest && !(piece.radius < tightest->radius)) continue;
        const Eigen::Vector3d middle = piece.point(piece.length() / 2.0);
        tightest = RadialExtreme{piece.radius, middle.head<2>(),
                                 wrapTwoPi(std::atan2(middle.y(), middle.x()))};
    }
    return bends;
}

GrooveLands grooveLands(const GrooveFlanks& flanks, std::optional<double> innerLandRadius,
                        std::optional<double> outerLandRadius) {
    return {nearestToCentre(flanks.inner), farthestFromCentre(flanks.outer), innerLandRadius,
            outerLandRadius};
}

FollowerSpec outerFlankRoller(const FollowerSpec& grooved) {
    FollowerSpec wide = grooved;
    wide.radius = grooved.radius + grooved.grooveClearance;
    wide.closure = Closure::Spring;
    return wide;
}

FollowerState onOuterFlank(const FollowerState& wide, double rollerRadius, double clearance) {
    FollowerState out = wide;
    // wide.normal points out of the inner flank towards the centre; the outer flank lies ρ on.
    out.contact = wide.center + rollerRadius * wide.normal;
    out.normal = -wide.normal;
    out.rhoProfile = wide.rhoProfile + 2.0 * rollerRadius + clearance;
    return out;
}

}  // namespace cam
