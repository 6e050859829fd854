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
        constexpr double kNone = -std::numeric_limits<double>::infinity();
        // Every check's value at one angle, from one profile point: |α| on rise, |α| on
        // return, the bend, and the profile's convex radius (+∞ where it is not convex).
        const auto values = [&](double phi) {
            const ProfilePoint q = p.at(phi);
            const double slope = d.liftAt(phi)[1];
            std::array<double, 4> v{kNone, kNone, kNone, std::numeric_limits<double>::infinity()};
            if (!flat) {
                if (slope > 0.0) v[0] = std::abs(q.pressureAngle);
                if (slope < 0.0) v[1] = std::abs(q.pressureAngle);
            }
            if (flat) {
                v[2] = (m_options.minRadius - q.rho) / std::max(m_options.minRadius, 1.0);
                v[3] = q.rho;
            } else {
                const double kappa = std::isfinite(q.rho) ? 1.0 / (q.rho + m_rho) : 0.0;
                if (allowed > 0.0) v[2] = kappa * allowed - 1.0;
                if (kappa > 0.0) v[3] = q.rho;
            }
            return v;
        };
        const auto quantity = [&](std::size_t k) {
            return std::function<double(double)>(
                [&values, k](double phi) { return values(phi)[k]; });
        };
        const double h = kTwoPi / kSizingSamples;
        std::array<std::pair<double, double>, 3> best;
        best.fill({kNone, 0.0});
        double convex = std::numeric_limits<double>::infinity(), convexAt = 0.0;
        for (int i = 0; i < kSizingSamples; ++i) {
            const double phi = i * h;
            const auto v = values(phi);
            for (std::size_t k = 0; k < 3; ++k) {
                if (v[k] > best[k].first) best[k] = {v[k], phi};
            }
            if (v[3] < convex) {
                convex = v[3];
                convexAt = phi;
            }
        }
        for (std::size_t k = 0; k < 3; ++k) {
            if (std::isfinite(best[k].first)) best[k] = refineMax(quantity(k), best[k].second, h);
        }
        if (std::isfinite(convex)) {
            convex = -refineMax([&](double phi) { return -values(phi)[3]; }, convexAt, h).first;
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

/// Halves [lo, hi] round the radius where a check passes or fails until it is `tolerance`
/// wide relative to hi (absolute below 1 mm): `lowSide(r)` tells whether r lies on lo's side.
template <class LowSide>
void bisectRadius(double& lo, double& hi, double tolerance, LowSide lowSide) {
    while (hi - lo > tolerance * std::max(1.0, hi)) {
        const double mid = 0.5 * (lo + hi);
        if (lowSide(mid)) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
}

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
    const bool near = options.near && *options.near > 0.0;
    const auto first = near ? checker.failing(checker.at(*options.near))
                            : std::optional<std::pair<SizingCheck, double>>{};
    if (near && (translating || !first)) {
        // Near a known answer a translating follower's checks only ease as the radius grows:
        // step out by 5 % until one radius fails and the next passes. An arm steps only down
        // from a radius that passes (above it the pivot ends the radii the arm reaches).
        double r = *options.near;
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
    bisectRadius(lo, hi, kSizingTolerance,
                 [&](double r) { return checker.failing(checker.at(r)).has_value(); });
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

double largestBaseRadius(const DesignSpec& design, const FollowerSpec& follower,
                         const SizingOptions& options, double smallest) {
    if (follower.motion != FollowerMotion::Oscillating) {
        return std::numeric_limits<double>::infinity();
    }
    const Checker checker(design, follower, options);
    const double reach = follower.pivot.norm() - contactRadius(follower);
    double lo = smallest, hi = reach * (1.0 - 1e-12);
    if (!checker.failing(checker.at(hi))) return reach;
    bisectRadius(lo, hi, 1e-6,
                 [&](double r) { return !checker.failing(checker.at(r)).has_value(); });
    return lo;
}

std::optional<Placement> placementOf(const FollowerSpec& follower) {
    if (follower.motion == FollowerMotion::Oscillating) return Placement::PivotDistance;
    if (followerKind(follower.type).flatFace) return std::nullopt;
    return Placement::Offset;
}

double placementValue(const FollowerSpec& follower, Placement placement) {
    return placement == Placement::Offset ? follower.offset : follower.pivot.norm();
}

FollowerSpec placedAt(FollowerSpec follower, Placement placement, double value) {
    if (placement == Placement::Offset) {
        follower.offset = value;
    } else {
        const double a = follower.pivot.norm();
        const Eigen::Vector2d direction =
            a > 0.0 ? Eigen::Vector2d(follower.pivot / a) : Eigen::Vector2d(1.0, 0.0);
        follower.pivot = value * direction;
    }
    return follower;
}

Result<PlacementSizing> sizePlacement(const DesignSpec& design, const FollowerSpec& follower,
                                      const SizingOptions& options, int edgePoints,
                                      const std::atomic<bool>* cancel) {
    const auto built = MotionDesign::build(design);
    if (!built.ok()) return built.errors();
    const Placement placement = placementOf(follower).value_or(Placement::Offset);
    const auto cancelled = [cancel] { return cancel && cancel->load(); };
    std::optional<double> near;
    const auto sizeAt = [&](double value) {
        SizingOptions o = options;
        o.near = near;
        auto sized = sizeBaseRadius(design, placedAt(follower, placement, value), o);
        if (sized.ok()) near = sized.value().baseRadius;
        return sized;
    };
    // The placements worth trying.
    double from = 0.0, to = 0.0;
    if (placement == Placement::Offset) {
        // The best offset balances the steepest rise against the steepest return, so it lies
        // within the range of s'.
        double steepest = 0.0;
        for (int i = 0; i < kSizingSamples; ++i) {
            steepest =
                std::max(steepest, std::abs(built.value().liftAt(i * kTwoPi / kSizingSamples)[1]));
        }
        to = steepest > 0.0 ? 1.1 * steepest : 1.0;
        from = -to;
    } else {
        // The pivot lies outside the pitch base circle (a > Rb + ρ), and the arm reaches it
        // only when Rb + ρ > a − L: no pivot beyond L + ρ + R allows a base radius below R.
        const double rho = contactRadius(follower), L = follower.armLength;
        const double a0 = follower.pivot.norm();
        const auto own = sizeBaseRadius(design, follower, options);
        to = own.ok() ? L + rho + own.value().baseRadius : 2.0 * (L + rho) + a0;
        from = rho + (to - rho) * 1e-3;
        // Pivots too near the cam swing the arm too steeply for any radius: a coarse look
        // first, and the region drawn only where radii pass, with a coarse step either side.
        constexpr int kCoarse = 11;
        int first = -1, last = -1;
        for (int i = 0; i < kCoarse; ++i) {
            if (cancelled()) return PlacementSizing{};
            if (sizeAt(from + (to - from) * i / (kCoarse - 1)).ok()) {
                if (first < 0) first = i;
                last = i;
            }
        }
        near.reset();
        if (first >= 0) {
            const double coarse = (to - from) / (kCoarse - 1), start = from;
            from = std::max(start, start + (first - 1) * coarse);
            to = std::min(to, start + (last + 1) * coarse);
        }
    }
    PlacementSizing result;
    result.placement = placement;
    const int n = std::max(edgePoints, 3);
    int best = -1;
    std::optional<Diagnostics> firstFailure;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int i = 0; i < n; ++i) {
        if (cancelled()) return PlacementSizing{};
        const double value = from + (to - from) * i / (n - 1);
        const auto sized = sizeAt(value);
        FeasibleSpan span{value, nan, nan};
        if (sized.ok()) {
            span.smallest = sized.value().baseRadius;
            span.largest = largestBaseRadius(design, placedAt(follower, placement, value), options,
                                             span.smallest);
        } else if (!firstFailure) {
            firstFailure = sized.errors();
        }
        result.region.push_back(span);
        if (sized.ok() &&
            (best < 0 || span.smallest < result.region[static_cast<std::size_t>(best)].smallest)) {
            best = i;
        }
    }
    if (best < 0) return *firstFailure;
    // Golden sections between the best edge point's neighbours (the smallest base radius is
    // unimodal there: for an offset, rise and return each ease as it moves their way).
    const double step = (to - from) / (n - 1);
    const double bestValue = result.region[static_cast<std::size_t>(best)].placement;
    const double lo = std::max(from, bestValue - step), hi = std::min(to, bestValue + step);
    const auto radiusAt = [&](double value) {
        const auto sized = sizeAt(value);
        return sized.ok() ? sized.value().baseRadius : std::numeric_limits<double>::infinity();
    };
    const GoldenSection g = goldenSectionMin(radiusAt, lo, hi, [&](double a, double b, int) {
        return b - a > kPlacementTolerance && !cancelled();
    });
    if (cancelled()) return PlacementSizing{};
    double value = g.f1 <= g.f2 ? g.x1 : g.x2;
    if (std::min(g.f1, g.f2) > result.region[static_cast<std::size_t>(best)].smallest) {
        value = bestValue;
    }
    near.reset();
    auto sized = sizeAt(value);
    if (!sized.ok()) return sized.errors();
    result.value = value;
    result.sizing = sized.value();
    return result;
}

}  // namespace cam
