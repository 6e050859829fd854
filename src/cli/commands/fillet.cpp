#include "cli/commands.h"

#include <ostream>

#include "cli/command_support.h"
#include "fillet/fillet.h"

namespace cam::cli {

int runFillet(const Arguments& args, std::ostream& out, std::ostream& /*err*/) {
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
    writeProjectOut(*outPath, filleted, summary);
    printJson(out, summary);
    return kOk;
}

}  // namespace cam::cli
