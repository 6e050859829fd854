// camwright-cli: everything the desktop application computes, without a display (cli.md).

#include <unistd.h>

#include <csignal>
#include <iostream>
#include <string>
#include <vector>

#include "cli/arguments.h"
#include "cli/commands.h"
#include "cli/output.h"
#include "io/atomic_file.h"

namespace {

constexpr const char* kUsageText = R"(usage: camwright-cli COMMAND PROJECT [options]

commands:
  validate PROJECT                      list every problem of a project (exit 2 if any)
  state PROJECT --t SECONDS             the follower's state at one instant, as JSON
  sample PROJECT [--samples N] [--out FILE.csv]
                                        one turn sampled at N instants, as CSV
  analyze PROJECT                       joints (continuity, jumps) and extremes, as JSON
  timing (PROJECT | --path POINTS.csv) --method seed|exact-stop|optimal
         [--accel AX,AY[,AZ]] [--vmax VX,VY[,VZ]] [--feed F] [--step L] [--detail]
         [--spline chord|circumcircle|oval]   (the points are teach-in knots of a spline)
                                        machining time of the contour (offset by the tool
                                        radius) or of a point list (x,y,z[,bulge] per line)
  fillet PROJECT --joint K (--radius R | --speed V --accel A --vae E) --out NEW
                                        round the corner between contour[K-1] and contour[K]
                                        by a tangent arc (radius given or V²/(vae·A))
  synthesize PROJECT --out NEW [--tolerance MM] [--output arcs]
                                        the contour made from the project's design (motion
                                        laws) for its follower: tangent arcs within the
                                        tolerance; a report of what the arcs cost the motion

  export PROJECT --format csv|dxf|svg|png|pdf|gcode|camtable --out FILE
         [--tolerance MM] [--points N] [--dialect csv|codesys] [--tool-radius MM]
         [--polyline] [--spline-entities] [--centres]
         [--depth MM] [--step-down MM] [--compensation]
         [--plot contour|velocity|acceleration|jerk|feed|axis-acceleration|pressure-angle] [--size WxH]
                                        the profile for CAD (dxf: LINE/ARC on layer CONTOUR,
                                        TOOLPATH with --tool-radius, CENTRES; svg: 1:1 in mm),
                                        G-code milling it from outside (gcode: the tool-centre
                                        path, or the contour with G41/G42 by --compensation;
                                        tool radius from the project unless given, depth
                                        default 5 mm, passes of --step-down), the sampled turn
                                        (csv) or a servo cam table (camtable); png, pdf and
                                        svg --plot: a plot as the app draws it (by the app
                                        camwright beside this program; default contour,
                                        1200x800 px for png, A4 landscape for pdf and svg)

units: mm, s, degrees; v in mm/s, a in mm/s², j in mm/s³.
exit codes: 0 ok, 1 usage error, 2 invalid input (or results that cannot be written),
            3 not computable.
)";

int run(const std::vector<std::string>& args, std::ostream& out) {
    using namespace cam::cli;
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
        out << kUsageText;
        return kOk;
    }
    if (!args.empty() && args[0] == "--version") {
        out << "camwright-cli " << CAMWRIGHT_VERSION << "\n";
        return kOk;
    }
    const std::vector<CommandSyntax> commands{
        {"validate", 1, {}, {}},
        {"state", 1, {"--t"}, {}},
        {"sample", 1, {"--samples", "--out"}, {}},
        {"analyze", 1, {}, {}},
        {"timing",
         1,
         {"--method", "--path", "--accel", "--vmax", "--feed", "--step", "--spline"},
         {"--detail"},
         0},
        {"fillet", 1, {"--joint", "--radius", "--speed", "--accel", "--vae", "--out"}, {}},
        {"synthesize", 1, {"--out", "--tolerance", "--output"}, {}},
        {"export",
         1,
         {"--format", "--out", "--tolerance", "--points", "--dialect", "--tool-radius", "--depth",
          "--step-down", "--plot", "--size"},
         {"--polyline", "--spline-entities", "--centres", "--compensation"}},
    };
    try {
        const Arguments parsed = parseArguments(args, commands);
        if (parsed.command == "validate") return runValidate(parsed, out, std::cerr);
        if (parsed.command == "state") return runState(parsed, out);
        if (parsed.command == "sample") return runSample(parsed, out);
        if (parsed.command == "analyze") return runAnalyze(parsed, out);
        if (parsed.command == "timing") return runTiming(parsed, out);
        if (parsed.command == "fillet") return runFillet(parsed, out);
        if (parsed.command == "synthesize") return runSynthesize(parsed, out);
        if (parsed.command == "export") return runExport(parsed, out);
        return kUsage;
    } catch (const CliError& e) {
        out.flush();
        std::cerr << "camwright-cli: " << e.location << ": " << e.message << "\n";
        if (e.code == kUsage) std::cerr << "(run 'camwright-cli --help' for usage)\n";
        return e.code;
    } catch (const std::exception& e) {
        out.flush();
        std::cerr << "camwright-cli: internal error: " << e.what() << "\n";
        return kNotComputable;
    }
}

}  // namespace

int main(int argc, char** argv) {
    using namespace cam::cli;
    occupyClosedStandardStreams();
    // Over a file size limit (ulimit -f) write() then fails with EFBIG and is reported with the
    // file's name, instead of the signal killing the program with a temporary file left behind.
    std::signal(SIGXFSZ, SIG_IGN);
    // Ctrl+C or a kill during `--out` leaves no temporary file behind (io/atomic_file.h).
    cam::installTemporaryFileCleanup();
    std::ios::sync_with_stdio(false);
    CheckedOutput results(STDOUT_FILENO);
    std::ostream out(&results);
    const int code = run(std::vector<std::string>(argv + 1, argv + argc), out);
    // Results that did not reach stdout are a failure, whatever the command said.
    if (!results.finish()) {
        std::cerr << "camwright-cli: stdout: " << results.failureText() << "\n";
        return code == kOk ? kInvalidInput : code;
    }
    return code;
}
