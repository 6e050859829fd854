#include "cli/help.h"

#include <algorithm>

#include "cli/commands.h"
#include "cli/export_choice.h"
#include "common/diagnostic.h"
#include "export/cam_table.h"
#include "export/dxf.h"
#include "export/gcode.h"
#include "export/svg.h"
#include "project/project.h"

namespace cam::cli {

namespace {

constexpr std::size_t kWidth = 80;

/// `text` broken into lines of at most kWidth columns (counted in UTF-8 characters), the first
/// after `first` (already on the line), the others indented by `indent` spaces. Blank lines in
/// `text` separate paragraphs.
std::string wrap(const std::string& text, std::size_t indent, std::size_t firstColumn) {
    auto columns = [](const std::string& s) {
        return static_cast<std::size_t>(
            std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
    };
    std::string out;
    std::size_t column = firstColumn;
    std::istringstream paragraphs(text);
    std::string line;
    bool lineStart = true;
    while (std::getline(paragraphs, line)) {
        if (line.empty()) {  // a paragraph break
            out += "\n\n";
            out.append(indent, ' ');
            column = indent;
            lineStart = true;
            continue;
        }
        std::istringstream words(line);
        std::string word;
        while (words >> word) {
            const std::size_t w = columns(word);
            if (!lineStart && column + 1 + w > kWidth) {
                out += '\n';
                out.append(indent, ' ');
                column = indent;
                lineStart = true;
            }
            if (!lineStart) {
                out += ' ';
                ++column;
            }
            out += word;
            column += w;
            lineStart = false;
        }
    }
    return out;
}

const std::string kExitCodes =
    "exit codes: 0 ok, 1 usage error, 2 invalid input (or results that cannot be\n"
    "            written), 3 not computable.\n";

/// The function that runs the command called `name` (cli/commands.h).
auto commandRunner(const std::string& name) -> decltype(CommandHelp::run) {
    static const std::pair<const char*, decltype(CommandHelp::run)> kRunners[] = {
        {"validate", runValidate},      {"state", runState},           {"sample", runSample},
        {"analyze", runAnalyze},        {"timing", runTiming},         {"fillet", runFillet},
        {"fit-windows", runFitWindows}, {"synthesize", runSynthesize}, {"size", runSize},
        {"suggest", runSuggest},        {"export", runExport},
    };
    for (const auto& [known, run] : kRunners) {
        if (name == known) return run;
    }
    return nullptr;
}

std::vector<CommandHelp> makeTable() {
    std::vector<CommandHelp> t;
    t.push_back({"validate",
                 "validate PROJECT",
                 "list every problem of a project (exit 2 if any)",
                 "Reads PROJECT and lists every problem it has, one per line on standard error, "
                 "each with the place it is at (contour[3].radius, joint 4|5, design.segments[1]) "
                 "and what is wrong there, and exits with 2. When nothing is, standard output "
                 "says \"valid: N segments\" and the exit code is 0. The follower is placed "
                 "on the contour too: a roller that does not fit is a problem.",
                 {},
                 {"validate cam.cam.json"}});
    t.push_back({"state",
                 "state PROJECT --t SECONDS",
                 "the follower's state at one instant, as JSON",
                 "The polar kinematics of the contour point under the follower ray at time t "
                 "(phi, the segment, r and the radial, circumferential and total velocity, "
                 "acceleration and jerk) and the follower's own motion (lift or arm angle and "
                 "its derivatives, contact point, pressure angle, radii of curvature), as one "
                 "JSON object. Lengths in mm, times in s, angles in degrees.",
                 {{"--t", "SECONDS",
                   "the instant (required); any t within 1e15 turns of 0, reduced to one "
                   "turn exactly"}},
                 {"state cam.cam.json --t 0.25"}});
    t.push_back({"sample",
                 "sample PROJECT [--samples N] [--out FILE.csv]",
                 "one turn sampled at N instants, as CSV",
                 "One turn sampled at N instants t = k·T/N, k = 0 … N−1, as CSV with the header "
                 "t,phi_deg,segment,r,x,y,v_r,v_phi,v,a_r,a_phi,a,j_r,j_phi,j; numbers round-trip "
                 "exactly.",
                 {{"--samples", "N",
                   "instants per turn, 1 to " + std::to_string(kMaxSamplesPerTurn) +
                       " (default: the project's sampling.samples_per_turn, else " +
                       std::to_string(kDefaultSamplesPerTurn) + ")"},
                  {"--out", "FILE.csv",
                   "write the CSV there (replaced whole or not at all) instead of to standard "
                   "output"}},
                 {"sample cam.cam.json --samples 360 --out turn.csv"}});
    t.push_back({"analyze",
                 "analyze PROJECT",
                 "joints, extremes and the follower's checks, as JSON",
                 "For every joint its angle, the gap between the segments (C0, mm), the tangent "
                 "break (degrees) and the jumps of r', r'' and of the radial acceleration; the "
                 "extremes of r, v, a and j with the angles where they occur; for the follower "
                 "the extremes of its lift (or arm angle) and derivatives, the largest pressure "
                 "angle on rise and return, the smallest radii of curvature and the angle ranges "
                 "where the profile undercuts.",
                 {},
                 {"analyze cam.cam.json"}});
    t.push_back(
        {"timing",
         "timing (PROJECT | --path POINTS.csv)\n"
         "[--method seed|exact-stop|optimal] [--accel AX,AY[,AZ]]\n"
         "[--vmax VX,VY[,VZ]] [--feed F] [--step L] [--detail]\n"
         "[--spline chord|circumcircle|oval]",
         "machining time of the contour or of a point list, as JSON",
         "The time a machine with per-axis acceleration and speed limits needs for the tool "
         "path: the contour offset by the project's tool radius, or a point list. Reports "
         "method, time_s, length_mm and segments (with --detail the time of each segment).\n\n"
         "The limits come from the project's machining section; the options override them. "
         "A point list has one point x,y,z[,bulge] per line in mm (a header line is allowed); "
         "a non-zero bulge makes the segment to the next point a circular arc in the XY plane "
         "(DXF convention: bulge = tan of a quarter of the included angle, positive counter-"
         "clockwise).",
         {{"--method", "seed|exact-stop|optimal",
           "optimal (the default): the fastest motion within the limits; exact-stop: rest at "
           "every joint; seed: the seed document's stepwise method"},
          {"--path", "POINTS.csv", "time this point list instead of a project"},
          {"--accel", "AX,AY[,AZ]",
           "axis accelerations in mm/s² (required without a project's machining section); "
           "without AZ the path must stay in one plane z = const, a path that moves along z is "
           "refused (exit 2)"},
          {"--vmax", "VX,VY[,VZ]", "axis speed limits in mm/s"},
          {"--feed", "F", "the path speed limit in mm/s"},
          {"--step", "L", "the seed method's step along the path in mm"},
          {"--detail", "", "add the time of every segment"},
          {"--spline", "chord|circumcircle|oval",
           "the points are teach-in knots of a spline with handles by this rule; it is milled as "
           "tangent arcs within 0.1 µm"}},
         {"timing cam.cam.json", "timing --path points.csv --accel 2000,2000 --feed 100 --detail"},
         1,
         0});
    t.push_back({"fillet",
                 "fillet PROJECT --joint K --out NEW\n(--radius R | --speed V --accel A --vae E)",
                 "round a corner by a tangent arc",
                 "Replaces the corner between contour[K-1] and contour[K] by a switch arc "
                 "tangent to both, and writes the project with it to NEW. The radius is given, "
                 "or the smallest a follower moving at V with the admissible acceleration A "
                 "allows with an admissible acceleration error: R = V²/(vae·A). When no "
                 "radius fits, exit 3 with the radius asked for, the range that would fit and "
                 "the reason.",
                 {{"--joint", "K", "the joint: between contour[K-1] and contour[K] (required)"},
                  {"--radius", "R", "the arc's radius in mm"},
                  {"--speed", "V", "the follower's speed at the corner in mm/s"},
                  {"--accel", "A", "the vector acceleration at the corner in mm/s²"},
                  {"--vae", "E", "the admissible acceleration error, a ratio > 0"},
                  {"--out", "NEW", "the file for the new project (required)"}},
                 {"fillet cam.cam.json --joint 3 --radius 2 --out rounded.cam.json"}});
    t.push_back(
        {"fit-windows",
         "fit-windows PROJECT --out NEW",
         "every window from where its neighbours meet",
         "Sets every window boundary to where its two neighbouring segments meet and writes "
         "the project with it to NEW, as Edit → Fit Windows does. Segments that touch meet at "
         "their tangent point; segments that cross (circles that overlap by the rounding of "
         "typed numbers do, at two points close together) at the intersection nearest the "
         "boundary as it was. Segments that miss each other by at most the typing tolerance of "
         "1e-05 mm are made to meet by the smallest change of the later one: a circle's "
         "centre moves along the line of centres (centre and radius together when that would "
         "open its other joint), a second piece of one circle takes the first piece's circle, a "
         "line moves across its direction; no segment moves by more than 1e-05 mm. Every "
         "change is listed on standard error; a JSON report on standard output gives each "
         "joint's angle and how the segments meet there, and each change.\n\n"
         "Exit 3 naming every joint whose segments miss each other by more than the typing "
         "tolerance, with the distance; exit 2 when the fitted project would still have "
         "problems (they are listed; NEW is not written).",
         {{"--out", "NEW", "the file for the new project (required)"}},
         {"fit-windows typed.cam.json --out fitted.cam.json"}});
    t.push_back({"synthesize",
                 "synthesize PROJECT --out NEW [--tolerance MM]\n[--output arcs]",
                 "the contour made from the project's motion design",
                 "Makes the exact cam profile of the project's design (motion laws over the "
                 "turn) for its follower, fits it with tangent-continuous arcs within the "
                 "tolerance and writes the project with that contour to NEW. A JSON report on "
                 "standard output says what the arcs cost the motion: segments, "
                 "max_deviation_mm (measured on the contour made, not the tolerance) and the "
                 "largest errors of lift, velocity and acceleration. Exit 3 with the reason when "
                 "the design cannot be made (undercut, a roller larger than a concave part, a "
                 "pressure angle beyond the limit of a strict design); exit 2 for a tolerance "
                 "below what double precision can certify for the cam (16 machine epsilons of "
                 "its largest radius; the message gives the limit).",
                 {{"--out", "NEW", "the file for the new project (required)"},
                  {"--tolerance", "MM",
                   "the largest normal deviation from the exact profile (default: the design's "
                   "tolerance)"},
                  {"--output", "arcs", "arcs (the only output of this version)"}},
                 {"synthesize design.cam.json --out cam.cam.json --tolerance 0.001"}});
    t.push_back(
        {"size",
         "size PROJECT [--min-radius MM] [--best-offset|--best-pivot]\n[--out NEW]",
         "the smallest base radius that passes every check",
         "Finds the smallest base radius of the project's motion design for which its "
         "follower (a radial knife when it names none) passes every check: the pressure "
         "angle within the follower's limit on rise and on return, no undercut (the "
         "profile does not fold), and the profile's convex radius at least --min-radius. "
         "It bisects on the exact checks of the exact profile to 1e-9 mm, and prints "
         "JSON: base_radius_mm, the binding check (pressure_angle_rise, "
         "pressure_angle_return, convex_radius) and the angle at_deg where it binds, the "
         "pressure angles and smallest convex radius at that base radius, and a flat "
         "face's face_width_mm. With --out, writes the project with that base radius to "
         "NEW (synthesize then makes its contour). Exit 3 when no base radius up to "
         "1000000 mm passes (an arm whose pivot is too near), naming the check. "
         "With --best-offset (a translating knife or roller), also finds the offset "
         "that allows the smallest base radius, to 1e-6 mm: offset_mm, offset_was_mm, "
         "and feasible_edge, the smallest base radius at 41 offsets over 1.1 times the "
         "steepest lift slope either side (every base radius above it passes); --out "
         "then writes the offset too. With --best-pivot (a swinging arm), finds the "
         "pivot distance instead, the pivot moved along its own direction and the arm "
         "keeping its length: pivot_mm, pivot_distance_mm, pivot_was_mm, and "
         "feasible_edge over pivot distances from the roller's radius to L + radius + "
         "the base radius found at the arm's own pivot.",
         {{"--min-radius", "MM",
           "the smallest convex radius of the profile, in mm (default 0: no cusp)"},
          {"--best-offset", "", "also find the offset that allows the smallest cam"},
          {"--best-pivot", "", "also find the arm's pivot distance that allows the smallest cam"},
          {"--out", "NEW", "the file for the project with the base radius found"}},
         {"size design.cam.json --min-radius 2 --out sized.cam.json"}});
    t.push_back(
        {"suggest",
         "suggest PROJECT [--segment K] [--out NEW]",
         "the recommended law for each stretch of the motion design",
         "Prints the project's design segment by segment with each segment's boundary "
         "classes (VDI 2143: rest, velocity, reversal or movement, as the neighbour at each "
         "end demands) and its law's Cv, Ca, Cj, then the same for the design with the "
         "recommended laws: for every segment that is not a dwell or a line, or only segment "
         "K, the law CODESYS SoftMotion's table recommends for its pair of classes (rest to "
         "rest: modified sine; equal velocities: a line or the inclined sine; every other "
         "pair: poly5 with the joint's velocity and acceleration), so that no velocity or "
         "acceleration jumps. changed lists the segments whose law changed. With --out, "
         "writes the project with those laws to NEW, without a contour (synthesize makes "
         "it). Exit 3 when even the suggested design cannot be built.",
         {{"--segment", "K", "only this segment (0 is the first)"},
          {"--out", "NEW", "the file for the project with the suggested laws"}},
         {"suggest design.cam.json --out suggested.cam.json"}});
    t.push_back(
        {"export",
         "export PROJECT --format " + joinNames(exportFormatNames(), "|") +
             "\n--out FILE [options]",
         "the profile for CAD, CNC and servo drives, or a plot",
         "Writes the profile for another program. dxf: one exact LINE or ARC entity per "
         "segment on layer CONTOUR (splines as tangent arcs within the tolerance). svg: the "
         "profile 1:1 in mm. gcode: a LinuxCNC program milling the contour from outside with "
         "G2/G3 arcs. camtable: a servo drive's electronic cam, master angle → follower lift "
         "with velocity and acceleration per degree, equidistant over one period. csv: the "
         "sampled turn with the follower's motion. png, pdf, and svg with --plot: a plot as "
         "the desktop application draws it (drawn by the program camwright beside this "
         "one).\n\n"
         "Each option belongs to the formats named with it; another is refused.",
         {{"--format", "FORMAT", joinNames(exportFormatNames(), ", ", " or ") + " (required)"},
          {"--out", "FILE", "the file to write (required); replaced whole or not at all"},
          {"--tolerance", "MM",
           "dxf, svg, gcode: how far arcs standing in for splines may deviate (default " +
               formatNumber(kDefaultExportToleranceMm) + " mm for dxf, " +
               formatNumber(kSvgToleranceMm) + " for svg, " +
               formatNumber(kDefaultGcodeToleranceMm) + " for gcode)"},
          {"--points", "N",
           "csv: instants per turn (default: the project's samples per turn); camtable: table "
           "rows, " +
               std::to_string(kMinCamTablePoints) + " to " + std::to_string(kMaxCamTablePoints) +
               " (default " + std::to_string(kDefaultCamTablePoints) + ")"},
          {"--dialect", joinNames(dialectNames(ExportFormatId::CamTable), "|"),
           "camtable: plain CSV (default) or a CODESYS cam table"},
          {"--tool-radius", "MM",
           "dxf: add the tool-centre path on layer TOOLPATH; gcode: the cutter radius "
           "(default: the project's machining.tool_radius)"},
          {"--polyline", "", "dxf: one LWPOLYLINE with bulges instead of LINE and ARC entities"},
          {"--spline-entities", "", "dxf: spline segments as SPLINE entities"},
          {"--centres", "", "dxf: the arcs' centres as points on layer CENTRES"},
          {"--depth", "MM",
           "gcode: the depth to cut to (default " + formatNumber(kDefaultGcodeDepthMm) + " mm)"},
          {"--step-down", "MM", "gcode: cut in passes at most this deep"},
          {"--plate", "1|2",
           "gcode: which plate of a conjugate pair to mill (default 1, the contour)"},
          {"--compensation", "",
           "gcode: program the contour itself with cutter compensation G41/G42 instead of the "
           "tool-centre path"},
          {"--plot", "NAME",
           "png, pdf, svg: contour (default), lift, velocity, acceleration, jerk, motion "
           "(the four on one sheet), feed, axis-acceleration or pressure-angle"},
          {"--size", "WxH",
           "png: pixels (default 1200x800); pdf: points, svg: user units (default 842x595, "
           "A4 landscape); each side 100 to 8000"}},
         {"export cam.cam.json --format dxf --out cam.dxf",
          "export cam.cam.json --format gcode --tool-radius 3 --out cam.ngc",
          "export cam.cam.json --format png --plot velocity --out v.png"}});
    for (CommandHelp& command : t) command.run = commandRunner(command.name);
    return t;
}

}  // namespace

CommandSyntax CommandHelp::syntax() const {
    CommandSyntax s{name, positionals, {}, {}, minPositionals};
    for (const OptionHelp& o : options) (o.value.empty() ? s.flags : s.options).push_back(o.name);
    return s;
}

const std::vector<CommandHelp>& commandTable() {
    static const std::vector<CommandHelp> table = makeTable();
    return table;
}

const CommandHelp* findCommand(const std::string& name) {
    for (const CommandHelp& c : commandTable()) {
        if (c.name == name) return &c;
    }
    return nullptr;
}

std::string overviewHelp() {
    std::string out =
        "usage: camwright-cli COMMAND PROJECT [options]\n"
        "       camwright-cli COMMAND --help    (the command's options)\n\n"
        "commands:\n";
    for (const CommandHelp& c : commandTable()) {
        out += "  " + c.name + std::string(12 - c.name.size(), ' ') + c.summary + "\n";
    }
    out +=
        "\nunits: mm, s, degrees; v in mm/s, a in mm/s², j in mm/s³.\n"
        "--out FILE: written to a temporary file beside it, then renamed over it: FILE\n"
        "    is the old file or the whole new one; a symlink stays a symlink, mode and\n"
        "    owner are kept, but a hard link to the old FILE keeps the old content.\n" +
        kExitCodes;
    return out;
}

std::string commandHelp(const CommandHelp& c) {
    std::string out = "camwright-cli " + c.name + " — " + c.summary + "\n\n";
    // Continuation lines of the synopsis under its first word.
    std::string synopsis = c.synopsis;
    for (std::size_t at = 0; (at = synopsis.find('\n', at)) != std::string::npos; at += 22) {
        synopsis.insert(at + 1, std::string(21, ' '));
    }
    out += "usage: camwright-cli " + synopsis + "\n\n";
    out += wrap(c.description, 0, 0) + "\n";
    if (!c.options.empty()) {
        out += "\noptions:\n";
        for (const OptionHelp& o : c.options) {
            std::string head = "  " + o.name + (o.value.empty() ? "" : " " + o.value);
            // The text beside a short option, below a long one.
            constexpr std::size_t kTextColumn = 26;
            if (head.size() + 2 <= kTextColumn) {
                head += std::string(kTextColumn - head.size(), ' ');
                out += head + wrap(o.text, kTextColumn, kTextColumn) + "\n";
            } else {
                out += head + "\n" + std::string(kTextColumn, ' ') +
                       wrap(o.text, kTextColumn, kTextColumn) + "\n";
            }
        }
    }
    out += "\n" + kExitCodes;
    out += "\nexample" + std::string(c.examples.size() > 1 ? "s" : "") + ":\n";
    for (const std::string& e : c.examples) out += "  camwright-cli " + e + "\n";
    return out;
}

}  // namespace cam::cli
