// Build benchmark (a report driver, not a timed test): generated N x N grids of rooms (doors
// inside, windows outside) through the fast path and the CGAL path, built and exported.
//
//   build_bench [--max-n N] [--cgal-max-n N] [--runs R]   prints a markdown table
//   build_bench --scad N FILE                             writes the grid as OpenSCAD
//
// The CGAL path is CGAL's Nef polyhedra with the walls of a cluster united as a balanced tree
// and all openings subtracted in one batch (the fastest exact CGAL recipe), then converted and
// labelled. bench/openscad_reference.sh times Debian's openscad on the same scenes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/grid_plan.h"
#include "io/mesh_export.h"
#include "modeling/build_model.h"
#include "modeling/mesh_check.h"

namespace roomcad::bench {
namespace {

struct PathResult {
  double ms = 0.0;  ///< best of the runs: build the wall solid and write it as OFF
  std::size_t triangles = 0;
  std::size_t faces = 0;
  std::size_t bytes = 0;
  bool valid = false;
};

PathResult run_path(const Plan& plan, BooleanPath path, int runs) {
  BuildOptions options;
  options.boolean = path;
  options.parts = {true, false, false};
  const auto file = std::filesystem::temp_directory_path() / "roomcad_build_bench.off";
  PathResult r;
  r.ms = 1e300;
  Model model;
  for (int i = 0; i < runs; ++i) {
    const auto start = std::chrono::steady_clock::now();
    model = build_model(plan, options);
    const Status written = write_mesh_file(file, MeshParts{{&model.walls}, &model.objects});
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (!written) throw std::runtime_error(written.error);
    r.ms = std::min(r.ms, ms);
  }
  const SolidCheck check = check_solid(model.walls);
  r.triangles = check.triangles;
  r.faces = model.walls.n_faces();
  r.bytes = std::filesystem::file_size(file);
  r.valid = check.is_valid() && std::abs(check.volume - analytic_wall_volume(plan)) <= 1e-9 * check.volume;
  std::filesystem::remove(file);
  return r;
}

std::string scad_box(const Wall& w, double u0, double u1, double w0, double w1, double z0, double z1) {
  const double deg = std::atan2(w.to.y - w.from.y, w.to.x - w.from.x) * 180.0 / std::numbers::pi;
  return fmt::format("translate([{},{},0]) rotate([0,0,{}]) translate([{},{},{}]) cube([{},{},{}]);\n",
                     w.from.x, w.from.y, deg, u0, w0, z0, u1 - u0, w1 - w0, z1 - z0);
}

/// The plan as OpenSCAD: union of wall boxes minus union of opening boxes (a hair wider than
/// the wall, as OpenSCAD models are usually written to avoid coincident faces).
std::string to_scad(const Plan& plan) {
  std::string out = "difference() {\nunion() {\n";
  for (const Wall& w : plan.walls) {
    const double length = std::hypot(w.to.x - w.from.x, w.to.y - w.from.y);
    out += scad_box(w, 0, length, -w.thickness / 2, w.thickness / 2, w.base, w.base + w.height);
  }
  out += "}\nunion() {\n";
  for (const Opening& o : plan.openings) {
    const Wall& w = *find_wall(plan, o.wall);
    const double t = w.thickness / 2 + 0.01;
    out += scad_box(w, o.offset, o.offset + o.width, -t, t, w.base + o.sill, w.base + o.sill + o.height);
  }
  return out + "}\n}\n";
}

int write_scad(int n, const char* path) {
  GridSpec spec;
  spec.n = n;
  std::ofstream(path) << to_scad(make_grid_plan(spec));
  return 0;
}

void print_row(int n, const Plan& plan, const PathResult& fast, const PathResult* cgal) {
  std::string cgal_cells = "| - | - | - ";
  if (cgal != nullptr)
    cgal_cells = fmt::format("| {:.1f} | {} | {:.0f}x ", cgal->ms, cgal->triangles, cgal->ms / fast.ms);
  std::printf("| %dx%d | %zu | %zu | %.2f | %zu | %zu | %zu %s| %s |\n", n, n, plan.walls.size(),
              plan.openings.size(), fast.ms, fast.faces, fast.triangles, fast.bytes,
              cgal_cells.c_str(), fast.valid && (cgal == nullptr || cgal->valid) ? "yes" : "NO");
  std::fflush(stdout);
}

}  // namespace
}  // namespace roomcad::bench

int main(int argc, char** argv) {
  using namespace roomcad;
  using namespace roomcad::bench;
  if (argc == 4 && std::string(argv[1]) == "--scad") return write_scad(std::atoi(argv[2]), argv[3]);
  int max_n = 70, cgal_max_n = 10, runs = 5;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const int value = std::atoi(argv[i + 1]);
    if (flag == "--max-n") max_n = value;
    else if (flag == "--cgal-max-n") cgal_max_n = value;
    else if (flag == "--runs") runs = std::max(1, value);
  }
  std::printf("| grid | walls | openings | fast ms | fast faces | fast triangles | OFF bytes "
              "| CGAL (Nef batched) ms | CGAL triangles | CGAL / fast | valid |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int n : {1, 2, 5, 10, 20, 50, 70}) {
    if (n > max_n) break;
    GridSpec spec;
    spec.n = n;
    const Plan plan = make_grid_plan(spec);
    const PathResult fast = run_path(plan, BooleanPath::automatic, runs);
    if (n <= cgal_max_n) {
      const PathResult cgal = run_path(plan, BooleanPath::cgal, 1);
      print_row(n, plan, fast, &cgal);
    } else {
      print_row(n, plan, fast, nullptr);
    }
  }
  return 0;
}
