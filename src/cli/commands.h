#pragma once
/// @file
/// @brief The camwright-cli commands (cli.md), one file each in cli/commands/. Each returns an
/// exit code or throws CliError; the command table (cli/help.cpp) names the function of each.

#include <iosfwd>

#include "cli/arguments.h"

namespace cam::cli {

int runValidate(const Arguments& args, std::ostream& out, std::ostream& err);
int runState(const Arguments& args, std::ostream& out, std::ostream& err);
int runSample(const Arguments& args, std::ostream& out, std::ostream& err);
int runAnalyze(const Arguments& args, std::ostream& out, std::ostream& err);
int runTiming(const Arguments& args, std::ostream& out, std::ostream& err);
int runFillet(const Arguments& args, std::ostream& out, std::ostream& err);
/// @brief `fit-windows`: every window from where its neighbours meet (Fit Windows), to --out.
int runFitWindows(const Arguments& args, std::ostream& out, std::ostream& err);
int runExport(const Arguments& args, std::ostream& out, std::ostream& err);
/// @brief `synthesize`: the design → an arc table (math.md §8), written to --out; a report.
int runSynthesize(const Arguments& args, std::ostream& out, std::ostream& err);
int runSuggest(const Arguments& args, std::ostream& out, std::ostream& err);
int runSize(const Arguments& args, std::ostream& out, std::ostream& err);

}  // namespace cam::cli
