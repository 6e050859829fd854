#include "design/sizing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>

#include "common/angles.h"
#include "common/golden_section.h"
#include "common/translate_marker.h"
#include "design/exact_profile.h"
#include "design/motion_design.h"
#include "project/follower_kind.h"

namespace cam {
namespace {

/// Samples per turn of the checks; every worst value is refined by golden sections after.
constexpr int kSizingSamples = 3600;

/// The largest value of f within a step h of phi (f is −∞ where it does not count).
std::pair<double, double> refineMax(const std::function<double(double)>& f, double phi, double h) {
    const GoldenSection g = goldenSectionMin(
        [&](double x) { return -f(x); }, phi - h, phi + h,
        [](double lo, double hi, int step) { return step < 80 && hi - lo > 1e-13; });
    std::pair<double, double> best{f(phi), phi};
    for (const auto& [x, fx] : {std::pair{g.x1, -g.f1}, std::pair{g.x2, -g.f2}}) {
        if (fx > best.first) best = {fx, x};
    }
    return best;
}

/// The checks of one base radius, each as the worst value over the turn and where.
struct Checks {
    bool reaches = false;
    /// |α| (rad) on rise and return; −∞ where the phase is missing or the follower is a face.
    std::pair<double, double> rise{-std::numeric_limits<double>::infinity(), 0.0};
    std::pair<double, double> fall{-std::numeric_limits<double>::infinity(), 0.0};
    /// How far the profile's tightest convex bend goes beyond what is allowed, as a ratio (> 0:
    /// too tight) — roller and knife: κ·(ρ_f + r_min) − 1 on the pitch curve; flat face:
    /// (r_min − (h + h'')) / max(r_min, 1 mm).
    std::pair<double, double> bend{-std::numeric_limits<double>::infinity(), 0.0};
    double minConvex = std::numeric_limits<double>::infinity();  ///< mm, the profile's
};

class Checker {
public:
    Checker(const DesignSpec& design, const FollowerSpec& follower, const SizingOptions& options)
        : m_design(design),
          m_follower(follower),
          m_options(options),
          m_rho(contactRadius(follower)),
          m_limit(degToRad(follower.maxPressureAngleOrDefault())) {}

    [[nodiscard]] Checks at(double baseRadius) const {
        Checks c;
        DesignSpec spec = m_design;
        spec.baseRadius = baseRadius;
        const auto design = MotionDesign::build(spec);
        if (!design.ok()) return c;
        const auto profile = ExactProfile::build(design.value(), m_follower);
        if (!profile.ok()) return c;
        c.reaches = true;
        const ExactProfile& p = profile.value();
        const MotionDesign& d = design.value();
        const bool flat = followerKind(m_follower.type).flatFace;
        const double allowed = m_rho + m_options.minRadius;  // the pitch curve's tightest radius
        const auto alpha = [&](double phi, double sign) {
            if (sign * d.liftAt(phi)[1] <= 0.0) return -std::numeric_limits<double>::infinity();
            return std::abs(p.at(phi).pressureAngle);
        };
        const auto bend = [&](double phi) {
            const ProfilePoint q = p.at(phi);
            if (flat) return (m_options.minRadius - q.rho) / std::max(m_options.minRadius, 1.0);
            const double kappa = std::isfinite(q.rho) ? 1.0 / (q.rho + m_rho) : 0.0;
            if (!(allowed > 0.0)) return -std::numeric_limits<double>::infinity();
            return kappa * allowed - 1.0;
        };
        const auto convexRadius = [&](double phi) {
            const ProfilePoint q = p.at(phi);
            if (flat) return q.rho;
            const double kappa = std::isfinite(q.rho) ? 1.0 / (q.rho + m_rho) : 0.0;
            return kappa > 0.0 ? q.rho : std::numeric_limits<double>::infinity();
        };
        const double h = kTwoPi / kSizingSamples;
        std::array<std::pair<double, double>, 3> best;
        best.fill({-std::numeric_limits<double>::infinity(), 0.0});
        const std::array<std::function<double(double)>, 3> quantity{
            [&](double phi) {
                return flat ? -std::numeric_limits<double>::infinity() : alpha(phi, 1.0);
            },
            [&](double phi) {
                return flat ? -std::numeric_limits<double>::infinity() : alpha(phi, -1.0);
            },
            bend};
        double convex = std::numeric_limits<double>::infinity(), convexAt = 0.0;
        for (int i = 0; i < kSizingSamples; ++i) {
            const double phi = i * h;
            for (std::size_t k = 0; k < 3; ++k) {
                const double v = quantity[k](phi);
                if (v > best[k].first) best[k] = {v, phi};
            }
            const double r = convexRadius(phi);
            if (r < convex) {
                convex = r;
                convexAt = phi;
            }
        }
        for (std::size_t k = 0; k < 3; ++k) {
            if (std::isfinite(best[k].first)) best[k] = refineMax(quantity[k], best[k].second, h);
        }
        if (std::isfinite(convex)) {
            convex = -refineMax([&](double phi) { return -convexRadius(phi); }, convexAt, h).first;
        }
        c.rise = best[0];
        c.fall = best[1];
        c.bend = best[2];
        c.minConvex = convex;
        return c;
    }

    /// Whether every check holds; otherwise the one that fails the most, and where.
    [[nodiscard]] std::optional<std::pair<SizingCheck, double>> failing(const Checks& c) const {
        if (!c.reaches) return std::pair{SizingCheck::Reach, 0.0};
        std::optional<std::pair<SizingCheck, double>> worst;
        double most = 0.0;
        const auto consider = [&](SizingCheck check, double excess, double phi) {
            if (excess > most) {
                most = excess;
                worst = std::pair{check, phi};
            }
        };
        consider(SizingCheck::PressureRise, (c.rise.first - m_limit) / m_limit, c.rise.second);
        consider(SizingCheck::PressureReturn, (c.fall.first - m_limit) / m_limit, c.fall.second);
        consider(SizingCheck::ConvexRadius, c.bend.first, c.bend.second);
        return worst;
    }

private:
    const DesignSpec& m_design;
    const FollowerSpec& m_follower;
    SizingOptions m_options;
    double m_rho, m_limit;
};

}  // namespace

const char* sizingCheckName(SizingCheck check) {
    switch (check) {
        case SizingCheck::PressureRise:
            return "pressure_angle_rise";
        case SizingCheck::PressureReturn:
            return "pressure_angle_return";
        case SizingCheck::ConvexRadius:
            return "convex_radius";
        case SizingCheck::Reach:
            return "reach";
    }
    return "";
}

const char* sizingCheckTitle(SizingCheck check) {
    switch (check) {
        case SizingCheck::PressureRise:
            return CAM_TRANSLATE_NOOP("Diagnostic", "the pressure angle on rise");
        case SizingCheck::PressureReturn:
            return CAM_TRANSLATE_NOOP("Diagnostic", "the pressure angle on return");
        case SizingCheck::ConvexRadius:
            return CAM_TRANSLATE_NOOP("Diagnostic", "the profile's convex radius");
        case SizingCheck::Reach:
            return CAM_TRANSLATE_NOOP("Diagnostic", "the follower's reach");
    }
    return "";
}

Result<SizingResult> sizeBaseRadius(const DesignSpec& design, const FollowerSpec& follower,
                                    const SizingOptions& options) {
    if (auto built = MotionDesign::build(design); !built.ok()) return built.errors();
    const Checker checker(design, follower, options);
    // Bracket on a geometric grid from 1 µm to 1 km (an arm's pivot ends the feasible radii
    // from above, so a doubling from below could step over them): the first radius that
    // passes, and the one before it, which fails.
    constexpr int kGrid = 120;
    double lo = 0.0, hi = 0.0;
    std::optional<std::pair<SizingCheck, double>> lastFailure;
    const bool translating = follower.motion != FollowerMotion::Oscillating;
    if (options.near && translating && *options.near > 0.0) {
        // Near a known answer a translating follower's checks only ease as the radius grows:
        // step out by 5 % until one radius fails and the next passes.
        double r = *options.near;
        const auto first = checker.failing(checker.at(r));
        if (first) {
            lo = r;
            lastFailure = first;
            for (int i = 0; i < 600 && r < 1e6; ++i) {
                r *= 1.05;
                const auto failure = checker.failing(checker.at(r));
                if (!failure) {
                    hi = r;
                    break;
                }
                lo = r;
                lastFailure = failure;
            }
        } else {
            hi = r;
            for (int i = 0; i < 600 && r > 1e-3; ++i) {
                r /= 1.05;
                if (checker.failing(checker.at(r))) {
                    lo = r;
                    break;
                }
                hi = r;
            }
        }
    } else {
        for (int i = 0; i <= kGrid; ++i) {
            const double r = 1e-3 * std::pow(1e9, static_cast<double>(i) / kGrid);
            const auto failure = checker.failing(checker.at(r));
            if (!failure) {
                hi = r;
                break;
            }
            lo = r;
            lastFailure = failure;
        }
    }
    if (!(hi > 0.0)) {
        const std::vector<DiagnosticArg> args{std::string(sizingCheckTitle(lastFailure->first)),
                                              radToDeg(lastFailure->second)};
        return Diagnostics{Diagnostic::make(FieldPlace{Field::DesignBaseRadius},
                                            DiagnosticCode::NoBaseRadiusPasses, args)};
    }
    if (lo == 0.0) lo = 0.5 * hi;  // the first grid radius passes: every check is loose
    while (hi - lo > kSizingTolerance * std::max(1.0, hi)) {
        const double mid = 0.5 * (lo + hi);
        if (checker.failing(checker.at(mid))) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    SizingResult result;
    result.baseRadius = hi;
    const Checks atHi = checker.at(hi);
    const auto binding = checker.failing(checker.at(lo));
    result.binding = binding ? binding->first : SizingCheck::Reach;
    switch (result.binding) {
        case SizingCheck::PressureRise:
            result.bindingPhi = atHi.rise.second;
            break;
        case SizingCheck::PressureReturn:
            result.bindingPhi = atHi.fall.second;
            break;
        case SizingCheck::ConvexRadius:
            result.bindingPhi = atHi.bend.second;
            break;
        case SizingCheck::Reach:
            result.bindingPhi = 0.0;
            break;
    }
    result.bindingPhi = std::fmod(result.bindingPhi + 2 * kTwoPi, kTwoPi);
    if (std::isfinite(atHi.rise.first)) result.pressureRise = atHi.rise.first;
    if (std::isfinite(atHi.fall.first)) result.pressureReturn = atHi.fall.first;
    if (std::isfinite(atHi.minConvex)) result.minConvexRadius = atHi.minConvex;
    if (followerKind(follower.type).flatFace) {
        DesignSpec spec = design;
        spec.baseRadius = hi;
        const MotionDesign d = MotionDesign::build(spec).value();
        const double h = kTwoPi / kSizingSamples;
        std::pair<double, double> low{-std::numeric_limits<double>::infinity(), 0.0};
        std::pair<double, double> high = low;
        for (int i = 0; i < kSizingSamples; ++i) {
            const double slope = d.liftAt(i * h)[1];
            if (slope > high.first) high = {slope, i * h};
            if (-slope > low.first) low = {-slope, i * h};
        }
        high = refineMax([&](double phi) { return d.liftAt(phi)[1]; }, high.second, h);
        low = refineMax([&](double phi) { return -d.liftAt(phi)[1]; }, low.second, h);
        result.faceWidth = high.first + low.first;
    }
    return result;
}

bool offsetSizable(const FollowerSpec& follower) {
    return follower.motion != FollowerMotion::Oscillating && !followerKind(follower.type).flatFace;
}

Result<OffsetSizing> sizeOffset(const DesignSpec& design, const FollowerSpec& follower,
                                const SizingOptions& options, int edgePoints,
                                const std::atomic<bool>* cancel) {
    const auto built = MotionDesign::build(design);
    if (!built.ok()) return built.errors();
    const auto cancelled = [cancel] { return cancel && cancel->load(); };
    // The offsets worth trying: the best balances the steepest rise against the steepest
    // return, so it lies within the range of s'.
    double steepest = 0.0;
    for (int i = 0; i < kSizingSamples; ++i) {
        steepest =
            std::max(steepest, std::abs(built.value().liftAt(i * kTwoPi / kSizingSamples)[1]));
    }
    const double reach = steepest > 0.0 ? 1.1 * steepest : 1.0;
    std::optional<double> near;
    const auto sizeAt = [&](double offset) {
        FollowerSpec f = follower;
        f.offset = offset;
        SizingOptions o = options;
        o.near = near;
        auto sized = sizeBaseRadius(design, f, o);
        if (sized.ok()) near = sized.value().baseRadius;
        return sized;
    };
    OffsetSizing result;
    const int n = std::max(edgePoints, 3);
    int best = -1;
    std::optional<Diagnostics> firstFailure;
    for (int i = 0; i < n; ++i) {
        if (cancelled()) return OffsetSizing{};
        const double e = -reach + 2.0 * reach * i / (n - 1);
        const auto sized = sizeAt(e);
        const double r =
            sized.ok() ? sized.value().baseRadius : std::numeric_limits<double>::quiet_NaN();
        if (!sized.ok() && !firstFailure) firstFailure = sized.errors();
        result.edge.push_back({e, r});
        if (sized.ok() && (best < 0 || r < result.edge[static_cast<std::size_t>(best)][1])) {
            best = i;
        }
    }
    if (best < 0) return *firstFailure;
    // Golden sections between the best edge point's neighbours (the smallest base radius over
    // offsets is unimodal there: rise and return each ease as the offset moves their way).
    const double step = 2.0 * reach / (n - 1);
    const double lo = std::max(-reach, result.edge[static_cast<std::size_t>(best)][0] - step);
    const double hi = std::min(reach, result.edge[static_cast<std::size_t>(best)][0] + step);
    const auto radiusAt = [&](double e) {
        const auto sized = sizeAt(e);
        return sized.ok() ? sized.value().baseRadius : std::numeric_limits<double>::infinity();
    };
    const GoldenSection g = goldenSectionMin(radiusAt, lo, hi, [&](double a, double b, int) {
        return b - a > kOffsetTolerance && !cancelled();
    });
    if (cancelled()) return OffsetSizing{};
    double offset = g.f1 <= g.f2 ? g.x1 : g.x2;
    if (std::min(g.f1, g.f2) > result.edge[static_cast<std::size_t>(best)][1]) {
        offset = result.edge[static_cast<std::size_t>(best)][0];
    }
    near.reset();
    auto sized = sizeAt(offset);
    if (!sized.ok()) return sized.errors();
    result.offset = offset;
    result.sizing = sized.value();
    return result;
}

}  // namespace cam
