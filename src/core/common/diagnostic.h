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

namespace cam {

enum class Severity { Error, Info };

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

/// @brief A place in the contour, as data: the app marks table cells from it, the text form is
/// derived from it and never parsed back.
struct SegmentPlace {
    std::size_t segment = 0;
    SegmentPart part = SegmentPart::Whole;
    int point = -1;  ///< SegmentPart::Points: which control point, 0..3
    int axis = -1;   ///< of a point: 0 x, 1 y; -1 the whole point

    friend bool operator==(const SegmentPlace&, const SegmentPlace&) = default;
};

/// @brief "contour[3]".
[[nodiscard]] std::string segmentLocation(std::size_t index);
/// @brief "contour[3]", "contour[3].radius", "contour[3].points[2][0]", "contour[3].p0[1]".
[[nodiscard]] std::string locationText(const SegmentPlace& place);
/// @brief "contour[4]/contour[5]": the joint where `left` ends and `right` begins.
[[nodiscard]] std::string jointLocation(std::size_t left, std::size_t right);

/// @brief Every kind of message the core makes that a window can show, with the arguments each
/// carries: X(Name, signature), one letter of the signature per argument, in order: `n` a number
/// (double), `i` a whole number (a count or an index, held as a double), `k` a segment index
/// (contour[k]), `s` a name (a term from a closed vocabulary such as a unit, a law, a JSON type,
/// or text from the file). The comment after each code is its English message, `%1` … for the
/// arguments.
///
/// Why an enum and not a string id: the codes never leave the process (files and the CLI carry
/// the English text), so what has to stay stable is the meaning of a code, which an enum keeps
/// as well as a string; and an enum lets the compiler find a code the app does not translate
/// (`-Wswitch` on its switch) and a test iterate every code (kDiagnosticCodeCount).
/// diagnosticCodeName() gives the stable name for test output and logs.
///
/// Why a fillet's reason is a name and not a code of its own: the reason a radius fails (the
/// tangent point would leave a neighbour, no circle fits, the ray would meet the arc twice,
/// the 1e6 mm limit) is one of six, and four messages end with one of them. A code per pair
/// would be 24 codes that differ only in their last clause; a reason code nested as an argument
/// would need arguments of its own in the middle of another code's list. So the reason is an
/// `s` argument from a closed vocabulary (FilletReason in fillet.h), worded once by the app; the
/// one neighbour a reason can name is one of the joint's two segments, which the diagnostic
/// carries as its places.
///
/// A message that lists a variable number of reasons ("no tangent line fits: a; b; c") keeps
/// them as `reasons`, each a coded Diagnostic of its own: no fixed signature can hold a list.
/// So does a message that nests another whole diagnostic, location and all (a fillet whose
/// contour fails validation names the validator's first problem).
///
/// An optional clause of the English ("… radius 30 mm (base radius + roller radius)" when the
/// follower has a roller) makes a second code, not a flag argument: the app then words each
/// sentence whole, without building it from pieces.
///
/// Sides and branches that follow from one sense ("the near side …, but the far side (outer
/// branch)") are a code each, not a name each, so that a language can word the pair as a whole.
#define CAM_DIAGNOSTIC_CODES(X)                                                                             \
    X(Unspecified, "")                       /* only the English text (no translation) */                   \
    X(NotFinite, "n")                        /* must be a finite number (got %1) */                         \
    X(LengthTooLarge, "n")                   /* magnitude must be at most 1e6 mm (got %1) */                \
    X(OutOfRange, "nnsn")                    /* must be between %1 and %2%3 (got %4) */                     \
    X(BelowMinimumLength, "nn")              /* must be at least %1 mm (got %2): … */                     \
    X(NotPositive, "n")                      /* must be > 0 (got %1) */                                     \
    X(SpeedIsZero, "")                       /* must not be 0 (its sign …) */                             \
    X(SpeedOutOfRange, "nnsn")               /* magnitude must be between %1 and %2%3 (…%4) */            \
    X(NoSegments, "")                        /* must have at least one segment */                           \
    X(AngleNotFinite, "n")                   /* must be a finite angle of magnitude … (%1) */             \
    X(WindowNotIncreasing, "nn")             /* must be greater than phi_start %1° (got %2°) */           \
    X(RayGrazes, "nn")                       /* at %1° the follower ray only grazes … %2 rad */          \
    X(WindowDisagreesWithLineEnds, "nnnn")   /* window %1° .. %2° … from/to (%3° .. %4°) */           \
    X(WindowDisagreesWithSplineEnds, "nnnn") /* window … its end points (%3° .. %4°) */                 \
    X(LineHasNoLength, "")                   /* must differ from `from` (…no length) */                   \
    X(LineThroughCentre, "")                 /* the line passes through the rotation centre */              \
    X(LineClockwise, "nn")                   /* the line runs clockwise … (from %1 to %2) */              \
    X(SplineEndOnCentre, "")                 /* an end point lies on the rotation centre */                 \
    X(SplineClockwise, "nn")                 /* the curve runs clockwise … (from %1 to %2) */             \
    X(RayMeetsSplineTimes, "in")             /* the follower ray meets the curve %1 times … */            \
    X(InnerBranchBehindCentre, "")           /* the rotation centre lies inside this circle */              \
    X(RayMissesArc, "nnnn")         /* … misses the circle inside %1 .. %2; … %3 .. %4 */               \
    X(WindowGap, "nnn")             /* gap of %1° between phi_end %2 and phi_start %3 */                   \
    X(WindowOverlap, "nnn")         /* overlap of %1° between phi_end %2 and … %3 */                     \
    X(WindowsNotOneTurn, "nnn")     /* the windows cover %1° (from %2° to %3°); … */                   \
    X(JointGap, "nn")               /* the segments do not meet at %1°: gap of %2 mm */                    \
    X(FlatFaceOscillating, "")      /* a flat face moves only translating … */                            \
    X(RollerTooLargeForArc, "nkn")  /* must be smaller than the radius %1 mm of … */                      \
    X(SamplesOutOfRange, "i")       /* must be between 16 and 10000000 (got %1) */                          \
    X(AxisCount, "i")               /* must list 2 or 3 axes (got %1) */                                    \
    X(JointNeedsTwoSegments, "si")  /* a %1 needs a joint between two segments … */                       \
    X(NoSuchJoint, "ii")            /* there is no joint %1: joints are numbered … */                     \
    X(DesignEndNotAfterStart, "nn") /* must be after %1°, where this segment starts */                     \
    X(DesignEndBeyondTurn, "n")     /* must be at most 360° (got %1°) */                                  \
    X(DwellLiftChanges, "nn")       /* a dwell keeps the lift it starts with (%1) … */                    \
    X(LiftUnchanged, "ns")          /* must differ from the lift … (%1) for %2; … */                    \
    X(DesignLastNot360, "n")        /* the last segment must end at 360° (got %1°) */                     \
    X(DesignNotReturning, "n")      /* the motion must return to the start: … (%1) */                     \
    X(DesignVelocityJump, "nn")     /* the velocity jumps from %1 to %2 per degree */                       \
    X(DesignAccelerationJump, "nn") /* the acceleration jumps from %1 to %2 per …² */                    \
    X(DesignVelocityAndAccelerationJump, "nnnn") /* the two above joined by "; " */                         \
    X(Missing, "")                               /* missing */                                              \
    X(UnknownKey, "")                            /* unknown key */                                          \
    X(WrongType, "ss")                           /* must be %1 (got %2): a JSON type */                     \
    X(PointShape, "i")              /* must be an array [x, y] of two numbers (got %1 elements) */          \
    X(NotOneOf, "ss")               /* must be "a" or "b" (got "%2"): %1 the choices */                     \
    X(UnknownSegmentType, "s")      /* unknown segment type "%1" (expected …) */                          \
    X(UnknownLaw, "ss")             /* unknown law "%1" (expected one of %2) */                             \
    X(SpeedNotExactlyOne, "i")      /* must give exactly one of omega_rad_s, rpm, period_s */               \
    X(NotWholeSampleCount, "n")     /* must be a whole number between 16 and 10000000 */                    \
    X(NewerFormatVersion, "s")      /* this file has format version %1; … */                              \
    X(NotFormatVersion1, "s")       /* must be 1 (got %1) */                                                \
    X(BezierPointCount, "")         /* must be an array of four points [x, y] */                            \
    X(JsonDuplicatedKey, "")        /* duplicated key */                                                    \
    X(JsonNumberTooLarge, "iis")    /* line %1, column %2: number %3 is too large … */                    \
    X(JsonSyntax, "iis")            /* line %1, column %2: the parser's English reason */                   \
    X(JsonTooDeep, "i")             /* nesting deeper than %1 levels */                                     \
    X(JsonNulByte, "iii")           /* line %1, column %2: a NUL byte (at byte offset %3) */                \
    X(JsonInvalid, "")              /* not valid JSON */                                                    \
    X(RowValueCount, "issi")        /* line %1: expected %2 or %3 (got %4 values) */                        \
    X(RowValueNotFinite, "iss")     /* line %1: %2 must be a finite number (got "%3") */                    \
    X(FilletContourInvalid, "")     /* the contour is not valid, so the joint cannot be rounded */          \
    X(FilletNeedsArcsAndLines, "k") /* fillets join arcs and lines; contour[%1] is neither */               \
    X(FilletAlreadyTangent, "nn") /* the segments already meet tangentially (… %1°, … %2° …) */     \
    X(FilletRadiusNeedsArcsAndLines, "nk") /* radius %1 mm does not fit: fillets join … */                \
    X(FilletRadiusAlreadyTangent, "nnn")   /* radius %1 mm does not fit: the segments … */                \
    X(FilletNothingFits, "ns") /* no fillet radius of at least %1 mm fits … (%2 reason) */                \
    X(FilletRadiusNothingFits, "nns") /* radius %1 mm does not fit: no fillet radius … %2 (%3) */         \
    X(FilletRadiusTooSmall, "nn") /* radius %1 mm is too small: a fillet radius is at least %2 */           \
    X(FilletRadiusNotPositive, "nn") /* radius %1 mm must be a number > 0: radii below %2 mm f… */        \
    X(FilletRadiusTooLarge, "nns")   /* radius %1 mm is too large: only radii below %2 … (%3) */          \
    X(FilletRadiusInGap, "nsn") /* radius %1 mm does not fit (%2), although most … %3 mm do */            \
    X(RollerNotSmallerThanArc, "nn") /* the roller radius %1 mm is not smaller than … %2 mm … */        \
    X(PivotInsideCam, "nnn") /* is inside the cam: … radius %1 mm … reaches %2 mm at %3° */            \
    X(ArmTooShort, "nnsn") /* is too short: at %1° the cam is %2 mm from the pivot, and %3 … %4 */       \
    X(ArmTooLong, "nsn") /* is too long: at %1° %2 passes beyond the whole cam (at most %3 …) */         \
    X(ArmNoContact, "sn") /* does not let %1 touch the cam at %2° (no contact on the … arm) */           \
    X(ToolAboveCurveRadius, "nn") /* the tool radius %1 mm is larger than this curve's … %2 mm */         \
    X(ToolNotBelowArcRadius, "nn") /* the tool radius %1 mm is not smaller than the radius %2 … */        \
    X(OffsetCornerUnmet, "")       /* the offset segments do not meet at this corner */                     \
    X(ToolTrimsSegment, "n") /* the tool radius %1 mm is too large here: … trimmed beyond … */          \
    X(SeedStepTooSmall, "nn") /* must be a finite length of at least %1 mm (got %2) */                      \
    X(SeedStepTooMany, "nnnin") /* %1 mm makes %2 steps on this %3 mm path; … at most %4: … %5 */       \
    X(AccelerationLimitMissing, "ii") /* no acceleration limit for the %1 axis … (segment %2) */          \
    X(PathEmpty, "")                  /* is empty */                                                        \
    X(PathPointInvalid, "")  /* coordinates must be finite, at most 1e6 mm, and the bulge … */            \
    X(PathTooFewPoints, "")  /* a path needs at least two points */                                         \
    X(PathPointRepeated, "") /* repeats the previous point */                                               \
    X(PathArcChangesHeight, "nnn") /* an arc (bulge %1) must keep its height, but z goes … */             \
    X(PathArcNoChord, "")          /* an arc needs two distinct points in the XY plane */                   \
    X(PathArcTooFar, "nnn") /* the arc (bulge %1) reaches %2 mm from the origin; … within %3 mm */        \
    X(TangentNeedsArcs, "ks")      /* a tangent line joins two arcs; contour[%1] is %2 (a… */             \
    X(TangentNotCircle, "k")       /* contour[%1] is not a circle (its radius must be …) */               \
    X(TangentSameCircle, "")       /* both arcs lie on the same circle, so … */                           \
    X(TangentCircleInside, "kk")   /* the circle of contour[%1] lies inside that of conto… */             \
    X(TangentNoneFits, "")         /* no tangent line fits: and `reasons` joined by "; " */                 \
    X(TangentTouch, "nn")          /* the circles touch at (%1, %2): the arcs can meet th… */             \
    X(TangentClockwise, "snnknnk") /* the %1 tangent from (%2, %3) on contour[%4] to … ru… */           \
    X(TangentOnNearSide, "snnknnkk") /* the %1 tangent … touches contour[%8] on the near si… */         \
    X(TangentOnFarSide, "snnknnkk") /* the %1 tangent … touches contour[%8] on the far sid… */          \
    X(TangentEmptiesLeft, "snnknnkn") /* with the %1 tangent … the window of contour[%4] wou… */        \
    X(TangentReversesRight, "snnknnknn") /* with the %1 tangent … contour[%7] … start %8°, … e… */ \
    X(ArcNoSegment, "")                  /* has no segment to continue */                                   \
    X(ArcNoSuchRow, "ki")                /* there is no contour[%1]: rows are 0 .. %2 */                    \
    X(ArcSingleNotCircle, "ks")   /* a contour of one segment must be a circle; contour[… */              \
    X(ArcRowNotCircle, "k")       /* contour[%1] is not a circle */                                         \
    X(ArcRayMissesEnd, "nk")      /* the follower ray at the end %1° of contour[%2] miss… */             \
    X(ArcNoEndDirection, "k")     /* contour[%1] has no direction at its end point */                       \
    X(ArcEndClockwise, "knn")     /* contour[%1] does not run counter-clockwise … end po… */            \
    X(ArcPointNotFinite, "nn")    /* the point must be finite (got (%1, %2)) */                             \
    X(ArcPointAtCentre, "")       /* the point is the rotation centre, which no arc … ca… */            \
    X(ArcPointIsEnd, "nnk")       /* the point is the end point (%1, %2) of contour[%3]:… */              \
    X(ArcPointOnTangent, "")      /* the point is on the tangent: use a line (…) */                       \
    X(ArcRadiusTooSmall, "nn")    /* the arc's radius would be %1 mm, below %2 mm, … */                   \
    X(ArcEndOffOuter, "knnn")     /* the end point of contour[%1] is not on the outer br… */              \
    X(ArcEndOffInner, "knnn")     /* … not on the inner branch of the circle (centre (%2… */            \
    X(ArcPointOnNearSide, "nnnk") /* the point lies on the near side of the circle … lea… */            \
    X(ArcPointOnFarSide, "nnnk")  /* the point lies on the far side of the circle … leav… */            \
    X(ArcRunsBackNear, "knnn")    /* the point lies behind the end point of contour[%1]… */               \
    X(ArcRunsBackFar, "knnn")     /* the point lies behind the end point of contour[%1]… */               \
    X(ArcPointOnEndRay, "nk")     /* the point lies on the follower ray at the end %1° o… */             \
    X(ArcEndsAfterNext, "nnk")    /* the arc would end at %1° (…), not before the end %2… */           \
    X(ArcPointIsNextEnd, "k")     /* the point is the end point of contour[%1], which wo… */              \
    X(ArcNextClockwise, "knn")    /* with its start point moved …, contour[%1] would no… */             \
    X(ExportToleranceOutOfRange, "nnn") /* the tolerance must be between %1 and %2 mm, not %3 */            \
    X(ExportToolRadiusOutOfRange, "nn") /* the tool radius must be above 0 and at most %1 mm,… */         \
    X(GcodeCompensationCutsPart, "") /* with cutter compensation the tool would have to rea… */           \
    X(GcodeLengthOutOfRange, "snn") /* %1 (the depth, …) must be above 0 and at most %2 mm… */          \
    X(GcodeFeedOutOfRange, "nn")    /* the feed must be above 0 and at most %1 mm/min, not… */            \
    X(GcodeToolNumber, "i")         /* the tool number must be from 1 to 99999, not %1 */                   \
    X(GcodeTooManyPasses, "nnni")   /* a step-down of %1 mm makes %2 passes for a depth of… */            \
    X(CamTablePoints, "iii")        /* a cam table has from %1 to %2 points, not %3 */                      \
    X(SampleNotFinite, "n")         /* is not a finite number (%1): the result is beyond w… */            \
    X(NoPoints, "")                 /* must be at least 1 (got 0) */                                        \
    X(NotFiniteForFile, "")         /* is not a finite number, which a file cannot hold */                  \
    X(FileCannotOpen, "s")          /* cannot open: %1 (the OS's words) */                                  \
    X(FileCannotExamineOpen, "s")   /* cannot examine: %1 (the OS's words) */                               \
    X(FileCannotRead, "s")          /* cannot read: %1 (the OS's words) */                                  \
    X(FileNotRegularToRead, "s")    /* is %1 (a kind of file), not a regular file: not read */              \
    X(FileTooLargeToRead, "nii")    /* is %1 MiB (%2 bytes): files larger than %3 MiB are… */             \
    X(FileGrewTooLarge, "i")        /* grew past %1 MiB while it was read: larger files ar… */            \
    X(FileNoName, "")               /* no file name given */                                                \
    X(FileCannotExamine, "ss")      /* cannot examine %1: %2 (the OS's words) */                            \
    X(FileLinkLoop, "s")            /* cannot follow its symbolic links: %1 (the OS's word… */            \
    X(FileCannotReadLink, "ss")     /* cannot read the symbolic link %1: %2 */                              \
    X(FileIsDescriptorLink, "")     /* is a link to an open file descriptor, not a file: n… */            \
    X(FileLinkTargetIsDescriptorLink, "s") /* %1 is a link to an open file descriptor, … not r… */      \
    X(FileNotRegular, "s")                 /* is %1, not a regular file: not replaced */                    \
    X(FileLinkTargetNotRegular, "ss")      /* %1 is %2, not a regular file: not replaced */                 \
    X(FileCannotWrite, "ss")               /* cannot write %1: %2 */                                        \
    X(FileNamesFolder, "")                 /* names a folder, not a file */                                 \
    X(FileCannotCreateTemporary, "ss")     /* cannot create a temporary file in %1: %2 */                   \
    X(FileCannotCopyOwner, "ss")           /* cannot give the new file the owner of %1: %2 */               \
    X(FileCannotCopyPermissions, "ss") /* cannot give the new file the permissions of %1: %2 */             \
    X(FileCannotFlush, "ss")           /* cannot flush %1 to disk: %2 */                                    \
    X(FileBecameOther, "ss")           /* %1 became %2 while it was written: not replaced */                \
    X(FileCannotReplace, "ss")         /* cannot replace %1: %2 */                                          \
    X(FileReplacedCannotClose, "ss")   /* replaced, but cannot close %1: %2 */                              \
    X(FileReplacedCannotFlushFolder, "ss") /* replaced, but cannot flush the folder %1 to disk… */        \
    X(NoSuchSegment, "")                   /* no such segment */                                            \
    X(NotAnArc, "")                        /* is not an arc */                                              \
    X(RadialErrorNotPositive, "")          /* the admissible radial error must be > 0 mm */                 \
    X(ApproximationStartMissesArc, "") /* the ray at the window's start does not meet the arc */            \
    X(ApproximationEndMissesArc, "")   /* the ray at the window's end does not meet the arc */              \
    X(SplineTooFewPoints, "")          /* a spline needs at least two points */                             \
    X(ClosedSplineTooFewPoints, "")    /* a closed spline needs at least three points */                    \
    X(BulgeNotPositive, "n")           /* must be a finite factor > 0 (got %1) */                           \
    X(WindowsSegmentsDoNotMeet, "")    /* the neighbouring segments do not meet, so … */                  \
    X(ContourNeverSynthesised, "")     /* is empty: the design's contour was never synthe… */             \
    X(NoDesign, "")                    /* the project has no design to synthesise a conto… */             \
    X(SynthesisedContourInvalid, "")   /* … not a valid contour: reasons[0] */                            \
    X(SynthesisedArcInvalid, "knni")   /* … contour[%1] … %2°–%3° … [%4]: … */                  \
    X(ToleranceCannotBeMet, "ni")      /* cannot be met near %1°: … 2^-%2 … */                         \
    X(ToleranceBelowPrecision, "nnn")  /* %1 mm … at least %2 mm (… %3 mm) */                           \
    X(ToleranceNotReached, "nnn")      /* … %2 mm … at %3° (asked %1 mm) */                            \
    X(OffsetOutsideBaseCircle, "nn") /* the follower's line (offset %1 mm) … radius %2 mm: … */         \
    X(OffsetOutsidePitchBaseCircle, "nn") /* … radius %2 mm (base radius + roller radius): … */         \
    X(ArmMissesBaseCircle, "nnn")      /* an arm of %1 mm from a pivot %2 mm … radius %3 mm */            \
    X(ArmMissesPitchBaseCircle, "nnn") /* … of radius %3 mm (base radius + roller radius) */              \
    X(UndercutRoller, "nnn")  /* undercut: … the roller radius %1 mm from %2° to %3° */                 \
    X(UndercutFlatFace, "nn") /* undercut: the face's envelope folds back … from %1° to %2° */          \
    X(PressureAngleExceeded, "nnn")    /* the pressure angle exceeds %1° from %2° to %3° */              \
    X(FilletRadiusInvalidContour, "n") /* radius %1 mm gives a contour that … (reasons[0]) */             \
    X(Cancelled, "")                   /* cancelled */

/// @brief What a diagnostic says, independent of the language it is shown in.
enum class DiagnosticCode : std::uint16_t {
#define CAM_DIAGNOSTIC_ENUM(name, signature) name,
    CAM_DIAGNOSTIC_CODES(CAM_DIAGNOSTIC_ENUM)
#undef CAM_DIAGNOSTIC_ENUM
};

/// @brief How many codes there are (DiagnosticCode values are 0 .. kDiagnosticCodeCount - 1).
inline constexpr std::size_t kDiagnosticCodeCount = 0
#define CAM_DIAGNOSTIC_COUNT(name, signature) +1
    CAM_DIAGNOSTIC_CODES(CAM_DIAGNOSTIC_COUNT)
#undef CAM_DIAGNOSTIC_COUNT
    ;

/// @brief "RayMissesArc": the code's stable name.
[[nodiscard]] std::string_view diagnosticCodeName(DiagnosticCode code);
/// @brief "nnnn": one letter per argument (see CAM_DIAGNOSTIC_CODES).
[[nodiscard]] std::string_view diagnosticCodeSignature(DiagnosticCode code);

/// @brief One argument of a message: a number or a name.
using DiagnosticArg = std::variant<double, std::string>;

/// @brief One problem (or note) and where it is, e.g. {"contour[3].radius", "must be > 0 (got
/// -2)"}. Problems in the contour also carry their place as data.
struct Diagnostic {
    Diagnostic() = default;
    Diagnostic(std::string location_, std::string message_, Severity severity_ = Severity::Error,
               std::vector<SegmentPlace> places_ = {})
        : location(std::move(location_)),
          message(std::move(message_)),
          severity(severity_),
          places(std::move(places_)) {}

    std::string location;
    std::string message;
    Severity severity = Severity::Error;
    /// The segment fields it concerns (empty when it is not about a segment): one for a field,
    /// two (phi_end of the left, phi_start of the right) for a joint.
    std::vector<SegmentPlace> places;
    /// What it says, for a window that words it in its own language (the English `message` is
    /// what the CLI prints and stays as it is); Unspecified where the core has no code for it.
    DiagnosticCode code = DiagnosticCode::Unspecified;
    /// The code's arguments, as its signature lists them.
    std::vector<DiagnosticArg> args;
    /// The reasons a message lists after its own words, each with its own code (TangentNoneFits
    /// has one for every tangent that was dropped; FilletRadiusInvalidContour the one problem of
    /// the contour it names).
    std::vector<Diagnostic> reasons;

    /// @brief This diagnostic with its code and arguments (`args` must match the signature).
    [[nodiscard]] Diagnostic coded(DiagnosticCode code_, std::vector<DiagnosticArg> args_) && {
        code = code_;
        args = std::move(args_);
        return std::move(*this);
    }

    /// @brief A problem of one segment field; the location text follows from the place.
    [[nodiscard]] static Diagnostic at(const SegmentPlace& place, std::string message,
                                       Severity severity = Severity::Error) {
        return {locationText(place), std::move(message), severity, {place}};
    }
    /// @brief A problem of the joint where `left` ends and `right` begins.
    [[nodiscard]] static Diagnostic atJoint(std::size_t left, std::size_t right,
                                            std::string message,
                                            Severity severity = Severity::Error) {
        return {jointLocation(left, right),
                std::move(message),
                severity,
                {{left, SegmentPart::PhiEnd}, {right, SegmentPart::PhiStart}}};
    }

    /// @brief "location: message", the form the CLI and the app show.
    [[nodiscard]] std::string text() const {
        return location.empty() ? message : location + ": " + message;
    }
};

using Diagnostics = std::vector<Diagnostic>;

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
