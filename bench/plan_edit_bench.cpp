// SPDX-License-Identifier: GPL-3.0-or-later
// Cost of the decimal-exact plan transforms (plan/transform2d.h, plan/plan_edit.h)
// against plain double arithmetic, as the number of walls grows.
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <array>

#include "plan/plan_edit.h"
#include "plan/transform2d.h"

namespace roomcad {
namespace {

/// A grid of n short walls with decimal coordinates, one window every fourth wall.
Plan grid_plan(int n) {
  Plan plan;
  for (int i = 0; i < n; ++i) {
    Wall w;
    w.id = fmt::format("w{}", i);
    w.from = {0.1 + 1.25 * (i % 100), 0.35 + 2.5 * (i / 100)};
    w.to = {w.from.x + 1.1, w.from.y};
    plan.walls.push_back(w);
    if (i % 4 != 0) continue;
    Opening o = default_opening(OpeningType::window);
    o.id = fmt::format("o{}", i);
    o.wall = w.id;
    o.width = 0.6;
    o.offset = 0.2;
    plan.openings.push_back(o);
  }
  return plan;
}

void BM_RotateAllQuarterTurn(benchmark::State& state) {
  Plan plan = grid_plan(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(rotate_all(plan, 90.0));
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_RotateAllQuarterTurn)->RangeMultiplier(10)->Range(10, 10000)->Complexity();

void BM_ScaleAll(benchmark::State& state) {
  Plan plan = grid_plan(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(scale_all(plan, 2.0));
    benchmark::DoNotOptimize(scale_all(plan, 0.5));
  }
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_ScaleAll)->RangeMultiplier(10)->Range(10, 10000)->Complexity();

void BM_ApplyExact(benchmark::State& state) {
  const Transform2d t = rotate(90.0, {3.3, 1.7});
  Point2 p{1.1, 2.3};
  for (auto _ : state) benchmark::DoNotOptimize(p = apply(t, p));
}
BENCHMARK(BM_ApplyExact);

void BM_ApplyPlainDouble(benchmark::State& state) {
  const Transform2d t = rotate(90.0, {3.3, 1.7});
  Point2 p{1.1, 2.3};
  for (auto _ : state) {
    p = {p.x * t.m[0][0] + p.y * t.m[1][0] + t.m[2][0],
         p.x * t.m[0][1] + p.y * t.m[1][1] + t.m[2][1]};
    benchmark::DoNotOptimize(p);
  }
}
BENCHMARK(BM_ApplyPlainDouble);

}  // namespace
}  // namespace roomcad

BENCHMARK_MAIN();
