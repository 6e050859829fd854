#include "follower/follower.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "follower/jet.h"
#include "geometry/bezier.h"

namespace cam {
namespace {

/// How far outside its span a crossing may fall and still count (rad, or parameter fraction):
/// joints meet at rounding distance, and an extended piece sticks out only by its square.
constexpr double kSpanSlack = 1e-9;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

/// The angle from `start` to `angle` in the direction of `sweep`, in [0, 2π).
double angleIntoSweep(double angle, double start, double sweep) {
    double d = sweep >= 0.0 ? angle - start : start - angle;
    d = std::fmod(d, kTwoPi);
    if (d < 0.0) d += kTwoPi;
    return d;
}

bool inSpan(double angle, double start, double sweep) {
    if (std::abs(sweep) >= kTwoPi) return true;
    const double d = angleIntoSweep(angle, start, sweep);
    return d <= std::abs(sweep) + kSpanSlack || d >= kTwoPi - kSpanSlack;
}

/// p(τ) of a cubic in power basis, with a jet τ.
JetVec polynomial(const std::array<Eigen::Vector2d, 4>& k, const Jet& t) {
    Jet x = Jet::constant(k[3].x()), y = Jet::constant(k[3].y());
    for (int i = 2; i >= 0; --i) {
        x = x * t + k[static_cast<std::size_t>(i)].x();
        y = y * t + k[static_cast<std::size_t>(i)].y();
    }
    return {x, y};
}

/// p'(τ) of a cubic in power basis, with a jet τ.
JetVec polynomialDerivative(const std::array<Eigen::Vector2d, 4>& k, const Jet& t) {
    const std::array<Eigen::Vector2d, 4> d{k[1], 2.0 * k[2], 3.0 * k[3], Eigen::Vector2d::Zero()};
    return polynomial(d, t);
}

/// Calls onRoot(τ) for every sign change of g over [lo, hi]: 48 intervals scanned, each change
/// bisected to the last bit.
template <class G, class OnRoot>
void forEachRoot(const G& g, double lo, double hi, const OnRoot& onRoot) {
    constexpr int kIntervals = 48;
    double t0 = lo, g0 = g(t0);
    for (int i = 1; i <= kIntervals; ++i) {
        const double t1 = lo + (hi - lo) * i / kIntervals;
        const double g1 = g(t1);
        if ((g0 <= 0.0) != (g1 <= 0.0) || g1 == 0.0) {
            double a = t0, b = t1, ga = g0;
            for (int it = 0; it < 200 && b - a > 1e-16; ++it) {
                const double mid = 0.5 * (a + b), gm = g(mid);
                if ((gm <= 0.0) == (ga <= 0.0)) {
                    a = mid;
                    ga = gm;
                } else {
                    b = mid;
                }
            }
            onRoot(0.5 * (a + b));
        }
        t0 = t1;
        g0 = g1;
    }
}

}  // namespace

struct FollowerModel::Candidate {
    Jet s;
    Eigen::Vector2d contact{0.0, 0.0};  ///< flat face: the support point
    std::size_t segment = 0;
    bool found = false;
};

Result<FollowerModel> FollowerModel::build(const Contour& contour, const FollowerSpec& spec) {
    if (spec.motion == FollowerMotion::Oscillating) {
        return Diagnostics{{"follower.motion",
                            "an oscillating follower is not computed by this version yet; "
                            "use \"translating\""}};
    }
    FollowerModel model;
    model.m_spec = spec;
    model.m_phiBegin = contour.phiBegin();
    const double rho = spec.type == FollowerType::Roller ? spec.radius : 0.0;
    const std::size_t n = contour.size();
    Diagnostics errors;
    std::vector<Eigen::Vector2d> ends(n);
    for (std::size_t k = 0; k < n; ++k) {
        const ContourSegment& seg = contour.segment(k);
        const double p0 = seg.phiStart, p1 = seg.phiEnd;
        const PolarDerivatives d0 = seg.evaluate(p0), d1 = seg.evaluate(p1);
        const Eigen::Vector2d u0(std::cos(p0), std::sin(p0)), n0(-u0.y(), u0.x());
        const Eigen::Vector2d u1(std::cos(p1), std::sin(p1));
        const Eigen::Vector2d a = d0.r * u0, b = d1.r * u1;
        const Eigen::Vector2d travel = d0.dr * u0 + d0.r * n0;  // dP/dφ at the start
        ends[k] = b;
        Piece piece;
        piece.segment = k;
        switch (seg.type) {
            case SegmentType::Arc: {
                const Eigen::Vector2d c = seg.arc.center;
                const double R = seg.arc.radius;
                piece.kind = Piece::Kind::Circle;
                piece.center = c;
                piece.convex = cross(a - c, travel) > 0.0;
                if (!piece.convex && rho >= R) {
                    errors.push_back(
                        Diagnostic::at({k, SegmentPart::Radius},
                                       "the roller radius " + std::to_string(rho) +
                                           " mm is not smaller than this concave arc's radius " +
                                           std::to_string(R) + " mm: the roller cannot follow it"));
                    continue;
                }
                piece.radius = piece.convex ? R + rho : R - rho;
                piece.start = std::atan2(a.y() - c.y(), a.x() - c.x());
                const double end = std::atan2(b.y() - c.y(), b.x() - c.x());
                if (p1 - p0 >= kTwoPi - 1e-12) {
                    piece.sweep = piece.convex ? kTwoPi : -kTwoPi;
                } else {
                    const double sweep =
                        angleIntoSweep(end, piece.start, piece.convex ? 1.0 : -1.0);
                    piece.sweep = piece.convex ? sweep : -sweep;
                }
                break;
            }
            case SegmentType::Line: {
                const Eigen::Vector2d dir = (b - a).normalized();
                piece.kind = Piece::Kind::Line;
                piece.m = Eigen::Vector2d(dir.y(), -dir.x());  // right of the travel: outside
                piece.q0 = a + rho * piece.m;
                piece.q1 = b + rho * piece.m;
                break;
            }
            default: {
                const auto& cp = seg.bezierKernel.p;
                const CubicBezier bezier{cp};
                piece.kind = Piece::Kind::Spline;
                piece.coeff = {cp[0], 3.0 * (cp[1] - cp[0]), 3.0 * (cp[2] - 2.0 * cp[1] + cp[0]),
                               cp[3] - 3.0 * cp[2] + 3.0 * cp[1] - cp[0]};
                const auto nearest = [&](double phi, double hint) {
                    const auto hits = bezier.rayParameters(std::cos(phi), std::sin(phi));
                    double best = hint;
                    double distance = std::numeric_limits<double>::infinity();
                    for (double t : hits) {
                        if (std::abs(t - hint) < distance) {
                            distance = std::abs(t - hint);
                            best = t;
                        }
                    }
                    return best;
                };
                const double ta = nearest(p0, 0.0), tb = nearest(p1, 1.0);
                piece.tLow = std::min(ta, tb);
                piece.tHigh = std::max(ta, tb);
                piece.orientation = ta <= tb ? 1.0 : -1.0;
                break;
            }
        }
        model.m_pieces.push_back(piece);
    }
    if (!errors.empty()) return errors;
    // Corners: a roller rolls round each joint on a circle of its radius; a flat face may rest
    // on a joint. (A circle round a smooth joint lies inside the pitch curve: never the
    // outermost crossing, so it changes nothing there.)
    for (std::size_t k = 0; k < n; ++k) {
        if (spec.type == FollowerType::Knife) break;
        Piece corner;
        corner.segment = k;
        corner.center = ends[k];
        if (spec.type == FollowerType::Roller) {
            corner.kind = Piece::Kind::Circle;
            corner.radius = rho;
            corner.sweep = kTwoPi;
        } else {
            corner.kind = Piece::Kind::Vertex;
        }
        model.m_pieces.push_back(corner);
    }

    // The smallest s: every local minimum of a fine sampling, refined by golden sections.
    constexpr int kSamples = 2048;
    const double h = kTwoPi / kSamples;
    std::vector<double> s(kSamples);
    for (int i = 0; i < kSamples; ++i) s[i] = model.best(model.m_phiBegin + i * h).s.value();
    double minimum = std::numeric_limits<double>::infinity();
    for (int i = 0; i < kSamples; ++i) {
        const double prev = s[(i + kSamples - 1) % kSamples], next = s[(i + 1) % kSamples];
        if (s[i] > prev || s[i] > next) continue;
        double lo = model.m_phiBegin + (i - 1) * h, hi = model.m_phiBegin + (i + 1) * h;
        constexpr double g = 0.6180339887498949;
        double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
        double f1 = model.best(x1).s.value(), f2 = model.best(x2).s.value();
        for (int it = 0; it < 80 && hi - lo > 1e-15; ++it) {
            if (f1 <= f2) {
                hi = x2;
                x2 = x1;
                f2 = f1;
                x1 = hi - g * (hi - lo);
                f1 = model.best(x1).s.value();
            } else {
                lo = x1;
                x1 = x2;
                f1 = f2;
                x2 = lo + g * (hi - lo);
                f2 = model.best(x2).s.value();
            }
        }
        minimum = std::min({minimum, s[i], f1, f2});
    }
    model.m_minS = minimum;
    return model;
}

void FollowerModel::crossings(double phi, std::vector<Candidate>& out) const {
    const double e = m_spec.offset;
    const double rho = m_spec.type == FollowerType::Roller ? m_spec.radius : 0.0;
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), nn(-u.y(), u.x());
    for (const Piece& piece : m_pieces) {
        switch (piece.kind) {
            case Piece::Kind::Circle: {
                // (s − a)² + (e − b)² = Rp², a = c·u, b = c·n; a' = b, b' = −a.
                const double a = piece.center.dot(u), b = piece.center.dot(nn);
                const double w = e - b, w1 = a, w2 = b, w3 = -a;
                const double f = piece.radius * piece.radius - w * w;
                if (f < 0.0) break;
                const double q = std::sqrt(f);
                const double f1 = -2.0 * w * w1, f2 = -2.0 * (w1 * w1 + w * w2),
                             f3 = -2.0 * (3.0 * w1 * w2 + w * w3);
                const double q1 = f1 / (2.0 * q), q2 = (f2 - 2.0 * q1 * q1) / (2.0 * q),
                             q3 = (f3 - 6.0 * q1 * q2) / (2.0 * q);
                for (double sigma : {1.0, -1.0}) {
                    const double s = a + sigma * q;
                    const Eigen::Vector2d x = e * nn + s * u - piece.center;
                    if (!inSpan(std::atan2(x.y(), x.x()), piece.start, piece.sweep)) continue;
                    Candidate c;
                    c.s = {{s, b + sigma * q1, (-a + sigma * q2) / 2.0, (-b + sigma * q3) / 6.0}};
                    c.segment = piece.segment;
                    c.found = true;
                    out.push_back(c);
                }
                break;
            }
            case Piece::Kind::Line: {
                // m·(e n + s u) = m·q0: s = N/D, N = m·q0 − e m·n, D = m·u.
                const double D = piece.m.dot(u), D1 = piece.m.dot(nn), D2 = -D, D3 = -D1;
                if (std::abs(D) < 1e-15) break;
                const double N = piece.m.dot(piece.q0) - e * D1, N1 = e * D, N2 = e * D1,
                             N3 = -e * D;
                const double s = N / D;
                const double s1 = (N1 - s * D1) / D;
                const double s2 = (N2 - 2.0 * s1 * D1 - s * D2) / D;
                const double s3 = (N3 - 3.0 * s2 * D1 - 3.0 * s1 * D2 - s * D3) / D;
                const Eigen::Vector2d x = e * nn + s * u;
                const Eigen::Vector2d d = piece.q1 - piece.q0;
                const double lambda = (x - piece.q0).dot(d) / d.squaredNorm();
                if (lambda < -kSpanSlack || lambda > 1.0 + kSpanSlack) break;
                Candidate c;
                c.s = {{s, s1, s2 / 2.0, s3 / 6.0}};
                c.segment = piece.segment;
                c.found = true;
                out.push_back(c);
                break;
            }
            case Piece::Kind::Spline: {
                // C(τ) = p(τ) + ρ·m(τ) on the line: g(τ) = C(τ)·n − e = 0.
                const auto pitch = [&](const Jet& t) {
                    const JetVec p = polynomial(piece.coeff, t);
                    if (rho == 0.0) return p;
                    const JetVec d = polynomialDerivative(piece.coeff, t);
                    const Jet len = sqrt(dot(d, d));
                    const Jet k = Jet::constant(piece.orientation * rho) / len;
                    return p + JetVec{d.y * k, -(d.x * k)};
                };
                // The scan in plain doubles: the same point as pitch(), four times cheaper.
                const auto& k = piece.coeff;
                const auto g = [&](double t) {
                    Eigen::Vector2d c = ((k[3] * t + k[2]) * t + k[1]) * t + k[0];
                    if (rho != 0.0) {
                        const Eigen::Vector2d d = (3.0 * k[3] * t + 2.0 * k[2]) * t + k[1];
                        c += (piece.orientation * rho / d.norm()) * Eigen::Vector2d(d.y(), -d.x());
                    }
                    return c.dot(nn) - e;
                };
                forEachRoot(g, piece.tLow, piece.tHigh, [&](double root) {
                    // The φ-jet of τ by Newton steps on jets: each step makes one more
                    // coefficient exact.
                    const Jet cu = cosJet(phi), su = sinJet(phi);
                    const JetVec uj{cu, su}, nj{-su, cu};
                    const JetVec ct = pitch(Jet::variable(root));
                    const double gt = ct.x.c[1] * nn.x() + ct.y.c[1] * nn.y();
                    if (gt == 0.0) return;
                    Jet t = Jet::constant(root);
                    for (int it = 0; it < 4; ++it) {
                        t = t - (dot(pitch(t), nj) - e) * (1.0 / gt);
                    }
                    Candidate c;
                    c.s = dot(pitch(t), uj);
                    c.segment = piece.segment;
                    c.found = true;
                    out.push_back(c);
                });
                break;
            }
            case Piece::Kind::Vertex:
                break;
        }
    }
}

void FollowerModel::supports(double phi, std::vector<Candidate>& out) const {
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), nn(-u.y(), u.x());
    for (const Piece& piece : m_pieces) {
        switch (piece.kind) {
            case Piece::Kind::Circle: {
                if (!piece.convex || !inSpan(phi, piece.start, piece.sweep)) break;
                // h = c·u + R, h' = c·n, h'' = −c·u, h''' = −c·n.
                const double a = piece.center.dot(u), b = piece.center.dot(nn);
                Candidate c;
                c.s = {{a + piece.radius, b, -a / 2.0, -b / 6.0}};
                c.contact = piece.center + piece.radius * u;
                c.segment = piece.segment;
                c.found = true;
                out.push_back(c);
                break;
            }
            case Piece::Kind::Vertex: {
                const double a = piece.center.dot(u), b = piece.center.dot(nn);
                Candidate c;
                c.s = {{a, b, -a / 2.0, -b / 6.0}};
                c.contact = piece.center;
                c.segment = piece.segment;
                c.found = true;
                out.push_back(c);
                break;
            }
            case Piece::Kind::Spline: {
                // Where the tangent is perpendicular to u and the outside faces u.
                const auto g = [&](double t) {
                    const JetVec d = polynomialDerivative(piece.coeff, Jet::constant(t));
                    return d.x.value() * u.x() + d.y.value() * u.y();
                };
                forEachRoot(g, piece.tLow, piece.tHigh, [&](double root) {
                    const JetVec d = polynomialDerivative(piece.coeff, Jet::variable(root));
                    const Eigen::Vector2d tangent(d.x.value(), d.y.value());
                    const Eigen::Vector2d out_(piece.orientation * tangent.y(),
                                               -piece.orientation * tangent.x());
                    if (out_.dot(u) > 0.0) {
                        const double gt = d.x.c[1] * u.x() + d.y.c[1] * u.y();
                        const Jet cu = cosJet(phi), su = sinJet(phi);
                        const JetVec uj{cu, su};
                        Jet t = Jet::constant(root);
                        for (int it = 0; it < 4; ++it) {
                            t = t - dot(polynomialDerivative(piece.coeff, t), uj) * (1.0 / gt);
                        }
                        const JetVec p = polynomial(piece.coeff, Jet::constant(root));
                        Candidate c;
                        c.s = dot(polynomial(piece.coeff, t), uj);
                        c.contact = Eigen::Vector2d(p.x.value(), p.y.value());
                        c.segment = piece.segment;
                        c.found = true;
                        out.push_back(c);
                    }
                });
                break;
            }
            case Piece::Kind::Line:
                break;
        }
    }
}

FollowerModel::Candidate FollowerModel::best(double phi) const {
    thread_local std::vector<Candidate> candidates;
    candidates.clear();
    if (m_spec.type == FollowerType::Flat) {
        supports(phi, candidates);
    } else {
        crossings(phi, candidates);
    }
    Candidate top;
    top.s = Jet::constant(-std::numeric_limits<double>::infinity());
    for (const Candidate& c : candidates) {
        if (c.s.value() > top.s.value()) top = c;
    }
    return top;
}

FollowerState FollowerModel::at(double phi, double omega) const {
    const Candidate c = best(phi);
    FollowerState st;
    st.phi = phi;
    for (int k = 0; k < 4; ++k) st.sPhi[static_cast<std::size_t>(k)] = c.s.derivative(k);
    const double s = st.sPhi[0], s1 = st.sPhi[1], s2 = st.sPhi[2];
    st.s = s;
    st.v = omega * s1;
    st.a = omega * omega * s2;
    st.j = omega * omega * omega * st.sPhi[3];
    st.segment = c.segment;
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), nn(-u.y(), u.x());
    const double e = m_spec.offset;
    st.center = e * nn + s * u;
    if (m_spec.type == FollowerType::Flat) {
        st.contact = c.contact;
        st.normal = u;
        st.pressureAngle = 0.0;
        st.rhoProfile = s + s2;  // h + h''
        st.rhoPitch = st.rhoProfile;
        return st;
    }
    // The pitch curve C(φ) = e·n + s·u in the cam frame: C' = (s' − e)·u + s·n,
    // C'' = (s'' − s)·u + (2s' − e)·n. Its outward normal is C' turned clockwise.
    const Eigen::Vector2d c1 = (s1 - e) * u + s * nn;
    const Eigen::Vector2d c2 = (s2 - s) * u + (2.0 * s1 - e) * nn;
    st.normal = Eigen::Vector2d(c1.y(), -c1.x()).normalized();
    st.pressureAngle = std::atan2(s1 - e, s);
    const double rho = m_spec.type == FollowerType::Roller ? m_spec.radius : 0.0;
    st.contact = st.center - rho * st.normal;
    const double speed = c1.norm();
    // A straight stretch (a knife or roller on a line) has no finite radius: +∞, not the
    // rounding noise of a vanishing cross product.
    const double curvature = cross(c1, c2) / (speed * speed * speed);
    if (std::abs(curvature) * std::max(std::abs(s), 1.0) <= 1e-12) {
        st.rhoPitch = st.rhoProfile = std::numeric_limits<double>::infinity();
        return st;
    }
    st.rhoPitch = 1.0 / curvature;
    st.rhoProfile = st.rhoPitch - rho;
    return st;
}

}  // namespace cam
