// SPDX-License-Identifier: GPL-3.0-or-later
// Generated grids of rooms for benchmarks and tests: n x n square rooms of `room` metres
// between wall centres; every wall runs one cell, node to node (2 n (n + 1) walls). Inner
// walls get a door, outer walls three windows (10 x 10: 220 walls, 180 doors, 120 windows);
// with `entrance`, the first south wall has a door to the outside instead of its middle window.
#pragma once

#include <string>

#include <fmt/format.h>

#include "plan/plan.h"

namespace roomcad::samples {

struct GridSpec {
  int n = 10;
  double room = 4.0;
  double thickness = 0.2;
  double height = 2.8;
  bool entrance =
      false;  ///< a door to the outside in the first south wall (instead of its middle window)
};

inline void add_grid_wall(Plan& plan, Point2 from, Point2 to, bool outer, const GridSpec& g) {
  Wall& w = plan.walls.emplace_back();
  w.id = fmt::format("w{}", plan.walls.size() - 1);
  w.from = from, w.to = to, w.thickness = g.thickness, w.height = g.height;
  auto add = [&](OpeningType type, double offset, double width, double sill, double height) {
    Opening& o = plan.openings.emplace_back();
    o.id = fmt::format("o{}", plan.openings.size() - 1);
    o.type = type, o.wall = w.id, o.offset = offset, o.width = width, o.sill = sill,
    o.height = height;
  };
  if (!outer) {
    add(OpeningType::door, 0.4 * g.room - 0.45, 0.9, 0.0, 2.1);
    return;
  }
  const bool entrance = g.entrance && plan.walls.size() == 1;
  for (int k = 0; k < 3; ++k) {
    if (entrance && k == 1) add(OpeningType::door, 0.5 * g.room - 0.45, 0.9, 0.0, 2.1);
    else add(OpeningType::window, g.room * (0.1 + 0.3 * k), 0.2 * g.room, 0.9, 1.2);
  }
}

/// @return the n x n grid plan on a site that holds it.
inline Plan make_grid_plan(const GridSpec& g) {
  Plan plan;
  plan.site.origin = {-1.0, -1.0};
  plan.site.cells = {static_cast<std::int64_t>(g.n * g.room) + 2,
                     static_cast<std::int64_t>(g.n * g.room) + 2};
  plan.site.max_height = g.height + 1.0;
  for (int j = 0; j <= g.n; ++j)
    for (int i = 0; i < g.n; ++i) {
      const double x = i * g.room, y = j * g.room;
      add_grid_wall(plan, {x, y}, {x + g.room, y}, j == 0 || j == g.n, g);  // along x
      add_grid_wall(plan, {y, x}, {y, x + g.room}, j == 0 || j == g.n, g);  // along y
    }
  return plan;
}

}  // namespace roomcad::samples
