// SPDX-License-Identifier: GPL-3.0-or-later
// What repair costs against validation of the same plan, printed as a markdown table: the
// bundled Sweet Home 3D homes (examples/sweethome3d/), the grids of rooms as drawn (nothing to
// repair: repair is one validation and one analytic volume), and the grids with every wall
// drawn twice (every wall repaired), from 10 x 10 rooms up. Best of `runs` wall-clock times.
// Run: build/bench/repair_bench [--quick]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "bench/bundled_homes.h"
#include "repair/repair.h"
#include "testing/grid_plan.h"
#include "validation/validate.h"

namespace {

using Clock = std::chrono::steady_clock;
using roomcad::Plan;

template <class F>
double best_ms(int runs, F&& f) {
  double best = 1e300;
  for (int r = 0; r < runs; ++r) {
    const auto start = Clock::now();
    f();
    best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  return best;
}

void row(const std::string& name, const Plan& plan, int runs) {
  std::size_t before = 0, after = 0, edits = 0;
  const double validate_ms = best_ms(runs, [&] { before = roomcad::validate(plan).error_count(); });
  const double repair_ms = best_ms(runs, [&] {
    const roomcad::RepairResult r = roomcad::repair_plan(plan).value();
    after = r.remaining.size();
    edits = r.edits.size();
  });
  std::printf("| %s | %zu | %zu | %zu | %zu | %.1f | %.1f | %.1f |\n", name.c_str(),
              plan.walls.size(), before, after, edits, validate_ms, repair_ms,
              repair_ms / validate_ms);
  std::fflush(stdout);
}

/// The grid with every wall drawn a second time over itself (ids "<id>-again").
Plan drawn_twice(Plan plan) {
  const std::size_t n = plan.walls.size();
  for (std::size_t i = 0; i < n; ++i) {
    roomcad::Wall copy = plan.walls[i];
    copy.id += "-again";
    plan.walls.push_back(copy);
  }
  return plan;
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const int runs = quick ? 1 : 3;
  std::printf(
      "| plan | walls | errors | after | edits | validate ms | repair ms | repair / validate |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const auto& home : roomcad::bench::read_homes({})) row(home.name, home.plan, runs);
  for (const int n : quick ? std::vector<int>{10, 20} : std::vector<int>{10, 20, 40, 224}) {
    roomcad::samples::GridSpec spec;
    spec.n = n;
    const Plan grid = roomcad::samples::make_grid_plan(spec);
    row("grid " + std::to_string(n) + "x" + std::to_string(n), grid, n >= 224 ? 1 : runs);
    if (n <= 80)
      row("grid " + std::to_string(n) + "x" + std::to_string(n) + ", walls drawn twice",
          drawn_twice(grid), runs);
  }
}
