// SPDX-License-Identifier: GPL-3.0-or-later
// The grid of a plane of rectangles (solid/detail/general_path/grid_faces.h) against the general 2D
// boolean for every plane, on real homes: each home is built with the grid and without it in
// turns, in one process (a build of each, then again), so that the machine's drift from one
// minute to the next falls on both alike. Prints per home the fastest and the median build of
// each, the median of the per-round ratios (grid / boolean: quote it), and whether the two
// solids agree (both valid as check_solid has it, of one genus, volumes within 1e-9 relative).
//
//   grid_planes_bench [--homes DIR]... [--threads N] [--rounds N]
//
// Homes: examples/sweethome3d/ and the generated 504-wall tower (testing/tower_plan.h), built as
// `roomcad build --force --parts walls,slabs` builds them; 2 threads and 40 rounds unless told.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/bundled_homes.h"
#include "mesh/mesh_check.h"
#include "solid/build_model.h"

namespace {

using namespace roomcad;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2.0;
}

// One build's time in ms, and its model.
double timed_build(const Plan& plan, const BuildOptions& options, Model& model) {
  const auto start = std::chrono::steady_clock::now();
  model = build_model(plan, options);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::filesystem::path> dirs;
  int threads = 2, rounds = 40;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 < argc && flag == "--homes") dirs.emplace_back(argv[++i]);
    else if (i + 1 < argc && flag == "--threads") threads = std::atoi(argv[++i]);
    else if (i + 1 < argc && flag == "--rounds") rounds = std::max(1, std::atoi(argv[++i]));
    else {
      std::fprintf(stderr,
                   "usage: grid_planes_bench [--homes DIR]... [--threads N] [--rounds N]\n");
      return 2;
    }
  }
  const std::vector<bench::NamedPlan> homes = bench::read_homes(dirs);
  std::printf("%d threads, %d rounds; ms per build\n", threads, rounds);
  std::printf("%-28s %9s %9s %9s %9s %7s  %s\n", "home", "grid min", "grid med", "bool min",
              "bool med", "ratio", "solids");
  for (const bench::NamedPlan& home : homes) {
    BuildOptions grid, boolean;
    grid.parts = boolean.parts = {true, false, false, true};  // walls and slabs
    grid.threads = boolean.threads = threads;
    boolean.grid_planes = false;
    std::vector<double> with, without, ratios;
    Model a, b;
    for (int r = 0; r < rounds; ++r) {
      // Which one goes first alternates.
      const double x = r % 2 ? timed_build(home.plan, boolean, b) : timed_build(home.plan, grid, a);
      const double y = r % 2 ? timed_build(home.plan, grid, a) : timed_build(home.plan, boolean, b);
      with.push_back(r % 2 ? y : x);
      without.push_back(r % 2 ? x : y);
      ratios.push_back(with.back() / without.back());
    }
    const SolidCheck ca = check_solid(a.walls), cb = check_solid(b.walls);
    const bool agree = ca.is_valid() && cb.is_valid() && ca.genus == cb.genus &&
                       std::abs(ca.volume - cb.volume) <= 1e-9 * std::abs(cb.volume);
    std::printf("%-28s %9.2f %9.2f %9.2f %9.2f %7.3f  %s\n", home.name.c_str(),
                *std::min_element(with.begin(), with.end()), median(with),
                *std::min_element(without.begin(), without.end()), median(without), median(ratios),
                agree ? "agree" : "DIFFER");
  }
  return 0;
}
