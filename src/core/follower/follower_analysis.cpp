#include "follower/follower_analysis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "common/angles.h"
#include "common/golden_section.h"
#include "project/follower_kind.h"

namespace cam {
namespace {

/// The extreme of f near phi (within one sample step h either side), by golden sections.
FollowerExtremum refine(const std::function<double(double)>& f, double phi, double h, bool max) {
    const double sign = max ? -1.0 : 1.0;  // minimise sign·f
    const GoldenSection g = goldenSectionMin(
        [&](double x) { return sign * f(x); }, phi - h, phi + h,
        [](double lo, double hi, int step) { return step < 90 && hi - lo > 1e-14; });
    FollowerExtremum e{f(phi), phi};
    for (const auto& [x, fx] : {std::pair{g.x1, g.f1}, std::pair{g.x2, g.f2}}) {
        if (fx < sign * e.value) e = {sign * fx, x};
    }
    return e;
}

/// The largest value of f over [from, to] (f is −∞ where it does not count): the best of the
/// samples a step h apart, refined by golden sections within a step either side.
FollowerExtremum largestInside(const std::function<double(double)>& f, double from, double to,
                               double h) {
    const int n = std::max(2, static_cast<int>(std::ceil((to - from) / h)) + 1);
    const double step = (to - from) / (n - 1);
    FollowerExtremum best{f(from), from};
    for (int i = 1; i < n; ++i) {
        const double phi = from + i * step;
        const double v = f(phi);
        if (v > best.value) best = {v, phi};
    }
    const FollowerExtremum refined = refine(f, best.phi, step, true);
    return refined.value > best.value ? refined : best;
}

/// The angle within the turn that begins at phiBegin.
double inTurn(double phi, double phiBegin) {
    return phiBegin + std::fmod(phi - phiBegin + 2 * kTwoPi, kTwoPi);
}

using Phase = MotionPhase;

/// The phase a motion design gives the cam's angle phi: Either where it gives none (no design,
/// or a segment that ends at the lift it starts with), else its segment's.
Phase designPhaseAt(double phi, const std::vector<PhaseSpan>& spans) {
    for (const PhaseSpan& span : spans) {
        if (inTurn(phi, span.from) <= span.to) return span.phase;
    }
    return Phase::Either;
}

/// The phase of each sample: the design's where it gives one; elsewhere rising or returning by
/// the sign of dq/dφ, dwelling where it is within kDwellSlope of its largest value. Without a
/// design, a rise or return that moves the follower by less than kPhaseLift of its stroke (the
/// ripple of an arc table round a dwell) is part of a dwell.
std::vector<Phase> samplePhases(const std::vector<FollowerState>& st, double dwellSlope,
                                double phiBegin, const std::vector<PhaseSpan>& spans) {
    const std::size_t n = st.size();
    const double h = kTwoPi / static_cast<double>(n);
    std::vector<Phase> phase(n);
    double qMin = std::numeric_limits<double>::infinity(), qMax = -qMin;
    for (std::size_t i = 0; i < n; ++i) {
        const double slope = st[i].sPhi[1];
        const Phase designed = designPhaseAt(phiBegin + static_cast<double>(i) * h, spans);
        phase[i] = designed != Phase::Either ? designed
                   : slope > dwellSlope      ? Phase::Rise
                   : slope < -dwellSlope     ? Phase::Fall
                                             : Phase::Dwell;
        qMin = std::min(qMin, st[i].s);
        qMax = std::max(qMax, st[i].s);
    }
    if (!spans.empty()) return phase;
    // The runs of one phase round the turn, from a sample where the phase changes.
    std::size_t start = 0;
    while (start < n && phase[start] == phase[(start + n - 1) % n]) ++start;
    if (start == n) return phase;  // one phase all round
    const double ripple = kPhaseLift * (qMax - qMin);
    for (std::size_t done = 0; done < n;) {
        const std::size_t first = (start + done) % n;
        std::size_t len = 1;
        while (len < n - done && phase[(first + len) % n] == phase[first]) ++len;
        if (phase[first] != Phase::Dwell) {
            // The lift over the run: from the sample before it to its last sample.
            const double lift = st[(first + len - 1) % n].s - st[(first + n - 1) % n].s;
            if (std::abs(lift) < ripple) {
                for (std::size_t k = 0; k < len; ++k) phase[(first + k) % n] = Phase::Dwell;
            }
        }
        done += len;
    }
    return phase;
}

/// The largest |α| in each phase: the best sample of the phase, refined within a sample step
/// either side while the phase holds (at a phase's end the refinement runs up to its border).
PressurePhases pressurePhases(const FollowerModel& model, double omega, double phiBegin,
                              const std::vector<FollowerState>& st,
                              const std::vector<PhaseSpan>& spans) {
    const int n = static_cast<int>(st.size());
    const double h = kTwoPi / n;
    double slopeMax = 0.0;
    for (const FollowerState& s : st) slopeMax = std::max(slopeMax, std::abs(s.sPhi[1]));
    const double dwellSlope = kDwellSlope * slopeMax;
    const std::vector<Phase> phase = samplePhases(st, dwellSlope, phiBegin, spans);
    const auto signOf = [&](const FollowerState& s) {
        if (s.sPhi[1] > dwellSlope) return Phase::Rise;
        if (s.sPhi[1] < -dwellSlope) return Phase::Fall;
        return Phase::Dwell;
    };
    const auto at = [&](int i) { return phase[static_cast<std::size_t>((i % n + n) % n)]; };
    // The phase at an angle between samples i and i + 1: the design's where it gives one;
    // else by its own sign where there is a design; without one, that of the neighbour whose
    // sign of dq/dφ it shares (a rise's ripple is a dwell), else a dwell (a ripple between
    // two samples).
    const auto phaseAt = [&](double phi, const FollowerState& s) {
        const Phase designed = designPhaseAt(phi, spans);
        if (designed != Phase::Either) return designed;
        const Phase sign = signOf(s);
        if (!spans.empty()) return sign;
        const int i = static_cast<int>(std::floor((phi - phiBegin) / h));
        for (const int k : {i, i + 1}) {
            if (signOf(st[static_cast<std::size_t>((k % n + n) % n)]) == sign) return at(k);
        }
        return Phase::Dwell;
    };
    std::array<int, 3> best{-1, -1, -1};
    for (int i = 0; i < n; ++i) {
        int& b = best[static_cast<std::size_t>(at(i))];
        if (b < 0 || std::abs(st[static_cast<std::size_t>(i)].pressureAngle) >
                         std::abs(st[static_cast<std::size_t>(b)].pressureAngle)) {
            b = i;
        }
    }
    PressurePhases p;
    std::array<std::optional<FollowerExtremum>*, 3> out{&p.rise, &p.fall, &p.dwell};
    bool any = false;
    for (std::size_t k = 0; k < 3; ++k) {
        if (best[k] < 0) continue;
        const auto ph = static_cast<Phase>(k);
        const auto f = [&](double phi) {
            const FollowerState s = model.at(phi, omega);
            return phaseAt(phi, s) == ph ? std::abs(s.pressureAngle)
                                         : -std::numeric_limits<double>::infinity();
        };
        const double phi0 = phiBegin + best[k] * h;
        FollowerExtremum e = refine(f, phi0, h, true);
        if (!(e.value >= f(phi0))) e = {f(phi0), phi0};
        // Reported within the turn, with the value at exactly the angle reported.
        e.phi = inTurn(e.phi, phiBegin);
        e.value = std::abs(model.at(e.phi, omega).pressureAngle);
        *out[k] = e;
        if (!any || e.value > p.max.value) p.max = e;
        any = true;
    }
    return p;
}

/// The smallest radius of each sense of the curve whose signed radius (positive where convex,
/// +∞ where straight) `rho` gives: the largest curvature 1/ρ of each sign, which is smooth
/// through an inflection where ρ is not, refined by golden sections.
CurvatureExtremes curvatureExtremes(const FollowerModel& model, double omega, double phiBegin,
                                    const std::vector<FollowerState>& st,
                                    double FollowerState::*rho) {
    const int n = static_cast<int>(st.size());
    const double h = kTwoPi / n;
    const auto kappa = [&](const FollowerState& s) { return 1.0 / (s.*rho); };
    CurvatureExtremes c;
    for (const double sign : {1.0, -1.0}) {
        int best = -1;
        for (int i = 0; i < n; ++i) {
            const double k = sign * kappa(st[static_cast<std::size_t>(i)]);
            if (k > 0.0 && (best < 0 || k > sign * kappa(st[static_cast<std::size_t>(best)]))) {
                best = i;
            }
        }
        if (best < 0) continue;
        const auto f = [&](double phi) { return sign * kappa(model.at(phi, omega)); };
        const double phi0 = phiBegin + best * h;
        FollowerExtremum e = refine(f, phi0, h, true);
        if (!(e.value >= f(phi0))) e = {f(phi0), phi0};
        e.phi = inTurn(e.phi, phiBegin);
        e.value = std::abs(model.at(e.phi, omega).*rho);
        (sign > 0.0 ? c.minConvex : c.minConcave) = e;
    }
    return c;
}

}  // namespace

std::vector<PhaseSpan> designPhases(const DesignSpec& design) {
    std::vector<PhaseSpan> spans;
    double from = 0.0, lift = design.segments.empty() ? 0.0 : design.segments.back().lift;
    for (const DesignSegmentSpec& segment : design.segments) {
        if (segment.toDeg > from) {
            const Phase phase = segment.law == MotionLawType::Dwell ? Phase::Dwell
                                : segment.lift > lift               ? Phase::Rise
                                : segment.lift < lift               ? Phase::Fall
                                                                    : Phase::Either;
            spans.push_back({degToRad(from), degToRad(segment.toDeg), phase});
        }
        from = segment.toDeg;
        lift = segment.lift;
    }
    return spans;
}

FollowerAnalysis analyzeFollower(const FollowerModel& model, double omega, double phiBegin,
                                 int samples, const std::atomic<bool>* cancel,
                                 const std::vector<PhaseSpan>& phases) {
    const int n = std::max(samples, 64);
    const double h = kTwoPi / n;
    std::vector<FollowerState> st(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        if (cancel && i % 256 == 0 && cancel->load(std::memory_order_relaxed)) return {};
        st[static_cast<std::size_t>(i)] = model.at(phiBegin + i * h, omega);
    }
    const auto at = [&](int i) -> const FollowerState& {
        return st[static_cast<std::size_t>(((i % n) + n) % n)];
    };
    const auto extreme = [&](const std::function<double(const FollowerState&)>& q, bool max) {
        int best = 0;
        for (int i = 1; i < n; ++i) {
            if (max ? q(at(i)) > q(at(best)) : q(at(i)) < q(at(best))) best = i;
        }
        const auto f = [&](double phi) { return q(model.at(phi, omega)); };
        FollowerExtremum e = refine(f, phiBegin + best * h, h, max);
        // Reported within the turn, with the value at exactly the angle reported.
        e.phi = inTurn(e.phi, phiBegin);
        e.value = f(e.phi);
        return e;
    };
    FollowerAnalysis a;
    a.sMin = extreme([](const FollowerState& s) { return s.s; }, false);
    a.sMax = extreme([](const FollowerState& s) { return s.s; }, true);
    a.vMin = extreme([](const FollowerState& s) { return s.v; }, false);
    a.vMax = extreme([](const FollowerState& s) { return s.v; }, true);
    a.aMin = extreme([](const FollowerState& s) { return s.a; }, false);
    a.aMax = extreme([](const FollowerState& s) { return s.a; }, true);
    a.jMin = extreme([](const FollowerState& s) { return s.j; }, false);
    a.jMax = extreme([](const FollowerState& s) { return s.j; }, true);
    a.pressure = pressurePhases(model, omega, phiBegin, st, phases);
    a.profileCurvature = curvatureExtremes(model, omega, phiBegin, st, &FollowerState::rhoProfile);
    a.pitchCurvature = curvatureExtremes(model, omega, phiBegin, st, &FollowerState::rhoPitch);
    if (followerKind(model.spec().type).flatFace) {
        const double lo = extreme([](const FollowerState& s) { return s.sPhi[1]; }, false).value;
        const double hi = extreme([](const FollowerState& s) { return s.sPhi[1]; }, true).value;
        a.faceWidth = hi - lo;
    }

    // Where |α| crosses the limit: bisection between samples on either side.
    a.limitRad = degToRad(model.spec().maxPressureAngleOrDefault());
    const auto over = [&](double phi) {
        return std::abs(model.at(phi, omega).pressureAngle) > a.limitRad;
    };
    const auto crossing = [&](double lo, double hi) {
        const bool startOver = over(lo);
        for (int it = 0; it < 60; ++it) {
            const double mid = 0.5 * (lo + hi);
            if (over(mid) == startOver) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return 0.5 * (lo + hi);
    };
    std::vector<double> ups, downs;
    for (int i = 0; i < n; ++i) {
        const bool here = std::abs(at(i).pressureAngle) > a.limitRad;
        const bool next = std::abs(at(i + 1).pressureAngle) > a.limitRad;
        if (here == next) continue;
        const double x = crossing(phiBegin + i * h, phiBegin + (i + 1) * h);
        (next ? ups : downs).push_back(x);
    }
    if (!ups.empty()) {
        // Pair each start with the next end round the turn.
        for (double from : ups) {
            double to = from + kTwoPi;
            for (double d : downs) {
                double dd = d;
                while (dd < from) dd += kTwoPi;
                to = std::min(to, dd);
            }
            a.pressureExceeded.push_back({from, to, {}});
        }
    } else if (std::abs(at(0).pressureAngle) > a.limitRad) {
        a.pressureExceeded.push_back({phiBegin, phiBegin + kTwoPi, {}});
    }
    for (AngleRange& r : a.pressureExceeded) {
        r.peak = largestInside(
            [&](double phi) {
                return phi >= r.from && phi <= r.to ? std::abs(model.at(phi, omega).pressureAngle)
                                                    : -std::numeric_limits<double>::infinity();
            },
            r.from, r.to, h);
        r.peak.phi = inTurn(r.peak.phi, phiBegin);
    }

    // Jumps of the contact point: a gap that does not shrink when the step is halved.
    double scale = 0.0;
    for (const FollowerState& s : st) scale = std::max(scale, s.contact.norm());
    const auto step = [&](int i) { return (at(i + 1).contact - at(i).contact).norm(); };
    for (int i = 0; i < n; ++i) {
        // A jump stands out from the steps either side of it (the contact point may run fast
        // round a small concave arc, but evenly); only those are bisected.
        const double gap = step(i);
        if (gap < 1e-3 * scale + 1e-12 || gap < 4.0 * std::max(step(i - 1), step(i + 1))) {
            continue;
        }
        double lo = phiBegin + i * h, hi = lo + h;
        FollowerState sl = at(i), sh = at(i + 1);
        for (int it = 0; it < 60; ++it) {
            const double mid = 0.5 * (lo + hi);
            const FollowerState sm = model.at(mid, omega);
            if ((sm.contact - sl.contact).norm() >= (sh.contact - sm.contact).norm()) {
                hi = mid;
                sh = sm;
            } else {
                lo = mid;
                sl = sm;
            }
        }
        if ((sh.contact - sl.contact).norm() > 1e-7 * scale) {
            const double phi = phiBegin + std::fmod(0.5 * (lo + hi) - phiBegin, kTwoPi);
            a.undercut.push_back({phi, sl.contact, sh.contact});
        }
    }
    return a;
}

CurvatureVerdict curvatureVerdict(const FollowerAnalysis& a, const FollowerSpec& spec,
                                  double toolRadius) {
    CurvatureVerdict v;
    if (followerKind(spec.type).hasRadius) {
        v.rollerFits =
            !a.pitchCurvature.minConvex || a.pitchCurvature.minConvex->value > contactRadius(spec);
    }
    if (toolRadius > 0.0) {
        v.toolFits =
            !a.profileCurvature.minConcave || a.profileCurvature.minConcave->value >= toolRadius;
    }
    return v;
}

}  // namespace cam
