#include "timing/seed_method.h"

#include <cmath>

namespace cam {
namespace {

/// Below this a direction component counts as zero: the axis does not move in this step.
constexpr double kTinyComponent = 1e-12;

}  // namespace

Diagnostics checkSeedStep(const ToolPath& path, double step, Field field) {
    if (!std::isfinite(step) || !(step >= kMinLengthMm)) {
        return {Diagnostic::make(FieldPlace{field}, DiagnosticCode::SeedStepTooSmall,
                                 {kMinLengthMm, step})};
    }
    const double length = path.length();
    const double steps = length / step;
    if (!(steps <= kMaxSeedSteps)) {
        return {Diagnostic::make(
            FieldPlace{field}, DiagnosticCode::SeedStepTooMany,
            {step, std::ceil(steps), length, kMaxSeedSteps, length / kMaxSeedSteps})};
    }
    return {};
}

double seedStepSpeed(const Eigen::Vector3d& n, const Eigen::Vector3d& vPrev, double step,
                     const MachineLimits& lim) {
    double x = lim.feedMax;
    for (int i = 0; i < 3; ++i) {
        const double a = lim.accel[i];
        if (std::isinf(a)) continue;
        if (std::abs(n[i]) < kTinyComponent) {
            // No motion of this axis in this step: only stopping its previous speed counts.
            if (std::abs(vPrev[i]) > 0) x = std::min(x, a * step / std::abs(vPrev[i]));
            continue;
        }
        // The rising root of |n_i|·x² − sgn(n_i)·v_i·x − a_i·step = 0.
        const double an = std::abs(n[i]);
        const double v = std::copysign(1.0, n[i]) * vPrev[i];
        x = std::min(x, (v + std::sqrt(v * v + 4.0 * an * a * step)) / (2.0 * an));
    }
    return x;
}

std::optional<double> seedTime(const PathSegment& segment, const MachineLimits& lim,
                               const std::atomic<bool>* cancel) {
    double time = 0.0;
    if (!walkSeed(
            segment, lim, [&](const SeedStep& step) { time += step.length / step.speed; },
            cancel)) {
        return std::nullopt;
    }
    return 2.0 * time;
}

double seedSegmentTime(const PathSegment& segment, const MachineLimits& lim) {
    return *seedTime(segment, lim, nullptr);
}

}  // namespace cam
