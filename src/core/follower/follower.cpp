#include "follower/follower.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/angles.h"
#include "common/golden_section.h"
#include "common/tolerances.h"
#include "follower/follower_candidate.h"
#include "follower/jet.h"
#include "follower/piece_geometry.h"
#include "geometry/bezier.h"
#include "project/follower_kind.h"

namespace cam {

using follower_detail::angleIntoSweep;
using follower_detail::forEachRoot;
using follower_detail::inSpanDirection;
using follower_detail::polynomial;
using follower_detail::polynomialDerivative;
using follower_detail::splinePitch;

Result<FollowerModel> FollowerModel::build(const Contour& contour, const FollowerSpec& spec) {
    FollowerModel model;
    model.m_spec = spec;
    model.m_pivotDirection = std::atan2(-spec.pivot.y(), -spec.pivot.x());
    model.m_phiBegin = contour.phiBegin();
    const double rho = contactRadius(spec);
    const std::size_t n = contour.size();
    Diagnostics errors;
    std::vector<Eigen::Vector2d> ends(n), startTravel(n), endTravel(n);
    const double tangentTolerance = degToRad(kTangentToleranceDeg);
    for (std::size_t k = 0; k < n; ++k) {
        const ContourSegment& seg = contour.segment(k);
        const double p0 = seg.phiStart, p1 = seg.phiEnd;
        const PolarDerivatives d0 = seg.evaluate(p0), d1 = seg.evaluate(p1);
        const Eigen::Vector2d u0(std::cos(p0), std::sin(p0)), n0(-u0.y(), u0.x());
        const Eigen::Vector2d u1(std::cos(p1), std::sin(p1)), n1(-u1.y(), u1.x());
        const Eigen::Vector2d a = d0.r * u0, b = d1.r * u1;
        const Eigen::Vector2d travel = d0.dr * u0 + d0.r * n0;  // dP/dφ at the start
        ends[k] = b;
        startTravel[k] = travel;
        endTravel[k] = d1.dr * u1 + d1.r * n1;
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
                    errors.push_back(Diagnostic::make(SegmentPlace{k, SegmentPart::Radius},
                                                      DiagnosticCode::RollerNotSmallerThanArc,
                                                      {rho, R}));
                    continue;
                }
                piece.radius = piece.convex ? R + rho : R - rho;
                piece.slack += tangentTolerance;
                piece.start = std::atan2(a.y() - c.y(), a.x() - c.x());
                const double end = std::atan2(b.y() - c.y(), b.x() - c.x());
                if (p1 - p0 >= kTwoPi - 1e-12) {
                    piece.sweep = piece.convex ? kTwoPi : -kTwoPi;
                } else {
                    const double sweep =
                        angleIntoSweep(end, piece.start, piece.convex ? 1.0 : -1.0);
                    piece.sweep = piece.convex ? sweep : -sweep;
                }
                piece.from = Eigen::Vector2d(std::cos(piece.start), std::sin(piece.start));
                piece.to = Eigen::Vector2d(std::cos(piece.start + piece.sweep),
                                           std::sin(piece.start + piece.sweep));
                break;
            }
            case SegmentType::Line: {
                const Eigen::Vector2d dir = (b - a).normalized();
                piece.kind = Piece::Kind::Line;
                piece.m = Eigen::Vector2d(dir.y(), -dir.x());  // right of the travel: outside
                piece.q0 = a + rho * piece.m;
                piece.q1 = b + rho * piece.m;
                piece.slack += rho * tangentTolerance / (b - a).norm();
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
                piece.slack = 1e-6;  // τ: about 1e-5 mm on a 10 mm spline
                break;
            }
        }
        model.m_pieces.push_back(piece);
    }
    if (!errors.empty()) return errors;
    // Corners: a roller rolls round each convex corner on a circle of its radius; a flat face
    // may rest on one. A joint tangent within kTangentToleranceDeg is no corner (its circle
    // would only touch the pitch curve, and win a tie at one angle with the wrong curvature);
    // the neighbours' slack closes the gap its small break leaves. A concave corner's circle
    // lies inside the pitch curve.
    for (std::size_t k = 0; k < n; ++k) {
        if (spec.type == FollowerType::Knife) break;
        const Eigen::Vector2d in = endTravel[k].normalized();
        const Eigen::Vector2d out = startTravel[(k + 1) % n].normalized();
        if (std::atan2(cross(in, out), in.dot(out)) <= tangentTolerance) continue;
        Piece corner;
        corner.segment = k;
        corner.center = ends[k];
        if (spec.type == FollowerType::Roller) {
            corner.kind = Piece::Kind::Circle;
            corner.radius = rho;
            corner.sweep = kTwoPi;
        } else {
            corner.kind = Piece::Kind::Vertex;
            corner.start = std::atan2(-in.x(), in.y());  // the tangent turned clockwise
            corner.sweep = std::atan2(cross(in, out), in.dot(out));
        }
        model.m_pieces.push_back(corner);
    }
    model.buildIndex();
    if (model.oscillating()) {
        Diagnostics pivotErrors = model.checkPivot(contour);
        if (!pivotErrors.empty()) return pivotErrors;
    }

    // The smallest s: every local minimum of a fine sampling, refined by golden sections.
    constexpr int kSamples = 2048;
    const double h = kTwoPi / kSamples;
    std::vector<double> s(kSamples);
    for (int i = 0; i < kSamples; ++i) s[i] = model.rankAt(model.m_phiBegin + i * h);
    // An arm that finds no contact at a sample cannot ride the cam (a line always finds one).
    for (int i = 0; i < kSamples && model.oscillating(); ++i) {
        if (!(s[i] > -std::numeric_limits<double>::infinity())) {
            return model.armUnreachable(contour, model.m_phiBegin + i * h);
        }
    }
    double minimum = std::numeric_limits<double>::infinity();
    for (int i = 0; i < kSamples; ++i) {
        const double prev = s[(i + kSamples - 1) % kSamples], next = s[(i + 1) % kSamples];
        if (s[i] > prev || s[i] > next) continue;
        const GoldenSection g = goldenSectionMin(
            [&model](double phi) { return model.rankAt(phi); }, model.m_phiBegin + (i - 1) * h,
            model.m_phiBegin + (i + 1) * h,
            [](double lo, double hi, int step) { return step < 80 && hi - lo > 1e-15; });
        minimum = std::min({minimum, s[i], g.f1, g.f2});
    }
    model.m_minRank = minimum;
    return model;
}

std::vector<std::pair<double, double>> FollowerModel::reach(const Piece& piece) const {
    const double whole = kTwoPi + 1.0;  // wider than a turn: every bin
    if (piece.kind == Piece::Kind::Vertex) return {{piece.start, piece.start + piece.sweep}};
    // Points along the piece (its pitch curve) or, for the flat face, its outward normals.
    constexpr int kSamples = 33;
    std::array<Eigen::Vector2d, kSamples> points, normals;
    for (int i = 0; i < kSamples; ++i) {
        const double f = static_cast<double>(i) / (kSamples - 1);
        auto& p = points[static_cast<std::size_t>(i)];
        auto& m = normals[static_cast<std::size_t>(i)];
        switch (piece.kind) {
            case Piece::Kind::Circle: {
                const double angle = piece.start + f * piece.sweep;
                m = Eigen::Vector2d(std::cos(angle), std::sin(angle));
                p = piece.center + piece.radius * m;
                if (!piece.convex) m = -m;
                break;
            }
            case Piece::Kind::Line:
                p = piece.q0 + f * (piece.q1 - piece.q0);
                m = piece.m;
                break;
            default: {
                const double t = piece.tLow + f * (piece.tHigh - piece.tLow);
                const double rho = contactRadius(m_spec);
                p = splinePitch(piece.coeff, piece.orientation * rho, t);
                const Eigen::Vector2d d =
                    (3.0 * piece.coeff[3] * t + 2.0 * piece.coeff[2]) * t + piece.coeff[1];
                m = piece.orientation * Eigen::Vector2d(d.y(), -d.x());
                break;
            }
        }
    }
    // The cam angles at which each sample is touched: up to two branches (a swinging arm meets
    // a point on either side); a sample out of reach leaves its branch.
    std::array<std::vector<double>, 2> branches;
    const double e = m_spec.offset, L = m_spec.armLength, a = m_spec.pivot.norm();
    const double pivotAngle = std::atan2(m_spec.pivot.y(), m_spec.pivot.x());
    for (int i = 0; i < kSamples; ++i) {
        const Eigen::Vector2d& p = points[static_cast<std::size_t>(i)];
        const double r = p.norm(), angle = std::atan2(p.y(), p.x());
        if (m_spec.type == FollowerType::Flat) {
            const Eigen::Vector2d& m = normals[static_cast<std::size_t>(i)];
            branches[0].push_back(std::atan2(m.y(), m.x()));
        } else if (!oscillating()) {
            if (!(r > std::abs(e) * (1.0 + 1e-9))) return {{0.0, whole}};
            branches[0].push_back(angle - std::asin(e / r));
        } else {
            // In the follower frame the point sits at angle α with |α·r − A| = L.
            const double k = (r * r + a * a - L * L) / (2.0 * r * a);
            if (!(std::abs(k) <= 1.0)) continue;
            const double spread = std::acos(k);
            branches[0].push_back(angle - (pivotAngle + spread));
            branches[1].push_back(angle - (pivotAngle - spread));
        }
    }
    std::vector<std::pair<double, double>> ranges;
    for (const auto& phis : branches) {
        if (phis.empty()) continue;
        // Unwrap, and widen by the largest step between samples (the curve between two samples
        // strays about that far at most).
        double lo = phis[0], hi = phis[0], previous = phis[0], step = 0.0;
        for (std::size_t i = 1; i < phis.size(); ++i) {
            const double next = previous + std::remainder(phis[i] - previous, kTwoPi);
            step = std::max(step, std::abs(next - previous));
            lo = std::min(lo, next);
            hi = std::max(hi, next);
            previous = next;
        }
        const double margin = step + 1e-9 + piece.slack;
        ranges.emplace_back(lo - margin, hi + margin);
    }
    if (oscillating() && branches[0].size() < kSamples) {
        // Part of the piece is out of the arm's reach: where reach ends, the branches meet, so
        // the gap between them belongs to the piece too.
        std::vector<std::pair<double, double>> joined;
        if (!ranges.empty()) {
            double lo = ranges[0].first, hi = ranges[0].second;
            for (const auto& [l, h] : ranges) {
                const double shift = std::round((lo - l) / kTwoPi) * kTwoPi;
                lo = std::min(lo, l + shift);
                hi = std::max(hi, h + shift);
            }
            joined.emplace_back(lo, hi);
        }
        return joined;
    }
    return ranges;
}

void FollowerModel::buildIndex() {
    const std::size_t bins = std::clamp<std::size_t>(2 * m_pieces.size(), 64, 1 << 16);
    m_binWidth = kTwoPi / static_cast<double>(bins);
    std::vector<std::vector<std::uint32_t>> lists(bins);
    for (std::size_t index = 0; index < m_pieces.size(); ++index) {
        for (const auto& [lo, hi] : reach(m_pieces[index])) {
            if (hi - lo >= kTwoPi) {
                for (auto& list : lists) list.push_back(static_cast<std::uint32_t>(index));
                continue;
            }
            const auto first = static_cast<long long>(std::floor((lo - m_phiBegin) / m_binWidth));
            const auto last = static_cast<long long>(std::floor((hi - m_phiBegin) / m_binWidth));
            for (long long b = first; b <= last; ++b) {
                const auto bin = static_cast<std::size_t>(
                    ((b % static_cast<long long>(bins)) + static_cast<long long>(bins)) %
                    static_cast<long long>(bins));
                auto& list = lists[bin];
                if (list.empty() || list.back() != index) {
                    list.push_back(static_cast<std::uint32_t>(index));
                }
            }
        }
    }
    m_binOffsets.assign(1, 0);
    m_binPieces.clear();
    for (const auto& list : lists) {
        m_binPieces.insert(m_binPieces.end(), list.begin(), list.end());
        m_binOffsets.push_back(static_cast<std::uint32_t>(m_binPieces.size()));
    }
}

std::span<const std::uint32_t> FollowerModel::piecesAt(double phi) const {
    if (m_binOffsets.size() < 2) return {};
    const std::size_t bins = m_binOffsets.size() - 1;
    double into = std::fmod(phi - m_phiBegin, kTwoPi);
    if (into < 0.0) into += kTwoPi;
    const std::size_t bin = std::min(bins - 1, static_cast<std::size_t>(into / m_binWidth));
    return {m_binPieces.data() + m_binOffsets[bin], m_binOffsets[bin + 1] - m_binOffsets[bin]};
}

void FollowerModel::crossings(double phi, const Eigen::Vector2d& u,
                              std::vector<Candidate>& out) const {
    const double e = m_spec.offset;
    const double rho = contactRadius(m_spec);
    const Eigen::Vector2d nn(-u.y(), u.x());
    for (const std::uint32_t index : piecesAt(phi)) {
        const Piece& piece = m_pieces[index];
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
                    if (!inSpanDirection(x, piece.from, piece.to, piece.sweep, piece.radius,
                                         piece.slack)) {
                        continue;
                    }
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
                if (lambda < -piece.slack || lambda > 1.0 + piece.slack) break;
                Candidate c;
                c.s = {{s, s1, s2 / 2.0, s3 / 6.0}};
                c.segment = piece.segment;
                c.found = true;
                out.push_back(c);
                break;
            }
            case Piece::Kind::Spline: {
                // C(τ) = p(τ) + ρ·m(τ) on the line: g(τ) = C(τ)·n − e = 0.
                const double offset = piece.orientation * rho;
                const auto pitch = [&](const Jet& t) {
                    return splinePitch(piece.coeff, offset, t);
                };
                const auto g = [&](double t) {
                    return splinePitch(piece.coeff, offset, t).dot(nn) - e;
                };
                forEachRoot(g, piece.tLow - piece.slack, piece.tHigh + piece.slack,
                            [&](double root) {
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

void FollowerModel::supports(double phi, const Eigen::Vector2d& u,
                             std::vector<Candidate>& out) const {
    const Eigen::Vector2d nn(-u.y(), u.x());
    for (const std::uint32_t index : piecesAt(phi)) {
        const Piece& piece = m_pieces[index];
        switch (piece.kind) {
            case Piece::Kind::Circle: {
                if (!piece.convex ||
                    !inSpanDirection(u, piece.from, piece.to, piece.sweep, 1.0, piece.slack)) {
                    break;
                }
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
                forEachRoot(
                    g, piece.tLow - piece.slack, piece.tHigh + piece.slack, [&](double root) {
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

double FollowerModel::rankAt(double phi) const {
    if (!oscillating()) return best(phi).rank;
    // armContacts' first piece is the one of the highest rank, and its contacts' ranks are
    // the ones armRank finds (the same intersections, without jets).
    double top = -std::numeric_limits<double>::infinity();
    for (const std::uint32_t index : piecesAt(phi)) {
        top = std::max(top, armRank(m_pieces[index], phi));
    }
    return top;
}

FollowerModel::Candidate FollowerModel::best(double phi) const {
    return best(phi, Eigen::Vector2d(std::cos(phi), std::sin(phi)));
}

FollowerModel::Candidate FollowerModel::best(double phi, const Eigen::Vector2d& u) const {
    thread_local std::vector<Candidate> candidates;
    candidates.clear();
    if (oscillating()) {
        armContacts(phi, candidates);
    } else if (m_spec.type == FollowerType::Flat) {
        supports(phi, u, candidates);
    } else {
        crossings(phi, u, candidates);
    }
    Candidate top;
    top.rank = -std::numeric_limits<double>::infinity();
    for (Candidate& c : candidates) {
        if (!oscillating()) c.rank = c.s.value();
        if (c.rank > top.rank) top = c;
    }
    return top;
}

double FollowerModel::liftOf(double q) const {
    if (!oscillating()) return q - m_minRank;
    return (awaySign() * (q - m_pivotDirection) - m_minRank) * (180.0 / kPi);
}

std::array<double, 4> FollowerModel::liftPhi(const FollowerState& state) const {
    const double sign = awaySign(), unit = oscillating() ? 180.0 / kPi : 1.0;
    return {liftOf(state.s), sign * unit * state.sPhi[1], sign * unit * state.sPhi[2],
            sign * unit * state.sPhi[3]};
}

std::array<double, 4> FollowerModel::liftMotion(double q, double v, double a, double j) const {
    const double scale = awaySign() * (oscillating() ? 180.0 / kPi : 1.0);
    return {liftOf(q), scale * v, scale * a, scale * j};
}

FollowerState FollowerModel::at(double phi, double omega) const {
    const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), nn(-u.y(), u.x());
    const Candidate c = best(phi, u);
    if (oscillating()) return armState(phi, omega, c);
    FollowerState st;
    st.phi = phi;
    for (int k = 0; k < 4; ++k) st.sPhi[static_cast<std::size_t>(k)] = c.s.derivative(k);
    const double s = st.sPhi[0], s1 = st.sPhi[1], s2 = st.sPhi[2];
    st.s = s;
    st.v = omega * s1;
    st.a = omega * omega * s2;
    st.j = omega * omega * omega * st.sPhi[3];
    st.segment = c.segment;
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
    const double rho = contactRadius(m_spec);
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
