#pragma once
/// @file
/// @brief The camwright-cli commands (cli.md). Each returns an exit code or throws CliError.

#include <iosfwd>

#include "cli/arguments.h"

namespace cam::cli {

int runValidate(const Arguments& args, std::ostream& out, std::ostream& err);
int runState(const Arguments& args, std::ostream& out);
int runSample(const Arguments& args, std::ostream& out);
int runAnalyze(const Arguments& args, std::ostream& out);
int runTiming(const Arguments& args, std::ostream& out);
int runFillet(const Arguments& args, std::ostream& out);
int runExport(const Arguments& args, std::ostream& out);
/// @brief `synthesize`: the design → an arc table (math.md §8), written to --out; a report.
int runSynthesize(const Arguments& args, std::ostream& out);

}  // namespace cam::cli
