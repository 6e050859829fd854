#include "follower/follower_analysis.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "common/angles.h"
#include "project/follower_kind.h"

namespace cam {
namespace {

/// The extreme of f near phi (within one sample step h either side), by golden sections.
FollowerExtremum refine(const std::function<double(double)>& f, double phi, double h, bool max) {
    const double sign = max ? -1.0 : 1.0;  // minimise sign·f
    double lo = phi - h, hi = phi + h;
    constexpr double g = 0.6180339887498949;
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = sign * f(x1), f2 = sign * f(x2);
    for (int it = 0; it < 90 && hi - lo > 1e-14; ++it) {
        if (f1 <= f2) {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = sign * f(x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = sign * f(x2);
        }
    }
    FollowerExtremum e{f(phi), phi};
    for (const auto& [x, fx] : {std::pair{x1, f1}, std::pair{x2, f2}}) {
        if (fx < sign * e.value) e = {sign * fx, x};
    }
    return e;
}

}  // namespace

FollowerAnalysis analyzeFollower(const FollowerModel& model, double omega, double phiBegin,
                                 int samples, const std::atomic<bool>* cancel) {
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
        e.phi = phiBegin + std::fmod(e.phi - phiBegin + 2 * kTwoPi, kTwoPi);
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
    a.pressureRise = extreme([](const FollowerState& s) { return s.pressureAngle; }, true);
    a.pressureReturn = extreme([](const FollowerState& s) { return s.pressureAngle; }, false);
    a.rhoProfileMin = extreme([](const FollowerState& s) { return s.rhoProfile; }, false);
    a.rhoPitchMin = extreme([](const FollowerState& s) { return s.rhoPitch; }, false);
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
            a.pressureExceeded.push_back({from, to});
        }
    } else if (std::abs(at(0).pressureAngle) > a.limitRad) {
        a.pressureExceeded.push_back({phiBegin, phiBegin + kTwoPi});
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

}  // namespace cam
