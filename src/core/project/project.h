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
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "common/dynamics_key.h"
#include "geometry/arc.h"
#include "geometry/bezier.h"
#include "geometry/line.h"

namespace cam {

enum class SegmentType { Arc, Line, Bezier, Hermite };

/// @brief True for the two spline kinds (both evaluate as a cubic Bézier).
[[nodiscard]] constexpr bool isSpline(SegmentType t) {
    return t == SegmentType::Bezier || t == SegmentType::Hermite;
}

/// @brief The curve of a segment, exactly as the file gives it: an arc (centre, radius, branch),
/// a line (from, to), a Bézier (four control points) or a Hermite cubic (p0, t0, p3, t1). The
/// alternatives are in the order of SegmentType.
using SegmentShape = std::variant<Arc, Line, CubicBezier, HermiteCurve>;

/// @brief One row of the segment table: a curve and its polar window [phiStartDeg, phiEndDeg).
/// It holds nothing else, so two segments compare equal exactly when a file would say the same.
struct SegmentSpec {
    SegmentShape shape = Arc{};
    double phiStartDeg = 0.0;
    double phiEndDeg = 0.0;

    [[nodiscard]] SegmentType type() const { return static_cast<SegmentType>(shape.index()); }
    /// @brief The curve if it is of kind `Shape`, else null.
    template <class Shape>
    [[nodiscard]] const Shape* as() const {
        return std::get_if<Shape>(&shape);
    }
    template <class Shape>
    [[nodiscard]] Shape* as() {
        return std::get_if<Shape>(&shape);
    }

    friend bool operator==(const SegmentSpec&, const SegmentSpec&) = default;
};
static_assert(
    std::is_same_v<std::variant_alternative_t<static_cast<int>(SegmentType::Hermite), SegmentShape>,
                   HermiteCurve>);

/// @brief The cubic Bézier of a spline segment (Hermite data converted exactly: P1 = p0 + t0/3,
/// P2 = p3 − t1/3). Requires a spline.
[[nodiscard]] CubicBezier bezierOf(const SegmentSpec& segment);

/// @brief Start and end point of a segment's curve (lines and splines; arcs need their window).
[[nodiscard]] std::pair<Eigen::Vector2d, Eigen::Vector2d> endPointsOf(const SegmentSpec& segment);

/// @brief r(φ) and its first three derivatives of the segment's curve at phiDeg (its own
/// formula, also just outside its window; at a spline's window ends its own end point). NaN or
/// infinite where the ray misses or only touches the curve.
[[nodiscard]] PolarDerivatives polarOfSegment(const SegmentSpec& segment, double phiDeg);

/// @brief Where the follower ray at angle phiDeg meets the segment's curve (its own formula,
/// also just outside its window). At a spline's window ends its own end point is meant, even
/// if the ray touches the curve elsewhere too. NaN where the ray misses.
[[nodiscard]] Eigen::Vector2d pointOnSegment(const SegmentSpec& segment, double phiDeg);

/// @brief The units a file gives its lengths and window angles in. The document always holds
/// millimetres and degrees; a file is saved in the units it was read in.
enum class LengthUnit { Mm, M };
enum class AngleUnit { Deg, Rad };

struct UnitsSpec {
    LengthUnit length = LengthUnit::Mm;
    AngleUnit angle = AngleUnit::Deg;

    /// @brief File value × lengthFactor() = millimetres.
    [[nodiscard]] double lengthFactor() const { return length == LengthUnit::M ? 1000.0 : 1.0; }
    /// @brief File value × angleFactor() = degrees.
    [[nodiscard]] double angleFactor() const;

    friend bool operator==(const UnitsSpec&, const UnitsSpec&) = default;
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

/// @brief The follower's contact with the cam. Everything else about a kind (its name, title,
/// contact circle, whether it swings) is its row in project/follower_kind.cpp.
enum class FollowerType { Knife, Roller, Flat };
/// @brief How the follower moves (math.md §7): along a line, or swinging on an arm.
enum class FollowerMotion { Translating, Oscillating };
/// @brief Which side of the line from the pivot to the cam centre an arm's roller is on.
enum class ArmSide { Ccw, Cw };
/// @brief What keeps the follower on the cam (project-format.md `follower.closure`): a spring
/// (the contour is the cam's profile), a groove milled into the disc (the contour is its
/// inner flank; a roller runs in it, closure/groove.h), or a second plate on the same shaft
/// driving a second roller on the follower (the contour is the first plate,
/// closure/conjugate.h).
enum class Closure { Spring, Groove, Conjugate };

/// @brief The usual limits of the pressure angle when the project sets none (math.md §7).
inline constexpr double kDefaultMaxPressureAngleTranslatingDeg = 30.0;
inline constexpr double kDefaultMaxPressureAngleOscillatingDeg = 45.0;

struct FollowerSpec {
    FollowerType type = FollowerType::Knife;
    FollowerMotion motion = FollowerMotion::Translating;
    double offset = 0.0;              ///< translating: e along n, mm
    double radius = 0.0;              ///< roller radius, mm
    Eigen::Vector2d pivot{0.0, 0.0};  ///< oscillating: in the follower frame, mm
    double armLength = 0.0;           ///< oscillating, mm
    ArmSide arm = ArmSide::Ccw;       ///< oscillating
    std::optional<double> maxPressureAngleDeg;
    Closure closure = Closure::Spring;
    double grooveClearance = 0.0;  ///< groove: the roller's play between its flanks, mm
    /// Groove: the smallest radius the inner flank may come to (the bore's land) and the
    /// largest the outer flank may reach (the rim's), mm; unchecked when not given.
    std::optional<double> innerLandRadius, outerLandRadius;
    /// Conjugate: the second roller's radius, mm; on a translating roller's yoke its centre
    /// this far behind the first on the same line, beyond the cam centre, mm; on a swinging
    /// arm's bell crank a second arm of this length (mm) on the same pivot, turned by this
    /// angle (degrees, counter-clockwise) from the first.
    double conjugateDistance = 0.0;
    double conjugateRadius = 0.0;
    double conjugateAngleDeg = 0.0;
    double conjugateArmLength = 0.0;

    [[nodiscard]] bool grooved() const { return closure == Closure::Groove; }
    [[nodiscard]] bool conjugate() const { return closure == Closure::Conjugate; }
    [[nodiscard]] double maxPressureAngleOrDefault() const {
        return maxPressureAngleDeg.value_or(motion == FollowerMotion::Translating
                                                ? kDefaultMaxPressureAngleTranslatingDeg
                                                : kDefaultMaxPressureAngleOscillatingDeg);
    }
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

// The ranges in which the arithmetic is sound (project-format.md; every value is checked on load
// and on every edit, so no computation sees a value outside them):
/// @brief Radii, roller radius and seed step are at least this (the joint tolerance): below it
/// a circle is a point and its curvature overflows in the jerk.
inline constexpr double kMinLengthMm = 1e-6;
/// @brief The speed's magnitude in the unit the project gives it: ω from 1e-6 to 1e6 rad/s,
/// 1e-5 to 1e7 rpm, a period from 1e-5 s to 1e7 s (about 116 days). Inside these ω³·r stays far
/// inside a double and the period 2π/|ω| never overflows or vanishes.
struct ValueRange {
    double lo;
    double hi;
};
inline constexpr ValueRange kOmegaRadSRange{1e-6, 1e6};
inline constexpr ValueRange kRpmRange{1e-5, 1e7};
inline constexpr ValueRange kPeriodSRange{1e-5, 1e7};
/// @brief The range of a speed's magnitude in its own unit.
[[nodiscard]] constexpr ValueRange speedRange(SpeedUnit unit) {
    return unit == SpeedUnit::OmegaRadS ? kOmegaRadSRange
           : unit == SpeedUnit::Rpm     ? kRpmRange
                                        : kPeriodSRange;
}
/// @brief At a window end the follower ray crosses the curve at least this steeply (rad).
inline constexpr double kMinRayAngleRad = 1e-6;
/// @brief Machine limits: accelerations in mm/s², speeds in mm/s.
inline constexpr double kMinMachineLimit = 1e-6;
inline constexpr double kMaxAccelMmS2 = 1e12;
inline constexpr double kMaxSpeedMmS = 1e9;

/// @brief The laws a design segment can follow (math.md §8, VDI 2143), in the order the window
/// lists them. Everything else about a law (its name in files, its title, its function, its
/// coefficients) is its row of the table in design/motion_law.cpp, which must have one row
/// per law in this order (a static_assert checks it).
#define CAM_MOTION_LAWS(X) \
    X(Dwell)               \
    X(Harmonic)            \
    X(Cycloidal)           \
    X(ModifiedTrapezoid)   \
    X(ModifiedSine)        \
    X(Poly345)             \
    X(Poly4567)            \
    X(Poly5)               \
    X(ConstantVelocity)    \
    X(InclinedSine)        \
    X(Scca)                \
    X(Poly7)               \
    X(Table)

#define CAM_MOTION_LAW_ENUM(name) name,
enum class MotionLawType { CAM_MOTION_LAWS(CAM_MOTION_LAW_ENUM) };
#undef CAM_MOTION_LAW_ENUM

/// @brief How many laws there are (MotionLawType values are 0 .. kMotionLawCount - 1).
#define CAM_MOTION_LAW_COUNT(name) +1
inline constexpr std::size_t kMotionLawCount = 0 CAM_MOTION_LAWS(CAM_MOTION_LAW_COUNT);
#undef CAM_MOTION_LAW_COUNT

/// @brief A point of a user's motion table (law `table`), normalised to its stretch: x in
/// [0, 1], y = 0 at x = 0 and 1 at x = 1, v = dy/dx where the user gives it.
struct MotionTablePoint {
    double x = 0.0, y = 0.0;
    std::optional<double> v{};
    friend bool operator==(const MotionTablePoint&, const MotionTablePoint&) = default;
};

/// @brief One stretch of the follower's motion: from where the previous segment ends (the
/// first from 0°) to `toDeg`, from the previous segment's lift (the first from 0) to `lift`.
struct DesignSegmentSpec {
    MotionLawType law = MotionLawType::Dwell;
    double toDeg = 0.0;
    /// The lift at toDeg: mm above the base circle (translating), or degrees swung away from
    /// the cam (oscillating). A dwell keeps the lift it starts with.
    double lift = 0.0;
    /// poly5 only: d(lift)/dφ and d²(lift)/dφ² at the start and the end, per degree of cam
    /// angle (mm/°, mm/°²; °/° on a swinging arm).
    /// inclined-sine: v0 is its velocity at both ends (a line's beside it, 0 beside a dwell).
    double v0 = 0.0, a0 = 0.0, v1 = 0.0, a1 = 0.0;
    /// poly7 only: d³(lift)/dφ³ at the start and the end, per degree³.
    double j0 = 0.0, j1 = 0.0;
    /// modified-sine, modified-trapezoid: where the acceleration changes sign, a fraction of
    /// the stretch in (0, 1) (CODESYS's inflection point λ); 0.5 is the classic symmetric law.
    double lambda = 0.5;
    /// scca: Norton's b (the sine ramps' share) and d (the cosine's share) of the stretch;
    /// the constant acceleration's share is c = 1 − b − d. The defaults are the modified
    /// trapezoid.
    double sccaB = 0.25, sccaD = 0.25;
    /// table: the user's motion, normalised: x from 0 to 1 over the stretch, y from 0 to 1
    /// over the lift, and where given dy/dx (a C2 quintic spline runs through them).
    std::vector<MotionTablePoint> table{};
    friend bool operator==(const DesignSegmentSpec&, const DesignSegmentSpec&) = default;
};

inline constexpr double kDefaultDesignToleranceMm = 0.001;

/// @brief The motion the contour is synthesised from (math.md §8).
struct DesignSpec {
    /// mm: the base circle of the profile, which the follower touches at lift 0 (for a roller
    /// the pitch curve's smallest radius is baseRadius + its radius).
    double baseRadius = 0.0;
    std::vector<DesignSegmentSpec> segments;
    double tolerance = kDefaultDesignToleranceMm;  ///< mm, the arc table's largest deviation
    /// Refuse to synthesise where the pressure angle exceeds the follower's limit (file key
    /// `strict_pressure_angle`, default false: then it is only reported).
    bool strictPressureAngle = false;
    friend bool operator==(const DesignSpec&, const DesignSpec&) = default;
};

/// @brief The follower train and the contact (math.md §9): each value exactly as the file or
/// the user gives it, absent where not given (the computation then takes its default: 0, the
/// safety factor 1). Units are in the keys (common/dynamics_key.h); what each key takes is
/// project/dynamics.cpp.
struct DynamicsSpec {
    std::array<std::optional<double>, kDynamicsKeyCount> values{};

    [[nodiscard]] const std::optional<double>& operator[](DynamicsKey key) const {
        return values[static_cast<std::size_t>(key)];
    }
    [[nodiscard]] std::optional<double>& operator[](DynamicsKey key) {
        return values[static_cast<std::size_t>(key)];
    }
    friend bool operator==(const DynamicsSpec&, const DynamicsSpec&) = default;
};

/// @brief The whole document.
struct Project {
    std::string name;
    UnitsSpec units;  ///< how the file gives its values; the fields below are in mm and degrees
    MotionSpec motion;
    std::vector<SegmentSpec> contour;
    std::optional<FollowerSpec> follower;
    std::optional<std::int64_t> samplesPerTurn;
    std::optional<MachiningSpec> machining;
    std::optional<DesignSpec> design;
    std::optional<DynamicsSpec> dynamics;
    /// Unknown top-level keys, kept verbatim (key, compact JSON text) for forward compatibility.
    std::vector<std::pair<std::string, std::string>> extraKeys;

    [[nodiscard]] std::int64_t samplesPerTurnOrDefault() const {
        return samplesPerTurn.value_or(kDefaultSamplesPerTurn);
    }

    friend bool operator==(const Project&, const Project&) = default;
};

}  // namespace cam
