#include "cli/commands.h"

#include <ostream>

#include "cli/command_support.h"

namespace cam::cli {

int runSample(const Arguments& args, std::ostream& out, std::ostream& /*err*/) {
    long long n = 0;
    if (const auto text = args.option("--samples")) {
        n = parseCount("--samples", *text, 1, kMaxSamplesPerTurn);
    }
    const Loaded loaded = load(args.positional.at(0));
    if (n == 0) n = loaded.project.samplesPerTurnOrDefault();
    writeSampleCsv(loaded, n, out, args.option("--out"));
    return kOk;
}

}  // namespace cam::cli
