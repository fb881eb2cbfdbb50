// SPDX-License-Identifier: GPL-3.0-or-later
// Reading plan files: read_plan_text on generated grids up to the 100,800-wall plan (n = 224,
// about 23 MB of canonical JSON), in MB/s; the canonical writer; and reading then validating,
// which is what `roomcad validate` does end to end. Run: build/bench/plan_read_bench
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "io/plan_json.h"
#include "testing/grid_plan.h"
#include "validation/validate.h"

namespace {

using namespace roomcad;

/// The canonical text of the n x n grid, made once per n.
const std::string& grid_text(int n) {
  static std::map<int, std::string> texts;
  auto [it, added] = texts.try_emplace(n);
  if (added) it->second = write_plan_text(samples::make_grid_plan({.n = n}));
  return it->second;
}

void BM_ReadPlan(benchmark::State& state) {
  const std::string& text = grid_text(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Result<Plan> plan = read_plan_text(text, "grid.json");
    if (!plan) state.SkipWithError(plan.message().c_str());
    benchmark::DoNotOptimize(plan);
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
  state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
}

void BM_WritePlan(benchmark::State& state) {
  const Plan plan = *read_plan_text(grid_text(static_cast<int>(state.range(0))), "grid.json");
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string text = write_plan_text(plan);
    bytes += text.size();
    benchmark::DoNotOptimize(text.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
}

void BM_ReadAndValidate(benchmark::State& state) {
  const std::string& text = grid_text(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Report report;
    const Result<Plan> plan = read_plan_text(text, "grid.json", &report);
    if (plan) report.append(validate(*plan, {.unknown_field_warnings = false}));
    benchmark::DoNotOptimize(report);
  }
}

BENCHMARK(BM_ReadPlan)->Arg(10)->Arg(70)->Arg(224)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WritePlan)->Arg(70)->Arg(224)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadAndValidate)->Arg(70)->Arg(224)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
