#pragma once
/// @file
/// @brief The project document: what a `.cam.json` file holds, in the units the user sees.
///
/// Lengths are millimetres and window angles are degrees, exactly as typed or read, so that
/// save → load → save is byte-stable. The engine works on a `Contour` compiled from it.

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/arc.h"

namespace cam {

enum class SegmentType { Arc, Line };

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
    // polar window [phiStartDeg, phiEndDeg)
    double phiStartDeg = 0.0;
    double phiEndDeg = 0.0;

    friend bool operator==(const SegmentSpec&, const SegmentSpec&) = default;
};

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
