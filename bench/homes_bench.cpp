// SPDX-License-Identifier: GPL-3.0-or-later
// Real homes built on every path side by side in one run (Google Benchmark; never a timed
// test): the Sweet Home 3D homes of examples/sweethome3d/ (imported plans; a home with
// validation errors is built as `--force` builds it), and a generated multi-storey home
// (`tower`: 6 storeys of the 6 x 6 grid on their floors, 504 walls; testing/tower_plan.h),
// each
// - `auto`: the automatic build, the exact fast path where it applies and the general path
//   for the rest (what `roomcad build` does);
// - `general`: the general path for every wall;
// - `nef`: CGAL's Nef polyhedra for every wall (the reference);
// - `before`: the fast path and Nef for the rest, the automatic build before the general path;
// - `boolean`: the automatic build with every plane of the general path through its 2D
//   boolean, none on the grid of its lines (BuildOptions::grid_planes: before that grid).
// 2 threads (`--threads N` to change), the solid of the walls and slabs (what `roomcad build
// --parts walls,slabs` writes). Nef builds neither slabs nor sloped tops and shaped openings
// (it refuses them by name): `nef` and `before` build the walls alone, and a home with a
// sloped top or a shaped opening is reported as refused there.
//
//   homes_bench [--homes DIR]... [--threads N] [--csv FILE] [Google Benchmark flags]
//
// Counters per run: walls, fast / general / nef walls (the share of each path), build_ms;
// for `auto`, analytic_difference: |volume - analytic volume| / analytic volume of the solid as
// written, and volume_difference: the same against Nef's volume for the walls alone (-1 where
// Nef refused). --csv writes one row per home: walls, the shares, the five times and both
// differences.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "bench/bundled_homes.h"
#include "core/error.h"
#include "mesh/mesh_check.h"
#include "solid/analytic_volume.h"
#include "solid/build_model.h"

namespace roomcad::bench {
namespace {

struct Home {
  std::string name;
  Plan plan;
  double nef_volume = 0.0;
};

struct Options {
  std::vector<std::filesystem::path> dirs;
  int threads = 2;
  std::string csv;
};

std::vector<Home>& homes() {
  static std::vector<Home> all;
  return all;
}

void load_homes(const Options& options) {
  for (NamedPlan& home : read_homes(options.dirs))
    homes().push_back({std::move(home.name), std::move(home.plan), 0.0});
}

// A way to build: its name in the benchmarks' names and the CSV's columns, its path, and
// whether the general path's planes of rectangles go on their grid.
struct Variant {
  const char* name;
  BooleanPath path;
  bool grid_planes = true;
};

// Nef first: the other paths' volumes are compared with it.
constexpr Variant kVariants[] = {{"nef", BooleanPath::nef},
                                 {"before", BooleanPath::fast_then_nef},
                                 {"general", BooleanPath::general},
                                 {"boolean", BooleanPath::automatic, false},
                                 {"auto", BooleanPath::automatic}};

BuildOptions options_for(const Variant& variant, int threads, bool slabs) {
  BuildOptions options;
  options.boolean = variant.path;
  options.parts = {true, false, false, slabs};
  options.threads = threads;
  options.grid_planes = variant.grid_planes;
  return options;
}

void run_home(benchmark::State& state, std::size_t index, const Variant& variant, int threads) {
  Home& home = homes()[index];
  const BooleanPath path = variant.path;
  const BuildOptions options = options_for(variant, threads, !uses_nef(path));
  Model model;
  BuildStats stats;
  double build_ms = 0.0;
  for (auto _ : state) {
    try {
      model = build_model(home.plan, options, &stats);
    } catch (const PreconditionError& e) {  // Nef refuses a sloped top or a shaped opening
      state.SkipWithError(e.what());
      break;
    }
    build_ms += stats.build_ms;
  }
  if (state.error_occurred()) return;
  const double volume = check_solid(model.walls).volume;
  if (path == BooleanPath::nef) home.nef_volume = volume;
  if (path == BooleanPath::automatic && variant.grid_planes) {
    const double analytic = analytic_wall_volume(home.plan);
    state.counters["analytic_difference"] = std::abs(volume - analytic) / analytic;
    state.counters["volume_difference"] = -1.0;  // Nef refused
    if (home.nef_volume > 0.0) {                 // the walls alone, as Nef built them
      const Model walls_alone = build_model(home.plan, options_for(variant, threads, false));
      state.counters["volume_difference"] =
          std::abs(check_solid(walls_alone.walls).volume - home.nef_volume) / home.nef_volume;
    }
  }
  // Shares of the walls as built: an arc wall is built as its chords, each a wall of a path.
  const double walls =
      double(stats.fast_path_walls + stats.general_path_walls + stats.nef_path_walls);
  state.counters["walls"] = double(home.plan.walls.size());
  state.counters["fast_pct"] = 100.0 * double(stats.fast_path_walls) / walls;
  state.counters["general_pct"] = 100.0 * double(stats.general_path_walls) / walls;
  state.counters["nef_pct"] = 100.0 * double(stats.nef_path_walls) / walls;
  state.counters["build_ms"] = build_ms / double(state.iterations());
}

Options parse_options(int& argc, char** argv) {
  Options o;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const bool has_value = i + 1 < argc;
    if (has_value && flag == "--homes") o.dirs.emplace_back(argv[++i]);
    else if (has_value && flag == "--threads") o.threads = std::atoi(argv[++i]);
    else if (has_value && flag == "--csv") o.csv = argv[++i];
    else argv[kept++] = argv[i];
  }
  argc = kept;
  return o;
}

// Collects each run's counters, for the CSV.
class CsvReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) rows_[r.run_name.function_name] = r.counters;  // "nef/Studio"
    ConsoleReporter::ReportRuns(runs);
  }
  [[nodiscard]] std::string csv() const {
    std::string out =
        "home,walls,slabs,fast_pct,general_pct,nef_pct,auto_ms,boolean_ms,general_ms,nef_ms,before_"
        "ms,"
        "analytic_difference,volume_difference\n";
    for (const Home& h : homes()) {
      auto get = [&](const char* path, const char* counter) -> double {
        const auto it = rows_.find(fmt::format("{}/{}", path, h.name));
        return it == rows_.end() || !it->second.count(counter) ? NAN
                                                               : double(it->second.at(counter));
      };
      out += fmt::format(
          "{},{},{},{:.1f},{:.1f},{:.1f},{:.2f},{:.2f},{:.2f},{:.1f},{:.1f},{:.2e},{:.2e}\n",
          h.name, h.plan.walls.size(), h.plan.slabs.size(), get("auto", "fast_pct"),
          get("auto", "general_pct"), get("auto", "nef_pct"), get("auto", "build_ms"),
          get("boolean", "build_ms"), get("general", "build_ms"), get("nef", "build_ms"),
          get("before", "build_ms"), get("auto", "analytic_difference"),
          get("auto", "volume_difference"));
    }
    return out;
  }

 private:
  std::map<std::string, benchmark::UserCounters> rows_;
};

}  // namespace
}  // namespace roomcad::bench

int main(int argc, char** argv) {
  using namespace roomcad;
  using namespace roomcad::bench;
  const Options options = parse_options(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  load_homes(options);
  for (const Variant& variant : kVariants)
    for (std::size_t i = 0; i < homes().size(); ++i) {
      auto* b =
          benchmark::RegisterBenchmark(fmt::format("{}/{}", variant.name, homes()[i].name).c_str(),
                                       run_home, i, variant, options.threads);
      b->Unit(benchmark::kMillisecond)->UseRealTime();
      if (uses_nef(variant.path)) b->Iterations(1);
    }
  CsvReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  if (!options.csv.empty()) std::ofstream(options.csv) << reporter.csv();
  benchmark::Shutdown();
  return 0;
}
