#include "grid_plan.h"

#include <cmath>
#include <string>

#include <fmt/format.h>

namespace roomcad::bench {
namespace {

void add_wall(Plan& plan, const GridOptions& g, Point2 from, Point2 to, bool exterior) {
  Wall w;
  w.id = fmt::format("w{}", plan.walls.size());
  w.from = from;
  w.to = to;
  w.thickness = g.thickness;
  w.height = g.height;
  plan.walls.push_back(w);
  if (!g.openings) return;
  Opening o;
  o.id = fmt::format("o{}", plan.openings.size());
  o.type = exterior ? OpeningType::window : OpeningType::door;
  const OpeningDefaults d = opening_defaults(o.type);
  o.wall = w.id;
  o.width = d.width;
  o.height = d.height;
  o.sill = d.sill;
  o.offset = (g.room_size - o.width) / 2;  // centred: clear of the junctions at both ends
  plan.openings.push_back(o);
}

}  // namespace

std::size_t grid_wall_count(const GridOptions& g) {
  return g.columns * (g.rows + 1) + g.rows * (g.columns + 1);
}

Plan make_grid_plan(const GridOptions& g) {
  Plan plan;
  const double s = g.room_size;
  plan.site.origin = {-1, -1};
  plan.site.cells = {static_cast<std::int64_t>(std::ceil(g.columns * s + 2)),
                     static_cast<std::int64_t>(std::ceil(g.rows * s + 2))};
  plan.walls.reserve(grid_wall_count(g));
  plan.openings.reserve(grid_wall_count(g));
  for (std::size_t j = 0; j <= g.rows; ++j)
    for (std::size_t i = 0; i < g.columns; ++i)
      add_wall(plan, g, {i * s, j * s}, {(i + 1) * s, j * s}, j == 0 || j == g.rows);
  for (std::size_t i = 0; i <= g.columns; ++i)
    for (std::size_t j = 0; j < g.rows; ++j)
      add_wall(plan, g, {i * s, j * s}, {i * s, (j + 1) * s}, i == 0 || i == g.columns);
  return plan;
}

}  // namespace roomcad::bench
