// Loading big project text (items = segments): parse, read and validate a polygon of N lines,
// and refuse a contour of N empty objects (one problem each). Both must be linear: the time per
// segment stays flat from 10,000 to 1,000,000 (at 612d090 160,000 segments took 10 s and
// 400,000 empty objects 24 s, as the callback parser rescanned its parent after every value).
// A million lines are 106 MB of text, more than a file may have (kMaxProjectFileBytes): here
// the text is parsed from memory.

#include <benchmark/benchmark.h>

#include <string>

#include "big_projects.h"
#include "io/project_json.h"

namespace {

void BM_LoadPolygon(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const std::string text = cam::test::projectOfLines(n);
    for (auto _ : state) {
        const auto project = cam::parseProject(text);
        if (!project.ok() || project.value().contour.size() != n) {
            state.SkipWithError("the polygon did not load");
            break;
        }
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
}

void BM_RefuseEmptyObjects(benchmark::State& state) {
    const auto n = static_cast<std::size_t>(state.range(0));
    const std::string text = cam::test::projectOfEmptySegments(n);
    for (auto _ : state) {
        const auto project = cam::parseProject(text);
        if (project.ok() || project.errors().size() != n) {
            state.SkipWithError("expected one problem per empty segment");
            break;
        }
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
}

BENCHMARK(BM_LoadPolygon)->Arg(10'000)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RefuseEmptyObjects)
    ->Arg(10'000)
    ->Arg(100'000)
    ->Arg(400'000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
