// SPDX-License-Identifier: GPL-3.0-or-later
#include "solid/wall_check.h"
#include "solid/analytic_volume.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace roomcad {

double vertex_rounding(const SolidMesh& mesh) {
  double largest = 0.0;
  for (const auto v : mesh.vertices())
    for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(mesh.point(v)[k]));
  return std::nextafter(largest, 2 * largest + 1) - largest;
}

double volume_tolerance(const SolidMesh& mesh, double volume) {
  double area = 0.0;
  for (const auto f : mesh.faces()) area += face_area(mesh, f);
  return kWallVolumeTolerance * std::abs(volume) + area * vertex_rounding(mesh);
}

WallCheck check_walls(const Model& model, const Plan& plan) {
  WallCheck v;
  v.solid = check_solid(model.walls);
  if (model.slabs_built || plan.slabs.empty()) {
    v.analytic = analytic_wall_volume(plan);
  } else {  // the solid is the walls' alone
    Plan walls_only = plan;
    walls_only.slabs.clear();
    v.analytic = analytic_wall_volume(walls_only);
  }
  const double diff = std::abs(v.solid.volume - v.analytic);
  v.relative = v.analytic != 0.0 ? diff / std::abs(v.analytic) : diff;
  v.limit = volume_tolerance(model.walls, v.analytic);
  v.ok = v.solid.is_valid() && diff <= v.limit;
  return v;
}

std::string describe_failures(const WallCheck& check) {
  const SolidCheck& s = check.solid;
  std::vector<std::string> found;
  const auto count = [&](std::size_t n, const char* what) {
    if (n > 0) found.push_back(fmt::format("{}: {}", what, n));
  };
  count(s.border_edges, "open edges");
  count(s.non_manifold_vertices + s.rejected_triangles, "non-manifold places");
  count(s.self_intersections, "self-intersections");
  count(s.degenerate_triangles, "degenerate faces");
  count(s.inward_components, "inside-out parts");
  if (std::abs(s.volume - check.analytic) > check.limit)
    found.push_back(fmt::format("volume: {} m^3, {} m^3 from the plan", s.volume, check.analytic));
  return fmt::format("{}", fmt::join(found, ", "));
}

}  // namespace roomcad
