// SPDX-License-Identifier: GPL-3.0-or-later
// The C++ side of bench/python_bench.py: writes the n x n grid plan (testing/grid_plan.h) to a
// file, then times what Plan.validate() and Plan.build() call (check_plan, build_model) on it,
// as the Python module calls them, and prints the times as JSON. The driver times the same
// calls through Python on the same file and reports the overhead.
// Run: build/bench/python_overhead_bench N OUT.json REPEATS THREADS
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "io/plan_check.h"
#include "io/plan_json.h"
#include "solid/build_model.h"
#include "testing/grid_plan.h"

namespace {

using namespace roomcad;

/// @return the best of `repeats` wall times of `work`, milliseconds.
template <class Work>
double best_ms(int repeats, Work&& work) {
  double best = 1e300;
  for (int i = 0; i < repeats; ++i) {
    const auto start = std::chrono::steady_clock::now();
    work();
    const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
    best = std::min(best, took.count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: python_overhead_bench N OUT.json REPEATS THREADS\n");
    return 2;
  }
  const int n = std::atoi(argv[1]), repeats = std::atoi(argv[3]), threads = std::atoi(argv[4]);
  if (const Status written = write_plan_file(samples::make_grid_plan({.n = n}), argv[2]);
      !written) {
    std::fprintf(stderr, "%s\n", written.error().message.c_str());
    return 2;
  }
  // Read back as the Python module reads it, so both time the same Plan and reading report.
  Report reading;
  const Plan plan = read_plan_file(argv[2], &reading).value();
  const double validate_ms = best_ms(repeats, [&] { (void)check_plan(plan, &reading); });
  BuildOptions options;
  options.threads = threads;
  const double build_ms = best_ms(repeats, [&] { (void)build_model(plan, options); });
  std::printf("{\"walls\": %zu, \"validate_ms\": %.3f, \"build_ms\": %.3f}\n", plan.walls.size(),
              validate_ms, build_ms);
  return 0;
}
