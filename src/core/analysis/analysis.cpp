#include "analysis/analysis.h"

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include "common/angles.h"
#include "common/golden_section.h"
#include "project/validate.h"

namespace cam {

const char* continuityName(Continuity c) {
    switch (c) {
        case Continuity::None:
            return "none";
        case Continuity::C0:
            return "C0";
        case Continuity::G1:
            return "G1";
        case Continuity::C1:
            return "C1";
        case Continuity::C2:
            return "C2";
    }
    return "?";
}

const char* quantityName(Quantity q) {
    switch (q) {
        case Quantity::R:
            return "r";
        case Quantity::VR:
            return "v_r";
        case Quantity::V:
            return "v";
        case Quantity::AR:
            return "a_r";
        case Quantity::A:
            return "a";
        case Quantity::JR:
            return "j_r";
        case Quantity::J:
            return "j";
    }
    return "?";
}

double quantityValue(Quantity q, const PolarDerivatives& d, const PolarMotion& m) {
    switch (q) {
        case Quantity::R:
            return d.r;
        case Quantity::VR:
            return m.vR;
        case Quantity::V:
            return m.v;
        case Quantity::AR:
            return m.aR;
        case Quantity::A:
            return m.a;
        case Quantity::JR:
            return m.jR;
        case Quantity::J:
            return m.j;
    }
    return 0.0;
}

namespace {

/// First and second derivative of a segment's curve in its own parameter, at its start (or end)
/// and in the direction of travel: Bézier s in [0, 1]; arc angle about its centre; line 0..1.
std::pair<Eigen::Vector2d, Eigen::Vector2d> curveDerivatives(const ContourSegment& seg,
                                                             bool atStart) {
    const double phi = atStart ? seg.phiStart : seg.phiEnd;
    if (seg.type == SegmentType::Line) {
        const Eigen::Vector2d a = seg.line.from, b = seg.line.to;
        return {b - a, Eigen::Vector2d::Zero()};
    }
    if (seg.type == SegmentType::Arc) {
        const PolarDerivatives d = seg.evaluate(phi);
        const Eigen::Vector2d u(std::cos(phi), std::sin(phi)), u1(-u.y(), u.x());
        const Eigen::Vector2d radial = (d.r * u - seg.arc.center) / seg.arc.radius;
        const Eigen::Vector2d travel = d.dr * u + d.r * u1;  // direction of increasing φ
        const Eigen::Vector2d t(-radial.y(), radial.x());    // counter-clockwise about the centre
        const double sign = t.dot(travel) >= 0 ? 1.0 : -1.0;
        return {sign * seg.arc.radius * t, -seg.arc.radius * radial};
    }
    const CubicBezier b{seg.bezierKernel.p};
    const double s = atStart ? 0.0 : 1.0;
    return {b.derivative(s, 1), b.derivative(s, 2)};
}

}  // namespace

JointAnalysis analyzeJoint(const Contour& contour, std::size_t k, double omega) {
    JointAnalysis j;
    j.left = k;
    j.right = (k + 1) % contour.size();
    const ContourSegment& left = contour.segment(j.left);
    const ContourSegment& right = contour.segment(j.right);
    j.phi = left.phiEnd;
    const double c = std::cos(j.phi);
    const double s = std::sin(j.phi);
    const PolarDerivatives dl = left.evaluate(c, s);
    const PolarDerivatives dr = right.evaluate(c, s);

    const Eigen::Vector2d u(c, s);
    const Eigen::Vector2d u1(-s, c);
    j.gapMm = std::abs(dr.r - dl.r);  // both points lie on the same ray
    const Eigen::Vector2d tl = dl.dr * u + dl.r * u1;
    const Eigen::Vector2d tr = dr.dr * u + dr.r * u1;
    const double cross = tl.x() * tr.y() - tl.y() * tr.x();
    j.tangentBreakDeg = radToDeg(std::abs(std::atan2(cross, tl.dot(tr))));
    j.jumpDr = dr.dr - dl.dr;
    j.jumpD2r = dr.d2r - dl.d2r;
    j.jumpD3r = dr.d3r - dl.d3r;
    const PolarMotion ml = polarMotion(dl, omega);
    const PolarMotion mr = polarMotion(dr, omega);
    j.jumpAR = mr.aR - ml.aR;
    j.jumpJR = mr.jR - ml.jR;

    // P = r·u; dP/dφ = r'·u + r·u'; d²P/dφ² = (r'' − r)·u + 2r'·u' (u'' = −u).
    auto d1 = [&](const PolarDerivatives& d) { return Eigen::Vector2d(d.dr * u + d.r * u1); };
    auto d2 = [&](const PolarDerivatives& d) {
        return Eigen::Vector2d((d.d2r - d.r) * u + 2.0 * d.dr * u1);
    };
    j.jumpP = (dr.r - dl.r) * u;
    j.jumpD1 = d1(dr) - d1(dl);
    j.jumpD2 = d2(dr) - d2(dl);
    const double n1 = std::max({d1(dl).norm(), d1(dr).norm(), 1e-300});
    const double n2 = std::max({d2(dl).norm(), d2(dr).norm(), 1e-300});
    j.relativeD1 = j.jumpD1.norm() / n1;
    j.relativeD2 = j.jumpD2.norm() / n2;
    j.continuity = kinematicContinuity(j.gapMm, j.tangentBreakDeg, j.relativeD2);

    const auto [l1, l2] = curveDerivatives(left, false);
    const auto [r1, r2] = curveDerivatives(right, true);
    j.curveJumpD1 = r1 - l1;
    j.curveJumpD2 = r2 - l2;
    j.curveRelativeD1 = j.curveJumpD1.norm() / std::max({l1.norm(), r1.norm(), 1e-300});
    j.curveRelativeD2 = j.curveJumpD2.norm() / std::max({l2.norm(), r2.norm(), 1e-300});
    j.geometric = geometricContinuity(j.continuity, j.curveRelativeD1, j.curveRelativeD2);
    return j;
}

// Written as !(x <= tolerance): a NaN measure fails every test instead of passing all of them.
Continuity kinematicContinuity(double gapMm, double tangentBreakDeg, double relativeD2) {
    if (!(gapMm <= kJointToleranceMm)) return Continuity::None;
    if (!(tangentBreakDeg <= kTangentToleranceDeg)) return Continuity::C0;
    if (!(relativeD2 <= kCurvatureToleranceRel)) return Continuity::C1;
    return Continuity::C2;
}

Continuity geometricContinuity(Continuity kinematic, double curveRelativeD1,
                               double curveRelativeD2) {
    if (kinematic == Continuity::None || kinematic == Continuity::C0) return kinematic;
    if (!(curveRelativeD1 <= kCurvatureToleranceRel)) return Continuity::G1;
    if (!(curveRelativeD2 <= kCurvatureToleranceRel)) return Continuity::C1;
    return Continuity::C2;
}

namespace {

/// Golden-section search for the maximum of f on [lo, hi].
std::pair<double, double> goldenMax(const std::function<double(double)>& f, double lo, double hi) {
    const GoldenSection g =
        goldenSectionMin([&](double x) { return -f(x); }, lo, hi,
                         [](double a, double b, int step) {
                             return step < 80 && (b - a) > 1e-13 * (1.0 + std::abs(a));
                         });
    return -g.f1 >= -g.f2 ? std::pair{g.x1, -g.f1} : std::pair{g.x2, -g.f2};
}

/// A segment's quantities on an even grid of its closed window: evaluated once, searched for
/// every quantity and both signs (the evaluation, not the search, is what costs).
class SegmentGrid {
public:
    static constexpr int kGrid = 256;

    SegmentGrid(const ContourSegment& seg, double omega) : m_seg(seg), m_omega(omega) {
        for (int i = 0; i <= kGrid; ++i) {
            const PolarDerivatives d = seg.evaluate(phiAt(i));
            m_points[static_cast<std::size_t>(i)] = {d, polarMotion(d, omega)};
        }
    }

    /// Largest value of sign·q over the window, as (phi, value): the best grid point, then a
    /// golden-section search between its neighbours.
    [[nodiscard]] Extremum extremum(std::size_t k, Quantity q, double sign) const {
        const auto valueAt = [&](int i) {
            const auto& [d, m] = m_points[static_cast<std::size_t>(i)];
            return sign * quantityValue(q, d, m);
        };
        int best = 0;
        double bestValue = valueAt(0);
        for (int i = 1; i <= kGrid; ++i) {
            const double value = valueAt(i);
            if (value > bestValue) {
                bestValue = value;
                best = i;
            }
        }
        double bestPhi = phiAt(best);
        const auto f = [&](double phi) {
            const PolarDerivatives d = m_seg.evaluate(phi);
            return sign * quantityValue(q, d, polarMotion(d, m_omega));
        };
        const auto [phi, value] =
            goldenMax(f, phiAt(std::max(0, best - 1)), phiAt(std::min(kGrid, best + 1)));
        if (value > bestValue) {
            bestValue = value;
            bestPhi = phi;
        }
        return {sign * bestValue, bestPhi, k};
    }

private:
    [[nodiscard]] double phiAt(int i) const {
        return m_seg.phiStart + (m_seg.phiEnd - m_seg.phiStart) * i / kGrid;
    }

    const ContourSegment& m_seg;
    double m_omega;
    std::array<std::pair<PolarDerivatives, PolarMotion>, kGrid + 1> m_points;
};

}  // namespace

std::vector<JointAnalysis> analyzeJoints(const Contour& contour, double omega,
                                         const std::atomic<bool>* cancel) {
    std::vector<JointAnalysis> joints;
    if (contour.size() < 2) return joints;
    joints.reserve(contour.size());
    for (std::size_t k = 0; k < contour.size(); ++k) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return {};
        joints.push_back(analyzeJoint(contour, k, omega));
    }
    return joints;
}

namespace {

/// The searches of analyzeContour: each quantity's largest (sign +1) and smallest (−1) value.
constexpr std::size_t kSearches = 2 * kAllQuantities.size();

/// Each search's value on a coarse grid of a segment's window (every kCoarseStep-th point of
/// SegmentGrid's, the same angles to the bit) and how far above that the segment's extreme
/// could lie: a smooth quantity peaks between two grid points by about an eighth of its
/// second difference there; eight of the largest are allowed, and a rounding's worth.
struct CoarseBound {
    std::array<double, kSearches> gridBest;  ///< sign·value, the best coarse grid point
    /// The most the segment's extreme may reach, rounded up to a float: kept for every segment
    /// (56 bytes each; a million segments' doubles would fault in 112 MB).
    std::array<float, kSearches> reach;
};

constexpr int kCoarseStep = 8;
constexpr int kCoarse = SegmentGrid::kGrid / kCoarseStep;

CoarseBound coarseBound(const ContourSegment& seg, double omega) {
    std::array<std::array<double, kSearches>, kCoarse + 1> v{};
    for (int i = 0; i <= kCoarse; ++i) {
        const double phi =
            seg.phiStart + (seg.phiEnd - seg.phiStart) * (i * kCoarseStep) / SegmentGrid::kGrid;
        const PolarDerivatives d = seg.evaluate(phi);
        const PolarMotion m = polarMotion(d, omega);
        for (std::size_t q = 0; q < kAllQuantities.size(); ++q) {
            const double value = quantityValue(kAllQuantities[q], d, m);
            v[static_cast<std::size_t>(i)][2 * q] = value;
            v[static_cast<std::size_t>(i)][2 * q + 1] = -value;
        }
    }
    CoarseBound b;
    for (std::size_t s = 0; s < kSearches; ++s) {
        double best = v[0][s], curvature = 0.0;
        for (std::size_t i = 1; i <= kCoarse; ++i) {
            best = std::max(best, v[i][s]);
            if (i < kCoarse) {
                curvature = std::max(curvature, std::abs(v[i - 1][s] - 2 * v[i][s] + v[i + 1][s]));
            }
        }
        b.gridBest[s] = best;
        const double reach = best + 8.0 * curvature + 1e-12 * (1.0 + std::abs(best));
        const auto rounded = static_cast<float>(reach);
        b.reach[s] = static_cast<double>(rounded) >= reach
                         ? rounded
                         : std::nextafter(rounded, std::numeric_limits<float>::infinity());
    }
    return b;
}

}  // namespace

ContourAnalysis analyzeContour(const Contour& contour, double omega,
                               const std::atomic<bool>* cancel, ContourSearch search) {
    const auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
    ContourAnalysis result;
    result.joints = analyzeJoints(contour, omega, cancel);
    const std::size_t n = contour.size();
    // A coarse look at every segment; then the full search (SegmentGrid) only in the segments
    // whose extreme could reach the best coarse value of all: the one that holds it among them.
    std::vector<std::array<float, kSearches>> reach(n);
    std::array<double, kSearches> threshold{};
    threshold.fill(-std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < n; ++k) {
        if (k % 256 == 0 && cancelled()) return result;
        const CoarseBound bound = coarseBound(contour.segment(k), omega);
        reach[k] = bound.reach;
        for (std::size_t s = 0; s < kSearches; ++s) {
            threshold[s] = std::max(threshold[s], bound.gridBest[s]);
        }
    }
    if (search == ContourSearch::EverySegment) {
        threshold.fill(-std::numeric_limits<double>::infinity());
    }
    std::array<QuantityExtremes, kAllQuantities.size()> extremes;
    std::array<bool, kSearches> found{};
    for (std::size_t i = 0; i < kAllQuantities.size(); ++i) {
        extremes[i].quantity = kAllQuantities[i];
    }
    for (std::size_t k = 0; k < n; ++k) {
        std::unique_ptr<SegmentGrid> grid;
        for (std::size_t s = 0; s < kSearches; ++s) {
            if (static_cast<double>(reach[k][s]) < threshold[s]) continue;
            if (!grid) {
                if (cancelled()) return result;
                grid = std::make_unique<SegmentGrid>(contour.segment(k), omega);
            }
            QuantityExtremes& e = extremes[s / 2];
            if (s % 2 == 0) {
                const Extremum hi = grid->extremum(k, e.quantity, 1.0);
                if (!found[s] || hi.value > e.max.value) e.max = hi;
            } else {
                const Extremum lo = grid->extremum(k, e.quantity, -1.0);
                if (!found[s] || lo.value < e.min.value) e.min = lo;
            }
            found[s] = true;
        }
    }
    result.extremes.assign(extremes.begin(), extremes.end());
    return result;
}

std::vector<UnboundedJerk> unboundedJerk(const std::vector<JointAnalysis>& joints, double omega) {
    std::vector<UnboundedJerk> out;
    for (const JointAnalysis& j : joints) {
        if (j.continuity == Continuity::C2) continue;
        out.push_back({j.left, j.right, j.phi, omega * omega * j.jumpD2.norm()});
    }
    return out;
}

}  // namespace cam
