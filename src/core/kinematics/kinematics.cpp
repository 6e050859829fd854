#include "kinematics/kinematics.h"

#include <algorithm>
#include <array>

#include "common/angles.h"
#include "common/simd.h"
#include "common/turn_angles.h"

namespace cam {

KinematicState stateAt(const Contour& contour, double omega, double t) {
    KinematicState s;
    s.t = t;
    s.phi = omega * t;
    s.segment = contour.segmentAt(s.phi);
    s.polar = contour.segment(s.segment).evaluate(s.phi);
    s.motion = polarMotion(s.polar, omega);
    return s;
}

double turnsAt(const MotionSpec& motion, double t) {
    switch (motion.unit) {
        case SpeedUnit::PeriodS:
            return t / motion.value;
        case SpeedUnit::Rpm:
            return t * motion.value / 60.0;
        case SpeedUnit::OmegaRadS:
            break;
    }
    return t * motion.value / kTwoPi;
}

KinematicState stateAt(const Contour& contour, const MotionSpec& motion, double t) {
    const double omega = motion.omegaRadS();
    // The fraction of the current turn is exact (turns − floor(turns) loses nothing), so the
    // only rounding left is that of the one division or product in turnsAt.
    const double turns = turnsAt(motion, t);
    const double reduced = kTwoPi * (turns - std::floor(turns));
    KinematicState s;
    s.t = t;
    s.phi = omega * t;
    s.segment = contour.segmentAt(reduced);
    s.polar = contour.segment(s.segment).evaluate(reduced);
    s.motion = polarMotion(s.polar, omega);
    return s;
}

void SampledTurn::resize(std::size_t n) {
    for (auto* v : {&t, &phi, &r, &x, &y, &vR, &vPhi, &v, &aR, &aPhi, &a, &jR, &jPhi, &j}) {
        v->resize(n);
    }
    segment.resize(n);
}

namespace {

constexpr std::size_t kBlockBits = TurnAngles::kBlockBits;
constexpr std::size_t kBlock = TurnAngles::kBlock;
static_assert(kBlock == kSampleBlock);

struct Outputs {
    double* __restrict t;
    double* __restrict phi;
    double* __restrict r;
    double* __restrict x;
    double* __restrict y;
    double* __restrict vR;
    double* __restrict vPhi;
    double* __restrict v;
    double* __restrict aR;
    double* __restrict aPhi;
    double* __restrict a;
    double* __restrict jR;
    double* __restrict jPhi;
    double* __restrict j;
    std::int32_t* __restrict segment;
    std::size_t first;  ///< index in the turn of element 0 of the arrays
};

/// Samples [k0, k0 + count) that share one block and one segment.
template <class Evaluate>
void runPiece(const Evaluate evaluate, const Outputs o, const double* __restrict ct,
              const double* __restrict st, double cb, double sb, std::size_t k0, std::size_t count,
              double omega, double dt, std::int32_t seg) {
    const std::size_t j0 = k0 & (kBlock - 1);
    const double k0d = static_cast<double>(k0);
    const std::size_t w0 = k0 - o.first;
    const auto n = static_cast<std::int32_t>(count);  // count <= kBlock
    for (std::int32_t i = 0; i < n; ++i) {
        const std::size_t k = w0 + static_cast<std::size_t>(i);
        const double c = cb * ct[j0 + i] - sb * st[j0 + i];
        const double s = sb * ct[j0 + i] + cb * st[j0 + i];
        const PolarDerivatives d = evaluate(c, s);
        const PolarMotion m = polarMotion(d, omega);
        const double t = (k0d + static_cast<double>(i)) * dt;  // exact: both are integers
        o.t[k] = t;
        o.phi[k] = omega * t;
        o.r[k] = d.r;
        o.x[k] = d.r * c;
        o.y[k] = d.r * s;
        o.vR[k] = m.vR;
        o.vPhi[k] = m.vPhi;
        o.v[k] = m.v;
        o.aR[k] = m.aR;
        o.aPhi[k] = m.aPhi;
        o.a[k] = m.a;
        o.jR[k] = m.jR;
        o.jPhi[k] = m.jPhi;
        o.j[k] = m.j;
        o.segment[k] = seg;
    }
}

template <class Evaluate>
void runSegment(const Evaluate& evaluate, const Outputs& o, const TurnAngles& angles,
                std::size_t k0, std::size_t k1, double omega, double dt, std::int32_t seg) {
    for (std::size_t k = k0; k < k1;) {
        const std::size_t end = std::min(k1, TurnAngles::blockEnd(k));
        runPiece(evaluate, o, angles.ct.data(), angles.st.data(), angles.blockCos(k),
                 angles.blockSin(k), k, end - k, omega, dt, seg);
        k = end;
    }
}

// The loops above are compiled once per instruction set (common/simd.h); see docs/performance.md
// for the figures.
CAMWRIGHT_MULTIVERSION
void runArcSegment(const Arc::Kernel& kernel, const Outputs& o, const TurnAngles& angles,
                   std::size_t k0, std::size_t k1, double omega, double dt, std::int32_t seg) {
    runSegment(kernel, o, angles, k0, k1, omega, dt, seg);
}

CAMWRIGHT_MULTIVERSION
void runLineSegment(const Line::Kernel& kernel, const Outputs& o, const TurnAngles& angles,
                    std::size_t k0, std::size_t k1, double omega, double dt, std::int32_t seg) {
    runSegment(kernel, o, angles, k0, k1, omega, dt, seg);
}

}  // namespace

bool sampleTurn(const Contour& contour, double omega, std::size_t n, SampledTurn& out,
                const std::atomic<bool>* cancel) {
    return sampleTurnRange(contour, omega, n, 0, n, out, cancel);
}

bool sampleTurnRange(const Contour& contour, double omega, std::size_t n, std::size_t first,
                     std::size_t count, SampledTurn& out, const std::atomic<bool>* cancel) {
    out.resize(count);
    const double period = kTwoPi / std::abs(omega);
    const double dt = period / static_cast<double>(n);
    const double dphi = omega * dt;          // signed step
    const std::size_t last = first + count;  // one past

    // The block table covers the blocks of [first, last) only; cos/sin of sample k depend on k
    // alone, so a chunk's values equal those of the whole turn.
    const TurnAngles angles(omega, dt, first, count);

    const Outputs o{out.t.data(),    out.phi.data(),  out.r.data(),       out.x.data(),
                    out.y.data(),    out.vR.data(),   out.vPhi.data(),    out.v.data(),
                    out.aR.data(),   out.aPhi.data(), out.a.data(),       out.jR.data(),
                    out.jPhi.data(), out.j.data(),    out.segment.data(), first};
    auto phiOf = [&](std::size_t k) { return omega * (static_cast<double>(k) * dt); };

    constexpr std::size_t kSamplesBetweenPolls = 16 * kBlock;
    for (std::size_t k = first; k < last;) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return false;
        const double x = contour.normalize(phiOf(k));
        const std::size_t seg = contour.segmentAtNormalized(x);
        const ContourSegment& s = contour.segment(seg);
        // Estimate where this window ends, then settle the boundary with the exact lookup so
        // that every sample is assigned exactly as segmentAt() would assign it.
        const double remaining = omega > 0.0 ? s.phiEnd - x : x - s.phiStart;
        const double steps = std::floor(remaining / std::abs(dphi));
        std::size_t end = k + 1 + static_cast<std::size_t>(std::max(0.0, std::min(steps, 1e18)));
        end = std::min(end, last);
        while (end > k + 1 && contour.segmentAt(phiOf(end - 1)) != seg) --end;
        while (end < last && contour.segmentAt(phiOf(end)) == seg) ++end;
        // Polls on the turn's grid, not k's: where a piece ends must not depend on where the
        // chunk began (a piece ending mid-block rounds its last samples differently).
        end = std::min(end, (k / kSamplesBetweenPolls + 1) * kSamplesBetweenPolls);

        const auto segIndex = static_cast<std::int32_t>(seg);
        if (s.type == SegmentType::Arc) {
            runArcSegment(s.arcKernel, o, angles, k, end, omega, dt, segIndex);
        } else if (s.type == SegmentType::Line) {
            runLineSegment(s.lineKernel, o, angles, k, end, omega, dt, segIndex);
        } else {
            // Splines solve a cubic per sample: no vectorised kernel, the plain loop.
            const auto spline = [&s](double c, double sn) { return s.evaluate(c, sn); };
            runSegment(spline, o, angles, k, end, omega, dt, segIndex);
        }
        k = end;
    }
    return true;
}

}  // namespace cam
