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
    } else {
        CamTableOptions options;
        if (const auto p = args.option("--points")) {
            options.points = static_cast<std::size_t>(
                parseCount("--points", *p, kMinCamTablePoints, kMaxCamTablePoints));
        }
        if (const auto d = args.option("--dialect")) {
            const ExportDialectKind* dialect = findDialect(kind, *d);
            if (!dialect) {
                throw CliError{kInvalidInput, "--dialect",
                               "unknown cam table dialect '" + *d + "' (" +
                                   joinNames(dialectNames(kind.id), ", ") + ")"};
            }
            // The table lists the dialects in CamTableDialect's order.
            options.dialect = static_cast<CamTableDialect>(dialect - kind.dialects.data());
        }
        options.name = exportName(loaded.project.name, input);
        options.follower = loaded.project.follower.value_or(FollowerSpec{});
        text = camTableText(loaded.contour, options);
    }
    if (!text.ok()) exportFailed(input, text.errors());
    writeExport(*outPath, text.value());
    return kOk;
}

}  // namespace cam::cli
