// SPDX-License-Identifier: GPL-3.0-or-later
#include "import/detail/sh3d_walls.h"

#include "import/detail/sh3d_junctions.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include <fmt/format.h>

#include "plan/arc_chords.h"
#include "plan/plan_chords.h"

namespace roomcad::sh3d {
namespace {

/// The wall's height (centimetres) at its start: its own, else the home's default, else its
/// level's, else 250 (Sweet Home 3D's default).
double height_cm(const Home& home, const WallRecord& w) {
  if (w.height_cm) return *w.height_cm;
  if (home.wall_height_cm) return *home.wall_height_cm;
  if (const auto l = std::ranges::find(home.levels, w.level, &Level::id);
      l != home.levels.end() && l->height_cm > 0)
    return l->height_cm;
  return 250.0;
}

/// A height (metres) from a height above the level's floor plus the stretch below it, on the
/// dyadic grid (so base + height lands exactly on the floor's grid value); a height that
/// comes out at most 0 (Sweet Home 3D accepts a zero height at one end) is a millimetre, with
/// an import_sloped_wall warning.
double wall_height(const WallRecord& w, double above_cm, double below_cm, Report& warnings) {
  const double height = z_of(above_cm) + z_of(below_cm);
  if (height > 0) return height;
  warnings.add(import_warning(
      Code::import_sloped_wall, w.id,
      fmt::format("wall '{}' has a height of {} m at one end; a wall's height must be positive, "
                  "so it is imported as 1 mm there",
                  w.id, above_cm / 100)));
  return on_dyadic_grid(1e-3);
}

/// The plan wall of `w`, on its level: from `elevation - floor offset` (base_z) up to its
/// height above the level's floor, sloped and curved as drawn.
PlacedWall make_wall(const Home& home, const WallRecord& w, const std::vector<PlacedLevel>& levels,
                     const WallOptions& options, Report& warnings) {
  PlacedWall placed;
  Wall& wall = placed.wall;
  wall.id = w.id;
  wall.from = w.start;
  wall.to = w.end;
  wall.thickness = w.thickness;
  if (w.color) wall.color = *w.color;
  const PlacedLevel* level = find_placed(levels, w.level);
  const double below_cm = level ? level->floor_offset_cm : 0.0;
  if (level) {
    wall.level = level->level.id;
    wall.base = 0.0 - z_of(below_cm);                    // no -0
    placed.base_z = level->level.elevation + wall.base;  // exact: both on the dyadic grid
  } else {
    wall.base = z_of(options.z_shift_cm);
    placed.base_z = wall.base;
  }
  const double start_cm = height_cm(home, w);
  wall.height = wall_height(w, start_cm, below_cm, warnings);
  if (w.height_at_end_cm && *w.height_at_end_cm != start_cm)
    wall.height_at_end = wall_height(w, *w.height_at_end_cm, below_cm, warnings);
  const double degrees = w.arc_extent.value_or(0.0) * 180 / std::numbers::pi;
  if (degrees != 0 && std::abs(degrees) < 360) wall.arc_extent = -degrees;
  placed.level = w.level;
  // An arc of more chords than a plan builds keeps its extent (validation and the build say
  // why); its doors and windows are placed on its chord.
  placed.polyline = is_buildable_arc(wall, options.chord_tolerance)
                        ? chord_polyline(wall, options.chord_tolerance)
                        : std::vector<Point2>{wall.from, wall.to};
  return placed;
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

std::vector<PlacedWall> convert_walls(const Home& home, std::vector<WallRecord> walls,
                                      const std::vector<PlacedLevel>& levels,
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
    placed.push_back(make_wall(home, w, levels, options, warnings));
  }
  return placed;
}

}  // namespace roomcad::sh3d
