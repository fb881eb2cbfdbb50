// SPDX-License-Identifier: GPL-3.0-or-later
// Modeling benchmark (Google Benchmark; a report driver, never a timed test): generated N x N
// grids of rooms (doors inside, windows outside; bench/grid_plan.h) built and exported by
// roomcad's fast path and its CGAL path, side by side with two outside references run on the
// same scenes in the same run: plain CGAL Nef polyhedra (balanced union, one batched
// subtraction; nef_reference.h) and Debian's openscad (openscad_reference.h).
//
//   build_bench [--max-n N] [--cgal-max-n N] [--openscad-max-n N] [--csv FILE] [--md FILE]
//               [Google Benchmark flags]
//
// Counters per run: walls, openings, triangles, bytes (the OFF file), volume_error (relative
// to the plan's analytic volume), build_ms (roomcad's paths: the build without the export).
// --csv and --md write the table bench/modeling_report.sh documents.
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench/modeling_table.h"
#include "bench/nef_reference.h"
#include "bench/openscad_reference.h"
#include "io/mesh_export.h"
#include "mesh/mesh_check.h"
#include "solid/analytic_volume.h"
#include "solid/build_model.h"
#include "testing/grid_plan.h"

namespace roomcad::bench {
namespace {

struct Scene {
  Plan plan;
  double analytic = 0.0;  ///< m^3
};

const Scene& grid_scene(int n) {
  static std::map<int, Scene> scenes;
  auto [it, added] = scenes.try_emplace(n);
  if (added) {
    samples::GridSpec spec;
    spec.n = n;
    it->second.plan = samples::make_grid_plan(spec);
    it->second.analytic = analytic_wall_volume(it->second.plan);
  }
  return it->second;
}

void set_counters(benchmark::State& state, const Scene& s, std::size_t triangles, double volume,
                  double bytes) {
  state.counters["walls"] = double(s.plan.walls.size());
  state.counters["openings"] = double(s.plan.openings.size());
  state.counters["triangles"] = double(triangles);
  state.counters["bytes"] = bytes;
  state.counters["volume_error"] = std::abs(volume - s.analytic) / s.analytic;
}

// roomcad: build the wall solid and write it as OFF, per iteration.
void run_roomcad(benchmark::State& state, int n, BooleanPath path) {
  const Scene& s = grid_scene(n);
  BuildOptions options;
  options.boolean = path;
  options.parts = {true, false, false};
  const auto file = std::filesystem::temp_directory_path() / "roomcad_build_bench.off";
  Model model;
  double build_ms = 0.0;  // the build alone, without the export (whose fsync waits on the disk)
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    model = build_model(s.plan, options);
    build_ms +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (const Status written = write_mesh_file(file, MeshParts{{&model.walls}, &model.objects});
        !written)
      return state.SkipWithError(written.message().c_str());
  }
  const SolidCheck check = check_solid(model.walls);
  if (!check.is_valid()) state.SkipWithError("the wall solid fails check_solid");
  set_counters(state, s, check.triangles, check.volume, double(std::filesystem::file_size(file)));
  state.counters["build_ms"] = build_ms / double(state.iterations());
  std::filesystem::remove(file);
}

void run_nef(benchmark::State& state, int n) {
  const Scene& s = grid_scene(n);
  PolygonSoup soup;
  for (auto _ : state) soup = build_nef_reference(s.plan);
  set_counters(state, s, count_triangles(soup), measure_volume(soup), 0.0);
}

void run_scad(benchmark::State& state, int n) {
  const Scene& s = grid_scene(n);
  const auto dir = std::filesystem::temp_directory_path() / "roomcad_build_bench_scad";
  std::filesystem::create_directories(dir);
  std::optional<PolygonSoup> soup;
  for (auto _ : state) soup = run_openscad(s.plan, dir, 600);
  if (!soup) return state.SkipWithError("openscad missing, failed or timed out");
  set_counters(state, s, count_triangles(*soup), measure_volume(*soup),
               double(std::filesystem::file_size(dir / "grid.off")));
  std::filesystem::remove_all(dir);
}

struct Limits {
  int max_n = 70, cgal_max_n = 10, openscad_max_n = 10;
  std::string csv, md;
};

// Takes this driver's flags out of argv (the rest goes to Google Benchmark).
Limits parse_limits(int& argc, char** argv) {
  Limits limits;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    const bool has_value = i + 1 < argc;
    if (has_value && flag == "--max-n") limits.max_n = std::atoi(argv[++i]);
    else if (has_value && flag == "--cgal-max-n") limits.cgal_max_n = std::atoi(argv[++i]);
    else if (has_value && flag == "--openscad-max-n") limits.openscad_max_n = std::atoi(argv[++i]);
    else if (has_value && flag == "--csv") limits.csv = argv[++i];
    else if (has_value && flag == "--md") limits.md = argv[++i];
    else argv[kept++] = argv[i];
  }
  argc = kept;
  return limits;
}

void register_all(const Limits& limits) {
  for (int n : {1, 2, 5, 10, 20, 50, 70}) {
    if (n > limits.max_n) break;
    benchmark::RegisterBenchmark(fmt::format("fast/{}", n).c_str(), run_roomcad, n,
                                 BooleanPath::automatic)
        ->Unit(benchmark::kMillisecond);
    if (n <= limits.cgal_max_n) {
      benchmark::RegisterBenchmark(fmt::format("cgal/{}", n).c_str(), run_roomcad, n,
                                   BooleanPath::nef)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
      benchmark::RegisterBenchmark(fmt::format("nef/{}", n).c_str(), run_nef, n)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
    }
    if (n <= limits.openscad_max_n)
      benchmark::RegisterBenchmark(fmt::format("openscad/{}", n).c_str(), run_scad, n)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(1);
  }
}

}  // namespace
}  // namespace roomcad::bench

int main(int argc, char** argv) {
  using namespace roomcad::bench;
  const Limits limits = parse_limits(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  register_all(limits);
  CollectingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const std::vector<TableRow> rows = make_table(reporter.runs());
  if (!limits.csv.empty() && !write_text(limits.csv, format_csv(rows))) return 2;
  if (!limits.md.empty() && !write_text(limits.md, format_markdown(rows))) return 2;
  benchmark::Shutdown();
  return 0;
}
