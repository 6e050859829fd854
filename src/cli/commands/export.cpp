#include "cli/commands.h"

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <span>
#include <string_view>
#include <vector>

#include "cli/command_support.h"
#include "cli/export_choice.h"
#include "cli/plot_pictures.h"
#include "design/motion_design.h"
#include "export/cam_table.h"
#include "export/dxf.h"
#include "export/export_formats.h"
#include "export/gcode.h"
#include "export/svg.h"

namespace cam::cli {
namespace {

/// The first error of an export that cannot be made: a bad option (exit 2) or geometry the
/// format cannot take (exit 3, naming the segment).
[[noreturn]] void exportFailed(const std::string& project, const Diagnostics& errors) {
    const Diagnostic& d = errors.front();
    if (d.location.rfind("--", 0) == 0) throw CliError{kInvalidInput, d.location, d.message};
    throw CliError{kNotComputable, project + ": " + d.location, d.message};
}

Json extremes(const CamExtreme& lo, const CamExtreme& hi) {
    return {
        {"min", lo.value}, {"min_at_deg", lo.atDeg}, {"max", hi.value}, {"max_at_deg", hi.atDeg}};
}

/// The JSON report of a cam table (printed on stdout).
Json camTableJson(const CamTableReport& r, std::string_view dialect, CamTableSource source,
                  bool arm, std::optional<double> tolerance) {
    Json json;
    json["format"] = "camtable";
    json["dialect"] = dialect;
    json["source"] = source == CamTableSource::Law ? "law" : "contour";
    json["slave_unit"] = arm ? "deg" : "mm";
    json["points"] = r.points;
    if (tolerance) json["tolerance"] = *tolerance;
    json["interpolation"] = r.interpolation;
    json["max_error"] = {{"position", r.positionError},
                         {"position_at_deg", r.positionErrorAtDeg},
                         {"velocity_per_deg", r.velocityError},
                         {"acceleration_per_deg2", r.accelerationError}};
    const CamCharacteristics& c = r.characteristics;
    json["characteristics"] = {
        {"position", extremes(c.positionMin, c.positionMax)},
        {"velocity_per_deg", extremes(c.velocityMin, c.velocityMax)},
        {"acceleration_per_deg2", extremes(c.accelerationMin, c.accelerationMax)},
        {"jerk_per_deg3", extremes(c.jerkMin, c.jerkMax)}};
    return json;
}

/// `export --format camtable`: the table of the design's law or of the follower on the contour
/// (`--source`), its points given (`--points`) or chosen for `--tolerance`; the report on stdout.
int exportCamTable(const Arguments& args, const ExportFormatKind& kind, const std::string& input,
                   const std::string& outPath, std::ostream& out) {
    CamTableOptions options;
    const std::optional<std::string> pointsText = args.option("--points");
    const std::optional<std::string> toleranceText = args.option("--tolerance");
    if (pointsText && toleranceText) {
        throw CliError{kUsage, "--tolerance",
                       "cannot be given with --points: the tolerance chooses the number of points"};
    }
    if (pointsText) {
        options.points = static_cast<std::size_t>(
            parseCount("--points", *pointsText, kMinCamTablePoints, kMaxCamTablePoints));
    }
    std::optional<double> tolerance;
    if (toleranceText) tolerance = parsePositive("--tolerance", *toleranceText, "mm");
    const ExportDialectKind* dialect = kind.dialects.data();
    if (const auto d = args.option("--dialect")) {
        dialect = findDialect(kind, *d);
        if (!dialect) {
            throw CliError{kInvalidInput, "--dialect",
                           "unknown cam table dialect '" + *d + "' (" +
                               joinNames(dialectNames(kind.id), ", ") + ")"};
        }
    }
    // The table lists the dialects in CamTableDialect's order.
    options.dialect = static_cast<CamTableDialect>(dialect - kind.dialects.data());
    std::optional<CamTableSource> source;
    if (const auto s = args.option("--source")) {
        if (*s == "law") {
            source = CamTableSource::Law;
        } else if (*s == "contour") {
            source = CamTableSource::Contour;
        } else {
            throw CliError{kInvalidInput, "--source", "unknown source '" + *s + "' (law, contour)"};
        }
    }

    // A design never synthesised is a plain electronic cam, master to slave directly: its law
    // makes the table.
    const LoadedOrDesign loaded = loadAllowingDesignOnly(input);
    const Project& project = loaded.loaded ? loaded.loaded->project : *loaded.designOnly;
    const CamTableSource chosen =
        source.value_or(project.design ? CamTableSource::Law : CamTableSource::Contour);
    const FollowerSpec follower = project.follower.value_or(FollowerSpec{});
    const bool arm = follower.motion == FollowerMotion::Oscillating;
    CamMotion motion;
    if (chosen == CamTableSource::Law) {
        if (!project.design) {
            throw CliError{
                kInvalidInput, "--source",
                "law: " + input + " has no design (no motion law to sample); use --source contour"};
        }
        auto design = MotionDesign::build(*project.design);
        if (!design.ok()) exportFailed(input, design.errors());
        motion = lawMotion(design.value(), arm);
    } else {
        if (!loaded.loaded) {
            throw CliError{kInvalidInput, "--source",
                           "contour: " + input +
                               " has no contour (its design was never synthesised: run "
                               "'camwright-cli synthesize', or use --source law)"};
        }
        auto fromContour = contourMotion(loaded.loaded->contour, follower);
        if (!fromContour.ok()) exportFailed(input, fromContour.errors());
        motion = std::move(fromContour).value();
    }
    if (tolerance) {
        const std::optional<std::size_t> points = camTablePointsFor(motion, options, *tolerance);
        if (!points) {
            throw CliError{kNotComputable, "--tolerance",
                           formatNumber(*tolerance) + " cannot be met with " +
                               std::to_string(kMaxCamTablePoints) + " points in the " +
                               std::string(dialect->name) + " dialect"};
        }
        options.points = *points;
    }
    options.name = exportName(project.name, input);
    options.follower = follower;
    Result<CamTable> table = camTable(motion, options);
    if (!table.ok()) exportFailed(input, table.errors());
    const Json report = camTableJson(table.value().report, dialect->name, chosen, arm, tolerance);
    requireFinite(report, "");
    writeExport(outPath, table.value().text);
    printJson(out, report);
    return kOk;
}

}  // namespace

int runExport(const Arguments& args, std::ostream& out, std::ostream& /*err*/) {
    const std::string& input = args.positional.at(0);
    const std::optional<std::string> format = args.option("--format");
    const std::string formats = joinNames(exportFormatNames(), ", ");
    if (!format) throw CliError{kUsage, "export", "--format is required (" + formats + ")"};
    const std::optional<std::string> outPath = args.option("--out");
    if (!outPath) throw CliError{kUsage, "export", "--out FILE is required"};
    const auto choice = chooseExportFormat(*format, args.option("--plot").has_value());
    if (!choice) {
        throw CliError{kUsage, "--format",
                       "unknown format '" + *format + "' (one of " + formats + ")"};
    }
    const ExportFormatKind& kind = *choice->format;
    // Which options each format takes (export/export_formats.h); any other is a mistake worth
    // saying.
    const auto takes = [](std::span<const std::string_view> names, const std::string& name) {
        return std::find(names.begin(), names.end(), name) != names.end();
    };
    for (const auto& [name, value] : args.options) {
        if (name == "--format" || name == "--out") continue;
        if (!takes(kind.options, name)) {
            throw CliError{kUsage, name, "is not an option of --format " + *format};
        }
    }
    for (const std::string& flag : args.flags) {
        if (!takes(kind.flags, flag)) {
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
    if (kind.id == ExportFormatId::CamTable)
        return exportCamTable(args, kind, input, *outPath, out);
    double tolerance = kind.id == ExportFormatId::Svg ? kSvgToleranceMm : kDefaultExportToleranceMm;
    if (const auto text = args.option("--tolerance")) {
        tolerance = parseFiniteNumber("--tolerance", *text, "a tolerance in mm");
    }
    const Loaded loaded = load(input);

    if (kind.id == ExportFormatId::Picture) {
        const std::string plot = args.option("--plot").value_or("contour");
        const auto& names = kPlotNames;
        if (std::find(std::begin(names), std::end(names), plot) == std::end(names)) {
            throw CliError{kUsage, "--plot",
                           "unknown plot '" + plot + "' (one of " + plotNameList() + ")"};
        }
        return drawPlotWithApp(input, plot, std::string(choice->dialect->name),
                               args.option("--size"), *outPath);
    }
    if (kind.id == ExportFormatId::Csv) {
        long long n = loaded.project.samplesPerTurnOrDefault();
        if (const auto text = args.option("--points")) {
            n = parseCount("--points", *text, 1, kMaxSamplesPerTurn);
        }
        writeSampleCsv(loaded, n, out, outPath, &loaded.follower);
        return kOk;
    }
    Result<std::string> text = std::string();
    if (kind.id == ExportFormatId::Dxf) {
        DxfOptions options;
        options.toleranceMm = tolerance;
        options.polyline = args.hasFlag("--polyline");
        options.splineEntities = args.hasFlag("--spline-entities");
        options.centres = args.hasFlag("--centres");
        if (const auto r = args.option("--tool-radius")) {
            options.toolRadiusMm = parseFiniteNumber("--tool-radius", *r, "a radius in mm");
        }
        options.groove = grooveOf(loaded.project);
        if (const auto plate = secondPlate(loaded, input)) options.secondPlate = plate->path;
        text = dxfDocument(loaded.contour, options);
    } else if (kind.id == ExportFormatId::Gcode) {
        GcodeOptions options;
        const MachiningSpec machining = loaded.project.machining.value_or(MachiningSpec{});
        options.groove = grooveOf(loaded.project);
        if (const auto r = args.option("--tool-radius")) {
            options.toolRadiusMm = parseFiniteNumber("--tool-radius", *r, "a radius in mm");
        } else if (options.groove) {
            // A groove is cut in one slot pass by a tool of half its width.
            options.toolRadiusMm = options.groove->width() / 2.0;
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
        options.projectName = exportName(loaded.project.name, input);
        // A conjugate pair's plates are milled one by one: the second is its fitted arcs.
        const std::optional<std::string> plate = args.option("--plate");
        if (plate && *plate != "1" && *plate != "2") {
            throw CliError{kUsage, "--plate", "must be 1 or 2 (got '" + *plate + "')"};
        }
        if (plate && !loaded.project.follower.value_or(FollowerSpec{}).conjugate()) {
            throw CliError{kUsage, "--plate",
                           "is for a conjugate pair; this project's follower has one plate"};
        }
        if (plate == "2") {
            auto contour = plateContour(*secondPlate(loaded, input));
            if (!contour.ok()) exportFailed(input, contour.errors());
            options.projectName += ", second plate";
            text = gcodeProgram(contour.value(), options);
        } else {
            text = gcodeProgram(loaded.contour, options);
        }
    } else if (kind.id == ExportFormatId::Svg) {
        SvgOptions options;
        options.toleranceMm = tolerance;
        options.title = exportName(loaded.project.name, input);
        options.groove = grooveOf(loaded.project);
        if (const auto plate = secondPlate(loaded, input)) options.secondPlate = plate->path;
        text = svgDocument(loaded.contour, options);
    }
    if (!text.ok()) exportFailed(input, text.errors());
    writeExport(*outPath, text.value());
    return kOk;
}

}  // namespace cam::cli
