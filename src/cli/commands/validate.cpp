#include "cli/commands.h"

#include <optional>
#include <ostream>

#include "cli/command_support.h"
#include "evaluation/evaluation.h"
#include "io/project_json.h"

namespace cam::cli {

int runValidate(const Arguments& args, std::ostream& out, std::ostream& err) {
    const std::string& path = args.positional.at(0);
    const auto project = loadProjectStructure(path);
    std::optional<ProjectEvaluation> evaluation;
    if (project.ok()) evaluation = evaluateProject(project.value());
    if (!evaluation || !evaluation->valid()) {
        // One write for all: stderr is unbuffered, and a file can have a problem per segment.
        std::string lines;
        for (const Diagnostic& d : evaluation ? evaluation->problems : project.errors()) {
            if (d.severity != Severity::Error) continue;
            lines += "camwright-cli: " + placeOf(path, d) + ": " + d.message + '\n';
        }
        err << lines;
        return kInvalidInput;
    }
    if (evaluation->status == EvaluationStatus::AwaitsContour) {
        // Valid (project-format.md): a design whose contour was never synthesised.
        out << "valid: a design, no contour yet (camwright-cli synthesize makes it)\n";
        return kOk;
    }
    out << "valid: " << project.value().contour.size() << " segments\n";
    return kOk;
}

}  // namespace cam::cli
