// SPDX-License-Identifier: GPL-3.0-or-later
// A generated multi-storey home for benchmarks and tests (plan format version 2): `storeys`
// levels, each the n x n grid of rooms of grid_plan.h on its own level, standing on a floor
// slab that covers the grid to the outer walls' faces, with a stair well in its first room above
// the ground storey. Storey k is level "L<k>" at elevation k x (height + floor); its walls stand on
// its floor (base 0) and reach the underside of the next floor. n = 6, 6 storeys: 504 walls, 6
// slabs.
#pragma once

#include <fmt/format.h>

#include "plan/plan.h"
#include "testing/grid_plan.h"

namespace roomcad::samples {

struct TowerSpec {
  GridSpec storey{.n = 6};  ///< each storey's grid (its height: the walls', floor to ceiling)
  int storeys = 6;
  double floor = 0.2;  ///< slab thickness
};

/// @return the tower on a site that holds it.
inline Plan make_tower_plan(const TowerSpec& t) {
  const GridSpec& g = t.storey;
  Plan plan = make_grid_plan(g);  // its site; the walls come per storey
  plan.walls.clear();
  plan.openings.clear();
  const double step = g.height + t.floor, side = g.n * g.room, face = g.thickness / 2;
  plan.site.max_height = t.storeys * step + 1.0;
  for (int k = 0; k < t.storeys; ++k) {
    const std::string level = fmt::format("L{}", k);
    plan.levels.push_back({level, t.floor + k * step, g.height, {}});
    const Plan storey = make_grid_plan(g);
    for (Wall w : storey.walls) {
      w.id = fmt::format("{}-{}", level, w.id);
      w.level = level;
      plan.walls.push_back(std::move(w));
    }
    for (Opening o : storey.openings) {
      o.id = fmt::format("{}-{}", level, o.id);
      o.wall = fmt::format("{}-{}", level, o.wall);
      plan.openings.push_back(std::move(o));
    }
    Slab& floor = plan.slabs.emplace_back();
    floor.id = fmt::format("{}-floor", level);
    floor.level = level;
    floor.outline = {
        {-face, -face}, {side + face, -face}, {side + face, side + face}, {-face, side + face}};
    const double r = g.room;
    if (k > 0)
      floor.holes = {
          {{0.15 * r, 0.15 * r}, {0.4 * r, 0.15 * r}, {0.4 * r, 0.8 * r}, {0.15 * r, 0.8 * r}}};
    floor.top = 0.0;
    floor.thickness = t.floor;
  }
  return plan;
}

}  // namespace roomcad::samples
