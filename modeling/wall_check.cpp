// SPDX-License-Identifier: GPL-3.0-or-later
#include "modeling/wall_check.h"

#include <cmath>

namespace roomcad {

WallCheck check_walls(const Model& model, const Plan& plan) {
  WallCheck v;
  v.solid = check_solid(model.walls);
  v.analytic = analytic_wall_volume(plan);
  const double diff = std::abs(v.solid.volume - v.analytic);
  v.relative = v.analytic != 0.0 ? diff / std::abs(v.analytic) : diff;
  v.ok = v.solid.is_valid() && v.relative <= kWallVolumeTolerance;
  return v;
}

}  // namespace roomcad
