#include "cli/commands.h"

#include <ostream>

#include "cli/command_support.h"
#include "contour/fit_windows.h"
#include "evaluation/evaluation.h"

namespace cam::cli {

namespace {

const char* meetingName(JointMeeting m) {
    switch (m) {
        case JointMeeting::Crossing:
            return "crossing";
        case JointMeeting::Tangent:
            return "tangent";
        case JointMeeting::SameCurve:
            return "same curve";
        case JointMeeting::SplineEnd:
            return "spline end";
    }
    return "";
}

Json point(const Eigen::Vector2d& p) { return Json::array({p.x(), p.y()}); }

Json changeJson(const SegmentMove& m) {
    Json change{{"segment", m.segment},
                {"meets", m.neighbour},
                {"also_touches", m.alsoNeighbour ? Json(*m.alsoNeighbour) : Json(nullptr)},
                {"same_curve", m.tookNeighboursCurve},
                {"distance_mm", m.distanceMm}};
    if (const Arc* arc = std::get_if<Arc>(&m.after)) {
        const Arc& was = std::get<Arc>(m.before);
        change["center"] = {{"from", point(was.center)}, {"to", point(arc->center)}};
        change["radius"] = {{"from", was.radius}, {"to", arc->radius}};
    } else {
        const Line& was = std::get<Line>(m.before);
        const Line& line = std::get<Line>(m.after);
        change["line"] = {{"from", {point(was.from), point(was.to)}},
                          {"to", {point(line.from), point(line.to)}}};
    }
    return change;
}

/// "camwright-cli: PATH: LOCATION: MESSAGE" per diagnostic, as one write (stderr is unbuffered).
std::string lines(const std::string& path, const Diagnostics& diagnostics) {
    std::string text;
    for (const Diagnostic& d : diagnostics) {
        text += "camwright-cli: " + placeOf(path, d) + ": " + d.message + '\n';
    }
    return text;
}

}  // namespace

int runFitWindows(const Arguments& args, std::ostream& out, std::ostream& err) {
    const std::string& path = args.positional.front();
    const auto outPath = args.option("--out");
    if (!outPath) throw CliError{kUsage, "--out", "is required (the file for the new project)"};
    // Not load(): its joints not meeting is what brings a project here.
    Project project = loadStructure(path);
    if (project.contour.empty() && project.design) {
        const Diagnostic d = contourNeverSynthesised();
        throw CliError{kInvalidInput, placeOf(path, d), d.message};
    }
    const auto fitted = fitWindows(project.contour);
    if (!fitted.ok()) {
        err << lines(path, fitted.errors());
        return kNotComputable;
    }
    const FittedWindows& f = fitted.value();
    project.contour = f.contour;
    // What else is wrong is wrong with the input: nothing is written, every problem is listed.
    const ProjectEvaluation evaluation = evaluateProject(project);
    if (!evaluation.valid()) {
        Diagnostics errors;
        for (const Diagnostic& d : evaluation.problems) {
            if (d.severity == Severity::Error) errors.push_back(d);
        }
        err << lines(path, errors);
        return kInvalidInput;
    }
    Json joints = Json::array();
    for (std::size_t k = 0; k < f.joints.size(); ++k) {
        joints.push_back({{"left", k},
                          {"right", (k + 1) % f.joints.size()},
                          {"angle_deg", f.joints[k].angleDeg},
                          {"meeting", meetingName(f.joints[k].meeting)}});
    }
    Json changes = Json::array();
    for (const SegmentMove& m : f.moves) changes.push_back(changeJson(m));
    const Json report{{"segments", f.contour.size()},
                      {"joints", joints},
                      {"changes", changes},
                      {"largest_change_mm", f.largestMoveMm()},
                      {"out", *outPath}};
    writeProjectOut(*outPath, project, report);
    // Every change on stderr (cli.md), the report on stdout.
    err << lines(path, f.notes);
    printJson(out, report);
    return kOk;
}

}  // namespace cam::cli
