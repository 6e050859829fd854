// `analyze`'s contour analysis (joints and the extremes of every quantity) per segment, on the
// six-lobe cam with each of its 13 arcs split into equal windows of the same circle: a real
// contour, its extremes in a few of its segments, at 1,000 to 100,000 segments (items =
// segments). Issue 29 asks for at most 5 µs per segment at 100,000. See docs/performance.md.

#include <benchmark/benchmark.h>

#include <cstdlib>

#include "analysis/analysis.h"
#include "contour/contour.h"
#include "io/project_json.h"

namespace {

/// The six-lobe cam, each arc cut into windows so that there are about n segments.
cam::Contour splitSixLobe(std::size_t n, double* omega) {
    auto loaded =
        cam::loadProjectFile(std::string(CAMWRIGHT_EXAMPLES) + "/six-lobe-arc-cam.cam.json");
    if (!loaded.ok()) std::abort();
    cam::Project project = loaded.value();
    *omega = project.motion.omegaRadS();
    const std::size_t pieces = std::max<std::size_t>(1, n / project.contour.size());
    std::vector<cam::SegmentSpec> split;
    for (const cam::SegmentSpec& s : project.contour) {
        for (std::size_t k = 0; k < pieces; ++k) {
            cam::SegmentSpec piece = s;
            const double width = s.phiEndDeg - s.phiStartDeg;
            piece.phiStartDeg = s.phiStartDeg + width * static_cast<double>(k) / pieces;
            piece.phiEndDeg = k + 1 == pieces
                                  ? s.phiEndDeg
                                  : s.phiStartDeg + width * static_cast<double>(k + 1) / pieces;
            split.push_back(piece);
        }
    }
    project.contour = std::move(split);
    auto contour = cam::Contour::build(project);
    if (!contour.ok()) std::abort();
    return contour.value();
}

void BM_AnalyzeContour(benchmark::State& state) {
    double omega = 0.0;
    const cam::Contour contour = splitSixLobe(static_cast<std::size_t>(state.range(0)), &omega);
    for (auto _ : state) {
        const cam::ContourAnalysis a = cam::analyzeContour(contour, omega);
        benchmark::DoNotOptimize(a.extremes.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(contour.size()));
    state.counters["us_per_segment"] =
        benchmark::Counter(static_cast<double>(state.iterations() * contour.size()) * 1e-6,
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_AnalyzeContour)->Arg(1'000)->Arg(10'000)->Arg(100'000)->Unit(benchmark::kMillisecond);

}  // namespace
