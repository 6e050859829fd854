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
    const bool bestOffset = args.hasFlag("--best-offset");
    if (bestOffset && !offsetSizable(follower)) {
        throw CliError{kInvalidInput, "--best-offset",
                       "sizes the offset of a translating knife or roller; this project's "
                       "follower has none that matters (a flat face, or a swinging arm)"};
    }
    const auto fail = [&path](const Diagnostics& errors) {
        const Diagnostic& d = errors.front();
        return CliError{kNotComputable, path + ": " + d.location, d.message};
    };
    std::optional<OffsetSizing> offsetSizing;
    if (bestOffset) {
        auto sized = sizeOffset(*project.design, follower, options);
        if (!sized.ok()) throw fail(sized.errors());
        offsetSizing = std::move(sized).value();
    }
    const auto sized = offsetSizing ? Result<SizingResult>(offsetSizing->sizing)
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
    if (offsetSizing) {
        report["offset_mm"] = offsetSizing->offset;
        report["offset_was_mm"] = follower.offset;
        Json edge = Json::array();
        for (const auto& [offset, radius] : offsetSizing->edge) {
            edge.push_back({{"offset_mm", offset},
                            {"base_radius_mm", std::isfinite(radius) ? Json(radius) : Json()}});
        }
        report["feasible_edge"] = std::move(edge);
    }
    if (const auto outPath = args.option("--out")) {
        report["out"] = *outPath;
        project.design->baseRadius = r.baseRadius;
        if (offsetSizing) {
            follower.offset = offsetSizing->offset;
            project.follower = follower;
        }
        writeProjectOut(*outPath, project, report);
    }
    printJson(out, report);
    return kOk;
}

}  // namespace cam::cli
