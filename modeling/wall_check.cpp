// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/wall_check.h"

#include <algorithm>
#include <cmath>

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

}  // namespace roomcad
