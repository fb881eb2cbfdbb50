// SPDX-License-Identifier: GPL-3.0-or-later
// Speed of the surface drawing: expression evaluation and the floating-horizon sweep.
#include <benchmark/benchmark.h>

#include <variant>

#include "render/floating_horizon.h"
#include "render/surface_expression.h"

namespace {

using namespace roomcad;

SurfaceExpression compile(const char* text) { return parse_surface_expression(text).value(); }

void BM_EvaluateDampedWave(benchmark::State& state) {
  const SurfaceExpression e = compile("cos(sqrt(x*x+z*z))/(sqrt(x*x+z*z)+1)");
  double x = 0.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(e.evaluate(x, 0.5));
    x += 1e-6;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_EvaluateDampedWave);

/// The propeller on an n x n grid, 800 columns: the sweep's cost grows with n^2 samples.
void BM_FloatingHorizonPropeller(benchmark::State& state) {
  const SurfaceExpression e = compile("x*z*(x+z)*(x-z)");
  const double step = 4.0 / static_cast<double>(state.range(0) - 1);
  const SurfaceView view{.x_min = -2,
                         .x_max = 2,
                         .z_min = -2,
                         .z_max = 2,
                         .dx = step,
                         .dz = step,
                         .rotate_x_deg = 30,
                         .rotate_y_deg = 10};
  std::size_t lines = 0;
  for (auto _ : state) {
    const SurfaceDrawing d = draw_floating_horizon(
        [&e](double x, double z) { return e.evaluate(x, z); }, view, SurfaceScreen{});
    lines = d.polylines.size();
    benchmark::DoNotOptimize(lines);
  }
  state.counters["polylines"] = static_cast<double>(lines);
  state.SetItemsProcessed(state.iterations() * state.range(0) * state.range(0));
}
BENCHMARK(BM_FloatingHorizonPropeller)
    ->Arg(101)
    ->Arg(401)
    ->Arg(1001)
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
