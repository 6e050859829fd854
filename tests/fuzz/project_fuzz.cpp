// libFuzzer harness: any byte string through the whole pipeline a project file takes —
// parse, validate, compile, state, sampling, analysis, save. Must never crash, hang or trip a
// sanitizer; a file that loads must save and load back to the same document.
// Build: cmake --preset fuzz && cmake --build --preset fuzz; run: see tests/fuzz/README.md.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "analysis/analysis.h"
#include "contour/contour.h"
#include "io/project_json.h"
#include "kinematics/kinematics.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const auto project = cam::parseProject(text);
    if (!project.ok()) {
        if (project.errors().empty()) std::abort();  // a refusal must say why
        return 0;
    }
    const auto contour = cam::Contour::build(project.value());
    if (!contour.ok()) std::abort();  // loading validates: a loaded project must compile
    const double omega = project.value().motion.omegaRadS();
    if (!std::isfinite(omega) || omega == 0.0) std::abort();
    for (double t : {0.0, 0.123, -7.5, 1e6}) (void)cam::stateAt(contour.value(), omega, t);
    cam::SampledTurn turn;
    cam::sampleTurn(contour.value(), omega, 97, turn);
    (void)cam::analyzeContour(contour.value(), omega);
    const std::string saved = cam::serializeProject(project.value());
    const auto again = cam::parseProject(saved);
    if (!again.ok() || !(again.value() == project.value())) std::abort();
    if (cam::serializeProject(again.value()) != saved) std::abort();
    return 0;
}
