#include "cli/commands.h"

#include <Eigen/Core>
#include <ostream>
#include <vector>

#include "cli/command_support.h"
#include "io/path_csv.h"
#include "io/project_json.h"
#include "spline/teach_in.h"
#include "timing/machining_time.h"
#include "timing/timing_job.h"
#include "toolpath/biarc.h"
#include "toolpath/tool_path.h"

namespace cam::cli {
namespace {

/// A machine limit or length given as an option: within [lo, hi] (the ranges in which the
/// arithmetic is sound, as the project's validation has them).
double checkInRange(const std::string& option, double value, double lo, double hi,
                    const char* unit) {
    if (!(value >= lo && value <= hi)) {
        throw CliError{kInvalidInput, option,
                       "must be between " + formatNumber(lo) + " and " + formatNumber(hi) + " " +
                           unit + " (got " + formatNumber(value) + ")"};
    }
    return value;
}

/// "AX,AY[,AZ]": 2 or 3 finite numbers in [lo, hi]; a missing third axis is unlimited.
Eigen::Vector3d parseAxes(const std::string& option, const std::string& text, double lo, double hi,
                          const char* unit) {
    std::vector<double> values;
    std::size_t begin = 0;
    while (begin <= text.size()) {
        const std::size_t comma = text.find(',', begin);
        const std::string cell =
            text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
        values.push_back(parseFiniteNumber(option, cell, unit));
        if (comma == std::string::npos) break;
        begin = comma + 1;
    }
    if (values.size() < 2 || values.size() > 3) {
        throw CliError{kInvalidInput, option,
                       "expects 2 or 3 comma-separated values (got \"" + text + "\")"};
    }
    for (const double v : values) checkInRange(option, v, lo, hi, unit);
    return {values[0], values[1], values.size() == 3 ? values[2] : kUnlimited};
}

}  // namespace

int runTiming(const Arguments& args, std::ostream& out, std::ostream& /*err*/) {
    // The fastest motion within the limits unless another method is asked for.
    const std::string methodText = args.option("--method").value_or("optimal");
    TimingMethod method;
    if (methodText == "seed") {
        method = TimingMethod::Seed;
    } else if (methodText == "exact-stop") {
        method = TimingMethod::ExactStop;
    } else if (methodText == "optimal") {
        method = TimingMethod::Optimal;
    } else {
        throw CliError{kUsage, "--method",
                       "must be seed, exact-stop or optimal (got \"" + methodText + "\")"};
    }
    const auto pathFile = args.option("--path");
    if (pathFile.has_value() == !args.positional.empty()) {
        throw CliError{kUsage, "timing", "give either PROJECT or --path POINTS.csv"};
    }

    // The tool path: a point list (or spline knots) as given, or the project's contour offset by
    // its tool radius inside the timing job.
    ToolPath given;
    std::optional<Loaded> loaded;
    TimingJob job;
    job.methods = {method};
    bool haveAccel = false;
    if (pathFile) {
        const auto text = readTextFile(*pathFile);
        if (!text.ok()) throw CliError{kInvalidInput, *pathFile, text.errors().front().message};
        const auto points = parsePathCsv(text.value());
        if (!points.ok()) {
            const Diagnostic& d = points.errors().front();
            throw CliError{kInvalidInput, *pathFile + ": " + d.location, d.message};
        }
        if (const auto rule = args.option("--spline")) {
            // The points are teach-in knots of an open Bézier spline (math.md §4), milled as
            // tangent arc pairs within 0.1 µm.
            HandleRule handles;
            if (*rule == "chord") {
                handles = HandleRule::Chord;
            } else if (*rule == "circumcircle") {
                handles = HandleRule::Circumcircle;
            } else if (*rule == "oval") {
                handles = HandleRule::Oval;
            } else {
                throw CliError{kUsage, "--spline",
                               "must be chord, circumcircle or oval (got \"" + *rule + "\")"};
            }
            std::vector<Eigen::Vector2d> knots;
            for (const PathPoint& p : points.value()) {
                if (p.bulge != 0.0 || p.position.z() != points.value().front().position.z()) {
                    throw CliError{kInvalidInput, *pathFile,
                                   "spline knots must lie in one plane z = const without bulges"};
                }
                knots.push_back(p.position.head<2>());
            }
            const auto spline = splineThroughPoints(knots, false, handles);
            if (!spline.ok()) {
                const Diagnostic& d = spline.errors().front();
                throw CliError{kInvalidInput, *pathFile + ": " + d.location, d.message};
            }
            given = toolPathFromSpline(spline.value(), kSplineToleranceMm,
                                       points.value().front().position.z());
        } else {
            auto built = toolPathFromPoints(points.value());
            if (!built.ok()) {
                const Diagnostic& d = built.errors().front();
                throw CliError{kInvalidInput, *pathFile + ": " + d.location, d.message};
            }
            given = std::move(built).value();
        }
    } else {
        loaded = load(args.positional.front());
        if (loaded->project.machining) {
            job = timingJobFor(*loaded->project.machining, {method});
            haveAccel = true;
        }
    }
    if (const auto v = args.option("--accel")) {
        job.limits.accel = parseAxes("--accel", *v, kMinMachineLimit, kMaxAccelMmS2, "mm/s²");
        haveAccel = true;
    }
    if (const auto v = args.option("--vmax")) {
        job.limits.vmax = parseAxes("--vmax", *v, kMinMachineLimit, kMaxSpeedMmS, "mm/s");
    }
    if (const auto v = args.option("--feed")) {
        job.limits.feedMax = checkInRange("--feed", parseFiniteNumber("--feed", *v, "mm/s"),
                                          kMinMachineLimit, kMaxSpeedMmS, "mm/s");
    }
    // The step's bound relative to the path (at most kMaxSeedSteps steps) is the job's, named
    // after where the step came from.
    if (const auto v = args.option("--step")) {
        job.limits.seedStep = checkInRange("--step", parseFiniteNumber("--step", *v, "mm"),
                                           kMinLengthMm, kMaxLengthMm, "mm");
    }
    if (!loaded || args.option("--step")) job.stepField = Field::StepOption;
    if (!haveAccel) {
        throw CliError{kUsage, "--accel",
                       "is required: the project has no machining section or a point list is used"};
    }
    if (!loaded) {
        // Two values leave z without a limit, which is right for a path in a plane; a path that
        // moves along z needs its limit given (issue 27: a plunge took 0 s by the seed method,
        // whose speed then had no bound). No default: any number put in would be a guess at the
        // machine, and a wrong one a wrong time.
        const Diagnostics unlimited = checkMovingAxesLimited(given, job.limits);
        if (!unlimited.empty()) {
            const Diagnostic& d = unlimited.front();
            const auto axis = static_cast<int>(std::get<double>(d.args[0]));
            const auto k = static_cast<std::size_t>(std::get<double>(d.args[1]));
            const char name = static_cast<char>('x' + axis);
            throw CliError{
                kInvalidInput, "--accel",
                std::string("gives no limit for the ") + name +
                    " axis, along which the path moves (segment " + std::to_string(k) +
                    (args.option("--spline") ? std::string()
                                             : ", from point[" + std::to_string(k) + "] to point[" +
                                                   std::to_string(k + 1) + "]") +
                    "): give all three, AX,AY,AZ"};
        }
    }

    const auto timed = loaded ? timeContour(loaded->contour, job) : timePath(std::move(given), job);
    if (!timed.ok()) {
        // A project's errors are located in it (contour[k] when the tool does not fit).
        const Diagnostic& d = timed.errors().front();
        throw CliError{kNotComputable,
                       loaded && !d.location.empty() ? args.positional.front() + ": " + d.location
                                                     : d.location,
                       d.message};
    }
    const ToolPath& path = timed.value().path;
    const TimingResult& r = timed.value().results.front();
    Json json{{"method", timingMethodName(r.method)},
              {"time_s", r.timeS},
              {"length_mm", r.lengthMm},
              {"segments", r.segments.size()}};
    if (r.gridPoints > 0) {
        json["grid_points"] = r.gridPoints;
        json["convergence"] = r.convergence;
        json["converged"] = r.converged;
        if (!r.converged) {
            json["warning"] = "not converged: the grid limit of one plan (" +
                              std::to_string(kMaxPlanPoints) +
                              " points) stopped the refinement before every segment's time had "
                              "settled to 1e-6 of itself; the total's estimated relative error "
                              "is " +
                              formatNumber(r.convergence);
        }
    }
    if (args.hasFlag("--detail")) {
        Json detail = Json::array();
        for (std::size_t k = 0; k < r.segments.size(); ++k) {
            const SegmentTiming& s = r.segments[k];
            detail.push_back(
                Json{{"segment", k},
                     {"kind", path.segments[k].kind == PathSegment::Kind::Line ? "line" : "arc"},
                     {"length_mm", s.lengthMm},
                     {"time_s", s.timeS},
                     {"entry_speed", s.entrySpeed},
                     {"exit_speed", s.exitSpeed}});
        }
        json["detail"] = std::move(detail);
    }
    // No number printed is non-finite: one that is ends the command with exit 3, named.
    printJson(out, json);
    return kOk;
}

}  // namespace cam::cli
