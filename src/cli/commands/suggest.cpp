#include <ostream>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "design/boundary_classes.h"
#include "design/motion_design.h"
#include "evaluation/evaluation.h"

namespace cam::cli {
namespace {

/// Each segment of a design: its law, stretch, boundary classes and Cv, Ca, Cj.
Json segmentsOf(const DesignSpec& spec, const MotionDesign& design) {
    const std::vector<SegmentClasses> classes = boundaryClasses(design);
    Json out = Json::array();
    double from = 0.0;
    for (std::size_t k = 0; k < spec.segments.size(); ++k) {
        const DesignSegmentSpec& s = spec.segments[k];
        const LawCoefficients c = design.coefficients(k);
        out.push_back({{"law", std::string(lawName(s.law))},
                       {"from_deg", from},
                       {"to_deg", s.toDeg},
                       {"start_class", std::string(boundaryClassName(classes[k].start))},
                       {"end_class", std::string(boundaryClassName(classes[k].end))},
                       {"cv", c.cv},
                       {"ca", c.ca},
                       {"cj", c.cj}});
        from = s.toDeg;
    }
    return out;
}

}  // namespace

int runSuggest(const Arguments& args, std::ostream& out, std::ostream& /*err*/) {
    const std::string& path = args.positional.front();
    Project project = loadStructure(path);
    if (!project.design) {
        throw CliError{kInvalidInput, path + ": design",
                       "the project has no design to suggest laws for"};
    }
    std::optional<std::size_t> only;
    if (const auto k = args.option("--segment")) {
        const auto last = static_cast<long long>(project.design->segments.size()) - 1;
        only = static_cast<std::size_t>(parseCount("--segment", *k, 0, std::max(last, 0LL)));
    }
    // The design's classes as they are (its joints need not fit yet), then the suggestion.
    const auto before = MotionDesign::buildIgnoringJoints(*project.design);
    if (!before.ok()) {
        const Diagnostic& d = before.errors().front();
        throw CliError{kInvalidInput, placeOf(path, d), d.message};
    }
    const auto suggested = suggestLaws(*project.design, only);
    if (!suggested.ok()) {
        const Diagnostic& d = suggested.errors().front();
        throw CliError{kInvalidInput, placeOf(path, d), d.message};
    }
    const auto after = MotionDesign::build(suggested.value());
    if (!after.ok()) {
        const Diagnostic& d = after.errors().front();
        throw CliError{kNotComputable, placeOf(path, d), d.message};
    }
    Json changed = Json::array();
    for (std::size_t k = 0; k < project.design->segments.size(); ++k) {
        if (!(suggested.value().segments[k] == project.design->segments[k])) changed.push_back(k);
    }
    Json report{{"segments", segmentsOf(*project.design, before.value())},
                {"suggested", segmentsOf(suggested.value(), after.value())},
                {"changed", changed}};
    Json notes = Json::array();
    for (const Diagnostic& d : after.value().jumps()) notes.push_back(d.text());
    report["notes"] = notes;
    if (const auto outPath = args.option("--out")) {
        // The contour of the old laws is no longer the design's: the new project has none
        // (synthesize makes it).
        project.design = suggested.value();
        project.contour.clear();
        report["out"] = *outPath;
        writeProjectOut(*outPath, project, report);
    }
    printJson(out, report);
    return kOk;
}

}  // namespace cam::cli
