#pragma once
/// @file
/// @brief Located messages: how the core reports problems without throwing or printing.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "common/place.h"

namespace cam {

enum class Severity { Error, Info };

/// @brief Every kind of message the core makes. What each says, and the arguments it takes, is
/// its row in the catalogue (common/diagnostic_catalogue.cpp): an English template with %1 … for
/// the arguments, which the core renders for the CLI and a window translates. The core makes
/// every message with a code; Unspecified is left for text worded elsewhere (a window's own
/// message about a failed computation), which is shown as it is.
///
/// Why an enum and not a string id: the codes never leave the process (files and the CLI carry
/// the English text), so what has to stay stable is the meaning of a code, which an enum keeps
/// as well as a string; and an enum lets a test iterate every code (kDiagnosticCodeCount).
/// diagnosticCodeName() gives the stable name for test output and logs.
///
/// An optional clause of the English ("… radius 30 mm (base radius + roller radius)" when the
/// follower has a roller) makes a second code, not a flag argument, and so do sides and
/// branches that follow from one sense ("the near side …, but the far side (outer branch)"):
/// a language then words each sentence whole, without building it from pieces.
#define CAM_DIAGNOSTIC_CODES(X)          \
    X(Unspecified)                       \
    X(NotFinite)                         \
    X(LengthTooLarge)                    \
    X(OutOfRange)                        \
    X(BelowMinimumLength)                \
    X(NotPositive)                       \
    X(SpeedIsZero)                       \
    X(SpeedOutOfRange)                   \
    X(NoSegments)                        \
    X(AngleNotFinite)                    \
    X(WindowNotIncreasing)               \
    X(RayGrazes)                         \
    X(WindowDisagreesWithLineEnds)       \
    X(WindowDisagreesWithSplineEnds)     \
    X(LineHasNoLength)                   \
    X(LineThroughCentre)                 \
    X(LineClockwise)                     \
    X(SplineEndOnCentre)                 \
    X(SplineClockwise)                   \
    X(RayMeetsSplineTimes)               \
    X(InnerBranchBehindCentre)           \
    X(RayMissesArc)                      \
    X(WindowGap)                         \
    X(WindowOverlap)                     \
    X(WindowsNotOneTurn)                 \
    X(JointGap)                          \
    X(FlatFaceOscillating)               \
    X(RollerTooLargeForArc)              \
    X(SamplesOutOfRange)                 \
    X(AxisCount)                         \
    X(JointNeedsTwoSegments)             \
    X(NoSuchJoint)                       \
    X(DesignEndNotAfterStart)            \
    X(DesignEndBeyondTurn)               \
    X(DwellLiftChanges)                  \
    X(LiftUnchanged)                     \
    X(DesignLastNot360)                  \
    X(DesignNotReturning)                \
    X(DesignVelocityJump)                \
    X(DesignAccelerationJump)            \
    X(DesignVelocityAndAccelerationJump) \
    X(DesignBoundaryMismatch)            \
    X(SccaSharesExceedOne)               \
    X(MotionTableTooFew)                 \
    X(MotionTableTooMany)                \
    X(MotionTableNotIncreasing)          \
    X(MotionTableEnds)                   \
    X(MotionTableColumns)                \
    X(MotionTableNotANumber)             \
    X(MotionTableSingular)               \
    X(Missing)                           \
    X(UnknownKey)                        \
    X(WrongType)                         \
    X(PointShape)                        \
    X(NotOneOf)                          \
    X(NotTheValue)                       \
    X(UnknownSegmentType)                \
    X(UnknownLaw)                        \
    X(SpeedNotExactlyOne)                \
    X(NotWholeSampleCount)               \
    X(NewerFormatVersion)                \
    X(NotFormatVersion1)                 \
    X(BezierPointCount)                  \
    X(JsonDuplicatedKey)                 \
    X(JsonNumberTooLarge)                \
    X(JsonSyntax)                        \
    X(JsonTooDeep)                       \
    X(JsonNulByte)                       \
    X(JsonInvalid)                       \
    X(RowValueCount)                     \
    X(RowValueCountExact)                \
    X(RowValueNotFinite)                 \
    X(FilletContourInvalid)              \
    X(FilletNeedsArcsAndLines)           \
    X(FilletAlreadyTangent)              \
    X(FilletRadiusNeedsArcsAndLines)     \
    X(FilletRadiusAlreadyTangent)        \
    X(FilletNothingFits)                 \
    X(FilletRadiusNothingFits)           \
    X(FilletRadiusTooSmall)              \
    X(FilletRadiusNotPositive)           \
    X(FilletRadiusTooLarge)              \
    X(FilletRadiusInGap)                 \
    X(FilletLeavesSegment)               \
    X(FilletNoCircle)                    \
    X(FilletNoLargerCircle)              \
    X(FilletRayNotOnce)                  \
    X(FilletRadiusLimit)                 \
    X(RollerNotSmallerThanArc)           \
    X(PivotInsideCam)                    \
    X(ArmTooShort)                       \
    X(ArmTooLong)                        \
    X(ArmNoContact)                      \
    X(ToolAboveCurveRadius)              \
    X(ToolNotBelowArcRadius)             \
    X(OffsetCornerUnmet)                 \
    X(ToolTrimsSegment)                  \
    X(GrooveOuterFlankUndercut)          \
    X(GrooveNeedsRoller)                 \
    X(GrooveToolTooWide)                 \
    X(GrooveToolTooNarrow)               \
    X(GrooveNoCompensation)              \
    X(ConjugateNeedsRoller)              \
    X(ConjugateRollerNotBeyondCentre)    \
    X(ConjugatePlateNotRoundCentre)      \
    X(ConjugatePlateFolds)               \
    X(LandRadiiCrossed)                  \
    X(SeedStepTooSmall)                  \
    X(SeedStepTooMany)                   \
    X(AccelerationLimitMissing)          \
    X(PathEmpty)                         \
    X(PathPointInvalid)                  \
    X(PathTooFewPoints)                  \
    X(PathPointRepeated)                 \
    X(PathArcChangesHeight)              \
    X(PathArcNoChord)                    \
    X(PathArcTooFar)                     \
    X(TangentNeedsArcs)                  \
    X(TangentNotCircle)                  \
    X(TangentSameCircle)                 \
    X(TangentCircleInside)               \
    X(TangentNoneFits)                   \
    X(TangentTouch)                      \
    X(TangentClockwise)                  \
    X(TangentOnNearSide)                 \
    X(TangentOnFarSide)                  \
    X(TangentEmptiesLeft)                \
    X(TangentReversesRight)              \
    X(ArcNoSegment)                      \
    X(ArcNoSuchRow)                      \
    X(ArcSingleNotCircle)                \
    X(ArcRowNotCircle)                   \
    X(ArcRayMissesEnd)                   \
    X(ArcNoEndDirection)                 \
    X(ArcEndClockwise)                   \
    X(ArcPointNotFinite)                 \
    X(ArcPointAtCentre)                  \
    X(ArcPointIsEnd)                     \
    X(ArcPointOnTangent)                 \
    X(ArcRadiusTooSmall)                 \
    X(ArcEndOffOuter)                    \
    X(ArcEndOffInner)                    \
    X(ArcPointOnNearSide)                \
    X(ArcPointOnFarSide)                 \
    X(ArcRunsBackNear)                   \
    X(ArcRunsBackFar)                    \
    X(ArcPointOnEndRay)                  \
    X(ArcEndsAfterNext)                  \
    X(ArcPointIsNextEnd)                 \
    X(ArcNextClockwise)                  \
    X(ExportToleranceOutOfRange)         \
    X(ExportToolRadiusOutOfRange)        \
    X(GcodeCompensationCutsPart)         \
    X(GcodeLengthOutOfRange)             \
    X(GcodeFeedOutOfRange)               \
    X(GcodeToolNumber)                   \
    X(GcodeTooManyPasses)                \
    X(CamTablePoints)                    \
    X(SampleNotFinite)                   \
    X(NoPoints)                          \
    X(NotFiniteForFile)                  \
    X(FileCannotOpen)                    \
    X(FileCannotExamineOpen)             \
    X(FileCannotRead)                    \
    X(FileNotRegularToRead)              \
    X(FileTooLargeToRead)                \
    X(FileGrewTooLarge)                  \
    X(FileNoName)                        \
    X(FileCannotExamine)                 \
    X(FileLinkLoop)                      \
    X(FileCannotReadLink)                \
    X(FileIsDescriptorLink)              \
    X(FileLinkTargetIsDescriptorLink)    \
    X(FileNotRegular)                    \
    X(FileLinkTargetNotRegular)          \
    X(FileCannotWrite)                   \
    X(FileNamesFolder)                   \
    X(FileCannotCreateTemporary)         \
    X(FileCannotCopyOwner)               \
    X(FileCannotCopyPermissions)         \
    X(FileCannotFlush)                   \
    X(FileBecameOther)                   \
    X(FileCannotReplace)                 \
    X(FileReplacedCannotClose)           \
    X(FileReplacedCannotFlushFolder)     \
    X(NoSuchSegment)                     \
    X(NotAnArc)                          \
    X(RadialErrorNotPositive)            \
    X(ApproximationStartMissesArc)       \
    X(ApproximationEndMissesArc)         \
    X(SplineTooFewPoints)                \
    X(ClosedSplineTooFewPoints)          \
    X(BulgeNotPositive)                  \
    X(WindowsSegmentsDoNotMeet)          \
    X(WindowsMoveTooLarge)               \
    X(WindowsMovesDoNotSettle)           \
    X(WindowsCircleMoved)                \
    X(WindowsCircleResized)              \
    X(WindowsCircleMadeSame)             \
    X(WindowsLineMoved)                  \
    X(ContourNeverSynthesised)           \
    X(NoDesign)                          \
    X(SynthesisedContourInvalid)         \
    X(SynthesisedArcInvalid)             \
    X(ToleranceCannotBeMet)              \
    X(ToleranceBelowPrecision)           \
    X(ToleranceNotReached)               \
    X(OffsetOutsideBaseCircle)           \
    X(OffsetOutsidePitchBaseCircle)      \
    X(ArmMissesBaseCircle)               \
    X(ArmMissesPitchBaseCircle)          \
    X(UndercutRoller)                    \
    X(UndercutFlatFace)                  \
    X(PressureAngleExceeded)             \
    X(FilletRadiusInvalidContour)        \
    X(NoBaseRadiusPasses)                \
    X(DynamicsKeyForArm)                 \
    X(DynamicsKeyForTranslating)         \
    X(PoissonOutOfRange)                 \
    X(Cancelled)

/// @brief What a diagnostic says, independent of the language it is shown in.
enum class DiagnosticCode : std::uint16_t {
#define CAM_DIAGNOSTIC_ENUM(name) name,
    CAM_DIAGNOSTIC_CODES(CAM_DIAGNOSTIC_ENUM)
#undef CAM_DIAGNOSTIC_ENUM
};

/// @brief How many codes there are (DiagnosticCode values are 0 .. kDiagnosticCodeCount - 1).
inline constexpr std::size_t kDiagnosticCodeCount = 0
#define CAM_DIAGNOSTIC_COUNT(name) +1
    CAM_DIAGNOSTIC_CODES(CAM_DIAGNOSTIC_COUNT)
#undef CAM_DIAGNOSTIC_COUNT
    ;

/// @brief "RayMissesArc": the code's stable name.
[[nodiscard]] std::string_view diagnosticCodeName(DiagnosticCode code);

/// @brief One argument of a message: a number, a name or text, or a segment field (the kinds
/// the catalogue's signatures list).
using DiagnosticArg = std::variant<double, std::string, SegmentPart>;

struct Diagnostic;
using Diagnostics = std::vector<Diagnostic>;

/// @brief One problem (or note) and where it is, e.g. {"contour[3].radius", "must be > 0 (got
/// -2)"}: its code, arguments and place, and the English the CLI prints, rendered from them.
struct Diagnostic {
    Diagnostic() = default;
    /// @brief A message without a code (Unspecified): text worded elsewhere, shown as it is.
    Diagnostic(std::string location_, std::string message_, Severity severity_ = Severity::Error)
        : location(std::move(location_)), message(std::move(message_)), severity(severity_) {}

    /// @brief The diagnostic `code` with its arguments (as its signature lists them) at
    /// `place`; its location and message are the English rendered from them.
    [[nodiscard]] static Diagnostic make(Place place, DiagnosticCode code,
                                         std::vector<DiagnosticArg> args = {},
                                         Severity severity = Severity::Error);

    /// @brief This diagnostic with the reasons its message lists (its `r` argument).
    [[nodiscard]] Diagnostic because(Diagnostics reasons_) &&;

    /// The place as the CLI prints it, derived from `place` (or given, for an uncoded message).
    std::string location;
    /// The English the CLI prints, rendered from the code's template (or given, uncoded).
    std::string message;
    Severity severity = Severity::Error;
    /// Where it points, as data: a window names and marks the place from this.
    Place place;
    /// What it says, for a window that words it in its own language.
    DiagnosticCode code = DiagnosticCode::Unspecified;
    /// The code's arguments, as its signature lists them.
    std::vector<DiagnosticArg> args;
    /// The diagnostics a message lists as its reasons, each with its own code (every tangent
    /// a TangentNoneFits dropped; the one problem of a contour FilletRadiusInvalidContour names;
    /// why a fillet radius fails).
    Diagnostics reasons;

    /// @brief The segment fields it concerns, for a table to mark (segmentFields of its place).
    [[nodiscard]] std::vector<SegmentPlace> segmentFields() const {
        return cam::segmentFields(place);
    }

    /// @brief "location: message", the form the CLI and the app show.
    [[nodiscard]] std::string text() const {
        return location.empty() ? message : location + ": " + message;
    }
};

[[nodiscard]] inline bool hasErrors(const Diagnostics& diagnostics) {
    for (const auto& d : diagnostics) {
        if (d.severity == Severity::Error) return true;
    }
    return false;
}

/// @brief Reports a broken precondition (a programming error, never bad input) and aborts.
[[noreturn]] void internalError(const std::string& what);

/// @brief Reports a Result read without a value and aborts.
[[noreturn]] void resultHasNoValue(const Diagnostics& errors);

/// @brief A value or the diagnostics that explain why there is none.
template <class T>
class Result {
public:
    Result(T value) : m_value(std::move(value)) {}  // NOLINT(google-explicit-constructor)
    Result(Diagnostics errors)
        : m_errors(std::move(errors)) {}  // NOLINT(google-explicit-constructor)

    [[nodiscard]] bool ok() const { return m_value.has_value(); }
    /// @brief The value; only when ok(). Without one it aborts with a message (in every build
    /// type), never reads an empty optional.
    [[nodiscard]] const T& value() const& {
        if (!m_value) [[unlikely]]
            resultHasNoValue(m_errors);
        return *m_value;
    }
    [[nodiscard]] T&& value() && {
        if (!m_value) [[unlikely]]
            resultHasNoValue(m_errors);
        return std::move(*m_value);
    }
    [[nodiscard]] const Diagnostics& errors() const { return m_errors; }

private:
    std::optional<T> m_value;
    Diagnostics m_errors;
};

/// @brief How many significant digits a number in a message has at most.
inline constexpr int kMessageDigits = 10;

/// @brief A number for a message (never for a file, which writes the exact value): at most
/// kMessageDigits significant digits and no trailing zeros, so a typed 12.5 reads 12.5 and the
/// round-off of a computed 215.6 (215.60000000000002) reads 215.6; never "-0".
std::string formatNumber(double value);

}  // namespace cam
