#pragma once
/// @file
/// @brief Where a diagnostic points, as data: a window marks cells and names fields from it,
/// the CLI prints its text form (locationText), which is derived from it and never parsed back.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "common/dynamics_key.h"

namespace cam {

/// @brief Which field of a segment a problem concerns.
enum class SegmentPart {
    Whole,  ///< the segment as a whole (its shape, its window)
    Type,
    Center,
    Radius,
    Branch,
    From,
    To,
    Points,  ///< a Bézier's control points; SegmentPlace::point says which
    P0,      ///< a Hermite's start point
    T0,      ///< its start tangent
    P3,      ///< its end point
    T1,      ///< its end tangent
    PhiStart,
    PhiEnd,
};

/// @brief A field of a segment of the contour: "contour[3].radius", "contour[3].points[2][0]".
struct SegmentPlace {
    std::size_t segment = 0;
    SegmentPart part = SegmentPart::Whole;
    int point = -1;  ///< SegmentPart::Points: which control point, 0..3
    int axis = -1;   ///< of a point: 0 x, 1 y; -1 the whole point

    friend bool operator==(const SegmentPlace&, const SegmentPlace&) = default;
};

/// @brief The joint where segment `left` ends and `right` begins: "contour[4]/contour[5]".
struct JointPlace {
    std::size_t left = 0;
    std::size_t right = 0;

    friend bool operator==(const JointPlace&, const JointPlace&) = default;
};

/// @brief The windows of the whole turn, from the first segment's phi_start to the last one's
/// phi_end: "contour".
struct TurnPlace {
    std::size_t last = 0;  ///< the last segment

    friend bool operator==(const TurnPlace&, const TurnPlace&) = default;
};

/// @brief A named field of the project or an input of a computation, by its key in the file or
/// the name its caller gives it (fieldKey() has the text of each).
enum class Field : std::uint8_t {
    Contour,
    Motion,
    MotionOmega,
    MotionRpm,
    MotionPeriod,
    FollowerOffset,
    FollowerRadius,
    FollowerMaxPressureAngle,
    FollowerType,
    FollowerPivot,
    FollowerArmLength,
    FollowerClosure,
    FollowerGrooveClearance,
    FollowerInnerLandRadius,
    FollowerOuterLandRadius,
    FollowerConjugateDistance,
    FollowerConjugateRadius,
    FollowerConjugateAngle,
    FollowerConjugateArmLength,
    SamplesPerTurn,
    MachiningAxisAccel,
    MachiningAxisVmax,
    MachiningFeedMax,
    MachiningToolRadius,
    MachiningStep,
    Design,
    DesignBaseRadius,
    DesignTolerance,
    DesignSegments,
    Points,              ///< a list of points (teach-in, a tool path), or how many are asked for
    Point,               ///< one point of such a list, FieldPlace::index says which
    Bulge,               ///< the teach-in's bulge factor
    ApproximationError,  ///< the admissible radial error of an arc's approximation
    MachineAccel,        ///< the timing's machine limits, per axis
    MachineVmax,
    MachineFeed,
    Path,
    SeedStep,
    StepOption,  ///< the command line's options
    ToleranceOption,
    ToolRadiusOption,
    DepthOption,
    StepDownOption,
    CompensationOption,
    PointsOption,
    GcodeSafeZ,  ///< the G-code options without an option of their own
    GcodeFeed,
    GcodeToolNumber,
};

/// @brief A named field, one of its entries when `index` >= 0: "machining.axis_accel[1]".
struct FieldPlace {
    Field field = Field::Contour;
    int index = -1;

    friend bool operator==(const FieldPlace&, const FieldPlace&) = default;
};

/// @brief Which field of a segment of the motion design a problem concerns.
enum class DesignPart {
    Whole,
    Law,
    ToDeg,
    Lift,
    V0,
    A0,
    V1,
    A1,
    J0,
    J1,
    Lambda,
    SccaB,
    SccaD,
    Points
};

/// @brief A field of a segment of the motion design: "design.segments[2].lift".
struct DesignSegmentPlace {
    std::size_t segment = 0;
    DesignPart part = DesignPart::Whole;

    friend bool operator==(const DesignSegmentPlace&, const DesignSegmentPlace&) = default;
};

/// @brief Where design segment `left` ends and `right` begins.
struct DesignJointPlace {
    std::size_t left = 0;
    std::size_t right = 0;

    friend bool operator==(const DesignJointPlace&, const DesignJointPlace&) = default;
};

/// @brief A position in a text file: "line 3, column 14", or "line 3" when `column` is 0.
struct FilePositionPlace {
    std::size_t line = 1;
    std::size_t column = 0;

    friend bool operator==(const FilePositionPlace&, const FilePositionPlace&) = default;
};

/// @brief A key of a file being read, by its path in the file ("contour[3].radius",
/// "(top level)"): the user finds it in the file by the file's own words.
struct FileKeyPlace {
    std::string key;

    friend bool operator==(const FileKeyPlace&, const FileKeyPlace&) = default;
};

/// @brief A file on disk, by the path it was given as.
struct FilePlace {
    std::string path;

    friend bool operator==(const FilePlace&, const FilePlace&) = default;
};

/// @brief One value of the sampled turn: "sample 12, r".
struct SamplePlace {
    std::size_t sample = 0;
    std::string quantity;

    friend bool operator==(const SamplePlace&, const SamplePlace&) = default;
};

/// @brief A value of the project's dynamics: "dynamics.mass_kg".
struct DynamicsPlace {
    DynamicsKey key = DynamicsKey::MassKg;

    friend bool operator==(const DynamicsPlace&, const DynamicsPlace&) = default;
};

/// @brief Where a diagnostic points; std::monostate for nowhere (its text has no location).
using Place = std::variant<std::monostate, SegmentPlace, JointPlace, TurnPlace, FieldPlace,
                           DesignSegmentPlace, DesignJointPlace, FilePositionPlace, FileKeyPlace,
                           FilePlace, SamplePlace, DynamicsPlace>;

/// @brief "contour[3]".
[[nodiscard]] std::string segmentLocation(std::size_t index);
/// @brief "radius", "phi_start": a segment field's key in the file ("" for the whole segment).
[[nodiscard]] std::string_view segmentPartKey(SegmentPart part);
/// @brief "machining.axis_accel", "--tolerance": the key of a named field.
[[nodiscard]] std::string_view fieldKey(Field field);
/// @brief "lift", "to_deg": a design segment field's key in the file ("" for the whole one).
[[nodiscard]] std::string_view designPartKey(DesignPart part);

/// @brief The place's text as the CLI prints it: "contour[3].radius", "contour[4]/contour[5]",
/// "machining.axis_accel[1]", "design.segments[2].lift", "line 3, column 14", … ("" for none).
[[nodiscard]] std::string locationText(const Place& place);

/// @brief The segment fields a place concerns, for a table to mark: the field of a
/// SegmentPlace; phi_end of the left and phi_start of the right segment of a joint; the
/// first phi_start and the last phi_end of the turn; none for any other place.
[[nodiscard]] std::vector<SegmentPlace> segmentFields(const Place& place);

}  // namespace cam
