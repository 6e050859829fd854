#include "cli/commands.h"

#include <cmath>
#include <optional>
#include <ostream>

#include "cli/command_support.h"
#include "common/angles.h"
#include "design/motion_design.h"
#include "design/sizing.h"
#include "evaluation/evaluation.h"

namespace cam::cli {

int runSize(const Arguments& args, std::ostream& out, std::ostream& /*err*/) {
    const std::string& path = args.positional.front();
    SizingOptions options;
    if (const auto text = args.option("--min-radius")) {
        options.minRadius = parseFiniteNumber("--min-radius", *text, "a radius in mm");
        if (options.minRadius < 0.0) {
            throw CliError{kInvalidInput, "--min-radius",
                           "must be ≥ 0 mm (got " + formatNumber(options.minRadius) + ")"};
        }
    }
    // A design whose contour was never synthesised is what sizing is for: the project is
    // checked as synthesize checks it, not by load().
    Project project = loadStructure(path);
    if (!project.design) {
        throw CliError{kInvalidInput, path + ": design",
                       "the project has no design to size (size finds its base radius)"};
    }
    for (const Diagnostic& d : designProblems(project)) {
        if (d.severity != Severity::Error) continue;
        throw CliError{kInvalidInput, placeOf(path, d), d.message};
    }
    FollowerSpec follower = project.follower.value_or(FollowerSpec{});
    // --best-offset moves a translating knife's or roller's offset, --best-pivot an arm's pivot.
    const bool bestOffset = args.hasFlag("--best-offset"), bestPivot = args.hasFlag("--best-pivot");
    if (bestOffset && bestPivot) {
        throw CliError{kInvalidInput, "--best-pivot",
                       "give --best-offset (a translating follower) or --best-pivot (a swinging "
                       "arm), not both"};
    }
    const auto placement = placementOf(follower);
    if (bestOffset && placement != Placement::Offset) {
        throw CliError{kInvalidInput, "--best-offset",
                       follower.motion == FollowerMotion::Oscillating
                           ? "sizes the offset of a translating knife or roller; this project's "
                             "follower swings on an arm: --best-pivot sizes its pivot"
                           : "sizes the offset of a translating knife or roller; a flat face's "
                             "pressure angle is 0 at any offset"};
    }
    if (bestPivot && placement != Placement::PivotDistance) {
        throw CliError{kInvalidInput, "--best-pivot",
                       "sizes the pivot of a swinging arm; this project's follower translates" +
                           std::string(placement ? ": --best-offset sizes its offset" : "")};
    }
    const auto fail = [&path](const Diagnostics& errors) {
        const Diagnostic& d = errors.front();
        return CliError{kNotComputable, path + ": " + d.location, d.message};
    };
    std::optional<PlacementSizing> placed;
    if (bestOffset || bestPivot) {
        auto sized = sizePlacement(*project.design, follower, options);
        if (!sized.ok()) throw fail(sized.errors());
        placed = std::move(sized).value();
    }
    const auto sized = placed ? Result<SizingResult>(placed->sizing)
                              : sizeBaseRadius(*project.design, follower, options);
    if (!sized.ok()) throw fail(sized.errors());
    const SizingResult& r = sized.value();
    const auto degreesOrNull = [](const std::optional<double>& rad) {
        return rad ? Json(radToDeg(*rad)) : Json(nullptr);
    };
    Json report{
        {"base_radius_mm", r.baseRadius},
        {"binding", sizingCheckName(r.binding)},
        {"at_deg", radToDeg(r.bindingPhi)},
        {"was_mm", project.design->baseRadius},
        {"min_radius_mm", options.minRadius},
        {"limit_deg", follower.maxPressureAngleOrDefault()},
        {"pressure_angle_rise_deg", degreesOrNull(r.pressureRise)},
        {"pressure_angle_return_deg", degreesOrNull(r.pressureReturn)},
        {"min_convex_radius_mm", r.minConvexRadius ? Json(*r.minConvexRadius) : Json(nullptr)}};
    if (r.faceWidth) report["face_width_mm"] = *r.faceWidth;
    const FollowerSpec moved =
        placed ? placedAt(follower, placed->placement, placed->value) : follower;
    if (placed) {
        const bool offset = placed->placement == Placement::Offset;
        if (offset) {
            report["offset_mm"] = moved.offset;
            report["offset_was_mm"] = follower.offset;
        } else {
            report["pivot_mm"] = {moved.pivot.x(), moved.pivot.y()};
            report["pivot_distance_mm"] = placed->value;
            report["pivot_was_mm"] = {follower.pivot.x(), follower.pivot.y()};
        }
        const auto mmOrNull = [](double mm) { return std::isfinite(mm) ? Json(mm) : Json(); };
        Json region = Json::array();
        for (const FeasibleSpan& span : placed->region) {
            Json point{{offset ? "offset_mm" : "pivot_distance_mm", span.placement},
                       {"base_radius_mm", mmOrNull(span.smallest)}};
            if (!offset) point["largest_base_radius_mm"] = mmOrNull(span.largest);
            region.push_back(std::move(point));
        }
        report["feasible_edge"] = std::move(region);
    }
    if (const auto outPath = args.option("--out")) {
        report["out"] = *outPath;
        project.design->baseRadius = r.baseRadius;
        if (placed) project.follower = moved;
        writeProjectOut(*outPath, project, report);
    }
    printJson(out, report);
    return kOk;
}

}  // namespace cam::cli
