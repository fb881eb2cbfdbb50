// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_walls.h"

#include "import/detail/sh3d_arcs.h"
#include "import/detail/sh3d_junctions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include <fmt/format.h>

namespace roomcad::sh3d {
namespace {


/// The wall's height (centimetres): its own, else the home's default, else its level's, else
/// 250 (Sweet Home 3D's default). A sloped top becomes flat at its higher end, with a warning.
double flat_height_cm(const Home& home, const WallRecord& w, Report& warnings) {
  double height = 250.0;
  if (w.height_cm) height = *w.height_cm;
  else if (home.wall_height_cm) height = *home.wall_height_cm;
  else if (const auto l = std::ranges::find(home.levels, w.level, &Level::id);
           l != home.levels.end() && l->height_cm > 0)
    height = l->height_cm;
  if (w.height_at_end_cm && *w.height_at_end_cm != height) {
    const double top = std::max(height, *w.height_at_end_cm);
    warnings.add(import_warning(
        Code::import_sloped_wall, w.id,
        fmt::format("wall '{}' has a sloped top from {} m to {} m; the plan format has one "
                    "height per wall, so it is imported flat at {} m",
                    w.id, height / 100, *w.height_at_end_cm / 100, top / 100)));
    height = top;
  }
  return height;
}

/// A plan wall from `from` to `to` with the thickness and colour of `w`, spanning z in
/// [base_cm, top_cm].
Wall make_wall(const WallRecord& w, std::string id, Point2 from, Point2 to, double base_cm,
               double top_cm) {
  Wall wall;
  wall.id = std::move(id);
  wall.from = from;
  wall.to = to;
  wall.thickness = w.thickness;
  wall.base = z_of(base_cm);
  wall.height = z_of(top_cm) - wall.base;  // exact: both on the same dyadic grid
  if (w.color) wall.color = *w.color;
  return wall;
}

/// How far from a chord's end an opening must stop for the mitre with the next chord (turning by
/// at most the chord angle for `tolerance`) to stay out of its hole, plus a millimetre.
double mitre_margin(const Arc& arc, const WallRecord& w, double tolerance) {
  const double turn = 2 * std::acos(std::max(-1.0, 1 - tolerance / arc.radius));
  return w.thickness / 2 * std::tan(std::min(turn, 1.0) / 2) + 1e-3;
}

}  // namespace

Diagnostic import_warning(Code code, const std::string& id, std::string message) {
  Diagnostic d;
  d.severity = Severity::warning;
  d.code = code;
  d.objects = {id};
  d.message = std::move(message);
  return d;
}

double on_dyadic_grid(double metres) {
  return std::round(std::ldexp(metres, 20)) / std::ldexp(1.0, 20);
}

double z_of(double cm) { return on_dyadic_grid(cm / 100); }

LevelBase level_base(const Home& home, const std::string& level_id) {
  const auto level = std::ranges::find(home.levels, level_id, &Level::id);
  if (level == home.levels.end()) return {};
  const double lowest = std::ranges::min(home.levels, {}, &Level::elevation_cm).elevation_cm;
  const double offset = level->elevation_cm == lowest ? 0.0 : level->floor_thickness_cm;
  return {.base_cm = level->elevation_cm - offset, .floor_offset_cm = offset};
}

double lowest_base_cm(const Home& home, const std::vector<WallRecord>& walls) {
  double lowest = std::numeric_limits<double>::max();
  for (const WallRecord& w : walls) lowest = std::min(lowest, level_base(home, w.level).base_cm);
  return walls.empty() ? 0.0 : lowest;
}

std::vector<PlacedWall> convert_walls(const Home& home, std::vector<WallRecord> walls,
                                      const std::vector<ItemRecord>& items,
                                      const WallOptions& options, Report& warnings) {
  snap_close_ends(walls, options.snap_distance);
  join_t_ends(walls, options.snap_distance, warnings);
  std::vector<PlacedWall> placed;
  for (const WallRecord& w : walls) {
    if (w.start == w.end) {  // nothing to build, and the plan format forbids it
      warnings.add(import_warning(
          Code::import_zero_length_wall, w.id,
          fmt::format("wall '{}' starts and ends at the same point in the home; it is left out",
                      w.id)));
      continue;
    }
    const LevelBase level = level_base(home, w.level);
    const double base_cm = level.base_cm + options.z_shift_cm;
    const double top_cm = base_cm + level.floor_offset_cm + flat_height_cm(home, w, warnings);
    if (!w.arc_extent || *w.arc_extent == 0) {
      placed.push_back({make_wall(w, w.id, w.start, w.end, base_cm, top_cm), w.level});
      continue;
    }
    const Arc arc = arc_through(w.start, w.end, *w.arc_extent);
    const std::vector<Point2> points =
        split_arc(w.start, w.end, *w.arc_extent, options.chord_tolerance,
                  openings_on_arc(w, arc, items, mitre_margin(arc, w, options.chord_tolerance)));
    for (std::size_t k = 1; k < points.size(); ++k)
      placed.push_back({make_wall(w, fmt::format("{}-arc{}", w.id, k), points[k - 1], points[k],
                                  base_cm, top_cm),
                        w.level});
    warnings.add(import_warning(
        Code::import_curved_wall, w.id,
        fmt::format("curved wall '{}' ({:.1f} degrees of arc) is imported as {} straight walls "
                    "'{}-arc1'..'{}-arc{}' within {} m of the arc",
                    w.id, std::abs(*w.arc_extent) * 180 / std::numbers::pi, points.size() - 1,
                    w.id, w.id, points.size() - 1, options.chord_tolerance)));
  }
  return placed;
}

}  // namespace roomcad::sh3d
