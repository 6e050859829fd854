#include "cli/commands.h"

#include <ostream>

#include "analysis/analysis.h"
#include "cli/command_support.h"
#include "closure/conjugate.h"
#include "contour/contour.h"
#include "design/synthesis.h"
#include "evaluation/evaluation.h"

namespace cam::cli {

int runSynthesize(const Arguments& args, std::ostream& out, std::ostream& /*err*/) {
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
    Project project = loadStructure(path);
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
    // What the arcs cost the jerk: an arc table is C1, so at every joint between arcs of
    // different curvature the acceleration jumps and the jerk is unbounded there.
    std::size_t jumps = 0;
    double largestJump = 0.0;
    if (const auto omega = usableOmega(project.motion)) {
        if (const auto made = Contour::build(project); made.ok()) {
            for (const UnboundedJerk& u :
                 unboundedJerk(analyzeJoints(made.value(), *omega), *omega)) {
                ++jumps;
                largestJump = std::max(largestJump, u.accelerationJump);
            }
        }
    }
    Json notes = Json::array();
    for (const Diagnostic& d : r.notes) notes.push_back(d.text());
    // A conjugate pair: the second plate for the new first one, and the play it leaves; or,
    // as a note, why it cannot be made (the project is written all the same: its distance or
    // second roller is the designer's to change).
    Json second;
    if (const auto yoke = SecondRoller::of(project)) {
        const ProjectEvaluation e = evaluateProject(project);
        Diagnostics problems = e.followerProblems;
        if (e.follower) {
            auto plate = conjugatePlate(*e.follower, *yoke, conjugateTolerance(project));
            if (plate.ok()) {
                const ConjugatePlate& p = plate.value();
                second = {{"plate_arcs", p.fit.arcs.size()},
                          {"max_play_mm", p.maxPlay},
                          {"min_play_mm", p.minPlay}};
            } else {
                problems = plate.errors();
            }
        }
        for (const Diagnostic& d : problems) {
            notes.push_back("no second plate: " + d.text());
        }
    }
    Json report{{"segments", r.segments},
                {"max_deviation_mm", r.maxDeviationMm},
                {swinging ? "max_lift_error_deg" : "max_lift_error_mm", r.maxLiftError},
                {"max_velocity_error", r.maxVelocityError},
                {"max_acceleration_error", r.maxAccelerationError},
                {"velocity_unit", swinging ? "deg/s" : "mm/s"},
                {"acceleration_unit", swinging ? "deg/s^2" : "mm/s^2"},
                {"tolerance_mm", tolerance.value_or(project.design->tolerance)},
                {"acceleration_jumps", jumps},
                {"max_acceleration_jump", largestJump},
                {"jerk", jumps > 0 ? "unbounded at each acceleration jump" : "bounded"},
                {"notes", notes},
                {"out", *outPath}};
    if (SecondRoller::of(project)) report["second_plate"] = second;
    writeProjectOut(*outPath, project, report);
    printJson(out, report);
    return kOk;
}

}  // namespace cam::cli
