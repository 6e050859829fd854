/// @file
/// @brief The swinging arm (math.md §7, "oscillating"): the tip or roller centre is where the
/// circle of radius L round the turned pivot meets the pitch curve; ψ's φ-derivatives follow in
/// closed form on circles and lines (circle–circle and circle–line intersections on jets) and
/// by differentiating |C(τ) − A(φ)|² = L² on splines.

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "common/translate_marker.h"
#include "follower/follower.h"
#include "follower/follower_candidate.h"
#include "follower/jet.h"
#include "follower/piece_geometry.h"
#include "geometry/planar.h"
#include "project/follower_kind.h"

namespace cam {

using follower_detail::forEachRoot;
using follower_detail::inSpanDirection;
using follower_detail::splinePitch;

namespace {

/// θ of an arm's end at x: its angle from the line pivot → cam centre in (−π, π], growing as
/// the arm swings away from the cam (σ), and ψ = β + σθ in the follower frame.
double armTheta(const Eigen::Vector2d& x, const Eigen::Vector2d& pivot, double phi, double sigma,
                double beta) {
    const double psi = std::atan2(x.y() - pivot.y(), x.x() - pivot.x()) - phi;
    double theta = std::remainder(sigma * (psi - beta), kTwoPi);
    if (theta <= -kPi) theta += kTwoPi;
    return theta;
}

}  // namespace

double FollowerModel::armRank(const Piece& piece, double phi) const {
    // The same intersections as armContacts, in plain doubles: only to find the piece whose
    // contact comes first; its jets are made for that piece alone.
    const double L = m_spec.armLength;
    const double rho = contactRadius(m_spec);
    const double sigma = awaySign();
    const double c = std::cos(phi), s = std::sin(phi);
    const Eigen::Vector2d& A = m_spec.pivot;
    const Eigen::Vector2d pivot(c * A.x() - s * A.y(), s * A.x() + c * A.y());
    double best = -std::numeric_limits<double>::infinity();
    const auto consider = [&](const Eigen::Vector2d& x) {
        best = std::max(best, armTheta(x, pivot, phi, sigma, m_pivotDirection));
    };
    switch (piece.kind) {
        case Piece::Kind::Circle: {
            const Eigen::Vector2d d = piece.center - pivot;
            const double d2 = d.squaredNorm();
            if (!(d2 > 0.0)) break;
            const double dn = std::sqrt(d2), R = piece.radius;
            const double a = (d2 + (L * L - R * R)) / (2.0 * dn);
            const double h2 = L * L - a * a;
            if (!(h2 > 0.0)) break;
            const Eigen::Vector2d along = d * (a / dn),
                                  across = Eigen::Vector2d(-d.y(), d.x()) * (std::sqrt(h2) / dn);
            for (double side : {1.0, -1.0}) {
                const Eigen::Vector2d x = pivot + along + side * across;
                if (inSpanDirection(x - piece.center, piece.from, piece.to, piece.sweep,
                                    piece.radius, piece.slack)) {
                    consider(x);
                }
            }
            break;
        }
        case Piece::Kind::Line: {
            const Eigen::Vector2d span = piece.q1 - piece.q0;
            const double length = span.norm();
            const Eigen::Vector2d dir = span / length, w = pivot - piece.q0;
            const double foot = w.dot(dir), h2 = L * L - (w.squaredNorm() - foot * foot);
            if (!(h2 > 0.0)) break;
            for (double side : {1.0, -1.0}) {
                const double t = foot + side * std::sqrt(h2);
                const double lambda = t / length;
                if (lambda < -piece.slack || lambda > 1.0 + piece.slack) continue;
                consider(piece.q0 + t * dir);
            }
            break;
        }
        case Piece::Kind::Spline: {
            const double offset = piece.orientation * rho;
            const auto g = [&](double t) {
                return (splinePitch(piece.coeff, offset, t) - pivot).squaredNorm() - L * L;
            };
            forEachRoot(g, piece.tLow - piece.slack, piece.tHigh + piece.slack,
                        [&](double root) { consider(splinePitch(piece.coeff, offset, root)); });
            break;
        }
        case Piece::Kind::Vertex:
            break;
    }
    return best;
}

void FollowerModel::armContacts(double phi, std::vector<Candidate>& out) const {
    // The piece touched first, found in doubles; then its contacts with their jets.
    std::uint32_t first = 0;
    double firstRank = -std::numeric_limits<double>::infinity();
    for (const std::uint32_t index : piecesAt(phi)) {
        const double rank = armRank(m_pieces[index], phi);
        if (rank > firstRank) {
            firstRank = rank;
            first = index;
        }
    }
    if (!(firstRank > -std::numeric_limits<double>::infinity())) return;
    const double L = m_spec.armLength;
    const double rho = contactRadius(m_spec);
    const double sigma = awaySign();
    const Jet cu = cosJet(phi), su = sinJet(phi);
    const Eigen::Vector2d& A = m_spec.pivot;
    const JetVec pivot{cu * A.x() - su * A.y(), su * A.x() + cu * A.y()};
    const Eigen::Vector2d pivotNow(pivot.x.value(), pivot.y.value());
    const auto constant = [](const Eigen::Vector2d& p) {
        return JetVec{Jet::constant(p.x()), Jet::constant(p.y())};
    };
    // ψ = angle(X − A(φ)) − φ, its value placed so that θ = σ(ψ − β) lies in (−π, π]: the
    // arm's angle from the line pivot → cam centre, growing as the arm swings away.
    const auto add = [&](const JetVec& x, std::size_t segment) {
        Jet psi = angleOf(x - pivot) - Jet::variable(phi);
        double theta = std::remainder(sigma * (psi.c[0] - m_pivotDirection), kTwoPi);
        if (theta <= -kPi) theta += kTwoPi;
        psi.c[0] = m_pivotDirection + sigma * theta;
        Candidate c;
        c.s = psi;
        c.point = x;
        c.rank = theta;
        c.segment = segment;
        c.found = true;
        out.push_back(c);
    };
    {
        const Piece& piece = m_pieces[first];
        switch (piece.kind) {
            case Piece::Kind::Circle: {
                // Two circles: along d = c − A by a = (L² − R² + |d|²)/(2|d|), across by
                // h = √(L² − a²).
                const JetVec d = constant(piece.center) - pivot;
                const Jet d2 = dot(d, d);
                if (!(d2.value() > 0.0)) break;
                const Jet dn = sqrt(d2);
                const double R = piece.radius;
                const Jet a = (d2 + (L * L - R * R)) / (dn * 2.0);
                const Jet h2 = Jet::constant(L * L) - a * a;
                if (!(h2.value() > 0.0)) break;  // apart, or touching without crossing
                const JetVec along = d * (a / dn);
                const Jet across = sqrt(h2) / dn;
                for (double side : {1.0, -1.0}) {
                    const JetVec x = pivot + along + perp(d) * (across * side);
                    const Eigen::Vector2d w(x.x.value() - piece.center.x(),
                                            x.y.value() - piece.center.y());
                    if (inSpanDirection(w, piece.from, piece.to, piece.sweep, piece.radius,
                                        piece.slack)) {
                        add(x, piece.segment);
                    }
                }
                break;
            }
            case Piece::Kind::Line: {
                // The foot of the pivot on the line, then ±√(L² − distance²) along it.
                const Eigen::Vector2d span = piece.q1 - piece.q0;
                const double length = span.norm();
                const Eigen::Vector2d dir = span / length;
                const JetVec w = pivot - constant(piece.q0);
                const Jet foot = w.x * dir.x() + w.y * dir.y();
                const Jet h2 = Jet::constant(L * L) - (dot(w, w) - foot * foot);
                if (!(h2.value() > 0.0)) break;
                const Jet h = sqrt(h2);
                for (double side : {1.0, -1.0}) {
                    const Jet t = foot + h * side;
                    const double lambda = t.value() / length;
                    if (lambda < -piece.slack || lambda > 1.0 + piece.slack) continue;
                    add({Jet::constant(piece.q0.x()) + t * dir.x(),
                         Jet::constant(piece.q0.y()) + t * dir.y()},
                        piece.segment);
                }
                break;
            }
            case Piece::Kind::Spline: {
                // g(τ) = |C(τ) − A(φ)|² − L² = 0; the φ-jet of τ by Newton steps on jets.
                const double offset = piece.orientation * rho;
                const auto g = [&](double t) {
                    return (splinePitch(piece.coeff, offset, t) - pivotNow).squaredNorm() - L * L;
                };
                forEachRoot(
                    g, piece.tLow - piece.slack, piece.tHigh + piece.slack, [&](double root) {
                        const JetVec ct = splinePitch(piece.coeff, offset, Jet::variable(root));
                        const Eigen::Vector2d c0(ct.x.c[0], ct.y.c[0]), c1(ct.x.c[1], ct.y.c[1]);
                        const double gt = 2.0 * (c0 - pivotNow).dot(c1);
                        if (gt == 0.0) return;
                        Jet t = Jet::constant(root);
                        for (int it = 0; it < 4; ++it) {
                            const JetVec r = splinePitch(piece.coeff, offset, t) - pivot;
                            t = t - (dot(r, r) - L * L) * (1.0 / gt);
                        }
                        add(splinePitch(piece.coeff, offset, t), piece.segment);
                    });
                break;
            }
            case Piece::Kind::Vertex:
                break;
        }
    }
}

FollowerState FollowerModel::armState(double phi, double omega, const Candidate& c) const {
    FollowerState st;
    st.phi = phi;
    if (!c.found) {
        // Only between the build's samples could the arm lose the cam; say so with NaN.
        constexpr double nan = std::numeric_limits<double>::quiet_NaN();
        st.sPhi = {nan, nan, nan, nan};
        st.s = st.v = st.a = st.j = st.pressureAngle = st.rhoProfile = st.rhoPitch = nan;
        st.center = st.contact = st.normal = Eigen::Vector2d(nan, nan);
        return st;
    }
    for (int k = 0; k < 4; ++k) st.sPhi[static_cast<std::size_t>(k)] = c.s.derivative(k);
    st.s = st.sPhi[0];
    st.v = omega * st.sPhi[1];
    st.a = omega * omega * st.sPhi[2];
    st.j = omega * omega * omega * st.sPhi[3];
    st.segment = c.segment;
    // The pitch curve C(φ) is the tip's (or roller centre's) path in the cam frame.
    const Eigen::Vector2d c0(c.point.x.derivative(0), c.point.y.derivative(0));
    const Eigen::Vector2d c1(c.point.x.derivative(1), c.point.y.derivative(1));
    const Eigen::Vector2d c2(c.point.x.derivative(2), c.point.y.derivative(2));
    st.center = c0;
    st.normal = Eigen::Vector2d(c1.y(), -c1.x()).normalized();
    const double rho = contactRadius(m_spec);
    st.contact = st.center - rho * st.normal;
    // The pressure angle: between the normal and the direction the tip moves away from the cam
    // (across the arm), signed like the translating follower's: positive where the normal leans
    // toward the way the cam's surface slides past the tip (on a line: atan2(s' − e, s)).
    const double theta = phi + st.s;
    const Eigen::Vector2d along(std::cos(theta), std::sin(theta));
    const Eigen::Vector2d across(-along.y(), along.x());
    const Eigen::Vector2d away = awaySign() * across;
    const Eigen::Vector2d slide = c0.dot(across) >= 0.0 ? along : Eigen::Vector2d(-along);
    st.pressureAngle = std::atan2(st.normal.dot(slide), st.normal.dot(away));
    const double speed = c1.norm();
    const double curvature = cross(c1, c2) / (speed * speed * speed);
    if (std::abs(curvature) * std::max(c0.norm(), 1.0) <= 1e-12) {
        st.rhoPitch = st.rhoProfile = std::numeric_limits<double>::infinity();
        return st;
    }
    st.rhoPitch = 1.0 / curvature;
    st.rhoProfile = st.rhoPitch - rho;
    return st;
}

namespace {

/// The profile point on the ray at φ.
Eigen::Vector2d profileAt(const Contour& contour, double phi) {
    return fromPolar(contour.segment(contour.segmentAt(phi)).evaluate(phi).r, phi);
}

constexpr int kProfileSamples = 2048;

}  // namespace

Diagnostics FollowerModel::checkPivot(const Contour& contour) const {
    const double h = kTwoPi / kProfileSamples;
    const double pivotRadius = m_spec.pivot.norm();
    // The pivot turns on a circle of radius |A| round the cam centre: it must stay outside.
    int far = 0;
    for (int i = 1; i < kProfileSamples; ++i) {
        if (profileAt(contour, m_phiBegin + i * h).norm() >
            profileAt(contour, m_phiBegin + far * h).norm()) {
            far = i;
        }
    }
    double phiFar = m_phiBegin + far * h, rFar = profileAt(contour, phiFar).norm();
    for (int it = 0; it < 60; ++it) {  // climb to the top between the neighbouring samples
        const double step = h * std::pow(0.5, it);
        for (double candidate : {phiFar - step, phiFar + step}) {
            const double r = profileAt(contour, candidate).norm();
            if (r > rFar) {
                rFar = r;
                phiFar = candidate;
            }
        }
    }
    if (pivotRadius > rFar) return {};
    return {Diagnostic::make(FieldPlace{Field::FollowerPivot}, DiagnosticCode::PivotInsideCam,
                             {pivotRadius, rFar, radToDeg(phiFar)})};
}

Diagnostics FollowerModel::armUnreachable(const Contour& contour, double phi) const {
    const double h = kTwoPi / kProfileSamples;
    const double rho = contactRadius(m_spec);
    const double L = m_spec.armLength;
    // How near and how far the cam is from the pivot at this angle.
    const Eigen::Vector2d pivot(
        std::cos(phi) * m_spec.pivot.x() - std::sin(phi) * m_spec.pivot.y(),
        std::sin(phi) * m_spec.pivot.x() + std::cos(phi) * m_spec.pivot.y());
    double nearest = std::numeric_limits<double>::infinity(), farthest = 0.0;
    for (int k = 0; k < kProfileSamples; ++k) {
        const double distance = (profileAt(contour, m_phiBegin + k * h) - pivot).norm();
        nearest = std::min(nearest, distance);
        farthest = std::max(farthest, distance);
    }
    const std::string what = rho > 0.0 ? CAM_TRANSLATE_NOOP("Diagnostic", "the roller")
                                       : CAM_TRANSLATE_NOOP("Diagnostic", "the tip");
    const FieldPlace arm{Field::FollowerArmLength};
    if (L + rho <= nearest) {
        return {Diagnostic::make(arm, DiagnosticCode::ArmTooShort,
                                 {radToDeg(phi), nearest, what, L + rho})};
    }
    if (L - rho >= farthest) {
        return {Diagnostic::make(arm, DiagnosticCode::ArmTooLong, {radToDeg(phi), what, farthest})};
    }
    return {Diagnostic::make(arm, DiagnosticCode::ArmNoContact, {what, radToDeg(phi)})};
}

}  // namespace cam
