#include "common/diagnostic_catalogue.h"

#include <array>
#include <cmath>
#include <cstdio>

#include "common/kind_table.h"
#include "common/translate_marker.h"

namespace cam {
namespace {

using Code = DiagnosticCode;

// Every code, one row each, in DiagnosticCode order. The templates are the English the CLI
// prints; a window translates them in the context kDiagnosticContext, which lupdate reads from
// the markers here.
constexpr std::array<DiagnosticEntry, kDiagnosticCodeCount> kCatalogue{{
    {Code::Unspecified, "", ""},  // uncoded: the message as it was given
    {Code::NotFinite, "n", CAM_TRANSLATE_NOOP("Diagnostic", "must be a finite number (got %1)")},
    {Code::LengthTooLarge, "n",
     CAM_TRANSLATE_NOOP("Diagnostic", "magnitude must be at most 1e6 mm (got %1)")},
    {Code::OutOfRange, "nntn",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be between %1 and %2%3 (got %4)")},
    {Code::BelowMinimumLength, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "must be at least %1 mm (got %2): a smaller circle or step is below the "
                        "precision of the joints")},
    {Code::NotPositive, "n", CAM_TRANSLATE_NOOP("Diagnostic", "must be > 0 (got %1)")},
    {Code::SpeedIsZero, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "must not be 0 (its sign gives the turning direction)")},
    {Code::SpeedOutOfRange, "nntn",
     CAM_TRANSLATE_NOOP("Diagnostic", "magnitude must be between %1 and %2%3 (got %4)")},
    {Code::NoSegments, "", CAM_TRANSLATE_NOOP("Diagnostic", "must have at least one segment")},
    {Code::AngleNotFinite, "n",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be a finite angle of magnitude at most 1e6° (got %1)")},
    {Code::WindowNotIncreasing, "fnn",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be greater than %1 %2° (got %3°)")},
    {Code::RayGrazes, "nn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "at %1° the follower ray only grazes the curve (it must cross it at an angle of at least "
         "%2 rad, or the follower would need an unbounded speed); the window must end before it")},
    {Code::WindowDisagreesWithLineEnds, "nnnn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "window %1° .. %2° disagrees with the polar angles of from/to (%3° .. %4°)")},
    {Code::WindowDisagreesWithSplineEnds, "nnnn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "window %1° .. %2° disagrees with the polar angles of its end points (%3° .. %4°)")},
    {Code::LineHasNoLength, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "must differ from `from` (the line has no length)")},
    {Code::LineThroughCentre, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the line passes through the rotation centre, so the follower ray meets it "
                        "at no angle or at every point")},
    {Code::LineClockwise, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the line runs clockwise around the rotation centre (from %1° to %2°); "
                        "swap `from` and `to`")},
    {Code::SplineEndOnCentre, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "an end point lies on the rotation centre")},
    {Code::SplineClockwise, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the curve runs clockwise around the rotation centre (from %1° to %2°); "
                        "reverse its points")},
    {Code::RayMeetsSplineTimes, "in",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the follower ray meets the curve %1 times at %2°; inside its window it "
                        "must meet it exactly once")},
    {Code::InnerBranchBehindCentre, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the rotation centre lies inside this circle, so the inner intersection is "
                        "behind the follower (r <= 0); use \"outer\"")},
    {Code::RayMissesArc, "nnnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the follower ray misses the circle inside the window %1° .. %2°; it meets "
                        "it only for phi in %3° .. %4°")},
    {Code::WindowGap, "nfnfn",
     CAM_TRANSLATE_NOOP("Diagnostic", "gap of %1° between %2 %3 and %4 %5")},
    {Code::WindowOverlap, "nfnfn",
     CAM_TRANSLATE_NOOP("Diagnostic", "overlap of %1° between %2 %3 and %4 %5")},
    {Code::WindowsNotOneTurn, "nnn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "the windows cover %1° (from %2° to %3°); they must cover exactly one turn, 360°")},
    {Code::JointGap, "nn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic", "the segments do not meet at %1°: gap of %2 mm (at most 1e-06 mm allowed)")},
    {Code::FlatFaceOscillating, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "a flat face moves only translating (math.md §7); use a knife or a roller "
                        "on an oscillating arm")},
    {Code::RollerTooLargeForArc, "nkn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "must be smaller than the radius %1 mm of the concave arc %2 (got %3 mm): "
                        "the roller cannot enter it")},
    {Code::SamplesOutOfRange, "i",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be between 16 and 10000000 (got %1)")},
    {Code::AxisCount, "i", CAM_TRANSLATE_NOOP("Diagnostic", "must list 2 or 3 axes (got %1)")},
    {Code::JointNeedsTwoSegments, "si",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "%1 needs a joint between two segments (the contour has %2)")},
    {Code::NoSuchJoint, "ii",
     CAM_TRANSLATE_NOOP("Diagnostic", "there is no joint %1: joints are numbered 0 .. %2")},
    {Code::DesignEndNotAfterStart, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be after %1°, where this segment starts (got %2°)")},
    {Code::DesignEndBeyondTurn, "n",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be at most 360° (got %1°)")},
    {Code::DwellLiftChanges, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic", "a dwell keeps the lift it starts with (%1), got %2")},
    {Code::LiftUnchanged, "nl",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "must differ from the lift it starts with (%1) for %2; a stretch without "
                        "motion is a dwell")},
    {Code::DesignLastNot360, "n",
     CAM_TRANSLATE_NOOP("Diagnostic", "the last segment must end at 360° (got %1°)")},
    {Code::DesignNotReturning, "n",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the motion must return to the start: the last lift must be 0 (got %1)")},
    {Code::DesignVelocityJump, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic", "the velocity jumps from %1 to %2 per degree")},
    {Code::DesignAccelerationJump, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic", "the acceleration jumps from %1 to %2 per degree²")},
    {Code::DesignVelocityAndAccelerationJump, "nnnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the velocity jumps from %1 to %2 per degree; the acceleration jumps from "
                        "%3 to %4 per degree²")},
    {Code::DesignBoundaryMismatch, "lssnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "%1 cannot meet the %2 at its %3: its velocity there is %4 per degree, "
                        "the neighbour's %5 (Suggest picks a law that can)")},
    {Code::SccaSharesExceedOne, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "b + d must be at most 1, the constant acceleration taking the rest "
                        "(got %1 + %2)")},
    {Code::MotionTableTooFew, "i",
     CAM_TRANSLATE_NOOP("Diagnostic", "a motion table needs at least 2 points (got %1)")},
    {Code::MotionTableTooMany, "ii",
     CAM_TRANSLATE_NOOP("Diagnostic", "a motion table takes at most %1 points (got %2)")},
    {Code::MotionTableNotIncreasing, "inn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "point %1: x must be greater than the point before's (%2), got %3")},
    {Code::MotionTableEnds, "nnnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "must run from (0, 0) to (1, 1), normalised (got (%1, %2) to (%3, %4))")},
    {Code::MotionTableColumns, "i",
     CAM_TRANSLATE_NOOP("Diagnostic", "must hold x y or x y dy/dx (got %1 columns)")},
    {Code::MotionTableNotANumber, "t", CAM_TRANSLATE_NOOP("Diagnostic", "is not a number: \"%1\"")},
    {Code::MotionTableSingular, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "no spline runs through these points (their spacing is too uneven)")},
    {Code::Missing, "", CAM_TRANSLATE_NOOP("Diagnostic", "missing")},
    {Code::UnknownKey, "", CAM_TRANSLATE_NOOP("Diagnostic", "unknown key")},
    {Code::WrongType, "ss", CAM_TRANSLATE_NOOP("Diagnostic", "must be %1 (got %2)")},
    {Code::PointShape, "i",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be an array [x, y] of two numbers (got %1 elements)")},
    {Code::NotOneOf, "ttt", CAM_TRANSLATE_NOOP("Diagnostic", "must be %1 or %2 (got \"%3\")")},
    {Code::NotTheValue, "tt", CAM_TRANSLATE_NOOP("Diagnostic", "must be %1 (got \"%2\")")},
    {Code::UnknownSegmentType, "t",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "unknown segment type \"%1\" (expected \"arc\", \"line\", \"bezier\" or \"hermite\")")},
    {Code::UnknownLaw, "tt",
     CAM_TRANSLATE_NOOP("Diagnostic", "unknown law \"%1\" (expected one of %2)")},
    {Code::SpeedNotExactlyOne, "i",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "must give exactly one of omega_rad_s, rpm, period_s (got %1)")},
    {Code::NotWholeSampleCount, "n",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be a whole number between 16 and 10000000 (got %1)")},
    {Code::NewerFormatVersion, "t",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "this file has format version %1; this Camwright reads version 1 only — "
                        "open it with a newer Camwright")},
    {Code::NotFormatVersion1, "t", CAM_TRANSLATE_NOOP("Diagnostic", "must be 1 (got %1)")},
    {Code::BezierPointCount, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be an array of four points [x, y]")},
    {Code::JsonDuplicatedKey, "", CAM_TRANSLATE_NOOP("Diagnostic", "duplicated key")},
    {Code::JsonNumberTooLarge, "t",
     CAM_TRANSLATE_NOOP("Diagnostic", "number %1 is too large for a double")},
    {Code::JsonSyntax, "t", CAM_TRANSLATE_NOOP("Diagnostic", "%1")},
    {Code::JsonTooDeep, "i", CAM_TRANSLATE_NOOP("Diagnostic", "nesting deeper than %1 levels")},
    {Code::JsonNulByte, "i",
     CAM_TRANSLATE_NOOP("Diagnostic", "a NUL byte (at byte offset %1): a project file is text")},
    {Code::JsonInvalid, "", CAM_TRANSLATE_NOOP("Diagnostic", "not valid JSON")},
    {Code::RowValueCount, "tti",
     CAM_TRANSLATE_NOOP("Diagnostic", "expected %1 or %2 (got %3 values)")},
    {Code::RowValueCountExact, "ti",
     CAM_TRANSLATE_NOOP("Diagnostic", "expected %1 (got %2 values)")},
    {Code::RowValueNotFinite, "tt",
     CAM_TRANSLATE_NOOP("Diagnostic", "%1 must be a finite number (got \"%2\")")},
    {Code::FilletContourInvalid, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "the contour is not valid, so the joint cannot be rounded")},
    {Code::FilletNeedsArcsAndLines, "k",
     CAM_TRANSLATE_NOOP("Diagnostic", "fillets join arcs and lines; %1 is neither")},
    {Code::FilletAlreadyTangent, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the segments already meet tangentially (their tangents differ by %1°, at "
                        "most %2° counts as tangent); there is no corner to round")},
    {Code::FilletRadiusNeedsArcsAndLines, "nk",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "radius %1 mm does not fit: fillets join arcs and lines; %2 is neither")},
    {Code::FilletRadiusAlreadyTangent, "nnn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "radius %1 mm does not fit: the segments already meet tangentially (their tangents differ "
         "by %2°, at most %3° counts as tangent); there is no corner to round")},
    {Code::FilletNothingFits, "nr",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "no fillet radius of at least %1 mm fits at this joint (%2)")},
    {Code::FilletRadiusNothingFits, "nnr",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "radius %1 mm does not fit: no fillet radius of at least %2 mm fits at this joint (%3)")},
    {Code::FilletRadiusTooSmall, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "radius %1 mm is too small: a fillet radius is at least %2 mm, the "
                        "smallest radius a project holds")},
    {Code::FilletRadiusNotPositive, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic", "radius %1 mm must be a number > 0: radii below %2 mm fit")},
    {Code::FilletRadiusTooLarge, "nnr",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "radius %1 mm is too large: only radii below %2 mm fit (%3)")},
    {Code::FilletRadiusInGap, "nrn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "radius %1 mm does not fit (%2), although most radii below %3 mm do")},
    {Code::FilletLeavesSegment, "k",
     CAM_TRANSLATE_NOOP("Diagnostic", "the tangent point would leave %1")},
    {Code::FilletNoCircle, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "no circle of that radius touches both neighbours inside the corner")},
    {Code::FilletNoLargerCircle, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "no larger circle touches both neighbours inside the corner")},
    {Code::FilletRayNotOnce, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the follower ray would not meet the fillet arc exactly once: it would "
                        "pass the rotation centre or turn back as seen from it")},
    {Code::FilletRadiusLimit, "", CAM_TRANSLATE_NOOP("Diagnostic", "radii are limited to 1e6 mm")},
    {Code::RollerNotSmallerThanArc, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the roller radius %1 mm is not smaller than this concave arc's radius %2 "
                        "mm: the roller cannot follow it")},
    {Code::PivotInsideCam, "nnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "is inside the cam: the pivot turns on a circle of radius %1 mm round the "
                        "cam centre, but the profile reaches %2 mm at %3°; move it farther out")},
    {Code::ArmTooShort, "nnsn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "is too short: at %1° the cam is %2 mm from the pivot, and %3 reaches only %4 mm")},
    {Code::ArmTooLong, "nsn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "is too long: at %1° %2 passes beyond the whole cam (at most %3 mm from the pivot)")},
    {Code::ArmNoContact, "sn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "does not let %1 touch the cam at %2° (no contact on the chosen side of the arm)")},
    {Code::ToolAboveCurveRadius, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the tool radius %1 mm is larger than this curve's tightest concave radius "
                        "%2 mm: the offset path degenerates")},
    {Code::ToolNotBelowArcRadius, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the tool radius %1 mm is not smaller than the radius %2 mm of this "
                        "concave arc: the offset path degenerates")},
    {Code::OffsetCornerUnmet, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "the offset segments do not meet at this corner")},
    {Code::ToolTrimsSegment, "n",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the tool radius %1 mm is too large here: at its concave corners the "
                        "offset of this segment would have to be trimmed beyond its ends")},
    {Code::GrooveOuterFlankUndercut, "nnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "undercuts the groove's outer flank: for a roller of %1 mm with %2 mm "
                        "clearance this concave stretch of radius %3 mm must be wider than twice "
                        "the roller radius plus the clearance")},
    {Code::GrooveNeedsRoller, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "a groove needs a roller follower: a knife or a flat face cannot run in "
                        "a groove; choose a roller or the spring closure")},
    {Code::GrooveToolTooWide, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the tool radius %1 mm is wider than the groove: at most half its width, "
                        "%2 mm (the roller radius plus half the clearance)")},
    {Code::GrooveToolTooNarrow, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the tool radius %1 mm is too small to clear the groove in a roughing pass "
                        "on its centre line and a finishing pass along each flank: at least %2 mm "
                        "(a sixth of its width)")},
    {Code::GrooveNoCompensation, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "a groove is milled on computed tool-centre paths: a controller's cutter "
                        "compensation (G41/G42) cannot follow both flanks")},
    {Code::ConjugateNeedsRoller, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "a conjugate pair needs a roller follower: its second roller runs on the "
                        "same line (a yoke) or on a second arm of the same pivot (a bell crank)")},
    {Code::ConjugateRollerNotBeyondCentre, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "must put the second roller beyond the cam centre at every angle: at %1° "
                        "its centre is only %2 mm behind it")},
    {Code::ConjugatePlateNotRoundCentre, "n",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "must let the second plate turn round the cam centre with the cam: at %1° "
                        "the second roller moves backwards round it or reaches across it")},
    {Code::ConjugatePlateFolds, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the second roller of %1 mm is wider than its path's bend at %2°: the "
                        "second plate would fold over")},
    {Code::LandRadiiCrossed, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "must be larger than the inner land radius %1 mm (got %2 mm): the groove "
                        "runs between the two")},
    {Code::SeedStepTooSmall, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be a finite length of at least %1 mm (got %2)")},
    {Code::SeedStepTooMany, "nnnnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "%1 mm makes %2 steps on this %3 mm path; the seed method takes at most "
                        "%4: a step of at least %5 mm")},
    {Code::AccelerationLimitMissing, "ai",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "no acceleration limit for the %1 axis, along which the path moves "
                        "(segment %2): without one its speed would be unbounded and its time 0")},
    {Code::PathEmpty, "", CAM_TRANSLATE_NOOP("Diagnostic", "is empty")},
    {Code::PathPointInvalid, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "coordinates must be finite, at most 1e6 mm, and the bulge finite")},
    {Code::PathTooFewPoints, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "a path needs at least two points")},
    {Code::PathPointRepeated, "", CAM_TRANSLATE_NOOP("Diagnostic", "repeats the previous point")},
    {Code::PathArcChangesHeight, "nnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "an arc (bulge %1) must keep its height, but z goes from %2 to %3")},
    {Code::PathArcNoChord, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "an arc needs two distinct points in the XY plane")},
    {Code::PathArcTooFar, "nnn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "the arc (bulge %1) reaches %2 mm from the origin; a path must stay within %3 mm")},
    {Code::TangentNeedsArcs, "ks",
     CAM_TRANSLATE_NOOP("Diagnostic", "a tangent line joins two arcs; %1 is %2")},
    {Code::TangentNotCircle, "k",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "%1 is not a circle (its radius must be a finite number > 0, its centre finite)")},
    {Code::TangentSameCircle, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "both arcs lie on the same circle, so they already meet tangentially: no "
                        "line fits between them")},
    {Code::TangentCircleInside, "kk",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "the circle of %1 lies inside that of %2, so the two circles have no common tangent")},
    {Code::TangentNoneFits, "r", CAM_TRANSLATE_NOOP("Diagnostic", "no tangent line fits: %1")},
    {Code::TangentTouch, "nn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "the circles touch at (%1, %2): the arcs can meet there directly, without a line")},
    {Code::TangentClockwise, "snnknnk",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "%1 from (%2, %3) on %4 to (%5, %6) on %7 runs clockwise around the rotation "
         "centre (its polar angle would not grow from %4 to %7)")},
    {Code::TangentOnNearSide, "snnknnkk",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "%1 from (%2, %3) on %4 to (%5, %6) on %7 touches %8 on the near side of its "
         "circle, but the arc follows the far side (outer branch)")},
    {Code::TangentOnFarSide, "snnknnkk",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "%1 from (%2, %3) on %4 to (%5, %6) on %7 touches %8 on the far side of its "
         "circle, but the arc follows the near side (inner branch)")},
    {Code::TangentEmptiesLeft, "snnknnkn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "with %1 from (%2, %3) on %4 to (%5, %6) on %7 the window of "
                        "%4 would be empty: its end would move onto its start %8°")},
    {Code::TangentReversesRight, "snnknnknn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "with %1 from (%2, %3) on %4 to (%5, %6) on %7 the window of %7 would be "
                        "empty or reversed: its start would move to %8°, not before its end %9°")},
    {Code::ArcNoSegment, "", CAM_TRANSLATE_NOOP("Diagnostic", "has no segment to continue")},
    {Code::ArcNoSuchRow, "ki",
     CAM_TRANSLATE_NOOP("Diagnostic", "there is no %1: rows are 0 .. %2")},
    {Code::ArcSingleNotCircle, "ks",
     CAM_TRANSLATE_NOOP("Diagnostic", "a contour of one segment must be a circle; %1 is %2")},
    {Code::ArcRowNotCircle, "k", CAM_TRANSLATE_NOOP("Diagnostic", "%1 is not a circle")},
    {Code::ArcRayMissesEnd, "nk",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "the follower ray at the end %1° of %2 misses its circle, so it has no end point")},
    {Code::ArcNoEndDirection, "k",
     CAM_TRANSLATE_NOOP("Diagnostic", "%1 has no direction at its end point")},
    {Code::ArcEndClockwise, "knn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "%1 does not run counter-clockwise around the rotation centre at its end "
                        "point (%2, %3) (its polar angle does not grow there)")},
    {Code::ArcPointNotFinite, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic", "the point must be finite (got (%1, %2))")},
    {Code::ArcPointAtCentre, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the point is the rotation centre, which no arc of the contour can reach")},
    {Code::ArcPointIsEnd, "nnk",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the point is the end point (%1, %2) of %3: an arc needs a second point")},
    {Code::ArcPointOnTangent, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the point is on the tangent: use a line (an arc through it would need a "
                        "radius or centre beyond 1e6 mm, the largest length a project holds)")},
    {Code::ArcRadiusTooSmall, "nn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "the arc's radius would be %1 mm, below %2 mm, the smallest a project holds")},
    {Code::ArcEndOffOuter, "knnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the end point of %1 is not on the outer branch of the circle (centre (%2, "
                        "%3), radius %4 mm)")},
    {Code::ArcEndOffInner, "knnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the end point of %1 is not on the inner branch of the circle (centre (%2, "
                        "%3), radius %4 mm)")},
    {Code::ArcPointOnNearSide, "nnnk",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "the point lies on the near side of the circle (centre (%1, %2), radius %3 mm) as seen "
         "from the rotation centre, but the arc leaves %4 on its far side (outer branch): the "
         "follower ray would not meet the arc at the point")},
    {Code::ArcPointOnFarSide, "nnnk",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "the point lies on the far side of the circle (centre (%1, %2), radius %3 mm) as seen "
         "from the rotation centre, but the arc leaves %4 on its near side (inner branch): the "
         "follower ray would not meet the arc at the point")},
    {Code::ArcRunsBackNear, "knnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the point lies behind the end point of %1 as seen from the rotation "
                        "centre: the arc along the circle (centre (%2, %3), radius %4 mm) would "
                        "pass to its near side and run back before reaching it")},
    {Code::ArcRunsBackFar, "knnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the point lies behind the end point of %1 as seen from the rotation "
                        "centre: the arc along the circle (centre (%2, %3), radius %4 mm) would "
                        "pass to its far side and run back before reaching it")},
    {Code::ArcPointOnEndRay, "nk",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the point lies on the follower ray at the end %1° of %2: the arc's window "
                        "would be empty")},
    {Code::ArcEndsAfterNext, "nnk",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the arc would end at %1° (the polar angle of the point), not before the "
                        "end %2° of %3, whose window would be empty or reversed")},
    {Code::ArcPointIsNextEnd, "k",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the point is the end point of %1, which would have no length left")},
    {Code::ArcNextClockwise, "knn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "with its start point moved to the point, %1 would no longer run "
                        "counter-clockwise from %2° to its end %3°")},
    {Code::ExportToleranceOutOfRange, "nnn",
     CAM_TRANSLATE_NOOP("Diagnostic", "the tolerance must be between %1 and %2 mm, not %3")},
    {Code::ExportToolRadiusOutOfRange, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic", "the tool radius must be above 0 and at most %1 mm, not %2")},
    {Code::GcodeCompensationCutsPart, "",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "with cutter compensation the tool would have to reach past the next programmed arc at a "
         "concave corner of this segment, which a controller offsetting one move at a time turns "
         "into a cut through the part; export the tool-centre path (without --compensation) or use "
         "a coarser --tolerance")},
    {Code::GcodeLengthOutOfRange, "snn",
     CAM_TRANSLATE_NOOP("Diagnostic", "%1 must be above 0 and at most %2 mm, not %3")},
    {Code::GcodeFeedOutOfRange, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic", "the feed must be above 0 and at most %1 mm/min, not %2")},
    {Code::GcodeToolNumber, "i",
     CAM_TRANSLATE_NOOP("Diagnostic", "the tool number must be from 1 to 99999, not %1")},
    {Code::GcodeTooManyPasses, "nnni",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "a step-down of %1 mm makes %2 passes for a depth of %3 mm; at most %4 are made")},
    {Code::CamTablePoints, "iii",
     CAM_TRANSLATE_NOOP("Diagnostic", "a cam table has from %1 to %2 points, not %3")},
    {Code::SampleNotFinite, "n",
     CAM_TRANSLATE_NOOP(
         "Diagnostic", "is not a finite number (%1): the result is beyond what a double can hold")},
    {Code::NoPoints, "", CAM_TRANSLATE_NOOP("Diagnostic", "must be at least 1 (got 0)")},
    {Code::NotFiniteForFile, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "is not a finite number, which a file cannot hold")},
    {Code::FileCannotOpen, "t", CAM_TRANSLATE_NOOP("Diagnostic", "cannot open: %1")},
    {Code::FileCannotExamineOpen, "t", CAM_TRANSLATE_NOOP("Diagnostic", "cannot examine: %1")},
    {Code::FileCannotRead, "t", CAM_TRANSLATE_NOOP("Diagnostic", "cannot read: %1")},
    {Code::FileNotRegularToRead, "s",
     CAM_TRANSLATE_NOOP("Diagnostic", "is %1, not a regular file: not read")},
    {Code::FileTooLargeToRead, "dii",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "is %1 MiB (%2 bytes): files larger than %3 MiB are not read")},
    {Code::FileGrewTooLarge, "i",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "grew past %1 MiB while it was read: larger files are not read")},
    {Code::FileNoName, "", CAM_TRANSLATE_NOOP("Diagnostic", "no file name given")},
    {Code::FileCannotExamine, "tt", CAM_TRANSLATE_NOOP("Diagnostic", "cannot examine %1: %2")},
    {Code::FileLinkLoop, "t",
     CAM_TRANSLATE_NOOP("Diagnostic", "cannot follow its symbolic links: %1")},
    {Code::FileCannotReadLink, "tt",
     CAM_TRANSLATE_NOOP("Diagnostic", "cannot read the symbolic link %1: %2")},
    {Code::FileIsDescriptorLink, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "is a link to an open file descriptor, not a file: not replaced")},
    {Code::FileLinkTargetIsDescriptorLink, "t",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "%1 is a link to an open file descriptor, not a file: not replaced")},
    {Code::FileNotRegular, "s",
     CAM_TRANSLATE_NOOP("Diagnostic", "is %1, not a regular file: not replaced")},
    {Code::FileLinkTargetNotRegular, "ts",
     CAM_TRANSLATE_NOOP("Diagnostic", "%1 is %2, not a regular file: not replaced")},
    {Code::FileCannotWrite, "tt", CAM_TRANSLATE_NOOP("Diagnostic", "cannot write %1: %2")},
    {Code::FileNamesFolder, "", CAM_TRANSLATE_NOOP("Diagnostic", "names a folder, not a file")},
    {Code::FileCannotCreateTemporary, "tt",
     CAM_TRANSLATE_NOOP("Diagnostic", "cannot create a temporary file in %1: %2")},
    {Code::FileCannotCopyOwner, "tt",
     CAM_TRANSLATE_NOOP("Diagnostic", "cannot give the new file the owner of %1: %2")},
    {Code::FileCannotCopyPermissions, "tt",
     CAM_TRANSLATE_NOOP("Diagnostic", "cannot give the new file the permissions of %1: %2")},
    {Code::FileCannotFlush, "tt", CAM_TRANSLATE_NOOP("Diagnostic", "cannot flush %1 to disk: %2")},
    {Code::FileBecameOther, "ts",
     CAM_TRANSLATE_NOOP("Diagnostic", "%1 became %2 while it was written: not replaced")},
    {Code::FileCannotReplace, "tt", CAM_TRANSLATE_NOOP("Diagnostic", "cannot replace %1: %2")},
    {Code::FileReplacedCannotClose, "tt",
     CAM_TRANSLATE_NOOP("Diagnostic", "replaced, but cannot close %1: %2")},
    {Code::FileReplacedCannotFlushFolder, "tt",
     CAM_TRANSLATE_NOOP("Diagnostic", "replaced, but cannot flush the folder %1 to disk: %2")},
    {Code::NoSuchSegment, "", CAM_TRANSLATE_NOOP("Diagnostic", "no such segment")},
    {Code::NotAnArc, "", CAM_TRANSLATE_NOOP("Diagnostic", "is not an arc")},
    {Code::RadialErrorNotPositive, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "the admissible radial error must be > 0 mm")},
    {Code::ApproximationStartMissesArc, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "the ray at the window's start does not meet the arc")},
    {Code::ApproximationEndMissesArc, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "the ray at the window's end does not meet the arc")},
    {Code::SplineTooFewPoints, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "a spline needs at least two points")},
    {Code::ClosedSplineTooFewPoints, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "a closed spline needs at least three points")},
    {Code::BulgeNotPositive, "n",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be a finite factor > 0 (got %1)")},
    {Code::WindowsSegmentsDoNotMeet, "n",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the neighbouring segments miss each other by %1 mm, more than the typing "
                        "tolerance of 1e-05 mm, so there is no boundary to fit")},
    {Code::WindowsMoveTooLarge, "kn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "making the neighbouring segments meet would move %1 by %2 mm in all, more "
                        "than the typing tolerance of 1e-05 mm")},
    {Code::WindowsMovesDoNotSettle, "ni",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the neighbouring segments still miss each other by %1 mm after %2 rounds "
                        "of moves; type the centres more exactly")},
    {Code::WindowsCircleMoved, "nnnnnk",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "moved by %1 mm, from (%2, %3) to (%4, %5), so that the circle touches %6 "
                        "(they missed each other by less than the typing tolerance of 1e-05 mm)")},
    {Code::WindowsCircleResized, "nnnnnnnkk",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "changed by %1 mm, centre (%2, %3) and radius %4 mm to centre (%5, %6) "
                        "and radius %7 mm, so that the circle touches both %8 and %9 (they "
                        "missed each other by less than the typing tolerance of 1e-05 mm)")},
    {Code::WindowsCircleMadeSame, "knnnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "made the same circle as %1: moved by %2 mm, to centre (%3, %4) and "
                        "radius %5 mm (the two pieces differed by less than the typing tolerance "
                        "of 1e-05 mm)")},
    {Code::WindowsLineMoved, "nk",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "moved by %1 mm across its direction so that it meets %2 (they missed "
                        "each other by less than the typing tolerance of 1e-05 mm)")},
    {Code::ContourNeverSynthesised, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "is empty: the design's contour was never synthesised (camwright-cli "
                        "synthesize makes it)")},
    {Code::NoDesign, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "the project has no design to synthesise a contour from")},
    {Code::SynthesisedContourInvalid, "r",
     CAM_TRANSLATE_NOOP("Diagnostic", "the synthesised arc table is not a valid contour: %1")},
    {Code::SynthesisedArcInvalid, "knnr",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the synthesised arc table is not a valid contour: %1, made for the cam "
                        "angles %2° to %3° (%4)")},
    {Code::ToleranceCannotBeMet, "ni",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "cannot be met near %1°: no arcs come within it even on pieces of 2^-%2 of "
                        "the profile's sampling step (the profile has a corner or a cusp there)")},
    {Code::ToleranceBelowPrecision, "nnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "%1 mm is below what double precision can certify for this cam: at least "
                        "%2 mm, for a profile reaching %3 mm from the centre")},
    {Code::ToleranceNotReached, "nnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "cannot be met: the closest arc table found lies %2 mm from the exact "
                        "profile (at %3° of cam angle), more than the %1 mm asked for")},
    {Code::OffsetOutsideBaseCircle, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "the follower's line (offset %1 mm) passes outside the base circle of "
                        "radius %2 mm: make the base radius larger than the offset")},
    {Code::OffsetOutsidePitchBaseCircle, "nn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "the follower's line (offset %1 mm) passes outside the base circle of radius %2 mm (base "
         "radius + roller radius): make the base radius larger than the offset")},
    {Code::ArmMissesBaseCircle, "nnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "an arm of %1 mm from a pivot %2 mm from the centre cannot touch the base "
                        "circle of radius %3 mm")},
    {Code::ArmMissesPitchBaseCircle, "nnn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "an arm of %1 mm from a pivot %2 mm from the centre cannot touch the base "
                        "circle of radius %3 mm (base radius + roller radius)")},
    {Code::UndercutRoller, "nnn",
     CAM_TRANSLATE_NOOP(
         "Diagnostic",
         "undercut: the pitch curve bends tighter than the roller radius %1 mm from %2° to %3°")},
    {Code::UndercutFlatFace, "nn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "undercut: the face's envelope folds back (h + h'' < 0) from %1° to %2°")},
    {Code::PressureAngleExceeded, "nnn",
     CAM_TRANSLATE_NOOP("Diagnostic", "the pressure angle exceeds %1° from %2° to %3°")},
    {Code::FilletRadiusInvalidContour, "nr",
     CAM_TRANSLATE_NOOP("Diagnostic", "radius %1 mm gives a contour that does not validate (%2)")},
    {Code::NoBaseRadiusPasses, "sn",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "no base radius up to 1000000 mm passes every check: %1 fails at %2°")},
    {Code::DynamicsKeyForArm, "",
     CAM_TRANSLATE_NOOP("Diagnostic", "is for a swinging arm; this project's follower translates")},
    {Code::DynamicsKeyForTranslating, "",
     CAM_TRANSLATE_NOOP("Diagnostic",
                        "is for a translating follower; this project's follower swings on an "
                        "arm")},
    {Code::PoissonOutOfRange, "n",
     CAM_TRANSLATE_NOOP("Diagnostic", "must be at least 0 and below 0.5 (got %1)")},
    {Code::Cancelled, "", CAM_TRANSLATE_NOOP("Diagnostic", "cancelled")},
}};

static_assert(rowsFollowTheirEnum(kCatalogue, &DiagnosticEntry::code),
              "the catalogue lists every code once, in DiagnosticCode order");

/// The type a signature letter's argument holds.
bool argumentHoldsKind(char kind, const DiagnosticArg& arg) {
    switch (kind) {
        case 's':
        case 't':
        case 'l':
            return std::holds_alternative<std::string>(arg);
        case 'f':
            return std::holds_alternative<SegmentPart>(arg);
        default:
            return std::holds_alternative<double>(arg);
    }
}

std::string wholeNumber(double value) {
    if (!(std::abs(value) < 9e18)) return formatNumber(value);
    return std::to_string(std::llround(value));
}

std::string oneDecimal(double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.1f", value);
    return buffer;
}

std::string axisName(double index) {
    static constexpr const char* kAxes[] = {"x", "y", "z"};
    return index >= 0.0 && index < 3.0 ? kAxes[static_cast<int>(index)] : formatNumber(index);
}

/// The reasons' texts, "a; b; c".
std::string reasonsText(const Diagnostics& reasons) {
    std::string out;
    for (const Diagnostic& reason : reasons) {
        if (!out.empty()) out += "; ";
        out += reason.text();
    }
    return out;
}

}  // namespace

const DiagnosticEntry& diagnosticEntry(DiagnosticCode code) {
    const auto i = static_cast<std::size_t>(code);
    return kCatalogue[i < kCatalogue.size() ? i : 0];
}

std::string_view diagnosticCodeSignature(DiagnosticCode code) {
    return diagnosticEntry(code).signature;
}

const char* diagnosticTemplate(DiagnosticCode code) { return diagnosticEntry(code).text; }

bool argumentsFit(DiagnosticCode code, const std::vector<DiagnosticArg>& args) {
    if (static_cast<std::size_t>(code) >= kDiagnosticCodeCount) return false;
    std::size_t next = 0;
    for (const char kind : diagnosticCodeSignature(code)) {
        if (kind == 'r') continue;
        if (next == args.size() || !argumentHoldsKind(kind, args[next])) return false;
        ++next;
    }
    return next == args.size();
}

std::string fillPlaceholders(std::string_view text, const std::vector<std::string>& values) {
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
        const auto digit = [&](std::size_t at) {
            return at < text.size() && text[at] >= '0' && text[at] <= '9';
        };
        if (text[i] != '%' || !digit(i + 1)) {
            out += text[i++];
            continue;
        }
        // Up to two digits, as Qt reads a placeholder: %1 … %99.
        std::size_t end = i + 2;
        if (digit(end)) ++end;
        const int n = std::stoi(std::string(text.substr(i + 1, end - i - 1)));
        if (n >= 1 && static_cast<std::size_t>(n) <= values.size()) {
            out += values[static_cast<std::size_t>(n) - 1];
        } else {
            out.append(text.substr(i, end - i));
        }
        i = end;
    }
    return out;
}

std::string englishArgument(char kind, const DiagnosticArg& arg) {
    if (const auto* text = std::get_if<std::string>(&arg)) return *text;
    if (const auto* part = std::get_if<SegmentPart>(&arg))
        return std::string(segmentPartKey(*part));
    const double value = std::get<double>(arg);
    switch (kind) {
        case 'i':
            return wholeNumber(value);
        case 'd':
            return oneDecimal(value);
        case 'k':
            return value >= 0.0 ? segmentLocation(static_cast<std::size_t>(value))
                                : formatNumber(value);
        case 'a':
            return axisName(value);
        default:
            return formatNumber(value);
    }
}

std::string englishMessage(DiagnosticCode code, const std::vector<DiagnosticArg>& args,
                           const Diagnostics& reasons) {
    std::vector<std::string> values;
    std::size_t next = 0;
    for (const char kind : diagnosticCodeSignature(code)) {
        if (kind == 'r') {
            values.push_back(reasonsText(reasons));
        } else if (next < args.size()) {
            values.push_back(englishArgument(kind, args[next++]));
        }
    }
    return fillPlaceholders(diagnosticTemplate(code), values);
}

}  // namespace cam
