// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the floor-plan drawing on the bundled house (21 walls) and on grids of rooms.
#include <benchmark/benchmark.h>

#include "io/floor_plan_svg.h"
#include "io/plan_json.h"
#include "render/floor_plan.h"
#include "testing/grid_plan.h"

namespace {

using namespace roomcad;

void BM_FloorPlanHouse(benchmark::State& state) {
  const Result<Plan> read = read_plan_file(ROOMCAD_SOURCE_DIR "/examples/house.json");
  if (!read) {
    state.SkipWithError("examples/house.json does not read");
    return;
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        make_floor_plan_svg(draw_floor_plan(read.value(), {}), "").to_string());
  }
}
BENCHMARK(BM_FloorPlanHouse)->Unit(benchmark::kMillisecond);

/// n x n rooms (testing/grid_plan.h): 2 n (n + 1) walls, with doors and windows; rooms included.
void BM_FloorPlanGrid(benchmark::State& state) {
  const Plan plan = samples::make_grid_plan({.n = static_cast<int>(state.range(0))});
  for (auto _ : state) benchmark::DoNotOptimize(draw_floor_plan(plan, {}).cut_walls.size());
  state.counters["walls"] = static_cast<double>(plan.walls.size());
}
BENCHMARK(BM_FloorPlanGrid)->Arg(2)->Arg(5)->Arg(10)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
