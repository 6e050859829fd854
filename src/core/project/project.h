#pragma once
/// @file
/// @brief The project document: what a `.cam.json` file holds, in the units the user sees.
///
/// Lengths are millimetres and window angles are degrees, exactly as typed or read, so that
/// save → load → save is byte-stable. The engine works on a `Contour` compiled from it.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/arc.h"
#include "geometry/bezier.h"

namespace cam {

enum class SegmentType { Arc, Line, Bezier, Hermite };

/// @brief True for the two spline kinds (both evaluate as a cubic Bézier).
[[nodiscard]] constexpr bool isSpline(SegmentType t) {
    return t == SegmentType::Bezier || t == SegmentType::Hermite;
}

/// @brief One row of the segment table. Fields of the other kinds are kept when the type changes.
struct SegmentSpec {
    SegmentType type = SegmentType::Arc;
    // arc
    Eigen::Vector2d center{0.0, 0.0};
    double radius = 1.0;
    Branch branch = Branch::Outer;
    // line
    Eigen::Vector2d from{0.0, 0.0};
    Eigen::Vector2d to{0.0, 0.0};
    // Bézier: the control points P0..P3. Hermite: p0, t0, p3, t1 (tangents are offsets, the
    // curve's derivative at s = 0 and 1). Kept as given so files round-trip exactly.
    std::array<Eigen::Vector2d, 4> controls{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                            Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
    // polar window [phiStartDeg, phiEndDeg)
    double phiStartDeg = 0.0;
    double phiEndDeg = 0.0;

    friend bool operator==(const SegmentSpec&, const SegmentSpec&) = default;
};

/// @brief The cubic Bézier of a spline segment (Hermite data converted exactly: P1 = p0 + t0/3,
/// P2 = p3 − t1/3).
[[nodiscard]] CubicBezier bezierOf(const SegmentSpec& segment);

/// @brief Start and end point of a segment's curve (lines and splines; arcs need their window).
[[nodiscard]] std::pair<Eigen::Vector2d, Eigen::Vector2d> endPointsOf(const SegmentSpec& segment);

/// @brief Where the follower ray at angle phiDeg meets the segment's curve (its own formula,
/// also just outside its window). At a spline's window ends its own end point is meant, even
/// if the ray touches the curve elsewhere too. NaN where the ray misses.
[[nodiscard]] Eigen::Vector2d pointOnSegment(const SegmentSpec& segment, double phiDeg);

/// @brief How the turning speed is given; exactly one of them is stored in the file.
enum class SpeedUnit { OmegaRadS, Rpm, PeriodS };

struct MotionSpec {
    SpeedUnit unit = SpeedUnit::PeriodS;
    double value = 1.0;

    /// @brief Angular speed in rad/s (negative turns clockwise). Requires a valid spec.
    [[nodiscard]] double omegaRadS() const;

    friend bool operator==(const MotionSpec&, const MotionSpec&) = default;
};

enum class FollowerType { Knife, Roller, Flat };

struct FollowerSpec {
    FollowerType type = FollowerType::Knife;
    double offset = 0.0;  ///< mm
    double radius = 0.0;  ///< roller radius, mm
    friend bool operator==(const FollowerSpec&, const FollowerSpec&) = default;
};

struct MachiningSpec {
    std::vector<double> axisAccel{500.0, 500.0, 200.0};  ///< mm/s² per axis
    std::vector<double> axisVmax;                        ///< mm/s per axis, empty if not given
    double feedMax = 100.0;                              ///< mm/s
    double toolRadius = 0.0;                             ///< mm
    double step = 1.0;                                   ///< seed-method step, mm
    friend bool operator==(const MachiningSpec&, const MachiningSpec&) = default;
};

inline constexpr std::int64_t kMinSamplesPerTurn = 16;
inline constexpr std::int64_t kMaxSamplesPerTurn = 10'000'000;
inline constexpr std::int64_t kDefaultSamplesPerTurn = 3600;
inline constexpr double kMaxLengthMm = 1e6;

/// @brief The whole document.
struct Project {
    std::string name;
    MotionSpec motion;
    std::vector<SegmentSpec> contour;
    std::optional<FollowerSpec> follower;
    std::optional<std::int64_t> samplesPerTurn;
    std::optional<MachiningSpec> machining;
    /// Unknown top-level keys, kept verbatim (key, compact JSON text) for forward compatibility.
    std::vector<std::pair<std::string, std::string>> extraKeys;

    [[nodiscard]] std::int64_t samplesPerTurnOrDefault() const {
        return samplesPerTurn.value_or(kDefaultSamplesPerTurn);
    }

    friend bool operator==(const Project&, const Project&) = default;
};

}  // namespace cam
