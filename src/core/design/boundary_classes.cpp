#include "design/boundary_classes.h"

#include <array>
#include <cmath>

#include "common/angles.h"

#include "common/translate_marker.h"

namespace cam {

BoundaryClass classifyBoundary(double v, double a, double zero) {
    const bool moving = std::abs(v) > zero, accelerating = std::abs(a) > zero;
    if (moving) return accelerating ? BoundaryClass::Movement : BoundaryClass::Velocity;
    return accelerating ? BoundaryClass::Reversal : BoundaryClass::Rest;
}

std::string_view boundaryClassName(BoundaryClass c) {
    switch (c) {
        case BoundaryClass::Rest:
            return "rest";
        case BoundaryClass::Velocity:
            return "velocity";
        case BoundaryClass::Reversal:
            return "reversal";
        case BoundaryClass::Movement:
            return "movement";
    }
    return "";
}

const char* boundaryClassTerm(BoundaryClass c) {
    switch (c) {
        case BoundaryClass::Rest:
            return CAM_TRANSLATE_NOOP("Diagnostic", "rest");
        case BoundaryClass::Velocity:
            return CAM_TRANSLATE_NOOP("Diagnostic", "constant velocity");
        case BoundaryClass::Reversal:
            return CAM_TRANSLATE_NOOP("Diagnostic", "reversal");
        case BoundaryClass::Movement:
            return CAM_TRANSLATE_NOOP("Diagnostic", "movement");
    }
    return "";
}

char boundaryClassLetter(BoundaryClass c) {
    switch (c) {
        case BoundaryClass::Rest:
            return 'R';
        case BoundaryClass::Velocity:
            return 'G';
        case BoundaryClass::Reversal:
            return 'U';
        case BoundaryClass::Movement:
            return 'B';
    }
    return '?';
}

std::vector<SegmentClasses> boundaryClasses(const MotionDesign& design) {
    const std::size_t n = design.spec().segments.size();
    std::vector<SegmentClasses> out(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::array<double, 4> before = design.endOf((k + n - 1) % n);
        const std::array<double, 4> after = design.startOf((k + 1) % n);
        out[k] = {classifyBoundary(before[1], before[2], design.zeroScale()),
                  classifyBoundary(after[1], after[2], design.zeroScale())};
    }
    return out;
}

Result<std::vector<SegmentClasses>> boundaryClasses(const DesignSpec& spec) {
    auto design = MotionDesign::buildIgnoringJoints(spec);
    if (!design.ok()) return design.errors();
    return boundaryClasses(design.value());
}

Result<DesignSpec> suggestLaws(const DesignSpec& spec, std::optional<std::size_t> only) {
    auto built = MotionDesign::buildIgnoringJoints(spec);
    if (!built.ok()) return built.errors();
    const MotionDesign& design = built.value();
    const std::size_t n = spec.segments.size();
    const auto lift = [&](std::size_t k) {
        return spec.segments[k].lift - spec.segments[(k + n - 1) % n].lift;
    };
    const auto suggested = [&](std::size_t k) {
        const MotionLawType law = spec.segments[k].law;
        if (law == MotionLawType::Dwell || law == MotionLawType::ConstantVelocity) return false;
        return !only || *only == k;
    };
    // v and a per radian where segment `left` ends and `right` starts, as Suggest makes it.
    const auto joint = [&](std::size_t left, std::size_t right, bool forRight) {
        if (!(suggested(left) && suggested(right))) {
            const std::array<double, 4> fixed =
                forRight ? design.endOf(left) : design.startOf(right);
            return std::array<double, 2>{fixed[1], fixed[2]};
        }
        const double d1 = lift(left), d2 = lift(right);
        const double h1 = design.widthRad(left), h2 = design.widthRad(right);
        if ((d1 > 0.0) != (d2 > 0.0)) {
            return std::array<double, 2>{0.0, 6.0 * (d2 / (h2 * h2) - d1 / (h1 * h1))};
        }
        const double s1 = d1 / h1, s2 = d2 / h2;
        return std::array<double, 2>{2.0 * s1 * s2 / (s1 + s2), 0.0};
    };
    DesignSpec out = spec;
    const double zero = design.zeroScale(), perDeg = kPi / 180.0;
    for (std::size_t k = 0; k < n; ++k) {
        if (!suggested(k)) continue;
        // Not structured bindings: the lambda below captures them (clang 14 cannot).
        const std::array<double, 2> start = joint((k + n - 1) % n, k, true);
        const std::array<double, 2> end = joint(k, (k + 1) % n, false);
        // Below the design's zero a value is what its class says: 0 (a cycloid's end
        // acceleration is sin 2π ≈ −2e-16, not 0).
        const auto clean = [zero](double v) { return std::abs(v) <= zero ? 0.0 : v; };
        const double v0 = clean(start[0]), a0 = clean(start[1]), v1 = clean(end[0]),
                     a1 = clean(end[1]);
        DesignSegmentSpec s;
        s.toDeg = spec.segments[k].toDeg;
        s.lift = spec.segments[k].lift;
        const double h = design.widthRad(k), d = lift(k), slope = d / h;
        const bool rest0 = classifyBoundary(v0, a0, zero) == BoundaryClass::Rest;
        const bool rest1 = classifyBoundary(v1, a1, zero) == BoundaryClass::Rest;
        const bool steady =
            std::abs(a0) <= zero && std::abs(a1) <= zero && std::abs(v0 - v1) <= zero;
        // Poly5 with the joint's velocity and acceleration at each end, per degree.
        const auto poly5 = [&] {
            s.law = MotionLawType::Poly5;
            s.v0 = v0 * perDeg;
            s.a0 = a0 * perDeg * perDeg;
            s.v1 = v1 * perDeg;
            s.a1 = a1 * perDeg * perDeg;
        };
        if (d == 0.0) {
            // A stretch that comes back to where it started (a poly5 or poly7 out and back):
            // no normalised law makes it.
            poly5();
        } else if (rest0 && rest1) {
            s.law = MotionLawType::ModifiedSine;
        } else if (steady && std::abs(v0 - slope) <= zero) {
            s.law = MotionLawType::ConstantVelocity;
        } else if (steady && v0 / slope >= 0.0 && v0 / slope <= 2.0) {
            // Between 0 and 2 the inclined sine runs one way: y' = 1 − (1 − v)·cos 2πx ≥ 0.
            s.law = MotionLawType::InclinedSine;
            s.v0 = v0 * perDeg;
        } else {
            poly5();
        }
        out.segments[k] = s;
    }
    return out;
}

}  // namespace cam
