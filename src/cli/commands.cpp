#include "cli/commands.h"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>

#include "analysis/analysis.h"
#include "cli/plot_pictures.h"
#include "common/angles.h"
#include "contour/contour.h"
#include "design/synthesis.h"
#include "evaluation/evaluation.h"
#include "export/cam_table.h"
#include "export/dxf.h"
#include "export/gcode.h"
#include "export/number_text.h"
#include "export/sample_csv.h"
#include "export/svg.h"
#include "fillet/fillet.h"
#include "follower/follower.h"
#include "follower/follower_analysis.h"
#include "io/atomic_file.h"
#include "io/path_csv.h"
#include "io/project_json.h"
#include "kinematics/kinematics.h"
#include "project/follower_kind.h"
#include "project/validate.h"
#include "spline/teach_in.h"
#include "timing/machining_time.h"
#include "timing/timing_job.h"
#include "toolpath/biarc.h"
#include "toolpath/tool_path.h"

namespace cam::cli {
namespace {

using Json = nlohmann::ordered_json;

struct Loaded {
    Project project;
    Contour contour;
    double omega;
    /// The project's follower placed on the contour (a radial knife when it names none).
    FollowerModel follower;
};

/// "PATH: LOCATION: MESSAGE" as the CLI names a project's problem (a problem of the file as a
/// whole is located at the path itself).
std::string placeOf(const std::string& path, const Diagnostic& d) {
    return d.location == path ? path : path + ": " + d.location;
}

/// Loads PROJECT and evaluates it (evaluation.h: the verdict the window has too) or throws its
/// first problem (exit 2); the rest go to stderr via `validate`, which is the command for
/// seeing them all.
Loaded load(const std::string& path) {
    auto project = loadProjectStructure(path);
    Diagnostics problems = project.ok() ? Diagnostics{} : project.errors();
    std::optional<ProjectEvaluation> evaluation;
    if (project.ok()) {
        evaluation = evaluateProject(project.value());
        switch (evaluation->status) {
            case EvaluationStatus::Computed:
                break;
            case EvaluationStatus::AwaitsContour:
                problems = {contourNeverSynthesised()};
                break;
            case EvaluationStatus::Invalid:
            case EvaluationStatus::Failed:
                for (const Diagnostic& d : evaluation->problems) {
                    if (d.severity == Severity::Error) problems.push_back(d);
                }
                break;
        }
    }
    if (!problems.empty()) {
        const Diagnostic& d = problems.front();
        std::string message = d.message;
        if (problems.size() > 1) {
            message += " (and " + std::to_string(problems.size() - 1) +
                       " more problems; run 'camwright-cli validate' for all)";
        }
        throw CliError{kInvalidInput, placeOf(path, d), message};
    }
    return {std::move(project).value(), std::move(*evaluation->contour), evaluation->omega,
            *evaluation->follower};
}

Json stateJson(const KinematicState& s) {
    const PolarMotion& m = s.motion;
    return Json{{"t", s.t},
                {"phi_deg", radToDeg(s.phi)},
                {"segment", s.segment},
                {"r", s.polar.r},
                {"v_r", m.vR},
                {"v_phi", m.vPhi},
                {"v", m.v},
                {"a_r", m.aR},
                {"a_phi", m.aPhi},
                {"a", m.a},
                {"j_r", m.jR},
                {"j_phi", m.jPhi},
                {"j", m.j}};
}

/// A radius of curvature: null where the curve is straight (an infinite radius).
Json radiusJson(double rho) { return std::isfinite(rho) ? Json(rho) : Json(nullptr); }

const char* motionName(const FollowerModel& model) {
    return model.oscillating() ? "oscillating" : "translating";
}

/// cli.md's `follower` object of `state`; a swinging arm gives psi_deg, omega_arm, alpha_arm
/// and jerk_arm (rad/s…) in place of s, v, a, j, and its lift in degrees.
Json followerJson(const FollowerModel& model, const FollowerState& f) {
    Json json{{"type", followerKind(model.spec().type).name}, {"motion", motionName(model)}};
    if (model.oscillating()) {
        json.update(Json{{"psi_deg", radToDeg(f.s)},
                         {"lift", model.lift(f)},
                         {"omega_arm", f.v},
                         {"alpha_arm", f.a},
                         {"jerk_arm", f.j}});
    } else {
        json.update(Json{{"s", f.s}, {"lift", model.lift(f)}, {"v", f.v}, {"a", f.a}, {"j", f.j}});
    }
    json.update(Json{{"center", {f.center.x(), f.center.y()}},
                     {"contact", {f.contact.x(), f.contact.y()}},
                     {"pressure_angle_deg", radToDeg(f.pressureAngle)},
                     {"rho_profile", radiusJson(f.rhoProfile)},
                     {"rho_pitch", radiusJson(f.rhoPitch)}});
    return json;
}

/// cli.md's `follower` object of `analyze`: the design checks of math.md §7.
Json followerAnalysisJson(const Loaded& loaded) {
    const FollowerModel& model = loaded.follower;
    const FollowerAnalysis a = analyzeFollower(model, loaded.omega, loaded.contour.phiBegin());
    const auto one = [](const FollowerExtremum& e) {
        return Json{{"value", radiusJson(e.value)}, {"phi_deg", radToDeg(e.phi)}};
    };
    const auto angle = [](const FollowerExtremum& e) {
        return Json{{"value_deg", radToDeg(e.value)}, {"phi_deg", radToDeg(e.phi)}};
    };
    Json exceeded = Json::array();
    for (const AngleRange& r : a.pressureExceeded) {
        exceeded.push_back({{"from_deg", radToDeg(r.from)}, {"to_deg", radToDeg(r.to)}});
    }
    Json undercut = Json::array();
    for (const NonContact& c : a.undercut) {
        undercut.push_back({{"phi_deg", radToDeg(c.phi)},
                            {"from", {c.from.x(), c.from.y()}},
                            {"to", {c.to.x(), c.to.y()}},
                            {"profile_from_deg", radToDeg(std::atan2(c.from.y(), c.from.x()))},
                            {"profile_to_deg", radToDeg(std::atan2(c.to.y(), c.to.x()))}});
    }
    const bool arm = model.oscillating();
    const auto range = [&](const FollowerExtremum& lo, const FollowerExtremum& hi) {
        return Json{{"min", one(lo)}, {"max", one(hi)}};
    };
    const auto degrees = [](FollowerExtremum e) {
        e.value = radToDeg(e.value);
        return e;
    };
    Json f{{"type", followerKind(model.spec().type).name}, {"motion", motionName(model)}};
    if (arm) {
        f["psi_deg"] = range(degrees(a.sMin), degrees(a.sMax));
        f["lift"] = radToDeg(a.sMax.value - a.sMin.value);
        f["omega_arm"] = range(a.vMin, a.vMax);
        f["alpha_arm"] = range(a.aMin, a.aMax);
        f["jerk_arm"] = range(a.jMin, a.jMax);
    } else {
        f["s"] = range(a.sMin, a.sMax);
        f["lift"] = a.sMax.value - a.sMin.value;
        f["v"] = range(a.vMin, a.vMax);
        f["a"] = range(a.aMin, a.aMax);
        f["j"] = range(a.jMin, a.jMax);
    }
    f.update(Json{{"pressure_angle",
                   {{"rise", angle(a.pressureRise)},
                    {"return", angle(a.pressureReturn)},
                    {"limit_deg", radToDeg(a.limitRad)},
                    {"exceeded", std::move(exceeded)}}},
                  {"rho_profile_min", one(a.rhoProfileMin)},
                  {"rho_pitch_min", one(a.rhoPitchMin)},
                  {"undercut", std::move(undercut)}});
    if (model.spec().type == FollowerType::Flat) f["face_width"] = a.faceWidth;
    return f;
}

/// No command prints a non-finite number with exit 0: a result that is not a finite number is
/// "not computable" (exit 3), named by its place in the output ("extremes/j/max/value").
void requireFinite(const Json& value, const std::string& where) {
    if (value.is_number_float() && !std::isfinite(value.get<double>())) {
        throw CliError{kNotComputable, where,
                       "is not a finite number (" + formatNumber(value.get<double>()) +
                           "): the result is beyond what a double can hold"};
    }
    if (value.is_object()) {
        for (const auto& [key, item] : value.items()) {
            requireFinite(item, where.empty() ? key : where + "/" + key);
        }
    } else if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i) {
            requireFinite(value[i], where + "[" + std::to_string(i) + "]");
        }
    }
}

/// Prints a JSON result after checking every number in it.
void printJson(std::ostream& out, const Json& result) {
    requireFinite(result, "");
    out << result.dump(2) << "\n";
}

/// Every sampled value is finite, checked before the first row is written.
void requireFiniteColumns(const SampledTurn& turn) {
    if (const auto problem = firstNonFiniteSample(turn)) {
        throw CliError{kNotComputable, problem->location, problem->message};
    }
}

/// Beyond 1e15 turns one rounding of t/T moves the angle by more than a tenth of a turn: the
/// instant no longer names a cam angle.
constexpr double kMaxTurns = 1e15;

}  // namespace

int runValidate(const Arguments& args, std::ostream& out, std::ostream& err) {
    const std::string& path = args.positional.at(0);
    const auto project = loadProjectStructure(path);
    std::optional<ProjectEvaluation> evaluation;
    if (project.ok()) evaluation = evaluateProject(project.value());
    if (!evaluation || !evaluation->valid()) {
        // One write for all: stderr is unbuffered, and a file can have a problem per segment.
        std::string lines;
        for (const Diagnostic& d : evaluation ? evaluation->problems : project.errors()) {
            if (d.severity != Severity::Error) continue;
            lines += "camwright-cli: " + placeOf(path, d) + ": " + d.message + '\n';
        }
        err << lines;
        return kInvalidInput;
    }
    if (evaluation->status == EvaluationStatus::AwaitsContour) {
        // Valid (project-format.md): a design whose contour was never synthesised.
        out << "valid: a design, no contour yet (camwright-cli synthesize makes it)\n";
        return kOk;
    }
    out << "valid: " << project.value().contour.size() << " segments\n";
    return kOk;
}

int runState(const Arguments& args, std::ostream& out) {
    const auto tText = args.option("--t");
    if (!tText) throw CliError{kUsage, "--t", "is required (the time in seconds)"};
    const double t = parseFiniteNumber("--t", *tText, "seconds");
    const Loaded loaded = load(args.positional.at(0));
    if (!(std::abs(turnsAt(loaded.project.motion, t)) <= kMaxTurns)) {
        throw CliError{kInvalidInput, "--t",
                       "must be within " + formatNumber(kMaxTurns) + " turns of 0 (got " +
                           formatNumber(t) + " s, " +
                           formatNumber(turnsAt(loaded.project.motion, t)) +
                           " turns): beyond that a double no longer resolves the cam angle"};
    }
    Json state = stateJson(stateAt(loaded.contour, loaded.project.motion, t));
    // The follower (math.md §7), at the same exactly reduced angle; the seed's knife edge on
    // the radial line when the project names none.
    const FollowerModel& follower = loaded.follower;
    const double turns = turnsAt(loaded.project.motion, t);
    const double reduced = kTwoPi * (turns - std::floor(turns));
    state["follower"] = followerJson(follower, follower.at(reduced, loaded.omega));
    printJson(out, state);
    return kOk;
}

namespace {

/// One turn at n instants as CSV (the `sample` columns, then the follower's when one is given),
/// to `outPath` (atomically) or `out`.
void writeSampleCsv(const Loaded& loaded, long long n, std::ostream& out,
                    const std::optional<std::string>& outPath,
                    const FollowerModel* follower = nullptr) {
    std::optional<AtomicFileWriter> file;
    if (outPath) {
        file.emplace(*outPath);
        if (!file->ok()) {
            throw CliError{kInvalidInput, *outPath, file->errors().front().message};
        }
    }
    SampledTurn turn;
    sampleTurn(loaded.contour, loaded.omega, static_cast<std::size_t>(n), turn);
    requireFiniteColumns(turn);

    FollowerTurn followerTurn;
    std::string chunk(kSampleCsvHeader);
    if (follower) {
        sampleFollowerTurn(*follower, loaded.omega, static_cast<std::size_t>(n), followerTurn);
        chunk.pop_back();
        chunk += ',';
        chunk += followerCsvColumns(*follower);
        chunk += '\n';
    }
    auto flush = [&] {
        if (file) {
            file->write(chunk);
        } else {
            out << chunk;
        }
        chunk.clear();
    };
    for (std::size_t k = 0; k < turn.size(); ++k) {
        appendSampleCsvRow(chunk, turn, k);
        if (follower) {
            chunk.pop_back();
            appendFollowerCsvColumns(chunk, *follower, followerTurn, k);
            chunk += '\n';
        }
        if (chunk.size() > (1u << 20)) flush();
        // A failed stdout (full disk, closed) is reported by main; a failed --out file below.
        if (!out || (file && !file->ok())) break;
    }
    flush();
    if (file) {
        const Diagnostics problems = file->commit();
        if (!problems.empty()) throw CliError{kInvalidInput, *outPath, problems.front().message};
    }
}

}  // namespace

int runSample(const Arguments& args, std::ostream& out) {
    long long n = 0;
    if (const auto text = args.option("--samples")) {
        n = parseCount("--samples", *text, 1, kMaxSamplesPerTurn);
    }
    const Loaded loaded = load(args.positional.at(0));
    if (n == 0) n = loaded.project.samplesPerTurnOrDefault();
    writeSampleCsv(loaded, n, out, args.option("--out"));
    return kOk;
}

int runAnalyze(const Arguments& args, std::ostream& out) {
    const Loaded loaded = load(args.positional.at(0));
    const ContourAnalysis analysis = analyzeContour(loaded.contour, loaded.omega);
    Json joints = Json::array();
    for (const JointAnalysis& j : analysis.joints) {
        joints.push_back(Json{{"joint", j.right},
                              {"left", j.left},
                              {"right", j.right},
                              {"phi_deg", radToDeg(j.phi)},
                              {"continuity", continuityName(j.continuity)},
                              {"c0_gap_mm", j.gapMm},
                              {"tangent_break_deg", j.tangentBreakDeg},
                              {"jump_dr", j.jumpDr},
                              {"jump_d2r", j.jumpD2r},
                              {"jump_d3r", j.jumpD3r},
                              {"jump_a_r", j.jumpAR},
                              {"jump_j_r", j.jumpJR},
                              {"jump_dP_dphi", {j.jumpD1.x(), j.jumpD1.y()}},
                              {"relative_jump_dP_dphi", j.relativeD1},
                              {"jump_d2P_dphi2", {j.jumpD2.x(), j.jumpD2.y()}},
                              {"relative_jump_d2P_dphi2", j.relativeD2},
                              {"geometric", continuityName(j.geometric)},
                              {"curve_jump_d1", {j.curveJumpD1.x(), j.curveJumpD1.y()}},
                              {"curve_relative_jump_d1", j.curveRelativeD1},
                              {"curve_jump_d2", {j.curveJumpD2.x(), j.curveJumpD2.y()}},
                              {"curve_relative_jump_d2", j.curveRelativeD2}});
    }
    Json extremes = Json::object();
    for (const QuantityExtremes& e : analysis.extremes) {
        auto one = [](const Extremum& x) {
            return Json{{"value", x.value}, {"phi_deg", radToDeg(x.phi)}, {"segment", x.segment}};
        };
        extremes[quantityName(e.quantity)] = Json{{"min", one(e.min)}, {"max", one(e.max)}};
    }
    const Json result{{"omega_rad_s", loaded.omega},
                      {"units", {{"length", "mm"}, {"angle", "deg"}, {"time", "s"}}},
                      {"joints", std::move(joints)},
                      {"extremes", std::move(extremes)},
                      {"follower", followerAnalysisJson(loaded)}};
    printJson(out, result);
    return kOk;
}

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

double parsePositive(const std::string& option, const std::string& text, const char* unit) {
    const double v = parseFiniteNumber(option, text, unit);
    if (!(v > 0)) throw CliError{kInvalidInput, option, "must be > 0 (got \"" + text + "\")"};
    return v;
}

}  // namespace

int runTiming(const Arguments& args, std::ostream& out) {
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
    if (!loaded || args.option("--step")) job.stepLocation = "--step";
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

int runFillet(const Arguments& args, std::ostream& out) {
    const auto jointText = args.option("--joint");
    if (!jointText)
        throw CliError{kUsage, "--joint",
                       "is required (joint K lies between contour[K-1] and contour[K])"};
    const auto outPath = args.option("--out");
    if (!outPath) throw CliError{kUsage, "--out", "is required (the file for the new project)"};
    const bool byRadius = args.option("--radius").has_value();
    const bool bySpeed = args.option("--speed") || args.option("--accel") || args.option("--vae");
    if (byRadius == bySpeed) {
        throw CliError{kUsage, "fillet", "give either --radius R or --speed V --accel A --vae E"};
    }
    const Loaded loaded = load(args.positional.front());
    const long long joint = parseCount("--joint", *jointText, 0,
                                       static_cast<long long>(loaded.project.contour.size()) - 1);
    double radius = 0.0;
    if (byRadius) {
        radius = parsePositive("--radius", *args.option("--radius"), "mm");
    } else {
        for (const char* name : {"--speed", "--accel", "--vae"}) {
            if (!args.option(name)) throw CliError{kUsage, name, "is required with --speed"};
        }
        radius = minimumSwitchRadius(parsePositive("--speed", *args.option("--speed"), "mm/s"),
                                     parsePositive("--accel", *args.option("--accel"), "mm/s²"),
                                     parsePositive("--vae", *args.option("--vae"), "(a ratio)"));
    }
    const auto result =
        filletJoint(loaded.project.contour, static_cast<std::size_t>(joint), radius);
    if (!result.ok()) {
        const Diagnostic& d = result.errors().front();
        throw CliError{kNotComputable, args.positional.front() + ": " + d.location, d.message};
    }
    Project filleted = loaded.project;
    filleted.contour = result.value().contour;
    const FilletResult& f = result.value();
    const Json summary{{"joint", joint},
                       {"radius_mm", f.radius},
                       {"center", {f.center.x(), f.center.y()}},
                       {"tangent_point_1", {f.tangentPoint1.x(), f.tangentPoint1.y()}},
                       {"tangent_point_2", {f.tangentPoint2.x(), f.tangentPoint2.y()}},
                       {"segments", filleted.contour.size()},
                       {"out", *outPath}};
    requireFinite(summary, "");  // before the file is written: nothing is left of a failure
    const Diagnostics written = writeFileAtomically(*outPath, serializeProject(filleted));
    if (!written.empty()) throw CliError{kInvalidInput, *outPath, written.front().message};
    printJson(out, summary);
    return kOk;
}

namespace {

/// Writes `text` to `path` atomically (io/atomic_file.h); a failure throws (exit 2).
void writeExport(const std::string& path, const std::string& text) {
    AtomicFileWriter file(path);
    file.write(text);
    Diagnostics problems = file.commit();
    if (!problems.empty()) throw CliError{kInvalidInput, path, problems.front().message};
}

/// The first error of an export that cannot be made: a bad option (exit 2) or geometry the
/// format cannot take (exit 3, naming the segment).
[[noreturn]] void exportFailed(const std::string& project, const Diagnostics& errors) {
    const Diagnostic& d = errors.front();
    if (d.location.rfind("--", 0) == 0) throw CliError{kInvalidInput, d.location, d.message};
    throw CliError{kNotComputable, project + ": " + d.location, d.message};
}

/// The formats `export` writes today, in the order --help lists them.
constexpr const char* kExportFormats = "csv, dxf, svg, png, pdf, gcode, camtable";

}  // namespace

int runExport(const Arguments& args, std::ostream& out) {
    const std::string& input = args.positional.at(0);
    const std::optional<std::string> format = args.option("--format");
    if (!format)
        throw CliError{kUsage, "export",
                       "--format is required (" + std::string(kExportFormats) + ")"};
    const std::optional<std::string> outPath = args.option("--out");
    if (!outPath) throw CliError{kUsage, "export", "--out FILE is required"};
    const bool picture =
        *format == "png" || *format == "pdf" || (*format == "svg" && args.option("--plot"));
    const bool known = *format == "csv" || *format == "dxf" || *format == "svg" ||
                       *format == "png" || *format == "pdf" || *format == "gcode" ||
                       *format == "camtable";
    if (!known) {
        throw CliError{
            kUsage, "--format",
            "unknown format '" + *format + "' (one of " + std::string(kExportFormats) + ")"};
    }
    // Which options each format takes; any other is a mistake worth saying.
    const std::map<std::string, std::vector<std::string>> accepts{
        {"csv", {"--points"}},
        {"dxf", {"--tolerance", "--tool-radius"}},
        {"svg", {"--tolerance"}},
        {"gcode", {"--tolerance", "--tool-radius", "--depth", "--step-down"}},
        {"camtable", {"--points", "--dialect"}},
        {"picture", {"--plot", "--size"}},
    };
    for (const auto& [name, value] : args.options) {
        if (name == "--format" || name == "--out") continue;
        const auto& ok = accepts.at(picture ? "picture" : *format);
        if (std::find(ok.begin(), ok.end(), name) == ok.end()) {
            throw CliError{kUsage, name, "is not an option of --format " + *format};
        }
    }
    for (const std::string& flag : args.flags) {
        const bool dxfFlag =
            flag == "--polyline" || flag == "--spline-entities" || flag == "--centres";
        const bool gcodeFlag = flag == "--compensation";
        if (!(dxfFlag && *format == "dxf") && !(gcodeFlag && *format == "gcode")) {
            throw CliError{kUsage, flag, "is not an option of --format " + *format};
        }
    }
    {
        // --out must not name the project it is made from (it would be replaced by the export).
        std::error_code ec;
        if (std::filesystem::equivalent(input, *outPath, ec)) {
            throw CliError{kInvalidInput, *outPath,
                           "is the project being exported; choose another file"};
        }
    }
    double tolerance = *format == "svg" ? kSvgToleranceMm : kDefaultExportToleranceMm;
    if (const auto text = args.option("--tolerance")) {
        tolerance = parseFiniteNumber("--tolerance", *text, "a tolerance in mm");
    }
    const Loaded loaded = load(input);

    if (picture) {
        const std::string plot = args.option("--plot").value_or("contour");
        const auto& names = kPlotNames;
        if (std::find(std::begin(names), std::end(names), plot) == std::end(names)) {
            throw CliError{kUsage, "--plot",
                           "unknown plot '" + plot + "' (one of " + plotNameList() + ")"};
        }
        return drawPlotWithApp(input, plot, *format, args.option("--size"), *outPath);
    }
    if (*format == "csv") {
        long long n = loaded.project.samplesPerTurnOrDefault();
        if (const auto text = args.option("--points")) {
            n = parseCount("--points", *text, 1, kMaxSamplesPerTurn);
        }
        writeSampleCsv(loaded, n, out, outPath, &loaded.follower);
        return kOk;
    }
    Result<std::string> text = std::string();
    if (*format == "dxf") {
        DxfOptions options;
        options.toleranceMm = tolerance;
        options.polyline = args.hasFlag("--polyline");
        options.splineEntities = args.hasFlag("--spline-entities");
        options.centres = args.hasFlag("--centres");
        if (const auto r = args.option("--tool-radius")) {
            options.toolRadiusMm = parseFiniteNumber("--tool-radius", *r, "a radius in mm");
        }
        text = dxfDocument(loaded.contour, options);
    } else if (*format == "gcode") {
        GcodeOptions options;
        const MachiningSpec machining = loaded.project.machining.value_or(MachiningSpec{});
        if (const auto r = args.option("--tool-radius")) {
            options.toolRadiusMm = parseFiniteNumber("--tool-radius", *r, "a radius in mm");
        } else if (machining.toolRadius > 0.0) {
            options.toolRadiusMm = machining.toolRadius;
        } else {
            throw CliError{kUsage, "--tool-radius",
                           "is required: the project gives no machining.tool_radius"};
        }
        options.feedMmMin = machining.feedMax * 60.0;
        // Finer than a drawing's default: the program is checked to 1e-4 mm.
        options.toleranceMm = args.option("--tolerance") ? tolerance : kDefaultGcodeToleranceMm;
        if (const auto d = args.option("--depth")) {
            options.depthMm = parseFiniteNumber("--depth", *d, "a depth in mm");
        }
        if (const auto d = args.option("--step-down")) {
            options.stepDownMm = parseFiniteNumber("--step-down", *d, "a depth in mm");
        }
        options.compensation = args.hasFlag("--compensation");
        options.projectName = loaded.project.name.empty()
                                  ? std::filesystem::path(input).filename().string()
                                  : loaded.project.name;
        text = gcodeProgram(loaded.contour, options);
    } else if (*format == "svg") {
        SvgOptions options;
        options.toleranceMm = tolerance;
        options.title = loaded.project.name.empty()
                            ? std::filesystem::path(input).filename().string()
                            : loaded.project.name;
        text = svgDocument(loaded.contour, options);
    } else {
        CamTableOptions options;
        if (const auto p = args.option("--points")) {
            options.points = static_cast<std::size_t>(
                parseCount("--points", *p, kMinCamTablePoints, kMaxCamTablePoints));
        }
        if (const auto d = args.option("--dialect")) {
            if (*d == "codesys") {
                options.dialect = CamTableDialect::Codesys;
            } else if (*d != "csv") {
                throw CliError{kInvalidInput, "--dialect",
                               "unknown cam table dialect '" + *d + "' (csv, codesys)"};
            }
        }
        options.name = loaded.project.name.empty()
                           ? std::filesystem::path(input).stem().stem().string()
                           : loaded.project.name;
        options.follower = loaded.project.follower.value_or(FollowerSpec{});
        text = camTableText(loaded.contour, options);
    }
    if (!text.ok()) exportFailed(input, text.errors());
    writeExport(*outPath, text.value());
    return kOk;
}

int runSynthesize(const Arguments& args, std::ostream& out) {
    const std::string& path = args.positional.front();
    const auto outPath = args.option("--out");
    if (!outPath) throw CliError{kUsage, "--out", "is required (the file for the new project)"};
    if (const auto output = args.option("--output"); output && *output != "arcs") {
        throw CliError{kInvalidInput, "--output",
                       *output == "bezier"
                           ? std::string("\"bezier\" is not available yet: this version "
                                         "synthesises arc tables only (--output arcs)")
                           : "must be \"arcs\" (got \"" + *output + "\")"};
    }
    std::optional<double> tolerance;
    if (const auto text = args.option("--tolerance")) {
        tolerance = parsePositive("--tolerance", *text, "mm");
    }
    // A design whose contour was never synthesised is valid with an empty contour
    // (project-format.md), but not a contour to compute: the project is checked here, not by
    // load().
    auto loaded = loadProjectStructure(path);
    if (!loaded.ok()) {
        const Diagnostic& d = loaded.errors().front();
        throw CliError{kInvalidInput, d.location == path ? path : path + ": " + d.location,
                       d.message};
    }
    Project project = std::move(loaded).value();
    if (!project.design) {
        throw CliError{kInvalidInput, path + ": design",
                       "the project has no design to synthesise a contour from"};
    }
    // The document's problems, but not the verdict's last check (evaluation.h): whether the
    // follower rides the contour Synthesize is about to replace does not matter.
    for (const Diagnostic& d : documentProblems(project)) {
        if (d.severity != Severity::Error) continue;
        throw CliError{kInvalidInput, placeOf(path, d), d.message};
    }
    const auto made = synthesize(project, tolerance);
    if (!made.ok()) {
        const Diagnostic& d = made.errors().front();
        if (d.code == DiagnosticCode::ToleranceBelowPrecision) {
            // A value no arc table can be certified to is bad input (exit 2), named where it
            // came from: the option, or the project's design.
            throw CliError{kInvalidInput, tolerance ? "--tolerance" : path + ": " + d.location,
                           d.message};
        }
        throw CliError{kNotComputable, path + ": " + d.location, d.message};
    }
    const SynthesisReport& r = made.value().report;
    project.contour = made.value().contour;
    if (tolerance) project.design->tolerance = *tolerance;
    const bool swinging =
        project.follower && project.follower->motion == FollowerMotion::Oscillating;
    Json notes = Json::array();
    for (const Diagnostic& d : r.notes) notes.push_back(d.text());
    const Json report{{"segments", r.segments},
                      {"max_deviation_mm", r.maxDeviationMm},
                      {swinging ? "max_lift_error_deg" : "max_lift_error_mm", r.maxLiftError},
                      {"max_velocity_error", r.maxVelocityError},
                      {"max_acceleration_error", r.maxAccelerationError},
                      {"velocity_unit", swinging ? "deg/s" : "mm/s"},
                      {"acceleration_unit", swinging ? "deg/s^2" : "mm/s^2"},
                      {"tolerance_mm", tolerance.value_or(project.design->tolerance)},
                      {"notes", notes},
                      {"out", *outPath}};
    requireFinite(report, "");
    const Diagnostics written = writeFileAtomically(*outPath, serializeProject(project));
    if (!written.empty()) throw CliError{kInvalidInput, *outPath, written.front().message};
    printJson(out, report);
    return kOk;
}

}  // namespace cam::cli
